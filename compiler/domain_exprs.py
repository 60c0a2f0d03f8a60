"""Expressions read out of YAML: the text at a key parsed (conditions, effects), a list
of them joined into one text whose every character keeps its place in the file.

Apart from the loader (domain.py) because the dungeon loader and the task loader read
expressions the same way.
"""
from __future__ import annotations

from ..errors import BccError
from .definitions import Expr
from .source import YList, YMap, error_at, origin, Origin


def expression(container, key, effects: bool = False) -> Expr:
    text = scalar_text(container, key)   # `pre: true` in YAML is a bool, not the text "true"
    where = origin(container, key)
    from .parse import parse_effects, parse_expression   # lark: imported only when text is parsed
    node = parse_effects(text, where) if effects else parse_expression(text, where)
    return Expr(node, where, text)


def condition(container, key) -> Expr:
    """A condition (a goal, a failure) written as one expression or, as `pre` may be, as a
    list of expressions that must all hold."""
    if not isinstance(container[key], YList):
        return expression(container, key)
    return joined(container, key, " and ", effects=False)


def joined(container, key, separator: str, effects: bool) -> Expr:
    """A YAML list of expressions (each in parentheses, for conditions) or of effects, parsed
    as one text joined by `separator`, whose every character keeps its place in the file:
    an error in the third item points into the third item."""
    items = container[key]
    if not items:
        raise error_at(container, key, f"`{key}` is an empty list: leave the key out instead")
    text, positions, parts = "", [], []
    for i in range(len(items)):
        part = scalar_text(items, i)
        where = origin(items, i)
        parts.append((part, where))
        start = where.locate(1, 1)
        if i:
            text += separator
            positions += [start] * len(separator)
        opening, closing = ("", "") if effects else ("(", ")")
        text += opening + part + closing
        positions += [start] * len(opening)
        line, col = 1, 1
        for ch in part:
            positions.append(where.locate(line, col))
            line, col = (line + 1, 1) if ch == "\n" else (line, col + 1)
        positions += [where.locate(line, col)] * len(closing)
    from .parse import parse_effects, parse_expression   # lark: imported only when text is parsed
    parse = parse_effects if effects else parse_expression
    first = origin(container, key)
    combined = Origin(first.path, first.line, first.col, 1, tuple(positions), text)
    try:
        node = parse(text, combined)
    except BccError:
        for part, where in parts:   # report the error as in the first bad item alone, not the joining's
            parse(part, where)
        raise
    return Expr(node, combined, text)


def scalar_text(container, key) -> str:
    """An expression's text as YAML gave it (`pre: true` is a bool, `cost: 1` an int); a
    list or a mapping where an expression belongs is bad input."""
    value = container[key]
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if not isinstance(value, str):
        kind = ("a list" if isinstance(value, YList) else "a mapping" if isinstance(value, YMap)
                else "nothing" if value is None else f"the number {value!r}" if isinstance(value, float)
                else f"a {type(value).__name__}")
        raise error_at(container, key, f"expected an expression as text, found {kind}")
    return value
