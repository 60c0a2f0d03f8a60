"""Structure goals: a blueprint of cells, read from YAML, becomes a conjunction of cell atoms.

A blueprint is written as a dungeon's map is: layers of rows of characters, bottom layer
first, each character standing for one grid value through a legend; a space is a cell
the blueprint leaves open (no atom). Row k of a layer is z = at.z + k, column i is
x = at.x + i, layer j is y = at.y + j:

    goal:
      structure:
        at: [2, 1, 2]
        legend: {"#": brick, ".": air}
        layers:
          - |
            ###
            #.#
            ###

It compiles to `GRID[x, y, z].VALUE == NAME and ...` over the domain's grid class, so the
rest of the compiler, the heuristics and the solvers see an ordinary goal.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from . import ast
from .source import YList, YMap, check_keys, error_at

KEYS = {"at", "legend", "layers"}


@dataclass
class Blueprint:
    at: tuple                 # the anchor: where layer 0, row 0, column 0 sits
    cells: dict               # (x, y, z) -> value name, in the world's coordinates
    chars: dict = field(default_factory=dict)   # value name -> its legend character (for drawing)

    def summary(self) -> dict:
        """What `bcc compile --json` reports of it."""
        xs, ys, zs = zip(*self.cells) if self.cells else ((0,), (0,), (0,))
        names = {}
        for v in self.cells.values():
            names[v] = names.get(v, 0) + 1
        return {"atoms": len(self.cells), "at": list(self.at),
                "size": {"width": max(xs) - min(xs) + 1, "height": max(ys) - min(ys) + 1,
                         "depth": max(zs) - min(zs) + 1},
                "values": dict(sorted(names.items()))}


def is_structure(node) -> bool:
    return isinstance(node, YMap) and "structure" in node


def listed_goal(goal) -> str | None:
    """A dungeon file's `goal:` as one line of text for a listing (`bcc list`, the server's
    /dungeons), read without compiling: an expression as written, a list of them joined
    with `and`, a blueprint as its cell count and anchor."""
    if goal is None or isinstance(goal, str):
        return goal
    if isinstance(goal, list):
        return " and ".join(f"({g})" for g in goal)
    if isinstance(goal, dict) and isinstance(goal.get("structure"), dict):
        spec = goal["structure"]
        layers = spec.get("layers") if isinstance(spec.get("layers"), list) else []
        cells = sum(len(row.rstrip()) - row.rstrip().count(" ") for layer in layers if isinstance(layer, str)
                    for row in layer.split("\n"))
        return f"structure of {cells} cells at {list(spec.get('at') or [])}"
    return str(goal)


def read_blueprint(holder: YMap, values: tuple, size: tuple) -> Blueprint:
    """The blueprint of `holder` (a mapping with `structure:`), checked against the grid's
    value names and its size (width, height, depth); errors point into the file."""
    spec = holder["structure"]
    if not isinstance(spec, YMap):
        raise error_at(holder, "structure", "`structure` is a mapping with `at`, `legend` and `layers`")
    check_keys(spec, KEYS, KEYS, "a structure")
    at = spec["at"]
    if not (isinstance(at, YList) and len(at) == 3 and all(isinstance(v, int) and not isinstance(v, bool) for v in at)):
        raise error_at(spec, "at", "`at` is the anchor [x, y, z]: three integers")
    legend = spec["legend"]
    if not isinstance(legend, YMap) or not legend:
        raise error_at(spec, "legend", "`legend` maps one character to a value name, e.g. {\"#\": "
                       f"{values[-1]}, \".\": {values[0]}}}")
    chars = {}
    for ch, name in legend.items():
        if not isinstance(ch, str) or len(ch) != 1 or ch == " " or not ch.isprintable():
            raise error_at(legend, ch, f"a legend key is one printable character other than a space, found {ch!r}",
                           on_key=True)
        if name not in values:
            from .source import suggest
            raise error_at(legend, ch, f"unknown value {name!r}{suggest(str(name), values)}")
        chars[ch] = name
    layers = spec["layers"]
    if not isinstance(layers, YList) or not layers:
        raise error_at(spec, "layers", "`layers` is a list of maps (`- |` then rows), bottom layer first")
    width, height, depth = size
    cells = {}
    for j, layer in enumerate(layers):
        if not isinstance(layer, str):
            raise error_at(layers, j, "a layer is a block of rows (`- |`), one character a cell")
        for k, row in enumerate(layer.rstrip("\n").split("\n")):
            for i, ch in enumerate(row.rstrip()):
                if ch == " ":
                    continue
                if ch not in chars:
                    raise error_at(layers, j, f"layer {j}, row {k}, column {i}: {ch!r} is not in the legend")
                x, y, z = at[0] + i, at[1] + j, at[2] + k
                if not (0 <= x < width and 0 <= y < height and 0 <= z < depth):
                    raise error_at(layers, j, f"layer {j}, row {k}, column {i} is the cell ({x}, {y}, {z}), "
                                   f"outside the world ({width} x {height} x {depth})")
                cells[(x, y, z)] = chars[ch]
    if not cells:
        raise error_at(spec, "layers", "the structure has no cell: every character is a space")
    return Blueprint(tuple(at), cells, {name: ch for ch, name in reversed(chars.items())})


def goal_node(blueprint: Blueprint, grid_class: str, value_attr: str):
    """The blueprint's conjunction as a syntax tree (balanced, so no walk goes deep)."""
    atoms = [ast.Compare((ast.Attr(ast.Index(ast.Name(grid_class), (ast.Int(x), ast.Int(y), ast.Int(z))), value_attr),
                          ast.Name(name)), ("==",))
             for (x, y, z), name in sorted(blueprint.cells.items(), key=lambda c: (c[0][1], c[0][2], c[0][0]))]

    def join(lo, hi):
        if hi - lo == 1:
            return atoms[lo]
        mid = (lo + hi) // 2
        return ast.And(join(lo, mid), join(mid, hi))
    return join(0, len(atoms))


def goal_text(blueprint: Blueprint, path: str) -> str:
    """The goal as `bcc compile` shows it: short, not the thousands of atoms."""
    s = blueprint.summary()["size"]
    return f"structure of {len(blueprint.cells)} cells ({s['width']} x {s['height']} x {s['depth']}) " \
           f"at {list(blueprint.at)} from {path}"


def structure_expr(blueprint: Blueprint, holder: YMap, grid_class: str, value_attr: str):
    """The goal `Expr` of the blueprint `holder` holds."""
    from .definitions import Expr
    from .source import Origin, node_pos, value_node
    line, col = node_pos(value_node(holder, "structure"))
    path = holder.src_of("structure").path
    return Expr(goal_node(blueprint, grid_class, value_attr), Origin(path, line, col), goal_text(blueprint, path))
