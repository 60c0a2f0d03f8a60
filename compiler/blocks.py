"""Read a dungeon's `blocks:` text: blocks listed by position, for big sparse 3D worlds.

Why text and not YAML lists: a world of 11,000 blocks as YAML sequences is 50,000 YAML
nodes, each with a position, and loading them costs seconds; one block scalar of lines
`X Y Z NAME` is read with one regular expression a line. A coordinate may be a range
`A..B` (both ends included), so a floor or a wall is one line. `#` starts a comment.

    blocks: |
      0..73 0 0..73 floor       # a floor: one line
      5 1 7 wall
"""
from __future__ import annotations

import re

from .source import Origin, suggest

_COORD = r"(-?\d+)(?:\.\.(-?\d+))?"
_LINE = re.compile(rf"\s*{_COORD}\s+{_COORD}\s+{_COORD}\s+([A-Za-z_][A-Za-z0-9_]*)\s*$")
USAGE = "a line of `blocks` is `X Y Z NAME`, each coordinate a number or a range A..B"


def parse_blocks(text, where: Origin, values: list) -> list[tuple]:
    """[(x0, x1, y0, y1, z0, z1, value index, line)] of the text; `values` names the blocks."""
    if not isinstance(text, str):
        raise where.error("`blocks` is a block of text (use `blocks: |`), one `X Y Z NAME` a line")
    index = {name: i for i, name in enumerate(values)}
    out = []
    for n, raw in enumerate(text.splitlines(), 1):
        line = raw.split("#", 1)[0]
        if not line.strip():
            continue
        m = _LINE.match(line)
        if m is None:
            raise where.error(USAGE, n, len(raw) - len(raw.lstrip()) + 1)
        nums = [int(m[i]) if m[i] is not None else int(m[i - 1]) for i in range(1, 7)]
        for axis, (lo, hi) in zip("xyz", ((nums[0], nums[1]), (nums[2], nums[3]), (nums[4], nums[5]))):
            if lo > hi:
                raise where.error(f"the range {lo}..{hi} of {axis} is empty (write the low end first)", n,
                                  line.index(f"{lo}..") + 1)
        name = m[7]
        if name not in index:
            raise where.error(f"unknown block type {name!r}{suggest(name, values)}", n, m.start(7) + 1)
        out.append((nums[0], nums[1], nums[2], nums[3], nums[4], nums[5], index[name], n))
    return out


def place_blocks(grid: bytearray, boxes: list, width: int, depth: int, height: int, where: Origin) -> None:
    """Write each box of `parse_blocks` into the dense grid [y][z][x]; a box reaching outside
    the world is refused at its line."""
    for x0, x1, y0, y1, z0, z1, value, n in boxes:
        for lo, hi, size, axis in ((x0, x1, width, "x"), (y0, y1, height, "y"), (z0, z1, depth, "z")):
            if lo < 0 or hi >= size:
                raise where.error(f"{axis} = {lo if lo < 0 else hi} is outside the world (0..{size - 1})", n)
        run = bytes([value]) * (x1 - x0 + 1)
        for y in range(y0, y1 + 1):
            for z in range(z0, z1 + 1):
                start = (y * depth + z) * width + x0
                grid[start:start + len(run)] = run
