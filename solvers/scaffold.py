"""Footing for the build solver: blocks put where the agent must stand, or under a cell
that must rest on something, when no walk reaches a place from which to write a cell.

The build solver (solvers/build.py) walks to a *standing place* of the next atom. In a
domain where the agent stands only on something (heuristics/goal_cells.footing), a place
in the air is out of reach until its footing is built: a cell made solid, itself written
from a standing place that may need footing in turn (at most MAX_DEPTH deep: a stair).
The block used is a *spare* value: one whose supply the pending atoms do not need up to
what is carried. Nothing here knows what the cells or values mean.
"""
from __future__ import annotations

from ..errors import ModelError

MAX_DEPTH = 3
CANDIDATES = 6      # standing places tried, nearest first


def _add(p, o):
    return (p[0] + o[0], p[1] + o[1], p[2] + o[2])


def _distance(a, b) -> int:
    return abs(a[0] - b[0]) + abs(a[1] - b[1]) + abs(a[2] - b[2])


def _inside(grid, p) -> bool:
    return 0 <= p[0] < grid.width and 0 <= p[1] < grid.height and 0 <= p[2] < grid.depth


def spare_value(b, state, todo):
    """A value the agent can write without taking what the pending atoms need: the one with
    the most left over (a value that takes nothing counts as plenty), or None."""
    sup, best, most = b.supplies, None, 0
    demand = sup.demand(todo.values()) if sup else {}
    for v, achievers in b.cells.achievers.items():
        if v is None or v == b.model.grid.default or not any(not a.moves for a in achievers):
            continue
        uses = sup.uses.get(v, ()) if sup else ()
        left = min((sup.value(state, var) - demand.get(var, 0) - k + 1 for var, k in uses), default=1 << 20)
        if left > most:
            best, most = v, left
    return best


def gather_spare(b, state, todo):
    """A path [(action, state)] that gathers one unit of a supply no pending atom takes
    (the nearest), for a value that can then be written anywhere; None if none is found."""
    sup = b.supplies
    if not sup:
        return None
    demand = sup.demand(todo.values(), b.wanted)
    short = {var: 1 for v, uses in sup.uses.items()
             if v is not None and v != b.model.grid.default and any(not a.moves for a in b.cells.achievers.get(v, ()))
             for var, _ in uses if var not in demand and sup.suppliers.get(var)}
    if not short:
        return None
    path, _ = b.gather(state, short, todo, footing=False)
    return path


def write_cell(b, s, cell, value):
    """From `s`, one achiever (that does not move the agent) writes `value` at `cell`:
    [(action, state)], or None."""
    here = b.model.agent_position(s)
    for a in b.cells.achievers.get(value, ()):
        if a.moves or _add(here, a.write) != cell:
            continue
        try:
            n = b.model.apply_fns[a.action](s)
        except ModelError:
            continue
        if n is not None and b.read(n, *cell) == value and not b.breaks_protected(s, a.action, n):
            return [(a.action, n)]
    return None


def make_solid(b, state, cell, todo, depth=MAX_DEPTH):
    """A path [(action, state)] after which `cell` holds something (a pending atom's own
    value when it is one, else a spare value, gathered if none is carried), what it rests
    on first, then a standing place (its footing built when no walk reaches one); None if
    not found."""
    read, default, agent = b.read, b.model.grid.default, b.model.agent_position
    if read(state, *cell) != default:
        return []
    if depth < 0 or not _inside(b.model.grid, cell) or cell in b.protected:
        return None
    value = todo.get(cell)
    if value == default:
        return None
    path = []
    rests = b.rests_on.get(value, ()) if value is not None else b.rests_on_any
    for rel in rests:
        sub = make_solid(b, state, _add(cell, rel), todo, depth - 1)
        if sub is None:
            return None
        b.keep.add(_add(cell, rel))
        path += sub
        state = path[-1][1] if path else state
    writers = b.cells.achievers.get(value, ()) if value is not None else \
        [a for v, lst in b.cells.achievers.items() if v is not None and v != default for a in lst]
    places = {_add(cell, (-a.write[0], -a.write[1], -a.write[2])) for a in writers if not a.moves}

    chosen = [value if value is not None else spare_value(b, state, todo)]

    def write(s):
        return None if chosen[0] is None else write_cell(b, s, cell, chosen[0])
    walk = b.walk(state, write, b.local_limit) if chosen[0] is not None else None
    if walk is None:
        walk = b.walk(state, lambda s: [] if agent(s) in places else None, b.local_limit)
        if walk is None and depth > 0:
            pre = stand_near(b, state, places, todo, depth - 1)
            if pre:
                more = b.walk(pre[-1][1], lambda s: [] if agent(s) in places else None, b.local_limit)
                walk = pre + more if more is not None else None
        if walk is None:
            return None
        path += walk
        state = path[-1][1] if path else state
        chosen[0] = value if value is not None else spare_value(b, state, todo)
        walk = b.walk(state, write, b.local_limit) if chosen[0] is not None else None
        if walk is None and value is None:   # nothing to spare: gather one, then come back
            more = gather_spare(b, state, todo)
            if not more:
                return None
            path += more
            chosen[0] = spare_value(b, more[-1][1], todo)
            walk = b.walk(more[-1][1], write, b.local_limit) if chosen[0] is not None else None
    if walk is None:
        return None
    b.keep.add(cell)    # footing in use: no supply is taken from it until the atom is written
    return path + walk


def stand_near(b, state, places, todo, depth=MAX_DEPTH):
    """A path [(action, state)] that builds the footing of one of `places` (nearest first;
    a place whose body cells are free), so a walk can reach it; None if none is found.
    An empty path when some place needs no footing."""
    solid, free = b.footing
    if not solid:
        return None
    read, default, grid = b.read, b.model.grid.default, b.model.grid
    here = b.model.agent_position(state)
    tried = 0
    for st in sorted(set(places), key=lambda p: _distance(here, p)):
        if tried >= CANDIDATES:
            break
        if not _inside(grid, st) or any(read(state, *_add(st, o)) != default or b.protected.get(_add(st, o), default)
                                        != default for o in free):
            continue
        tried += 1
        path, s = [], state
        for o in solid:
            sub = make_solid(b, s, _add(st, o), todo, depth)
            if sub is None:
                break
            path += sub
            s = path[-1][1] if path else s
        else:
            if path:
                return path
    return None
