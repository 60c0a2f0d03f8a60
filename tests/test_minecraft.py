"""The Minecraft bridge without a server: the world map, the state parser, the action
controller's geometry, gap filling in the recorder, and the process plumbing's errors
(with a fake `node`). The real server is exercised in test_minecraft_live.py."""
from __future__ import annotations

import stat
import sys
import textwrap

import pytest
from click.testing import CliRunner

from bcc.cli import main
from bcc.errors import BccError
from bcc.minecraft import bridge as bridge_mod
from bcc.minecraft.actions import geometry
from bcc.minecraft.bridge import Bridge, MinecraftError
from bcc.minecraft.record import explain, parse_chat
from bcc.minecraft.world import ORIGIN, WorldMap, check_supported

# The bridge plan, written out by hand from the map (spec section 4): turn round (north ->
# west -> south), step onto (1, 4), look down, mine the stone at (1, 5), step onto it,
# turn to face east, step to (2, 5), select the stone, fill the lava at (3, 5), and walk
# three cells east onto the gold at (5, 5).
BRIDGE_PLAN = ["rotate_left", "rotate_left", "move_forward", "look_down", "destroy_block", "move_forward",
               "rotate_left", "move_forward", "change_item", "place_block", "move_forward", "move_forward",
               "move_forward"]


def replay(model, actions):
    states = [model.initial]
    for a in actions:
        nxt = model.apply(model.action_index(a), states[-1])
        assert nxt is not None, a
        states.append(nxt)
    return states


def observation(model, state, yaw_jitter=0.0, pitch=None, feet=0.0):
    """What the bridge would report for `state`, built independently of the parser: the
    agent's cell centre, Minecraft's yaw (quarter turns from south), the hotbar under
    Minecraft's names, and every block of the dungeon's box in [y][z][x] order."""
    names = {"gold": "gold_block", "burlap_stone": "stone"}
    v = model.decode(state)
    x, y, z = model.agent_position(state)
    g = model.grid
    palette, cells = [], []
    for yy in range(g.height):
        for zz in range(g.depth):
            for xx in range(g.width):
                name = names.get(g.value_names[g.cell(state, xx, yy, zz)], g.value_names[g.cell(state, xx, yy, zz)])
                if name not in palette:
                    palette.append(name)
                cells.append(palette.index(name))
    hotbar = []
    for i in range(9):
        kind, count = v[f"inventoryBlock[{i}].blockType"], v[f"inventoryBlock[{i}].count"]
        hotbar.append(None if count == 0 else [names.get(kind, kind), count])
    return {"position": [ORIGIN[0] + x + 0.5, ORIGIN[1] + y + feet, ORIGIN[2] + z + 0.5],
            "yaw": 90.0 * v["agent.rotationalDirection"] + yaw_jitter,
            "pitch": (60.0 if v["agent.verticalDirection"] else 0.0) if pitch is None else pitch,
            "onGround": True, "selected": v["agent.selectedItem"], "hotbar": hotbar,
            "palette": palette, "cells": cells}


def test_blocks_map_cells_one_to_one(model_of):
    m = model_of("bridge")
    blocks = {(x, y, z): name for x, y, z, name in WorldMap(m).blocks()}
    assert blocks[(5, 0, 5)] == "gold_block"
    assert blocks[(1, 1, 5)] == "stone"          # burlap_stone
    assert blocks[(3, 0, 2)] == "lava"
    assert blocks[(0, 2, 0)] == "bedrock"
    assert (1, 1, 3) not in blocks               # air is not built
    # 7 x 7 floor, the 24 wall columns' two upper blocks, and the stone
    assert len(blocks) == 49 + 24 * 2 + 1


def test_mineable_comes_from_the_model(model_of):
    assert WorldMap(model_of("bridge")).mineable() == ["stone"]
    assert WorldMap(model_of("grid")).mineable() == []


def test_parser_reads_every_state_of_a_plan(model_of):
    m = model_of("bridge")
    w = WorldMap(m)
    for state in replay(m, BRIDGE_PLAN):
        parsed = w.parse(observation(m, state))
        assert parsed.state == state
        assert parsed.notes == [] and parsed.on_floor


def test_parser_snaps_yaw_and_pitch(model_of):
    m = model_of("bridge")
    w = WorldMap(m)
    s = m.initial                                   # facing north, looking ahead
    assert w.parse(observation(m, s, yaw_jitter=25.0)).state == s
    assert w.parse(observation(m, s, yaw_jitter=-25.0 + 360.0)).state == s
    west = m.apply(m.action_index("rotate_left"), s)
    assert w.parse(observation(m, s, yaw_jitter=-80.0)).state == west     # 100 degrees: west
    down = m.apply(m.action_index("look_down"), s)
    assert w.parse(observation(m, s, pitch=48.0)).state == down           # the block at foot level
    assert w.parse(observation(m, s, pitch=20.0)).state == s


