"""The builder domain (domains/builder.yaml): MinePlanner's moves in YAML.

Optimal costs come from hand derivations (in comments) and agree between A* with LM-cut,
blind A* and breadth-first search. The simulator is held against tests/builder_reference.py,
a literal reading of MinePlanner's PDDL, on random worlds (hypothesis)."""
from __future__ import annotations

import random
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import builder_reference as ref
from bcc.compiler import compile_dungeon
from bcc.solvers import Budget, get_solver

HERE = Path(__file__).parent / "builder"


def solve_cost(path, solver="astar", **options) -> int:
    model = compile_dungeon(str(path))
    result = get_solver(solver)(model, Budget(time_limit=60), **options)
    assert result.solved
    return result.cost


@pytest.mark.parametrize("solver,options", [("astar", {"heuristic": "lmcut"}), ("astar", {"heuristic": "blind"}),
                                            ("bfs", {})])
def test_steps_optimal_cost_4(solver, options):
    # S . # . G on bedrock, a stone on the '#' column at feet level. Walking needs the
    # stone gone (break: 1 + 4 moves = 5); jumping onto it and dropping off the far side
    # is move, jump, drop, move = 4, and no plan is shorter: 4 cells east at one per action.
    assert solve_cost(HERE / "steps.yaml", solver, **options) == 4


@pytest.mark.parametrize("solver,options", [("astar", {"heuristic": "lmcut"}), ("bfs", {})])
def test_tower_optimal_cost_3(solver, options):
    # The diamond lies at y = 3 on a two-high wall at x = 2; the agent stands at y = 1.
    # Feet rise one level per jump, so two jumps; the first needs a block at feet level in
    # front of the agent, which x = 1 lacks: one place. 3 actions, and no fewer.
    assert solve_cost(HERE / "tower.yaml", solver, **options) == 3


def test_walking_onto_an_item_picks_it_up_when_there_is_room(tmp_path):
    # No stone to climb with, 64 diamonds carried: the only way up is to place a diamond
    # (63 left), jump twice and pick the lying one up on arrival (64 again).
    text = (HERE / "tower.yaml").read_text().replace("count: 1}", "count: 0}")
    text = text.replace("- {name: gems, kind: diamond}", "- {name: gems, kind: diamond, count: 64}")
    (tmp_path / "full.yaml").write_text(text.replace("goal: has(diamond, 1)", "goal: agentAt(agent, 2, 3, 0)"))
    model = compile_dungeon(str(tmp_path / "full.yaml"))
    result = get_solver("bfs")(model, Budget(time_limit=30))
    assert result.plan == ["place_east(agent, gems)", "jump_east", "jump_east"]
    state = model.initial
    for name in result.plan:
        state = model.apply(model.action_index(name), state)
    assert model.decode(state)["gems.count"] == 64 and not model.decode(state)["gem.present"]


def test_blocks_listed_by_position_build_the_same_world_as_the_map(tmp_path):
    listed = compile_dungeon(str(HERE / "tower.yaml"))
    mapped = (HERE / "tower.yaml").read_text().replace(
        "width: 5\ndepth: 1\n", "legend:\n  '.': [bedrock]\n  '#': [bedrock, stone, stone]\nmap: |\n  ..#..\n"
    ).replace("  0..4 0 0 bedrock     # the floor\n  2 1..2 0 stone       # a wall two blocks high\n", "  0 0 0 bedrock\n")
    (tmp_path / "mapped.yaml").write_text(mapped)
    other = compile_dungeon(str(tmp_path / "mapped.yaml"))
    assert listed.grid.static == other.grid.static and listed.initial == other.initial


@pytest.mark.parametrize("line,message", [
    ("0..4 0 0 bedrok", "8:12: unknown block type 'bedrok' (did you mean 'bedrock'?)"),
    ("0..9 0 0 bedrock", "8:3: x = 9 is outside the world (0..4)"),
    ("4..0 0 0 bedrock", "8:3: the range 4..0 of x is empty"),
    ("0 0 bedrock", "8:3: a line of `blocks` is `X Y Z NAME`"),
])
def test_bad_blocks_lines_are_one_positioned_error(tmp_path, line, message):
    bad = tmp_path / "bad.yaml"
    bad.write_text((HERE / "tower.yaml").read_text().replace("0..4 0 0 bedrock ", line + " "))
    out = subprocess.run([sys.executable, "-m", "bcc", "solve", str(bad)], capture_output=True, text=True)
    assert out.returncode == 2
    assert out.stderr.strip().startswith(f"{bad}:{message}"), out.stderr


MATERIALS = ["stone", "dirt", "bedrock"]


