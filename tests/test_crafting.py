"""Recipes as data: enumeration parameters, table properties (`per:`), a base's values
given properties by an extending domain, range folding (compiler/domain.py, ground.py,
pipeline.py), and the crafting domain that uses them (domains/crafting.yaml).

Optimal costs come from breadth-first search and A* (two solvers) and a hand derivation,
never from the solver under test."""
from __future__ import annotations

import json
import re
import textwrap

import pytest
from click.testing import CliRunner
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bcc.cli import main
from bcc.compiler import compile_dungeon
from bcc.compiler.definitions import table_row
from bcc.compiler.domain import load_domain
from bcc.errors import BccError
from bcc.solvers import Budget, get_solver

MATERIALS = ("log", "planks", "stick", "stone")


def write(tmp_path, domain: str, goal: str = "true", stock=MATERIALS, counts=None) -> str:
    """A one-row builder world on a domain of our own; `stock` lists the materials carried."""
    (tmp_path / "d.yaml").write_text(textwrap.dedent(domain))
    counts = counts or {}
    lines = "".join(f"  - {{name: s_{m}, kind: {m}, count: {counts.get(m, 0)}}}\n" for m in stock)
    (tmp_path / "w.yaml").write_text(
        "dungeon: w\ndomain: d.yaml\nheight: 3\nlegend:\n  \".\": [bedrock]\n  \"L\": [bedrock, log]\n"
        f"map: |\n  ..L\nagent: {{start: [0, 1, 0]}}\nstock:\n{lines}goal: {goal}\n")
    return str(tmp_path / "w.yaml")


RECIPES = """\
domain: d
extends: builder
types:
  material:
    values:
      stick: {id: 280}
  recipe:
    properties:
      makes: {type: material, default: air}
      count: 1
      uses: {type: int, per: material, default: 0}
    values:
      planks: {makes: planks, count: 4, uses: {log: 1}}
      stick: {makes: stick, count: 4, uses: {planks: 2}}
actions:
  craft:
    params: {r: recipe}
    pre:
      - forall s in stock . s.count >= r.uses[s.kind]
      - exists s in stock . s.kind == r.makes and s.count + r.count <= max_count
    effect:
      - forall s in stock where r.uses[s.kind] > 0 { s.count -= r.uses[s.kind] }
      - first s in stock where s.kind == r.makes { s.count += r.count }
"""


def test_an_enumeration_parameter_grounds_the_schema_once_per_value(tmp_path):
    model = compile_dungeon(write(tmp_path, RECIPES, "has(stick, 4)"))
    assert [n for n in model.action_names if n.startswith("craft")] == ["craft(planks)", "craft(stick)"]
    # break the log (1), planks from it (1), sticks from two planks (1), after walking to it (1)
    result = get_solver("bfs")(model, Budget())
    assert result.cost == 4 and result.plan[-2:] == ["craft(planks)", "craft(stick)"]


def test_table_entries_fold_into_the_grounded_action(tmp_path):
    model = compile_dungeon(write(tmp_path, RECIPES, "has(stick, 4)", counts={"planks": 3}))
    craft = model.action_index("craft(stick)")
    after = model.decode(model.apply(craft, model.initial))
    assert after["s_planks.count"] == 1 and after["s_stick.count"] == 4
    # `s.count >= r.uses[s.kind]` is `s.count >= 0` for the other stocks: folded away by the
    # count's range, so craft(stick) has two preconditions left
    assert len(model.pre_texts[craft]) == 2


def test_a_combination_whose_preconditions_are_false_is_not_grounded(tmp_path):
    # no stock of sticks: craft(stick) can never make one, so it is not an action at all
    model = compile_dungeon(write(tmp_path, RECIPES, "has(planks, 4)", stock=("log", "planks")))
    assert [n for n in model.action_names if n.startswith("craft")] == ["craft(planks)"]