def test_parser_applies_lava_death(model_of):
    m = model_of("bridge")
    w = WorldMap(m)
    s = m.apply(m.action_index("rotate_right"), m.initial)               # face east
    s = m.apply(m.action_index("move_forward"), s)                       # (2, 3)
    dead = m.apply(m.action_index("move_forward"), s)                    # onto the lava at (3, 3)
    assert m.is_failure(dead)
    parsed = w.parse(observation(m, dead, feet=-0.7))                    # sunk into it
    assert parsed.state == dead


def test_parser_reports_what_does_not_fit(model_of):
    m = model_of("bridge")
    w = WorldMap(m)
    obs = observation(m, m.initial)
    obs["palette"] = [("dirt" if n == "gold_block" else n) for n in obs["palette"]]
    parsed = w.parse(obs)
    assert any("dirt" in n for n in parsed.notes)
    obs = observation(m, m.initial)
    obs["position"][0] += 20
    with pytest.raises(BccError, match="outside the dungeon"):
        w.parse(obs)


def test_geometry_of_dig_and_place(model_of):
    m = model_of("bridge")
    w = WorldMap(m)
    states = replay(m, BRIDGE_PLAN)
    ox, oy, oz = ORIGIN
    dig = geometry(w, "destroy_block", states[4], states[5])
    assert dig["kind"] == "dig" and dig["block"] == [ox + 1, oy + 1, oz + 5]
    place = geometry(w, "place_block", states[9], states[10])
    # standing on (2, 0, 5) facing east: click that block's east face to fill the lava
    assert place["kind"] == "place" and place["at"] == [ox + 3, oy + 0, oz + 5]
    assert place["reference"] == [ox + 2, oy + 0, oz + 5] and place["face"] == [1, 0, 0]
    assert place["item"] == "stone"
    walk = geometry(w, "move_forward", states[10], states[11])
    assert walk == {"kind": "walk", "target": [ox + 3.5, oy + 1, oz + 5.5], "yaw": 270.0, "pitch": 60.0}
    assert geometry(w, "change_item", states[8], states[9])["slot"] == 1


def test_geometry_places_on_the_floor_at_foot_level(model_of):
    m = model_of("bridge")
    w = WorldMap(m)
    states = replay(m, BRIDGE_PLAN[:6] + ["rotate_left", "rotate_left", "change_item", "place_block"])
    # at (1, 5) facing north onto the floor cell (1, 4): the stone stands on it, at y = 1
    place = geometry(w, "place_block", states[-2], states[-1])
    ox, oy, oz = ORIGIN
    assert place["at"] == [ox + 1, oy + 1, oz + 4]
    assert place["reference"] == [ox + 1, oy + 0, oz + 4] and place["face"] == [0, 1, 0]


def test_explain_fills_gaps_between_polls(model_of):
    m = model_of("bridge")
    states = replay(m, BRIDGE_PLAN)
    assert explain(m, states[0], states[0]) == []
    assert explain(m, states[0], states[1]) == [states[1]]
    assert explain(m, states[0], states[3]) == states[1:4]       # three actions in one poll
    gold_gone = bytearray(m.dense(states[0]))                   # the dense layout has a place for every cell
    g = m.grid
    gold_gone[g.base + 1 * g.width * g.depth + 1 * g.width + 2] = g.value_names.index("gold")
    assert explain(m, states[0], m.compact(bytes(gold_gone))) is None   # a gold block appears: no action


def test_chat_commands():
    assert parse_chat("learn go to the gold block") == ("learn", "go to the gold block")
    assert parse_chat("  Learn  x ") == ("learn", "x")
    assert parse_chat("done") == ("done", "")
    assert parse_chat("hello there") is None


def test_only_minecraft_domain_dungeons(model_of):
    with pytest.raises(BccError, match="minecraft domain only"):
        check_supported(model_of("barnyard"))
    result = CliRunner().invoke(main, ["minecraft", "run", "barnyard"])
    assert result.exit_code == 2
    assert "minecraft domain only" in result.output


def test_help_lists_the_commands():
    result = CliRunner().invoke(main, ["minecraft", "--help"])
    assert result.exit_code == 0
    for command in ("setup", "serve", "run", "record"):
        assert command in result.output


# -- process plumbing, with a fake node ----------------------------------------------------

def fake_node(tmp_path, body: str) -> str:
    """An executable standing in for node: Python running `body` (it ignores its argument)."""
    path = tmp_path / "fake-node"
    path.write_text(f"#!{sys.executable}\n" + textwrap.dedent(body))
    path.chmod(path.stat().st_mode | stat.S_IEXEC)
    return str(path)


