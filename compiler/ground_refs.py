"""What a name in an expression can stand for besides an IR value -- a named object, a
keyed object, a class, a table -- and the scope names are looked up in (`Ctx`).

Kept apart from ground.py because both halves of grounding (expressions there, effects in
ground_effects.py) and the back end's hierarchy compiler build and match these values.
"""
from __future__ import annotations

from dataclasses import dataclass

from ..errors import BccError
from .definitions import Expr


@dataclass(frozen=True)
class ObjRef:
    """A named object (`agent`, the room `red`)."""
    name: str
    cls: str


@dataclass(frozen=True)
class KeyRef:
    """An object of a keyed class, by key: `block[x, y, z]`, `inventoryBlock[slot]`."""
    cls: str
    keys: tuple


@dataclass(frozen=True)
class ClassName:
    name: str


@dataclass(frozen=True)
class Table:
    """A table indexed by `[...]`: a list constant (`dx[d]`, indexed by an int), or a table
    property of an enumeration value (`r.uses[m]`, indexed by a value of its `per` type).
    With `row` (a run-time enumeration value), `values` holds every value's row, one after
    another, each `width` long."""
    name: str
    values: tuple
    index_type: str = "int"
    value_type: str = "int"
    row: object = None
    width: int = 0


class Ctx:
    """Names in scope, and the text being checked (for error positions)."""

    def __init__(self, src: Expr, env: dict | None = None, stack: tuple = ()):
        self.src, self.env, self.stack = src, dict(env or {}), stack

    def bind(self, **names) -> "Ctx":
        return Ctx(self.src, {**self.env, **names}, self.stack)

    def error(self, node, message: str) -> BccError:
        return self.src.error(message, node)