def _dungeon_text(w: ref.World, stocks: list) -> str:
    lines = [f"{x} {y} {z} {m}" for (x, y, z), m in sorted(w.solid.items())]
    items = "".join(f"  - {{name: i{k}, kind: {m}, at: [{c[0]}, {c[1]}, {c[2]}]}}\n"
                    for k, (m, c, _) in enumerate(w.items))
    stock = "".join(f"  - {{name: {m}_stock, kind: {m}, count: {w.counts[m]}}}\n" for m in stocks)
    return (f"dungeon: random\ndomain: builder\nwidth: {w.width}\ndepth: {w.depth}\nheight: {w.height}\n"
            "blocks: |\n" + "".join(f"  {l}\n" for l in lines) + (f"items:\n{items}" if items else "")
            + f"stock:\n{stock}agent:\n  start: [{w.at[0]}, {w.at[1]}, {w.at[2]}]\ngoal: agentAt(agent, 0, 0, 0)\n")


def _world(seed: int) -> ref.World:
    rnd = random.Random(seed)
    width, depth, height = rnd.randint(2, 4), rnd.randint(1, 3), rnd.randint(4, 6)
    solid = {}
    for x in range(width):
        for z in range(depth):
            for y in range(rnd.choice([0, 1, 1, 2, 2, 3])):
                solid[(x, y, z)] = rnd.choice(MATERIALS)
    floor = [(x, z) for x in range(width) for z in range(depth) if (x, 0, z) in solid]
    if not floor:
        solid[(0, 0, 0)] = "bedrock"
        floor = [(0, 0)]
    x, z = rnd.choice(floor)
    y = max(yy for (xx, yy, zz) in solid if (xx, zz) == (x, z)) + 1
    if y + 1 >= height:
        height = y + 2
    items = []
    for _ in range(rnd.randint(0, 3)):
        c = (rnd.randrange(width), rnd.randint(1, 3), rnd.randrange(depth))
        if c not in solid and c != (x, y, z):
            items.append([rnd.choice(["stone", "dirt"]), c, True])
    counts = {"stone": rnd.choice([0, 1, 63, 64]), "dirt": rnd.choice([0, 2])}
    return ref.World(width, depth, height, solid, items, counts, (x, y, z))


def _bcc_world(model, state, names) -> tuple:
    d = model.decode(state)
    solid = {}
    g = model.grid
    for x in range(g.width):
        for y in range(g.height):
            for z in range(g.depth):
                v = g.value_names[g.cell(state, x, y, z)]
                if v != "air":
                    solid[(x, y, z)] = v
    items = [d[f"i{k}.present"] for k in range(len(names))]
    counts = {m: d[f"{m}_stock.count"] for m in ("stone", "dirt")}
    return model.agent_position(state), solid, items, counts


@settings(max_examples=40, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 10**6))
def test_simulator_agrees_with_a_literal_reading_of_mineplanner(seed):
    world = _world(seed)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "random.yaml"
        path.write_text(_dungeon_text(world, ["stone", "dirt"]))
        model = compile_dungeon(str(path), prune=False)
    state, rnd = model.initial, random.Random(seed)
    for _ in range(25):
        options = []
        for i, name in enumerate(model.action_names):
            base, _, stock = name.partition("(agent, ")
            expected = ref.apply(world, base, stock.rstrip(")").replace("_stock", "") or None)
            got = model.apply(i, state)
            assert (got is None) == (expected is None), (seed, name, world.at)
            if got is not None:
                at, solid, items, counts = _bcc_world(model, got, world.items)
                assert at == expected.at and solid == expected.solid, (seed, name)
                assert items == [i[2] for i in expected.items] and counts == expected.counts, (seed, name)
                options.append((got, expected))
        if not options:
            break
        state, world = rnd.choice(options)


def test_manhattan_counts_a_jump_as_one_step():
    # A jump moves along x and y at once: the distance heuristic must not count it twice.
    # On steps.yaml the optimum is 4 (above); with an overestimate A* returned 5.
    model = compile_dungeon(str(HERE / "steps.yaml"))
    assert model.position_steps == ((0, 0, 0), (1, 0, 0), (1, 1, 0))
    from bcc.heuristics.position import manhattan
    h = manhattan(model)
    assert h(model.initial) == 4        # max(|dx| + |dz|, |dy|) = max(4, 0)
    assert solve_cost(HERE / "steps.yaml", "astar", heuristic="manhattan") == 4


def test_minecraft_distances_are_unchanged():
    # move_forward's step is read from a table (dx[facing]): unknown here, so one cell per action.
    assert compile_dungeon("bridge").position_steps is None
