"""Fix the state layout: one byte per dynamic variable, then the changed grid cells.

A state is an immutable `bytes`: hashable, compact, cheap to copy (one `bytearray`).
Each dynamic attribute of each object gets one byte holding `value - low`; enumerations
hold their dense index, booleans 0/1. The grid layers that some action can change are
numbered cell by cell (layer, then z, then x: the "mutable cell index"); a state stores
only the cells whose value differs from the start's, as 4-byte entries, the int
(index << 8) | value in little-endian order, sorted by index (model.cell_entries). So the size of a state grows with
what changed, not with the map, and equal worlds give equal bytes. Everything else stays
in constant tables outside the state. Read states through `Model.view`.

The dense layout (the variables, then every mutable cell) remains for the edges that
want it (`Model.dense`, and the PDDL export's symbolic run of the dense functions).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from ..errors import BccError
from . import ir

if TYPE_CHECKING:   # the YAML front-end: not loaded by `bcc import pddl`, which only needs Layout
    from .dungeon import Dungeon
    from .ground import Grounder


@dataclass(frozen=True)
class Slot:
    var: ir.StateVar
    index: int
    lo: int
    hi: int


@dataclass(frozen=True)
class KeyedBlock:
    """Where a keyed class's dynamic attributes live: index = base + (key - key_lo) * stride + offset[attr]."""
    base: int
    stride: int
    key_lo: int
    count: int
    offsets: dict


@dataclass
class Layout:
    slots: list[Slot]
    by_var: dict
    keyed: dict[str, KeyedBlock]
    width: int
    depth: int
    height: int
    grid_base: int
    layers: tuple[int, ...]           # mutable y layers, in order
    static_grid: bytes                # the whole initial grid, [y][z][x]
    grid_default: int

    @property
    def size(self) -> int:
        """Bytes of a dense state (every mutable cell)."""
        return self.grid_base + self.mutable_cells

    @property
    def mutable_cells(self) -> int:
        return len(self.layers) * self.width * self.depth

    @property
    def start_cells(self) -> bytes:
        """The mutable cells at the start, by mutable cell index."""
        area = self.width * self.depth
        return b"".join(self.static_grid[y * area:(y + 1) * area] for y in self.layers)

    def layer_index(self, y: int) -> int | None:
        return self.layers.index(y) if y in self.layers else None

    def initial(self, grounder: Grounder, d: Dungeon) -> bytes:
        """The start state: its variables (no cell has changed yet)."""
        out = bytearray(self.grid_base)
        for slot in self.slots:
            value = grounder.value_const(slot.var.cls, slot.var.attr,
                                         grounder.object_value(slot.var.owner, slot.var.cls, slot.var.attr)).value
            if not slot.lo <= int(value) <= slot.hi:
                where = d.where.get((slot.var.owner, slot.var.attr))
                message = f"{slot.var.label} = {value} is outside its range [{slot.lo}, {slot.hi}]"
                from .source import error_at
                raise error_at(*where, message) if where else BccError(message, d.path)
            out[slot.index] = int(value) - slot.lo
        return bytes(out)


def make_layout(grounder: Grounder, d: Dungeon, dynamic: set, grid_layers: set[int] | None) -> Layout:
    dom = d.domain
    slots: list[Slot] = []

    def add(owner, cls, attr):
        rng = grounder.attr_range(dom.classes[cls], attr)
        if rng is None:
            raise BccError(f"attribute {cls}.{attr} is changed by actions, so it needs a `range: [low, high]`", dom.path)
        lo, hi = rng
        if hi - lo > 255:
            raise BccError(f"attribute {cls}.{attr} has a range of {hi - lo + 1} values; at most 256 are supported", dom.path)
        var = ir.StateVar(owner, cls, attr, dom.classes[cls].attrs[attr].type)
        slots.append(Slot(var, len(slots), lo, hi))

    keyed = {}
    for cname, cdef in dom.classes.items():
        attrs = [a for a in cdef.attrs if (cname, a) in dynamic and a not in cdef.key]
        if not attrs or cname == d.grid_class:
            continue
        if cdef.key:
            keys = grounder.keys_of(cname)
            base = len(slots)
            for key in keys:
                for a in attrs:
                    add((cname, key), cname, a)
            lo = grounder.key_ranges[cname][0][0] if len(cdef.key) == 1 else 0
            keyed[cname] = KeyedBlock(base, len(attrs), lo, len(keys), {a: i for i, a in enumerate(attrs)})
        else:
            for name in grounder.by_class[cname]:
                for a in attrs:
                    add(name, cname, a)
    layers = tuple(sorted(range(d.height) if grid_layers is None else grid_layers))
    default = int(grounder.value_const(d.grid_class, _value_attr(d), _default(d)).value) & 255   # a cell is a byte
    return Layout(slots, {s.var: s for s in slots}, keyed, d.width, d.depth, d.height, len(slots), layers,
                  bytes(d.grid), default)


def _value_attr(d: Dungeon) -> str:
    cdef = d.domain.classes[d.grid_class]
    return next(a for a in cdef.attrs if a not in cdef.key)


def _default(d: Dungeon):
    return d.domain.classes[d.grid_class].attrs[_value_attr(d)].default