def test_a_table_indexed_by_a_run_time_row(tmp_path):
    # the agent's chosen recipe is state: `uses` is read with a row known only at run time
    domain = RECIPES + textwrap.indent(textwrap.dedent("""\
    choose:
      params: {c: chooser}
      pre: c.pick == planks
      effect: c.pick = stick
    make_chosen:
      params: {c: chooser}
      pre: exists s in stock . s.count >= c.pick.uses[s.kind] and c.pick.uses[s.kind] > 0
      effect: first s in stock where s.kind == c.pick.makes { s.count += 1 }
    """), "  ") + textwrap.dedent("""\
    classes:
      chooser:
        attributes:
          pick: {type: recipe, default: planks}
    dungeon:
      lists:
        choosers: {class: chooser, fields: {pick: pick}, required: []}
    """)
    path = write(tmp_path, domain, "has(stick, 1)", counts={"planks": 2})
    text = open(path).read() + "choosers:\n  - {name: me}\n"
    open(path, "w").write(text)
    model = compile_dungeon(path)
    make = model.action_index("make_chosen")
    assert model.apply(make, model.initial) is None       # the planks recipe wants a log; none is carried
    s = model.apply(model.action_index("choose"), model.initial)
    assert model.is_goal(model.apply(make, s))            # stick recipe: 2 planks >= 2


def test_an_extending_domain_sets_properties_of_a_base_value(tmp_path):
    domain = RECIPES.replace("      stick: {id: 280}\n", "      stick: {id: 280}\n      stone: {breakable: false}\n")
    model = compile_dungeon(write(tmp_path, domain, "true"))
    assert model  # loads; stone keeps its id 1 and is no longer breakable by the builder's breaks
    material = load_domain(tmp_path / "d.yaml").enums["material"]
    i = material.values.index("stone")
    assert material.ids[i] == 1 and material.properties["breakable"][i] is False


# (text replaced, its replacement, where the error points (the first occurrence of this
# text in the new file), the message)
BAD_DATA = [
    ("uses: {log: 1}", "uses: {logg: 1}", "logg",
     "'logg' is not a value of 'material', which indexes the table recipe.uses (did you mean 'log'?)"),
    ("uses: {log: 1}", "uses: {log: many}", "many", "property 'uses' must be an int, found 'many'"),
    ("uses: {log: 1}", "uses: [log]", "[log]",
     "property 'uses' is a table: a mapping from values of 'material' to int, e.g. {name: 1}"),
    ("per: material,", "per: materials,", "materials",
     "`per` names the enumeration that indexes the table; unknown type 'materials' (did you mean 'material'?)"),
    ("default: air}", "default: aire}", "aire",
     "property 'makes' must be a value of 'material', found 'aire' (did you mean 'air'?)"),
    ("makes: planks,", "makes: plank,", "plank,",
     "property 'makes' must be a value of 'material', found 'plank' (did you mean 'planks'?)"),
    ("      stick: {id: 280}\n", "      stick: {id: 280}\n      stone: {id: 1}\n", "id: 1",
     "'stone' is listed twice in 'material': it is the base domain's value, whose id stays; an extending "
     "domain may set its properties only"),
    ("params: {r: recipe}", "params: {r: recipes}", "recipes}",
     "unknown type or class 'recipes' (did you mean 'recipe'?)"),
]


@pytest.mark.parametrize("old,new,marker,message", BAD_DATA)
def test_bad_recipe_data_is_one_positioned_line_exit_2(tmp_path, old, new, marker, message):
    assert old in RECIPES
    text = RECIPES.replace(old, new, 1)
    path = write(tmp_path, text)
    before = text[:text.index(marker)]
    line, col = before.count("\n") + 1, len(before) - before.rfind("\n")
    result = CliRunner().invoke(main, ["compile", path], catch_exceptions=False)
    assert result.exit_code == 2
    assert result.stderr.strip().splitlines() == [f"{tmp_path / 'd.yaml'}:{line}:{col}: {message}"]


