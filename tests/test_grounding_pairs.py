"""Command/task pairs without demonstrations (issue 20): bcc corpus evaluate --train, bcc train --pairs,
the log-linear model and spelling normalisation. The pairs here are made up for the tests."""
from __future__ import annotations

import json
import math
import random

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from bcc.cli import main
from bcc.errors import BccError
from bcc.grounding.loglinear import LogLinear
from bcc.grounding.text import Speller, edit_distance
from click.testing import CliRunner

ROOMS = ["red", "green", "blue"]
GO = ["go to the {r} room", "walk into the {r} room", "head for the {r} room", "move to the {r} room please"]
CARRY = ["take the chair to the {r} room", "bring the chair into the {r} room", "push the chair to the {r} room"]
BOTH = ["put the chair in the {c} room then go to the {r} room", "move the chair to {c} and walk to {r}"]


def synthetic(n: int, seed: int) -> list[dict]:
    rng = random.Random(seed)
    out = []
    for i in range(n):
        kind = rng.choice(["go", "carry", "both"])
        if kind == "go":
            r = rng.choice(["red", "green"])         # the agent starts in blue
            out.append({"id": i, "level": "L2", "command": rng.choice(GO).format(r=r), "task": f"agentInRoom(agent, {r})"})
        elif kind == "carry":
            c = rng.choice(["green", "blue"])        # the chair starts in red
            out.append({"id": i, "level": "L1", "command": rng.choice(CARRY).format(r=c), "task": f"blockInRoom(chair, {c})"})
        else:
            c, r = rng.choice([("blue", "green"), ("green", "blue")])
            # conjuncts in either order: compared as sets
            task = (f"blockInRoom(chair, {c}) and agentInRoom(agent, {r})" if i % 2 else
                    f"agentInRoom(agent, {r}) and blockInRoom(chair, {c})")
            out.append({"id": i, "level": "L1", "command": rng.choice(BOTH).format(c=c, r=r), "task": task})
    return out


def write(path, rows):
    path.write_text("".join(json.dumps(r) + "\n" for r in rows))
    return str(path)


def run(*args):
    return CliRunner().invoke(main, list(args))


def test_evaluate_train_test_json_shape_and_accuracy(tmp_path):
    train = write(tmp_path / "train.jsonl", synthetic(120, 1))
    test = write(tmp_path / "test.jsonl", synthetic(40, 2))
    r = run("corpus", "evaluate", "--train", train, "--test", test, "--dungeon", "cleanup", "--from", "tasks", "--json")
    assert r.exit_code == 0, r.output
    out = json.loads(r.stdout)
    assert set(out) >= {"accuracy", "by_level", "pairs", "confusion"}
    assert set(out["by_level"]) == {"L1", "L2"}
    assert sum(v["total"] for v in out["by_level"].values()) == 40
    assert {"id", "command", "task", "predicted", "correct"} <= set(out["pairs"][0])
    # templated commands over three rooms: a model that learned anything gets nearly all
    assert out["accuracy"] >= 0.9, [p for p in out["pairs"] if not p["correct"]]
    both = [p for p in out["pairs"] if " and " in p["task"]]
    assert both and all(p["task"].startswith("agentInRoom") for p in both)   # canonical order


def test_folds_levels_and_both_modes(tmp_path):
    train = write(tmp_path / "pairs.jsonl", synthetic(60, 3))
    r = run("corpus", "evaluate", "--train", train, "--folds", "3", "--level", "L2", "--dungeon", "cleanup", "--json")
    assert r.exit_code == 0, r.output
    out = json.loads(r.stdout)
    assert set(out["modes"]) == {"tasks", "demonstrations"}
    assert set(out["by_level"]) == {"L2"} and out["by_level"]["L2"]["total"] == sum(
        row["level"] == "L2" for row in synthetic(60, 3))
    plain = run("corpus", "evaluate", "--train", train, "--folds", "3", "--dungeon", "cleanup", "--from", "tasks")
    assert plain.exit_code == 0 and "confusion" in plain.stdout and "L1" in plain.stdout


