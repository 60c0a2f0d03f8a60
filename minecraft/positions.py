"""The world of a model whose agent is a position and a stock of blocks (no view, no
hotbar): the building domains and MinePlanner's tasks.

What such a model's state holds, and how the world shows it:
- the agent's x, y, z (the model's position attributes): the cell the player's feet are in;
- the cells: blocks (model.grid), as for every dungeon;
- what the agent carries: the variables `inventory.derive` finds counting each material,
  given to the player as items (stacks of 64, the hotbar first) and read back as totals.
Anything else in the state (an item lying on the ground, a flag) cannot be shown: such a
model is refused, naming the variable.
"""
from __future__ import annotations

import math

from ..errors import BccError
from ..model import Model
from .inventory import Inventory, derive

CARRY_LIMIT = 36 * 64        # a player's 36 inventory slots of 64 blocks


def check(model: Model) -> Inventory:
    """The inventory of a model the positions path can show, else BccError saying what not."""
    if model.grid is None:
        raise BccError(f"{model.name}: the Minecraft bridge shows block worlds; this model has no grid", model.path)
    inventory = derive(model)
    if inventory is None:
        raise BccError(f"{model.name}: the Minecraft bridge needs the model's actions to read its inventory", model.path)
    axes = {p[0] for p in model.position if p is not None}
    position = {v.label for v in model.variables if v.index in axes}
    extra = [v.label for v in model.variables if v.label not in position and v.label not in inventory.labels]
    if extra:
        raise BccError(f"{model.name}: the Minecraft bridge cannot play this dungeon (its state has {extra[0]}, "
                       "which a Minecraft world cannot show: only the agent's position, its view and "
                       "what it carries, and blocks)", model.path)
    for material, n in inventory.totals(model.initial).items():
        if n > CARRY_LIMIT:
            raise BccError(f"{model.name}: the agent starts with {n} {material}; a Minecraft player carries at most "
                           f"{CARRY_LIMIT} blocks (36 stacks of 64)", model.path)
    return inventory


def setup_args(world, state: bytes) -> dict:
    """The bridge's `setup` arguments for a state: the feet at the cell's centre, the
    carried blocks as item totals."""
    x, y, z = world.model.agent_position(state)
    ox, oy, oz = world.origin
    carried = [[world.mc_name(t), n] for t, n in world.inventory.totals(state).items() if n > 0]
    return {"position": [ox + x + 0.5, oy + y, oz + z + 0.5], "yaw": 0.0, "pitch": 0.0, "selected": 0,
            "hotbar": None, "inventory": carried}


def parse(world, obs: dict, hint: bytes | None = None) -> tuple:
    """An observation -> (the model's state, notes, on the floor) (see world.Parsed).
    `hint`, the predicted state, settles what the game does not show (how carried blocks
    split into stacks)."""
    m, g = world.model, world.model.grid
    notes = []
    ox, oy, oz = world.origin
    px, py, pz = obs["position"]
    feet = py - oy
    x, z = math.floor(px - ox), math.floor(pz - oz)
    y = round(feet) if abs(feet - round(feet)) < 0.05 else math.floor(feet)
    on_floor = abs(feet - round(feet)) <= 0.05
    if not (0 <= x < g.width and 0 <= z < g.depth and 0 <= y < g.height):
        raise BccError(f"the player is outside the dungeon, at world ({px:.1f}, {py:.1f}, {pz:.1f})")
    if not on_floor:
        notes.append(f"the player's feet are at y = {feet:.2f}, between two levels")
    state = bytearray(m.dense(m.initial))
    world.read_cells(obs, state, notes)
    for axis, p in zip((x, y, z), m.position):
        if p is not None:
            index, lo = p
            state[index] = axis - lo
    for axis, fixed, name in zip((x, y, z), m.position_static, "xyz"):
        if fixed is not None and axis != fixed:
            notes.append(f"the player's {name} is {axis}; in the model it is always {fixed}")
    totals = {}
    for item, n in (obs.get("inventory") or {}).items():
        material = world.model_value(item)
        if material is None or material not in world.inventory.holdings:
            notes.append(f"the player carries {n} {item}, which {m.name}'s agent does not carry")
            continue
        totals[material] = totals.get(material, 0) + n
    notes += world.inventory.assign(state, totals, None if hint is None else m.dense(hint))
    return m.compact(bytes(state)), notes, on_floor and bool(obs.get("onGround", True))


def describe(world, state: bytes) -> str:
    """One short line: the agent's cell and what it carries."""
    x, y, z = world.model.agent_position(state)
    carried = " ".join(f"{t}x{n}" for t, n in world.inventory.totals(state).items() if n > 0)
    return f"({x},{y},{z}) [{carried}]"
