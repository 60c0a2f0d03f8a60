"""The counting abstraction's builder (counting.py tells the story): the cells kept
exactly and the classes counted, the actions' touched cells, and the answers for one
abstract state (its view, its successors, its goal test) that the forward exploration
of the abstract states and the backward distances (counting_explore.py) ask for."""
from __future__ import annotations

import array
import itertools

from ..compiler import ir
from ..compiler.abstract import Abstract
from ..compiler.access import CELLS, action_access, reads
from .counting_data import (MAX_EXACT, TOUCH_CAP, CountingDatabase, TooBig,
                            Unsupported, cells_in, and_parts, const_value, effect_nodes, getter, has_loop)
from .counting_explore import Exploration


class Builder:
    def __init__(self, layout, actions, search, goal, failure, reach, n_values, initial, apply_fns, is_goal,
                 is_failure, deadline, max_states, keep=None, project=()):
        if not layout.layers:
            raise Unsupported("no mutable cells")
        from ..compiler.reachability import Analysis
        self.L, self.actions, self.search = layout, actions, list(search)
        self.failure, self.reach = failure, reach
        self.an = Analysis(layout, n_values)
        self.base = layout.grid_base
        self.initial = initial[:self.base]
        self.apply_fns, self.is_goal, self.is_failure = apply_fns, is_goal, is_failure
        self.deadline = deadline
        self.max_states = max_states
        self.start = layout.start_cells
        self.area = layout.width * layout.depth
        self.written = reach.written
        self.failure_reads_cells = CELLS in reads(failure, vars_of=self.an.vars_of)   # a loop over the grid too
        self.goal_vars = {v for v in reads(goal, vars_of=self.an.vars_of) if isinstance(v, ir.StateVar)}
        self._classify(goal, keep)
        self._plan_actions()
        # Variables projected away: any of their reachable values (an over-approximation);
        # never one the goal reads or one that places a cell an action touches.
        slots = [layout.slots[j] for j in project]
        if any(sl.var in self.goal_vars or sl.index in self.coordinate_vars for sl in slots):
            raise Unsupported("cannot project away a variable the goal or a cell position reads")
        self.projected = tuple((sl.index, tuple(sorted(v - sl.lo for v in reach.values.get(sl.var, range(sl.lo, sl.hi + 1)))))
                               for sl in slots)
        failure_vars = reads(failure, vars_of=self.an.vars_of)
        self.failure_projected = any(sl.var in failure_vars for sl in slots)

    def projectable(self) -> list:
        """Variables that may be projected away, the one with the most reachable values first."""
        failure_vars = reads(self.failure, vars_of=self.an.vars_of)
        out = []
        for sl in self.L.slots:
            n = len(self.reach.values.get(sl.var, range(sl.lo, sl.hi + 1)))
            if n > 1 and sl.var not in self.goal_vars and sl.var not in failure_vars \
                    and sl.index not in self.coordinate_vars:
                out.append((-n, sl.index))
        return [j for _, j in sorted(out)]

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

    def _classify(self, goal, keep=None) -> None:
        n = len(self.start)
        sig = [[True] * len(self._alphabet(m)) for m in range(n)]
        exact = set()
        for conj in and_parts(goal):
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
            if has_loop(conj):
                raise Unsupported("a grid quantifier nested in the goal")
            for cell in cells_in(conj):
                xyz = [const_value(c) for c in (cell.x, cell.y, cell.z)]
                if None in xyz:
                    if xyz[1] is not None and xyz[1] not in self.L.layers:
                        continue   # a static layer
                    raise Unsupported("the goal reads a cell at a position that changes")
                m = self._mutable(*xyz)
                if m is not None:
                    exact.add(m)
        self.must_change = [m for m in range(n) if not sig[m][self._alphabet(m).index(self.start[m])]]
        exact |= set(self.must_change) if keep is None else set(keep) & set(self.must_change)
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
        if any(len(mm) > 65_535 for mm in self.members):
            raise Unsupported("a class of more cells than a count holds")
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
            effect_nodes(a.effects, nodes)
            if any(has_loop(nd) for nd in nodes):
                raise Unsupported(f"{a.name} quantifies over the grid")
            cells = []
            for nd in nodes:
                cells.extend(cells_in(nd, lets))
            coord_vars: set = set()
            for c in cells:
                for part in (c.x, c.y, c.z):
                    r = reads(part, lets, self.an.vars_of)
                    if CELLS in r:
                        raise Unsupported(f"{a.name} reads a cell at a position read from a cell")
                    coord_vars |= r
            idx = sorted(self.L.by_var[v].index for v in coord_vars if v in self.L.by_var)
            self.touch_vars[i] = (idx, cells, lets)
        self.coordinate_vars = {j for idx, _, _ in self.touch_vars.values() for j in idx}
        # What an action does depends on the variables it reads or writes (and its cells):
        # its outcomes are memoized by their values (a move: by position and facing only).
        self.key_of, self.writes_of, self.deltas = {}, {}, {}
        for i in self.search:
            r, w = action_access(self.actions[i], self.an.vars_of)
            kidx = sorted({self.L.by_var[v].index for v in r | w if v in self.L.by_var})
            self.key_of[i] = getter(kidx)
            self.writes_of[i] = sorted(self.L.by_var[v].index for v in w if v in self.L.by_var)
        self.touch_memo: dict = {}
        self.touch_key = {i: getter(self.touch_vars[i][0]) for i in self.search}

    def touched(self, i: int, vars_: bytes) -> tuple:
        """The mutable cells action i may read or write when the variables are `vars_`,
        and for each whether it is exact (its position) or counted (its class)."""
        key = (i, self.touch_key[i](vars_))
        found = self.touch_memo.get(key)
        if found is not None:
            return found
        idx, cells, lets = self.touch_vars[i]
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
        touched = tuple(sorted(out))
        kinds = tuple(("e", self.exact[m]) if m in self.exact else ("c", self.class_of[m]) for m in touched)
        found = self.touch_memo[key] = (touched, kinds)
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
        """Explore the abstract states from the start's, a layer at a time, then search
        backward by cost (counting_explore.py)."""
        return Exploration(self).run()

    def _seen(self, part: bytes, cap: int) -> bytes:
        """What a cell part tells actions that touch at most `cap` cells each: the exact
        cells' values, then per count slot and per class's cells still at their start
        value, the count capped at `cap` (`_choices` and `_feasible` read no more)."""
        n_exact = len(self.exact)
        counts = self._counts(part)
        free = [len(mm) - sum(counts[s] for s in slots.values()) for mm, slots in zip(self.members, self.slot_of_class)]
        return part[:n_exact] + bytes(min(c, cap) for c in counts) + bytes(min(f, cap) for f in free)

    def _view(self, plan: list, var_id, costs) -> tuple:
        """For one variables' plan: the function giving a cell part's view (the bytes of
        `_seen` the touched cells' values are read from), the actions that touch cells,
        and the successors of those that touch none ((next variables id, cost), each once)."""
        n_exact = len(self.exact)
        at: set = set()
        cell_plan, free = [], {}
        for i, touched, kinds, nxt in plan:
            if nxt is not None:
                for x in nxt:
                    free.setdefault((var_id(x), costs[i]), None)
                continue
            cell_plan.append((i, touched, kinds))
            for kind, k in kinds:
                if kind == "e":
                    at.add(k)
                else:
                    at.update(n_exact + slot for slot in self.slot_of_class[k].values())
                    at.add(n_exact + self.n_slots + k)
        cap = max((len(touched) for _, touched, _ in cell_plan), default=0)
        view_of = getter(sorted(at))
        if cap > TOUCH_CAP:   # more cells than the seen counts tell apart: memoized by the cell part itself
            view_of = None
        return view_of, tuple(cell_plan), tuple(free), cap

    def _cell_successors(self, vid, vars_, rid, part, cell_plan, var_id, costs, cell_entries, choices_of,
                         outcomes) -> tuple:
        """(next variables id, changes, cost) of every action that touches cells, from
        these variables and this cell part; a move back to the same abstract state is
        left out. The touched cells' possible values are memoized by (cell part, cells),
        an action's outcomes by (action, variables, the cells' values)."""
        out = {}
        for i, touched, kinds in cell_plan:
            ckey = (rid, kinds)
            options = choices_of.get(ckey)
            if options is None:
                options = choices_of[ckey] = self._choices(part, touched, kinds)
            for choice in options:
                okey = (i, vid, choice)
                outs = outcomes.get(okey)
                if outs is None:
                    outs = outcomes[okey] = tuple((var_id(nxt), changes) for nxt, changes
                                                  in self._outcome(i, vars_, touched, choice, cell_entries))
                for nvid, changes in outs:
                    if nvid != vid or changes:
                        out.setdefault((nvid, changes, costs[i]), None)
        return tuple(out)

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
        if not check_cells and not self.failure_projected and self.is_failure(self.concrete(vars_, {})):
            return out   # the search never expands a failed state (it is a goal, or dropped)
        for i in self.search:
            touched, kinds = self.touched(i, vars_)
            free = None
            if not touched:
                found = self._outcome(i, vars_, (), (), cell_entries)
                if not found:
                    continue
                free = tuple(f[0] for f in found)
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

    def _outcome(self, i, vars_, touched, choice, cell_entries) -> tuple:
        """The (next variables, ((cell, old, new), ...)) action i may give from these
        variables with its touched cells holding `choice` (several where variables are
        projected away)."""
        key = (i, self.key_of[i](vars_), choice)
        found = self.deltas.get(key)
        if found is None:
            found = self.deltas[key] = self._run(i, vars_, touched, choice, cell_entries)
        out = []
        for delta, changes in found:
            vb = bytearray(vars_)
            for j, value in delta:
                vb[j] = value
            nxt = self._projected(bytes(vb))
            if (nxt != vars_ or changes) and (nxt, changes) not in out:
                out.append((nxt, changes))
        return tuple(out)

    def _run(self, i, vars_, touched, choice, cell_entries) -> tuple:
        """Run action i on the concrete states: ((written variables' values), changes) each."""
        cells = dict(zip(touched, choice))
        found = []
        writes = self.writes_of[i]
        for vb in self._unprojected(vars_):
            state = self.concrete(vb, cells)
            nxt = self.apply_fns[i](state)
            if nxt is None or nxt == state:
                continue
            after = dict(cells)
            for m in cells:
                after[m] = self.start[m]
            for e in cell_entries(nxt[self.base:]):
                m = e >> 8
                if m not in cells:
                    raise Unsupported("an action wrote a cell it was not expected to touch")
                after[m] = e & 255
            changes = tuple((m, cells[m], after[m]) for m in sorted(cells) if after[m] != cells[m])
            out = (tuple((j, nxt[j]) for j in writes), changes)
            if out not in found:
                found.append(out)
        return tuple(found)

    def _unprojected(self, vars_: bytes):
        """The variables with every combination of values of the projected ones."""
        if not self.projected:
            yield vars_
            return
        vb = bytearray(vars_)
        for combo in itertools.product(*(values for _, values in self.projected)):
            for (j, _), value in zip(self.projected, combo):
                vb[j] = value
            yield bytes(vb)

    def _projected(self, vars_: bytes) -> bytes:
        if not self.projected:
            return vars_
        vb = bytearray(vars_)
        for j, _ in self.projected:
            vb[j] = self.initial[j]
        return bytes(vb)


