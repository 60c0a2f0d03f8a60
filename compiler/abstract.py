"""Over-approximate the values expressions can take, without search (abstract interpretation).

A value is a frozenset of possible values, or None for "anything". State variables take
their values from `sets` (a StateVar -> frozenset map; missing = anything); grid cells
from `cells(x, y, z)` for known coordinates, or `layer(y)` (every value the layer may hold)
when x or z is unknown (or `box(xs, ys, zs)`, the union over a box of cells, where given: the
same answer, faster). Every operation over-approximates, so "definitely false" results
are sound facts about all states the sets describe. Used by reachability.py (which
actions can ever apply), heuristics/patterns.py (an abstraction heuristic) and the goal positions.
"""
from __future__ import annotations

import itertools
import operator

from . import ir

MAX_COMBOS = 256       # beyond this many operand combinations, integers go by intervals
MAX_SET = 4096
_OPS = {"+": operator.add, "-": operator.sub, "*": operator.mul,
        "//": lambda a, b: a // b if b else None, "%": lambda a, b: a % b if b else None}
_CMP = {"==": operator.eq, "!=": operator.ne, "<": operator.lt, "<=": operator.le, ">": operator.gt, ">=": operator.ge}
UNKNOWN_BOOL = frozenset({False, True})


class Abstract:
    def __init__(self, lets: dict, cells, layer=None, sets: dict | None = None, pins: dict | None = None,
                 var_at=None, box=None):
        self.lets, self.cells, self.layer, self.box = lets, cells, layer, box
        self.sets, self.pins, self.var_at = sets or {}, pins or {}, var_at
        self.memo: dict = {}

    def eval(self, node):
        # Only Locals and Vars are pinned; testing every node would hash whole subtrees.
        if self.pins and isinstance(node, (ir.Local, ir.Var)) and node in self.pins:
            return self.pins[node]
        m = _RULES.get(type(node))
        return m(self, node) if m else None

    def e_Const(self, node):
        return frozenset({node.value})

    def e_Local(self, node):
        if node.name in self.lets:
            if node.name not in self.memo:
                self.memo[node.name] = self.eval(self.lets[node.name])
            return self.memo[node.name]
        return None

    def e_Var(self, node):
        return self.sets.get(node.var)

    def e_VarAt(self, node):
        keys = self.eval(node.key)
        if keys is None or self.var_at is None:
            return None
        out = set()
        for k in keys:
            var = self.var_at(node.cls, k, node.attr)
            values = self.sets.get(var) if var is not None else None
            if values is None:
                return None
            out |= values
        return frozenset(out)

    def e_Cell(self, node):
        xs, ys, zs = (self.eval(c) for c in (node.x, node.y, node.z))
        if ys is None:
            return None
        if xs is None or zs is None or len(xs) * len(zs) > MAX_COMBOS:
            if self.layer is None:
                return None
            out = set()
            for y in ys:
                out |= self.layer(y)
            return frozenset(out)
        if self.box is not None:    # every cell of the box at once (reachability: ~2 M cell reads on a big structure)
            return self.box(xs, ys, zs)
        out = set()
        for x, y, z in itertools.product(xs, ys, zs):
            out |= self.cells(x, y, z)
        return frozenset(out)

    def e_Lookup(self, node):
        idx = self.eval(node.index)
        if idx is None:
            return frozenset(node.table)
        return frozenset(node.table[i] for i in idx if 0 <= i < len(node.table))

    def _values(self, parts):
        values = [self.eval(p) for p in parts]
        if any(v is None for v in values):
            return None, 0
        n = 1
        for v in values:
            n *= max(1, len(v))
        return values, n

    def e_Arith(self, node):
        values, n = self._values((node.left, node.right))
        if values is None:
            return None
        if n <= MAX_COMBOS:
            fn = _OPS[node.op]
            return frozenset(r for a, b in itertools.product(*values) if (r := fn(a, b)) is not None)
        (alo, ahi), (blo, bhi) = ((min(v), max(v)) for v in values)
        if node.op == "+":
            lo, hi = alo + blo, ahi + bhi
        elif node.op == "-":
            lo, hi = alo - bhi, ahi - blo
        elif node.op == "%" and blo > 0:
            lo, hi = 0, bhi - 1
        else:
            return None
        return frozenset(range(lo, hi + 1)) if hi - lo < MAX_SET else None

    def e_Neg(self, node):
        v = self.eval(node.operand)
        return None if v is None else frozenset(-x for x in v)

    def e_Cmp(self, node):
        values, n = self._values(node.operands)
        if values is None:
            return UNKNOWN_BOOL
        if n <= MAX_COMBOS and len(values) == 2 and values[0] and values[1]:
            return _pair_cmp(node.ops[0], *values)
        if n <= MAX_COMBOS:
            results = set()
            for combo in itertools.product(*values):
                results.add(all(_CMP[op](a, b) for op, a, b in zip(node.ops, combo, combo[1:])))
                if len(results) == 2:
                    break
            return frozenset(results)
        # Intervals: each link is decided only when the bounds settle it.
        bounds = [(min(v), max(v)) for v in values]
        decided_true = True
        for op, (alo, ahi), (blo, bhi) in zip(node.ops, bounds, bounds[1:]):
            sure, never = _interval_cmp(op, alo, ahi, blo, bhi)
            if never:
                return frozenset({False})
            decided_true &= sure
        return frozenset({True}) if decided_true else UNKNOWN_BOOL

    def narrow(self, conditions) -> bool:
        """Restrict Locals and Vars by conditions known to hold (`0 <= tx < width`): a
        non-relational refinement, sound because only values violating a hard condition go.
        Returns whether some value set shrank (if not, every evaluation stays as it was)."""
        shrank = False
        for cond in ir.conjuncts(conditions):
            if not isinstance(cond, ir.Cmp):
                continue
            free = [i for i, o in enumerate(cond.operands) if not isinstance(o, ir.Const)]
            if len(free) != 1 or not isinstance(cond.operands[free[0]], (ir.Local, ir.Var)):
                continue
            target = cond.operands[free[0]]
            values = self.eval(target)
            if values is None:
                continue
            kept = set()
            for v in values:
                vals = [o.value if isinstance(o, ir.Const) else v for o in cond.operands]
                if all(_CMP[op](a, b) for op, a, b in zip(cond.ops, vals, vals[1:])):
                    kept.add(v)
            shrank |= len(kept) != len(values)
            self.pins[target] = frozenset(kept)
        if shrank:
            self.memo.clear()
        return shrank

    def e_Not(self, node):
        v = self.eval(node.operand)
        return UNKNOWN_BOOL if v is None else frozenset(not b for b in v)

    def e_BoolOp(self, node):
        decisive = node.op == "or"
        unknown = False
        for item in node.items:  # short-circuit like the real thing, and to save work
            v = self.eval(item)
            if v is not None and v == frozenset({decisive}):
                return frozenset({decisive})
            if v is None or v != frozenset({not decisive}):
                unknown = True
        return UNKNOWN_BOOL if unknown else frozenset({not decisive})


# The rule of each IR node type (`Abstract.e_<type name>`), looked up once per node type.
_RULES = {t: getattr(Abstract, "e_" + t.__name__) for t in vars(ir).values()
          if isinstance(t, type) and hasattr(Abstract, "e_" + t.__name__)}


def maybe_true(value) -> bool:
    return value is None or True in value


_TRUE, _FALSE = frozenset({True}), frozenset({False})


def _pair_cmp(op: str, a: frozenset, b: frozenset) -> frozenset:
    """The outcomes of `a op b` over every pair of values: exactly what trying each pair
    gives, without the pairs (a position's 71 values against a constant, ~30,000 times a
    compile). Equality asks whether the sets meet; an order, where their bounds lie."""
    if op in ("==", "!="):
        can_equal = not a.isdisjoint(b)
        can_differ = len(a) > 1 or len(b) > 1 or a != b
        can_true, can_false = (can_equal, can_differ) if op == "==" else (can_differ, can_equal)
    else:     # for whole sets of values an order is settled by their bounds alone
        sure, never = _interval_cmp(op, min(a), max(a), min(b), max(b))
        can_true, can_false = not never, not sure
    if can_true and can_false:
        return UNKNOWN_BOOL
    return _TRUE if can_true else _FALSE


def _interval_cmp(op, alo, ahi, blo, bhi) -> tuple[bool, bool]:
    """(surely true, surely false) for `a op b` with a in [alo, ahi], b in [blo, bhi]."""
    if op == "<":
        return ahi < blo, alo >= bhi
    if op == "<=":
        return ahi <= blo, alo > bhi
    if op == ">":
        return alo > bhi, ahi <= blo
    if op == ">=":
        return alo >= bhi, ahi < blo
    if op == "==":
        return alo == ahi == blo == bhi, ahi < blo or bhi < alo
    return ahi < blo or bhi < alo, alo == ahi == blo == bhi  # "!="