def test_bad_pairs_are_bad_input(tmp_path):
    bad = tmp_path / "bad.jsonl"
    bad.write_text('{"command": "walk over to the red room now", "task": "agentInRoom(agent, red)"}\n{"command": 1}\n')
    r = run("corpus", "evaluate", "--train", str(bad), "--dungeon", "cleanup", "--folds", "2")
    assert r.exit_code == 2 and "bad.jsonl:2:1:" in r.stderr
    bad.write_text('{"command": "walk over to the red room now", "task": "agentInRoom(agent, purple)"}\n')
    r = run("corpus", "evaluate", "--train", str(bad), "--dungeon", "cleanup", "--folds", "2")
    assert r.exit_code == 2 and "bad.jsonl:1:1:" in r.stderr and "not a task" in r.stderr
    bad.write_text('{"command": "go", "task": "agentInRoom(agent, red)"\n')
    r = run("corpus", "evaluate", "--train", str(bad), "--dungeon", "cleanup")
    assert r.exit_code == 2 and "invalid JSON" in r.stderr
    # No dungeon named and none given: the tasks must pick one shipped dungeon.
    # agentInRoom(agent, red) is a task of cleanup and of manipulation (both have a red room):
    two = write(tmp_path / "two.jsonl", [{"command": "go to the red room", "task": "agentInRoom(agent, red)"}] * 4)
    r = run("corpus", "evaluate", "--train", two, "--folds", "2")
    assert r.exit_code == 2 and "two.jsonl:1:1:" in r.stderr and "cleanup, manipulation" in r.stderr \
        and "--dungeon" in r.stderr
    none = write(tmp_path / "none.jsonl", [{"command": "go to the moon", "task": "agentOnBlock(agent, moon)"}])
    r = run("corpus", "evaluate", "--train", none, "--folds", "2")
    assert r.exit_code == 2 and "none.jsonl:1:1:" in r.stderr and "no shipped dungeon" in r.stderr
    assert run("corpus", "evaluate", "--folds", "3").exit_code == 2
    # A pair naming a dungeon that does not exist, or a level that is not a name: the pair's line.
    bad.write_text('{"command": "go", "task": "agentInRoom(agent, red)"}\n'
                   '{"command": "go", "task": "agentInRoom(agent, red)", "dungeon": "nope"}\n')
    r = run("corpus", "evaluate", "--train", str(bad), "--dungeon", "cleanup", "--folds", "2")
    assert r.exit_code == 2 and "bad.jsonl:2:1:" in r.stderr and "nope" in r.stderr
    bad.write_text('{"command": "go", "task": "agentInRoom(agent, red)", "level": ["L1"]}\n')
    r = run("corpus", "evaluate", "--train", str(bad), "--dungeon", "cleanup", "--folds", "2")
    assert r.exit_code == 2 and "bad.jsonl:1:1:" in r.stderr and "level" in r.stderr


def test_pairs_with_no_dungeon_are_read_in_the_one_their_tasks_fit(tmp_path):
    # synthetic pairs move the chair: of the shipped dungeons only cleanup has a chair
    train = write(tmp_path / "train.jsonl", synthetic(60, 5))
    test = write(tmp_path / "test.jsonl", synthetic(20, 6))
    r = run("corpus", "evaluate", "--train", train, "--test", test, "--from", "tasks", "--json")
    assert r.exit_code == 0, r.output
    assert "read in 'cleanup'" in r.stderr and json.loads(r.stdout)["by_level"]
    named = run("corpus", "evaluate", "--train", train, "--test", test, "--from", "tasks", "--json",
                "--dungeon", "cleanup")
    assert named.exit_code == 0 and "read in" not in named.stderr
    assert json.loads(named.stdout)["accuracy"] == json.loads(r.stdout)["accuracy"]


def test_train_pairs_then_command_cleanup(tmp_path):
    pairs = write(tmp_path / "pairs.jsonl", synthetic(150, 5))
    db = str(tmp_path / "d.sqlite")
    r = run("train", "--pairs", pairs, "--dungeon", "cleanup", "--db", db, "--json")
    assert r.exit_code == 0, r.output
    assert json.loads(r.stdout)["pairs"] == 150
    r = run("command", "cleanup", "take the chiar to the blue room", "--db", db, "--json")   # a typo
    assert r.exit_code == 0, r.output
    out = json.loads(r.stdout)
    assert out["task"] == "blockInRoom(chair, blue)" and out["solved"]
    assert out["cost"] == 20     # derived by hand in tests/test_cleanup.py
    # without --corpus the new model knows only the pairs' dungeon, and says so
    r = run("train", "--pairs", pairs, "--db", db)
    assert r.exit_code == 0 and "knows commands for cleanup only" in r.stderr and "--corpus" in r.stderr


