"""Relaxed reachability: which values can each variable ever take, which actions can ever apply.

A fixpoint in the spirit of Fast Downward's relaxed exploration, over value sets: start
from the initial values; while some action's preconditions may hold under the current
sets, add every value its effects may write. Grid layers collect the values written into
them. Everything over-approximates, so an action never found applicable can never apply
in any reachable state, and a layer nothing is written to is static.
"""
from __future__ import annotations

from dataclasses import dataclass

from . import ir
from .abstract import Abstract, maybe_true

WIDEN_AFTER = 2  # rounds a variable's value set may grow before it is widened to its range


@dataclass
class Reachability:
    values: dict          # StateVar -> frozenset of reachable values
    written: dict         # y -> frozenset of values some action may write into layer y
    applicable: set       # indices of actions that may apply in some reachable state


class Analysis:
    """Shared helpers over a layout: variable lookup, cell and layer value sets."""

    def __init__(self, layout, n_values: int):
        self.L, self.n_values = layout, n_values
        self.area = layout.width * layout.depth
        g = layout.static_grid
        self.static_layers = {y: frozenset(g[y * self.area:(y + 1) * self.area]) for y in range(layout.height)}

    def var_at(self, cls: str, key: int, attr: str):
        kb = self.L.keyed.get(cls)
        if kb is None or not 0 <= key - kb.key_lo < kb.count:
            return None
        return self.L.slots[kb.base + (key - kb.key_lo) * kb.stride + kb.offsets[attr]].var

    def vars_of(self, cls: str, attr: str) -> list:
        kb = self.L.keyed.get(cls)
        if kb is None:
            return []
        return [self.L.slots[kb.base + i * kb.stride + kb.offsets[attr]].var for i in range(kb.count)]

    def full_range(self, var) -> frozenset:
        slot = self.L.by_var[var]
        return frozenset(range(slot.lo, slot.hi + 1))

    def cells(self, written: dict):
        L, area = self.L, self.area

        def cell(x, y, z):
            if not (0 <= x < L.width and 0 <= z < L.depth and 0 <= y < L.height):
                return frozenset({L.grid_default})
            return frozenset({L.static_grid[y * area + z * L.width + x]}) | written.get(y, frozenset())

        def layer(y):
            if not 0 <= y < L.height:
                return frozenset({L.grid_default})
            return self.static_layers[y] | written.get(y, frozenset()) | frozenset({L.grid_default})

        return cell, layer

    def box(self, written: dict):
        """`box(xs, ys, zs)`: the union of `cell(x, y, z)` over the box, read row by row."""
        L, area = self.L, self.area
        W, D, H, grid, default = L.width, L.depth, L.height, L.static_grid, L.grid_default

        def box(xs, ys, zs):
            if not xs or not ys or not zs:
                return frozenset()
            inx = [x for x in xs if 0 <= x < W]
            inz = [z for z in zs if 0 <= z < D]
            out = set()
            if len(inx) < len(xs) or len(inz) < len(zs) or any(not 0 <= y < H for y in ys):
                out.add(default)
            if not inx or not inz:
                return frozenset(out)
            lo, hi = min(inx), max(inx)
            run = hi - lo + 1 == len(inx)      # x a run of cells (a range of positions): read a row's slice
            for y in ys:
                if not 0 <= y < H:
                    continue
                out |= written.get(y, frozenset())
                for z in inz:
                    row = y * area + z * W
                    if run:
                        out.update(grid[row + lo:row + hi + 1])
                    else:
                        out.update([grid[row + x] for x in inx])
            return frozenset(out)
        return box

    def abstract(self, action, sets: dict, written: dict, pins=None) -> Abstract:
        """An abstract evaluator for one action; after `applies`, narrowed by its preconditions."""
        cell, layer = self.cells(written)
        lets = {loc.name: value for loc, value in action.lets}
        return Abstract(lets, cell, layer, sets=sets, pins=dict(pins or {}), var_at=self.var_at, box=self.box(written))

    def applies(self, action, ab: Abstract) -> bool:
        """May the action's preconditions hold? If so, narrow `ab` by them for its effects."""
        if not all(maybe_true(ab.eval(c)) for c in action.pre):
            return False
        if not ab.narrow(action.pre):
            return True   # nothing narrowed: the preconditions evaluate as they just did
        return all(maybe_true(ab.eval(c)) for c in action.pre)


def reachable(layout, actions, initial_values: dict, n_values: int) -> Reachability:
    an = Analysis(layout, n_values)
    values = {var: frozenset({v}) for var, v in initial_values.items()}
    written: dict = {}
    applicable: set = set()
    growth: dict = {}
    changed = True
    while changed:
        changed = False
        for i, a in enumerate(actions):
            ab = an.abstract(a, values, written)
            if not an.applies(a, ab):
                continue
            applicable.add(i)
            adds: list = []
            _collect(an, a, ab, a.effects, [], values, written, adds)
            for kind, key, new in adds:
                table = values if kind == "var" else written
                if kind == "var":  # a write outside the range is a run-time error, never a state
                    new = new & an.full_range(key)
                old = table.get(key, frozenset())
                if not new <= old:
                    table[key] = old | new
                    changed = True
                    if kind == "var":
                        growth[key] = growth.get(key, 0) + 1
                        if growth[key] > WIDEN_AFTER:  # widening: a counter grows by one per round
                            table[key] = an.full_range(key)
    return Reachability(values, written, applicable)


def _collect(an: Analysis, a, ab: Abstract, effects, guards: list, values, written, adds: list):
    for e in effects:
        if isinstance(e, ir.When):
            c = ab.eval(e.cond)
            if maybe_true(c):
                _collect(an, a, ab, e.then, guards + [e.cond], values, written, adds)
            if c is None or False in c:
                _collect(an, a, ab, e.orelse, guards + [ir.Not(e.cond)], values, written, adds)
        elif isinstance(e, ir.SetVar):
            v = ab.eval(e.value)
            adds.append(("var", e.var, an.full_range(e.var) if v is None else v))
        elif isinstance(e, ir.SetVarAt):
            keys = ab.eval(e.key)
            targets = an.vars_of(e.cls, e.attr) if keys is None else \
                [t for k in keys if (t := an.var_at(e.cls, k, e.attr)) is not None]
            v = ab.eval(e.value)
            for t in targets:
                adds.append(("var", t, an.full_range(t) if v is None else v))
        elif isinstance(e, ir.SetCell):
            ys = ab.eval(e.y)
            ys = range(an.L.height) if ys is None else [y for y in ys if 0 <= y < an.L.height]
            adds.extend(("cell", y, _written_values(an, a, e, guards, values, written, ab)) for y in ys)


def _written_values(an: Analysis, a, e, guards, values, written, ab) -> frozenset:
    """Values this SetCell may write: each candidate v counts only if the action's
    preconditions and the enclosing conditions may hold with the value pinned to v."""
    if isinstance(e.value, ir.Const):
        return frozenset({int(e.value.value)})
    candidates = ab.eval(e.value)
    candidates = range(an.n_values) if candidates is None else candidates
    out = set()
    for v in candidates:
        pinned = an.abstract(a, values, written, pins={e.value: frozenset({v})})
        if an.applies(a, pinned) and all(maybe_true(pinned.eval(c)) for c in guards):
            out.add(v)
    return frozenset(out)
