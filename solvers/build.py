"""The builder: satisficing search for goals of many cell atoms, one atom at a time.

A goal that is a conjunction of cell atoms (heuristics/goal_cells.py) is reached by
*serialising* it: the next atom is the nearest one that is *ready* (an achiever's needs
on the other cells hold, e.g. what it rests on is there) and that no pending atom waits
for (the orders the actions imply); a small greedy search reaches it from the current
state with h = the walk to its nearest standing place, never changing an atom already
achieved (each achieved atom is *protected*). An atom whose search fails is set aside
until another one is achieved. When nothing is ready or every ready atom fails, or when
the goal's other conjuncts remain, gbfs finishes from the state reached (the fallback),
with what is left of the budget. A first try plans ahead: columns under the atoms that
rest on nothing the goal builds (scaffold.planned_supports: serialised with the goal's
atoms, they stay), and orders that fill an enclosed region from the inside out
(access.exit_orders). Nothing here knows what is being built.

The result carries `lower_bound` (goal_cells.lower_bound at the start: admissible).
"""
from __future__ import annotations

import dataclasses
import heapq
import itertools
import random

from ..heuristics.cell_reach import goal_never_holds
from ..heuristics.goal_cells import CellReader, footing, goal_cells, lower_bound, orders, ready, support_levels
from ..heuristics.supplies import supplies, wanted
from .access import Access, exit_orders
from .gather import gather
from .scaffold import CANDIDATES, DEEP_DEPTH, MAX_DEPTH, make_solid, planned_supports, stand_near, write_cell
from ..errors import ModelError
from .base import Budget, Meter, Result
from .options import Option, declare

NAME = "build"
LIFTS = 2          # actions that write and move tried at the end of a walk (a climb, twice)
IMPROVE_UP_TO = 40       # plans this short are handed to A* for a shorter one
RETRY = 8          # atoms achieved before a set-aside atom is tried again


class _Spent(Exception):
    """The budget ran out inside a walk (its name in args[0])."""


def _distance(a, b) -> int:
    return abs(a[0] - b[0]) + abs(a[1] - b[1]) + abs(a[2] - b[2])


