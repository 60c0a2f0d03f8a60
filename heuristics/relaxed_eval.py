"""Partial and branching evaluation of grounded IR, for the relaxed view (relaxed_build.py).

`residual` folds what a context pins (variables, cells, lets, static cells) into
constants and leaves *atoms*: `Var` nodes (read through their group) and `CellAtom`s.
`Evaluator.branch` then evaluates an expression over atoms by a decision tree: when the
evaluation needs an atom's value it is tried with each value of the atom's domain, so
every leaf is a partial assignment (a minterm) with the result under it. Short-circuit
evaluation keeps the trees small (`a and b` never asks for b's atoms when a is false).
"""
from __future__ import annotations

import operator
from dataclasses import dataclass

from ..compiler import ir

MAX_LOOP_CELLS = 20_000   # a grid quantifier over more cells is left unexpanded (and relaxed away)

_OPS = {"+": operator.add, "-": operator.sub, "*": operator.mul}
_CMP = {"==": operator.eq, "!=": operator.ne, "<": operator.lt, "<=": operator.le, ">": operator.gt, ">=": operator.ge}
BAD = ir.Const(None, "<error>")   # an expression that raises at run time (out-of-range key, ...)


@dataclass(frozen=True)
class CellAtom:
    """A cell of a mutable layer, by its index among the mutable cells."""
    index: int
    type: str = "cell"


class Need(Exception):
    def __init__(self, atom):
        self.atom = atom


class Fail(Exception):
    """Evaluation hits a run-time error: no transition."""


class TooBig(Exception):
    pass


class Drop(Exception):
    """The expression cannot be evaluated over atoms (it is relaxed away)."""


def conjuncts(node) -> list:
    """Top-level conjuncts, with negations pushed through `or` (De Morgan)."""
    return ir.conjuncts(node, de_morgan=True)


_CONSTS: dict = {}
_CELLS: dict = {}


def _const(value, type_="int"):
    key = (value, "bool" if isinstance(value, bool) else type_)
    node = _CONSTS.get(key)
    if node is None:
        node = _CONSTS[key] = ir.Const(*key)
    return node


def _cell_atom(index):
    node = _CELLS.get(index)
    if node is None:
        node = _CELLS[index] = CellAtom(index)
    return node


def _key(a):
    if isinstance(a, tuple):
        return tuple(map(_key, a))
    if a is None or isinstance(a, (str, int, ir.StateVar)):
        return a
    return id(a)


def _mk(ev, cls, *args):
    """An IR node, interned: equal residuals built in different contexts are one object,
    so the builder's caches key them by identity instead of hashing whole trees again."""
    table = ev.interned
    key = (cls, *map(_key, args))
    node = table.get(key)
    if node is None:
        node = table[key] = cls(*args)
    return node


def residual(node, ev: "Evaluator", pins: dict, cells: dict, lets: dict, memo: dict, locs: dict | None = None):
    """`node` with pinned variables and cells, lets and static cells folded (BAD on a run-time error)."""
    locs = locs or {}
    r = _res(node, ev, pins, cells, lets, memo, locs)
    return r


def _res(node, ev, pins, cells, lets, memo, locs):
    """`node` residualised (see `residual`): leaves here, the other nodes by kind below."""
    t = type(node)
    if t is ir.Const:
        return node if node is BAD else _const(node.value, node.type)
    if t is CellAtom:
        return node
    if t is ir.Var:
        return _const(pins[node.var], node.var.type) if node.var in pins else _mk(ev, ir.Var, node.var)
    if t is ir.Local:
        if node.name in locs:
            return _const(locs[node.name])
        if node.name in lets:
            if node.name not in memo:
                memo[node.name] = _res(lets[node.name], ev, pins, cells, lets, memo, locs)
            return memo[node.name]
        raise Drop(node.name)
    if t is ir.VarAt or t is ir.Cell or t is ir.Lookup:
        return _res_access(node, t, ev, pins, cells, lets, memo, locs)
    if t is ir.CellLoop:
        return _res_loop(node, ev, pins, cells, lets, memo, locs)
    return _res_operator(node, t, ev, pins, cells, lets, memo, locs)


