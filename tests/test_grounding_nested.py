"""Nested cross-validation (issue 32): the votes chosen inside each training part only, and
the report over several shuffles (mean, spread, Wilson interval)."""
from __future__ import annotations

import json

import pytest

from bcc.grounding import nested
from bcc.grounding.shuffles import summarise, wilson
from test_grounding_pairs import run, synthetic, write


def test_wilson_interval_matches_hand_derivations():
    # 50 of 100, z = 1.96: centre (0.5 + 1.9208/100) / 1.038415 = 0.5; half-width
    # 1.96 / 1.038415 * sqrt(0.0025 + 3.8415/40000) = 0.0962 -> the textbook [0.4038, 0.5962]
    lo, hi = wilson(0.5, 100)
    assert lo == pytest.approx(0.4038, abs=1e-4) and hi == pytest.approx(0.5962, abs=1e-4)
    # all 10 right: the lower end is n / (n + z^2) = 10 / 13.8415 = 0.7225, the upper 1
    lo, hi = wilson(1.0, 10)
    assert lo == pytest.approx(0.7225, abs=1e-4) and hi == pytest.approx(1.0)
    assert wilson(0.9, 0) == (0.0, 1.0)


def test_summary_over_shuffles():
    one = {"accuracy": 0.8, "by_level": {"L0": {"accuracy": 0.7, "total": 10}}, "pairs": [0] * 20}
    two = {"accuracy": 0.9, "by_level": {"L0": {"accuracy": 0.9, "total": 10}}, "pairs": [0] * 20}
    s = summarise([one, two])
    assert s["L0"]["mean"] == pytest.approx(0.8) and (s["L0"]["low"], s["L0"]["high"]) == (0.7, 0.9)
    assert s["L0"]["ci95"] == pytest.approx(list(wilson(0.8, 10)))     # n: the level's commands, not 2 x 10
    assert s["all"]["mean"] == pytest.approx(0.85) and s["all"]["total"] == 20


class _Fixed:
    """A stand-in member that always puts its probability on one candidate position."""
    def __init__(self, pick):
        self.pick = pick

    @classmethod
    def trainer(cls, pick):
        return type("Member", (cls,), {"train": classmethod(lambda c, examples: c(pick))})

    def log_posterior(self, command, tasks):
        return [0.0 if k == self.pick(command, tasks) else -5.0 for k in range(len(tasks))]


def test_choose_takes_the_configuration_right_most_often_first_on_a_tie(monkeypatch):
    tasks = ["a", "b"]
    examples = [(f"c{k}", tasks, {tasks[k % 2]: 1.0}) for k in range(12)]
    truth = lambda k: tasks[k % 2]                                              # noqa: E731
    right = _Fixed.trainer(lambda command, t: int(command[1:]) % 2)            # always right
    wrong = _Fixed.trainer(lambda command, t: 1 - int(command[1:]) % 2)        # always wrong
    monkeypatch.setattr(nested, "POOL", (("right", right, {}), ("wrong", wrong, {})))
    monkeypatch.setattr(nested, "CONFIGS", (("wrong-only", (0, 1)), ("right-only", (1, 0)),
                                            ("right-heavy", (2, 1)), ("right-too", (1, 0))))
    splits = [(list(range(0, 8)), list(range(8, 12))), (list(range(4, 12)), list(range(0, 4)))]
    best, accuracy, votes = nested.choose(examples, truth, splits)
    assert accuracy == {"wrong-only": 0.0, "right-only": 1.0, "right-heavy": 1.0, "right-too": 1.0}
    assert best == "right-only" and votes == (1, 0)     # three tie at 100 %: the first listed


def test_stacked_votes_are_fitted_on_other_splits_and_chosen_when_right_more_often(monkeypatch):
    tasks = ["a", "b"]
    examples = [(f"c{k}", tasks, {tasks[k % 2]: 1.0}) for k in range(12)]
    truth = lambda k: tasks[k % 2]                                              # noqa: E731
    right = _Fixed.trainer(lambda command, t: int(command[1:]) % 2)
    wrong = _Fixed.trainer(lambda command, t: 1 - int(command[1:]) % 2)
    monkeypatch.setattr(nested, "POOL", (("right", right, {}), ("wrong", wrong, {})))
    monkeypatch.setattr(nested, "CONFIGS", (("equal-ish", (1, 1.5)), (nested.STACKED, None)))
    splits = [(list(range(0, 8)), list(range(8, 12))), (list(range(4, 12)), list(range(0, 4)))]
    best, accuracy, votes = nested.choose(examples, truth, splits)
    # the fixed votes side with the wrong member (1.5 > 1) on every command; the stacked
    # votes, fitted on the other split's held-out commands, give it none
    assert accuracy == {"equal-ish": 0.0, nested.STACKED: 1.0}
    assert best == nested.STACKED and votes[1] == 0.0 and votes[0] > 0


