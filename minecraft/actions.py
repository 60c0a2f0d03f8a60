"""The action controller: one canonical bcc action -> what the bot does in the world.

The model decides (is the action applicable, what changes); this module only turns the
model's before/after states into geometry for the bridge: the yaw and pitch to hold, the
hotbar slot, the cell to walk to, the block to dig, the face to click to place a block.
"""
from __future__ import annotations

from ..errors import BccError
from ..model import Model
from .world import WorldMap, minecraft_name


def changed_cells(model: Model, before: bytes, after: bytes) -> list:
    """[(x, y, z, old value, new value)] for the grid cells an action changed."""
    g = model.grid
    out = []
    for y in g.layers:
        for z in range(g.depth):
            for x in range(g.width):
                a, b = g.cell(before, x, y, z), g.cell(after, x, y, z)
                if a != b:
                    out.append((x, y, z, a, b))
    return out


def geometry(world: WorldMap, action: str, before: bytes, after: bytes) -> dict:
    """The bridge request (`act` arguments) that performs `action` from `before` so that the
    world shows `after` (the model's prediction)."""
    m = world.model
    pose = world.pose(after)
    view = {"yaw": pose["yaw"], "pitch": pose["pitch"]}
    if action in ("rotate_left", "rotate_right", "look_down", "look_ahead"):
        return {"kind": "look", **view}
    if action == "change_item":
        return {"kind": "select", "slot": pose["selected"], **view}
    if action == "move_forward":
        return {"kind": "walk", "target": pose["position"], **view}
    cells = changed_cells(m, before, after)
    if action == "destroy_block":
        if len(cells) != 1:
            raise BccError(f"destroy_block changed {len(cells)} cells in the model; the bot digs exactly one")
        x, y, z, _, _ = cells[0]
        return {"kind": "dig", "block": world.world(x, y, z), **view}
    if action == "place_block":
        if len(cells) != 1:
            raise BccError(f"place_block changed {len(cells)} cells in the model; the bot places exactly one")
        x, y, z, _, new = cells[0]
        ax, ay, az = m.agent_position(before)
        item = minecraft_name(m.grid.value_names[new])
        if y == ay - 1:
            # filling the floor in front (air or lava): click the side of the block the
            # agent stands on, facing the hole
            reference, face = world.world(ax, ay - 1, az), [x - ax, 0, z - az]
        else:
            # on top of the solid floor in front, at foot level
            reference, face = world.world(x, y - 1, z), [0, 1, 0]
        return {"kind": "place", "reference": reference, "face": face, "at": world.world(x, y, z),
                "item": item, **view}
    raise BccError(f"the Minecraft bot has no controller for action {action!r}")
