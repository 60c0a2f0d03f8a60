"""Generate manipulation dungeons: three rooms in a row, stones to carry into the blue one.

`generate_manipulation(stones)` lays out a red, a green and a blue room (interiors 4 x 5,
double wool walls with a door between neighbours), the agent in the green room facing
north with the pickaxe in slot 0, and `stones` burlap stones (`M`, a stone at foot level)
spread over the red and green rooms. The goal is "every stone in the blue room": no
stone outside the blue room, and none left in the agent's hands. Every instance is
solvable: mine the stones, walk into the blue room and place them there (its 20 cells
hold all 8 stones the generator allows).

The same arguments always give the same text.
"""
from __future__ import annotations

import json

from .errors import BccError

MAX_STONES = 8
# Stone cells (x, z), alternating between the red room (x 1..4) and the green room
# (x 7..10), off the door row z = 3 and off the agent's start (8, 3).
STONE_CELLS = [(2, 1), (9, 1), (3, 5), (8, 5), (1, 2), (10, 2), (4, 4), (7, 4)]

GOAL = ("not agentHasBlock(agent, burlap_stone) and "
        "forall b in block . (b.blockType != burlap_stone or blockInRoom(b, blue))")

HEADER = '''domain: minecraft
height: 3
legend:
  "r": [red_wool, red_wool, red_wool]
  "g": [green_wool, green_wool, green_wool]
  "b": [blue_wool, blue_wool, blue_wool]
  ".": [bedrock]
  "S": [bedrock]
  "M": [bedrock, burlap_stone]
'''

FOOTER = '''agent:
  start: S
  facing: north
  looking: ahead
  selected: 0
inventory:
  - {item: diamond_pickaxe, count: 1}
rooms:
  - {name: red, color: red, x: [0, 5], z: [0, 6]}
  - {name: green, color: green, x: [6, 11], z: [0, 6]}
  - {name: blue, color: blue, x: [12, 17], z: [0, 6]}
'''


def room_map(stones: int) -> list[str]:
    rows = []
    for z in range(7):
        row = []
        for x in range(18):
            room = "r" if x <= 5 else "g" if x <= 11 else "b"
            wall = z in (0, 6) or x in (0, 5, 6, 11, 12, 17)
            door = z == 3 and x in (5, 6, 11, 12)
            row.append(room if wall and not door else ".")
        rows.append(row)
    rows[3][8] = "S"
    for x, z in STONE_CELLS[:stones]:
        rows[z][x] = "M"
    return ["".join(r) for r in rows]


def generate_manipulation(stones: int = 4, name: str | None = None) -> str:
    """The YAML text of a three-room dungeon with `stones` stones (1..8) to carry."""
    if not isinstance(stones, int) or isinstance(stones, bool) or not 1 <= stones <= MAX_STONES:
        raise BccError(f"stones must be a whole number from 1 to {MAX_STONES}, got {stones!r}")
    name = name or f"manipulation_{stones}"
    body = "\n".join("  " + row for row in room_map(stones))
    return (f"dungeon: {json.dumps(name)}\n"
            f"description: Three rooms; carry all {stones} stones into the blue room.\n"
            + HEADER + "map: |\n" + body + "\n" + FOOTER + f"goal: {GOAL}\n")
