"""What the object-oriented model learner perceives, and how it describes what changed.

A state is seen from the agent: its own attributes, what its index attributes point to
(the item held, not the slot number), and the cells and objects around it in its own
frame (ahead, right, up) -- never its absolute position. A transition is described the
same way: attributes stepped or set, the position moved and the cells changed, relative
to the agent. So what is learned in one place holds in every place that looks the same.
"""
from __future__ import annotations

import re

from ..model import Model

# Compass names of a facing attribute's values (spec section 2): the direction ahead as
# (dx, dz) in the world's x and z.
COMPASS = {"south": (0, 1), "west": (-1, 0), "north": (0, -1), "east": (1, 0)}

NOTHING = ((), (0, 0, 0), ())   # the effect of an action that changed nothing


class Perception:
    """Features of a state (a tuple: attributes, pointed-to attributes, cells around in
    three layers within `radius`, then which object stands in each plane cell) and
    effects of a transition ((attribute changes), (ahead, up, right) moved, (cells))."""

    def __init__(self, model: Model, radius: int = 1):
        self.model = model
        g = model.grid
        self.pos = [p[0] if p is not None else None for p in model.position]
        pos_idx = {i for i in self.pos if i is not None}
        self.attrs = [v.index for v in model.variables if v.index not in pos_idx]
        self.cyclic = {v.index: v.hi - v.lo + 1 for v in model.variables if v.type == "int"}
        self.pointers = self._pointers(model, pos_idx)
        self.index_features = {self.attrs.index(v) for v, _ in self.pointers}
        self.facing, self.ahead = self._frame(model)
        # The cells around the agent in its own frame: (ahead, up, right).
        self.offsets = [(da, dy, dr) for dy in (-1, 0, 1) for da in range(-radius, radius + 1)
                        for dr in range(-radius, radius + 1) if abs(da) + abs(dr) <= radius]
        self.objects = self._objects(model)
        self.plane = [(da, dr) for da, dy, dr in self.offsets if dy == 0]
        self.area = g.width * g.depth
        self.span = {v.index: v.hi - v.lo for v in model.variables}
        self.cache = {}          # state -> its feature tuple
        # The agent's own features (but its facing: it sees in its own frame, and index
        # attributes: what they point to counts), what it holds, and who stands next to it.
        agent = next((model.variables[i].label.split(".")[0] for i in self.pos if i is not None), None)
        own = [k for k, i in enumerate(self.attrs)
               if model.variables[i].label.split(".")[0] == agent and i != self.facing and k not in self.index_features]
        own += range(len(self.attrs), len(self.attrs) + len(self.pointers))
        first_object = len(self.attrs) + len(self.pointers) + len(self.offsets)
        own += range(first_object, first_object + (len(self.plane) if self.objects else 0))
        self.own_features = own
        self.own = frozenset(own)

    @staticmethod
    def _objects(model):
        """Other objects that stand in a cell (a domain's creatures, ...), each as a function of the
        state giving its (x, z): read from the state where it moves, else where the
        dungeon put it. Their cells are perceived like the grid's (`features`)."""
        by_label = {v.label: v for v in model.variables}
        out = []
        for name, x, z in (model.display or {}).get("objects", ()):
            vx, vz = by_label.get(f"{name}.x"), by_label.get(f"{name}.z")
            if vx is not None and vz is not None:
                out.append(lambda s, vx=vx, vz=vz: (s[vx.index] + vx.lo, s[vz.index] + vz.lo))
            elif x is not None and z is not None:
                out.append(lambda s, at=(x, z): at)
        return out

    @staticmethod
    def _frame(model):
        """The agent's own frame, when the domain declares which attribute is its facing and
        names that attribute's values by compass direction (spec section 2): the state index
        of the facing and, per stored value, the (dx, dz) ahead. Without it the frame is the
        world's (ahead = +x, right = +z), and what is learned facing one way is not reused
        facing another."""
        facing = (model.display or {}).get("facing")
        if not facing or facing.get("index") is None:
            return None, {}
        ahead = {value - facing["lo"]: COMPASS.get(str(name)) for value, name in facing["names"].items()}
        if not ahead or None in ahead.values():
            return None, {}
        return facing["index"], ahead

    def _axes(self, s):
        """(dx, dz) of the agent's ahead in state s."""
        return (1, 0) if self.facing is None else self.ahead.get(s[self.facing], (1, 0))

    @staticmethod
    def _to_world(axes, da, dr):
        fx, fz = axes
        return da * fx - dr * fz, da * fz + dr * fx

    @staticmethod
    def _to_frame(axes, dx, dz):
        fx, fz = axes
        return dx * fx + dz * fz, dz * fx - dx * fz

    @staticmethod
    def _pointers(model, skip):
        """Integer attributes that index a list of objects (a selected slot), each with the
        attributes of the object it points to: [(index variable, [variable per value])].
        The object pointed to is what matters (the item held), not the number."""
        lists = {}
        for v in model.variables:
            m = re.fullmatch(r"(.+)\[(\d+)\]\.(\w+)", v.label)
            if m:
                lists.setdefault((m.group(1), m.group(3)), {})[int(m.group(2))] = v.index
        out = []
        for v in model.variables:
            if v.type != "int" or v.index in skip:
                continue
            for members in lists.values():
                if sorted(members) == list(range(v.lo, v.hi + 1)):
                    out.append((v.index, [members[k] for k in range(v.lo, v.hi + 1)]))
        return out

    def features(self, s):
        """The state as the agent sees it (see the class docstring), computed once per state."""
        f = self.cache.get(s)
        if f is None:
            x, y, z = self.model.agent_position(s)
            cell, axes, world = self.model.grid.cell, self._axes(s), self._to_world
            around = []
            for da, dy, dr in self.offsets:
                dx, dz = world(axes, da, dr)
                around.append(cell(s, x + dx, y + dy, z + dz))
            if self.objects:
                standing = {where(s): k + 1 for k, where in reversed(list(enumerate(self.objects)))}
                for da, dr in self.plane:
                    dx, dz = world(axes, da, dr)
                    around.append(standing.get((x + dx, z + dz), 0))
            f = (tuple(s[i] for i in self.attrs) + tuple(s[members[s[i]]] for i, members in self.pointers)
                 + tuple(around))
            self.cache[s] = f
        return f

    def effect(self, s, n):
        """What `n` changed in `s`, relative to the agent: integer attributes moved on by a
        (cyclic) step, other attributes set, position moved and cells changed in its frame."""
        sets = tuple((i, "add", (n[i] - s[i]) % self.cyclic[i]) if i in self.cyclic else (i, "set", n[i])
                     for i in self.attrs if s[i] != n[i])
        delta = [(n[i] - s[i]) if i is not None else 0 for i in self.pos]
        axes = self._axes(s)
        da, dr = self._to_frame(axes, delta[0], delta[2])
        x, y, z = self.model.agent_position(s)
        cells = []
        vs, vn = self.model.view(s), self.model.view(n)
        for cx, cy, cz in sorted(set(vs.changed()) | set(vn.changed()), key=lambda c: (c[1], c[2], c[0])):
            v = vn.cell(cx, cy, cz)
            if vs.cell(cx, cy, cz) != v:
                ca, cr = self._to_frame(axes, cx - x, cz - z)
                cells.append((ca, cy - y, cr, v))
        return sets, (da, delta[1], dr), tuple(cells)

    def apply_effect(self, s, eff):
        sets, (da, dy, dr), cells = eff
        n = bytearray(s)
        for i, op, v in sets:
            n[i] = (s[i] + v) % self.cyclic[i] if op == "add" else v
        axes = self._axes(s)
        dx, dz = self._to_world(axes, da, dr)
        for i, d in zip(self.pos, (dx, dy, dz)):
            if d:
                if i is None:
                    return None  # a static axis cannot move: the caller falls back
                v = s[i] + d
                if not 0 <= v <= self.span[i]:
                    return None  # off the map: not a state; the caller falls back
                n[i] = v
        if cells:
            g = self.model.grid
            x, y, z = self.model.agent_position(s)
            n = bytearray(self.model.dense(bytes(n)))   # cells by position; compact again below
            for ca, cy, cr, v in cells:
                cdx, cdz = self._to_world(axes, ca, cr)
                cx, cy, cz = x + cdx, y + cy, z + cdz
                k = g.mutable_index(cx, cy, cz)
                if k is None:
                    return None
                n[g.base + k] = v
            return self.model.compact(bytes(n))
        return bytes(n)

    def locus(self, eff):
        """The features an effect acts on: the attributes it changes, and the cells in the
        columns it changes or moves into. Its condition is trusted only where these look as
        they did in its examples (a block placed on one kind of floor is not expected to fill another),
        and they are preferred when two constraints explain the data equally well."""
        sets, (da, _, dr), cells = eff
        columns = {(ca, cr) for ca, _, cr, _ in cells} | ({(da, dr)} if (da, dr) != (0, 0) else set())
        first = len(self.attrs) + len(self.pointers)
        return ({self.attrs.index(i) for i, _, _ in sets}
                | {first + k for k, (oa, _, orr) in enumerate(self.offsets) if (oa, orr) in columns})

    def cells_acted_on(self, eff):
        """The features of the very cells an effect changes or moves the agent into (for a
        move, its whole column): narrower than the locus, whose whole columns are there to
        guard an effect's own condition, not to tell which surroundings a failure shares."""
        _, (da, _, dr), cells = eff
        changed = {(ca, cy, cr) for ca, cy, cr, _ in cells}
        first = len(self.attrs) + len(self.pointers)
        return {first + k for k, (oa, oy, orr) in enumerate(self.offsets)
                if (oa, oy, orr) in changed or (oa, orr) == (da, dr) != (0, 0)}