SMALL = """\
domain: small
types:
  material:
    values: [air, log, planks, stick, stone, dirt, sand]
  recipe:
    properties:
      uses: {type: int, per: material, default: DEFAULT}
    values:
      one: {uses: ENTRIES}
classes:
  agent:
    attributes: {x: int}
actions:
  wait:
    params: {a: agent}
    effect: a.x = a.x
"""
SMALL_MATERIALS = ("air", "log", "planks", "stick", "stone", "dirt", "sand")
YAML_WORDS = {"y", "n", "yes", "no", "on", "off", "true", "false", "null"}


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(table=st.dictionaries(st.sampled_from(SMALL_MATERIALS), st.integers(-5, 70), max_size=7),
       default=st.integers(0, 3))
def test_any_table_reads_back_its_entries_and_the_default(tmp_path, table, default):
    """Whatever entries a table gives, its row is each entry, else the declared default,
    in the order of the `per` enumeration's values."""
    entries = "{" + ", ".join(f"{k}: {v}" for k, v in table.items()) + "}"
    path = tmp_path / "small.yaml"
    path.write_text(SMALL.replace("DEFAULT", str(default)).replace("ENTRIES", entries))
    enums = load_domain(path).enums
    assert table_row(enums, enums["recipe"], "uses", 0) == tuple(table.get(m, default) for m in SMALL_MATERIALS)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(key=st.text(alphabet="abcdefghijklmnopqrstuvwxyz_", min_size=1, max_size=12)
       .filter(lambda k: k not in SMALL_MATERIALS and k not in YAML_WORDS),
       pad=st.integers(0, 6))
def test_an_unknown_table_key_is_reported_at_the_key(tmp_path, key, pad):
    text = SMALL.replace("DEFAULT", "0").replace("ENTRIES", "{log: 2," + " " * pad + key + ": 1}")
    path = tmp_path / "small.yaml"
    path.write_text(text)
    with pytest.raises(BccError) as err:
        load_domain(path)
    line = next(n for n, l in enumerate(text.splitlines(), 1) if "one: {uses:" in l)
    col = text.splitlines()[line - 1].index("{log: 2,") + 9 + pad
    assert (err.value.line, err.value.col) == (line, col)
    assert err.value.message.startswith(f"{key!r} is not a value of 'material', which indexes the table recipe.uses")


# ---- the crafting domain ---------------------------------------------------------------

def test_crafting_bench_optimum_by_two_solvers_and_by_hand():
    # By hand: 3 logs are needed (the table takes 4 planks, 4 sticks 2, the pickaxe 3: 9,
    # and a log gives 4), so 3 breaks and 3 crafts of planks; the table is crafted and
    # placed (2), sticks (1), the pickaxe (1), the stone broken (1): 11 actions, none of
    # which moves the agent, and the stone at (3, 1, 2) is not in front of the start
    # (2, 1, 1) in any direction, so at least one move: 12. Both searches find 12.
    model = compile_dungeon("crafting_bench")
    costs = {name: get_solver(name)(model, Budget(time_limit=120)).cost for name in ("bfs", "astar")}
    assert costs == {"bfs": 12, "astar": 12}


def test_crafting_wall_is_solved_and_replays_through_the_cli(tmp_path):
    solved = CliRunner().invoke(main, ["solve", "crafting_wall", "--json"], catch_exceptions=False)
    assert solved.exit_code == 0
    result = json.loads(solved.stdout)
    # at least crafting_bench's 11 actions, a second stone mined and two blocks placed (14),
    # and a move: no stone is in front of the start
    assert result["solver"] == "build" and result["cost"] >= 15
    plan = tmp_path / "plan.txt"
    plan.write_text("\n".join(result["plan"]) + "\n")
    valid = CliRunner().invoke(main, ["validate", "crafting_wall", str(plan)], catch_exceptions=False)
    assert valid.exit_code == 0 and valid.stdout.startswith("valid")
    shown = json.loads(CliRunner().invoke(main, ["show", "crafting_wall", "--plan", str(plan), "--json"]).stdout)
    assert shown["goal_cells"]["done"] == 2 and shown["goal_cells"]["pending"] == 0


