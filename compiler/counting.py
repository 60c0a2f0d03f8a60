"""A counting abstraction of the whole model: exact distances in a smaller state space.

The position pattern database (patterns.py) sees only where the agent stands, so a goal
about the grid's contents ("no cell outside region R holds value v") gets h = 0, and the
delete relaxation (relaxed.py) never has to put anything down. This abstraction keeps
what both lose:

- every state variable, exactly (the agent, what it holds);
- exactly, each mutable cell whose start value breaks the goal's condition on that cell
  (or that the goal reads at a fixed position): these must change;
- every other mutable cell only as a count: cells are grouped into classes of equal
  start value and equal goal treatment (for each value, does the goal's per-cell
  condition hold?), and an abstract state keeps, per class, how many of its cells hold
  each value other than the start's. The goal holds or fails alike in every arrangement
  of the counts, so the abstract goal test is exact.

An action's cells are read and written at coordinates computed from the variables (the
agent's pose), so the abstract transition knows which exact cell or which class it
touches. A counted cell may hold any value its class still counts (an over-
approximation: the abstraction cannot tell which cell of a class holds what). The
action itself runs as generated code (`apply`) on a concrete state built from the
abstract one with each choice of values for the counted cells it touches; what it
changes updates the exact part and the counts. Every real transition s -> t has an
abstract one alpha(s) -> alpha(t) of the same cost, so the exact abstract distance
(backward from the abstract goal states) never overestimates and is consistent.

Built by a forward exploration of the abstract states reachable from the start's, then
a backward search by cost; bounded by a state limit and a time limit (None past them).
"""
from __future__ import annotations

import array
import itertools
import math
import operator
import time
from dataclasses import dataclass

from . import ir
from .abstract import Abstract
from .relevance import CELLS, reads

MAX_STATES = 3_000_000     # abstract states explored at most
MAX_EXACT = 12             # cells kept exactly at most


class Unsupported(Exception):
    """The model is outside what this abstraction handles (no database is built)."""


class TooBig(Exception):
    """The abstraction ran past its state or time limit."""

    def __init__(self, message: str, timed_out: bool = False):
        super().__init__(message)
        self.timed_out = timed_out


@dataclass(frozen=True)
class CountingDatabase:
    base: int              # state[:base] are the variables
    exact: dict            # mutable cell index -> its position in the exact part
    start_exact: bytes     # the exact cells' start values
    tracked: dict          # (mutable cell index, value) -> count slot (values other than the cell's start)
    n_slots: int
    table: dict            # abstract key -> distance to the goal (finite ones only)
    dead: frozenset        # abstract keys from which the goal is unreachable
    states: int            # abstract states explored

    def key(self, state: bytes, entries) -> bytes | None:
        """The abstract key of a state (its changed-cell `entries`), or None if some cell
        holds a value the abstraction did not expect."""
        ex = bytearray(self.start_exact)
        counts = array.array("H", bytes(2 * self.n_slots))
        exact, tracked = self.exact, self.tracked
        for e in entries:
            i = e >> 8
            p = exact.get(i)
            if p is not None:
                ex[p] = e & 255
                continue
            slot = tracked.get((i, e & 255))
            if slot is None:
                return None
            counts[slot] += 1
        return state[:self.base] + bytes(ex) + counts.tobytes()


def build(layout, actions, search, goal, failure, reach, n_values, initial: bytes, apply_fns, is_goal, is_failure,
          time_limit: float | None = None, max_states: int = MAX_STATES) -> CountingDatabase:
    """The database; raises Unsupported outside the abstraction, TooBig past its limits."""
    return _Builder(layout, actions, search, goal, failure, reach, n_values, initial, apply_fns, is_goal,
                    is_failure, time_limit, max_states).run()


