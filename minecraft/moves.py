"""The generic controller: any action of a model whose agent is a position and a stock of
blocks, done by the bot from the model's predicted before and after states alone.

Nothing here knows an action's name. What changed says what to do, in this order:
1. every cell that becomes empty is dug (at once: such models have no tools);
2. every cell that becomes a block is placed, clicking a face of a solid neighbour
   (below first, then the sides, then above) with the item of that block in the hand;
   a block placed where the feet were while the agent rises by one is placed after the
   jump (a pillar: jump, place under the feet, land on it);
3. the agent moves: one cell north, south, east or west at the same level, up one (a
   jump) or down one (walking off the edge) is walked with Minecraft's physics when the
   agent stands on a block before and after; straight down onto a block (the one under
   the feet dug) is a fall. Any other move, or one that leaves the agent standing on
   nothing, cannot be walked in the game: the bot is held in the model's cell without
   physics (see differences.py: the model has no gravity).
"""
from __future__ import annotations

from ..errors import BccError
from .actions import changed_cells
from .world import ITEM_OF, WorldMap

# Minecraft blocks a player cannot stand on or click to place against
NOT_SOLID = frozenset({"air", "water", "lava", "grass", "dandelion", "wheat", "torch", "ladder"})

# the yaw (degrees, Minecraft's) that walks one cell along (dx, dz)
YAW = {(0, 1): 0.0, (-1, 0): 90.0, (0, -1): 180.0, (1, 0): 270.0}


def solid(world: WorldMap, state: bytes, x: int, y: int, z: int, override: dict | None = None) -> bool:
    """Is there a block one can stand on or click in cell (x, y, z) (outside the box: no)?"""
    g = world.model.grid
    if override and (x, y, z) in override:
        value = override[(x, y, z)]
    elif 0 <= x < g.width and 0 <= y < g.height and 0 <= z < g.depth:
        value = g.cell(state, x, y, z)
    else:
        return False
    return value != g.default and world.mc_name(g.value_names[value]) not in NOT_SOLID


def supported(world: WorldMap, state: bytes) -> bool:
    """Does the agent of `state` stand on a block?"""
    x, y, z = world.model.agent_position(state)
    return solid(world, state, x, y - 1, z)


def centre(world: WorldMap, cell) -> list:
    ox, oy, oz = world.origin
    return [ox + cell[0] + 0.5, oy + cell[1], oz + cell[2] + 0.5]


def _place(world: WorldMap, before: bytes, now: dict, cell, value: int, **extra) -> dict:
    """The request that places block `value` into `cell`, against a solid neighbour."""
    g = world.model.grid
    x, y, z = cell
    for dx, dy, dz in ((0, -1, 0), (1, 0, 0), (-1, 0, 0), (0, 0, 1), (0, 0, -1), (0, 1, 0)):
        n = (x + dx, y + dy, z + dz)
        if solid(world, before, *n, override=now):
            block = world.mc_name(g.value_names[value])
            return {"kind": "place", "reference": world.world(*n), "face": [-dx, -dy, -dz],
                    "at": world.world(x, y, z), "item": ITEM_OF.get(block, block), "block": block,
                    "select": True, **extra}
    raise BccError(f"the model places {g.value_names[value]} at {cell}, where no block touches it: "
                   "Minecraft places a block only against another one")


def controls(world: WorldMap, before: bytes, after: bytes) -> list:
    """The bridge `act` requests that take the world from `before` to `after`, in order
    (none when nothing the world shows changes: repacking what is carried)."""
    m, g = world.model, world.model.grid
    p0, p1 = m.agent_position(before), m.agent_position(after)
    cells = changed_cells(m, before, after)
    now: dict = {}          # cells as the world will be once the earlier requests are done
    out = []
    for x, y, z, old, new in cells:
        if old != g.default:
            out.append({"kind": "dig", "block": world.world(x, y, z), "instant": True})
            now[(x, y, z)] = g.default
    rises = (p1[0], p1[1], p1[2]) == (p0[0], p0[1] + 1, p0[2])
    late = []
    for x, y, z, old, new in cells:
        if new == g.default:
            continue
        if rises and (x, y, z) == tuple(p0):
            late.append(((x, y, z), new))
            continue
        out.append(_place(world, before, now, (x, y, z), new))
        now[(x, y, z)] = new
    if p1 != p0:
        stands_before = solid(world, before, p0[0], p0[1] - 1, p0[2], override=now)
        stands_after = supported(world, after)
        dx, dy, dz = (b - a for a, b in zip(p0, p1))
        if late and stands_before and stands_after and len(late) == 1:
            cell, value = late.pop()
            req = _place(world, before, now, cell, value, target=centre(world, p1))
            out.append({**req, "kind": "pillar"})
        elif stands_before and stands_after and abs(dx) + abs(dz) == 1 and abs(dy) <= 1:
            out.append({"kind": "walk", "target": centre(world, p1), "yaw": YAW[(dx, dz)], "pitch": 0.0,
                        "jump": dy == 1})
        elif stands_after and dx == dz == 0 and dy < 0:
            out.append({"kind": "fall", "target": centre(world, p1)})
        else:
            out.append({"kind": "hover", "target": centre(world, p1)})
        for cell, value in late:
            out.append(_place(world, before, now, cell, value))
            now[cell] = value
    if out:
        out[-1]["hover"] = not supported(world, after)
    return out
