"""New object classes in YAML only: the farm domain, composition rules, and a villager."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from bcc.compiler import compile_dungeon
from bcc.errors import BccError
from bcc.simulate import replay
from bcc.solvers import Budget, get_solver

ROOT = Path(__file__).resolve().parent.parent
BUDGET = Budget(time_limit=60)


def test_no_animal_words_in_compiler_or_solvers():
    words = re.compile(r"animal|cow|wheat|villager|emerald", re.I)
    for folder in ("compiler", "solvers"):
        for path in (ROOT / folder).glob("*.py"):
            assert not words.search(path.read_text()), path


def test_pasture_solved_optimally():
    # Daisy (4,3) is fenced in by stones on all four sides; the agent starts at (4,6)
    # facing north. It must stand on a neighbour cell facing her: the nearest is (4,4),
    # a stone. Step to (4,5), look down, mine (4,4), step in, select the wheat (slot 1),
    # feed: 6 actions, each unavoidable.
    model = compile_dungeon("pasture")
    bfs = get_solver("bfs")(model, BUDGET)
    astar = get_solver("astar")(model, BUDGET)
    assert bfs.cost == astar.cost == 6
    assert astar.plan[-1] == "feed_animal" and replay(model, [(a, 1, 1) for a in astar.plan]).valid


def test_barnyard_needs_both_foods():
    model = compile_dungeon("barnyard")
    bfs = get_solver("bfs")(model, BUDGET)
    astar = get_solver("astar")(model, BUDGET)
    assert bfs.solved and bfs.cost == astar.cost
    assert {"feed_animal(agent, daisy)", "feed_animal(agent, wilbur)"} <= set(astar.plan)


def test_animals_block_movement_and_building():
    model = compile_dungeon("barnyard", goal="agentNextToAnimal(agent, daisy)")
    s = model.initial
    # (4,3) facing north; turn west and walk to (1,3) then north to (1,2): next to Daisy.
    for name in ["rotate_left", "move_forward", "move_forward", "move_forward", "rotate_right", "move_forward"]:
        s = model.apply(model.action_index(name), s)
    assert model.is_goal(s)
    assert model.apply(model.action_index("move_forward"), s) is None  # Daisy stands at (1,1)
    assert "passable" in model.why_not(model.action_index("move_forward"), s)


def test_feeding_the_wrong_food_is_refused():
    model = compile_dungeon("pasture")
    plan = ["move_forward", "look_down", "destroy_block", "move_forward"]  # still holding the pickaxe
    r = replay(model, [(a, 1, 1) for a in plan + ["feed_animal"]])
    assert not r.valid and r.failed_step == 5 and "food" in r.message


VILLAGER_DOMAIN = """\
domain: village
extends: minecraft
types:
  blocktype:
    values:
      emerald: {id: 388}
      bread:   {id: 297}
classes:
  villager:
    position: [x, y, z]
    attributes:
      x: {type: int, range: [0, width - 1]}
      y: {type: int, range: [0, height - 1]}
      z: {type: int, range: [0, depth - 1]}
      traded: {type: bool}
dungeon:
  lists:
    villagers: {class: villager, fields: {at: [x, y, z]}}
functions:
  hasTraded: {params: {v: villager}, body: v.traded}
actions:
  trade:
    params: {a: agent, v: villager}
    let:
      tx: a.x + dx[a.rotationalDirection]
      tz: a.z + dz[a.rotationalDirection]
    pre:
      - v.x == tx and v.z == tz and not v.traded
      - inventoryBlock[a.selectedItem].blockType == emerald
      - inventoryBlock[a.selectedItem].count > 0
    effect: |
      v.traded = true;
      inventoryBlock[a.selectedItem].blockType = bread
"""

VILLAGE = """\
domain: village.yaml
height: 3
legend: {"#": [bedrock, bedrock, bedrock], ".": [bedrock], "S": [bedrock]}
map: |
  #####
  #...#
  #S..#
  #####
agent: {start: S, facing: east}
inventory:
  - {item: diamond_pickaxe, count: 1}
  - {item: emerald, count: 1}
villagers:
  - {name: bob, at: [3, 1, 1]}
