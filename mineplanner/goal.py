"""MinePlanner's goal (the precondition of its `checkgoal` action) as a bcc goal expression.

What it says: the agent stands at a position (`at-x ?ag P` ...), holds counts
(`agent-has-n-T ?ag countK`, an `or` over K >= k becomes `T.count >= k`), or a block of a
material stands at a position (`exists (?b - T-block) (and (block-present ?b) (at-x ?b X)
...)` becomes `block[x, y, z].kind == T`), joined by `and`, `or`, `not`. Anything else is
refused at its place in the domain file.
"""
from __future__ import annotations

from ..errors import BccError
from .task import Task
from .world import Frame

HAS = "agent-has-n-"
AXES = {"at-x": 0, "at-y": 1, "at-z": 2}


class _Reader:
    def __init__(self, task: Task):
        self.task = task
        self.path = task.paths[0]
        self.pos = {p: i for i, p in enumerate(task.positions)}
        self.count = {c: i for i, c in enumerate(task.count_objects)}

    def error(self, node, message: str) -> BccError:
        return BccError(message, self.path, getattr(node, "line", 0) or None, getattr(node, "column", 0) or None)

    def position(self, atom) -> int:
        if atom not in self.pos:
            raise self.error(atom, f"{atom} is not a position of the problem")
        return self.pos[atom]

    def block_cell(self, node) -> tuple:
        """(material or None for any block, (x, y, z)) of an `exists` over one block."""
        params, body = node[1], node[2]
        if len(params) != 3 or params[1] != "-" or not isinstance(body, list) or body[:1] != ["and"]:
            raise self.error(node, "`exists` in checkgoal is supported over one block: "
                                   "(exists (?b - T-block) (and (block-present ?b) (at-x ?b X) (at-y ?b Y) (at-z ?b Z)))")
        var, btype = params[0], params[2]
        material = None if btype == "block" else self.task.block_types.get(btype)
        if btype != "block" and material is None:
            raise self.error(btype, f"{btype} is not a block type of the task")
        at = [None] * 3
        for part in body[1:]:
            if part[:2] == ["block-present", var]:
                continue
            if isinstance(part, list) and len(part) == 3 and part[0] in AXES and part[1] == var:
                at[AXES[part[0]]] = self.position(part[2])
                continue
            raise self.error(part, "only `block-present` and `at-x/y/z` of the block are supported here")
        if None in at:
            raise self.error(node, "the block's x, y and z must all be given")
        return material, tuple(at)

    def cells(self, node, out: list) -> list:
        if isinstance(node, list) and node[:1] == ["exists"]:
            out.append(self.block_cell(node)[1])
        elif isinstance(node, list):
            for part in node[1:]:
                self.cells(part, out)
        return out

    def expr(self, node, fr: Frame) -> str:
        if not isinstance(node, list) or not node:
            raise self.error(node, f"unexpected {node!r} in checkgoal")
        head = node[0]
        if head == "and":
            parts = [self.expr(p, fr) for p in node[1:]]
            parts = [p for p in parts if p != "true"]
            return " and ".join(f"({p})" if " or " in p else p for p in parts) or "true"
        if head == "or":
            counts = self.count_range(node)
            if counts is not None:
                return counts
            return " or ".join(f"({self.expr(p, fr)})" for p in node[1:]) or "false"
        if head == "not" and len(node) == 2:
            return f"not ({self.expr(node[1], fr)})"
        if head == "agent-alive":
            return "true"
        if head in AXES and len(node) == 3 and node[1] == "?ag":
            axis = AXES[head]
            value = self.position(node[2]) - (fr.x0, fr.y0, fr.z0)[axis]
            return f"agent.{'xyz'[axis]} == {value}" if value >= 0 else "false"
        if isinstance(head, str) and head.startswith(HAS) and len(node) == 3:
            material = self.material(node)
            return f"{material}.count == {self.count[node[2]]}"
        if head == "exists":
            material, at = self.block_cell(node)
            x, y, z = fr.local(at)
            return f"block[{x}, {y}, {z}].kind " + (f"== {material}" if material else "!= air")
        raise self.error(node, f"`{head}` is not supported in checkgoal by the importer")

    def material(self, node) -> str:
        material = node[0][len(HAS):]
        if material not in self.task.counts:
            raise self.error(node[0], f"{node[0]}: {material} is not an item type of the task")
        if node[2] not in self.count:
            raise self.error(node[2], f"{node[2]} is not a count of the problem")
        return material

    def count_range(self, node) -> str | None:
        """`T.count >= k` for an `or` of `agent-has-n-T` over every count from k up (`k <= T.count <= m`
        to m)."""
        parts = node[1:]
        if not parts or not all(isinstance(p, list) and len(p) == 3 and isinstance(p[0], str)
                                and p[0].startswith(HAS) for p in parts):
            return None
        materials = {self.material(p) for p in parts}
        if len(materials) != 1:
            return None
        values = sorted({self.count[p[2]] for p in parts})
        material = materials.pop()
        if values == list(range(values[0], len(self.count))):
            return f"{material}.count >= {values[0]}"
        if values == list(range(values[0], values[-1] + 1)):
            return f"{values[0]} <= {material}.count <= {values[-1]}"
        return f"{material}.count in [{', '.join(map(str, values))}]"


def goal_cells(task: Task) -> list:
    """The cells (task coordinates) the goal names, which the world must contain."""
    return _Reader(task).cells(task.goal, [])


def goal_expression(task: Task, fr: Frame) -> str:
    return _Reader(task).expr(task.goal, fr)
