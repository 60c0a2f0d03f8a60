"""A slow, literal reading of the spec (sections 2-4), independent of bcc's compiler.

Nothing here imports `bcc.compiler` or reads `domains/minecraft.yaml`: block types,
directions and the eight actions are written down again from the spec's table, so a
differential test can hold the compiled model against this reading. The reference
dungeons of section 4 are copied here from the spec's maps, not from `dungeons/*.yaml`.

A `World` is the whole OO-MDP state in plain Python: every cell's block name, the agent's
pose and the nine hotbar slots as `(blockType, count)`.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

# Section 2: block types. The spec names bedrock, gold, burlap_stone and the wool colours
# of the four rooms as solid; lava and air are not solid.
SOLID = frozenset({"bedrock", "gold", "burlap_stone",
                   "red_wool", "orange_wool", "green_wool", "blue_wool"})
MINEABLE = frozenset({"burlap_stone"})
PLACEABLE = frozenset({"burlap_stone"})
PICKAXE = "diamond_pickaxe"
AIR = "air"
LAVA = "lava"
MAX_STACK = 64
SLOTS = 9

# Section 2: rotationalDirection 0 south = +z, 1 west = -x, 2 north = -z, 3 east = +x.
FACING = {"south": 0, "west": 1, "north": 2, "east": 3}
LOOKING = {"ahead": 0, "down": 1}
STEP = {0: (0, 1), 1: (-1, 0), 2: (0, -1), 3: (1, 0)}   # direction -> (dx, dz)

# Section 3: canonical action names.
ACTIONS = ("move_forward", "rotate_left", "rotate_right", "look_down", "look_ahead",
           "change_item", "destroy_block", "place_block")


@dataclass
class World:
    width: int
    height: int
    depth: int
    blocks: tuple           # block names of every cell inside the dungeon, [y][z][x] order
    x: int
    y: int
    z: int
    rot: int                # rotationalDirection
    vert: int               # verticalDirection
    sel: int                # selectedItem
    alive: bool = True
    inventory: list = field(default_factory=lambda: [(AIR, 0)] * SLOTS)

    def index(self, x: int, y: int, z: int) -> int:
        return (y * self.depth + z) * self.width + x

    def block(self, x: int, y: int, z: int) -> str:
        """The block in a cell; outside the dungeon there is nothing (air)."""
        if 0 <= x < self.width and 0 <= y < self.height and 0 <= z < self.depth:
            return self.blocks[self.index(x, y, z)]
        return AIR

    def with_block(self, x: int, y: int, z: int, name: str) -> tuple:
        cells = list(self.blocks)
        cells[self.index(x, y, z)] = name
        return tuple(cells)

    def in_bounds(self, x: int, z: int) -> bool:
        return 0 <= x < self.width and 0 <= z < self.depth

    def front(self) -> tuple[int, int]:
        dx, dz = STEP[self.rot]
        return self.x + dx, self.z + dz

    def copy(self) -> "World":
        return dataclasses.replace(self, inventory=list(self.inventory))

    def mineable_total(self) -> int:
        """Mineable blocks in the world plus those carried in the inventory."""
        return (sum(1 for b in self.blocks if b in MINEABLE)
                + sum(c for t, c in self.inventory if t in MINEABLE))


# ---------------------------------------------------------------- section 3, row by row

def _solid(name: str) -> bool:
    return name in SOLID


def move_forward(w: World) -> World | None:
    tx, tz = w.front()
    if not w.in_bounds(tx, tz):
        return None
    if _solid(w.block(tx, w.y, tz)) or _solid(w.block(tx, w.y + 1, tz)):
        return None
    below = w.block(tx, w.y - 1, tz)
    if below == AIR:
        return None
    n = w.copy()
    n.x, n.z = tx, tz
    if below == LAVA:
        n.alive = False
    return n


def rotate_left(w: World) -> World:
    n = w.copy()
    n.rot = (w.rot + 3) % 4
    return n


def rotate_right(w: World) -> World:
    n = w.copy()
    n.rot = (w.rot + 1) % 4
    return n


def look_down(w: World) -> World:
    n = w.copy()
    n.vert = 1
    return n


def look_ahead(w: World) -> World:
    n = w.copy()
    n.vert = 0
    return n


def change_item(w: World) -> World:
    n = w.copy()
    n.sel = (w.sel + 1) % SLOTS
    return n


def destroy_block(w: World) -> World | None:
    if w.vert != 1:
        return None
    kind, count = w.inventory[w.sel]
    if kind != PICKAXE or count <= 0:
        return None
    tx, tz = w.front()
    target = w.block(tx, w.y, tz)
    if not w.in_bounds(tx, tz) or target not in MINEABLE:
        return None
    n = w.copy()
    n.blocks = w.with_block(tx, w.y, tz, AIR)
    inv = list(n.inventory)
    stack = next((i for i, (t, c) in enumerate(inv) if t == target and 0 < c < MAX_STACK), None)
    if stack is not None:
        inv[stack] = (target, inv[stack][1] + 1)
    else:
        # A slot holding nothing (count 0) is empty, whatever its type says.
        empty = next((i for i, (t, c) in enumerate(inv) if c == 0), None)
        if empty is not None:
            inv[empty] = (target, 1)
        # else: no slot takes it; the block is gone all the same
    n.inventory = inv
    return n


def place_block(w: World) -> World | None:
    if w.vert != 1:
        return None
    kind, count = w.inventory[w.sel]
    if kind not in PLACEABLE or count <= 0:
        return None
    tx, tz = w.front()
    if not w.in_bounds(tx, tz):
        return None
    floor = w.block(tx, w.y - 1, tz)
    foot = w.block(tx, w.y, tz)
    if floor in (AIR, LAVA):
        target = (tx, w.y - 1, tz)          # case 1: fill the floor (bridging lava)
    elif _solid(floor) and foot == AIR:
        target = (tx, w.y, tz)              # case 2: a new obstacle standing on the floor
    else:
        return None
    if not (0 <= target[1] < w.height):
        return None
    n = w.copy()
    n.blocks = w.with_block(*target, kind)
    inv = list(n.inventory)
    inv[w.sel] = (kind, count - 1) if count > 1 else (AIR, 0)
    n.inventory = inv
    return n


APPLY = {
    "move_forward": move_forward, "rotate_left": rotate_left, "rotate_right": rotate_right,
    "look_down": look_down, "look_ahead": look_ahead, "change_item": change_item,
    "destroy_block": destroy_block, "place_block": place_block,
}


def apply(w: World, action: str) -> World | None:
    """The state after `action`, or None when its precondition fails."""
    return APPLY[action](w)


def successors(w: World) -> dict[str, World]:
    out = {}
    for name in ACTIONS:
        n = apply(w, name)
        if n is not None:
            out[name] = n
    return out


def is_failure(w: World) -> bool:
    return not w.alive


def agent_on(w: World, block: str) -> bool:
    """agentOnBlock(agent, block): the block right under the agent's feet."""
    return w.block(w.x, w.y - 1, w.z) == block