def goal_changes_cells(layout, actions, search, goal, failure, reach, n_values, initial: bytes, *rest) -> bool:
    """Whether the goal needs some cell of the grid changed (a cell kept exactly): where
    it does not (the goal reads variables alone), search without the abstraction is
    usually cheaper than building it. Cheap: no state is explored."""
    try:
        return bool(_Builder(layout, actions, search, goal, failure, reach, n_values, initial, None, None, None,
                             None, 0).exact)
    except (Unsupported, TooBig):
        return False


def build_or_none(*args, **kw) -> dict:
    """{"db": the database, or None outside the abstraction or past its size limits} (to
    be cached); raises TooBig when the time limit stops it (nothing worth remembering)."""
    try:
        return {"db": build(*args, **kw)}
    except Unsupported:
        return {"db": None}
    except TooBig as exc:
        if exc.timed_out:
            raise
        return {"db": None}


class _Builder:
    def __init__(self, layout, actions, search, goal, failure, reach, n_values, initial, apply_fns, is_goal,
                 is_failure, time_limit, max_states):
        if not layout.layers:
            raise Unsupported("no mutable cells")
        from .reachability import Analysis
        self.L, self.actions, self.search = layout, actions, list(search)
        self.an = Analysis(layout, n_values)
        self.base = layout.grid_base
        self.initial = initial[:self.base]
        self.apply_fns, self.is_goal, self.is_failure = apply_fns, is_goal, is_failure
        self.deadline = math.inf if time_limit is None else time.process_time() + time_limit
        self.max_states = max_states
        self.start = layout.start_cells
        self.area = layout.width * layout.depth
        self.written = reach.written
        self.failure_reads_cells = CELLS in reads(failure, self.an, {}, set()) or _has_loop(failure)
        self.goal_vars = {v for v in reads(goal, self.an, {}, set()) if isinstance(v, ir.StateVar)}
        self._classify(goal)
        self._plan_actions()

    # ---- cells: which are exact, which counted in which class ------------------------
    def _xyz(self, m: int) -> tuple:
        layer, rest = divmod(m, self.area)
        z, x = divmod(rest, self.L.width)
        return x, self.L.layers[layer], z

    def _mutable(self, x, y, z) -> int | None:
        L = self.L
        if y not in L.layers or not (0 <= x < L.width and 0 <= z < L.depth):
            return None
        return (L.layers.index(y) * L.depth + z) * L.width + x

    def _alphabet(self, m: int) -> tuple:
        _, y, _ = self._xyz(m)
        return tuple(sorted({self.start[m]} | set(self.written.get(y, ()))))

    def _classify(self, goal) -> None:
        n = len(self.start)
        sig = [[True] * len(self._alphabet(m)) for m in range(n)]
        exact = set()
        for conj in _conjuncts(goal):
            if isinstance(conj, ir.CellLoop):
                if conj.kind != "forall":
                    raise Unsupported("an `exists` over the grid in the goal")
                for m in range(n):
                    for k, v in enumerate(self._alphabet(m)):
                        r = self._cell_condition(conj, m, v)
                        if r is None:
                            raise Unsupported("the goal's condition on a cell reads more than that cell")
                        sig[m][k] = sig[m][k] and r
                continue
            if _has_loop(conj):
                raise Unsupported("a grid quantifier nested in the goal")
            for cell in _cells_in(conj):
                xyz = [_const(c) for c in (cell.x, cell.y, cell.z)]
                if None in xyz:
                    if xyz[1] is not None and xyz[1] not in self.L.layers:
                        continue   # a static layer
                    raise Unsupported("the goal reads a cell at a position that changes")
                m = self._mutable(*xyz)
                if m is not None:
                    exact.add(m)
        for m in range(n):
            if not sig[m][self._alphabet(m).index(self.start[m])]:
                exact.add(m)
        if len(exact) > MAX_EXACT:
            raise TooBig(f"{len(exact)} cells to keep exactly")
        self.exact = {m: p for p, m in enumerate(sorted(exact))}
        self.start_exact = bytes(self.start[m] for m in sorted(exact))
        classes: dict = {}
        self.class_of = {}
        for m in range(n):
            if m in self.exact:
                continue
            key = (tuple(sig[m]), self.start[m], self._alphabet(m))
            self.class_of[m] = classes.setdefault(key, len(classes))
        self.members = [[] for _ in classes]
        for m, k in self.class_of.items():
            self.members[k].append(m)
        self.tracked, self.slot_of_class = {}, []
        slots = 0
        for (s, start, alphabet), k in classes.items():
            mine = {}
            for v in alphabet:
                if v != start:
                    mine[v] = slots
                    slots += 1
            self.slot_of_class.append(mine)
            for m in self.members[k]:
                for v, slot in mine.items():
                    self.tracked[(m, v)] = slot
        self.class_start = [start for (_, start, _), _ in sorted(classes.items(), key=lambda kv: kv[1])]
        self.n_slots = slots

    def _cell_condition(self, loop, m: int, v: int):
        """The goal's per-cell condition at cell m holding v: True, False, or None (unknown)."""
        x, y, z = self._xyz(m)
        lets = {loop.names[0]: ir.Const(x, "int"), loop.names[1]: ir.Const(y, "int"), loop.names[2]: ir.Const(z, "int")}
        cell, layer = self.an.cells(self.written)

        def cells(cx, cy, cz):
            return frozenset({v}) if (cx, cy, cz) == (x, y, z) else cell(cx, cy, cz)

        ab = Abstract(lets, cells, layer, sets={}, var_at=None)
        r = ab.eval(loop.body)
        if r is None or len(r) != 1:
            return None
        return next(iter(r))

    # ---- actions: which cells each one touches, given the variables ------------------
    def _plan_actions(self) -> None:
        self.touch_vars = {}
        for i in self.search:
            a = self.actions[i]
            lets = {loc.name: value for loc, value in a.lets}
            nodes = []
            for _, value in a.lets:
                nodes.append(value)
            nodes.extend(a.pre)
            _effect_nodes(a.effects, nodes)
            if any(_has_loop(nd) for nd in nodes):
                raise Unsupported(f"{a.name} quantifies over the grid")
            cells = []
            for nd in nodes:
                cells.extend(_cells_in(nd, lets))
            coord_vars: set = set()
            for c in cells:
                for part in (c.x, c.y, c.z):
                    r = reads(part, self.an, lets, set())
                    if CELLS in r:
                        raise Unsupported(f"{a.name} reads a cell at a position read from a cell")
                    coord_vars |= r
            idx = sorted(self.L.by_var[v].index for v in coord_vars if v in self.L.by_var)
            self.touch_vars[i] = (idx, cells, lets)
        self.touch_memo: dict = {}

    def touched(self, i: int, vars_: bytes) -> tuple:
        """The mutable cells action i may read or write when the variables are `vars_`."""
        idx, cells, lets = self.touch_vars[i]
        key = (i, bytes(vars_[j] for j in idx))
        found = self.touch_memo.get(key)
        if found is not None:
            return found
        sets = {s.var: frozenset({vars_[s.index] + s.lo}) for s in self.L.slots}
        ab = Abstract(lets, lambda x, y, z: None, None, sets=sets, var_at=self.an.var_at)
        out = set()
        for c in cells:
            xyz = [ab.eval(part) for part in (c.x, c.y, c.z)]
            if any(v is None for v in xyz):
                raise Unsupported("a cell position that the variables do not fix")
            for x, y, z in itertools.product(*xyz):
                m = self._mutable(x, y, z)
                if m is not None:
                    out.add(m)
        found = self.touch_memo[key] = tuple(sorted(out))
        return found

    # ---- concrete states from abstract ones ------------------------------------------
    def concrete(self, vars_: bytes, cells: dict) -> bytes:
        """The compact state with these variables and these mutable cells (others at start)."""
        start = self.start
        entries = sorted((m, v) for m, v in cells.items() if v != start[m])
        return vars_ + b"".join(((m << 8) | v).to_bytes(4, "little") for m, v in entries)

    def exact_cells(self, ex: bytes) -> dict:
        return {m: ex[p] for m, p in self.exact.items()}

    def representative(self, vars_: bytes, ex: bytes, counts) -> bytes:
        cells = self.exact_cells(ex)
        for k, slots in enumerate(self.slot_of_class):
            members = iter(self.members[k])
            for v, slot in slots.items():
                for _ in range(counts[slot]):
                    cells[next(members)] = v
        return self.concrete(vars_, cells)

    # ---- the exploration ----------------------------------------------------------------
    def run(self) -> CountingDatabase:
        """Explore the abstract states from the start's, then search backward by cost.
        A state is its key: the variables, the exact cells, the counts (2 bytes each).
        What an action does depends on the variables and the touched cells' values only,
        and what a change does to the cells on the cell part only: both are memoized."""
        from ..model import cell_entries
        base, exact = self.base, self.exact
        n_exact = len(self.exact)
        zero = array.array("H", bytes(2 * self.n_slots))
        start_key = self.initial + self.start_exact + zero.tobytes()
        ids = {start_key: 0}
        states = [start_key]
        src, dst, cost_of = array.array("i"), array.array("i"), array.array("d")
        goals = []
        plans: dict = {}         # variables -> [(action, touched cells, kinds)]
        outcomes: dict = {}      # (action, variables, values of the touched cells) -> (next variables, changes) | None
        moved: dict = {}         # (cell part, changes) -> next cell part
        choices_of: dict = {}    # (cell part, kinds) -> the value choices of the touched cells
        goal_memo: dict = {}
        goal_idx = sorted(self.L.by_var[v].index for v in self.goal_vars if v in self.L.by_var)
        costs = [a.cost for a in self.actions]
        check_cells = self.failure_reads_cells
        max_states, deadline = self.max_states, self.deadline
        uniform = len({costs[i] for i in self.search}) <= 1
        goal_of = operator.itemgetter(*goal_idx) if goal_idx else (lambda v: ())
        u = 0
        while u < len(states):
            if u & 1023 == 0 and time.process_time() > deadline:
                raise TooBig("the time limit ran out", timed_out=True)
            key = states[u]
            vars_, rest = key[:base], key[base:]
            gkey = (goal_of(vars_), rest)
            g = goal_memo.get(gkey)
            if g is None:
                g = goal_memo[gkey] = self._goal(vars_, rest)
            if g:
                goals.append(u)
            plan = plans.get(vars_)
            if plan is None:
                plan = plans[vars_] = self._plan(vars_, cell_entries, check_cells)
            for i, touched, kinds, free in plan:
                if free is not None:   # touches no mutable cell: the outcome is known
                    nkey = free + rest
                    v = ids.get(nkey)
                    if v is None:
                        v = ids[nkey] = len(states)
                        states.append(nkey)
                    src.append(u)
                    dst.append(v)
                    if not uniform:
                        cost_of.append(costs[i])
                    continue
                ckey = (rest, kinds)
                options = choices_of.get(ckey)
                if options is None:
                    options = choices_of[ckey] = self._choices(rest, touched, kinds)
                for choice in options:
                    okey = (i, vars_, choice)
                    out = outcomes.get(okey, False)
                    if out is False:
                        out = outcomes[okey] = self._outcome(i, vars_, rest[:n_exact], touched, choice, cell_entries)
                    if out is None:
                        continue
                    new_vars, changes = out
                    if changes:
                        mkey = (rest, changes)
                        nrest = moved.get(mkey)
                        if nrest is None:
                            nrest = moved[mkey] = self._moved(rest, changes)
                    else:
                        nrest = rest
                    nkey = new_vars + nrest
                    v = ids.get(nkey)
                    if v is None:
                        v = ids[nkey] = len(states)
                        states.append(nkey)
                    if v != u:
                        src.append(u)
                        dst.append(v)
                        if not uniform:
                            cost_of.append(costs[i])
            if len(states) > max_states:
                raise TooBig(f"more than {max_states:,} abstract states")
            u += 1
        if uniform:
            cost_of = array.array("d", [costs[self.search[0]] if self.search else 1]) * len(src)
        dist = _backward(len(states), src, dst, cost_of, goals)
        table = {k: (int(d) if d == int(d) else d) for k, d in zip(states, dist) if d != math.inf}
        dead = frozenset(k for k, d in zip(states, dist) if d == math.inf)
        return CountingDatabase(base, dict(exact), self.start_exact, dict(self.tracked), self.n_slots, table, dead,
                                len(states))

    def _counts(self, rest: bytes) -> array.array:
        return array.array("H", rest[len(self.exact):])

    def _goal(self, vars_: bytes, rest: bytes) -> bool:
        ex = rest[:len(self.exact)]
        return bool(self.is_goal(self.representative(vars_, ex, self._counts(rest))))

    def _plan(self, vars_: bytes, cell_entries, check_cells) -> list:
        """Per action that may apply: the mutable cells it touches with these variables,
        for each whether it is exact (its position) or counted (its class), and for an
        action that touches none its next variables (it changes no cell)."""
        out = []
        if not check_cells and self.is_failure(self.concrete(vars_, {})):
            return out   # the search never expands a failed state (it is a goal, or dropped)
        for i in self.search:
            touched = self.touched(i, vars_)
            kinds = tuple(("e", self.exact[m]) if m in self.exact else ("c", self.class_of[m]) for m in touched)
            free = None
            if not touched:
                found = self._outcome(i, vars_, self.start_exact, (), (), cell_entries, exact=False)
                if found is None:
                    continue
                free = found[0]
            out.append((i, touched, kinds, free))
        return out

    def _choices(self, rest: bytes, touched, kinds) -> tuple:
        """Every combination of values the touched cells may hold in this cell part."""
        counts = self._counts(rest)
        sizes = [len(mm) for mm in self.members]
        options = []
        for kind, k in kinds:
            if kind == "e":
                options.append((rest[k],))
                continue
            slots = self.slot_of_class[k]
            free = sizes[k] - sum(counts[s] for s in slots.values())
            vals = [self.class_start[k]] if free > 0 else []
            vals.extend(v for v, s in slots.items() if counts[s] > 0)
            options.append(vals)
        return tuple(c for c in itertools.product(*options)
                     if len(touched) < 2 or self._feasible(touched, c, counts, sizes))

    def _moved(self, rest: bytes, changes) -> bytes:
        """The cell part after these (cell, old value, new value) changes."""
        n_exact = len(self.exact)
        ex = bytearray(rest[:n_exact])
        counts = self._counts(rest)
        for m, old, new in changes:
            p = self.exact.get(m)
            if p is not None:
                ex[p] = new
                continue
            slots = self.slot_of_class[self.class_of[m]]
            if old in slots:
                counts[slots[old]] -= 1
            if new in slots:
                counts[slots[new]] += 1
        return bytes(ex) + counts.tobytes()

    def _feasible(self, touched, choice, counts, sizes) -> bool:
        """Distinct counted cells of one class need distinct cells of each value."""
        need: dict = {}
        for m, v in zip(touched, choice):
            k = self.class_of.get(m)
            if k is not None:
                need[(k, v)] = need.get((k, v), 0) + 1
        for (k, v), c in need.items():
            if c < 2:
                continue
            slots = self.slot_of_class[k]
            have = counts[slots[v]] if v in slots else sizes[k] - sum(counts[s] for s in slots.values())
            if c > have:
                return False
        return True

    def _outcome(self, i, vars_, ex, touched, choice, cell_entries, exact=True):
        """(next variables, ((cell, old, new), ...)) of action i on the concrete state, or None.
        With `exact` false the action touches no mutable cell, so none is set."""
        cells = self.exact_cells(ex) if exact else {}
        cells.update(zip(touched, choice))
        state = self.concrete(vars_, cells)
        nxt = self.apply_fns[i](state)
        if nxt is None or nxt == state:
            return None
        after = dict(cells)
        for m in cells:
            after[m] = self.start[m]
        for e in cell_entries(nxt[self.base:]):
            m = e >> 8
            if m not in cells:
                raise Unsupported("an action wrote a cell it was not expected to touch")
            after[m] = e & 255
        changes = tuple((m, cells[m], after[m]) for m in sorted(cells) if after[m] != cells[m])
        return nxt[:self.base], changes


