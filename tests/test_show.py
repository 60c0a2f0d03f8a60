"""`bcc show` on 3D worlds: layer by layer, with a structure goal's progress (render.py),
through the CLI."""
from __future__ import annotations

import json

from click.testing import CliRunner

from bcc.cli import main
from bcc.generate_structures import generate_structure


def run(*args):
    return CliRunner().invoke(main, [str(a) for a in args], catch_exceptions=False)


def house(tmp_path, **replace) -> str:
    """A 3 x 3 x 2 house of planks at [2, 1, 2] on a 7 x 7 bedrock floor, the agent at (0, 1, 0)."""
    text = generate_structure("house", 3, 3, 2, material="planks")
    for old, new in replace.items():
        text = text.replace(old, new)
    path = tmp_path / "house.yaml"
    path.write_text(text)
    return str(path)


def test_a_structure_goal_is_drawn_layer_by_layer_with_its_progress(tmp_path):
    result = run("show", house(tmp_path), "--json")
    assert result.exit_code == 0
    out = json.loads(result.stdout)
    assert out["view"] == "layers"
    assert [layer["y"] for layer in out["layers"]] == [0, 1, 2, 3]   # the floor, two walls, the roof
    # 23 planks to place (pending); the door's 2 cells and the inside's 2 are air already (done)
    assert {k: out["goal_cells"][k] for k in ("done", "pending", "wrong")} == {"done": 4, "pending": 23, "wrong": 0}
    y1 = out["layers"][1]["rows"]
    assert y1[0] == "@......" and y1[2] == "..+++.." and y1[3] == "..+.+.."
    assert out["layers"][0]["rows"] == ["b" * 7] * 7 and out["legend"] == {".": "air", "b": "bedrock"}
    assert [3, 1, 3] in out["goal_cells"]["cells"]["done"] and [2, 1, 2] in out["goal_cells"]["cells"]["pending"]


def test_a_plans_end_state_shows_done_and_wrong_cells(tmp_path):
    # a stone block already stands where the blueprint wants planks: a wrong cell, `!`
    path = house(tmp_path, **{'  ".": [bedrock]\n': '  ".": [bedrock]\n  "X": [bedrock, stone]\n',
                              "map: |\n  S......\n  .......\n  .......\n": "map: |\n  S......\n  .......\n  ..X....\n"})
    plan = tmp_path / "plan.txt"
    plan.write_text("move_south\nplace_east\n")   # the agent at (0, 1, 1) places planks at (1, 1, 1)
    out = json.loads(run("show", path, "--plan", plan, "--json").stdout)
    assert out["goal_cells"]["wrong"] == 1 and out["goal_cells"]["cells"]["wrong"] == [[2, 1, 2]]
    y1 = out["layers"][1]["rows"]
    assert y1[:3] == ["o......", "@#.....", "..!++.."]       # path, agent, the planks placed, the stone
    assert out["legend"]["#"] == "planks" and out["legend"]["s"] == "stone"
    assert out["plan_note"].startswith("invalid: the plan ends after 2 step(s)")

    text = run("show", path, "--plan", plan).stdout
    assert "y = 1\n  o......\n  @#.....\n  ..!++..\n" in text
    assert "legend: # planks, . air, b bedrock, s stone; @ agent, o path" in text
    assert "goal cells: 4 done, 22 pending (+), 1 wrong (!)" in text


def test_one_layer_and_the_top_view_on_request(tmp_path):
    path = house(tmp_path)
    out = json.loads(run("show", path, "--layer", 3, "--json").stdout)
    assert [layer["y"] for layer in out["layers"]] == [3] and out["layers"][0]["rows"][2] == "..+++.."
    top = json.loads(run("show", path, "--view", "top", "--json").stdout)
    assert top["view"] == "top" and "layers" not in top and top["rows"][0] == "@......"
    bad = run("show", path, "--layer", 7)
    assert bad.exit_code == 2 and "level 7 is outside the world (y = 0 .. 6)" in bad.stderr


def test_a_flat_world_keeps_the_top_view():
    # the minecraft agent never changes level and the goal has no cell atom: the top view
    out = json.loads(run("show", "bridge", "--json").stdout)
    assert out["view"] == "top" and "layers" not in out and out["rows"][1] == "#..L..#"
    assert run("show", "bridge").stdout.splitlines()[1] == "#######"


def test_a_world_whose_agent_changes_level_is_drawn_in_layers():
    # crafting_bench: no cell atom in its goal, but the mason's agent climbs: layers
    out = json.loads(run("show", "crafting_bench", "--json").stdout)
    assert out["view"] == "layers" and [layer["y"] for layer in out["layers"]] == [0, 1, 2]
    assert out["layers"][1]["rows"] == ["bbbbb", "bl@lb", "b.lsb", "bbbbb"]
    assert {k: out["goal_cells"][k] for k in ("done", "pending", "wrong")} == {"done": 0, "pending": 0, "wrong": 0}
