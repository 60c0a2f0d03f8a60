"""A MinePlanner task as a bcc dungeon on the `builder` domain (domains/builder.yaml).

The world is the box of the task's blocks, items, agent and goal cells. Its lowest layer
is that of the lowest block (nothing can stand lower), its top two layers above the
highest block, item, goal cell or the agent's head (`headroom`), never above the task's
own top position: higher, the agent could only build pillars towards nothing, and every
layer costs state space. Blocks are written one line per run along x (`blocks:`).
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from ..errors import BccError
from .task import Task

HEADROOM = 2
# north is -z, as in minecraft.yaml and MinePlanner's `are-seq ?z_end ?z_start`
STEPS = {"north": (0, -1), "south": (0, 1), "east": (1, 0), "west": (-1, 0)}


@dataclass(frozen=True)
class Frame:
    """Where the dungeon's cell (0, 0, 0) is in the task's coordinates, and its size."""
    x0: int
    y0: int
    z0: int
    width: int
    height: int
    depth: int

    def local(self, at) -> tuple:
        return at[0] - self.x0, at[1] - self.y0, at[2] - self.z0


def frame(task: Task, goal_cells: list, headroom: int = HEADROOM) -> Frame:
    if not task.blocks:
        raise BccError("the task has no blocks: nothing to stand on", task.paths[1])
    points = list(task.blocks) + [at for _, _, at in task.items] + [task.agent_at] + goal_cells
    xs, zs = [p[0] for p in points], [p[2] for p in points]
    y0 = min(y for _, y, _ in task.blocks)
    top = max([y for _, y, _ in task.blocks] + [at[1] for _, _, at in task.items] + [task.agent_at[1] + 1]
              + [p[1] for p in goal_cells]) + headroom
    top = min(top, len(task.positions) - 1)
    height = top - y0 + 1
    if height > 255:
        raise BccError(f"the world would be {height} layers high; at most 255", task.paths[1])
    return Frame(min(xs), y0, min(zs), max(xs) - min(xs) + 1, height, max(zs) - min(zs) + 1)


def identifier(name: str, taken: set) -> str:
    """A bcc name for a PDDL object name (letters, digits, `_`), new among `taken`."""
    base = re.sub(r"[^A-Za-z0-9_]", "_", name)[:60] or "item"
    if base[0].isdigit():
        base = "i" + base
    out, n = base, 1
    while out in taken:
        out, n = f"{base}_{n}", n + 1
    taken.add(out)
    return out


def item_names(task: Task) -> list:
    taken = {"agent", *task.counts}
    return [identifier(name, taken) for name, _, _ in task.items]


def dungeon_text(task: Task, goal_expr: str, fr: Frame, materials: set, source: str) -> str:
    for at, (name, material) in task.blocks.items():
        if material not in materials:
            raise BccError(f"the block {name} is of {material!r}, which the builder domain does not know",
                           task.paths[1])
    for material in task.counts:
        if material not in materials:
            raise BccError(f"the item type {material!r} is not a material of the builder domain", task.paths[0])
    lines = [f"# {source}", f"dungeon: {identifier(task.name, set())}", "domain: builder",
             "description: A MinePlanner task, imported by `bcc import mineplanner`.",
             f"width: {fr.width}", f"depth: {fr.depth}", f"height: {fr.height}", "blocks: |"]
    rows: dict = {}
    for at, (_, material) in task.blocks.items():
        x, y, z = fr.local(at)
        rows.setdefault((y, z), []).append((x, material))
    for (y, z) in sorted(rows):
        run = sorted(rows[(y, z)])
        start = 0
        for i in range(1, len(run) + 1):
            if i == len(run) or run[i][0] != run[i - 1][0] + 1 or run[i][1] != run[start][1]:
                a, b = run[start][0], run[i - 1][0]
                xs = f"{a}" if a == b else f"{a}..{b}"
                lines.append(f"  {xs} {y} {z} {run[start][1]}")
                start = i
    if task.items:
        lines.append("items:")
        for name, (_, material, at) in zip(item_names(task), task.items):
            x, y, z = fr.local(at)
            lines.append(f"  - {{name: {name}, kind: {material}, at: [{x}, {y}, {z}]}}")
    lines.append("stock:")
    for material in sorted(task.counts):
        lines.append(f"  - {{name: {material}, kind: {material}, count: {task.counts[material]}}}")
    x, y, z = fr.local(task.agent_at)
    lines += ["agent:", f"  start: [{x}, {y}, {z}]", f"goal: {goal_expr}", ""]
    return "\n".join(lines)