class _Builder:
    def __init__(self, model, cells, meter, budget, local_limit, seed=0, keep=True, ahead=True, deep=False):
        self.model, self.cells, self.meter, self.budget = model, cells, meter, budget
        self.read = CellReader(model)
        self.succ = model.search_successors()
        self.local_limit = local_limit
        self.expanded = self.generated = 0
        self.protected = {}            # position -> value
        self.writes = {}               # action -> offsets it writes (None: not known)
        for lst in cells.achievers.values():
            for a in lst:
                self.writes.setdefault(a.action, set()).add(a.write)
        c = model.data("compiled")
        from ..heuristics.goal_cells import _count_writes, _displacement, _moves
        axes = {v: i for i, v in enumerate(c.position_vars)}
        for i in c.search:
            if _count_writes(c.actions[i].effects) and i not in self.writes:
                self.writes[i] = None
        for i, s in self.writes.items():
            if s is not None and len(s) < _count_writes(c.actions[i].effects):
                self.writes[i] = None
        # actions that write no cell: the walks of `walk`; actions that write a cell and move
        # the agent (a way up or down): tried a few in a row at the end of a walk
        self.movers = [i for i in c.search if not _count_writes(c.actions[i].effects)]
        self.lifts = sorted({a.action for lst in cells.achievers.values() for a in lst if a.moves} |
                            {i for i in c.search if i in self.writes and _moves(c.actions[i].effects, axes)})
        # walks may also clear a cell on the way (take a scaffold down), never fill one
        clear = model.grid.default
        self.walkers = self.movers + sorted({a.action for a in cells.achievers.get(clear, ()) if a.moves})
        shifts = {i: _displacement(c.actions[i], {loc.name: e for loc, e in c.actions[i].lets}, axes)
                  for i in self.walkers}
        back = {sh for sh in shifts.values() if sh is not None}
        # walks that can be walked back: a walk to the next atom that takes the agent down
        # a drop it cannot climb again (into a room the structure closes) is tried last
        self.returnable = [i for i in self.walkers if shifts[i] is not None and tuple(-d for d in shifts[i]) in back]
        self.rng = random.Random(seed) if seed else None   # another try: other ties (solvers/build_finish.py)
        self.footing_depth = DEEP_DEPTH if deep else MAX_DEPTH   # scaffold.py: how deep footing is looked for
        self.reserve = keep   # searches keep what the pending atoms take (a try may go without: build_finish.py)
        self.ahead = ahead    # plan supports and exit orders at the start (a try may go without: build_finish.py)
        if self.rng:
            self.rng.shuffle(self.walkers)
            self.rng.shuffle(self.returnable)
        # actions that clear a cell without moving: a gathering walk may use them when blocked in
        self.clearers = sorted({a.action for a in cells.achievers.get(clear, ()) if not a.moves})
        self.clear_set = set(self.clearers)
        self.supplies = supplies(model, cells)
        self.wanted = wanted(model)    # variables the goal wants at or above a value
        self.strict = True             # atoms that wall others in wait (solvers/access.py)
        self.todo = {}                 # the pending atoms (position -> value), while running
        self.keep = set()              # footing built for the atom in hand (solvers/scaffold.py)
        self.footing_failed = {}       # scaffold.py: questions of footing that found none
        self.climbs_failed = set()     # and of climbs
        self.footing = footing(model)  # (offsets the agent stands on, offsets its body takes)
        self.access = Access(cells, self.footing[1], model.grid.default) if self.footing[1] else None
        self.exhausted = {}            # variable -> plan length when no way to raise it was found
        self.rests_on = {}             # value -> offsets every achiever of it needs to hold something
        for v, lst in cells.achievers.items():
            units = [{c[0][0] for c in a.needs if len(c) == 1 and c[0][1] == "!=" and c[0][2] == model.grid.default
                      and c[0][0] != (0, 0, 0)} for a in lst if not a.moves] or [set()]
            self.rests_on[v] = set.intersection(*units)
        spare = [r for v, r in self.rests_on.items() if v is not None and v != model.grid.default and cells.achievers[v]]
        self.rests_on_any = set.intersection(*spare) if spare else set()   # what any written block rests on
        self.goal = dict(cells.atoms)   # the goal's cells -> values (planned supports join `cells` later)
        # how many support levels above the lowest pending one a write ahead may go: the
        # spread of the cells one standing place writes (three heights: two levels)
        offsets = [a.write for lst in cells.achievers.values() for a in lst if not a.moves]
        self.reach_span = max((max(o[i] for o in offsets) - min(o[i] for o in offsets) for i in range(3)), default=0)
        self.by_place = {}             # standing place -> [(atom position, achiever action)]
        for pos, v in cells.atoms:
            for a in cells.achievers.get(v, ()):
                place = (pos[0] - a.write[0], pos[1] - a.write[1], pos[2] - a.write[2])
                self.by_place.setdefault(place, []).append((pos, a.action))

    def walk(self, state, finish, limit, keep=None, walkers=None, score=None):
        """Breadth-first over the actions that write no cell, to the nearest state where
        `finish(s)` gives the last steps [(action, state)] (reversed; e.g. an achiever that
        writes an eligible atom): the whole path [(action, state)], or None."""
        apply, agent, base = self.model.apply_fns, self.model.agent_position, self.read.base
        parents = {state: None}
        where = (lambda n: agent(n)) if keep is not None else (lambda n: (agent(n), n[base:]))
        seen = {where(state)}                   # a place and the cells: what else a walk changes
        frontier = [state]                      # (things picked up) does not make a new place
        while frontier and len(parents) <= limit:
            nxt, found = [], []
            for s in frontier:
                tail = finish(s)
                if tail is not None:
                    found.append((s, tail))
                    if score is None:
                        break
            if found:
                s, path = max(found, key=lambda f: score(f[1][0][1])) if score else found[0]
                while parents[s] is not None:
                    prev, a = parents[s]
                    path.append((a, s))
                    s = prev
                path.reverse()
                return path
            for s in frontier:
                self.expanded += 1
                if not self.expanded & self.meter.mask:
                    which = self.meter.check(self.expanded, self.generated, len(parents))
                    if which:
                        raise _Spent(which)
                for a in walkers or self.walkers:
                    try:
                        n = apply[a](s)
                    except ModelError:
                        continue
                    self.generated += 1
                    if n is None or n in parents or self.model.is_failure(n) or self.breaks_protected(s, a, n):
                        continue
                    if keep is not None and self._writes_into(s, a, keep):
                        continue
                    key = where(n) if keep is None or a not in self.clear_set else (agent(n), n[base:])
                    if key in seen:
                        continue
                    seen.add(key)
                    parents[n] = (s, a)
                    nxt.append(n)
            frontier = nxt
        return None

    def _writes_into(self, state, action, cells) -> bool:
        offs = self.writes.get(action, ())
        if not offs:
            return offs is None
        x, y, z = self.model.agent_position(state)
        return any((x + dx, y + dy, z + dz) in cells for dx, dy, dz in offs)

    def breaks_protected(self, state, action, nxt) -> bool:
        offs = self.writes.get(action, ())
        if offs is None:   # a write whose place is not known: compare the protected cells
            return any(self.read(nxt, *p) != v for p, v in self.protected.items())
        if not offs:
            return False
        x, y, z = self.model.agent_position(state)
        for dx, dy, dz in offs:
            p = (x + dx, y + dy, z + dz)
            v = self.protected.get(p)
            if v is not None and self.read(nxt, *p) != v:
                return True
        return False

    def _finish(self, s, todo, eligible, lifts):
        """From `s`, an achiever that writes an eligible atom, after up to `lifts` actions
        that write and move: the steps [(action, state)] in reverse order, or None."""
        apply, read = self.model.apply_fns, self.read
        for pos, action in self.by_place.get(self.model.agent_position(s), ()):
            value = todo.get(pos)
            if value is None or not eligible(pos):
                continue
            try:
                n = apply[action](s)
            except ModelError:
                continue
            if n is not None and read(n, *pos) == value and not self.breaks_protected(s, action, n):
                return [(action, n)]
        if lifts:
            for a in self.lifts:
                try:
                    n = apply[a](s)
                except ModelError:
                    continue
                if n is None or self.model.is_failure(n) or self.breaks_protected(s, a, n):
                    continue
                tail = self._finish(n, todo, eligible, lifts - 1)
                if tail is not None:
                    return tail + [(a, n)]
        return None

    def reach(self, state, atom):
        """A greedy search from `state` to one where `atom` holds and no protected atom
        changed: (the path's [(action, state)], "ok" | "failed" | budget name)."""
        (pos, value), read = atom, self.read
        default, protected = self.model.grid.default, self.protected
        places = [p for p in self.cells.standing(atom) if protected.get(p, default) == default]
        return self.search(state, lambda s: read(s, *pos) == value, places, self._floor(self.todo))

    def _floor(self, todo) -> dict:
        """{variable: amount} the pending atoms `todo` (and the goal) still take: what a
        search on the way to something else must not spend (on scaffolding, say)."""
        return self.supplies.demand(todo.values(), self.wanted) if self.supplies and self.reserve else {}

    def _spends(self, s, n, floor) -> bool:
        """The step s -> n takes a variable below what `floor` keeps for the pending atoms."""
        value, held = self.supplies.value, self.supplies.held
        return any(value(n, var) < value(s, var) and held(n, var) < keep for var, keep in floor.items())

    def search(self, state, done, places, floor=None, avoid=None):
        """Greedy from `state` to one where `done(s)`, h = 1 + the distance to the nearest
        of `places`, changing no protected atom, spending nothing `floor` keeps (except
        on the last step) and taking no step `avoid(s, a)` rules out: (path, "ok" |
        "failed" | budget name)."""
        agent = self.model.agent_position
        near = {}   # position -> 1 + its distance to the nearest place (states share positions)

        def h(s):
            if done(s):
                return 0
            here = agent(s)
            v = near.get(here)
            if v is None:
                v = near[here] = 1 + min((_distance(here, p) for p in places), default=0)
            return v

        tie = itertools.count()
        parents = {state: None}
        frontier = [(h(state), 0, next(tie), state)]
        local = 0
        while frontier:
            hv, g, _, s = heapq.heappop(frontier)
            if hv == 0:
                path = []
                while parents[s] is not None:
                    prev, a = parents[s]
                    path.append((a, s))
                    s = prev
                path.reverse()
                return path, "ok"
            local += 1
            self.expanded += 1
            if local > self.local_limit:
                return None, "failed"
            if not self.expanded & self.meter.mask:
                which = self.meter.check(self.expanded, self.generated, len(parents))
                if which:
                    return None, which
            for a, n in self.succ(s):
                self.generated += 1
                if n in parents or self.model.is_failure(n) or self.breaks_protected(s, a, n):
                    continue
                if floor and self._spends(s, n, floor) and not done(n):
                    continue
                if avoid is not None and avoid(s, a):
                    continue
                parents[n] = (s, a)
                heapq.heappush(frontier, (h(n), g + 1, next(tie), n))
        return None, "failed"

    def _walls_in(self, p) -> bool:
        """Writing the atom at p now takes the last standing place of another pending atom
        (solvers/access.py); not asked once every atom left does so (`strict` off)."""
        return self.strict and self.access is not None and self.access.kills(p, self.todo, self.protected)

    def _blocked(self, state, var) -> bool:
        """Too little of `var` is left to write even one atom that takes it."""
        need = min((k for lst in self.supplies.uses.values() for v, k in lst if v == var), default=0)
        return self.supplies.value(state, var) < need

    def _starved(self, state, value) -> bool:
        """Writing `value` takes more of a variable than the state holds, and no gathering
        walk found a way to raise it (`exhausted`): the atom's greedy search, whose h is
        the walk alone, cannot get it either (where the blocks must first be made from
        others: 4 x 4,000 expansions for nothing), so the atom waits for the gbfs fallback."""
        return any(var in self.exhausted and self.supplies.value(state, var) < k
                   for var, k in self.supplies.uses.get(value, ()))

    def _reserved(self, todo) -> set:
        """Cells that every achiever of a pending atom needs to hold something (what it rests
        on): a supply must not be taken from them."""
        out = set()
        for (x, y, z), v in todo.items():
            for dx, dy, dz in self.rests_on.get(v, ()):
                out.add((x + dx, y + dy, z + dz))
        return out

    def gather(self, state, short, todo, footing: bool = True):
        """The nearest way to raise one of the `short` variables (solvers/gather.py):
        (path, "ok" | "failed" | budget name)."""
        return gather(self, state, short, todo, footing)

    def prepare(self, state, pos, todo):
        """Footing first, then the atom at `pos`: what it rests on (cells outside the goal,
        made solid with a spare value), a standing place's footing when no walk reaches
        one, then the walk that writes it. The path [(action, state)], or None."""
        value, path = todo[pos], []
        self.keep.clear()
        for rel in self.rests_on.get(value, ()):
            cell = (pos[0] + rel[0], pos[1] + rel[1], pos[2] + rel[2])
            if cell in todo:
                continue
            sub = make_solid(self, state, cell, todo)
            if sub is None:
                return None
            path += sub
            state = path[-1][1] if path else state

        def finish(s):
            return write_cell(self, s, pos, value)
        walk = self.walk(state, finish, self.local_limit)
        if walk is None:
            pre = stand_near(self, state, self.cells.standing((pos, value)), todo)
            if not pre:
                return None
            walk = self.walk(pre[-1][1], finish, self.local_limit)
            if walk is None:
                return None
            walk = pre + walk
        return path + walk

    def goal_left(self) -> int:
        """How many of the goal's atoms are still pending (planned supports aside)."""
        return sum(p in self.goal for p in self.todo)

    @staticmethod
    def _forgive(set_aside):
        for p in list(set_aside):
            set_aside[p] -= 1
            if set_aside[p] <= 0:
                del set_aside[p]

    def _achieved(self, state, todo, released, blockers):
        """Protect the atoms that now hold; release the atoms that waited for them."""
        for p in [p for p, v in todo.items() if self.read(state, *p) == v]:
            self.protected[p] = todo.pop(p)
            self.strict = True
            for q in released.get(p, ()):
                blockers[q] -= 1

    def run(self, start):
        """Serialise the cell atoms from `start`: (the plan's actions, the state reached,
        None or a budget name)."""
        reached = []
        try:
            return self._run(start, reached)
        except _Spent as spent:
            plan, state = reached or ([], start)
            return plan, state, spent.args[0]

    def _orders(self, start):
        """The pending atoms (`self.todo`; those already holding are protected) and the
        orders among them: (todo, blockers: q -> how many atoms q still waits for,
        released: p -> [q] that wait for p)."""
        waits = orders(self.cells)             # q -> atoms that must come before q
        if self.ahead:
            for q, ps in self._exit_orders(start, waits).items():
                waits.setdefault(q, []).extend(ps)
        blockers = {q: len(ps) for q, ps in waits.items()}
        released = {}
        for q, ps in waits.items():
            for p in ps:
                released.setdefault(p, []).append(q)
        todo = self.todo = {}
        for pos, v in self.cells.atoms:
            if self.read(start, *pos) == v:
                self.protected[pos] = v
            else:
                todo[pos] = v
        for pos in self.protected:
            for q in released.get(pos, ()):
                blockers[q] -= 1
        return todo, blockers, released

    def _short(self, state, todo, plan) -> dict:
        """What to gather before the next atom: the amounts the pending atoms (and the goal)
        take beyond what is held, less those no gathering walk raised at this plan length
        (or earlier, unless too little is left to write even one atom)."""
        short = self.supplies.short(state, todo.values(), self.wanted) if self.supplies else {}
        return {v: k for v, k in short.items()
                if self.exhausted.get(v) is None or (self.exhausted[v] != len(plan) and self._blocked(state, v))}

    def _nearest(self, state, todo, keep) -> list:
        """[(distance to its nearest standing place, position)] of the pending atoms for
        which `keep(position)` holds, nearest first."""
        here = self.model.agent_position(state)
        return sorted((min((_distance(here, p) for p in self.cells.standing((pos, v))), default=0), pos)
                      for pos, v in todo.items() if keep(pos))

    def _first_written(self, state, todo, candidates, set_aside):
        """The path that writes the first of `candidates` that can be written (its footing
        prepared for the nearest few, else the greedy search): (path, "ok"), or (None,
        "failed" | budget name). A candidate that fails is set aside."""
        for k, (_, pos) in enumerate(candidates):
            if self.supplies and self._starved(state, todo[pos]):
                set_aside[pos] = RETRY
                continue
            path = self.prepare(state, pos, todo) if k < CANDIDATES and self.footing[0] else None
            why = "ok"
            if path is None:
                path, why = self.reach(state, (pos, todo[pos]))
            if why not in ("ok", "failed"):
                return None, why
            if path is None:
                set_aside[pos] = RETRY
                continue
            return path, "ok"
        return None, "failed"

    def _pending(self, start) -> dict:
        """{position: value} of the atoms that do not hold in `start`."""
        return {p: v for p, v in self.cells.atoms if self.read(start, *p) != v}

    def _exit_orders(self, start, waits) -> dict:
        """access.exit_orders from `start` ({} without access)."""
        if self.access is None:
            return {}
        todo = self._pending(start)
        return exit_orders(self.access, todo, {p for p, _ in self.cells.atoms if p not in todo}, waits)

    def plans_ahead(self, start) -> bool:
        """Whether planning ahead finds supports or exit orders to plan from `start` (a try
        that plans ahead and finds none would repeat the next one)."""
        if planned_supports(self, start, self._pending(start), support_levels(self.cells, self.read, start)):
            return True
        return bool(self._exit_orders(start, orders(self.cells)))

    def _plan_supports(self, start):
        """Serialise planned supports (scaffold.planned_supports) with the goal's atoms:
        they join `cells` (a copy: the goal and its lower bound stay as they are)."""
        if not self.ahead:
            return
        extra = planned_supports(self, start, self._pending(start), support_levels(self.cells, self.read, start))
        if not extra:
            return
        self.cells = dataclasses.replace(self.cells, atoms=[*self.cells.atoms, *extra.items()])
        for pos, v in extra.items():
            for a in self.cells.achievers.get(v, ()):
                place = (pos[0] - a.write[0], pos[1] - a.write[1], pos[2] - a.write[2])
                self.by_place.setdefault(place, []).append((pos, a.action))
        if self.access is not None:
            self.access = Access(self.cells, self.footing[1], self.model.grid.default)

    def _ahead(self, state, todo, level, late, lowest, open_now):
        """The test (on a position) whether the atom of a later support level there may
        be written now: `open_now` holds of it, it is at most `reach_span` levels above
        `lowest`, and its cell is in no standing place that an atom of a lower level still
        needs (with footing there, or a goal atom to stand on). Walls go up several levels
        a pass (a cell behind the agent, at its feet or head), not one. None without
        access."""
        if self.access is None:
            return None
        read, default, goal = self.read, self.model.grid.default, self.goal

        def footed(place):
            for dx, dy, dz in self.footing[0]:
                c = (place[0] + dx, place[1] + dy, place[2] + dz)
                if read(state, *c) == default and goal.get(c, default) == default:
                    return False
            return True

        def ok(p):
            mine = level.get(p, late)
            return mine <= lowest + self.reach_span and open_now(p) and \
                not self.access.in_the_way(p, todo, lambda q: level.get(q, late) < mine, footed)
        return ok

    def _run(self, start, reached):
        self._plan_supports(start)
        cells, read = self.cells, self.read
        todo, blockers, released = self._orders(start)
        plan, state, set_aside = [], start, {}    # set aside: position -> achievements left to wait
        reached[:] = [plan, state]
        retried = -1               # plan length when the set-aside atoms were last given another try
        level = support_levels(cells, read, start)
        late = len(level) + 1      # atoms never made ready by the others come last
        wanted = self.wanted
        while todo or (wanted and self.supplies.short(state, (), wanted)):
            which = self.meter.check(self.expanded, self.generated, self.expanded)
            if which:
                return plan, state, which
            lowest = min((level.get(p, late) for p in todo if p not in set_aside), default=late)

            def open_now(p):   # not set aside, waits for nothing, ready, walls nothing in
                return p not in set_aside and blockers.get(p, 0) <= 0 \
                    and ready(cells, read, state, (p, todo[p])) and not self._walls_in(p)

            def eligible(p):
                return level.get(p, late) <= lowest and open_now(p)
            short = self._short(state, todo, plan)
            if short:   # gather what writing the pending atoms takes, nearest first
                if not todo:   # no atom left to stand for: earlier footing may be taken
                    self.keep.clear()
                path, why = self.gather(state, short, todo)
                if why not in ("ok", "failed"):
                    return plan, state, why
                if path:
                    plan.extend(a for a, _ in path)
                    state = path[-1][1]
                    self._achieved(state, todo, released, blockers)
                    continue
                self.exhausted.update((v, len(plan)) for v in short)
                if not todo:
                    return plan, state, None
            ahead = self._ahead(state, todo, level, late, lowest, open_now)
            path = self._finish(state, todo, ahead, 0) if ahead else None
            score = None
            if ahead:
                def score(s):   # atoms writable where the walk ends: of the nearest, the busiest place
                    return len({pos for pos, _ in self.by_place.get(self.model.agent_position(s), ())
                                if pos in todo and read(s, *pos) != todo[pos] and (eligible(pos) or ahead(pos))})
            def finish(s):
                return self._finish(s, todo, eligible, LIFTS)
            if path is None and len(self.returnable) < len(self.walkers):
                path = self.walk(state, finish, self.local_limit, walkers=self.returnable, score=score)
            if path is None:
                path = self.walk(state, finish, self.local_limit, score=score)
            why = "ok" if path is not None else None
            if path is None:
                candidates = self._nearest(state, todo, eligible)
                if not candidates and lowest >= late:   # nothing ready: what they rest on is built first
                    candidates = self._nearest(state, todo, lambda pos: pos not in set_aside
                                               and blockers.get(pos, 0) <= 0 and not self._walls_in(pos))
                path, why = self._first_written(state, todo, candidates, set_aside)
                if why not in ("ok", "failed"):
                    return plan, state, why
            if why == "ok":
                plan.extend(a for a, _ in path)
                state = path[-1][1] if path else state
                self._achieved(state, todo, released, blockers)
                self._forgive(set_aside)
                continue
            if lowest >= late:
                if self.strict:    # every atom left walls another in: one of them must be written
                    self.strict = False
                    continue
                if set_aside and retried != len(plan):   # the state moved on since: try them again
                    set_aside.clear()
                    retried = len(plan)
                    continue
                return plan, state, None
            set_aside.update((p, RETRY) for p in todo if level.get(p, late) <= lowest)   # the next level
        return plan, state, None