def _res_access(node, t, ev, pins, cells, lets, memo, locs):
    """A read by a key (`VarAt`), a position (`Cell`) or an index (`Lookup`): folded to
    the variable, cell or entry when the key is known."""
    if t is ir.VarAt:
        key = _res(node.key, ev, pins, cells, lets, memo, locs)
        if key is BAD:
            return BAD
        if isinstance(key, ir.Const):
            var = ev.var_at(node.cls, key.value, node.attr)
            if var is None:
                return BAD
            return _res(ir.Var(var), ev, pins, cells, lets, memo, locs)
        return _mk(ev, ir.VarAt, node.cls, key, node.attr, node.type)
    if t is ir.Cell:
        parts = [_res(p, ev, pins, cells, lets, memo, locs) for p in (node.x, node.y, node.z)]
        if any(p is BAD for p in parts):
            return BAD
        if all(isinstance(p, ir.Const) for p in parts):
            kind, value = ev.cell_at(*(p.value for p in parts))
            if kind == "const":
                return _const(value)
            return _const(cells[value]) if value in cells else _cell_atom(value)
        return _mk(ev, ir.Cell, *parts, node.type)
    i = _res(node.index, ev, pins, cells, lets, memo, locs)
    if i is BAD:
        return BAD
    if isinstance(i, ir.Const):
        return _const(node.table[i.value], node.type) if 0 <= i.value < len(node.table) else BAD
    return _mk(ev, ir.Lookup, node.table, i, node.type, node.label)


def _res_operator(node, t, ev, pins, cells, lets, memo, locs):
    """Arithmetic, comparisons and boolean operators: folded when their operands are
    constants (`and`/`or` as soon as one item decides)."""
    if t is ir.Arith:
        a = _res(node.left, ev, pins, cells, lets, memo, locs)
        b = _res(node.right, ev, pins, cells, lets, memo, locs)
        if a is BAD or b is BAD:
            return BAD
        if isinstance(a, ir.Const) and isinstance(b, ir.Const):
            try:
                return _const(_arith(node.op, a.value, b.value))
            except Fail:
                return BAD
        return _mk(ev, ir.Arith, node.op, a, b, node.type)
    if t is ir.Neg:
        a = _res(node.operand, ev, pins, cells, lets, memo, locs)
        if a is BAD:
            return BAD
        return _const(-a.value) if isinstance(a, ir.Const) else _mk(ev, ir.Neg, a)
    if t is ir.Cmp:
        ops = [_res(p, ev, pins, cells, lets, memo, locs) for p in node.operands]
        if any(p is BAD for p in ops):
            return BAD
        if all(isinstance(p, ir.Const) for p in ops):
            vals = [p.value for p in ops]
            return _const(all(_CMP[o](x, y) for o, x, y in zip(node.ops, vals, vals[1:])))
        return _mk(ev, ir.Cmp, node.ops, tuple(ops))
    if t is ir.Not:
        a = _res(node.operand, ev, pins, cells, lets, memo, locs)
        if a is BAD:
            return BAD
        return _const(not a.value) if isinstance(a, ir.Const) else _mk(ev, ir.Not, a)
    if t is ir.BoolOp:
        decisive = node.op == "or"
        items = []
        for item in node.items:
            r = _res(item, ev, pins, cells, lets, memo, locs)
            if r is BAD:
                return BAD  # evaluated left to right, an error before a decisive item raises
            if isinstance(r, ir.Const):
                if r.value == decisive:
                    return _const(decisive)
                continue
            items.append(r)
        if not items:
            return _const(not decisive)
        return items[0] if len(items) == 1 else _mk(ev, ir.BoolOp, node.op, tuple(items))
    raise Drop(t.__name__)


def _res_loop(node, ev, pins, cells, lets, memo, locs):
    """A grid quantifier, expanded over every cell (small grids only: else dropped)."""
    L = ev.L
    if L.width * L.height * L.depth > MAX_LOOP_CELLS:
        raise Drop("grid quantifier")
    expanded = []
    for y in range(L.height):
        for z in range(L.depth):
            for x in range(L.width):
                inner = dict(locs)
                inner.update(zip(node.names, (x, y, z)))
                expanded.append(_res(node.body, ev, pins, cells, lets, {}, inner))
    return _res(ir.BoolOp("or" if node.kind == "exists" else "and", tuple(expanded)), ev, pins, cells, lets,
                memo, locs) if expanded else _const(node.kind != "exists")


def _arith(op, a, b):
    if op in _OPS:
        return _OPS[op](a, b)
    if b == 0:
        raise Fail()
    return a // b if op == "//" else a % b


