"""Heuristics of the agent's position: `blind` (0 everywhere) and `manhattan`.

`manhattan` is the distance from the agent's position to the nearest position at which
the goal may hold (found by the compiler's over-approximation, so it never overestimates
when each action moves the agent at most one cell at cost >= 1).
"""
from __future__ import annotations

import math

from ..model import Model


def blind(model: Model, time_limit: float | None = None):
    return lambda state: 0


def manhattan(model: Model, time_limit: float | None = None):
    goals = model.goal_positions
    if goals is None:
        return blind(model)
    dyn = [(axis, p) for axis, p in enumerate(model.position) if p is not None]
    if not dyn:
        return blind(model)
    if len(goals) == 0:
        return lambda state: math.inf  # the goal holds at no position: nothing can reach it
    # One table over the dynamic axes' ranges: h = table[flattened position].
    by_index = {v.index: v for v in model.variables}
    ranges = [(index, lo, by_index[index].hi - lo + 1) for _, (index, lo) in dyn]
    sizes = [n for _, _, n in ranges]
    strides = []
    acc = 1
    for n in reversed(sizes):
        strides.append(acc)
        acc *= n
    strides.reverse()
    seeds: dict = {}
    for goal in goals:
        static_cost = sum(abs(goal[axis] - value) for axis, value in enumerate(model.position_static)
                          if value is not None)
        flat = sum((goal[axis] - lo) * st for (axis, _), (_, lo, _), st in zip(dyn, ranges, strides))
        seeds[flat] = min(seeds.get(flat, math.inf), static_cost)
    table = tuple(_l1_distances(seeds, sizes, strides))
    if len(ranges) == 2:
        (i0, _, _), (i1, _, n1) = ranges  # the common case, without a loop
        return lambda s: table[s[i0] * n1 + s[i1]]
    idx = [(i, st) for (i, _, _), st in zip(ranges, strides)]
    return lambda s: table[sum(s[i] * st for i, st in idx)]


def position_blind(model: Model) -> bool:
    """Whether `manhattan` (and the pattern database, which abstracts the same goal test
    to positions) is 0 in every state: the goal may hold at every position the agent can
    take, as for a goal about carrying things. A* then searches blind, in its fast loop."""
    goals = model.goal_positions
    if not goals:
        return False
    by_index = {v.index: v for v in model.variables}
    box = math.prod(by_index[index].hi - lo + 1 for p in model.position if p is not None for index, lo in [p])
    return len(set(goals)) >= box


def _l1_distances(seeds: dict, sizes: list, strides: list) -> list:
    """min over seeds (flat index -> cost) of cost + the L1 distance, for every point of the
    box `sizes`: the separable distance transform, a forward and a backward sweep along
    each axis in turn (linear in the box, without numpy)."""
    total = math.prod(sizes)
    d = [math.inf] * total
    for i, c in seeds.items():
        d[i] = c
    for n, st in zip(sizes, strides):
        for first in range(total):
            if (first // st) % n:
                continue   # not the first point of a line along this axis
            last = first + (n - 1) * st
            for i in range(first + st, last + 1, st):
                if d[i - st] + 1 < d[i]:
                    d[i] = d[i - st] + 1
            for i in range(last - st, first - 1, -st):
                if d[i + st] + 1 < d[i]:
                    d[i] = d[i + st] + 1
    return [int(v) if v != math.inf else v for v in d]