def _backward(n: int, src, dst, cost, goals) -> list:
    """Cheapest cost from each abstract state to a goal state (math.inf: none)."""
    import numpy as np
    dist = np.full(n, np.inf)
    if not goals:
        return dist.tolist()
    s = np.frombuffer(src, dtype=np.int32)
    d = np.frombuffer(dst, dtype=np.int32)
    c = np.frombuffer(cost, dtype=np.float64)
    order = np.argsort(d, kind="stable")
    s, d, c = s[order], d[order], c[order]
    starts = np.searchsorted(d, np.arange(n + 1))
    g = np.asarray(goals, dtype=np.int64)
    dist[g] = 0
    if len(c) and np.all(c == c[0]) and c[0] > 0:
        # Equal costs: breadth-first, one frontier at a time, in numpy.
        step = c[0]
        frontier = np.unique(g)
        level = 0.0
        while len(frontier):
            level += step
            lo, hi = starts[frontier], starts[frontier + 1]
            if not len(lo):
                break
            total = hi - lo
            idx = np.repeat(lo - np.concatenate(([0], np.cumsum(total)[:-1])), total) + np.arange(total.sum())
            preds = np.unique(s[idx])
            preds = preds[dist[preds] == np.inf]
            dist[preds] = level
            frontier = preds
        return dist.tolist()
    import heapq
    sl, cl, st = s.tolist(), c.tolist(), starts.tolist()
    out = dist.tolist()
    heap = [(0.0, int(x)) for x in set(goals)]
    heapq.heapify(heap)
    while heap:
        du, u = heapq.heappop(heap)
        if du > out[u]:
            continue
        for j in range(st[u], st[u + 1]):
            v, nd = sl[j], du + cl[j]
            if nd < out[v]:
                out[v] = nd
                heapq.heappush(heap, (nd, v))
    return out


