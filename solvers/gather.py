"""Gathering for the build solver: the nearest way to raise a supply the pending atoms
take (blocks to place, say) when too little of it is held.

First a walk that ends with a supplier (an action that raises the variable: breaking a
block, picking one up), then the same walk allowed to clear cells in its way (blocked
in), then a greedy search toward the cells holding a value whose taking raises it. No
step of any of them takes what is *reserved*: a cell a pending atom rests on, or footing
built for the atom in hand (`b.keep`) -- a gathering search that took the block the
agent stands on to reach its atom undid the footing it had just built. Nothing here knows
what the variables or cells mean.
"""
from __future__ import annotations

from ..errors import ModelError
from .scaffold import stand_near

GATHER_LIMIT = 100_000   # states a walk to a supply may visit (positions, in effect)


def gather(b, state, short, todo, footing: bool = True):
    """The nearest way to raise one of the `short` variables: a walk ending with a
    supplier (or a walk that picks something up), else a greedy search toward the cells
    that hold a value taking it. (path, "ok" | "failed" | budget name)."""
    sup, apply = b.supplies, b.model.apply_fns
    before = {v: sup.value(state, v) for v in short}
    reserved = b._reserved(todo) | b.keep
    suppliers = sorted({a for v in short for a in sup.suppliers.get(v, ())})

    def gained(n):
        return any(sup.value(n, v) > k for v, k in before.items())

    def touches_reserved(s, a):
        offs = b.writes.get(a, ())
        if not offs:
            return False
        x, y, z = b.model.agent_position(s)
        return any((x + dx, y + dy, z + dz) in reserved for dx, dy, dz in offs)

    def finish(s):
        if s is not state and gained(s):
            return []
        for a in suppliers:
            try:
                n = apply[a](s)
            except ModelError:
                continue
            if n is not None and gained(n) and not b.model.is_failure(n) \
                    and not b.breaks_protected(s, a, n) and not touches_reserved(s, a):
                return [(a, n)]
        return None
    path = b.walk(state, finish, GATHER_LIMIT)
    if path:
        return path, "ok"
    if footing and b.clearers:   # blocked in: a walk that may also clear cells in its way
        walkers, b.walkers = b.walkers, b.walkers + b.clearers
        try:   # (a place is reached once, however cleared: the first way there is kept)
            path = b.walk(state, finish, GATHER_LIMIT, keep=reserved | set(b.protected))
        finally:
            b.walkers = walkers
        if path:
            return path, "ok"
    # no walk reaches a supplier: search toward the cells holding a value that takes one
    import numpy   # (here: the module is loaded with every solver, numpy is not)
    values = {v for v, lst in sup.uses.items() for var, _ in lst if var in short}
    grid = b.model.grid.array(state)
    cells = [(int(x), int(y), int(z)) for v in values for y, z, x in numpy.argwhere(grid == v)]
    cells = [c for c in cells if c not in reserved and c not in b.protected]
    offsets = {o for a in suppliers for o in (b.writes.get(a) or ())}
    places = [(x - o[0], y - o[1], z - o[2]) for x, y, z in cells for o in offsets]
    if not places:
        return None, "failed"
    pre = stand_near(b, state, places, todo) if footing else None   # (footing gathers without footing)
    if pre:
        walk = b.walk(pre[-1][1], finish, GATHER_LIMIT)
        if walk is not None:
            return pre + walk, "ok"
        walk, why = b.search(pre[-1][1], gained, places, b._floor(todo), touches_reserved)   # the last steps in
        if walk is not None:
            return pre + walk, why
    return b.search(state, gained, places, b._floor(todo), touches_reserved)
