"""The shipped corpus: its size and variety, held-out accuracy, and the fallback model."""
from __future__ import annotations

import json
import re

from bcc.cli import main
from bcc.grounding import corpus
from bcc.grounding.demonstration import from_actions
from bcc.grounding.learn import train
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
    model, _ = train([r for r in rows if r["split"] == "train"])
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
