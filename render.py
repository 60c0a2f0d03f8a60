"""Draw a state as an ASCII top view (row k is z = k, column i is x = i).

Each column is drawn with the dungeon legend's character for the same blocks; a column
an action changed into something the legend lacks is drawn `*`. The agent is an arrow
for its facing (`^ v < >`, else `@`); other named objects with a position are the
initial of their name, upper case; with a plan, cells the agent visited are `o`.
"""
from __future__ import annotations

from .model import Model

ARROWS = {"north": "^", "south": "v", "west": "<", "east": ">"}


def facing_name(model: Model, state: bytes) -> str | None:
    f = model.display.get("facing")
    if not f:
        return None
    value = state[f["index"]] + f["lo"] if f["index"] is not None else f["value"]
    return f["names"].get(value)


def render(model: Model, state: bytes, path: list | None = None) -> str:
    g = model.grid
    glyphs = model.display.get("glyphs", {})
    ax, _, az = model.agent_position(state)
    visited = {(p[0], p[2]) for p in (path or [])}
    others = {(x, z): name[0].upper() for name, x, z in model.display.get("objects", [])}
    rows = []
    for z in range(g.depth):
        row = []
        for x in range(g.width):
            if (x, z) == (ax, az):
                row.append(ARROWS.get(facing_name(model, state) or "", "@"))
            elif (x, z) in others:
                row.append(others[(x, z)])
            elif (x, z) in visited:
                row.append("o")
            else:
                row.append(glyphs.get(model.column(state, x, z), "*"))
        rows.append("".join(row))
    return "\n".join(rows)
