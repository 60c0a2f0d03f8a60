"""Model <-> Minecraft world: where a dungeon's cells are, which blocks they become, and
the state parser that turns what the server reports back into the model's state.

Cells map 1:1 to blocks: model cell (x, y, z) is world block ORIGIN + (x, y, z), in a
void world, so nothing but the dungeon is around. Minecraft and the spec share the axes
and the facings (south = +z, west = -x, north = -z, east = +x) and Minecraft's yaw counts
the same quarter turns (0 south, 90 west, 180 north, 270 east), so rotationalDirection is
yaw / 90. A player looks "down" (verticalDirection 1) when the pitch is at least
DOWN_THRESHOLD degrees below the horizon: the blocks bcc's actions touch (the front cell
at foot level and the one below it) sit 48 and 65 degrees down from the eyes.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

from ..errors import BccError
from ..model import Model

ORIGIN = (0, 64, 0)          # world position of model cell (0, 0, 0)
DOWN_PITCH = 60.0            # the pitch the bot uses for verticalDirection = 1
DOWN_THRESHOLD = 30.0        # a person counts as looking down from here on

# bcc block type -> Minecraft (1.16.5) block or item name; names not listed are the same
# in both. burlap_stone was a custom block of BurlapCraft: stone is its closest relative.
# The others are the building domains' materials (MinePlanner's names), where Minecraft
# 1.16.5 names a kind of wood, a colour or a flower.
TO_MINECRAFT = {"gold": "gold_block", "burlap_stone": "stone", "planks": "oak_planks", "log": "oak_log",
                "leaves": "oak_leaves", "wool": "white_wool", "diamond": "diamond_block", "fence": "oak_fence",
                "flower": "dandelion", "wheat_seeds": "wheat"}
FROM_MINECRAFT = {v: k for k, v in TO_MINECRAFT.items()}
# the item that places a block, where Minecraft names it differently from the block
ITEM_OF = {"wheat": "wheat_seeds"}

_AGENT = ("agent.x", "agent.z", "agent.rotationalDirection", "agent.verticalDirection",
          "agent.selectedItem", "agent.alive")


def minecraft_name(name: str) -> str:
    return TO_MINECRAFT.get(name, name)


def model_name(name: str) -> str:
    return FROM_MINECRAFT.get(name, name)


def check_playable(model: Model) -> str:
    """How the world shows a model: "poses" for the minecraft domain's agent (a view
    direction and a hotbar: `check_supported`), "positions" for an agent that is a
    position and a stock of blocks (positions.py); BccError, saying what cannot be shown,
    for any other."""
    from . import positions
    labels = {v.label for v in model.variables}
    if any(label in labels for label in _AGENT if label not in ("agent.x", "agent.z")):
        check_supported(model)
        return "poses"
    positions.check(model)
    return "positions"


def check_supported(model: Model) -> None:
    """The pose parser observes an agent, its view, its hotbar and blocks; refuse models
    with more (`bcc minecraft serve` and `record` play these only)."""
    labels = {v.label for v in model.variables}
    missing = [label for label in _AGENT if label not in labels]
    extra = sorted(label for label in labels if label not in _AGENT and label != "agent.y"
                   and not label.startswith("inventoryBlock["))
    if missing or extra:
        what = (f"it has no {missing[0]}" if missing
                else f"its state has {extra[0]}, which a Minecraft world cannot show")
        raise BccError(f"{model.name}: the Minecraft bridge plays dungeons of the minecraft domain only ({what})",
                       model.path)


@dataclass(frozen=True)
class WorldMap:
    """Where a compiled dungeon sits in the world, and how its state looks there."""
    model: Model
    origin: tuple = ORIGIN

    @cached_property
    def kind(self) -> str:
        """"poses" (the minecraft domain's agent) or "positions" (see check_playable)."""
        return check_playable(self.model)

    @cached_property
    def inventory(self):
        from .inventory import derive
        return derive(self.model)

    def mc_name(self, value: str) -> str:
        """The Minecraft block of a model value."""
        return minecraft_name(value)

    def model_value(self, mc: str) -> str | None:
        """The model value a Minecraft block or item shows, or None: this model's values
        first (stone is stone in a model that has stone, burlap_stone where that is the one)."""
        return self._values.get(mc)

    @cached_property
    def _values(self) -> dict:
        out = {}
        for v in reversed(self.model.grid.value_names):
            name = minecraft_name(v)
            out[ITEM_OF.get(name, name)] = out[name] = v
        return out

    def setup_args(self, state: bytes) -> dict:
        """The bridge's `setup` arguments that put the player into `state`."""
        if self.kind == "positions":
            from .positions import setup_args
            return setup_args(self, state)
        return {**self.pose(state), "hotbar": self.hotbar(state)}

    def describe(self, state: bytes) -> str:
        if self.kind == "positions":
            from .positions import describe as short
            return short(self, state)
        return describe(self.model, state)

    @property
    def size(self) -> tuple:
        g = self.model.grid
        return (g.width, g.height, g.depth)

    def world(self, x: int, y: int, z: int) -> list:
        ox, oy, oz = self.origin
        return [ox + x, oy + y, oz + z]

    def blocks(self, state: bytes | None = None) -> list:
        """Every non-air cell of a state (default: the start) as [x, y, z, minecraft name]."""
        state = self.model.initial if state is None else state
        g = self.model.grid
        out = []
        for y in range(g.height):
            for z in range(g.depth):
                for x in range(g.width):
                    name = g.value_names[g.cell(state, x, y, z)]
                    if name != "air":
                        out.append([x, y, z, minecraft_name(name)])
        return out

    def mineable(self) -> list:
        """Minecraft names of the block types destroy_block can remove, found by asking the
        model: each type in the mutable layers is put in front of the agent (looking down,
        each starting hotbar slot selected in turn) and destroy_block is tried on it."""
        m, g = self.model, self.model.grid
        if self.kind == "positions":
            # the model decides what may be dug: the bot digs only where it predicts a block goes
            return sorted({minecraft_name(v) for i, v in enumerate(g.value_names) if i != g.default})
        if "destroy_block" not in m.action_names:
            return []
        destroy = m.action_index("destroy_block")
        index = {v.label: v for v in m.variables}
        x0, y, z0 = m.agent_position(m.initial)
        start = m.decode(m.initial)
        slots = [i for i in range(9) if start.get(f"inventoryBlock[{i}].count", 0) > 0]
        if y not in g.layers:
            return []
        area = g.width * g.depth
        types = {g.cell(m.initial, x, yy, z) for yy in g.layers for z in range(g.depth) for x in range(g.width)}
        found = set()
        for t in types - {g.default}:
            for d, (dx, dz) in enumerate(((0, 1), (-1, 0), (0, -1), (1, 0))):
                tx, tz = x0 + dx, z0 + dz
                if not (0 <= tx < g.width and 0 <= tz < g.depth):
                    continue
                for slot in slots:
                    probe = bytearray(m.dense(m.initial))  # the dense layout: every mutable cell has a place
                    probe[index["agent.rotationalDirection"].index] = d - index["agent.rotationalDirection"].lo
                    probe[index["agent.verticalDirection"].index] = 1 - index["agent.verticalDirection"].lo
                    probe[index["agent.selectedItem"].index] = slot - index["agent.selectedItem"].lo
                    probe[g.base + g.layers.index(y) * area + tz * g.width + tx] = t
                    if m.apply(destroy, m.compact(bytes(probe))) is not None:
                        found.add(g.value_names[t])
        return sorted(minecraft_name(n) for n in found)

    def agent_y(self, state: bytes | None = None) -> int:
        return self.model.agent_position(self.model.initial if state is None else state)[1]

    def pose(self, state: bytes) -> dict:
        """Where the agent of `state` stands in the world and where it looks."""
        v = self.model.decode(state)
        x, y, z = self.model.agent_position(state)
        ox, oy, oz = self.origin
        return {"position": [ox + x + 0.5, oy + y, oz + z + 0.5],
                "yaw": 90.0 * v["agent.rotationalDirection"],
                "pitch": DOWN_PITCH if v["agent.verticalDirection"] == 1 else 0.0,
                "selected": v["agent.selectedItem"]}

    def hotbar(self, state: bytes) -> list:
        """The 9 hotbar slots of `state` as [minecraft name, count] or None."""
        v = self.model.decode(state)
        out = []
        for i in range(9):
            kind, count = v.get(f"inventoryBlock[{i}].blockType", "air"), v.get(f"inventoryBlock[{i}].count", 0)
            out.append([minecraft_name(kind), count] if kind != "air" and count > 0 else None)
        return out

    def read_cells(self, obs: dict, state: bytearray, notes: list, back=None) -> None:
        """The observed blocks of the dungeon's box into a dense state (`back`: Minecraft
        name -> model value; this model's own values by default)."""
        m, g = self.model, self.model.grid
        back = back or (lambda mc: self.model_value(mc) or mc)
        palette, cells = obs["palette"], obs["cells"]
        area = g.width * g.depth
        for yy in range(g.height):
            for zz in range(g.depth):
                for xx in range(g.width):
                    mc = palette[cells[yy * area + zz * g.width + xx]]
                    name = back(mc)
                    if name not in g.value_names:
                        notes.append(f"block ({xx}, {yy}, {zz}) is {mc}, which {m.name} does not know: read as air")
                        name = "air"
                    value = g.value_names.index(name)
                    if yy in g.layers:
                        state[g.base + g.layers.index(yy) * area + zz * g.width + xx] = value
                    elif g.cell(m.initial, xx, yy, zz) != value:
                        notes.append(f"block ({xx}, {yy}, {zz}) is {mc} in the world but cannot change in the model")

    def parse(self, obs: dict, hint: bytes | None = None) -> "Parsed":
        """The state parser: an observation from the bridge (player pose, hotbar or
        inventory, and the blocks of the dungeon's box) -> the model's state, plus what did
        not fit. `hint` (the predicted state) settles what the world does not show."""
        if self.kind == "positions":
            from .positions import parse
            return Parsed(*parse(self, obs, hint))
        m = self.model
        g = m.grid
        notes = []
        ox, oy, oz = self.origin
        px, py, pz = obs["position"]
        x, z = math.floor(px - ox), math.floor(pz - oz)
        y = self.agent_y()
        feet = py - oy
        if not (0 <= x < g.width and 0 <= z < g.depth):
            raise BccError(f"the player is outside the dungeon, at world ({px:.1f}, {py:.1f}, {pz:.1f})")
        state = bytearray(m.dense(m.initial))  # the dense layout (variables first, then every mutable cell)
        self.read_cells(obs, state, notes, model_name)
        yaw = obs["yaw"] % 360.0
        facing = int(round(yaw / 90.0)) % 4
        off = abs((yaw - 90.0 * round(yaw / 90.0)))
        if off > 30:
            notes.append(f"yaw {yaw:.0f} is {off:.0f} degrees from a facing: read as {facing * 90}")
        down = 1 if obs["pitch"] >= DOWN_THRESHOLD else 0
        under = g.value_names[g.cell(m.compact(bytes(state)), x, y - 1, z)]
        # The server applies no lava damage: the parser does. Standing on (or sunk into)
        # lava is death in bcc's rules, as is having dropped below the floor.
        alive = under != "lava" and feet > y - 0.5
        if abs(feet - y) > 0.05:
            notes.append(f"the player's feet are at y = {feet:.2f}, not on the floor (y = {y})")
        values = {"agent.x": x, "agent.z": z, "agent.rotationalDirection": facing,
                  "agent.verticalDirection": down, "agent.selectedItem": obs["selected"], "agent.alive": alive}
        hotbar = obs["hotbar"]
        for i in range(9):
            entry = hotbar[i] if i < len(hotbar) else None
            kind, count = ("air", 0) if entry is None else (model_name(entry[0]), entry[1])
            values[f"inventoryBlock[{i}].blockType"] = kind
            values[f"inventoryBlock[{i}].count"] = count
        for v in m.variables:
            if v.label == "agent.y":
                values["agent.y"] = y
            value = values.get(v.label)
            if value is None:
                continue
            if v.names:
                if value not in v.names:
                    notes.append(f"{v.label} = {value} is not a {v.type} of {m.name}: read as {v.names[0]}")
                    value = v.names[0]
                state[v.index] = v.names.index(value) - v.lo
            else:
                raw = int(value)
                if not v.lo <= raw <= v.hi:
                    notes.append(f"{v.label} = {raw} is outside [{v.lo}, {v.hi}]: clipped")
                    raw = min(max(raw, v.lo), v.hi)
                state[v.index] = raw - v.lo
        return Parsed(m.compact(bytes(state)), notes, on_floor=abs(feet - y) <= 0.05 and bool(obs.get("onGround", True)))


@dataclass(frozen=True)
class Parsed:
    state: bytes
    notes: list          # what did not fit the model (empty when the world is a model state)
    on_floor: bool       # False while the player jumps or falls: the pose is not a model pose yet


def describe(model: Model, state: bytes) -> str:
    """One short line for a state: position, facing, view, slot and non-empty hotbar."""
    v = model.decode(state)
    x, y, z = model.agent_position(state)
    facing = ("south", "west", "north", "east")[v["agent.rotationalDirection"]]
    view = "down" if v["agent.verticalDirection"] else "ahead"
    items = [f"{i}:{v[f'inventoryBlock[{i}].blockType']}x{v[f'inventoryBlock[{i}].count']}"
             for i in range(9) if v.get(f"inventoryBlock[{i}].count", 0) > 0]
    dead = "" if v["agent.alive"] else " DEAD"
    return f"({x},{z}) {facing:<5} {view:<5} slot {v['agent.selectedItem']} [{' '.join(items)}]{dead}"


def difference(model: Model, predicted: bytes, observed: bytes) -> list:
    """Human-readable differences between two states (variables, then cells)."""
    from ..demonstration import changes
    return [f"{what}: predicted {a}, observed {b}" for what, a, b in changes(model, predicted, observed)]
