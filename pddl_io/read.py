"""Read a PDDL file into nested lists of tokens, with positions (grammar/pddl.lark).

Why s-expressions: PDDL is Lisp-shaped, so the grammar stays small and lifted.py can
say exactly which construct is not supported, at its line and column. Atoms are `Atom`s
(a `str` with the grammar's terminal name as `.type`, and `.line` and `.column`, as
lark's tokens have), lowercased (PDDL ignores case); a list is an `SList`, a `list`
that remembers where its "(" was.

Why two readers of one grammar: importing lark costs about 50 ms of CPU, a third of a
small `bcc import pddl`. A file the grammar accepts is read by `_scan`, one regular
expression made of the grammar's own terminals (read from grammar/pddl.lark, in lark's
order: higher priority first) and a stack of open lists. Anything `_scan` cannot read
(an unexpected character, an unbalanced parenthesis) goes to lark's parser of the same
grammar, which is the authority: it says what is wrong and where. A property test checks
that the two agree on random text.
"""
from __future__ import annotations

import functools
import re
from pathlib import Path

from ..errors import BccError

GRAMMAR = Path(__file__).resolve().parent.parent / "grammar" / "pddl.lark"
WS = r"[ \t\f\r\n]+"     # lark's common.WS, which the grammar imports and ignores


class SList(list):
    """A parenthesised PDDL list; `line`/`column` are those of its "(" (1-based)."""
    line = 0
    column = 0


class Atom(str):
    """A PDDL atom: its terminal (`type`: NAME, VARIABLE, KEYWORD, NUMBER) and position."""
    __slots__ = ("type", "line", "column")


def _terminals(grammar: str) -> tuple[list, set]:
    """(name, priority, regex) of the grammar's named terminals in lark's lexing order
    (priority first; the grammar's terminals of equal priority never start alike), and
    the names it ignores."""
    terminals = []
    for m in re.finditer(r"^([A-Z]+)(?:\.(\d+))?:(.*)$", grammar, re.M):
        alternatives = re.findall(r"/((?:[^/\\\n]|\\.)*)/", m[3])
        terminals.append((m[1], int(m[2] or 0), "|".join(f"(?:{a})" for a in alternatives)))
    terminals.sort(key=lambda t: -t[1])
    ignored = set(re.findall(r"^%ignore\s+([A-Z]+)", grammar, re.M))
    return terminals, ignored


@functools.lru_cache(maxsize=4)
def _scanner(grammar_path: Path = GRAMMAR):
    terminals, ignored = _terminals(grammar_path.read_text())
    parts = [f"(?P<WS>{WS})", r"(?P<LPAR>\()", r"(?P<RPAR>\))"]
    parts += [f"(?P<{name}>{regex})" for name, _, regex in terminals]
    return re.compile("|".join(parts)).match, ignored | {"WS"}


def _scan(text: str, grammar_path: Path = GRAMMAR) -> list | None:
    """The top-level items of `text`, or None where lark must say what is wrong."""
    match, ignored = _scanner(grammar_path)
    top: list = []
    stack: list = []
    items = top
    pos, end, line, line_start = 0, len(text), 1, 0
    while pos < end:
        m = match(text, pos)
        if m is None:
            return None
        kind, tok = m.lastgroup, m[0]
        if kind == "LPAR":
            lst = SList()
            lst.line, lst.column = line, pos - line_start + 1
            items.append(lst)
            stack.append(items)
            items = lst
        elif kind == "RPAR":
            if not stack:
                return None
            items = stack.pop()
        elif kind in ignored:
            newlines = tok.count("\n")
            if newlines:
                line += newlines
                line_start = pos + tok.rindex("\n") + 1
        else:
            atom = Atom(tok)
            atom.type, atom.line, atom.column = kind, line, pos - line_start + 1
            items.append(atom)
        pos = m.end()
    return None if stack else top


@functools.lru_cache(maxsize=4)
def _parser(grammar_path: Path = GRAMMAR):
    from lark import Lark, Transformer

    class ToLists(Transformer):
        def start(self, items):
            return items

        def list(self, items):
            out = SList(items[1:])
            out.line, out.column = items[0].line, items[0].column
            return out

    grammar = grammar_path.read_text()
    grammar = grammar.replace('list: "(" _item* ")"', 'list: LPAR _item* ")"\nLPAR: "("')
    tables = _cached_tables(grammar)
    if tables is not None:
        try:
            return Lark._load_from_dict(tables["data"], tables["memo"], transformer=ToLists())
        except Exception:  # noqa: BLE001 - a stale or damaged entry: build the tables again
            pass
    parser = Lark(grammar, parser="lalr", maybe_placeholders=False)
    _save_tables(grammar, parser)
    return Lark(grammar, parser="lalr", transformer=ToLists(), maybe_placeholders=False)


def _tables_path(grammar: str) -> Path | None:
    """Where the parser tables of `grammar` are cached: the user's bcc cache folder
    (compiler/cache.py: BCC_CACHE_DIR, BCC_NO_CACHE), keyed by grammar, lark and Python."""
    import hashlib
    import sys

    import lark

    from ..compiler.cache import cache_dir
    folder = cache_dir()
    if folder is None:
        return None
    key = hashlib.sha256(f"{grammar}|{lark.__version__}|{sys.version_info[:2]}".encode()).hexdigest()[:32]
    return folder / f"pddl-parser-{key}.txt"


