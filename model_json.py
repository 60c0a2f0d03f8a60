"""The compiled model as documented JSON (format `bcc-model/2`), for other tools to read.

Why: `bcc compile --json` prints a report for people; this is the model itself -- its
state layout, objects, grid and grounded actions -- in a form a program can load
without bcc. Keys (all always present):

- `format`: "bcc-model/2"; `dungeon`, `domain`, `goal` (the goal's source text);
- `report`: the compile report (classes, objects, functions, action schemas, sizes);
- `state_bytes`: length of the packed initial state; `initial`: it as a list of bytes;
- `variables`: [{label, index, lo, hi, type, names}] -- byte `index` holds `value - lo`,
  enumerations their dense index into `names`, booleans 0/1;
- `grid`: {width, depth, height, base, layers, value_names, default, cells}: a state holds,
  from byte `base` on, only the cells of the mutable `layers` that differ from `cells`:
  4 bytes each, the little-endian int (index << 8) | value where index is the mutable
  cell index (layer * depth + z) * width + x, sorted by index; `cells` is the initial grid as value
  indices, `cells[y][z][x]` (static layers never change);
- `actions`: [{index, name, cost, preconditions}]: the grounded actions in canonical
  order, each precondition as its source text; `search_actions`: the indices solvers use;
- `initial_values`: every variable of the initial state by label (enumeration names).
"""
from __future__ import annotations

FORMAT = "bcc-model/2"   # 2: states store changed cells only (1: every mutable cell)


def model_json(model) -> dict:
    g = model.grid
    cells = [[[g.cell(model.initial, x, y, z) for x in range(g.width)] for z in range(g.depth)]
             for y in range(g.height)]
    return {
        "format": FORMAT,
        "dungeon": model.name,
        "domain": model.report.get("domain"),
        "goal": model.goal_text,
        "report": model.report,
        "state_bytes": len(model.initial),
        "initial": list(model.initial),
        "variables": [{"label": v.label, "index": v.index, "lo": v.lo, "hi": v.hi, "type": v.type,
                       "names": list(v.names)} for v in model.variables],
        "grid": {"width": g.width, "depth": g.depth, "height": g.height, "base": g.base,
                 "layers": list(g.layers), "value_names": list(g.value_names), "default": g.default,
                 "cells": cells},
        "actions": [{"index": i, "name": n, "cost": c, "preconditions": list(p)}
                    for i, (n, c, p) in enumerate(zip(model.action_names, model.action_costs, model.pre_texts))],
        "search_actions": list(model.search_actions),
        "initial_values": model.decode(model.initial),
    }