def test_spelling_is_corrected_against_training_words():
    speller = Speller({"chair": 5, "green": 9, "room": 20, "the": 40, "go": 30})
    assert speller.normalise("go to the gren rooom with the chiar") == ["go", "to", "the", "green", "room", "with",
                                                                        "the", "chair"]
    assert edit_distance("chiar", "chair", 2) == 1 and edit_distance("abc", "xyzw", 1) == 2


def test_model_file_round_trip(tmp_path):
    tasks = ["agentInRoom(agent, red)", "agentInRoom(agent, green)"]
    ex = [("go to red", tasks, {tasks[0]: 1.0}), ("go to green", tasks, {tasks[1]: 1.0})] * 3
    model = LogLinear.train(ex, iterations=60)
    model.save(tmp_path / "m.json")
    again = LogLinear.load(tmp_path / "m.json")
    a, b = model.log_posterior("go to green", tasks), again.log_posterior("go to green", tasks)
    assert b[1] > b[0] and abs(a[1] - b[1]) < 1e-3


def test_ensemble_votes_and_round_trips(tmp_path):
    from bcc.grounding import models
    from bcc.grounding.ensemble import Ensemble
    from bcc.grounding.loglinear import command_features
    # pairs of words a few apart: "chair ... green" with three words between them
    assert "s:chair_green" in command_features("chair to the big green".split(), skips=4)
    assert not any(f.startswith("s:") for f in command_features("chair to the big green".split()))
    tasks = ["blockInRoom(chair, green)", "blockInRoom(chair, blue)"]
    ex = [("push the chair into the green room", tasks, {tasks[0]: 1.0}),
          ("push the chair into the blue room", tasks, {tasks[1]: 1.0})] * 3
    model = Ensemble.train(ex)
    from bcc.grounding.network import Network
    from bcc.grounding.route_model import RouteModel
    # the shipped members (ensemble.MEMBERS): words, skips, whole, network, routes, steps
    assert [getattr(m, "skips", None) for m in model.members] == [0, 4, 0, 0, None, None]
    assert [getattr(m, "factored", None) for m in model.members] == [True, True, False, True, None, None]
    assert isinstance(model.members[3], Network)
    assert [getattr(m, "reads", None) for m in model.members[4:]] == ["routes", "steps"]
    assert all(isinstance(m, RouteModel) for m in model.members[4:])
    assert list(model.weights) == [1.0, 1.0, 1.0, 1.5, 1.0, 1.0]
    # no scene (no map to read a route on): the route members abstain, the words vote
    assert model.members[4].log_posterior("chair into green", tasks) is None
    alone = [m.log_posterior("chair into green", tasks) for m in model.members[:4]]
    both = model.log_posterior("chair into green", tasks)
    # the weighted mean of the members' log-probabilities, renormalised (two tasks: the
    # first task's log-odds is the weighted mean of the members' log-odds)
    odds = [a[0] - a[1] for a in alone]
    assert both[0] > both[1]
    assert abs((both[0] - both[1]) - (odds[0] + odds[1] + odds[2] + 1.5 * odds[3]) / 4.5) < 1e-9
    # a task the whole-task member never saw: it abstains, the others vote
    other = tasks + ["blockInRoom(chair, red)"]
    assert not model.members[2].knows(other) and model.members[0].knows(other)
    alone = [m.log_posterior("chair into green", other) for m in model.members[:4]]
    mean = (np.array(alone[0]) + np.array(alone[1]) + 1.5 * np.array(alone[3])) / 3.5
    assert np.allclose(model.log_posterior("chair into green", other), mean - np.logaddexp.reduce(mean))
    model.save(tmp_path / "e.json")
    again = models.load(tmp_path / "e.json")
    assert isinstance(again, Ensemble) and abs(again.log_posterior("chair into green", tasks)[0] - both[0]) < 1e-3
    (tmp_path / "bad.json").write_text('{"format": "bcc-ensemble/1", "members": [{"format": "x"}]}')
    with pytest.raises(BccError, match="members"):
        models.load(tmp_path / "bad.json")
    data = json.loads((tmp_path / "e.json").read_text())
    (tmp_path / "w.json").write_text(json.dumps(data | {"weights": [1, -1, 0]}))
    with pytest.raises(BccError, match="weights"):
        models.load(tmp_path / "w.json")
    bad = json.loads(json.dumps(data))
    bad["members"][2]["factored"] = "no"
    (tmp_path / "f.json").write_text(json.dumps(bad))
    with pytest.raises(BccError, match="factored"):
        models.load(tmp_path / "f.json")
    # a file from before the weights (and naive Bayes): equal votes of its members
    old = data | {"members": data["members"][:2]}
    del old["weights"]
    (tmp_path / "old.json").write_text(json.dumps(old))
    assert list(models.load(tmp_path / "old.json").weights) == [1.0, 1.0]