def _cached_tables(grammar: str) -> dict | None:
    """Building lark's LALR tables takes 60 ms, most of a small import; reading them back,
    5 ms. The entry is a Python literal read by `ast.literal_eval`: a tampered file can
    be refused, never run (unlike lark's own pickle cache)."""
    import ast
    path = _tables_path(grammar)
    if path is None:
        return None
    try:
        tables = ast.literal_eval(path.read_text(encoding="utf-8"))
    except Exception:  # noqa: BLE001 - missing, unreadable or damaged: a miss
        return None
    return tables if isinstance(tables, dict) and {"data", "memo"} <= tables.keys() else None


def _save_tables(grammar: str, parser) -> None:
    from lark.grammar import Rule
    from lark.lexer import TerminalDef
    path = _tables_path(grammar)
    if path is None:
        return
    try:
        data, memo = parser.memo_serialize([TerminalDef, Rule])
        from ..atomic import write_text
        path.parent.mkdir(parents=True, exist_ok=True)
        write_text(path, repr({"data": data, "memo": memo}))
    except Exception:  # noqa: BLE001 - no cache (read-only home, full disk): only slower
        pass


def read_sexpr(path: str, grammar_path: Path = GRAMMAR, language: str = "PDDL") -> list:
    """The top-level lists of a PDDL file, or a BccError at the offending position. HDDL,
    lexically PDDL, is read by the same reader with its own grammar (grammar/hddl.lark)."""
    try:
        text = Path(path).read_text(encoding="utf-8", errors="replace")
    except FileNotFoundError:
        raise BccError(f"no such {language} file", path) from None
    except OSError as exc:
        raise BccError(f"cannot read {language}: {exc.strerror or exc}", path) from None
    lowered = text.lower()   # PDDL ignores case (there are no strings)
    items = _scan(lowered, grammar_path)
    return items if items is not None else parse_with_lark(text, path, grammar_path, language)


def parse_with_lark(text: str, path: str, grammar_path: Path = GRAMMAR, language: str = "PDDL") -> list:
    """lark's reading of `text` (the grammar's authority), or its complaint as a BccError."""
    from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, UnexpectedToken
    try:
        return _parser(grammar_path).parse(text.lower())
    except UnexpectedCharacters as exc:
        ch = text[exc.pos_in_stream] if exc.pos_in_stream is not None and exc.pos_in_stream < len(text) else "?"
        raise BccError(f"unexpected character {ch!r} in {language}", path, exc.line, exc.column) from None
    except UnexpectedToken as exc:
        if exc.token.type == "$END":
            line, col = _last_open(text)
            raise BccError("this '(' is never closed", path, line, col) from None
        early = _early_close(text)
        if early:
            raise BccError("this ')' closes the file's first list, but more text follows: one ')' too many "
                           "before it", path, *early) from None
        raise BccError(f"unexpected {exc.token.value!r}: a ')' closes no '('", path, exc.line, exc.column) from None
    except UnexpectedEOF:
        line, col = _last_open(text)
        raise BccError("this '(' is never closed", path, line, col) from None
    except UnexpectedInput as exc:  # any other lark complaint still has a position
        raise BccError(f"cannot read {language}", path, getattr(exc, "line", None), getattr(exc, "column", None)) \
            from None


ACTION_PARTS = {":parameters", ":precondition", ":effect"}
SECTIONS = {":action", ":durative-action", ":derived", ":predicates", ":functions", ":types", ":constants",
            ":requirements", ":objects", ":init", ":goal", ":metric", ":domain"}


def _early_close(text: str) -> tuple[int, int] | None:
    """The ')' that closes the first top-level list when lists still follow it."""
    import re
    depth, closed_at = 0, None
    for m in re.finditer(r";[^\n]*|\(|\)", text):
        tok = m.group()
        if tok == "(":
            if closed_at is not None:
                return closed_at
            depth += 1
        elif tok == ")":
            depth -= 1
            if depth == 0 and closed_at is None:
                line = text.count("\n", 0, m.start()) + 1
                closed_at = (line, m.start() - (text.rfind("\n", 0, m.start()) + 1) + 1)
    return None


def _last_open(text: str) -> tuple[int, int]:
    """Where a ')' is missing: the '(' still open when a section or an action's part
    (`:effect`) starts inside it, else the innermost '(' open at the end of `text`."""
    import re
    stack: list = []         # [line, column, head] of each open list
    expect_head = False
    for m in re.finditer(r";[^\n]*|\(|\)|[^\s()]+|\n", text):
        tok = m.group()
        if tok[0] == ";" or tok == "\n":
            continue
        line = text.count("\n", 0, m.start()) + 1
        col = m.start() - (text.rfind("\n", 0, m.start()) + 1) + 1
        if tok == "(":
            stack.append([line, col, None])
            expect_head = True
            continue
        if tok == ")":
            if stack:
                stack.pop()
            expect_head = False
            continue
        tok = tok.lower()
        if expect_head:
            stack[-1][2] = tok
            expect_head = False
            if tok in SECTIONS and len(stack) > 2:
                return tuple(stack[-2][:2])
        elif tok in ACTION_PARTS and stack and stack[-1][2] not in (":action", ":durative-action"):
            return tuple(stack[-1][:2])
    return tuple(stack[-1][:2]) if stack else (1, 1)
