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


# ---- a 3D world layer by layer ---------------------------------------------------------
# Marks drawn over a layer's cells; a value is never drawn with one of these.
AGENT, PATH, PENDING, WRONG, EMPTY = "@", "o", "+", "!", "."
_RESERVED = {AGENT, PATH, PENDING, WRONG, EMPTY, " ", "*"}


def draws_layers(model: Model) -> bool:
    """`bcc show`'s choice when no view is asked for: layer by layer when the goal has cell
    atoms (a structure) or the agent changes level (its y is a state variable), else the
    top view."""
    return bool(_goal_atoms(model)) or (len(model.position) == 3 and model.position[1] is not None)


def _goal_atoms(model: Model) -> list:
    from .heuristics.goal_cells import goal_cells
    cells = goal_cells(model)
    return list(cells.atoms) if cells is not None else []


def value_chars(model: Model, values) -> dict:
    """One character per grid value to draw (value index -> character): the empty value is
    `.`; a value a blueprint's legend names keeps that character; any other value takes the
    first letter of its name that is free (lower case first, then upper case, then a digit)."""
    names, default = model.grid.value_names, model.grid.default
    wanted = model.display.get("value_chars", {})
    out, used = {default: EMPTY}, set(_RESERVED)
    for v in sorted(values):
        ch = wanted.get(names[v])
        if v != default and ch and ch not in used:
            out[v] = ch
            used.add(ch)
    for v in sorted(values):
        if v in out:
            continue
        letters = [c for c in names[v] if c.isalnum()]
        choices = [c.lower() for c in letters] + [c.upper() for c in letters] + list("0123456789")
        out[v] = next((c for c in choices if c not in used), "?")
        used.add(out[v])
    return out


def layer_view(model: Model, state: bytes, path: list | None = None, only: list | None = None) -> dict:
    """The world as layers (y from the bottom up; row k is z = k, column i is x = i), each
    cell drawn by its value's character, the agent's feet `@`, a plan's path `o`, and each
    cell of the goal's cell atoms that is not done yet `+` (empty now) or `!` (holding
    another value). Layers holding nothing but the empty value and no mark are left out,
    unless `only` names them. Returns {"layers": [{"y", "rows"}], "legend": {character:
    value name}, "goal_cells": {"done", "pending", "wrong": counts, "cells": {...}}}."""
    g = model.grid
    grid = model.view(state).grid()                      # [y][z][x] value indices
    atoms = _goal_atoms(model)
    marks: dict = {}
    progress = {"done": [], "pending": [], "wrong": []}
    for (x, y, z), want in atoms:
        have = int(grid[y][z][x])
        kind = "done" if have == want else ("pending" if have == g.default else "wrong")
        progress[kind].append([x, y, z])
        if kind != "done":
            marks[(x, y, z)] = PENDING if kind == "pending" else WRONG
    for p in path or []:
        marks.setdefault(tuple(p), PATH)
    marks[tuple(model.agent_position(state))] = AGENT
    ys = sorted(set(only)) if only else [y for y in range(g.height)
                                          if (grid[y] != g.default).any() or any(m[1] == y for m in marks)]
    present = {int(v) for y in ys for v in set(grid[y].flatten().tolist())}
    chars = value_chars(model, present)
    layers = []
    for y in ys:
        rows = []
        for z in range(g.depth):
            rows.append("".join(marks.get((x, y, z)) or chars[int(grid[y][z][x])] for x in range(g.width)))
        layers.append({"y": y, "rows": rows})
    legend = {ch: g.value_names[v] for v, ch in sorted(chars.items(), key=lambda item: item[1]) if v in present}
    counts = {k: len(v) for k, v in progress.items()}
    return {"layers": layers, "legend": legend, "goal_cells": {**counts, "cells": progress}}


def render_layers(view: dict) -> str:
    """`layer_view`'s answer as text: each layer under a `y = N` line, then the legend and
    the goal's progress."""
    lines = []
    for layer in view["layers"]:
        lines.append(f"y = {layer['y']}")
        lines += ["  " + row for row in layer["rows"]]
    lines.append("legend: " + ", ".join(f"{ch} {name}" for ch, name in view["legend"].items())
                 + f"; {AGENT} agent, {PATH} path")
    gc = view["goal_cells"]
    if gc["done"] + gc["pending"] + gc["wrong"]:
        lines.append(f"goal cells: {gc['done']} done, {gc['pending']} pending ({PENDING}), "
                     f"{gc['wrong']} wrong ({WRONG})")
    return "\n".join(lines)
