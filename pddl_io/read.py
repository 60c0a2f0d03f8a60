"""Read a PDDL file into nested lists of tokens, with positions (grammar/pddl.lark).

Why s-expressions: PDDL is Lisp-shaped, so the grammar stays small and lifted.py can
say exactly which construct is not supported, at its line and column. Atoms are lark
`Token`s (a `str` with `.line` and `.column`), lowercased (PDDL ignores case);
a list is an `SList`, a `list` that remembers where its "(" was.
"""
from __future__ import annotations

import functools
from pathlib import Path

from ..errors import BccError


class SList(list):
    """A parenthesised PDDL list; `line`/`column` are those of its "(" (1-based)."""
    line = 0
    column = 0


@functools.lru_cache(maxsize=1)
def _parser():
    from lark import Lark, Transformer

    class ToLists(Transformer):
        def start(self, items):
            return items

        def list(self, items):
            out = SList(items[1:])
            out.line, out.column = items[0].line, items[0].column
            return out

    grammar = (Path(__file__).resolve().parent.parent / "grammar" / "pddl.lark").read_text()
    grammar = grammar.replace('list: "(" _item* ")"', 'list: LPAR _item* ")"\nLPAR: "("')
    return Lark(grammar, parser="lalr", transformer=ToLists(), maybe_placeholders=False)


def read_sexpr(path: str) -> list:
    """The top-level lists of a PDDL file, or a BccError at the offending position."""
    from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, UnexpectedToken
    try:
        text = Path(path).read_text(encoding="utf-8", errors="replace")
    except FileNotFoundError:
        raise BccError("no such PDDL file", path) from None
    except OSError as exc:
        raise BccError(f"cannot read PDDL: {exc.strerror or exc}", path) from None
    try:
        return _parser().parse(text.lower())  # PDDL ignores case (there are no strings)
    except UnexpectedCharacters as exc:
        ch = text[exc.pos_in_stream] if exc.pos_in_stream is not None and exc.pos_in_stream < len(text) else "?"
        raise BccError(f"unexpected character {ch!r} in PDDL", path, exc.line, exc.column) from None
    except UnexpectedToken as exc:
        if exc.token.type == "$END":
            line, col = _last_open(text)
            raise BccError("this '(' is never closed", path, line, col) from None
        raise BccError(f"unexpected {exc.token.value!r}: a ')' closes no '('", path, exc.line, exc.column) from None
    except UnexpectedEOF:
        line, col = _last_open(text)
        raise BccError("this '(' is never closed", path, line, col) from None
    except UnexpectedInput as exc:  # any other lark complaint still has a position
        raise BccError("cannot read PDDL", path, getattr(exc, "line", None), getattr(exc, "column", None)) from None


def _last_open(text: str) -> tuple[int, int]:
    """Line and column of the outermost '(' still open at the end of `text`."""
    stack = []
    line, col = 1, 1
    in_comment = False
    for ch in text:
        if in_comment:
            in_comment = ch != "\n"
        elif ch == ";":
            in_comment = True
        elif ch == "(":
            stack.append((line, col))
        elif ch == ")" and stack:
            stack.pop()
        if ch == "\n":
            line, col = line + 1, 1
        else:
            col += 1
    return stack[0] if stack else (line, col)
