"""Compile grounded IR to Python source, then to functions (the hot loop never sees an AST).

For each grounded action: `apply_i(s) -> bytes | None` and `why_i(s) -> int | None` (the
index of the first failing precondition, for `bcc validate`). One `successors(s)` inlines
every action, evaluating each `let` only when a precondition first needs it. Also
`goal(s)` and `failure(s)`. Reads come from the old state `s`, writes go to `n`.

States are compact (see compiler/layout.py): the variables, then the changed mutable
cells. A function that reads cells first expands them, once, into `c` (the start's cells
when nothing changed, no copy); cell writes are collected in `w` and merged into the new
state's sorted diff. `compact=False` emits the same functions over the dense layout
(variables, then every mutable cell), which the PDDL export executes symbolically.
"""
from __future__ import annotations

import functools
import itertools
import math

from ..errors import BccError, InternalError, ModelError
from ..model import fresh_from
from . import ir
from .ir import GroundAction
from .access import CELLS, constant_stores, delta_slots, effect_locals, var_reads, writes, writes_any
from .emit_helpers import run_time_helpers
from .emit_layers import LayerExpanders
from .layout import Layout


_MIRROR = {"<": ">", "<=": ">=", ">": "<", ">=": "<=", "==": "=="}   # c OP v  <=>  v MIRROR[OP] c