def _conjuncts(node):
    if isinstance(node, ir.BoolOp) and node.op == "and":
        for item in node.items:
            yield from _conjuncts(item)
    else:
        yield node


def _has_loop(node) -> bool:
    if isinstance(node, ir.CellLoop):
        return True
    return any(_has_loop(c) for c in ir.children(node))


def _cells_in(node, lets: dict | None = None, seen: set | None = None) -> list:
    """Cell nodes in an expression (through the action's lets)."""
    out = []
    seen = set() if seen is None else seen
    if isinstance(node, ir.Cell):
        out.append(node)
    if isinstance(node, ir.Local) and lets and node.name in lets and node.name not in seen:
        seen.add(node.name)
        out.extend(_cells_in(lets[node.name], lets, seen))
    for c in ir.children(node):
        out.extend(_cells_in(c, lets, seen))
    return out


def _effect_nodes(effects, out: list) -> None:
    for e in effects:
        if isinstance(e, ir.When):
            out.append(e.cond)
            _effect_nodes(e.then, out)
            _effect_nodes(e.orelse, out)
        elif isinstance(e, ir.SetVar):
            out.append(e.value)
        elif isinstance(e, ir.SetVarAt):
            out.extend((e.key, e.value))
        elif isinstance(e, ir.SetCell):
            out.append(ir.Cell(e.x, e.y, e.z, "cell"))
            out.append(e.value)


def _const(node):
    return node.value if isinstance(node, ir.Const) else None
