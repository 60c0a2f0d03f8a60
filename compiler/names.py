"""The one rule for names a domain or dungeon file gives, and for text bcc prints back.

Names (types, values, classes, attributes, functions, actions, parameters, lets, objects,
rooms, list items, dungeons) become action names, JSON keys and words on a terminal, so
they are checked once, here, when a file is loaded: an ASCII identifier of at most
`MAX_NAME` characters. Generated code never contains them (see `emit.py`); this rule is
the second wall. Free text (a description) may hold any printable character, but no
control characters or terminal escapes.
"""
from __future__ import annotations

import re

from ..errors import CONTROL

MAX_NAME = 64
IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")


def name_problem(value) -> str | None:
    """Why `value` is not a valid name, or None when it is."""
    if not isinstance(value, str):
        return f"must be a name (letters, digits and _), found {_shown(value)}"
    if len(value) > MAX_NAME:
        return f"is {len(value)} characters long; names have at most {MAX_NAME}"
    if not IDENTIFIER.match(value):
        return f"must be letters, digits and _ (not starting with a digit), found {_shown(value)}"
    return None


def check_name(container, key, value, what: str, on_key: bool = False) -> str:
    """`value` (found at container[key]) if it is a valid name; else a BccError at its position."""
    problem = name_problem(value)
    if problem is not None:
        from .source import error_at
        raise error_at(container, key, f"{what} {problem}", on_key=on_key)
    return value


def name_from_stem(stem: str) -> str:
    """A dungeon's name when its file gives none: the file name's stem, made a valid name
    (`my-maze` -> `my_maze`)."""
    name = re.sub(r"[^A-Za-z0-9_]", "_", stem)[:MAX_NAME] or "dungeon"
    return name if not name[0].isdigit() else "_" + name[:MAX_NAME - 1]


def text_problem(value: str) -> str | None:
    """Why free text cannot be printed safely (control characters, lone surrogates), or None."""
    bad = CONTROL.search(value)
    if bad is None:
        return None
    return f"contains the control character {bad.group()!r} (at character {bad.start() + 1})"


def check_text(container, key, value, what: str) -> str:
    """Free text (descriptions, titles) without control characters, tabs and newlines allowed."""
    if not isinstance(value, str):
        from .source import error_at
        raise error_at(container, key, f"{what} must be text")
    problem = text_problem(value)
    if problem is not None:
        from .source import error_at
        raise error_at(container, key, f"{what} {problem}")
    return value


def _shown(value) -> str:
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."
