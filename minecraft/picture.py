"""A picture of the world as the server reports it: an isometric SVG of the blocks of the
dungeon's box (from `observe`), seen from the south-east and above, and the player.

It is drawn from the observation, not from the model, so it shows what was really built.
Only the visible faces are drawn (a face against another block is left out), back to
front; colours are Minecraft's, roughly, with the sides shaded.
"""
from __future__ import annotations

import math

# a block's colour (its top); names not listed are drawn in COLOUR_OTHER
COLOURS = {
    "oak_planks": "#b8945f", "stone": "#8a8a8a", "bedrock": "#4f4f4f", "dirt": "#8b5e3c",
    "grass_block": "#6aa84f", "cobblestone": "#7a7a7a", "oak_log": "#6b5134", "white_wool": "#eeeeee",
    "bricks": "#9c5a48", "stone_bricks": "#7b7b7b", "glass": "#cfe8f0", "water": "#3f76e4", "lava": "#e25a12",
    "gold_block": "#f5d142", "sand": "#dbcf8e", "gravel": "#857b7b", "obsidian": "#1e1430",
    "oak_leaves": "#3f7f2f", "diamond_block": "#62dbd5", "glowstone": "#f0c060",
}
COLOUR_OTHER = "#b070c0"
SHADE = {"top": 1.0, "south": 0.78, "east": 0.62}
SEE_THROUGH = {"glass": 0.45, "water": 0.6}


def _shade(colour: str, k: float) -> str:
    r, g, b = (int(colour[i:i + 2], 16) for i in (1, 3, 5))
    return "#%02x%02x%02x" % tuple(max(0, min(255, round(c * k))) for c in (r, g, b))


def svg(obs: dict, size: tuple, origin: tuple, title: str = "", scale: float = 24.0) -> str:
    """The SVG text for an observation with blocks (`palette`, `cells` in [y][z][x]) of a
    box of `size` (width, height, depth) at `origin`, and the player's position."""
    width, height, depth = size
    palette, cells = obs["palette"], obs["cells"]
    area = width * depth
    blocks = {}
    for y in range(height):
        for z in range(depth):
            for x in range(width):
                name = palette[cells[y * area + z * width + x]]
                if name not in ("air", "cave_air", "void_air"):
                    blocks[(x, y, z)] = name
    cx, cy = math.cos(math.pi / 6) * scale, math.sin(math.pi / 6) * scale

    def point(x: float, y: float, z: float) -> tuple:
        return ((x - z) * cx, (x + z) * cy - y * scale)

    def solid(cell) -> bool:
        name = blocks.get(cell)
        return name is not None and name not in SEE_THROUGH

    polys = []      # (depth key, points, fill, opacity)
    for (x, y, z), name in blocks.items():
        colour = COLOURS.get(name, COLOUR_OTHER)
        faces = []
        if not solid((x, y + 1, z)):
            faces.append(("top", [(x, y + 1, z), (x + 1, y + 1, z), (x + 1, y + 1, z + 1), (x, y + 1, z + 1)]))
        if not solid((x, y, z + 1)):
            faces.append(("south", [(x, y, z + 1), (x + 1, y, z + 1), (x + 1, y + 1, z + 1), (x, y + 1, z + 1)]))
        if not solid((x + 1, y, z)):
            faces.append(("east", [(x + 1, y, z), (x + 1, y, z + 1), (x + 1, y + 1, z + 1), (x + 1, y + 1, z)]))
        for face, corners in faces:
            polys.append(((x + y + z, y), [point(*c) for c in corners], _shade(colour, SHADE[face]),
                          SEE_THROUGH.get(name, 1.0)))
    ox, oy, oz = origin
    px, py, pz = obs["position"]
    bx, by, bz = px - ox, py - oy, pz - oz
    player = []     # the player: a red box 0.6 wide and 1.8 high, drawn in its place in the order
    lo, hi = (bx - 0.3, by, bz - 0.3), (bx + 0.3, by + 1.8, bz + 0.3)
    key = (math.floor(bx) + math.floor(by) + math.floor(bz) + 0.5, math.floor(by))
    for face, corners in (
            ("top", [(lo[0], hi[1], lo[2]), (hi[0], hi[1], lo[2]), (hi[0], hi[1], hi[2]), (lo[0], hi[1], hi[2])]),
            ("south", [(lo[0], lo[1], hi[2]), (hi[0], lo[1], hi[2]), (hi[0], hi[1], hi[2]), (lo[0], hi[1], hi[2])]),
            ("east", [(hi[0], lo[1], lo[2]), (hi[0], lo[1], hi[2]), (hi[0], hi[1], hi[2]), (hi[0], hi[1], lo[2])])):
        player.append((key, [point(*c) for c in corners], _shade("#d03030", SHADE[face]), 1.0))
    polys += player
    polys.sort(key=lambda p: p[0])
    xs = [p[0] for _, pts, _, _ in polys for p in pts] or [0.0]
    ys = [p[1] for _, pts, _, _ in polys for p in pts] or [0.0]
    pad = scale
    x0, y0 = min(xs) - pad, min(ys) - pad - (scale if title else 0)
    w, h = max(xs) - min(xs) + 2 * pad, max(ys) - min(ys) + 2 * pad + (scale if title else 0)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{x0:.1f} {y0:.1f} {w:.1f} {h:.1f}" '
           f'width="{w:.0f}" height="{h:.0f}">',
           f'<rect x="{x0:.1f}" y="{y0:.1f}" width="{w:.1f}" height="{h:.1f}" fill="#f4f7fb"/>']
    if title:
        out.append(f'<text x="{x0 + pad / 2:.1f}" y="{y0 + scale:.1f}" font-family="sans-serif" '
                   f'font-size="{scale * 0.6:.0f}" fill="#333">{_escape(title)}</text>')
    for _, pts, fill, opacity in polys:
        path = " ".join(f"{x:.1f},{y:.1f}" for x, y in pts)
        extra = f' fill-opacity="{opacity}"' if opacity < 1 else ""
        out.append(f'<polygon points="{path}" fill="{fill}"{extra} stroke="#00000040" stroke-width="0.6"/>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def _escape(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