def test_whole_task_log_linear_model():
    """Not factored: one feature per task (its text), so nothing learned about one task's
    atoms carries over to another; the factored model's features are unchanged."""
    from bcc.grounding.loglinear import LogLinear, task_features
    task = "agentInRoom(agent, green) and blockInRoom(chair, blue)"
    assert task_features(task, factored=False) == ["T:" + task]
    assert "FA:blockInRoom:blue" in task_features(task) and task_features(task)[0] == "T:" + task
    tasks = ["agentInRoom(agent, red)", "agentInRoom(agent, green)", "blockInRoom(chair, green)"]
    ex = [("go to red", tasks, {tasks[0]: 1.0}), ("go to green", tasks, {tasks[1]: 1.0})] * 3
    model = LogLinear.train(ex, factored=False)
    assert sorted(model.task_index) == sorted("T:" + t for t in tasks)
    lp = model.log_posterior("go to green", tasks)
    assert max(range(3), key=lp.__getitem__) == 1
    assert model.knows(tasks) and not model.knows(tasks + ["agentInRoom(agent, blue)"])
    again = LogLinear.from_json(json.loads(json.dumps(model.to_json())))
    assert again.factored is False and np.allclose(again.log_posterior("go to green", tasks), lp, atol=1e-3)
    # a file from before the option: factored
    old = model.to_json()
    del old["factored"]
    assert LogLinear.from_json(old).factored is True


def test_letter_ngrams_share_word_forms_and_round_trip(tmp_path):
    """chars=N adds each word's letter n-grams (2..N letters, the word padded by spaces, as
    scikit-learn's analyzer="char_wb"): a word form never seen in training still shares
    features with the seen one, and the option is kept in the model file."""
    from bcc.grounding import models
    from bcc.grounding.ensemble import Ensemble
    from bcc.grounding.loglinear import command_features, letter_ngrams
    # " go " padded: 2-grams " g", "go", "o "; 3-grams " go", "go "; 4-gram " go " (by hand)
    assert letter_ngrams(["go"], 4) == ["g: g", "g:go", "g:o ", "g: go", "g:go ", "g: go "]
    assert letter_ngrams(["go", "go"], 2) == ["g: g", "g:go", "g:o "]          # each word once
    assert not any(f.startswith("g:") for f in command_features(["go", "to", "red"]))
    assert "g: gre" in command_features(["greenish"], chars=4) and "g: gre" in command_features(["green"], chars=4)
    tasks = ["agentInRoom(agent, green)", "agentInRoom(agent, red)"]
    ex = [("walk to the greenery room", tasks, {tasks[0]: 1.0}), ("walk to the greenhouse room", tasks, {tasks[0]: 1.0}),
          ("walk to the reddish room", tasks, {tasks[1]: 1.0}), ("walk to the redder room", tasks, {tasks[1]: 1.0})] * 3
    words_only = LogLinear.train(ex, factored=False)
    letters = LogLinear.train(ex, factored=False, chars=4)
    # "greens" was never said, and is not within the speller's reach of a training word:
    # the word model sees only "walk to the ... room", said as often of either room (an even
    # vote), the letters model also " gr", "gre", "reen", ...
    words_lp, letters_lp = words_only.log_posterior("walk to the greens room", tasks), \
        letters.log_posterior("walk to the greens room", tasks)
    assert abs(words_lp[0] - words_lp[1]) < 0.2 and letters_lp[0] - letters_lp[1] > 1.0
    again = LogLinear.from_json(json.loads(json.dumps(letters.to_json())))
    assert again.chars == 4 and np.allclose(again.log_posterior("walk to the greens room", tasks), letters_lp, atol=1e-2)
    assert "chars" not in words_only.to_json() and LogLinear.from_json(words_only.to_json()).chars == 0
    # in an ensemble file (the nested choice may give the letters member a vote)
    both = Ensemble([words_only, letters], [1.0, 1.0])
    both.save(tmp_path / "e.json")
    loaded = models.load(tmp_path / "e.json")
    assert [m.chars for m in loaded.members] == [0, 4]