def residual_effects(effects, ev, pins, cells, lets, memo):
    out = []
    for e in effects:
        if isinstance(e, ir.When):
            c = _res(e.cond, ev, pins, cells, lets, memo, {})
            if c is BAD:
                return BAD
            then = residual_effects(e.then, ev, pins, cells, lets, memo)
            orelse = residual_effects(e.orelse, ev, pins, cells, lets, memo)
            if then is BAD or orelse is BAD:
                return BAD
            if isinstance(c, ir.Const):
                out.extend(then if c.value else orelse)
            elif then or orelse:
                out.append(_mk(ev, ir.When, c, then, orelse))
        elif isinstance(e, ir.SetVar):
            v = _res(e.value, ev, pins, cells, lets, memo, {})
            if v is BAD:
                return BAD
            out.append(_mk(ev, ir.SetVar, e.var, v))
        elif isinstance(e, ir.SetVarAt):
            key = _res(e.key, ev, pins, cells, lets, memo, {})
            v = _res(e.value, ev, pins, cells, lets, memo, {})
            if key is BAD or v is BAD:
                return BAD
            if isinstance(key, ir.Const):
                var = ev.var_at(e.cls, key.value, e.attr)
                if var is None:
                    return BAD
                out.append(_mk(ev, ir.SetVar, var, v))
            else:
                out.append(_mk(ev, ir.SetVarAt, e.cls, key, e.attr, v))
        elif isinstance(e, ir.SetCell):
            parts = [_res(p, ev, pins, cells, lets, memo, {}) for p in (e.x, e.y, e.z, e.value)]
            if any(p is BAD for p in parts):
                return BAD
            out.append(_mk(ev, ir.SetCell, *parts))
    return tuple(out)