@pytest.fixture
def no_install_check(monkeypatch, tmp_path):
    """No packages needed, and their data folder missing, as on a machine that never ran
    `bcc minecraft setup` (the bridge once failed there with a misleading 'cannot run node')."""
    monkeypatch.setattr(bridge_mod, "check_installed", lambda: None)
    monkeypatch.setattr(bridge_mod, "node_dir", lambda: tmp_path / "never-set-up")


def test_missing_node_is_a_clear_error(monkeypatch):
    monkeypatch.setenv("BCC_NODE", "")
    monkeypatch.setenv("PATH", "/nonexistent")
    with pytest.raises(MinecraftError, match="needs Node.js"):
        bridge_mod.node_executable()


def test_a_bridge_that_never_answers_times_out(tmp_path, monkeypatch, no_install_check):
    monkeypatch.setenv("BCC_NODE", fake_node(tmp_path, """
        import sys, time
        print('{"event": "hello"}', flush=True)
        for line in sys.stdin:
            time.sleep(60)
    """))
    with Bridge(timeout=1.0) as b:
        with pytest.raises(MinecraftError, match="did not answer 'ping' within 1 s"):
            b.request("ping")


def test_a_dead_bridge_is_a_clear_error(tmp_path, monkeypatch, no_install_check):
    log = tmp_path / "bridge.log"
    monkeypatch.setenv("BCC_NODE", fake_node(tmp_path, """
        import sys
        print('{"event": "hello"}', flush=True)
        sys.stdin.readline()
        print("Error: something broke in the server", file=sys.stderr, flush=True)
        sys.exit(3)
    """))
    with Bridge(log_path=log, timeout=10.0) as b:
        with pytest.raises(MinecraftError, match="exited with code 3.*something broke"):
            b.request("ping")
        with pytest.raises(MinecraftError, match="exited"):
            b.request("ping")


def test_bridge_errors_are_reported(tmp_path, monkeypatch, no_install_check):
    monkeypatch.setenv("BCC_NODE", fake_node(tmp_path, """
        import json, sys
        print('{"event": "hello"}', flush=True)
        for line in sys.stdin:
            r = json.loads(line)
            print(json.dumps({"event": "chat", "player": "alex", "text": "hi"}), flush=True)
            print(json.dumps({"id": r["id"], "ok": False, "error": "no player is online"}), flush=True)
    """))
    with Bridge(timeout=10.0) as b:
        with pytest.raises(MinecraftError, match="observe: no player is online"):
            b.observe()
        assert b.next_event(5) == {"event": "chat", "player": "alex", "text": "hi"}


def test_a_bridge_that_does_not_start(tmp_path, monkeypatch, no_install_check):
    monkeypatch.setenv("BCC_NODE", fake_node(tmp_path, "import sys; sys.exit(1)\n"))
    with pytest.raises(MinecraftError, match="did not start"):
        Bridge(timeout=1.0)


def test_store_adds_the_pair_with_bcc_learn(tmp_path, model_of):
    from bcc.demonstration import Demonstration, from_actions
    from bcc.cli.minecraft import store
    m = model_of("bridge")
    demo = from_actions(m, BRIDGE_PLAN, command="go to the gold block")
    db = tmp_path / "grounding.sqlite"
    info = store(demo, tmp_path / "demo.json", db=db)
    assert Demonstration.load(tmp_path / "demo.json", model=m).actions == BRIDGE_PLAN
    if not info["stored"] and "store it in the grounding dataset with: bcc learn" in info["message"]:
        pytest.skip("`bcc learn` is not installed here")
    assert info["stored"], info["message"]
    assert "agentOnBlock" in info["task"] and "gold" in info["task"]
    assert db.exists()
    # a demonstration that achieves nothing is refused by `bcc learn`, and said so
    idle = from_actions(m, [], command="stay")
    info = store(idle, tmp_path / "idle.json", db=db)
    assert not info["stored"] and "not stored" in info["message"]


def test_run_takes_the_solver_options_and_checks_them_before_starting(model_of):
    from bcc.minecraft.run import solve_from
    from bcc.solvers import Budget
    model = model_of("bridge")
    chosen = solve_from(model, model.initial, "astar", Budget(time_limit=30), replanning=True,
                        solver_options={"heuristic": "blind"})
    assert chosen.solved and chosen.heuristic == "blind"          # the user's choice, even when replanning
    quick = solve_from(model, model.initial, "astar", Budget(time_limit=30), replanning=True)
    assert quick.heuristic == "manhattan" and quick.cost == chosen.cost   # the cheap default for replans
    bad = CliRunner().invoke(main, ["minecraft", "run", "bridge", "--heuristic", "nope"])
    assert bad.exit_code == 2 and "--heuristic must be one of" in bad.output
    # the run's own --max-steps (actions in the world) is one option, not a solver flag's duplicate
    params = [p for p in main.get_command(None, "minecraft").commands["run"].params if "--max-steps" in p.opts]
    assert len(params) == 1
