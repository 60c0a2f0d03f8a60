"""The builder of the relaxed view of a compiled dungeon (relaxed_view.py has the whole
story): fact numbering by groups and cells, action contexts, partial evaluation of
conditions and effects into operators, fired effects."""
from __future__ import annotations

import bisect
import itertools
import time

from ..compiler import ir
from ..compiler.access import reads, state_vars
from .relaxed_eval import BAD, Drop, Evaluator, Fail, TooBig, conjuncts, residual, residual_effects
from .relaxed_task import Reachability, RelaxedTooBig

MAX_GROUP = 4096        # largest product of value ranges a group of variables may have
MAX_CONTEXTS = 200_000  # contexts (over all actions) before the view gives up
SPLIT_LIMIT = 4         # leaves of an action's effect decision tree before effects are fired apart
FIRE_LIMIT = 256        # cases of one fired effect's conditions per old value before they are relaxed
COND_LIMIT = 4096       # leaves of one condition's decision tree before it is dropped (relaxed)


def _groups(layout, actions) -> list:
    """Variables written side by side in one effect block are merged (union-find), as long
    as the product of their ranges stays within MAX_GROUP."""
    parent = {s.var: s.var for s in layout.slots}

    def find(v):
        while parent[v] is not v:
            parent[v] = parent[parent[v]]
            v = parent[v]
        return v

    def size(root):
        n = 1
        for s in layout.slots:
            if find(s.var) is root:
                n *= s.hi - s.lo + 1
        return n

    def blocks(effects):
        yield effects
        for e in effects:
            if isinstance(e, ir.When):
                yield from blocks(e.then)
                yield from blocks(e.orelse)

    for a in actions:
        lets = {loc.name: value for loc, value in a.lets}
        for block in blocks(a.effects):
            sets = [e for e in block if isinstance(e, ir.SetVar) and e.var in parent]
            written = {e.var for e in sets}
            # Only a move-like block is merged: each new value is computed from an old value
            # of the block's own variables (x = x + dx, z = z + dz).
            if len(sets) < 2 or not all(state_vars(reads(e.value, lets)) & written for e in sets):
                continue
            vs = [e.var for e in sets]
            for u, v in zip(vs, vs[1:]):
                ru, rv = find(u), find(v)
                if ru is not rv and size(ru) * size(rv) <= MAX_GROUP:
                    parent[rv] = ru
    out: dict = {}
    for s in layout.slots:
        out.setdefault(find(s.var), []).append(s.var)
    return list(out.values())


def _context_vars(action) -> set:
    """State variables read where they choose a cell, or a keyed object written (through lets)."""
    lets = {loc.name: value for loc, value in action.lets}
    out: set = set()

    def read(node, acc):
        acc |= state_vars(reads(node, lets))

    def walk(node):
        if isinstance(node, ir.Local) and node.name in lets:
            walk(lets[node.name])
        if isinstance(node, ir.Cell):
            for c in (node.x, node.y, node.z):
                read(c, out)
        # A keyed object only read (inventoryBlock[selected]) needs no context: its key
        # becomes one more atom of the condition, shared by every context.
        for c in ir.children(node):
            walk(c)

    def walk_effects(effects):
        for e in effects:
            if isinstance(e, ir.When):
                walk(e.cond)
                walk_effects(e.then)
                walk_effects(e.orelse)
            elif isinstance(e, ir.SetVar):
                walk(e.value)
            elif isinstance(e, ir.SetVarAt):
                read(e.key, out)
                walk(e.key)
                walk(e.value)
            elif isinstance(e, ir.SetCell):
                for c in (e.x, e.y, e.z):
                    read(c, out)
                    walk(c)
                walk(e.value)

    for c in action.pre:
        walk(c)
    walk_effects(action.effects)
    return out