class Evaluator:
    """Concrete evaluation of residual IR over an assignment of atoms, raising Need for
    an atom it does not have yet. Atoms: ("g", group) -> tuple, ("c", cell) -> value."""

    def __init__(self, layout, group_of: dict, domain):
        self.L, self.group_of, self.domain = layout, group_of, domain
        self.area = layout.width * layout.depth
        self.layer_of = {y: i for i, y in enumerate(layout.layers)}
        self.keyed = layout.keyed
        self.interned: dict = {}   # residual nodes built so far (see _mk)

    def var_at(self, cls, key, attr):
        kb = self.keyed.get(cls)
        if kb is None or not 0 <= key - kb.key_lo < kb.count:
            return None
        return self.L.slots[kb.base + (key - kb.key_lo) * kb.stride + kb.offsets[attr]].var

    def cell_at(self, x, y, z):
        """("const", value) for a cell outside the grid or in a static layer, else ("atom", index)."""
        L = self.L
        if not (0 <= x < L.width and 0 <= z < L.depth and 0 <= y < L.height):
            return "const", L.grid_default
        i = self.layer_of.get(y)
        if i is None:
            return "const", L.static_grid[y * self.area + z * L.width + x]
        return "atom", i * self.area + z * L.width + x

    # ---- evaluation ----------------------------------------------------------------------
    def value(self, node, env):
        t = type(node)
        if t is ir.Const:
            if node is BAD:
                raise Fail()
            return node.value
        if t is ir.Var:
            g, pos = self.group_of[node.var]
            atom = ("g", g)
            v = env.get(atom)
            if v is None:
                raise Need(atom)
            return v[pos]
        if t is CellAtom:
            atom = ("c", node.index)
            v = env.get(atom)
            if v is None:
                raise Need(atom)
            return v
        if t is ir.Cell:
            kind, v = self.cell_at(self.value(node.x, env), self.value(node.y, env), self.value(node.z, env))
            return v if kind == "const" else self.value(CellAtom(v), env)
        if t is ir.VarAt:
            var = self.var_at(node.cls, self.value(node.key, env), node.attr)
            if var is None:
                raise Fail()
            return self.value(ir.Var(var), env)
        if t is ir.Lookup:
            i = self.value(node.index, env)
            if not 0 <= i < len(node.table):
                raise Fail()
            return node.table[i]
        if t is ir.Arith:
            return _arith(node.op, self.value(node.left, env), self.value(node.right, env))
        if t is ir.Neg:
            return -self.value(node.operand, env)
        if t is ir.Cmp:
            a = self.value(node.operands[0], env)
            for op, nxt in zip(node.ops, node.operands[1:]):
                b = self.value(nxt, env)
                if not _CMP[op](a, b):
                    return False
                a = b
            return True
        if t is ir.Not:
            return not self.value(node.operand, env)
        if t is ir.BoolOp:
            decisive = node.op == "or"
            for item in node.items:
                if bool(self.value(item, env)) == decisive:
                    return decisive
            return not decisive
        raise Drop(t.__name__)

    def truth(self, node, env) -> bool:
        return bool(self.value(node, env))

    def branch(self, fn, env: dict, limit: int, domains: dict | None = None) -> list:
        """[(minterm, result)]: a minterm is a tuple of (atom, value) pairs (atoms not in
        env); raises TooBig past `limit` leaves. A run-time error gives result None."""
        leaves = []
        stack = [()]
        while stack:
            m = stack.pop()
            e = dict(env)
            e.update(m)
            try:
                r = fn(e)
            except Need as n:
                dom = (domains or {}).get(n.atom) or self.domain(n.atom)
                stack.extend(m + ((n.atom, v),) for v in dom)
                if len(stack) + len(leaves) > limit:
                    raise TooBig() from None
                continue
            except Fail:
                r = None
            leaves.append((m, r))
        return leaves

    # ---- effects -------------------------------------------------------------------------
    def simulate(self, effects, env, pins: dict) -> dict | None:
        """The atoms the effects write and their new values (groups as whole tuples)."""
        wv, wc = {}, {}
        self._run(effects, env, wv, wc)
        out = {}
        touched = {}
        for var, v in wv.items():
            slot = self.L.by_var[var]
            if not slot.lo <= v <= slot.hi:
                raise Fail()
            g, pos = self.group_of[var]
            touched.setdefault(g, {})[pos] = v
        for g, changes in touched.items():
            members = self.group_members[g]
            out[("g", g)] = tuple(changes[i] if i in changes else
                                  (pins[m] if m in pins else self.value(ir.Var(m), env))
                                  for i, m in enumerate(members))
        for k, v in wc.items():
            out[("c", k)] = v
        return out

    def _run(self, effects, env, wv, wc):
        for e in effects:
            t = type(e)
            if t is ir.When:
                self._run(e.then if self.truth(e.cond, env) else e.orelse, env, wv, wc)
            elif t is ir.SetVar:
                wv[e.var] = self.value(e.value, env)
            elif t is ir.SetVarAt:
                var = self.var_at(e.cls, self.value(e.key, env), e.attr)
                if var is None:
                    raise Fail()
                wv[var] = self.value(e.value, env)
            else:
                kind, k = self.cell_at(self.value(e.x, env), self.value(e.y, env), self.value(e.z, env))
                if kind == "const":
                    raise Fail()  # a write outside the grid or into a static layer: a run-time error
                wc[k] = self.value(e.value, env)

    def written_atoms(self, effects, acc: set) -> set:
        for e in effects:
            if isinstance(e, ir.When):
                self.written_atoms(e.then, acc)
                self.written_atoms(e.orelse, acc)
            elif isinstance(e, ir.SetVar):
                acc.add(("g", self.group_of[e.var][0]))
            elif isinstance(e, ir.SetVarAt):
                kb = self.keyed[e.cls]
                for i in range(kb.count):
                    var = self.L.slots[kb.base + i * kb.stride + kb.offsets[e.attr]].var
                    acc.add(("g", self.group_of[var][0]))
            else:
                parts = (e.x, e.y, e.z)
                if not all(isinstance(p, ir.Const) for p in parts):
                    raise Drop("a cell written at a place the context does not fix")
                kind, k = self.cell_at(*(p.value for p in parts))
                if kind == "atom":
                    acc.add(("c", k))
        return acc

    def candidates(self, effects, env, atom, pins) -> list:
        """Over-approximated new values of `atom` (env holds its old value): conditions that
        need other atoms count as both true and false, values that need them as anything."""
        kind, key = atom
        if kind == "g":
            members = self.group_members[key]
            cand = [set() for _ in members]
        else:
            cand = [set()]
        unknown = [False] * len(cand)

        def val(node):
            try:
                return self.value(node, env)
            except (Need, Drop):
                return None

        def walk(effs):
            for e in effs:
                t = type(e)
                if t is ir.When:
                    try:
                        c = self.truth(e.cond, env)
                    except (Need, Drop):
                        c = None
                    except Fail:
                        continue
                    if c is not False:
                        walk(e.then)
                    if c is not True:
                        walk(e.orelse)
                    continue
                if t is ir.SetVarAt:
                    k = val(e.key)
                    targets = [self.var_at(e.cls, k, e.attr)] if k is not None else \
                        [self.var_at(e.cls, kk + self.keyed[e.cls].key_lo, e.attr) for kk in range(self.keyed[e.cls].count)]
                    targets = [v for v in targets if v is not None]
                elif t is ir.SetVar:
                    targets = [e.var]
                else:
                    if kind != "c":
                        continue
                    k = self.cell_at(e.x.value, e.y.value, e.z.value)
                    if k != ("atom", key):
                        continue
                    v = val(e.value)
                    if v is None:
                        unknown[0] = True
                    else:
                        cand[0].add(v)
                    continue
                for var in targets:
                    g, pos = self.group_of[var]
                    if kind == "g" and g == key:
                        try:
                            v = val(e.value)
                        except Fail:
                            continue
                        if v is None:
                            unknown[pos] = True
                        else:
                            cand[pos].add(v)

        walk(effects)
        old = env[atom]
        if kind == "c":
            values = set(range(self.n_values)) if unknown[0] else cand[0]
            return sorted(v for v in values if v != old)
        out = []
        per = []
        for pos, m in enumerate(self.group_members[key]):
            slot = self.L.by_var[m]
            vals = set(range(slot.lo, slot.hi + 1)) if unknown[pos] else cand[pos] | {old[pos]}
            per.append(sorted(v for v in vals if slot.lo <= v <= slot.hi))
        import itertools
        for t in itertools.product(*per):
            if t != old:
                out.append(t)
        return out