class Emitter(LayerExpanders):
    def __init__(self, layout: Layout, enum_sizes: dict, compact: bool = True):
        self.L = layout
        self.enum_sizes = enum_sizes
        self.compact = compact
        # where cell reads and writes go: the expanded cells `c` and the write dict `w`
        # (compact), or the state itself past grid_base (dense)
        self.read_cells, self.write_cells = ("c", "w") if compact else ("s", "n")
        self.cell_base = 0 if compact else layout.grid_base
        self.uses_cells = False   # set while emitting a function that reads cells
        self.state = "s"          # the name variable reads come from (the failure test reads `t`)
        self.delta = False        # stores add to `_d` (see `_new_state`) instead of writing `n`
        self.uses_int = False     # set while emitting a function that builds states as sums
        self.known: dict = {}     # IR local name -> (lo, hi) its preconditions so far guarantee
        self.ns: dict = {"SG": layout.static_grid, "ModelError": ModelError}
        self.tables: dict = {}
        self.tmp = itertools.count()
        self.locals: dict = {}  # IR local name -> generated identifier (input text never becomes code)
        self.area = layout.width * layout.depth
        self._install_helpers()

    # ---- namespace ---------------------------------------------------------------------
    def local(self, name: str) -> str:
        """The generated identifier of an IR local: `v<number>`, never the name from the file."""
        if name not in self.locals:
            self.locals[name] = f"v{len(self.locals)}"
        return self.locals[name]

    def table(self, values: tuple) -> str:
        if values not in self.tables:
            name = f"T{len(self.tables)}"
            self.tables[values] = name
            self.ns[name] = tuple(int(v) for v in values)
        return self.tables[values]

    def _install_helpers(self):
        """The run-time helpers the generated code calls (emit_helpers.py)."""
        self.ns.update(run_time_helpers(self.L, self.area, self.cell_base))

    # ---- expressions -------------------------------------------------------------------
    def simple(self, node) -> bool:
        return isinstance(node, (ir.Const, ir.Local, ir.Var))

    def var_range(self, node):
        if isinstance(node, ir.Const):
            return node.value, node.value
        if isinstance(node, ir.Var):
            slot = self.L.by_var[node.var]
            return slot.lo, slot.hi
        return None

    def within(self, node, lo: int, hi: int) -> bool:
        r = self.interval(node)
        return r is not None and lo <= r[0] and r[1] <= hi

    def interval(self, node):
        """Bounds of an integer expression's value, when cheaply known (else None)."""
        if isinstance(node, (ir.Const, ir.Var)):
            return self.var_range(node)
        if isinstance(node, ir.Local) and node.name in self.known:
            return self.known[node.name]
        if node.type == "bool":
            return 0, 1
        if node.type in self.enum_sizes:
            return 0, self.enum_sizes[node.type] - 1
        if isinstance(node, ir.Lookup):
            return min(node.table), max(node.table)
        if isinstance(node, ir.Arith):
            a, b = self.interval(node.left), self.interval(node.right)
            if node.op == "%" and isinstance(node.right, ir.Const) and node.right.value > 0:
                return 0, node.right.value - 1
            if a is None or b is None:
                return None
            if node.op == "+":
                return a[0] + b[0], a[1] + b[1]
            if node.op == "-":
                return a[0] - b[1], a[1] - b[0]
        return None

    def _nonzero(self, node) -> bool:
        """The divisor can never be 0 (a constant, or a value whose bounds exclude it)."""
        if isinstance(node, ir.Const):
            return node.value != 0
        bounds = self.interval(node)
        return bounds is not None and (bounds[0] > 0 or bounds[1] < 0)

    def ex(self, node) -> str:
        if isinstance(node, ir.Const):
            return repr(bool(node.value)) if node.type == "bool" else str(int(node.value))
        if isinstance(node, ir.Local):
            return self.local(node.name)
        if isinstance(node, ir.Var):
            slot = self.L.by_var.get(node.var)
            if slot is None:
                raise InternalError(f"{node.var.label} has no place in the state")
            s = self.state
            return f"{s}[{slot.index}]" if slot.lo == 0 else f"({s}[{slot.index}] + {slot.lo})"
        if isinstance(node, ir.VarAt):
            return f"{self.state}[{self.keyed_index(node.cls, node.key, node.attr)}]" + \
                self._lo_suffix(node.cls, node.attr)
        if isinstance(node, ir.Cell):
            return self.cell(node)
        if isinstance(node, ir.Lookup):
            idx = self.ex(node.index)
            if not self.within(node.index, 0, len(node.table) - 1):
                idx = f"_index({idx}, {len(node.table)}, {node.label!r})"
            return f"{self.table(node.table)}[{idx}]"
        if isinstance(node, ir.Arith):
            if node.op in ("//", "%") and not self._nonzero(node.right):
                return f"_divide({self.ex(node.left)}, {self.ex(node.right)}, {node.op == '%'}, {node.label!r})"
            return f"({self.ex(node.left)} {node.op} {self.ex(node.right)})"
        if isinstance(node, ir.Neg):
            return f"(-{self.ex(node.operand)})"
        if isinstance(node, ir.Cmp):
            parts = [self.ex(node.operands[0])]
            for op, operand in zip(node.ops, node.operands[1:]):
                parts += [op, self.ex(operand)]
            return "(" + " ".join(parts) + ")"
        if isinstance(node, ir.BoolOp):
            return "(" + f" {node.op} ".join(self.ex(i) for i in node.items) + ")"
        if isinstance(node, ir.Not):
            return f"(not {self.ex(node.operand)})"
        if isinstance(node, ir.CellLoop):
            x, y, z = (self.local(n) for n in node.names)
            fn = "any" if node.kind == "exists" else "all"
            L = self.L
            return (f"{fn}({self.ex(node.body)} for {y} in range({L.height}) "
                    f"for {z} in range({L.depth}) for {x} in range({L.width}))")
        raise InternalError(f"cannot compile {type(node).__name__}")

    def _lo_suffix(self, cls, attr) -> str:
        kb = self.L.keyed[cls]
        slot = self.L.slots[kb.base + kb.offsets[attr]]
        return f" + {slot.lo}" if slot.lo else ""

    def keyed_index(self, cls: str, key, attr: str) -> str:
        kb = self.L.keyed.get(cls)
        if kb is None:
            raise InternalError(f"class {cls} has no dynamic attributes in the state")
        k = self.ex(key)
        rel = k if kb.key_lo == 0 else f"({k} - {kb.key_lo})"
        if not self.within(key, kb.key_lo, kb.key_lo + kb.count - 1):
            rel = f"_index({rel}, {kb.count}, {cls + '[]'!r})"
        return f"{kb.base + kb.offsets[attr]} + {rel} * {kb.stride}"

    def cell(self, node: ir.Cell) -> str:
        L = self.L
        if not isinstance(node.y, ir.Const) or not (self.simple(node.x) and self.simple(node.z)):
            self.uses_cells = True
            return f"_cell({self.read_cells}, {self.ex(node.x)}, {self.ex(node.y)}, {self.ex(node.z)})"
        y = node.y.value
        if not 0 <= y < L.height:
            return str(L.grid_default)
        X, Z = self.ex(node.x), self.ex(node.z)
        layer = L.layer_index(y)
        if layer is None:
            base, arr = y * self.area, "SG"
        else:
            base, arr = self.cell_base + layer * self.area, self.read_cells
            self.uses_cells = True
        checks = []
        if not self.within(node.x, 0, L.width - 1):
            checks.append(f"0 <= {X} < {L.width}")
        if not self.within(node.z, 0, L.depth - 1):
            checks.append(f"0 <= {Z} < {L.depth}")
        read = f"{arr}[{base} + {Z} * {L.width} + {X}]"
        return f"({read} if {' and '.join(checks)} else {L.grid_default})" if checks else read

    # ---- effects -----------------------------------------------------------------------
    def effects(self, effects, indent: str, action: str) -> list[str]:
        lines = []
        for e in effects:
            if isinstance(e, ir.When):
                lines.append(f"{indent}if {self.ex(e.cond)}:")
                lines += self.effects(e.then, indent + "    ", action) or [indent + "    pass"]
                orelse = e.orelse
                while len(orelse) == 1 and isinstance(orelse[0], ir.When):   # an elif chain, one block
                    lines.append(f"{indent}elif {self.ex(orelse[0].cond)}:")
                    lines += self.effects(orelse[0].then, indent + "    ", action) or [indent + "    pass"]
                    orelse = orelse[0].orelse
                if orelse:
                    lines.append(f"{indent}else:")
                    lines += self.effects(orelse, indent + "    ", action)
            elif isinstance(e, ir.SetVar):
                slot = self.L.by_var[e.var]
                lines += self.store(f"{slot.index}", e.value, slot.lo, slot.hi, e.var.label, indent)
            elif isinstance(e, ir.SetVarAt):
                kb = self.L.keyed[e.cls]
                slot = self.L.slots[kb.base + kb.offsets[e.attr]]
                lines += self.store(self.keyed_index(e.cls, e.key, e.attr), e.value, slot.lo, slot.hi,
                                    f"{e.cls}[].{e.attr}", indent)
            elif isinstance(e, ir.SetCell):
                lines += self.store_cell(e, indent, action)
            else:
                raise InternalError(f"cannot compile effect {type(e).__name__}")
        return lines

    def store(self, index: str, value, lo: int, hi: int, label: str, indent: str) -> list[str]:
        if isinstance(value, ir.Const):
            v = int(value.value)
            if not lo <= v <= hi:
                raise BccError(f"an effect sets {label} to {v}, outside its range [{lo}, {hi}]")
            return [self._put(index, str(v - lo), indent, value, hi - lo)]
        if value.type != "int" or self.within(value, lo, hi):
            return [self._put(index, self.ex(value) + (f" - {lo}" if lo else ""), indent, value, hi - lo)]
        t = f"_t{next(self.tmp)}"
        return [f"{indent}{t} = {self.ex(value)}",
                f"{indent}if not {lo} <= {t} <= {hi}: _range({label!r}, {t}, {lo}, {hi})",
                self._put(index, t + (f" - {lo}" if lo else ""), indent)]

    def _put(self, index: str, stored: str, indent: str, value=None, span: int = 255) -> str:
        """Store byte `stored` at state index `index`: into the copy `n`, or, building the
        next state as a sum (`self.delta`), add its change at that byte to `_d`. A change
        that depends on that byte alone (a constant, a turn `(d + 1) % 4`) is read from a
        table of its shifted values, one per old value (0..span)."""
        if not self.delta:
            return f"{indent}n[{index}] = {stored}"
        shift = 8 * int(index)
        change = f"({stored} - s[{index}])"
        if value is not None and not ir.locals_of(value):
            reads, complex_ = var_reads(value)
            if not complex_ and {self.L.by_var[v].index for v in reads} <= {int(index)}:
                code = compile(f"{change} << {shift}", "<bcc table>", "eval")
                old = bytearray(int(index) + 1)
                values = []
                for b in range(span + 1):
                    old[int(index)] = b
                    values.append(eval(code, self.ns, {"s": old}))
                return f"{indent}_d += {self.table(tuple(values))}[s[{index}]]"
        return f"{indent}_d += {change} << {shift}" if shift else f"{indent}_d += {change}"

    def store_cell(self, e: ir.SetCell, indent: str, action: str) -> list[str]:
        L = self.L
        value = self.ex(e.value)
        if isinstance(e.y, ir.Const) and L.layer_index(e.y.value) is not None and self.simple(e.x) and self.simple(e.z):
            X, Z = self.ex(e.x), self.ex(e.z)
            base = self.cell_base + L.layer_index(e.y.value) * self.area
            w = self.write_cells
            lines = []
            if not (self.within(e.x, 0, L.width - 1) and self.within(e.z, 0, L.depth - 1)):
                lines.append(f"{indent}if not (0 <= {X} < {L.width} and 0 <= {Z} < {L.depth}): "
                             f"_set_cell({w}, {X}, {e.y.value}, {Z}, 0, {action!r})")
            return lines + [f"{indent}{w}[{base} + {Z} * {L.width} + {X}] = {value}"]
        return [f"{indent}_set_cell({self.write_cells}, {self.ex(e.x)}, {self.ex(e.y)}, {self.ex(e.z)}, "
                f"{value}, {action!r})"]

    # ---- whole functions ---------------------------------------------------------------
    def action_parts(self, a: GroundAction):
        """Yield ("let", line) / ("pre", expr) in the order they are needed."""
        defs = {loc.name: (loc, value) for loc, value in a.lets}
        done: set = set()

        def need(names):
            for name in sorted(names, key=lambda nm: [l.name for l, _ in a.lets].index(nm) if nm in defs else -1):
                if name in done or name not in defs:
                    continue
                loc, value = defs[name]
                yield from need(ir.locals_of(value))
                done.add(name)
                yield "let", f"{self.local(loc.name)} = {self.ex(value)}"

        self.known = {}
        for cond in a.pre:
            yield from need(ir.locals_of(cond))
            yield "pre", self.ex(cond)
            self.learn(cond)   # what follows runs only where `cond` held
        yield from need(effect_locals(a.effects))

    def learn(self, cond) -> None:
        """Record the bounds a precondition puts on locals (`0 <= v < 14`), so that reads
        and stores after it skip range checks it already made."""
        if isinstance(cond, ir.BoolOp) and cond.op == "and":
            for item in cond.items:
                self.learn(item)
            return
        if not isinstance(cond, ir.Cmp):
            return
        for op, left, right in zip(cond.ops, cond.operands, cond.operands[1:]):
            if isinstance(left, ir.Local) and isinstance(right, ir.Const):
                local, c, op = left, int(right.value), op
            elif isinstance(left, ir.Const) and isinstance(right, ir.Local):
                local, c, op = right, int(left.value), _MIRROR.get(op)
            else:
                continue
            lo, hi = self.known.get(local.name, (-math.inf, math.inf))
            if op in ("<", "<="):
                hi = min(hi, c - 1 if op == "<" else c)
            elif op in (">", ">="):
                lo = max(lo, c + 1 if op == ">" else c)
            elif op == "==":
                lo, hi = max(lo, c), min(hi, c)
            else:
                continue
            self.known[local.name] = (lo, hi)

    def _new_state(self, a: GroundAction, indent: str, sums: bool = False) -> tuple[list[str], str]:
        """Lines that make the next state and apply a's effects, and the expression of the
        finished state. With `sums`, an action that writes only fixed variables, each at
        most once, builds it as one integer: `_I` (the state read as a little-endian int)
        plus each written byte's change shifted to its place, turned back into bytes
        (`_L` long, so the changed cells after the variables are kept): one object per
        next state instead of a bytearray copy and its bytes copy."""
        if sums and self.compact and delta_slots(a.effects, self.L) is not None:
            self.delta = self.uses_int = True
            try:
                lines = [f"{indent}_d = 0"] + self.effects(a.effects, indent, a.name)
            finally:
                self.delta = False
            first = f"{indent}_d += "
            if len(lines) > 1 and lines[1].startswith(first):
                if len(lines) == 2:   # one unconditional store: no `_d` at all
                    return [], f"(_I + {lines[1][len(first):]}).to_bytes(_L, 'little')"
                lines[:2] = [f"{indent}_d = " + lines[1][len(first):]]
            return lines, "(_I + _d).to_bytes(_L, 'little')"
        lines = [f"{indent}n = bytearray(s)"]
        writes_cells = self.compact and CELLS in writes(a.effects)
        if writes_cells:
            lines.append(f"{indent}w = {{}}")
        lines += self.effects(a.effects, indent, a.name)
        return lines, "_merge(n, w)" if writes_cells else "bytes(n)"

    def _function(self, header: str, body: list[str]) -> str:
        """A function whose body reads cells gets their expansion as its first line."""
        nv = self.L.grid_base   # inline `_cells(s)`: most states changed no cell
        prologue = [f"    c = _S0 if len(s) == {nv} else _CC.get(s[{nv}:]) or _expand(s[{nv}:])"] \
            if self.compact and self.uses_cells else []
        if self.uses_int:
            prologue.append("    _I = _from_bytes(s, 'little'); _L = len(s)")
        self.uses_cells = self.uses_int = False
        return "\n".join([header] + prologue + body)

    def successors_source(self, actions: list[GroundAction], search: list[int], failure=None,
                          fresh: bool = False) -> str:
        """`successors(s)`: every applicable search action and its next state. With
        `failure` (the failure condition), `live(s)` instead: the same, less next states
        equal to `s` (an action whose constant writes change nothing is not even tried)
        and failure states that are not goals -- what a search keeps. The failure test
        runs only after actions that write a variable it reads; a state that already fails
        goes through `_live_slow`.

        With `fresh` too, `fresh(s, seen, out)`: the search's inner loop fused with `live`
        for searches whose first path to a state is a cheapest one (breadth-first, blind
        search with equal costs). Each next state not yet a key of `seen` becomes one,
        with `s` as its value (its parent), and is appended to `out`; it returns how many
        next states `live` would have listed (duplicates included). No pair, no list."""
        self.uses_cells = False
        live = failure is not None
        failure_false = live and isinstance(failure, ir.Const) and not failure.value
        lines = ["    _k = 0"] if fresh else ["    out = []"]
        if live and not failure_false:
            slow = "_fresh_slow(s, seen, out)" if fresh else "_live_slow(s)"
            lines.append(f"    if {self.ex(failure)}: return {slow}")
        lines += self._search_body(actions, search, failure, "    ",
                                   lambda i, state, indent: self._keep(i, state, indent, fresh))
        lines.append("    return _k" if fresh else "    return out")
        name = "fresh" if fresh else "live" if live else "successors"
        return self._function(f"def {name}(s, seen, out):" if fresh else f"def {name}(s):", lines)

    def _search_body(self, actions: list[GroundAction], search: list[int], failure, base: str, keep,
                     skip=frozenset()) -> list[str]:
        """Every search action but those in `skip`, inlined: its lets, its preconditions as
        nested ifs, its next state; `keep(i, state, indent)` gives the lines that hand the
        next state on. With `failure`, what `live` leaves out is left out (see
        `successors_source`)."""
        live = failure is not None
        reads, complex_failure = var_reads(failure) if live else (set(), False)
        failure_false = live and isinstance(failure, ir.Const) and not failure.value
        lines = []
        for i in search:
            if i in skip:
                continue
            a = actions[i]
            lines.append(f"{base}# action {i}")  # a number, never the name: comments carry no input text
            indent = base
            for kind, text in self.action_parts(a):
                if kind == "let":
                    lines.append(indent + text)
                else:
                    lines.append(f"{indent}if {text}:")
                    indent += "    "
            if live:
                consts = constant_stores(a.effects, self.L)
                if consts:
                    lines.append(f"{indent}if {' or '.join(f's[{k}] != {v}' for k, v in consts)}:")
                    indent += "    "
            made, result = self._new_state(a, indent, sums=True)
            lines += made
            if live and not failure_false and (complex_failure or writes_any(a.effects, reads)):
                lines.append(f"{indent}t = {result}")
                lines.append(f"{indent}if not {self._test_on_t(failure, 'failure')} or goal(t):")
                lines += keep(i, "t", indent + "    ")
            else:
                lines += keep(i, result, indent)
        return lines

    def _test_on_t(self, node, fallback: str) -> str:
        """Condition `node` on next state `t`: inline when it reads only variables and
        fixed cells, else a call of its generated function `fallback`."""
        saved, self.uses_cells, self.state = self.uses_cells, False, "t"
        try:
            text = self.ex(node)
            return f"{fallback}(t)" if self.uses_cells else text
        finally:
            self.uses_cells, self.state = saved, "s"

    @staticmethod
    def _keep(i: int, state: str, indent: str, fresh: bool) -> list[str]:
        """Lines that hand on next state `state` of action `i`."""
        if not fresh:
            return [f"{indent}out.append(({i}, {state}))"]
        lines = [] if state == "t" else [f"{indent}t = {state}"]
        return lines + [f"{indent}_k += 1",
                        f"{indent}if t not in seen:",
                        f"{indent}    seen[t] = s",
                        f"{indent}    out.append(t)"]

    def apply_source(self, i: int, a: GroundAction) -> str:
        self.uses_cells = False
        lines = []
        for kind, text in self.action_parts(a):
            lines.append(f"    {text}" if kind == "let" else f"    if not {text}: return None")
        made, result = self._new_state(a, "    ")
        lines += made + [f"    return {result}"]
        apply = self._function(f"def apply_{i}(s):", lines)
        lines = []
        k = 0
        for kind, text in self.action_parts(a):
            if kind == "let":
                lines.append(f"    {text}")
            else:
                lines.append(f"    if not {text}: return {k}")
                k += 1
        lines.append("    return None")
        return apply + "\n" + self._function(f"def why_{i}(s):", lines)

    def predicate_source(self, name: str, node) -> str:
        self.uses_cells = False
        body = [f"    return {self.ex(node)}"]
        return self._function(f"def {name}(s):", body)

    def build(self, actions: list[GroundAction], goal_ir, failure, search: list[int]) -> tuple[dict, str]:
        """`search`: the actions `successors` generates (all but those pruned as irrelevant)."""
        parts = [self.successors_source(actions, search), self.successors_source(actions, search, failure),
                 self.successors_source(actions, search, failure, fresh=True)]
        parts += [self.apply_source(i, a) for i, a in enumerate(actions)]
        parts.append(self.predicate_source("goal", goal_ir))
        parts.append(self.predicate_source("failure", failure))
        source = "\n\n".join(parts) + "\n"
        ns = dict(self.ns)
        exec(compile(source, "<bcc model>", "exec"), ns)
        successors, fails, goal = ns["successors"], ns["failure"], ns["goal"]
        ns["_live_slow"] = live_slow = \
            lambda s: [(a, n) for a, n in successors(s) if n != s and (not fails(n) or goal(n))]
        ns["_fresh_slow"] = functools.partial(fresh_from, live_slow)
        if self.compact:
            # compiled on first use: only breadth-first and blind searches run them
            ns["_build_layers"] = functools.partial(self.layer_functions, actions, goal_ir, failure, search, ns)
        return ns, source
