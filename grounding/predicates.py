"""Many goal expressions compiled against one dungeon, as fast state predicates.

Task inference tests dozens of candidate reward functions on every state of every
demonstration. `compile_dungeon(name, goal=...)` would load and ground the domain once per
candidate (~0.4 s each); here the dungeon is loaded and laid out once, and each goal is
emitted as one generated function over the same packed state (a few ms). The layout is
checked against `compile_dungeon`'s, so a predicate always reads the states the model makes.
"""
from __future__ import annotations

import functools
from pathlib import Path

from ..errors import BccError, InternalError
from ..model import Model


class Predicates:
    """Goal expressions of one dungeon -> (state -> bool), plus a cheap satisfiability test."""

    def __init__(self, model: Model, dungeon_ref: str | Path):
        from ..compiler import pipeline as c   # the compiler's own passes, reused
        from ..compiler.emit import Emitter
        from ..compiler.ground import Grounder
        from ..compiler.layout import make_layout
        from ..compiler.reachability import Analysis, reachable
        self.model = model
        d = c.load_dungeon(dungeon_ref)
        self.dungeon = d
        # The same passes as compile_dungeon: discover what actions write, fold the rest, lay out.
        Grounder(d, None).check_domain()
        discovery = Grounder(d, None)
        c._ground_actions(discovery, d)
        dynamic = {w for w in discovery.writes if w[0] != "<grid>"}
        g = Grounder(d, dynamic)
        actions = c._ground_actions(g, d)
        grid_ys = [y for kind, y in g.writes if kind == "<grid>"]
        layers = {int(y.value) for y in grid_ys if 0 <= y.value < d.height} \
            if all(isinstance(y, c.ir.Const) for y in grid_ys) else None
        venum = d.domain.enums[d.domain.classes[d.grid_class].attrs[c._grid_value_attr(d)].type]
        layout = make_layout(g, d, dynamic, layers)
        initial = layout.initial(g, d)
        reach = reachable(layout, actions, {s.var: initial[s.index] + s.lo for s in layout.slots}, len(venum.values))
        layout = make_layout(g, d, dynamic, {y for y, vals in reach.written.items() if vals})
        if layout.initial(g, d) != model.initial or layout.layers != model.grid.layers:
            raise InternalError(f"the predicate layout of {d.name} differs from the compiled model's")
        self._g, self._layout, self._reach = g, layout, reach
        self._an = Analysis(layout, len(venum.values))
        self._emitter = Emitter(layout, {n: len(e.values) for n, e in d.domain.enums.items()})
        self._position = c._position(d, layout)
        self._goal_positions = c._goal_positions
        self._count = 0
        # per-instance caches (a cache on the class would keep every dungeon alive)
        self.predicate = functools.cache(self.predicate)
        self.reads = functools.cache(self.reads)
        self._positions = functools.cache(self._positions)

    def predicate(self, text: str):
        """The compiled test `state -> bool` of a goal expression (BccError if it does not compile)."""
        from ..compiler.domain import Expr
        from ..compiler.ground import Ctx
        from ..compiler.parse import parse_expression
        from ..compiler.source import Origin
        where = Origin("<task>", 1, 1)
        src = Expr(parse_expression(text, where), where, text)
        node = self._g.bool_expr(src.node, Ctx(src))
        self._count += 1
        name = f"task_{self._count}"
        ns = dict(self._emitter.ns)
        exec(compile(self._emitter.predicate_source(name, node), "<bcc task>", "exec"), ns)
        fn = ns[name]
        fn.ir = node
        return fn

    def reads(self, text: str) -> tuple:
        """What the expression reads: (state indices of variables, whether it reads the grid)."""
        from ..compiler.access import CELLS, reads
        read = reads(self.predicate(text).ir, vars_of=self._an.vars_of)
        index = tuple(sorted(self._layout.by_var[v].index for v in read if v != CELLS and v in self._layout.by_var))
        return index, CELLS in read

    def projection(self, key: tuple):
        """state -> the part of it a `reads` key covers (for testing each distinct part once)."""
        index, cells = key
        base = self._layout.grid_base
        if cells:
            return lambda s: (bytes(s[i] for i in index), s[base:])
        return lambda s: bytes(s[i] for i in index)

    def maybe_satisfiable(self, text: str) -> bool:
        """False when abstract interpretation proves no reachable state satisfies the expression."""
        return self._positions(text)[0] > 0

    def position_dependent(self, text: str) -> bool:
        """True when the expression may hold at some agent positions but not at others."""
        found, total = self._positions(text)
        return 0 < found < total

    def _positions(self, text: str) -> tuple[int, int]:
        """(agent positions where the expression may hold, all positions) by abstract interpretation."""
        node = self.predicate(text).ir
        position, static, variables = self._position
        found = self._goal_positions(self._an, self._reach, node, position, static, variables, self._layout)
        if found is None:  # no agent position to enumerate: evaluate once over all reachable values
            from ..compiler.abstract import Abstract, maybe_true
            cell, layer = self._an.cells(self._reach.written)
            ok = maybe_true(Abstract({}, cell, layer, sets=dict(self._reach.values), var_at=self._an.var_at).eval(node))
            return int(ok), 1
        total = 1
        for dyn in position:
            if dyn is not None:
                slot = self._layout.slots[dyn[0]]
                total *= slot.hi - slot.lo + 1
        return len(found), total
