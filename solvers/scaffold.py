"""Footing for the build solver: blocks put where the agent must stand, or under a cell
that must rest on something, when no walk reaches a place from which to write a cell.

The build solver (solvers/build.py) walks to a *standing place* of the next atom. In a
domain where the agent stands only on something (heuristics/goal_cells.footing), a place
in the air is out of reach until its footing is built: a cell made solid, itself written
from a standing place that may need footing in turn (at most MAX_DEPTH deep: a stair;
DEEP_DEPTH in the build solver's last try: a place ten levels up, say).
The block used is a *spare* value: one whose supply the pending atoms do not need up to
what is carried. Nothing here knows what the cells or values mean.
"""
from __future__ import annotations

import functools

from ..errors import ModelError

MAX_DEPTH = 3
DEEP_DEPTH = 6      # the footing depth of the build solver's last try (solvers/build_finish.py): a taller stair
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
    demand = sup.demand(todo.values(), b.wanted) if sup else {}
    for v, achievers in b.cells.achievers.items():
        if v is None or v == b.model.grid.default or not any(not a.moves for a in achievers):
            continue
        uses = sup.uses.get(v, ()) if sup else ()
        left = min((sup.value(state, var) - demand.get(var, 0) - k + 1 for var, k in uses), default=1 << 20)
        if left > most:
            best, most = v, left
    return best


def planned_supports(b, state, todo, level) -> dict:
    """{cell: value}: the columns to build under the atoms that never become ready (no
    support level: what they rest on is outside the goal and empty, e.g. a top over an
    enclosed space), down to a solid cell or a goal cell, in one spare value. They are
    serialised with the goal's atoms, so they rise with the rest while every cell is in reach,
    instead of being made last, from a place that may be closed in by then. Empty when no
    spare value has enough left over for all of them."""
    default, grid = b.model.grid.default, b.model.grid
    goal = {p for p, _ in b.cells.atoms}
    value = spare_value(b, state, todo)
    if value is None:
        return {}
    out: dict = {}
    for p, v in todo.items():
        if p in level:
            continue
        stack = [_add(p, rel) for rel in b.rests_on.get(v, ())]
        while stack:
            c = stack.pop()
            if c in out or c in goal or not _inside(grid, c) or b.read(state, *c) != default:
                continue
            out[c] = value
            stack.extend(_add(c, rel) for rel in b.rests_on.get(value, ()))
    sup = b.supplies
    if out and sup:
        demand = sup.demand(list(todo.values()) + [value] * len(out), b.wanted)
        if any(sup.value(state, var) < demand.get(var, 0) for var, _ in sup.uses.get(value, ())):
            return {}
    return out


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


def _remember_failures(find):
    """Footing not found from a state is not looked for again there: the same question
    (the state, the cell or places, the depth, the footing in use, how many atoms are
    achieved and pending) gets the same answer, and the footing the failed attempt kept
    (`b.keep`) is kept again. Looking for a stair asks the same questions many times
    over (a place ten levels up: 840 of 1,045 `make_free` calls were repeats).
    `depth` left out: the builder's own (`footing_depth`)."""
    @functools.wraps(find)
    def remembered(b, state, target, todo, depth=None):
        depth = b.footing_depth if depth is None else depth
        key = (find.__name__, state, frozenset(target) if isinstance(target, (set, list)) else target, depth,
               frozenset(b.keep), len(b.protected), len(todo), b.strict)
        kept = b.footing_failed.get(key)
        if kept is not None:
            b.keep |= kept
            return None
        before = set(b.keep)
        path = find(b, state, target, todo, depth)
        if path is None:
            b.footing_failed[key] = b.keep - before
        return path
    return remembered


@_remember_failures
def make_solid(b, state, cell, todo, depth):
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
    if value == default or (value is not None and b._walls_in(cell)):   # (the last place of another atom)
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


@_remember_failures
def make_free(b, state, cell, todo, depth):
    """A path [(action, state)] after which `cell` holds nothing: an achiever of the
    default value (one that does not move the agent) applied from a standing place beside
    it, that place's footing built and its body cleared first when no walk reaches one
    (recursively, as `make_solid`); None if not found. A protected cell, a footing in use
    or the cell of a pending atom that already holds is never cleared."""
    read, default = b.read, b.model.grid.default
    if read(state, *cell) == default:
        return []
    if depth < 0 or not _inside(b.model.grid, cell) or cell in b.protected or cell in b.keep \
            or cell in b._reserved(todo):
        return None
    clearers = [a for a in b.cells.achievers.get(default, ()) if not a.moves]
    if not clearers:
        return None
    places = {_add(cell, (-a.write[0], -a.write[1], -a.write[2])) for a in clearers}

    def clear(s):
        return write_cell(b, s, cell, default)
    walk = b.walk(state, clear, b.local_limit)
    if walk is None and depth > 0:
        pre = stand_near(b, state, places, todo, depth - 1)
        if pre:
            more = b.walk(pre[-1][1], clear, b.local_limit)
            walk = pre + more if more is not None else None
    return walk


def climb(b, state, st, todo):
    """A path [(action, state)] to the standing place `st`, whose footing holds and whose
    body is free but which no walk reaches (a ledge one level up or more): the build
    solver's greedy search (any action: blocks put down to step on), spending nothing the
    pending atoms take; None if it fails within its limit."""
    agent = b.model.agent_position
    floor = b._floor(todo)
    key = (state, st, frozenset(floor.items()), len(b.protected))   # (the search reads no more)
    if key in b.climbs_failed:
        return None
    path, why = b.search(state, lambda s: agent(s) == st, [st], floor)
    if why != "ok":
        b.climbs_failed.add(key)
        return None
    return path


def _changes(b, state, st):
    """What standing at `st` needs done first: (cells to fill, cells to clear), or None
    when a body cell must keep what it holds (protected, or a footing in use)."""
    solid, free = b.footing
    read, default = b.read, b.model.grid.default
    fill = [_add(st, o) for o in solid if read(state, *_add(st, o)) == default]
    clear = []
    for o in free:
        cell = _add(st, o)
        if b.protected.get(cell, default) != default:
            return None
        if read(state, *cell) != default:
            if cell in b.keep or cell in b.protected:
                return None
            clear.append(cell)
    return fill, clear


@_remember_failures
def stand_near(b, state, places, todo, depth):
    """A path [(action, state)] that builds the footing of one of `places` and clears its
    body cells (the fewest cells to clear first, then the nearest; at most CANDIDATES
    places tried), so a walk can reach it; None if none is found (a place that needs
    nothing done is no answer: a walk would have found it)."""
    solid, free = b.footing
    if not solid:
        return None
    grid = b.model.grid
    here = b.model.agent_position(state)
    ranked = []
    for st in set(places):
        if not _inside(grid, st):
            continue
        changes = _changes(b, state, st)
        if changes is not None:
            ranked.append((len(changes[1]), _distance(here, st), st, changes))
    jitter = b.rng.random if b.rng else (lambda: 0)     # another try breaks ties another way
    ranked.sort(key=lambda r: (r[0], r[1], jitter()))   # else ties in the order of `places`
    for _, _, st, (fill, clear) in ranked[:CANDIDATES]:
        if not fill and not clear:   # ready but out of a walk's reach (up a level): a short search
            path = climb(b, state, st, todo)
            if path:
                return path
            continue
        path, s = [], state
        for make, cell in [(make_solid, c) for c in fill] + [(make_free, c) for c in clear]:
            sub = make(b, s, cell, todo, depth)
            if sub is None:
                break
            path += sub
            s = path[-1][1] if path else s
        else:
            if path:
                return path
    return None