def test_stack_votes_weigh_the_informative_member_and_fall_back_to_equal_votes(monkeypatch):
    # two candidates; member 0 puts log-probability 0 on the truth and -5 on the other,
    # member 1 is uniform (log 1/2 each): only member 0 moves the likelihood, so the ridge
    # drives member 1's vote to 0
    monkeypatch.setattr(nested, "POOL", (("a", None, {}), ("b", None, {})))
    uniform = [-0.6931, -0.6931]
    records = [([[0.0, -5.0] if t == 0 else [-5.0, 0.0], uniform], [True, True], t) for t in (0, 1) * 5]
    w = nested.stack_votes(records)
    assert w[0] > 0.1 and w[1] == pytest.approx(0.0, abs=1e-3)
    assert nested.stack_votes([]) == (1.0, 1.0)                                  # nothing to fit
    # only a member that reads routes helps: an ensemble needs one that reads words, so equal votes
    from bcc.grounding.route_model import RouteModel
    monkeypatch.setattr(nested, "POOL", (("a", RouteModel, {}), ("b", None, {})))
    assert nested.stack_votes(records) == (1.0, 1.0)
    monkeypatch.setattr(nested, "POOL", (("a", None, {}), ("b", None, {})))
    assert nested.stack_votes([(r[0], r[1], -1) for r in records]) == (1.0, 1.0)  # no truth among the candidates


def test_every_configuration_votes_with_pool_members_only():
    names = [name for name, _ in nested.CONFIGS]
    assert len(names) == len(set(names)) and len(names) <= 13       # about a dozen tries at most
    assert all(w is None or (len(w) == len(nested.POOL) and sum(w) > 0 and min(w) >= 0) for _, w in nested.CONFIGS)
    assert [name for name, w in nested.CONFIGS if w is None] == [nested.STACKED]


@pytest.mark.slow
def test_evaluate_nested_over_shuffles_json(tmp_path):
    pairs = write(tmp_path / "pairs.jsonl", synthetic(48, 5))
    r = run("corpus", "evaluate", "--train", pairs, "--folds", "3", "--shuffles", "2", "--nested",
            "--dungeon", "cleanup", "--from", "tasks", "--json")
    assert r.exit_code == 0, r.output
    out = json.loads(r.stdout)
    assert [s["seed"] for s in out["shuffles"]] == [0, 1]
    names = {name for name, _ in nested.CONFIGS}
    for shuffle in out["shuffles"]:
        assert len(shuffle["chosen"]) == 3 and all(c["config"] in names for c in shuffle["chosen"])
        assert all(set(c["inner_accuracy"]) == names for c in shuffle["chosen"])
    summary = out["summary"]
    assert set(summary) == {"L1", "L2", "all"}
    for v in summary.values():
        assert v["low"] <= v["mean"] <= v["high"] and v["ci95"][0] <= v["mean"] <= v["ci95"][1]
    assert summary["all"]["mean"] == pytest.approx(sum(s["accuracy"] for s in out["shuffles"]) / 2)
    text = run("corpus", "evaluate", "--train", pairs, "--folds", "3", "--nested", "--dungeon", "cleanup",
               "--from", "tasks")
    assert text.exit_code == 0 and "votes chosen by the inner cross-validations:" in text.stdout


def test_shuffles_need_folds(tmp_path):
    pairs = write(tmp_path / "pairs.jsonl", synthetic(20, 6))
    r = run("corpus", "evaluate", "--train", pairs, "--test", pairs, "--shuffles", "2", "--dungeon", "cleanup")
    assert r.exit_code == 2 and "--shuffles needs cross-validation" in r.output
    r = run("corpus", "evaluate", "--nested")
    assert r.exit_code == 2 and "need --train FILE" in r.output