@declare(Option("local_limit", int, 4000, "expansions of one atom's greedy search before it is set aside", low=1),
         Option("improve", int, IMPROVE_UP_TO, "plans of at most this many actions are handed to blind A* (as long as finding the "
                "plan took, at least 1 s, at most a quarter of the time left, 100,000 states and 400 MB) for a shorter one; 0: never", low=0))
def solve(model, budget: Budget, progress=None, local_limit: int = 4000, improve: int = IMPROVE_UP_TO,
          **options) -> Result:
    """Builds a goal of many cell atoms one atom at a time (satisficing), reporting a lower bound."""
    from . import get_solver
    from .build_finish import finish, serialise
    meter = Meter(budget, progress)
    cells = goal_cells(model) or (goal_cells(model, allow_empty=True) if wanted(model) else None)
    if cells is None:   # no cell atoms and no amount to gather: nothing to serialise
        result = get_solver("gbfs")(model, budget, progress)
        result.solver = NAME
        return result
    never = goal_never_holds(model)
    if never:   # a relaxation proves it (also asked by the run path; a library caller gets it here)
        return meter.finish(Result(solver=NAME, solved=False, status="no_solution", message=never))
    run = serialise(model, lambda seed, keep, ahead, deep, try_meter: _Builder(model, cells, try_meter, budget,
                                                                               local_limit, seed, keep, ahead, deep),
                    meter, budget)
    return finish(model, budget, meter, run, improve, progress)
