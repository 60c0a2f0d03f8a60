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
    """(the bound, BFS's result); `older`: also the bound without the distinct places."""
    model = compile_dungeon(str(path))
    bfs = get_solver("bfs")(model, Budget(max_states=300_000))
    cells = goal_cells(model)
    bound = lower_bound(cells, model, model.initial)
    if older:
        return bound, bfs, lower_bound(dataclasses.replace(cells, complete=False), model, model.initial)
    return bound, bfs


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
    # bound <= its optimal cost; and the distinct-places term raises the bound on some.
    finished = raised = 0
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
        bound, bfs, old = _bound_and_optimum(path, older=True)
        if bfs.status == "budget":
            continue
        finished += 1
        raised += bound > old
        if bfs.solved:
            assert bound <= bfs.cost, (seed, text, bound, bfs.plan)
    assert finished >= 20 and raised >= 3, (finished, raised)