goal: hasTraded(bob) and agentHasBlock(agent, bread)
"""


def test_a_new_class_in_a_temporary_yaml_file_only(tmp_path):
    (tmp_path / "village.yaml").write_text(VILLAGER_DOMAIN)
    (tmp_path / "v.yaml").write_text(VILLAGE)
    model = compile_dungeon(tmp_path / "v.yaml")
    result = get_solver("astar")(model, BUDGET)
    # From (1,2) facing east: step to (2,2), turn north... bob is at (3,1): stand at (2,1)
    # facing east, or (3,2) facing north. (1,2)->(2,2)->(3,2) (2 moves) then turn north (1),
    # select the emerald (1), trade (1) = 5; BFS confirms.
    assert result.cost == get_solver("bfs")(model, BUDGET).cost == 5


def test_effects_written_one_a_line_need_no_semicolons(tmp_path):
    # The trade effect as people write a YAML block scalar: one effect a line, no `;`.
    one_a_line = VILLAGER_DOMAIN.replace("v.traded = true;\n", "v.traded = true\n")
    assert one_a_line != VILLAGER_DOMAIN
    (tmp_path / "village.yaml").write_text(one_a_line)
    (tmp_path / "v.yaml").write_text(VILLAGE)
    model = compile_dungeon(tmp_path / "v.yaml")
    result = get_solver("bfs")(model, BUDGET)
    # the same 5-step plan as with `;` (derived in the test above): the trade gives bread
    assert result.cost == 5 and result.plan[-1].startswith("trade")


def _domain(tmp_path, text: str) -> Path:
    (tmp_path / "d.yaml").write_text(text)
    (tmp_path / "g.yaml").write_text((ROOT / "dungeons" / "grid.yaml").read_text().replace(
        "domain: minecraft", "domain: d.yaml"))
    return tmp_path / "g.yaml"


@pytest.mark.parametrize("text,message", [
    ("domain: x\nextends: minecraft\nactions:\n  rotate_left:\n    params: {a: agent}\n    effect: a.x = 1\n",
     "already defined in 'minecraft'; add `override: true`"),
    ("domain: x\nextends: minecraft\nfunctions:\n  nothing:\n    override: true\n    body: true\n",
     "nothing to override"),
    ("domain: x\nextends: minecrafft\n", "unknown domain 'minecrafft'"),
    ("domain: x\nextends: d.yaml\n", "cycle"),
    ("domain: x\nextends: minecraft\ntypes:\n  blocktype:\n    values:\n      gold: {id: 999}\n",
     "'gold' is listed twice"),
])
def test_composition_errors_have_positions(tmp_path, text, message):
    with pytest.raises(BccError) as err:
        compile_dungeon(_domain(tmp_path, text))
    assert message in err.value.message and err.value.line is not None
    assert err.value.path.endswith("d.yaml")


def test_override_replaces_by_name(tmp_path):
    # rotate_left overridden to turn right: the grid's plan then changes but stays solvable.
    text = ("domain: x\nextends: minecraft\nactions:\n  rotate_left:\n    override: true\n"
            "    params: {a: agent}\n    effect: a.rotationalDirection = (a.rotationalDirection + 1) % 4\n")
    model = compile_dungeon(_domain(tmp_path, text))
    s = model.apply(model.action_index("rotate_left"), model.initial)
    assert model.decode(s)["agent.rotationalDirection"] == 3  # north (2) + 1 = east


def test_added_enum_values_take_declared_property_defaults():
    from bcc.compiler.domain import load_domain
    enum = load_domain(ROOT / "domains" / "farm.yaml").enums["blocktype"]
    wheat = enum.index("wheat")
    assert enum.properties["fillable"][wheat] is False and enum.properties["solid"][wheat] is False


def test_listed_object_positions_are_checked(tmp_path):
    text = (ROOT / "dungeons" / "pasture.yaml").read_text().replace("at: [4, 1, 3]", "at: [40, 1, 3]")
    (tmp_path / "p.yaml").write_text(text)
    with pytest.raises(BccError) as err:
        compile_dungeon(tmp_path / "p.yaml")
    line = next(i for i, l in enumerate(text.splitlines(), 1) if "name: daisy" in l)
    assert "daisy.x = 40 is outside its range [0, 8]" in err.value.message and err.value.line == line
