"""The shipped corpus: its size and variety, held-out accuracy, and the fallback model."""
from __future__ import annotations

import json
import re

import pytest
from bcc.cli import main
from bcc.errors import BccError
from bcc.grounding import corpus
from bcc.demonstration import from_actions

from click.testing import CliRunner
from conftest import compiled


def test_the_corpus_is_large_varied_and_consistent():
    rows = corpus.load()
    assert len(rows) >= 300
    splits = {r["split"] for r in rows}
    assert splits == {"train", "test"} and sum(r["split"] == "test" for r in rows) >= 50
    commands = " ".join(r["command"] for r in rows)
    for verb in ["go", "walk", "move", "head", "get", "navigate", "stand on", "enter", "into", "toward", "over to"]:
        assert re.search(rf"\b{verb}\b", commands), verb
    tasks = {r["task"] for r in rows}
    assert {f"agentInRoom(agent, {c})" for c in ("red", "orange", "green", "blue")} <= tasks
    assert {"agentOnBlock(agent, gold)", "agentHasBlock(agent, burlap_stone)"} <= tasks
    dungeons = {r["dungeon"] for r in rows}
    assert {"bridge", "four_rooms", "easy_maze"} <= dungeons and any(d.startswith("dungeons/") for d in dungeons)


def test_demonstrations_replay_and_end_in_their_task():
    """Every 10th pair: the demonstration replays from its start and achieves the true task,
    and the task inference run now agrees with the stored explanations."""
    from bcc.grounding.learn import explain
    for row in corpus.load()[::10]:
        space, start = corpus.start_state(row)
        demo = from_actions(space.model, row["actions"], start=start)
        assert space.predicates.predicate(row["task"])(demo.states[-1])
        assert explain(demo, corpus.resolve(row["dungeon"])) == row["explanations"]


def test_held_out_accuracy_is_at_least_95_percent():
    rows = corpus.load()
    model, _ = corpus.train([r for r in rows if r["split"] == "train"])
    result = corpus.evaluate(model, [r for r in rows if r["split"] == "test"])
    assert result["accuracy"] >= 0.95, result["errors"]


def test_command_falls_back_to_the_corpus_model(tmp_path, monkeypatch):
    monkeypatch.setenv("BCC_HOME", str(tmp_path))        # an empty dataset: nothing trained yet
    r = CliRunner().invoke(main, ["command", "four_rooms", "walk into the green room", "--json"])
    assert r.exit_code == 0, r.output
    out = json.loads(r.output)
    assert out["task"] == "agentInRoom(agent, green)" and out["solved"] and out["model"] == "shipped corpus"
    goal = compiled("four_rooms", "agentInRoom(agent, green)")
    assert goal.is_goal(from_actions(goal, out["plan"]).states[-1])
    r = CliRunner().invoke(main, ["command", "bridge", "pick up the stone"])
    assert r.exit_code == 0 and "task: agentHasBlock(agent, burlap_stone)" in r.output


def test_command_naming_a_thing_the_model_never_saw_is_not_understood(tmp_path, monkeypatch):
    # The shipped corpus has no chair: its model would ignore "chair" and guess from "blue
    # room" (before, it answered agentInRoom(agent, red) and walked there).
    monkeypatch.setenv("BCC_HOME", str(tmp_path))
    r = CliRunner().invoke(main, ["command", "cleanup", "take the chair to the blue room", "--json"])
    assert r.exit_code == 1, r.output
    out = json.loads(r.output)
    assert out["task"] is None and out["plan"] == [] and "chair" in out["message"] and "train" in out["message"]
    # an unknown word that names nothing in the dungeon is still only ignored
    r = CliRunner().invoke(main, ["command", "four_rooms", "walk into the green room quickly", "--json"])
    assert r.exit_code == 0 and json.loads(r.output)["task"] == "agentInRoom(agent, green)"


def _small_corpus(monkeypatch):
    """Three dungeons instead of nineteen (a quick corpus), and a demonstration refused for
    about a third of the starts, so that guesses made ahead by the parallel generator are
    often wrong and must be redrawn."""
    import hashlib
    monkeypatch.setattr(corpus, "REFERENCE", ["grid", "bridge"])
    monkeypatch.setattr(corpus, "MAZES", corpus.MAZES[:1])
    monkeypatch.setattr(corpus, "ROOM_SEEDS", corpus.ROOM_SEEDS[:1])
    real = corpus._demonstrate
    refused = []

    def demonstrate(item):
        if hashlib.sha256(item.start + item.task.encode()).digest()[0] % 3 == 0:
            refused.append(item)
            return None
        return real(item)
    monkeypatch.setattr(corpus, "_demonstrate", demonstrate)
    return demonstrate, refused


