"""What writing the goal's cells consumes, and which actions supply it.

An achiever of a cell atom (heuristics/goal_cells.py) may need more than cells: a count
it decrements (`s.count -= 1` with `s.count > 0` before it). For each goal value, the
*uses* are the (variable, amount) pairs that every achiever of that value takes away;
the *demand* of a set of pending atoms is their sum per variable. A *supplier* of a
variable is any action that may set it other than by taking an amount away (adding to
it, setting it outright), read from the IR through conditional effects. A variable
whose value is below the demand is *short*; the build solver gathers it first.

Nothing here knows what the variables mean; it reads only IR shapes.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from ..compiler import ir


@dataclass
class Supplies:
    uses: dict          # goal value -> ((StateVar, amount), ...) every achiever of it takes
    suppliers: dict     # StateVar -> [action index] that may raise it
    slots: dict         # StateVar -> (state index, lo)
    refills: dict = field(default_factory=dict)   # StateVar -> ((StateVar taken, amount given per one taken), ...)

    def value(self, state: bytes, var) -> int:
        index, lo = self.slots[var]
        return state[index] + lo

    def held(self, state: bytes, var) -> int:
        """What of `var` the state holds, counting what the suppliers that turn another
        held variable into it would give (a closed stack of blocks is blocks held)."""
        out = self.value(state, var)
        for other, amount in self.refills.get(var, ()):
            if other in self.slots:
                out += self.value(state, other) * amount
        return out

    def demand(self, values, wanted=None) -> dict:
        """{var: amount} that writing atoms of these values (one per atom) takes, plus the
        amounts the goal itself wants held (`wanted`: {var: least value})."""
        out = dict(wanted or {})
        for v in values:
            for var, amount in self.uses.get(v, ()):
                out[var] = out.get(var, 0) + amount
        return out

    def short(self, state: bytes, values, wanted=None) -> dict:
        """{var: how much is missing} for the variables the atoms of `values` take (and the
        goal wants), that a supplier could raise."""
        out = {}
        for var, amount in self.demand(values, wanted).items():
            have = self.value(state, var)
            if have < amount and self.suppliers.get(var):
                out[var] = amount - have
        return out


def _taken(value, var) -> int | None:
    """`var - k` (k > 0 a constant): k, else None."""
    if isinstance(value, ir.Arith) and value.op == "-" and isinstance(value.left, ir.Var) \
            and value.left.var == var and isinstance(value.right, ir.Const):
        k = value.right.value
        return k if isinstance(k, int) and not isinstance(k, bool) and k > 0 else None
    return None


def _given(value, var) -> int:
    """What an effect that raises `var` gives at least: k for `var + k` or a constant k
    (k > 0), else 0."""
    if isinstance(value, ir.Const) and isinstance(value.value, int) and not isinstance(value.value, bool):
        return max(value.value, 0)
    if isinstance(value, ir.Arith) and value.op == "+" and isinstance(value.left, ir.Var) \
            and value.left.var == var and isinstance(value.right, ir.Const):
        k = value.right.value
        return k if isinstance(k, int) and not isinstance(k, bool) and k > 0 else 0
    return 0


def wanted(model) -> dict:
    """{var: least value} for the goal's conjuncts that hold a variable at or above a
    constant (`5 <= v`, `v >= 5`, `v > 4`; an upper bound beside it is ignored)."""
    c = model.data("compiled")
    if c is None:
        return {}
    items = c.goal.items if isinstance(c.goal, ir.BoolOp) and c.goal.op == "and" else (c.goal,)
    out = {}
    for g in items:
        if not isinstance(g, ir.Cmp):
            continue
        for op, a, b in zip(g.ops, g.operands, g.operands[1:]):
            if op in (">=", ">"):
                op, a, b = {">=": "<=", ">": "<"}[op], b, a
            if op in ("<=", "<") and isinstance(a, ir.Const) and isinstance(b, ir.Var) \
                    and isinstance(a.value, int) and not isinstance(a.value, bool):
                least = a.value + (op == "<")
                if least > 0:
                    out[b.var] = max(out.get(b.var, 0), least)
    return out


def supplies(model, cells) -> Supplies | None:
    """The analysis for a compiled model and its goal cells (heuristics/goal_cells.py), or
    None when the model has no IR."""
    c = model.data("compiled")
    if c is None:
        return None
    memo = model.memo.get("supplies")
    if memo is not None:
        return memo
    position = set(c.position_vars)
    suppliers, slots, refills = {}, {}, {}
    for index in c.search:
        effects = ir.set_vars(c.actions[index].effects)
        for s, always in effects:
            if s.var in position or _taken(s.value, s.var) is not None:
                continue
            suppliers.setdefault(s.var, []).append(index)
            given = _given(s.value, s.var)
            for t, also in effects:
                k = _taken(t.value, t.var)
                if always and also and k is not None and given and t.var not in position:
                    refills.setdefault(s.var, set()).add((t.var, given // k))
    uses = {}
    for value, achievers in cells.achievers.items():
        common = None
        for a in achievers:
            taken = {(s.var, _taken(s.value, s.var)) for s, always in ir.set_vars(c.actions[a.action].effects)
                     if always and _taken(s.value, s.var) is not None}
            common = taken if common is None else common & taken
        uses[value] = tuple(sorted(common or (), key=lambda t: t[0].label))
    for var in {v for lst in uses.values() for v, _ in lst} | set(wanted(model)):
        slot = c.layout.by_var.get(var)
        if slot is None:
            uses = {v: tuple(t for t in lst if t[0] != var) for v, lst in uses.items()}
        else:
            slots[var] = (slot.index, slot.lo)
    for var in list(refills):   # the variables taken need slots too
        for other, _ in refills[var]:
            slot = c.layout.by_var.get(other)
            if slot is not None:
                slots.setdefault(other, (slot.index, slot.lo))
    out = Supplies(uses, {v: sorted(set(a)) for v, a in suppliers.items()}, slots,
                   {v: tuple(sorted(r, key=lambda t: t[0].label)) for v, r in refills.items()})
    model.memo["supplies"] = out
    return out