def test_naive_bayes_counts_and_unseen_tasks(tmp_path):
    import math
    from bcc.grounding.bayes import ALPHA, PRIOR, NaiveBayes
    from bcc.grounding.loglinear import command_features
    tasks = ["agentInRoom(agent, red)", "agentInRoom(agent, green)", "agentInRoom(agent, orange)"]
    ex = [("go to red", tasks, {tasks[0]: 1.0})] * 3 + [("go to green", tasks, {tasks[1]: 1.0})]
    model = NaiveBayes.train(ex)
    lp = model.log_posterior("go to red", tasks)
    assert lp[0] > lp[1] and abs(sum(math.exp(x) for x in lp) - 1) < 1e-9
    # by hand: 4 features name the colour ("w:red", "b:to_red", "h2:red", "e:red"), present
    # in all 3 red commands and absent from the green one, and the green ones the other
    # way round; 7 are shared (w:, h1:, e: of "go" and "to", and "b:go_to"), present in
    # every command of both tasks
    feats = command_features(["go", "to", "red"])
    assert len([f for f in feats if "red" in f]) == 4 and len(feats) == 1 + 4 + 7    # and the bias
    p_red_red, p_red_green = (3 + ALPHA) / (3 + 2 * ALPHA), ALPHA / (1 + 2 * ALPHA)
    p_green_red, p_green_green = ALPHA / (3 + 2 * ALPHA), (1 + ALPHA) / (1 + 2 * ALPHA)
    expected = (math.log(3 + PRIOR) - math.log(1 + PRIOR)
                + 4 * (math.log(p_red_red) - math.log(p_red_green))            # red features present
                + 4 * (math.log(1 - p_green_red) - math.log(1 - p_green_green))  # green ones absent
                + 7 * (math.log(p_red_red) - math.log(p_green_green)))           # shared: 3 of 3 against 1 of 1
    assert abs((lp[0] - lp[1]) - expected) < 1e-9
    # a task never seen in training is scored as the pooled language, with the smallest prior
    assert lp[2] < lp[0] and math.isfinite(lp[2])
    # demonstrations: fractional counts
    soft = NaiveBayes.train([("go to red", tasks, {tasks[0]: 3.0, tasks[1]: 1.0})] * 2)
    assert soft.task_counts == {tasks[0]: 1.5, tasks[1]: 0.5}
    model.save(tmp_path / "nb.json")
    again = NaiveBayes.load(tmp_path / "nb.json")
    assert again.log_posterior("go to red", tasks) == pytest.approx(lp)
    (tmp_path / "bad.json").write_text(json.dumps(model.to_json() | {"feature_counts": {tasks[0]: {"99": 1}}}))
    with pytest.raises(BccError, match="malformed"):
        NaiveBayes.load(tmp_path / "bad.json")


def test_network_scores_word_combinations_and_round_trips(tmp_path):
    """The feed-forward network (network.py): it learns a pair of words that only together
    say the task, scores other dungeons' tasks by their atoms, trains the same model twice
    from the same pairs, and saves its weights exactly."""
    from bcc.grounding.network import Network
    tasks = ["blockInRoom(chair, green)", "blockInRoom(chair, blue)",
             "agentInRoom(agent, green)", "agentInRoom(agent, blue)"]
    # "green" alone does not say which atom: "chair" beside it does
    ex = [("push the chair into green", tasks, {tasks[0]: 1.0}), ("push the chair into blue", tasks, {tasks[1]: 1.0}),
          ("walk into green", tasks, {tasks[2]: 1.0}), ("walk into blue", tasks, {tasks[3]: 1.0})] * 4
    model = Network.train(ex, starts=2, epochs=60)
    for command, want in (("push the chair into green", 0), ("walk into blue", 3), ("the chair into blue", 1)):
        lp = model.log_posterior(command, tasks)
        assert max(range(4), key=lp.__getitem__) == want, command
        assert abs(sum(math.exp(x) for x in lp) - 1) < 1e-9
    # factored: a task never trained on is scored by its atoms' parts, not ruled out
    other = tasks + ["blockInRoom(chair, red)"]
    assert model.knows(other) and all(math.isfinite(x) for x in model.log_posterior("chair into red", other))
    again = Network.train(ex, starts=2, epochs=60)
    assert again.log_posterior("walk into green", tasks) == model.log_posterior("walk into green", tasks)
    model.save(tmp_path / "n.json")
    loaded = Network.load(tmp_path / "n.json")
    assert np.allclose(loaded.log_posterior("walk into green", tasks), model.log_posterior("walk into green", tasks),
                       atol=1e-5)
    data = json.loads((tmp_path / "n.json").read_text())
    for broken, message in ((data["starts"][0] | {"W1": "AAAA"}, "numbers"), (data["starts"][0] | {"V": 7}, "base64"),
                            (data["starts"][0] | {"b1": "@@"}, "base64")):
        (tmp_path / "bad.json").write_text(json.dumps(data | {"starts": [broken]}))
        with pytest.raises(BccError, match=message):
            Network.load(tmp_path / "bad.json")
    # latent tasks (a demonstration's weighted explanations) train as their mixture
    soft = Network.train([("walk into green", tasks, {tasks[2]: 3.0, tasks[0]: 1.0})] * 8, starts=1, epochs=30)
    lp = soft.log_posterior("walk into green", tasks)
    assert lp[2] > lp[1] and lp[0] > lp[1]