def _sequential(n, seed, out, demonstrate):
    """The generator as a plain loop, one demonstration after another (how it was written
    before planning went through the batch API): the output the parallel one must match."""
    import random
    from bcc.grounding.learn import space_for
    rng = random.Random(seed)
    refs = corpus.REFERENCE + corpus._write_dungeons(out)
    spaces = {ref: space_for(corpus.resolve(ref, out)) for ref in refs}
    offers = {ref: corpus._family_tasks(spaces[ref]) for ref in refs}
    families = list(corpus.FAMILIES)
    rows = []
    while len(rows) < n:
        family = rng.choices(families, weights=[corpus.FAMILIES[f][0] for f in families])[0]
        ref = rng.choice([r for r in refs if family in offers[r]])
        task, slots = rng.choice(offers[ref][family])
        space = spaces[ref]
        prefix, state = corpus._random_walk(space.model, rng, rng.randint(0, 12))
        if space.predicates.predicate(task)(state) or space.model.is_failure(state):
            continue
        found = demonstrate(corpus._Demo(corpus.resolve(ref, out), task, state))
        if found is None:
            continue
        actions, explained = found
        command = rng.choice(corpus.FAMILIES[family][1]).format(**slots)
        rows.append({"id": len(rows), "split": "test" if rng.random() < corpus.TEST_FRACTION else "train",
                     "command": command, "dungeon": ref, "task": task, "prefix": prefix, "actions": actions,
                     "explanations": explained})
    return "".join(json.dumps(r, separators=(",", ":")) + "\n" for r in rows)


def test_generation_through_the_batch_api_is_the_same_for_any_workers(tmp_path, monkeypatch):
    demonstrate, refused = _small_corpus(monkeypatch)
    expected = _sequential(12, 5, tmp_path, demonstrate)   # same folder: the dungeons compile once
    assert refused, "no refused demonstration: the test would not exercise wrong guesses"
    for workers in (1, 3):
        stats = corpus.generate(12, 5, out=tmp_path, workers=workers)
        assert stats["pairs"] == 12
        assert (tmp_path / "pairs.jsonl").read_text() == expected, workers
        (tmp_path / "pairs.jsonl").unlink()
    assert sorted(p.name for p in (tmp_path / "dungeons").iterdir()) == ["maze_9x9_seed1.yaml", "rooms_seed1.yaml"]


def _maze_gold():
    """Gold in the 9x9 maze from its start: a demonstration of some 10k expansions."""
    from bcc.grounding.learn import space_for
    ref = corpus.resolve("dungeons/maze_9x9_seed1.yaml")
    return corpus._Demo(ref, "agentOnBlock(agent, gold)", space_for(ref).model.initial)


def test_the_planning_budget_counts_states_not_seconds(monkeypatch):
    """A demonstration is kept or dropped by how many states A* stores, never by the clock:
    the state count comes from an unlimited search, and the budget just below it drops the
    pair however fast the machine is."""
    from bcc.grounding.interpret import plan
    from bcc.solvers import Budget
    item = _maze_gold()
    full = plan(item.dungeon, item.task, item.start, Budget())
    assert full.solved and full.stored > 2 * 1024
    monkeypatch.setattr(corpus, "PLAN_STATES", full.stored)
    actions, explained = corpus._demonstrate(item)
    assert actions == full.plan and explained[0]["task"] == item.task
    monkeypatch.setattr(corpus, "PLAN_STATES", full.stored // 2)
    assert corpus._demonstrate(item) is None


def test_the_wall_clock_safety_net_fails_generation_loudly(tmp_path, monkeypatch):
    """A* stopped by the clock (here: a zero-second safety net, hit at its first check after
    1024 expansions) is an error that names the limit, never a silently dropped pair."""
    monkeypatch.setattr(corpus, "SAFETY_SECONDS", 0)
    with pytest.raises(BccError, match="safety limit"):
        corpus._demonstrate(_maze_gold())
    monkeypatch.setattr(corpus, "REFERENCE", [])
    monkeypatch.setattr(corpus, "MAZES", corpus.MAZES[:1])
    monkeypatch.setattr(corpus, "ROOM_SEEDS", [])
    monkeypatch.setattr(corpus, "FAMILIES", {"gold": corpus.FAMILIES["gold"]})
    with pytest.raises(BccError, match="safety limit"):
        corpus.generate(10, 0, out=tmp_path, workers=2)
    assert not (tmp_path / "pairs.jsonl").exists()


def test_generate_takes_a_number_of_workers():
    r = CliRunner().invoke(main, ["corpus", "generate", "--help"])
    assert r.exit_code == 0 and "--workers" in r.output and "the output is the same" in " ".join(r.output.split())
    r = CliRunner().invoke(main, ["corpus", "generate", "--workers", "0"])
    assert r.exit_code == 2 and "--workers" in r.output


def test_shipped_model_is_the_corpus_model_and_gold_means_gold():
    # The model shipped beside the pairs was trained on this very file (its digest), and
    # "get to the gold" in bridge means the gold block, not the stone (the seed's IBM
    # Model 2 chose agentOnBlock(agent, burlap_stone)).
    import json as _json
    from bcc.grounding.interpret import rank
    from bcc.grounding.learn import space_for
    data = _json.loads(corpus.MODEL.read_text())
    assert data["corpus"] == f"{corpus.digest()}:train"
    model = corpus.corpus_model()
    space = space_for("bridge")
    assert rank(model, space, space.model.initial, "get to the gold").task == "agentOnBlock(agent, gold)"
