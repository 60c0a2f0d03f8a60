"""Generate small four-room dungeons with colored rooms, a gold block and a stone, for the corpus.

Like `four_rooms`, each room is walled with the wool of its color and named after it; the
walls between rooms have one door each. Colors, sizes, doors, gold, stone and start are
drawn from `random.Random(seed)`, so a seed always gives the same text.
"""
from __future__ import annotations

import random

COLORS = ["red", "orange", "green", "blue"]
WOOL = {"red": "r", "orange": "o", "green": "g", "blue": "b"}


def generate_rooms(seed: int, name: str | None = None) -> str:
    rng = random.Random(seed)
    width, depth = rng.choice([9, 10, 11, 12]), rng.choice([9, 10, 11, 12])
    sx, sz = rng.randint(4, width - 5), rng.randint(4, depth - 5)
    colors = rng.sample(COLORS, 4)
    # quadrants: (x range of walls, z range of walls, color)
    quads = [((0, sx), (0, sz)), ((sx, width - 1), (0, sz)), ((0, sx), (sz, depth - 1)), ((sx, width - 1), (sz, depth - 1))]
    grid = [["." for _ in range(width)] for _ in range(depth)]
    for (x0, x1), (z0, z1), color in [(q[0], q[1], c) for q, c in zip(quads, colors)]:
        for x in range(x0, x1 + 1):
            for z in (z0, z1):
                grid[z][x] = WOOL[color]
        for z in range(z0, z1 + 1):
            for x in (x0, x1):
                grid[z][x] = WOOL[color]
    doors = []
    for z0, z1 in ((0, sz), (sz, depth - 1)):          # doors in the wall x = sx
        z = rng.randint(z0 + 1, z1 - 1)
        grid[z][sx] = "."
        doors += [(sx - 1, z), (sx + 1, z)]
    for x0, x1 in ((0, sx), (sx, width - 1)):          # doors in the wall z = sz
        x = rng.randint(x0 + 1, x1 - 1)
        grid[sz][x] = "."
        doors += [(x, sz - 1), (x, sz + 1)]
    interiors = [[(x, z) for z in range(q[1][0] + 1, q[1][1]) for x in range(q[0][0] + 1, q[0][1])] for q in quads]
    taken = set(doors)
    # the stone goes in a room corner away from doors: it never cuts a room in two
    corners = [c for room in interiors for c in (room[0], room[-1]) if c not in taken]
    stone = rng.choice(corners)
    taken.add(stone)
    gold_room, start_room = rng.sample(range(4), 2)
    gold = rng.choice([c for c in interiors[gold_room] if c not in taken])
    taken.add(gold)
    start = rng.choice([c for c in interiors[start_room] if c not in taken])
    for (x, z), ch in ((stone, "M"), (gold, "G"), (start, "S")):
        grid[z][x] = ch
    name = name or f"rooms_seed{seed}"
    lines = [f"dungeon: {name}", "domain: minecraft",
             (f"description: Generated for the grounding corpus from seed {seed}; four colored rooms, "
              f"a gold block in the {colors[gold_room]} room, a stone to mine."),
             "height: 3", "legend:"]
    lines += [f'  "{ch}": [{c}_wool, {c}_wool, {c}_wool]' for c, ch in WOOL.items()]
    lines += ['  ".": [bedrock]', '  "S": [bedrock]', '  "G": [gold]', '  "M": [bedrock, burlap_stone]', "map: |"]
    lines += ["  " + "".join(row) for row in grid]
    lines += ["agent:", "  start: S", f"  facing: {rng.choice(['north', 'south', 'east', 'west'])}",
              "  looking: ahead", "  selected: 0", "inventory:", "  - {item: diamond_pickaxe, count: 1}", "rooms:"]
    for q, c in zip(quads, colors):
        lines.append(f"  - {{name: {c}, color: {c}, x: [{q[0][0]}, {q[0][1]}], z: [{q[1][0]}, {q[1][1]}]}}")
    lines.append("goal: agentOnBlock(agent, gold)")
    return "\n".join(lines) + "\n"
