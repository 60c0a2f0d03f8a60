"""Syntax trees of the expression language, as parsed (names not yet resolved).

Every node carries `pos`, its (line, col) inside the source text; positions never take
part in equality, so two spellings of the same expression compare equal.
"""
from __future__ import annotations

from dataclasses import dataclass, field

Pos = tuple[int, int]


def _pos() -> Pos:
    return field(default=(1, 1), compare=False, repr=False)


@dataclass(frozen=True)
class Node:
    pass


# ---- expressions -------------------------------------------------------------------
@dataclass(frozen=True)
class Int(Node):
    value: int
    pos: Pos = _pos()


@dataclass(frozen=True)
class Bool(Node):
    value: bool
    pos: Pos = _pos()


@dataclass(frozen=True)
class Name(Node):
    name: str
    pos: Pos = _pos()


@dataclass(frozen=True)
class Attr(Node):
    obj: Node
    name: str
    pos: Pos = _pos()


@dataclass(frozen=True)
class Index(Node):
    obj: Node
    args: tuple[Node, ...]
    pos: Pos = _pos()


@dataclass(frozen=True)
class Call(Node):
    func: str
    args: tuple[Node, ...]
    pos: Pos = _pos()


@dataclass(frozen=True)
class Neg(Node):
    operand: Node
    pos: Pos = _pos()


@dataclass(frozen=True)
class BinOp(Node):
    op: str  # + - * // %
    left: Node
    right: Node
    pos: Pos = _pos()


@dataclass(frozen=True)
class Compare(Node):
    """A chain `a < b <= c`, meaning `a < b and b <= c` (as in Python)."""
    operands: tuple[Node, ...]
    ops: tuple[str, ...]
    pos: Pos = _pos()


@dataclass(frozen=True)
class And(Node):
    left: Node
    right: Node
    pos: Pos = _pos()


@dataclass(frozen=True)
class Or(Node):
    left: Node
    right: Node
    pos: Pos = _pos()


@dataclass(frozen=True)
class Not(Node):
    operand: Node
    pos: Pos = _pos()


@dataclass(frozen=True)
class Quantifier(Node):
    kind: str  # "exists" | "forall"
    var: str
    cls: str
    body: Node
    pos: Pos = _pos()


# ---- effects -----------------------------------------------------------------------
@dataclass(frozen=True)
class Assign(Node):
    target: Node
    value: Node
    pos: Pos = _pos()


@dataclass(frozen=True)
class If(Node):
    """`if c {..} elif c2 {..} else {..}`: branches is a tuple of (condition, effects)."""
    branches: tuple[tuple[Node, tuple[Node, ...]], ...]
    orelse: tuple[Node, ...]
    pos: Pos = _pos()


@dataclass(frozen=True)
class First(Node):
    """`first v: C where cond {..} else {..}`: the first object of C (in declaration or key
    order) satisfying cond gets the effects; if none does, the else branch applies."""
    var: str
    cls: str
    cond: Node
    body: tuple[Node, ...]
    orelse: tuple[Node, ...]
    pos: Pos = _pos()


@dataclass(frozen=True)
class ForEach(Node):
    """`forall v: C where cond {..}`: the effects apply to every object satisfying cond."""
    var: str
    cls: str
    cond: Node | None
    body: tuple[Node, ...]
    pos: Pos = _pos()


@dataclass(frozen=True)
class Add(Node):
    """`add block[x, y, z] {blockType = t}`: create an object of a keyed class."""
    target: Node
    inits: tuple[tuple[str, Node], ...]
    pos: Pos = _pos()


@dataclass(frozen=True)
class Remove(Node):
    """`remove block[x, y, z]`: delete an object of a keyed class (its cell becomes empty)."""
    target: Node
    pos: Pos = _pos()


def conjuncts(node: Node) -> list[Node]:
    """Split `a and b and c` into [a, b, c]."""
    if isinstance(node, And):
        return conjuncts(node.left) + conjuncts(node.right)
    return [node]
