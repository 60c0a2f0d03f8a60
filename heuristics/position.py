"""Heuristics of the agent's position: `blind` (0 everywhere) and `manhattan`.

`manhattan` is the distance from the agent's position to the nearest position at which
the goal may hold (found by the compiler's over-approximation), counted in steps: where
the compiler knows how far each action moves the agent along each axis (compiler/steps.py),
it is the largest, over groups of axes, of the L1 distance over a group divided by the
most one action changes it (a jump up-and-forward moves along x and y at once: the
distance is max(|dx| + |dz|, |dy|), not |dx| + |dy| + |dz|). Never above the cost when
actions cost >= 1, and consistent. Where the steps are unknown, one cell per action.
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
    groups = _axis_groups(model.position_steps, len(sizes))
    if groups is None:
        table = tuple(_l1_distances(seeds, sizes, strides))
    else:
        parts = [[-(-v // most) if v != math.inf else v for v in _l1_distances(seeds, sizes, strides, group)]
                 for group, most in groups]
        table = tuple(max(vs) for vs in zip(*parts)) if parts else tuple([0] * math.prod(sizes))
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


def _axis_groups(steps, n_axes: int):
    """[(axes, most)]: the groups of axes worth a distance of their own, each with the most
    one action moves the agent over it (the sum of its axes' moves). A group is left out
    when a larger group moves as little (its distance is never smaller) or when it splits
    into two groups whose moves add up to its own (the larger of their quotients is never
    smaller). None when the steps are unknown."""
    if steps is None:
        return None
    import itertools
    subsets = [frozenset(c) for k in range(1, n_axes + 1) for c in itertools.combinations(range(n_axes), k)]
    most = {g: max((sum(v[a] for a in g) for v in steps), default=0) for g in subsets}
    keep = []
    for g in subsets:
        if most[g] == 0:
            continue
        if any(g < h and most[h] == most[g] for h in subsets):
            continue
        halves = [frozenset(c) for k in range(1, len(g)) for c in itertools.combinations(sorted(g), k)]
        if any(most[h] and most[g - h] and most[h] + most[g - h] == most[g] for h in halves):
            continue
        keep.append((tuple(sorted(g)), most[g]))
    return keep


def _l1_distances(seeds: dict, sizes: list, strides: list, axes=None) -> list:
    """min over seeds (flat index -> cost) of cost + the L1 distance over `axes` (default:
    all), for every point of the box `sizes`: the separable distance transform, a forward
    and a backward sweep along each axis in turn (along an axis outside `axes`, a step
    costs 0), linear in the box, without numpy."""
    total = math.prod(sizes)
    d = [math.inf] * total
    for i, c in seeds.items():
        d[i] = c
    for axis, (n, st) in enumerate(zip(sizes, strides)):
        step = 1 if axes is None or axis in axes else 0
        for first in range(total):
            if (first // st) % n:
                continue   # not the first point of a line along this axis
            last = first + (n - 1) * st
            for i in range(first + st, last + 1, st):
                if d[i - st] + step < d[i]:
                    d[i] = d[i - st] + step
            for i in range(last - st, first - 1, -st):
                if d[i + st] + step < d[i]:
                    d[i] = d[i + st] + step
    return [int(v) if v != math.inf else v for v in d]
