"""Generate manipulation dungeons: three rooms in a row, stones to carry into the blue one.

`generate_manipulation(stones)` lays out a red, a green and a blue room (interiors 3 x 3,
one wool wall between neighbours with a door in it), the agent in the green room facing
north with the pickaxe in slot 0, and `stones` burlap stones (`M`, a stone at foot level)
spread over the red and green rooms. The goal is "every stone in the blue room": no
stone outside the blue room, and none left in the agent's hands. Every instance is
solvable: mine the stones, walk into the blue room and place them there (its 9 cells
hold all 8 stones the generator allows: fill it from the far side, the last from the door).

The same arguments always give the same text.
"""
from __future__ import annotations

import json

from .compiler.names import name_problem
from .errors import BccError

MAX_STONES = 8
WIDTH, DEPTH = 13, 5
START = (6, 2)
# Stone cells (x, z), alternating between the red room (x 1..3) and the green room
# (x 5..7), in corners so that no stone closes a door (x 4 and 8, z 2).
STONE_CELLS = [(1, 1), (7, 1), (3, 3), (5, 3), (1, 3), (7, 3), (3, 1), (5, 1)]

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
  - {name: red, color: red, x: [0, 4], z: [0, 4]}
  - {name: green, color: green, x: [4, 8], z: [0, 4]}
  - {name: blue, color: blue, x: [8, 12], z: [0, 4]}
'''


def room_map(stones: int) -> list[str]:
    rows = []
    for z in range(DEPTH):
        row = []
        for x in range(WIDTH):
            room = "r" if x < 4 else "g" if x < 8 else "b"
            wall = z in (0, DEPTH - 1) or x in (0, 4, 8, WIDTH - 1)
            door = z == DEPTH // 2 and x in (4, 8)
            row.append(room if wall and not door else ".")
        rows.append(row)
    rows[START[1]][START[0]] = "S"
    for x, z in STONE_CELLS[:stones]:
        rows[z][x] = "M"
    return ["".join(r) for r in rows]


def generate_manipulation(stones: int = 4, name: str | None = None) -> str:
    """The YAML text of a three-room dungeon with `stones` stones (1..8) to carry."""
    if not isinstance(stones, int) or isinstance(stones, bool) or not 1 <= stones <= MAX_STONES:
        raise BccError(f"stones must be a whole number from 1 to {MAX_STONES}, got {stones!r}")
    if name is not None and name_problem(name) is not None:
        raise BccError(f"the name {name_problem(name)}")
    name = name or f"manipulation_{stones}"
    body = "\n".join("  " + row for row in room_map(stones))
    return (f"dungeon: {json.dumps(name)}\n"
            f"description: Three rooms; carry all {stones} stones into the blue room.\n"
            + HEADER + "map: |\n" + body + "\n" + FOOTER + f"goal: {GOAL}\n")
