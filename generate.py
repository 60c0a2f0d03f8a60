"""Generate maze dungeons (spec section 5 format) that are solvable by construction.

`generate_maze(width, depth, stones, lava, loops, seed)` carves a perfect maze with a
randomized depth-first search (recursive backtracker) on the odd-coordinate cells, then:

- knocks out `loops` (a fraction) of the remaining interior walls between two cells;
- starts the agent `S` at cell (1, 1) and puts the gold `G` on the corridor cell farthest
  from it (BFS distance in the final maze);
- turns `lava` wall rows into lava rivers: every opening of such a row (an even z) becomes
  lava (`L`), the rest of the row stays wall. A row only becomes a river if the maze's
  tree path from S to G crosses it exactly once, so G lies below the last river; every
  river gets one bridging stone `M` in the region between it and the previous river that
  this path walks through (reachable without touching lava). Following the path and
  fetching each bridging stone on the way always reaches the gold: one stone per river,
  placed into the lava where the path crosses it. With rivers, G is the farthest cell
  whose path allows them. When a few mazes in a row offer no such rows (large mazes with
  many rivers), the river rows are drawn first and the depth-first search may carve
  through each of them only once (still a perfect maze); G is then the farthest cell
  past the last river;
- puts `stones` burlap stones (`M`, a stone at foot level) on other corridor cells: they
  block the way until mined with the pickaxe, and can be placed again.

The same arguments always give the same text (`random.Random(seed)` drives every choice).
"""
from __future__ import annotations

import json
import random
from collections import deque

import yaml

from .compiler.names import name_problem
from .errors import BccError

MAX_SIZE = 255          # a coordinate is one byte of the packed state
FREE_ATTEMPTS = 10      # unconstrained mazes tried before the river rows are drawn first
MAX_ATTEMPTS = 20       # in all; a maze with rows drawn first always has room for the rivers

LEGEND = '''legend:
  "#": [bedrock, bedrock, bedrock]
  ".": [bedrock]
  "G": [gold]
  "S": [bedrock]
  "M": [bedrock, burlap_stone]
  "L": [lava]'''

Cell = tuple[int, int]  # (x, z)


