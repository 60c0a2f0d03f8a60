"""What the counting abstraction (counting.py) builds and its builder shares: the database
kept in the cache, its limits and errors, and what it reads of the grounded IR."""
from __future__ import annotations

import array
import math
import operator
from dataclasses import dataclass

from ..compiler import ir

MAX_STATES = 3_000_000     # abstract states explored at most
FULL_STATES = 500_000      # past this many with every variable kept, some are projected away
MAX_EXACT = 12             # cells kept exactly at most


class Unsupported(Exception):
    """The model is outside what this abstraction handles (no database is built)."""


class TooBig(Exception):
    """The abstraction ran past its state or time limit."""

    def __init__(self, message: str, timed_out: bool = False):
        super().__init__(message)
        self.timed_out = timed_out


TOUCH_CAP = 4  # counts are seen up to this many (cells one action touches; more: memoized by the part)
SHIFT = 24     # an abstract state's number: variables id << SHIFT | cell part id


@dataclass(frozen=True)
class CountingDatabase:
    base: int              # state[:base] are the variables
    exact: dict            # mutable cell index -> its position in the exact part
    start_exact: bytes     # the exact cells' start values
    tracked: dict          # (mutable cell index, value) -> count slot (values other than the cell's start)
    n_slots: int
    variables: dict        # the variables (bytes) of abstract states -> their id
    parts: dict            # cell parts (exact values, then 2-byte counts) -> their id
    table: dict            # abstract state number -> distance to the goal (math.inf: unreachable)
    states: int            # abstract states explored
    projected: tuple = ()  # (index, start byte) of each variable projected away
    shift: int = SHIFT

    def part(self, entries) -> bytes | None:
        """The cell part of a state (from its changed-cell `entries`), or None if some
        cell holds a value the abstraction did not expect."""
        ex = bytearray(self.start_exact)
        counts = array.array("H", bytes(2 * self.n_slots))
        exact, tracked = self.exact, self.tracked
        for e in entries:
            i = e >> 8
            p = exact.get(i)
            if p is not None:
                ex[p] = e & 255
                continue
            slot = tracked.get((i, e & 255))
            if slot is None:
                return None
            counts[slot] += 1
        return bytes(ex) + counts.tobytes()

    def project(self, state: bytes) -> bytes:
        """The state's variables, each projected one at its start value."""
        if not self.projected:
            return state[:self.base]
        vb = bytearray(state[:self.base])
        for j, c in self.projected:
            vb[j] = c
        return bytes(vb)

    def number(self, state: bytes, entries) -> int | None:
        """The abstract state's number, or None if the abstraction never met it."""
        v = self.variables.get(self.project(state))
        r = self.parts.get(self.part(entries))
        return None if v is None or r is None else v << SHIFT | r


def getter(indices):
    """A function from bytes to the values at `indices`, as one hashable value."""
    if len(indices) > 1:
        return operator.itemgetter(*indices)
    if indices:
        j = indices[0]
        return lambda b: b[j]
    return lambda b: ()


def as_numbers(dist) -> list:
    """Distances as Python numbers: ints where whole (the usual case), math.inf where no
    goal is reachable."""
    import numpy as np
    d = np.asarray(dist, dtype=np.float64)
    finite = np.isfinite(d)
    if not np.array_equal(d[finite], np.floor(d[finite])):
        return [x if x == math.inf or x != int(x) else int(x) for x in d.tolist()]
    out = np.where(finite, d, 0).astype(np.int64).tolist()
    for j in np.flatnonzero(~finite).tolist():
        out[j] = math.inf
    return out


def and_parts(node):
    if isinstance(node, ir.BoolOp) and node.op == "and":
        for item in node.items:
            yield from and_parts(item)
    else:
        yield node


def has_loop(node) -> bool:
    if isinstance(node, ir.CellLoop):
        return True
    return any(has_loop(c) for c in ir.children(node))


def cells_in(node, lets: dict | None = None, seen: set | None = None) -> list:
    """Cell nodes in an expression (through the action's lets)."""
    out = []
    seen = set() if seen is None else seen
    if isinstance(node, ir.Cell):
        out.append(node)
    if isinstance(node, ir.Local) and lets and node.name in lets and node.name not in seen:
        seen.add(node.name)
        out.extend(cells_in(lets[node.name], lets, seen))
    for c in ir.children(node):
        out.extend(cells_in(c, lets, seen))
    return out


def effect_nodes(effects, out: list) -> None:
    for e in effects:
        if isinstance(e, ir.When):
            out.append(e.cond)
            effect_nodes(e.then, out)
            effect_nodes(e.orelse, out)
        elif isinstance(e, ir.SetVar):
            out.append(e.value)
        elif isinstance(e, ir.SetVarAt):
            out.extend((e.key, e.value))
        elif isinstance(e, ir.SetCell):
            out.append(ir.Cell(e.x, e.y, e.z, "cell"))
            out.append(e.value)


def const_value(node):
    return node.value if isinstance(node, ir.Const) else None
