"""Structure goals (compiler/structure.py), the build solver (solvers/build.py) and its
analysis (heuristics/goal_cells.py), `bcc generate house|wall|tower|bridge`.

Optimal costs come from breadth-first search (an independent solver), never from the
build solver's own output."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from bcc.compiler import compile_dungeon
from bcc.generate_structures import generate_structure
from bcc.heuristics.goal_cells import CellReader, goal_cells, lower_bound, support_levels
from bcc.solvers import Budget, default_solver, get_solver

from conftest import replays

HERE = Path(__file__).parent / "structures"


def bcc(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "bcc", *map(str, args)], capture_output=True, text=True, cwd=cwd)


def test_blueprint_compiles_to_its_cell_atoms():
    # steps.yaml: layer 0 "##" at (2, 1, 1), (3, 1, 1); layer 1 "#." at (2, 2, 1) stone, (3, 2, 1) air.
    model = compile_dungeon(str(HERE / "steps.yaml"))
    assert model.report["structure"] == {"atoms": 4, "at": [2, 1, 1], "size": {"width": 2, "height": 2, "depth": 1},
                                         "values": {"air": 1, "stone": 3}}
    cells = goal_cells(model)
    stone = model.grid.value_names.index("stone")
    air = model.grid.value_names.index("air")
    assert sorted(cells.atoms) == [((2, 1, 1), stone), ((2, 2, 1), stone), ((3, 1, 1), stone), ((3, 2, 1), air)]
    assert not cells.rest
    # what rests on what: the upper stone needs the one below it (builder: place on top of a block)
    levels = support_levels(cells, CellReader(model), model.initial)
    assert levels[(2, 1, 1)] == levels[(3, 1, 1)] == 0 and levels[(2, 2, 1)] == 1


def test_generated_house_counts(tmp_path):
    # 3 x 3 walls 2 high: a ring of 8 cells on 2 layers less the door's 2 = 14, a roof of 9:
    # 23 bricks; the door's 2 cells and the inside's 1 x 1 x 2 are air: 27 atoms.
    path = tmp_path / "house.yaml"
    path.write_text(generate_structure("house", 3, 3, 2, material="bricks"))
    report = compile_dungeon(str(path)).report["structure"]
    assert report["atoms"] == 27 and report["values"] == {"air": 4, "bricks": 23}
    # a 10 x 10 x 10 house: 36 x 10 + 100 = 460 cells of material less the door's 2
    assert "(458 blocks)" in generate_structure("house", 10, 10, 10)


@pytest.mark.parametrize("dungeon", ["steps.yaml", "shelter.yaml"])
def test_build_plans_replay_and_bound_is_below_them(dungeon):
    model = compile_dungeon(str(HERE / dungeon))
    result = get_solver("build")(model, Budget(time_limit=120))
    assert result.solved and replays(model, result.plan)
    assert 0 < result.lower_bound <= result.cost


def test_lower_bound_is_below_the_optimum():
    # BFS's cost is optimal (unit costs); the bound must not exceed it.
    model = compile_dungeon(str(HERE / "steps.yaml"))
    optimum = get_solver("bfs")(model, Budget(time_limit=120))
    assert optimum.solved
    bound = lower_bound(goal_cells(model), model, model.initial)
    assert 3 <= bound <= optimum.cost     # at least one action per stone to place


def test_solve_picks_build_for_cells_to_write():
    assert default_solver(compile_dungeon(str(HERE / "steps.yaml"))) == "build"
    assert default_solver(compile_dungeon("bridge")) == "astar"
    # one cell atom to write is built too; one that already holds is no work for build
    assert default_solver(compile_dungeon(str(HERE / "steps.yaml"), goal="block[2, 1, 1].kind == stone")) == "build"
    assert default_solver(compile_dungeon(str(HERE / "steps.yaml"), goal="block[2, 1, 1].kind == air")) == "astar"


def test_cli_generate_solve_validate(tmp_path):
    out = tmp_path / "house.yaml"
    r = bcc("generate", "house", "--width", 3, "--length", 3, "--height", 2, "--material", "bricks", "-o", out)
    assert r.returncode == 0, r.stderr
    r = bcc("solve", out, "--json")
    assert r.returncode == 0, r.stderr
    result = json.loads(r.stdout)
    assert result["solver"] == "build" and result["lower_bound"] <= result["cost"]
    plan = tmp_path / "plan.txt"
    plan.write_text("".join(a + "\n" for a in result["plan"]))
    r = bcc("validate", out, plan)
    assert r.returncode == 0 and "valid" in r.stdout, r.stderr


def test_goal_file_is_a_blueprint():
    r = bcc("solve", HERE / "steps.yaml", "--goal", HERE / "roof.yaml", "--json")
    assert r.returncode == 0, r.stderr
    result = json.loads(r.stdout)
    assert result["solver"] == "build" and result["goal"].startswith("structure of 1 cells")


@pytest.mark.parametrize("layers,message", [
    ('["#x"]', "'x' is not in the legend"),
    ('["#####"]', "outside the world"),
    ('["  "]', "has no cell"),
])
def test_bad_blueprints_are_one_line_at_their_place(tmp_path, layers, message):
    path = tmp_path / "bad.yaml"
    path.write_text((HERE / "steps.yaml").read_text().split("goal:")[0] +
                    f'goal:\n  structure:\n    at: [2, 1, 1]\n    legend: {{"#": stone}}\n    layers: {layers}\n')
    r = bcc("compile", path)
    assert r.returncode == 2
    assert r.stderr.count("\n") == 1 and message in r.stderr and f"{path}:" in r.stderr


def test_bad_generate_arguments_exit_2():
    r = bcc("generate", "house", "--width", 99)
    assert r.returncode == 2 and "--width 99" in r.stderr


def test_supplies_and_footing_are_read_from_the_actions():
    # builder: every place(D, logs) takes one from logs.count; an arriving agent stands on
    # the cell below and its body takes that cell and the one above (move/jump/drop alike)
    from bcc.heuristics.goal_cells import footing
    from bcc.heuristics.supplies import supplies, wanted
    model = compile_dungeon(str(HERE / "gather.yaml"))
    cells = goal_cells(model)
    log = model.grid.value_names.index("log")
    sup = supplies(model, cells)
    (var, amount), = sup.uses[log]
    assert var.label == "logs.count" and amount == 1
    assert sup.short(model.initial, [log, log]) == {var: 2}
    assert footing(model) == ({(0, -1, 0)}, {(0, 0, 0), (0, 1, 0)})
    counted = compile_dungeon(str(HERE / "gather.yaml"), goal="2 <= logs.count and logs.count <= 63")
    assert {v.label: k for v, k in wanted(counted).items()} == {"logs.count": 2}


def test_build_gathers_then_builds_on_footing():
    # no log is carried: both are broken first; the upper one is written standing one level
    # up, on a stone the solver puts down (its footing). improve=0: the builder's own plan.
    model = compile_dungeon(str(HERE / "gather.yaml"))
    assert default_solver(model) == "build"
    result = get_solver("build")(model, Budget(time_limit=120), improve=0)
    assert result.solved and replays(model, result.plan)
    assert 0 < result.lower_bound <= result.cost
    assert any(a.startswith("break_") for a in result.plan) and "place_south(agent, stones)" in result.plan


def test_build_gathers_an_amount_the_goal_asks_for():
    # 2 <= logs.count: walk 3 east to (4, 1, 1), break (5, 1, 1), step into it, break
    # (6, 1, 1): 6 actions, and no plan is shorter (each break needs the agent beside the
    # log at feet level, and x = 4 is 3 moves away).
    model = compile_dungeon(str(HERE / "gather.yaml"), goal="2 <= logs.count")
    assert default_solver(model) == "build"
    result = get_solver("build")(model, Budget(time_limit=120), improve=0)
    assert result.solved and replays(model, result.plan) and result.cost == 6


@pytest.mark.slow
def test_build_on_gather_is_optimal_after_improving():
    # BFS (independent, unit costs) gives the optimum; build's short plan goes to A*
    model = compile_dungeon(str(HERE / "gather.yaml"))
    optimum = get_solver("bfs")(model, Budget(time_limit=300))
    result = get_solver("build")(model, Budget(time_limit=300))
    assert optimum.solved and result.solved and replays(model, result.plan)
    assert result.lower_bound <= optimum.cost == result.cost


def test_action_elimination_takes_a_detour_out():
    # the optimal 6-action plan for 2 <= logs.count (see above) with a step west and back
    # in front: elimination must give a plan that still reaches the goal, shorter than 8
    # and not shorter than the optimum
    from bcc.solvers.shorten import eliminate
    model = compile_dungeon(str(HERE / "gather.yaml"), goal="2 <= logs.count")
    names = ["move_west", "move_east", "move_east", "move_east", "move_east", "break_east", "move_east", "break_east"]
    assert replays(model, names)
    out = [model.action_names[a] for a in eliminate(model, [model.action_index(n) for n in names])]
    assert replays(model, out) and 6 <= len(out) < len(names)


def test_solve_picks_build_for_a_cell_with_nothing_below():
    # steps.yaml: one stone at (2, 2, 1), one level up with nothing under it: the stone
    # below must come first, so the goal is built, not searched by A*
    assert default_solver(compile_dungeon(str(HERE / "steps.yaml"), goal="block[2, 2, 1].kind == stone")) == "build"


def test_build_clears_its_way_to_a_supply(tmp_path):
    # a corridor one cell deep and three high: a stone at (3, 1, 0) stands between the
    # agent at x = 1 and a log lying on the ground at x = 5 (an item: no cell holds it, so
    # only a walk finds it); no jump fits under the ceiling and there is no way round, so
    # the stone must be broken: move, break, move, move, move onto the log (5, by hand)
    path = tmp_path / "corridor.yaml"
    path.write_text("dungeon: corridor\ndomain: builder\nwidth: 7\ndepth: 1\nheight: 3\n"
                    "blocks: |\n  0..6 0 0 bedrock\n  3 1 0 stone\n"
                    "items:\n  - {name: log0, kind: log, at: [5, 1, 0]}\n"
                    "stock:\n  - {name: logs, kind: log, count: 0}\n  - {name: stones, kind: stone, count: 0}\n"
                    "agent:\n  start: [1, 1, 0]\ngoal: 1 <= logs.count\n")
    model = compile_dungeon(str(path))
    result = get_solver("build")(model, Budget(time_limit=120), improve=0)
    assert result.solved and replays(model, result.plan) and result.cost == 5
    # the builder's own walk gets there (not its gbfs fallback)
    from bcc.solvers.base import Meter
    from bcc.solvers.build import _Builder
    builder = _Builder(model, goal_cells(model, allow_empty=True), Meter(Budget(time_limit=60), None), None, 4000)
    plan, state, why = builder.run(model.initial)
    assert why is None and model.is_goal(state) and len(plan) == 5
