"""What the agent carries, read from the model's actions: which state variables count
blocks of which material, and how many blocks one unit of each stands for.

A Minecraft player carries items; a model carries whatever its variables say. Nothing
here knows a domain's names: the meaning comes from the grounded actions' effects.

- An action that writes a cell to a constant block T and, always, takes one from a
  variable v (`v = v - 1`) places T out of v: v counts blocks of T, one a unit.
- An action that writes a cell to the empty value and, when the cell held T, adds to v
  (`when T == ... { v = v + 1 }`) mines T into v: v counts T too.
- An action that writes no cell and does not move the agent, needs v == 0, sets v to a
  constant C and takes j from u, only repacks what is carried (a full stack opened): u
  counts T as well, C / j blocks a unit.

The total of T in a state is then the sum of its variables times their units; the game's
inventory is read back into those variables (see `Inventory.assign`).
"""
from __future__ import annotations

from dataclasses import dataclass

from ..compiler import ir


@dataclass(frozen=True)
class Holding:
    """One state variable that counts blocks of a material."""
    label: str
    index: int      # the variable's place in the (dense) state
    lo: int
    hi: int
    unit: int       # blocks one unit stands for


@dataclass(frozen=True)
class Inventory:
    holdings: dict          # material name -> (Holding, ...), the unit-1 holding first

    @property
    def labels(self) -> set:
        return {h.label for hs in self.holdings.values() for h in hs}

    def totals(self, state: bytes) -> dict:
        """{material: blocks carried} in a (compact or dense) state."""
        return {t: sum((state[h.index] + h.lo) * h.unit for h in hs) for t, hs in self.holdings.items()}

    def assign(self, dense: bytearray, totals: dict, hint: bytes | None = None) -> list:
        """Write the game's per-material totals into the holdings of a dense state. Where
        the hint (the predicted state) carries the same total, its split between open and
        full stacks is kept (the game has no such split); otherwise the biggest units are
        filled first. Returns notes for what does not fit."""
        notes = []
        for t, hs in self.holdings.items():
            n = int(totals.get(t, 0))
            if hint is not None and sum((hint[h.index] + h.lo) * h.unit for h in hs) == n:
                for h in hs:
                    dense[h.index] = hint[h.index]
                continue
            left = n
            for h in sorted(hs, key=lambda h: -h.unit):
                take = min(h.hi, max(h.lo, left // h.unit))
                dense[h.index] = take - h.lo
                left -= take * h.unit
            if left:
                notes.append(f"the player carries {n} {t}, which {', '.join(h.label for h in hs)} cannot hold")
        return notes


def _taken(node, var):
    """k for `var - k` (a positive constant k), else None."""
    if isinstance(node, ir.Arith) and node.op == "-" and isinstance(node.left, ir.Var) \
            and node.left.var == var and isinstance(node.right, ir.Const) and node.right.value > 0:
        return node.right.value
    return None


def _added(node, var) -> bool:
    return isinstance(node, ir.Arith) and node.op == "+" and isinstance(node.left, ir.Var) \
        and node.left.var == var and isinstance(node.right, ir.Const) and node.right.value > 0


def _when_value(cond, value_type: str):
    """T for a condition `T == something` (T a constant of the grid's value type)."""
    if isinstance(cond, ir.Cmp) and cond.ops == ("==",):
        for o in cond.operands:
            if isinstance(o, ir.Const) and o.type == value_type:
                return o.value
    return None


def _needs_zero(action, var) -> bool:
    for p in action.pre:
        if isinstance(p, ir.Cmp) and p.ops == ("==",):
            a, b = p.operands
            if (isinstance(a, ir.Var) and a.var == var and isinstance(b, ir.Const) and b.value == 0) or \
                    (isinstance(b, ir.Var) and b.var == var and isinstance(a, ir.Const) and a.value == 0):
                return True
    return False


def derive(model) -> Inventory | None:
    """The model's inventory, or None when the model has no grounded actions to read."""
    c = model.data("compiled")
    if c is None:
        return None
    g = model.grid
    counts: dict = {}                        # StateVar -> (material index, unit)
    position = set(c.position_vars)
    repacks = []
    for a in c.actions:
        cells = [e for e in a.effects if isinstance(e, ir.SetCell)]
        sets = [e for e in a.effects if isinstance(e, ir.SetVar)]
        for e in cells:
            if isinstance(e.value, ir.Const):
                if e.value.value != g.default:
                    taken = [s.var for s in sets if _taken(s.value, s.var) == 1]
                    if len(taken) == 1:
                        counts.setdefault(taken[0], (e.value.value, 1))
                else:
                    for w in a.effects:
                        if isinstance(w, ir.When):
                            t = _when_value(w.cond, e.value.type)
                            for s in w.then:
                                if t is not None and isinstance(s, ir.SetVar) and _added(s.value, s.var):
                                    counts.setdefault(s.var, (t, 1))
        if not cells and not any(s.var in position for s in sets) and len(sets) == 2:
            repacks.append((a, sets))
    changed = True
    while changed:          # repacking may chain (stacks of stacks)
        changed = False
        for a, sets in repacks:
            for s, other in ((sets[0], sets[1]), (sets[1], sets[0])):
                if s.var in counts and other.var not in counts and isinstance(s.value, ir.Const) \
                        and _needs_zero(a, s.var):
                    j = _taken(other.value, other.var)
                    t, unit = counts[s.var]
                    if j and (s.value.value * unit) % j == 0:
                        counts[other.var] = (t, s.value.value * unit // j)
                        changed = True
    holdings: dict = {}
    for var, (t, unit) in counts.items():
        slot = c.layout.by_var.get(var)
        if slot is None:
            continue            # a constant count: nothing to show or read back
        v = next(v for v in model.variables if v.label == var.label)
        holdings.setdefault(g.value_names[t], []).append(Holding(v.label, v.index, v.lo, v.hi, unit))
    return Inventory({t: tuple(sorted(hs, key=lambda h: (h.unit, h.label))) for t, hs in holdings.items()})
