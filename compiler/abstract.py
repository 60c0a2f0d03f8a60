"""Over-approximate what values expressions can take, without search.

Used to find the goal's possible agent positions (the Manhattan heuristic's targets): a
value is a frozenset of possible values, or None for "anything". Mutable grid cells can
hold their initial value or any value some action may write there; a written value `v`
counts only if the writing action's preconditions are not definitely false when its
value expression is pinned to `v` (so a value the preconditions forbid is never written).
"""
from __future__ import annotations

import itertools
import operator

from . import ir

MAX_COMBOS = 4096
_OPS = {"+": operator.add, "-": operator.sub, "*": operator.mul,
        "//": lambda a, b: a // b if b else None, "%": lambda a, b: a % b if b else None}
_CMP = {"==": operator.eq, "!=": operator.ne, "<": operator.lt, "<=": operator.le, ">": operator.gt, ">=": operator.ge}
UNKNOWN_BOOL = frozenset({False, True})


class Abstract:
    def __init__(self, layout, lets: dict, cell_values, fixed: dict | None = None, pins: dict | None = None):
        self.L, self.lets, self.cell_values = layout, lets, cell_values
        self.fixed, self.pins = fixed or {}, pins or {}

    def eval(self, node):
        if node in self.pins:
            return self.pins[node]
        m = getattr(self, "e_" + type(node).__name__, None)
        return m(node) if m else None

    def e_Const(self, node):
        return frozenset({node.value})

    def e_Local(self, node):
        if node.name in self.lets:
            return self.eval(self.lets[node.name])
        return None

    def e_Var(self, node):
        v = self.fixed.get(node.var)
        return None if v is None else frozenset({v})

    def e_Cell(self, node):
        coords = [self.eval(c) for c in (node.x, node.y, node.z)]
        if any(c is None for c in coords):
            return None
        out = set()
        for x, y, z in itertools.product(*coords):
            out |= self.cell_values(x, y, z)
        return frozenset(out)

    def e_Lookup(self, node):
        idx = self.eval(node.index)
        if idx is None:
            return frozenset(node.table) if len(set(node.table)) < MAX_COMBOS else None
        return frozenset(node.table[i] for i in idx if 0 <= i < len(node.table))

    def _combine(self, fn, parts):
        values = [self.eval(p) for p in parts]
        if any(v is None for v in values):
            return None
        if eval_size(values) > MAX_COMBOS:
            return None
        return frozenset(r for combo in itertools.product(*values) if (r := fn(*combo)) is not None)

    def e_Arith(self, node):
        return self._combine(_OPS[node.op], (node.left, node.right))

    def e_Neg(self, node):
        return self._combine(operator.neg, (node.operand,))

    def e_Cmp(self, node):
        def chain(*vals):
            return all(_CMP[op](a, b) for op, a, b in zip(node.ops, vals, vals[1:]))
        return self._combine(chain, node.operands)

    def e_Not(self, node):
        v = self.eval(node.operand)
        return UNKNOWN_BOOL if v is None else frozenset(not b for b in v)

    def e_BoolOp(self, node):
        values = [self.eval(i) for i in node.items]
        decisive = node.op == "or"
        if any(v is not None and v == frozenset({decisive}) for v in values):
            return frozenset({decisive})
        if all(v is not None and v == frozenset({not decisive}) for v in values):
            return frozenset({not decisive})
        return UNKNOWN_BOOL


def eval_size(values) -> int:
    n = 1
    for v in values:
        n *= max(1, len(v))
    return n


def maybe_true(value) -> bool:
    return value is None or True in value


def written_cell_values(layout, actions, value_count: int) -> set[int]:
    """Every value some action may write into a grid cell (see the module docstring)."""
    out: set[int] = set()
    no_cells = lambda x, y, z: frozenset(range(value_count))  # noqa: E731 - "any value", conservatively

    def walk(a, effects, guards):
        lets = {loc.name: value for loc, value in a.lets}
        for e in effects:
            if isinstance(e, ir.When):
                walk(a, e.then, guards + [e.cond])
                walk(a, e.orelse, guards + [ir.Not(e.cond)])
            elif isinstance(e, ir.SetCell):
                if isinstance(e.value, ir.Const):
                    out.add(int(e.value.value))
                    continue
                for v in range(value_count):
                    ab = Abstract(layout, lets, no_cells, pins={e.value: frozenset({v})})
                    if all(maybe_true(ab.eval(c)) for c in list(a.pre) + guards):
                        out.add(v)

    for a in actions:
        walk(a, a.effects, [])
    return out