# ---------------------------------------------------------------- section 4, copied

# Legend of the reference maps (section 4): columns from y = 0 up.
SPEC_LEGEND = {
    "#": ["bedrock", "bedrock", "bedrock"],
    ".": ["bedrock"],
    "L": ["lava"],
    "G": ["gold"],
    "M": ["bedrock", "burlap_stone"],
    "S": ["bedrock"],
    "r": ["red_wool"] * 3,
    "o": ["orange_wool"] * 3,
    "g": ["green_wool"] * 3,
    "b": ["blue_wool"] * 3,
}

_EASY = """\
##############
#...#...#....#
#.#.#.#.#.S..#
#.....#.#..#.#
##.####...#..#
##....#.#.####
###.#.###...##
#...#.#.###.##
###.#.......##
#...#..#.###.#
#.##..#...#..#
#.#..#..#....#
#G#.###...#..#
##############"""


def _tough() -> str:
    rows = [list(r) for r in _EASY.splitlines()]
    for x, z in [(1, 3), (1, 10), (3, 2), (3, 6), (8, 9), (9, 4)]:
        rows[z][x] = "M"
    return "\n".join("".join(r) for r in rows)


SPEC_MAPS = {
    "grid": (3, """\
#####
#G..#
##..#
#S..#
#####"""),
    "bridge": (4, """\
#######
#..L..#
#..L..#
#S.L..#
#..L..#
#M.L.G#
#######"""),
    "easy_maze": (4, _EASY),
    "tough_maze": (4, _tough()),
    "four_rooms": (3, """\
rrrrrrooooo
r....ro...o
r....ro...o
rS........o
r....roo.oo
rrr.rrgg.gg
bbb.bg....g
b...bg....g
b.........g
b...bg....g
b...bg....g
bbbbbgggggg"""),
}