class Builder:
    def __init__(self, layout, actions, search, goal, reach, n_values, deadline):
        self.L, self.actions, self.search, self.goal = layout, actions, search, goal
        self.reach, self.n_values, self.deadline = reach, n_values, deadline
        self.groups = _groups(layout, [actions[i] for i in search])
        self.group_of = {}
        for g, members in enumerate(self.groups):
            for pos, v in enumerate(members):
                self.group_of[v] = (g, pos)
        # Fact numbering: each group gets the full product of its members' ranges.
        self.bases, self.strides, n = [], [], 0
        for members in self.groups:
            slots = [layout.by_var[v] for v in members]
            strides, acc = [], 1
            for s in reversed(slots):
                strides.append(acc)
                acc *= s.hi - s.lo + 1
            self.strides.append(list(reversed(strides)))
            self.bases.append(n)
            n += acc
        self.area = layout.width * layout.depth
        self.cell_base = n
        n += len(layout.layers) * self.area * n_values
        self.n_facts = n
        self.labels: dict = {}
        self.group_domains = [self._group_domain(members) for members in self.groups]
        written = reach.written
        self.cell_domains: dict = {}
        for li, y in enumerate(layout.layers):
            extra = written.get(y, frozenset())
            for k in range(self.area):
                static = layout.static_grid[y * self.area + k]
                self.cell_domains[li * self.area + k] = sorted({static} | extra)
        self.ev = Evaluator(layout, self.group_of, self.domain)
        self.ev.group_members, self.ev.n_values = self.groups, n_values
        self.ops: dict = {}          # (pre, add, cost, action) -> None (ordered set)
        self.live = None             # relaxed reachability of the operators built so far
        self.or_facts: dict = {}     # frozenset of minterms -> aux fact
        self.fired: dict = {}        # (action, residual effects) -> aux fact
        self.fired_values: dict = {}  # fired fact -> (the atom it writes, the facts it may add)
        self.fired_steps: dict = {}  # fired fact -> [(preconditions besides it, the fact added)]
        self.step_costs: dict = {}   # op key -> its cost in the guiding view (fire_effects)
        self.chained: set = set()    # fired facts whose steps cost their action's cost there
        # Caches keyed by the identity of residual IR (interned, relaxed_eval._mk), each
        # entry holding its key objects so that no id is reused while the builder lives.
        self.keep: list = []
        self.cond_cache: dict = {}   # residual condition -> its decision-tree leaves
        self.clusters_cache: dict = {}  # residual conjuncts -> their clusters
        self.written_cache: dict = {}  # residual top-level effect -> atoms it may write

    # ---- facts -------------------------------------------------------------------------
    def _group_domain(self, members) -> list:
        sets = [sorted(self.reach.values.get(v, range(self.L.by_var[v].lo, self.L.by_var[v].hi + 1)))
                for v in members]
        return list(itertools.product(*sets))

    def domain(self, atom) -> list:
        kind, key = atom
        return self.group_domains[key] if kind == "g" else self.cell_domains[key]

    def fact(self, atom, value) -> int:
        kind, key = atom
        if kind == "g":
            members = self.groups[key]
            f = self.bases[key]
            for v, val, st in zip(members, value, self.strides[key]):
                f += (val - self.L.by_var[v].lo) * st
            if f not in self.labels:
                self.labels[f] = ", ".join(f"{v.label}={val}" for v, val in zip(members, value))
            return f
        f = self.cell_base + key * self.n_values + value
        if f not in self.labels:
            layer, k = divmod(key, self.area)
            z, x = divmod(k, self.L.width)
            self.labels[f] = f"cell({x}, {self.L.layers[layer]}, {z})={value}"
        return f

    def atom_of(self, f: int):
        """(atom, facts it may take) for a fact an operator adds: a group's or a cell's
        fact itself, or a fired fact's candidate values; None for other auxiliary facts."""
        if f < self.cell_base:
            return ("g", bisect.bisect_right(self.bases, f) - 1), {f}
        if f < self.cell_base + len(self.L.layers) * self.area * self.n_values:
            return ("c", (f - self.cell_base) // self.n_values), {f}
        return self.fired_values.get(f)

    def or_minterms(self) -> dict:
        return {f: [self.minterm_facts(m) for m in key] for key, f in self.or_facts.items()}

    def new_fact(self, label: str) -> int:
        f = self.n_facts
        self.n_facts += 1
        self.labels[f] = label
        return f

    def minterm_facts(self, minterm) -> tuple:
        return tuple(sorted(self.fact(a, v) for a, v in minterm))

    def condition(self, minterms) -> tuple:
        """Facts whose conjunction stands for a disjunction of minterms."""
        if len(minterms) == 1:
            return self.minterm_facts(next(iter(minterms)))
        key = frozenset(minterms)
        f = self.or_facts.get(key)
        if f is None:
            f = self.new_fact(f"or#{len(self.or_facts)}")
            self.or_facts[key] = f
            for m in minterms:
                self.op(self.minterm_facts(m), (f,), 0, -1)
        return (f,)

    def op(self, pre, add, cost, action) -> tuple | None:
        add = tuple(sorted(set(add) - set(pre)))
        if add:
            key = (tuple(sorted(set(pre))), add, cost, action)
            if key not in self.ops:
                self.ops[key] = None
                if self.live is not None:
                    self.live.add(key[0], add)
            return key
        return None

    # ---- conditions ----------------------------------------------------------------------
    def clusters(self, conds, env, limit=COND_LIMIT):
        """Minterm sets of the conjuncts, those that share atoms evaluated together.
        None if the conjunction is false; conjuncts too big to enumerate are dropped.
        Without an environment the answer depends on the conjuncts only: remembered (many
        contexts leave the same residual preconditions)."""
        if env:
            return self._clusters(conds, env, limit)
        key = (tuple(map(id, conds)), limit)
        hit = self.clusters_cache.get(key)
        if hit is None:   # the conjuncts are kept with the answer: their ids stay theirs
            hit = self.clusters_cache[key] = (conds, self._clusters(conds, env, limit))
        return hit[1]

    def _clusters(self, conds, env, limit):
        parts = []
        for c in conds:
            hit = self.cond_cache.get(id(c)) if not env else None
            leaves = None if hit is None else hit[1]
            if leaves is None:
                try:
                    leaves = self.ev.branch(lambda e, c=c: self.ev.truth(c, e), env, limit)
                except (TooBig, Drop):
                    leaves = ()
                if not env:
                    self.cond_cache[id(c)] = (c, leaves)
            if leaves == ():
                continue
            true = [m for m, r in leaves if r]
            if not true:
                return None
            atoms = {a for m, _ in leaves for a, _ in m}
            if atoms:
                parts.append(([c], atoms, true))
        merged = True
        while merged:  # conjuncts reading a common atom are enumerated jointly
            merged = False
            for i, j in itertools.combinations(range(len(parts)), 2):
                if parts[i][1] & parts[j][1]:
                    conds_ij = parts[i][0] + parts[j][0]
                    try:
                        leaves = self.ev.branch(lambda e: all(self.ev.truth(c, e) for c in conds_ij), env, limit)
                    except (TooBig, Drop):
                        continue
                    true = [m for m, r in leaves if r]
                    if not true:
                        return None
                    parts[i] = (conds_ij, parts[i][1] | parts[j][1], true)
                    del parts[j]
                    merged = True
                    break
        return [[frozenset(m) for m in p[2]] for p in parts]

    # ---- actions -----------------------------------------------------------------------
    def build_actions(self, init_facts) -> None:
        """Every action in every context whose context facts are reachable in the relaxation
        (lazy grounding, as Fast Downward's translator does): contexts are built as their
        facts become reachable from the operators built so far, so a wall cell's position,
        say, is never a context. Other contexts could never fire; dropping them leaves
        what `_prune` keeps unchanged."""
        live = self.live = Reachability(init_facts)
        todo = []
        for index in self.search:
            a = self.actions[index]
            lets = {loc.name: value for loc, value in a.lets}
            ctx = sorted({self.group_of[v][0] for v in _context_vars(a) if v in self.group_of})
            todo.append((index, a, lets, ctx))
        value_of = {}
        for g in {g for *_, ctx in todo for g in ctx}:
            for v in self.group_domains[g]:
                value_of[self.fact(("g", g), v)] = (g, v)
        reached: dict = {g: [] for g, _ in value_of.values()}
        built = 0
        first = True
        while True:
            fresh: dict = {}
            for f in live.take():
                gv = value_of.get(f)
                if gv is not None:
                    fresh.setdefault(gv[0], []).append(gv[1])
            if not fresh and not first:
                return
            old = {g: list(vs) for g, vs in reached.items()}
            for g, vs in fresh.items():
                reached[g].extend(vs)
            for index, a, lets, ctx in todo:
                if not ctx:
                    combos = [()] if first else []
                else:
                    # Each combination with at least one new value, once: old values before
                    # the first new position, new at it, any value after it.
                    combos = itertools.chain.from_iterable(
                        itertools.product(*([old[g] for g in ctx[:k]] + [fresh[ctx[k]]] + [reached[g] for g in ctx[k + 1:]]))
                        for k in range(len(ctx)) if ctx[k] in fresh)
                for values in combos:
                    built += 1
                    if built > MAX_CONTEXTS:
                        raise RelaxedTooBig(f"more than {MAX_CONTEXTS} action contexts")
                    if built % 256 == 0 and time.perf_counter() > self.deadline:
                        raise RelaxedTooBig("the time budget ran out while building the relaxed view")
                    pins = {}
                    for g, vals in zip(ctx, values):
                        pins.update(zip(self.groups[g], vals))
                    self.build_context(index, a, lets, ctx, values, pins)
            first = False

    def build_context(self, index, a, lets, ctx_groups, values, pins) -> None:
        cells: dict = {}
        memo: dict = {}
        pre = []
        for c in a.pre:
            try:
                r = residual(c, self.ev, pins, cells, lets, memo)
            except Drop:
                continue  # relaxed away: fewer preconditions over-approximate
            if r is BAD or r == ir.FALSE:
                return
            pre.extend(conjuncts(r))
        ctx_facts = [self.fact(("g", g), v) for g, v in zip(ctx_groups, values)]
        parts = self.clusters(pre, {})
        if parts is None:
            return
        pre_facts = list(ctx_facts)
        narrowed: dict = {}
        for minterms in parts:
            pre_facts.extend(self.condition(minterms))
            common = set.intersection(*({atom for atom, _ in m} for m in minterms))
            for atom in common:
                narrowed[atom] = {dict(m)[atom] for m in minterms}
        # Atoms the preconditions pin to one value are constants for the effects.
        pins2, cells2 = dict(pins), dict(cells)
        for (kind, key), vals in narrowed.items():
            if len(vals) == 1:
                (v,) = vals
                if kind == "g":
                    pins2.update(zip(self.groups[key], v))
                else:
                    cells2[key] = v
        try:
            effects = residual_effects(a.effects, self.ev, pins2, cells2, lets, {})
        except Drop as exc:
            raise RelaxedTooBig(f"cannot relax the effects of {a.name}: {exc}") from None
        if effects is BAD:
            return
        try:
            leaves = self.ev.branch(lambda e: self.ev.simulate(effects, e, pins2), {}, SPLIT_LIMIT,
                                    {k: sorted(v) for k, v in narrowed.items() if len(v) > 1})
            for minterm, writes in leaves:
                if writes is None:
                    continue
                adds = [self.fact(atom, v) for atom, v in writes.items()]
                self.op(pre_facts + list(self.minterm_facts(minterm)), adds, a.cost, index)
            return
        except (TooBig, Drop):
            pass
        # Too many cases: each written atom gets its own component, fired apart and
        # shared by every context whose component reads the same after folding.
        try:
            written = [self._written(top) for top in effects]
        except Drop as exc:
            raise RelaxedTooBig(str(exc)) from None
        adds = []
        for atom in sorted(set().union(*written)):
            tops = tuple(top for top, w in zip(effects, written) if atom in w)
            key = (index, atom, tuple(map(id, tops)))
            f = self.fired.get(key)
            if f is None:
                comp = _component(tops, atom, self.ev)
                try:
                    leaves = self.ev.branch(lambda e: self.ev.simulate(comp, e, pins2), {}, 1)
                    if len(leaves) == 1 and not leaves[0][0] and leaves[0][1] is not None:
                        adds.extend(self.fact(at, v) for at, v in leaves[0][1].items())
                        continue
                except (TooBig, Drop, Fail):
                    pass
                f = self.new_fact(f"fired:{a.name}#{len(self.fired)}")
                self.fired[key] = f
                self.keep.append(tops)   # their ids stay theirs
                self.fire_effects(comp, f, atom, a.cost)
            adds.append(f)
        key = self.op(pre_facts, adds, a.cost, index)
        if key is not None and all(f in self.chained for f in adds):
            self.step_costs[key] = 0   # its steps pay for it (fire_effects)

    def _written(self, top) -> frozenset:
        hit = self.written_cache.get(id(top))
        w = None if hit is None else hit[1]
        if w is None:
            w = frozenset(self.ev.written_atoms((top,), set()))
            self.written_cache[id(top)] = (top, w)
        return w

    def fire_effects(self, effects, fired: int, atom, cost) -> None:
        """Zero-cost operators, one per old value of the written atom (and, where the
        effects' conditions read other atoms, per value of those: FIRE_LIMIT cases at most,
        else those conditions count as true and false, an over-approximation): `fired`,
        atom = old (and the conditions' facts) add the value the effects give the atom.

        When the new value depends on the old (a count going up or down), the fired fact,
        once reached, would walk the atom through every value for free: one execution
        standing for many. Such steps cost the action's `cost` in the guiding view
        (hadd, hff), so emptying a hand of k things counts k actions (an action whose only
        effects are such steps is free there instead: its steps pay); hmax and LM-cut keep
        the free steps, which never overestimate."""
        values = self.fired_values[fired] = (atom, set())
        steps = self.fired_steps[fired] = []    # (preconditions besides `fired`, the fact added)
        by_old: dict = {}
        exact = [True]
        for old in self.domain(atom):
            old_fact = self.fact(atom, old)
            for minterm, new in self._steps(effects, atom, old, exact):
                pre = (old_fact,) + self.minterm_facts(minterm)
                f = self.fact(atom, new)
                values[1].add(f)
                steps.append((pre, f))
                by_old.setdefault(old, set()).add(new)
        chained = len({frozenset(v) for v in by_old.values()}) > 1   # else: one constant
        if chained:
            self.chained.add(fired)
        for pre, f in steps:
            key = self.op((fired,) + pre, (f,), 0, -1)
            if chained and key is not None:
                self.step_costs[key] = cost

    def _steps(self, effects, atom, old, exact: list) -> list:
        """[(minterm over other atoms, new value)] the effects may give `atom` from `old`;
        `exact[0]` goes False (for the next old values too) once the cases are too many."""
        try:
            if not exact[0]:
                raise TooBig()
            leaves = self.ev.branch(lambda e: self.ev.simulate(effects, e, {}), {atom: old}, FIRE_LIMIT)
        except (TooBig, Drop):
            exact[0] = False
            return [((), v) for v in self.ev.candidates(effects, {atom: old}, atom, {})]
        return [(m, w[atom]) for m, w in leaves if w is not None and atom in w and w[atom] != old]

    def build_goal(self):
        try:
            r = residual(self.goal, self.ev, {}, {}, {}, {})
        except Drop:
            return ()
        if r is BAD or r == ir.FALSE:
            return None
        parts = self.clusters(conjuncts(r), {})
        if parts is None:
            return None
        out = []
        for minterms in parts:
            out.extend(self.condition(minterms))
        return tuple(sorted(set(out)))


def _component(effects, atom, ev) -> tuple:
    """The part of `effects` that may write `atom` (conditions kept, other writes dropped)."""
    out = []
    for e in effects:
        if isinstance(e, ir.When):
            then, orelse = _component(e.then, atom, ev), _component(e.orelse, atom, ev)
            if then or orelse:
                out.append(ir.When(e.cond, then, orelse))
        elif atom in ev.written_atoms((e,), set()):
            out.append(e)
    return tuple(out)