def test_network_whole_tasks_abstain_on_unseen_ones():
    from bcc.grounding.network import Network
    tasks = ["agentInRoom(agent, red)", "agentInRoom(agent, green)"]
    model = Network.train([("go to red", tasks, {tasks[0]: 1.0}), ("go to green", tasks, {tasks[1]: 1.0})] * 4,
                          factored=False, starts=1, epochs=40)
    assert sorted(model.task_index) == sorted("T:" + t for t in tasks)
    assert model.knows(tasks) and not model.knows(tasks + ["agentInRoom(agent, blue)"])
    lp = model.log_posterior("go to green", tasks)
    assert lp[1] > lp[0]


_shipped = {}


@settings(max_examples=60, deadline=None)
@given(st.text(max_size=200))
def test_any_text_gets_a_distribution_from_every_voter(text):
    """Whatever is typed (empty, punctuation, other scripts, words never trained on), each
    member of the shipped model and their vote give finite log-probabilities summing to 1."""
    from bcc.grounding import corpus, learn
    if not _shipped:
        _shipped["model"], _shipped["tasks"] = corpus.corpus_model(), learn.candidates("bridge")
    model, tasks = _shipped["model"], _shipped["tasks"]
    for scorer in [*model.members, model]:
        lp = np.array(scorer.log_posterior(text, tasks))
        assert lp.shape == (len(tasks),) and np.isfinite(lp).all()
        assert abs(np.logaddexp.reduce(lp)) < 1e-9


def test_evaluate_shows_progress_on_a_terminal_only(tmp_path, monkeypatch):
    """Cross-validation trains a model per fold and mode (minutes on a real corpus): on a
    terminal a line on stderr counts them; piped, stderr stays quiet."""
    from bcc.cli import grounding as commands
    train = write(tmp_path / "train.jsonl", synthetic(60, 1))
    args = ("corpus", "evaluate", "--train", train, "--folds", "2", "--dungeon", "cleanup", "--from", "tasks")
    assert "models trained" not in run(*args).stderr
    monkeypatch.setattr(commands, "progress_enabled", lambda: (lambda *a: None))
    r = run(*args)
    assert r.exit_code == 0 and "from tasks: 1/2 models trained" in r.stderr and "2/2" in r.stderr


def test_evaluate_on_several_workers_reports_the_same(tmp_path):
    """Folds trained in child processes (bcc.batch.map_runs) give the report one process gives:
    the models are seeded, and the pairs come back in the folds' order."""
    train = write(tmp_path / "train.jsonl", synthetic(90, 3))
    base = ("corpus", "evaluate", "--train", train, "--folds", "3", "--dungeon", "cleanup", "--json")
    one, two = run(*base), run(*base, "--workers", "2")
    assert one.exit_code == 0 and two.exit_code == 0, two.output
    a, b = json.loads(one.stdout), json.loads(two.stdout)
    for report in (a, b):
        for mode in report["modes"].values():
            del mode["train_seconds"]
        del report["train_seconds"]
    assert a == b and len(a["pairs"]) == 90
    r = run("corpus", "evaluate", "--workers", "2")
    assert r.exit_code == 2 and "--workers need --train FILE" in r.stderr


def test_evaluate_on_workers_stops_at_the_time_limit_and_leaves_no_child(tmp_path):
    import multiprocessing
    train = write(tmp_path / "train.jsonl", synthetic(400, 4))
    r = run("corpus", "evaluate", "--train", train, "--folds", "10", "--dungeon", "cleanup", "--workers", "2",
            "--time-limit", "1")
    assert r.exit_code == 1 and "stopped: the time limit (--time-limit) ran out" in r.stderr
    assert not multiprocessing.active_children()