def world_from_map(text: str, legend: dict, height: int, start: str = "S", facing: str = "north",
                   looking: str = "ahead", selected: int = 0, inventory=None) -> World:
    """A world from a top-view map: row k is z = k, column i is x = i. The agent stands
    on top of its start column (y = the number of blocks in it)."""
    rows = text.splitlines()
    depth, width = len(rows), len(rows[0])
    blocks = [AIR] * (width * height * depth)
    start_at = None
    for z, row in enumerate(rows):
        for x, ch in enumerate(row):
            column = legend[ch]
            for y, name in enumerate(column):
                blocks[(y * depth + z) * width + x] = name
            if ch == start:
                start_at = (x, len(column), z)
    inv = [(AIR, 0)] * SLOTS
    for slot, (item, count) in enumerate([(PICKAXE, 1)] if inventory is None else inventory):
        inv[slot] = (item, count)
    x, y, z = start_at
    return World(width, height, depth, tuple(blocks), x, y, z, FACING[facing], LOOKING[looking],
                 selected, True, inv)


def spec_world(name: str) -> World:
    """The initial state of a section-4 dungeon: facing north, looking ahead, slot 0
    selected holding one diamond_pickaxe, every other slot empty."""
    height, text = SPEC_MAPS[name]
    return world_from_map(text, SPEC_LEGEND, height)


# ---------------------------------------------------------------- reading bcc's states

def model_blocks(model, state: bytes) -> tuple:
    """Every cell of a compiled state, read one by one with `Grid.cell`, [y][z][x] order."""
    g = model.grid
    names = g.value_names
    return tuple(names[g.cell(state, x, y, z)]
                 for y in range(g.height) for z in range(g.depth) for x in range(g.width))


def world_from_model(model, state: bytes, cache: dict | None = None) -> World:
    """Read a compiled model's state through its public API (decode, grid, position).

    Reading every cell is the slow part; with a `cache`, cells are read once per distinct
    mutable grid (`state[grid.base:]`), since most actions leave the grid alone."""
    d = model.decode(state)
    g = model.grid
    if cache is None:
        blocks = model_blocks(model, state)
    else:
        key = state[g.base:]
        blocks = cache.get(key)
        if blocks is None:
            blocks = cache[key] = model_blocks(model, state)
    x, y, z = model.agent_position(state)
    inv = [(d[f"inventoryBlock[{i}].blockType"], d[f"inventoryBlock[{i}].count"]) for i in range(SLOTS)]
    return World(g.width, g.height, g.depth, blocks, x, y, z,
                 d["agent.rotationalDirection"], d["agent.verticalDirection"],
                 d["agent.selectedItem"], bool(d.get("agent.alive", True)), inv)


def diff(a: World, b: World) -> list[str]:
    """Human-readable differences between two worlds (empty when equal)."""
    out = []
    for attr in ("width", "height", "depth", "x", "y", "z", "rot", "vert", "sel", "alive"):
        if getattr(a, attr) != getattr(b, attr):
            out.append(f"{attr}: {getattr(a, attr)!r} != {getattr(b, attr)!r}")
    for i, (s, t) in enumerate(zip(a.inventory, b.inventory)):
        if s != t:
            out.append(f"inventory[{i}]: {s!r} != {t!r}")
    if a.blocks != b.blocks and (a.width, a.height, a.depth) == (b.width, b.height, b.depth):
        for y in range(a.height):
            for z in range(a.depth):
                for x in range(a.width):
                    if a.block(x, y, z) != b.block(x, y, z):
                        out.append(f"block({x}, {y}, {z}): {a.block(x, y, z)!r} != {b.block(x, y, z)!r}")
    return out


# ---------------------------------------------------------------- section 5, writing

def dungeon_yaml(rows, legend: dict, height: int, *, start: str = "S", facing: str = "north",
                 looking: str = "ahead", selected: int = 0, inventory=(("diamond_pickaxe", 1),),
                 goal: str = "agentOnBlock(agent, gold)", name: str = "test") -> str:
    """A dungeon file in the spec's section-5 format. `rows` is the map (a string or a
    list of rows); `inventory` lists (item, count) from slot 0, None for an empty slot."""
    if isinstance(rows, str):
        rows = rows.strip("\n").splitlines()
    lines = [f"dungeon: {name}", "domain: minecraft", f"height: {height}", "legend:"]
    for ch, column in legend.items():
        lines.append(f'  "{ch}": [{", ".join(column)}]')
    lines.append("map: |")
    lines += [f"  {row}" for row in rows]
    lines += ["agent:", f"  start: {start}", f"  facing: {facing}", f"  looking: {looking}",
              f"  selected: {selected}", "inventory:"]
    for entry in inventory:
        item, count = entry if entry is not None else (AIR, 0)
        lines.append(f"  - {{item: {item}, count: {count}}}")
    if not inventory:
        lines[-1] = "inventory: []"
    lines.append(f"goal: {goal}")
    return "\n".join(lines) + "\n"