TOOLS = """\
dungeon: tools
domain: crafting
height: 3
legend:
  ".": [bedrock]
  "I": [bedrock, iron_ore]
  "F": [bedrock]
map: |
  FI.
agent: {start: F}
stock:
  - {name: picks, kind: wooden_pickaxe, count: 1}
  - {name: stone_picks, kind: stone_pickaxe, count: 0}
  - {name: ores, kind: iron_ore}
  - {name: furnaces, kind: furnace, count: 1}
  - {name: coal, kind: coal, count: 2}
  - {name: cobble, kind: cobblestone, count: 2}
  - {name: stone, kind: stone}
  - {name: ingots, kind: iron_ingot}
goal: has(stone, 2)
"""


def test_iron_ore_needs_a_stone_pickaxe(tmp_path):
    path = tmp_path / "tools.yaml"
    path.write_text(TOOLS)
    model = compile_dungeon(str(path))
    mine = model.action_index("break_east(iron_ore)")
    assert model.apply(mine, model.initial) is None
    assert model.why_not(mine, model.initial).startswith("m.tool_needed == 0 or (exists s in stock")
    path.write_text(TOOLS.replace("kind: stone_pickaxe, count: 0", "kind: stone_pickaxe, count: 1"))
    model = compile_dungeon(str(path))
    after = model.apply(model.action_index("break_east(iron_ore)"), model.initial)
    assert model.decode(after)["ores.count"] == 1


def test_smelting_needs_the_furnace_next_to_the_agent(tmp_path):
    # By hand: 2 stone need 2 smelts, and a smelt needs the furnace in front (placed: 1):
    # 3. Breadth-first search agrees.
    path = tmp_path / "tools.yaml"
    path.write_text(TOOLS.replace("  FI.\n", "  F..\n"))
    model = compile_dungeon(str(path))
    assert model.apply(model.action_index("smelt(stone)"), model.initial) is None
    result = get_solver("bfs")(model, Budget(time_limit=60))
    assert result.cost == 3 and result.plan[0].startswith("place_") and result.plan[1:] == ["smelt(stone)"] * 2


def test_a_blueprint_goal_is_listed_as_one_line():
    listed = json.loads(CliRunner().invoke(main, ["list", "--json"]).stdout)
    goals = {d["name"]: d["goal"] for d in listed["dungeons"]}
    assert goals["crafting_wall"] == "structure of 2 cells at [1, 1, 3]" and goals["crafting_bench"] == "has(cobblestone, 1)"


def test_an_atom_whose_stock_no_walk_can_raise_gets_no_greedy_search(monkeypatch):
    """On crafting_wall the cobblestone to place must be mined with a pickaxe that must be
    crafted: no gathering walk raises the stock, so each atom's greedy search (h = the walk
    alone) is skipped and gbfs finishes from where the builder stands."""
    from bcc.solvers import build
    searched = []
    real = build._Builder.reach
    monkeypatch.setattr(build._Builder, "reach", lambda self, state, atom: searched.append(atom) or real(self, state, atom))
    result = get_solver("build")(compile_dungeon("crafting_wall"), Budget(time_limit=120), improve=0)
    assert result.solved and searched == []


def test_a_starved_value_is_one_whose_exhausted_stock_is_below_its_use():
    from bcc.heuristics.goal_cells import goal_cells
    from bcc.solvers import build
    from bcc.solvers.base import Meter
    model = compile_dungeon("crafting_wall")
    cells = goal_cells(model)
    builder = build._Builder(model, cells, Meter(Budget(), None), Budget(), 10)
    (pos, value), = {cells.atoms[0]}
    (var, amount), = builder.supplies.uses[value]       # one cobblestone a block placed
    assert builder.supplies.value(model.initial, var) < amount   # none at the start
    assert not builder._starved(model.initial, value)   # no gathering tried yet
    builder.exhausted[var] = 0
    assert builder._starved(model.initial, value)
