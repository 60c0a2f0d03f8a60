"""The shared demonstration format: snapshots, extraction from polled states, files."""
from __future__ import annotations

import json

import pytest
from bcc.errors import BccError
from bcc.demonstration import (
    Demonstration,
    extract,
    from_actions,
    snapshot,
    state_from_snapshot,
)
from bcc.solvers import Budget, get_solver
from conftest import compiled

# The bridge: start (1, 3) facing north, stone at (1, 5) one cell south of (1, 4).
# Turning round twice, looking down and mining changes the agent and a grid cell.
MINE = ["rotate_left", "rotate_left", "move_forward", "look_down", "destroy_block"]


def test_snapshot_round_trips_every_state_of_a_plan():
    m = compiled("bridge")
    demo = from_actions(m, MINE)
    assert len(demo.states) == len(MINE) + 1
    for s in demo.states:
        snap = json.loads(json.dumps(snapshot(m, s)))
        assert state_from_snapshot(m, snap) == s
    # mining put the stone in the inventory and removed it from the grid
    last = m.decode(demo.states[-1])
    assert last["inventoryBlock[1].blockType"] == "burlap_stone"
    assert m.grid.value_names[m.grid.cell(demo.states[-1], 1, 1, 5)] == "air"


def test_extract_drops_polled_duplicates_and_infers_actions():
    m = compiled("bridge")
    demo = from_actions(m, MINE)
    snaps = []
    for s in demo.states:   # a 100 ms poller sees each state several times
        snaps += [snapshot(m, s)] * 3
    again = extract(m, snaps)
    # rotate_left twice equals rotate_right twice in effect, but each single step is unique
    assert again.actions == MINE
    assert again.states == demo.states


def test_extract_names_the_step_no_action_explains():
    m = compiled("bridge")
    demo = from_actions(m, ["move_forward", "move_forward"])
    # skip the middle state: a jump of two cells is no single action
    snaps = [snapshot(m, demo.states[0]), snapshot(m, demo.states[2])]
    with pytest.raises(BccError, match=r"step 1: no action explains .*agent.z: 3 -> 1"):
        extract(m, snaps, "demo.json")


def test_bad_snapshots_are_reported():
    m = compiled("bridge")
    good = snapshot(m, m.initial)
    bad = json.loads(json.dumps(good))
    bad["variables"]["agent.x"] = 99
    with pytest.raises(BccError, match="agent.x = 99 is not an integer"):
        state_from_snapshot(m, bad)
    bad = json.loads(json.dumps(good))
    del bad["variables"]["agent.alive"]
    with pytest.raises(BccError, match="agent.alive' is missing"):
        state_from_snapshot(m, bad)
    bad = json.loads(json.dumps(good))
    bad["cells"].pop()
    with pytest.raises(BccError, match="1 cell.* missing"):
        state_from_snapshot(m, bad)
    bad = json.loads(json.dumps(good))
    bad["cells"][0][3] = "diamond"
    with pytest.raises(BccError, match="unknown block 'diamond'"):
        state_from_snapshot(m, bad)
    bad = json.loads(json.dumps(good))
    bad["cells"].append([0, 3, 0, "gold"])   # y = 3 is static air in the bridge
    with pytest.raises(BccError, match="no action can change it"):
        state_from_snapshot(m, bad)


def test_save_and_load_states_only_actions_only_and_both(tmp_path):
    m = compiled("bridge")
    plan = get_solver("astar")(m, Budget(time_limit=30)).plan
    demo = from_actions(m, plan, command="go to the gold block")
    path = tmp_path / "demo.json"
    demo.save(path)
    data = json.loads(path.read_text())
    assert data["format"] == "bcc-demonstration/1" and data["dungeon"] == "bridge"
    loaded = Demonstration.load(path)
    assert loaded.actions == plan and loaded.states == demo.states
    assert loaded.command == "go to the gold block"
    assert m.is_goal(loaded.states[-1])

    only_states = dict(data, actions=None)
    (tmp_path / "s.json").write_text(json.dumps(only_states))
    assert Demonstration.load(tmp_path / "s.json", m).actions == plan

    only_actions = {k: v for k, v in data.items() if k != "states"}
    (tmp_path / "a.json").write_text(json.dumps(only_actions))
    assert Demonstration.load(tmp_path / "a.json", m).states == demo.states

    other = "rotate_left" if plan[0] != "rotate_left" else "rotate_right"   # any plan's first step differs
    wrong = dict(data, actions=[other] + plan[1:])
    (tmp_path / "w.json").write_text(json.dumps(wrong))
    with pytest.raises(BccError, match="disagree at step 1"):
        Demonstration.load(tmp_path / "w.json", m)


def test_actions_only_file_with_a_start_elsewhere(tmp_path):
    m = compiled("bridge")
    # two steps from the gold at (5, 5): stand at (5, 3) facing south (rotationalDirection 0)
    start = from_actions(m, []).states[0]
    snap = snapshot(m, start)
    snap["variables"].update({"agent.x": 5, "agent.z": 3, "agent.rotationalDirection": 0})
    data = {"format": "bcc-demonstration/1", "dungeon": "bridge", "command": "go to the gold block",
            "start": snap, "actions": ["move_forward", "move_forward"]}
    (tmp_path / "d.json").write_text(json.dumps(data))
    demo = Demonstration.load(tmp_path / "d.json")
    assert m.agent_position(demo.states[-1]) == (5, 1, 5) and m.is_goal(demo.states[-1])


def test_load_errors(tmp_path):
    m = compiled("bridge")
    p = tmp_path / "x.json"
    p.write_text("{not json")
    with pytest.raises(BccError, match="invalid JSON") as e:
        Demonstration.load(p, m)
    assert e.value.line == 1
    p.write_text(json.dumps({"format": "other"}))
    with pytest.raises(BccError, match="not a demonstration"):
        Demonstration.load(p, m)
    p.write_text(json.dumps({"format": "bcc-demonstration/1", "dungeon": "bridge", "actions": ["fly"]}))
    with pytest.raises(BccError, match="step 1: unknown action 'fly'"):
        Demonstration.load(p, m)
    p.write_text(json.dumps({"format": "bcc-demonstration/1", "dungeon": "bridge", "actions": ["destroy_block"]}))
    with pytest.raises(BccError, match="step 1: destroy_block does not apply"):
        Demonstration.load(p, m)
    with pytest.raises(BccError, match="no such demonstration file"):
        Demonstration.load(tmp_path / "missing.json", m)
