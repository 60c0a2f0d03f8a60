"""A literal reading of MinePlanner's propositional PDDL moves, independent of bcc.

Written from the action schemas of MinePlanner's domain files (move-D, jumpup-D,
jumpdown-D, break-T-D, place-T-D and the *_and_pickup-T-D variants), not from
domains/builder.yaml: a world is a set of solid cells, a list of items, a count per
material and the agent's cell; positions exist from 0 to the world's size - 1 on each
axis (PDDL's position objects), counts from 0 to 64. Where PDDL leaves a choice (which
of several items in one cell a move picks up), the first in list order with room is taken.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

MAX = 64
DIRS = {"north": (0, -1), "south": (0, 1), "east": (1, 0), "west": (-1, 0)}
UNBREAKABLE = {"bedrock"}


@dataclass
class World:
    width: int
    depth: int
    height: int
    solid: dict                 # (x, y, z) -> material
    items: list                 # [material, (x, y, z), present]
    counts: dict                # material -> count
    at: tuple

    def copy(self) -> "World":
        return dataclasses.replace(self, solid=dict(self.solid), items=[list(i) for i in self.items],
                                   counts=dict(self.counts))

    def exists(self, x=0, y=0, z=0) -> bool:
        return 0 <= x < self.width and 0 <= y < self.height and 0 <= z < self.depth

    def item_at(self, cell):
        return [i for i in self.items if i[2] and i[1] == cell]


def _enter(w: World, cell) -> World | None:
    """move/jumpup/jumpdown's last conjunct: no item in the feet cell (the plain action), or
    the *_and_pickup variant for an item whose count can still rise."""
    items = w.item_at(cell)
    n = w.copy()
    n.at = cell
    if not items:
        return n
    for item in items:
        if n.counts.get(item[0], MAX) < MAX:
            j = w.items.index(item)
            n.items[j][2] = False
            n.counts[item[0]] += 1
            return n
    return None


def apply(w: World, action: str, stock: str | None = None) -> World | None:
    kind, direction = action.split("_")
    dx, dz = DIRS[direction]
    x, y, z = w.at
    fx, fz = x + dx, z + dz
    if not w.exists(fx, 0, fz):
        return None                      # no position object for the cell in front
    S = lambda *c: c in w.solid
    if kind == "move":                   # y_up, y_2_down exist; block below in front; two free cells
        if not (w.exists(y=y + 1) and w.exists(y=y - 1)):
            return None
        if S(fx, y - 1, fz) and not S(fx, y, fz) and not S(fx, y + 1, fz):
            return _enter(w, (fx, y, fz))
        return None
    if kind == "jump":                   # y_up, y_up_up exist; free above the head; block in front
        if not w.exists(y=y + 2):
            return None
        if not S(x, y + 2, z) and not S(fx, y + 1, fz) and not S(fx, y + 2, fz) and S(fx, y, fz):
            if S(x, y + 1, z) and w.item_at((fx, y + 1, fz)):
                return None              # jumpup_and_pickup also wants the head's cell free
            return _enter(w, (fx, y + 1, fz))
        return None
    if kind == "drop":                   # y_up, y_2_down, y_3_down exist; three free; block below them
        if not (w.exists(y=y + 1) and w.exists(y=y - 2)):
            return None
        if not S(fx, y + 1, fz) and not S(fx, y, fz) and not S(fx, y - 1, fz) and S(fx, y - 2, fz):
            return _enter(w, (fx, y - 1, fz))
        return None
    if kind == "break":                  # the block at feet level in front; no item on it; count < 64
        t = w.solid.get((fx, y, fz))
        if t is None or t in UNBREAKABLE or not w.exists(y=y + 1) or w.item_at((fx, y + 1, fz)):
            return None
        if t not in w.counts or w.counts[t] >= MAX:
            return None
        n = w.copy()
        del n.solid[(fx, y, fz)]
        n.counts[t] += 1
        return n
    if kind == "place":                  # count >= 1; block below in front; cell in front empty
        if w.counts.get(stock, 0) < 1 or not w.exists(y=y - 1):
            return None
        if S(fx, y - 1, fz) and not S(fx, y, fz) and not w.item_at((fx, y, fz)):
            n = w.copy()
            n.solid[(fx, y, fz)] = stock
            n.counts[stock] -= 1
            return n
        return None
    raise ValueError(action)