def max_rivers(depth: int) -> int:
    """How many non-adjacent river rows (even z in 2..depth-3, two apart at least) fit."""
    rows = max(0, (depth - 3) // 2)
    return (rows + 1) // 2


def max_stones(width: int, depth: int, lava: int = 0, loops: float = 0.0) -> int:
    """Stones that always fit: corridor cells minus S, G, the bridging stones and the most
    lava the rivers can take (one cell per maze column each); independent of the seed."""
    a, b = (width - 1) // 2, (depth - 1) // 2
    cells = a * b
    corridor = 2 * cells - 1 + _knocked(width, depth, loops)
    return corridor - 2 - lava * (a + 1)


def _knocked(width: int, depth: int, loops: float) -> int:
    a, b = (width - 1) // 2, (depth - 1) // 2
    remaining = a * (b - 1) + b * (a - 1) - (a * b - 1)
    return int(loops * remaining + 0.5)


def _validate(width, depth, stones, lava, loops, seed, name) -> None:
    def whole(value, what):
        if not isinstance(value, int) or isinstance(value, bool):
            raise BccError(f"{what} must be a whole number, got {value!r}")
    for value, what in ((width, "width"), (depth, "depth")):
        whole(value, what)
        if value < 5 or value % 2 == 0 or value > MAX_SIZE:
            raise BccError(f"{what} must be odd and between 5 and {MAX_SIZE}, got {value}")
    for value, what in ((stones, "stones"), (lava, "lava"), (seed, "seed")):
        whole(value, what)
    if stones < 0 or lava < 0:
        raise BccError(f"stones and lava must not be negative, got stones={stones}, lava={lava}")
    if isinstance(loops, bool) or not isinstance(loops, (int, float)) or not 0.0 <= loops <= 1.0:
        raise BccError(f"loops must be a fraction between 0 and 1, got {loops!r}")
    if name is not None and name_problem(name) is not None:
        raise BccError(f"the name {name_problem(name)}")
    if lava > max_rivers(depth):
        raise BccError(f"lava={lava}: a maze {depth} deep has room for at most {max_rivers(depth)} "
                       f"non-adjacent lava rivers")
    room = max_stones(width, depth, lava, loops)
    if stones > room:
        raise BccError(f"stones={stones}: a {width}x{depth} maze with lava={lava} has room for at most "
                       f"{max(room, 0)} stones in its corridors")


def _carve(rng: random.Random, width: int, depth: int, rivers=()) -> list[list[str]]:
    """A perfect maze by randomized DFS from (1, 1); the wall rows `rivers` are carved
    through once each."""
    grid = [["#"] * width for _ in range(depth)]
    grid[1][1] = "."
    stack, crossed = [(1, 1)], set()
    while stack:
        x, z = stack[-1]
        nexts = [(x + dx, z + dz) for dx, dz in ((2, 0), (-2, 0), (0, 2), (0, -2))
                 if 0 < x + dx < width - 1 and 0 < z + dz < depth - 1 and grid[z + dz][x + dx] == "#"
                 and not (dz and z + dz // 2 in rivers and z + dz // 2 in crossed)]
        if not nexts:
            stack.pop()
            continue
        nx, nz = rng.choice(nexts)
        grid[(z + nz) // 2][(x + nx) // 2] = grid[nz][nx] = "."
        if nz != z:
            crossed.add((z + nz) // 2)
        stack.append((nx, nz))
    return grid


def _knock(rng: random.Random, grid, width: int, depth: int, loops: float) -> None:
    """Remove `loops` of the walls still standing between two maze cells."""
    walls = [(x, z) for z in range(1, depth - 1) for x in range(1, width - 1)
             if grid[z][x] == "#" and (x % 2) != (z % 2)]
    for x, z in rng.sample(walls, _knocked(width, depth, loops)):
        grid[z][x] = "."


def _river_rows(rng: random.Random, depth: int, wanted: int) -> list[int]:
    """`wanted` random wall rows of 2..depth-3, no two adjacent (rows two apart at least)."""
    slots = sorted(rng.sample(range(len(range(2, depth - 2, 2)) - wanted + 1), wanted))
    return [2 + 2 * (slot + k) for k, slot in enumerate(slots)]


def _neighbours(grid, cell: Cell):
    x, z = cell
    for nx, nz in ((x, z - 1), (x + 1, z), (x, z + 1), (x - 1, z)):
        if grid[nz][nx] != "#":
            yield nx, nz


def _bfs(grid, start: Cell, allowed=lambda c: True) -> dict[Cell, Cell | None]:
    """Parent links of a BFS from start over corridor cells satisfying `allowed`."""
    parent: dict[Cell, Cell | None] = {start: None}
    queue = deque([start])
    while queue:
        cell = queue.popleft()
        for n in _neighbours(grid, cell):
            if n not in parent and allowed(n):
                parent[n] = cell
                queue.append(n)
    return parent


def _crossings(order, parent, rows: list[int]):
    """For every cell, along its BFS-tree path from the start: how often the path enters
    each candidate river row (capped at 2), and the last cell it entered in each."""
    index = {z: i for i, z in enumerate(rows)}
    count: dict[Cell, bytes] = {order[0]: bytes(len(rows))}
    cell_in: dict[Cell, tuple] = {order[0]: (None,) * len(rows)}
    for cell in order[1:]:
        c, v = count[parent[cell]], cell_in[parent[cell]]
        i = index.get(cell[1])
        if i is not None:
            c = c[:i] + bytes([min(c[i] + 1, 2)]) + c[i + 1:]
            v = v[:i] + (cell,) + v[i + 1:]
        count[cell], cell_in[cell] = c, v
    return count, cell_in


def _rivers(rng, grid, start: Cell, goal: Cell, parent, rows, count, cell_in, wanted: int):
    """`wanted` river rows, two wall rows apart at least, that the tree path start -> goal
    crosses exactly once, as (row, previous row or None, the path's cell just before the
    crossing); None if there are none."""
    once = [z for i, z in enumerate(rows) if count[goal][i] == 1 and z != goal[1]]
    # chain[k]: most rivers that fit from once[k] on (greedy is optimal for a minimum gap)
    chain = [1] * len(once)
    for k in range(len(once) - 1, -1, -1):
        later = [j for j in range(k + 1, len(once)) if once[j] >= once[k] + 4]
        chain[k] = 1 + (chain[later[0]] if later else 0)
    if not chain or max(chain) < wanted:
        return None
    before = {z: parent[cell_in[goal][rows.index(z)]] for z in once}

    def has_room(prev, z):
        # The region before river z is connected and holds `before[z]`; it lacks a cell for
        # the bridging stone only if that is the start and the start has no other neighbour.
        lo = prev if prev is not None else 0
        return before[z] != start or any(lo < n[1] < z for n in _neighbours(grid, start))

    def choose(prev, left):
        if left == 0:
            return []
        options = [z for k, z in enumerate(once) if (prev is None or z >= prev + 4) and chain[k] >= left]
        rng.shuffle(options)
        for z in options:
            rest = choose(z, left - 1) if has_room(prev, z) else None
            if rest is not None:
                return [(z, prev, before[z])] + rest
        return None
    return choose(None, wanted)


def _layout(rng, width, depth, stones, lava, loops, rows_first: bool):
    """One attempt: (grid, river rows, goal, whether the goal is the farthest cell), or
    None if no goal admits `lava` rivers in this maze."""
    start = (1, 1)
    rows = _river_rows(rng, depth, lava) if rows_first else list(range(2, depth - 2, 2))
    grid = _carve(rng, width, depth, rows if rows_first else ())
    tree = _bfs(grid, start)    # the perfect maze: paths here stay valid after the loops
    _knock(rng, grid, width, depth, loops)
    parent = _bfs(grid, start)
    order = list(parent)        # BFS order: parents first, nondecreasing distance
    dist = {start: 0}
    for cell in order[1:]:
        dist[cell] = dist[parent[cell]] + 1
    candidates = sorted(order[1:], key=lambda c: (-dist[c], c[1], c[0]))
    rivers: list = []
    if lava == 0:
        goal = candidates[0]
    else:
        count, cell_in = _crossings(list(tree), tree, rows)
        for goal in candidates:
            if goal in tree:
                rivers = _rivers(rng, grid, start, goal, tree, rows, count, cell_in, lava)
                if rivers is not None:
                    break
        else:
            return None
    lava_cells = {(x, z) for z, _, _ in rivers for x in range(width) if grid[z][x] != "#"}
    taken = {start, goal}
    bridges = []
    for z, prev, before in rivers:
        lo = prev if prev is not None else 0
        band = _bfs(grid, before, lambda c: lo < c[1] < z)  # reachable without crossing lava
        cell = rng.choice(sorted((c for c in band if c not in taken), key=lambda c: (c[1], c[0])))
        bridges.append(cell)
        taken.add(cell)
    free = sorted((c for c in order if c not in taken and c not in lava_cells), key=lambda c: (c[1], c[0]))
    extra = rng.sample(free, stones)
    for x, z in lava_cells:
        grid[z][x] = "L"
    for x, z in bridges + extra:
        grid[z][x] = "M"
    grid[start[1]][start[0]] = "S"
    grid[goal[1]][goal[0]] = "G"
    return grid, [z for z, _, _ in rivers], goal, goal == candidates[0]


def _scalar(text: str) -> str:
    """A YAML scalar reading back as `text`: plain when that is safe, else double-quoted."""
    try:
        if yaml.safe_load(text) == text:
            return text
    except yaml.YAMLError:
        pass
    return json.dumps(text)


def generate_maze(width: int, depth: int, stones: int = 0, lava: int = 0, loops: float = 0.0,
                  seed: int = 0, name: str | None = None) -> str:
    """Return the YAML text of a valid, solvable dungeon in the spec section 5 format.

    Raises BccError (one line) for bad arguments: even or too small sizes (width and depth
    are odd, >= 5), negative counts, `loops` outside 0..1, more stones than the corridors
    hold (`max_stones`), more rivers than the depth allows (`max_rivers`), or river rows
    that no maze of this size could be given.
    """
    _validate(width, depth, stones, lava, loops, seed, name)
    rng = random.Random(seed)
    for attempt in range(MAX_ATTEMPTS):
        layout = _layout(rng, width, depth, stones, lava, loops, rows_first=lava > 0 and attempt >= FREE_ATTEMPTS)
        if layout is not None:
            break
    else:
        raise BccError(f"lava={lava}: found no {width}x{depth} maze (seed {seed}) whose path to the gold "
                       f"crosses {lava} rivers once each; use fewer rivers or a bigger maze")
    grid, river_rows, (gx, gz), farthest = layout
    name = name if name is not None else f"maze_{width}x{depth}_s{stones}_l{lava}_seed{seed}"
    rivers = "" if not lava else (
        f", 1 lava river (wall row z = {river_rows[0]}) with one bridging stone" if lava == 1 else
        f", {lava} lava rivers (wall rows z = {', '.join(map(str, river_rows))}) each with one bridging stone")
    knocked = f"{loops:g} of the remaining walls knocked out" if loops else "no loops"
    description = (f"Generated by bcc.generate from seed {seed}. A {width}x{depth} perfect maze "
                   f"(randomized depth-first search) with {knocked}, "
                   f"{stones} mineable stone{'s' if stones != 1 else ''}{rivers}; "
                   f"start S at (1, 1), gold at ({gx}, {gz}), the farthest cell from S"
                   f"{'' if farthest else ' whose path crosses every river once'}.")
    rows = "\n".join("  " + "".join(row) for row in grid)
    used = {c for row in grid for c in row}
    # only the characters the map uses: an unused legend character is a warning
    legend = "\n".join(line for line in LEGEND.splitlines()
                       if not line.startswith('  "') or line[3] in used)
    return (f"dungeon: {_scalar(name)}\n"
            f"domain: minecraft\n"
            f"description: {_scalar(description)}\n"
            f"height: 4\n"
            f"{legend}\n"
            f"map: |\n{rows}\n"
            f"agent:\n"
            f"  start: S\n"
            f"  facing: north\n"
            f"  looking: ahead\n"
            f"  selected: 0\n"
            f"inventory:\n"
            f"  - {{item: diamond_pickaxe, count: 1}}\n"
            f"goal: agentOnBlock(agent, gold)\n")
