"""The build solver's admissible lower bound (heuristics/goal_cells.lower_bound), held
against breadth-first search's optimum (unit costs) on hand-made and random builder
worlds: it must never exceed it."""
from __future__ import annotations

import dataclasses
import random

import pytest

from bcc.compiler import compile_dungeon
from bcc.heuristics.goal_cells import goal_cells, lower_bound
from bcc.solvers import Budget, get_solver
from test_cell_reach import _text

FLOOR = {(x, 0, 0): "bedrock" for x in range(8)}


def _bound_and_optimum(path, older: bool = False) -> tuple:
    """(the bound, BFS's result); `older`: also the bound without the walk."""
    model = compile_dungeon(str(path))
    bfs = get_solver("bfs")(model, Budget(max_states=300_000))
    cells = goal_cells(model)
    bound = lower_bound(cells, model, model.initial)
    if older:
        return bound, bfs, lower_bound(dataclasses.replace(cells, complete=False), model, model.initial)
    return bound, bfs


def _tally(path, counts: dict, baseline: int | None = None) -> None:
    """Count a random case BFS finished, and whether the bound beat `baseline` (default: the
    bound without the walk); the bound must not exceed BFS's optimum."""
    bound, bfs, old = _bound_and_optimum(path, older=True)
    if bfs.status == "budget":
        return
    counts["finished"] += 1
    counts["raised"] += bound > (old if baseline is None else baseline)
    if bfs.solved:
        assert bound <= bfs.cost, (path.read_text(), bound, bfs.plan)


def test_two_far_apart_blocks_need_two_places_to_stand(tmp_path):
    # Stones at x = 2 and x = 6 on a one-row floor, the agent at x = 0: each is placed
    # from a cell beside it, and the two sets of such cells do not meet, so the agent
    # stands in two places it does not start on: at least 2 moves and 2 places, 4 (the
    # older bound, 2 places + the walk of 1 to the nearest standing cell, said 3).
    # BFS: move, place, jump onto it, drop, move, move, place = 7.
    path = tmp_path / "two.yaml"
    path.write_text(_text(8, 1, 4, FLOOR, (0, 1, 0), "block[2, 1, 0].kind == stone and block[6, 1, 0].kind == stone",
                          {"stone": 2}))
    bound, bfs = _bound_and_optimum(path)
    assert bfs.solved and bfs.cost == 7
    assert bound == 4


def test_blocks_that_share_a_standing_place_count_once(tmp_path):
    # Stones at x = 2 and x = 4 can both be placed from x = 3: no two atoms with disjoint
    # standing places, so the places term says 1 move, as the walk to the nearest standing
    # place (x = 1) does: 2 + 1 = 3, as before.
    path = tmp_path / "shared.yaml"
    path.write_text(_text(8, 1, 4, FLOOR, (0, 1, 0), "block[2, 1, 0].kind == stone and block[4, 1, 0].kind == stone",
                          {"stone": 2}))
    bound, bfs = _bound_and_optimum(path)
    assert bfs.solved and bound <= bfs.cost
    assert bound == 3


@pytest.mark.slow
def test_the_bound_never_exceeds_the_optimum_on_random_worlds(tmp_path):
    # 40 random one-row worlds with two or three stones to place: wherever BFS finishes,
    # bound <= its optimal cost; and the walk raises the bound on some.
    counts = {"finished": 0, "raised": 0}
    for seed in range(40):
        rnd = random.Random(seed)
        width = rnd.randint(4, 7)
        solid = {(x, 0, 0): "bedrock" for x in range(width)}
        for x in rnd.sample(range(width), rnd.randint(0, 2)):
            solid[(x, 1, 0)] = "dirt"
        free = [x for x in range(width) if (x, 1, 0) not in solid]
        if len(free) < 3:
            continue
        at, *goal = rnd.sample(free, min(len(free), rnd.randint(3, 4)))
        text = _text(width, 1, 4, solid, (at, 1, 0), " and ".join(f"block[{x}, 1, 0].kind == stone" for x in goal),
                     {"stone": len(goal), "dirt": 0})
        path = tmp_path / f"case{seed}.yaml"
        path.write_text(text)
        _tally(path, counts)
    assert counts["finished"] >= 20 and counts["raised"] >= 3, counts


MASON = """dungeon: case
domain: mason
description: a small mason world for the lower bound's tests
height: 4
legend:
  ".": [bedrock]
  "S": [bedrock]
  "#": [bedrock, stone]
map: |
{rows}
agent:
  start: S
stock:
  - {{name: bricks_stock, kind: bricks, count: {count}, full: 0}}
goal: {goal}
"""


def _mason(rows: list[str], goal: list[tuple]) -> str:
    return MASON.format(rows="\n".join("  " + r for r in rows), count=len(goal),
                        goal=" and ".join(f"block[{x}, {y}, {z}].kind == bricks" for x, y, z in goal))


def test_a_climbing_builder_still_walks_between_far_apart_places(tmp_path):
    # The mason domain: climbing writes the cell the agent stands in and moves it up, so no
    # bound from places in three dimensions; but no writer moves the agent along x or z, so
    # seen from above, bricks at x = 2 and x = 7 (z = 1) are written from the cells around
    # each or its own: {1, 2, 3} x {1} and {2} x {0, 2}, the same about x = 7, which do not
    # meet. From x = 0 the agent walks 1 to the first set and 3 from it to the second
    # (x = 3 to x = 6), one cell a move: 4 moves and 2 placements, 6. BFS: east 3, place
    # west, east 3, place east = 8.
    path = tmp_path / "apart.yaml"
    path.write_text(_mason([".........", "S........", "........."], [(2, 1, 1), (7, 1, 1)]))
    bound, bfs = _bound_and_optimum(path)
    assert bfs.solved and bfs.cost == 8
    assert bound == 6


@pytest.mark.slow
def test_the_bound_never_exceeds_the_optimum_in_random_mason_worlds(tmp_path):
    # 40 random mason worlds (climbing, descending, climbing down and sliding move the agent
    # up and down), two or three bricks to place, some of them on top of others: wherever
    # BFS finishes, bound <= its optimal cost; and the walk raises the bound above the
    # placements on some.
    counts = {"finished": 0, "raised": 0}
    for seed in range(40):
        rnd = random.Random(seed)
        width, depth = rnd.randint(4, 7), rnd.randint(1, 3)
        cells = [(x, z) for x in range(width) for z in range(depth)]
        start, *rest = rnd.sample(cells, len(cells))
        stones = set(rest[:rnd.randint(0, 2)])
        free = [c for c in rest if c not in stones]
        goal = []
        for x, z in free[:rnd.randint(2, 3)]:
            goal.append((x, 1, z))
            if rnd.random() < 0.3:
                goal.append((x, 2, z))
        rows = ["".join("S" if (x, z) == start else "#" if (x, z) in stones else "." for x in range(width))
                for z in range(depth)]
        path = tmp_path / f"mason{seed}.yaml"
        path.write_text(_mason(rows, goal))
        _tally(path, counts, len(goal))
    assert counts["finished"] >= 20 and counts["raised"] >= 5, counts
