"""Heuristics over a compiled model; each `make(model)` returns h(state) -> number.

`pdb` (the default) looks up the compiler's pattern database: maze distance with turns.

`manhattan` is the distance from the agent's position to the nearest position at which
the goal may hold (found by the compiler's over-approximation, so it never overestimates
when each action moves the agent at most one cell at cost >= 1).
"""
from __future__ import annotations

import math

from ..model import Model


def blind(model: Model):
    return lambda state: 0


def manhattan(model: Model):
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


def pdb(model: Model):
    """The pattern database the compiler builds (compiler/patterns.py): exact distances in
    an abstraction over the agent's position and facing; falls back to manhattan."""
    db = model.data("pattern_database")
    if db is None:
        return manhattan(model)
    table = db.table
    if len(db.indices) == 3:
        (i0, i1, i2), (_, n1, n2) = db.indices, db.sizes  # the common case, without a loop
        return lambda s: table[(s[i0] * n1 + s[i1]) * n2 + s[i2]]
    return lambda s: table[db.index_of(s)]


def counting(model: Model, time_limit: float | None = None):
    """Exact distances in the compiler's counting abstraction (compiler/counting.py): every
    variable and the cells the goal needs changed kept exactly, the other cells counted.
    Admissible and consistent; falls back to blind search where it cannot be built."""
    db = model.data("counting_database", time_limit=time_limit)
    if db is None:
        h = blind(model)
        h.fallback = "blind"
        return h
    from ..model import cell_entries
    base, variables, parts, part, get, shift = db.base, db.variables.get, db.parts.get, db.part, db.table.get, db.shift

    project = db.project if db.projected else None
    part_of: dict = {}   # a state's changed cells (its tail) -> its cell part's id: states share a few tails

    def h(s):
        v = variables(project(s) if project else s[:base])
        tail = s[base:]
        r = part_of.get(tail, -1)
        if r == -1:
            r = part_of[tail] = parts(part(cell_entries(tail)))
        d = None if v is None or r is None else get(v << shift | r)
        return 0 if d is None else d   # None: never met by the abstraction (cannot happen); 0 stays admissible
    return h


def _relaxed(kind: str):
    def make(model: Model, time_limit: float | None = None):
        from .relaxed_heuristics import relaxed_of
        r = relaxed_of(model, time_limit)
        if r is None:  # the relaxed view is too big for its limits: search blind, say so
            h = blind(model)
            h.fallback = "blind"
            return h
        return getattr(r, kind)
    make.__doc__ = f"{kind} on the relaxed view of the model (solvers/relaxed_heuristics.py)"
    return make


# Never above the true cost, so 0 on every goal state: a state they rate above 0 is no goal
ADMISSIBLE = frozenset({"blind", "manhattan", "pdb", "hmax", "lmcut", "counting"})
HEURISTICS = {"pdb": pdb, "manhattan": manhattan, "blind": blind,
              "hmax": _relaxed("hmax"), "hadd": _relaxed("hadd"), "hff": _relaxed("hff"), "lmcut": _relaxed("lmcut"),
              "counting": counting}
