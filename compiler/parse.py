"""Text -> syntax tree, with lark (LALR) and the grammar in grammar/expressions.lark.

Syntax errors become one-line BccErrors that say what was expected and what was found,
positioned in the file the text came from (via an `Origin`).
"""
from __future__ import annotations

from functools import lru_cache

from lark import Lark, Token, Transformer, v_args
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, UnexpectedToken, VisitError

from ..errors import BccError
from ..grammar import GRAMMAR_FILE
from . import ast
from .source import Origin

# Spellings of the grammar's anonymous terminals, so errors never say "LPAR" or "__ANON_0".
_SPELLING = {
    "LPAR": "'('", "RPAR": "')'", "LSQB": "'['", "RSQB": "']'", "LBRACE": "'{'", "RBRACE": "'}'",
    "COMMA": "','", "DOT": "'.'", "COLON": "':'", "SEMICOLON": "';'", "EQUAL": "'='",
    "MINUS": "'-'", "CMP_OP": "a comparison", "ADD_OP": "'+' or '-'", "MUL_OP": "'*', '//' or '%'",
    "NAME": "a name", "INT": "a number", "$END": "the end of the text", "_IN": "'in' or ':'",
}


@lru_cache(maxsize=1)
def _parser() -> Lark:
    return Lark(GRAMMAR_FILE.read_text(encoding="utf-8"), start=["start_expr", "start_effects"],
                parser="lalr", propagate_positions=True, maybe_placeholders=True,
                cache=True)  # lark keys its cache on the grammar text: a changed grammar rebuilds


def _spell(terminal: str) -> str:
    if terminal in _SPELLING:
        return _SPELLING[terminal]
    pattern = _parser().get_terminal(terminal).pattern
    return repr(pattern.value) if pattern.type == "str" else terminal.lower()


def _pos(meta_or_token) -> ast.Pos:
    return (getattr(meta_or_token, "line", 1) or 1, getattr(meta_or_token, "column", 1) or 1)


@v_args(meta=True, inline=True)
class _ToAst(Transformer):
    def start_expr(self, meta, e):
        return e

    def start_effects(self, meta, effs):
        return effs

    # expressions
    def int(self, meta, tok):
        return ast.Int(int(tok), _pos(tok))

    def true(self, meta):
        return ast.Bool(True, _pos(meta))

    def false(self, meta):
        return ast.Bool(False, _pos(meta))

    def name(self, meta, tok):
        return ast.Name(str(tok), _pos(tok))

    def attr(self, meta, obj, name):
        return ast.Attr(obj, str(name), _pos(name))

    def index(self, meta, obj, args):
        return ast.Index(obj, args, _pos(meta))

    def call(self, meta, name, args):
        return ast.Call(str(name), args or (), _pos(name))

    def args(self, meta, *items):
        return tuple(items)

    def neg(self, meta, operand):
        return ast.Neg(operand, _pos(meta))

    def binop(self, meta, left, op, right):
        return ast.BinOp(str(op), left, right, _pos(op))

    def compare(self, meta, *items):
        return ast.Compare(tuple(items[0::2]), tuple(str(t) for t in items[1::2]), _pos(items[1]))

    def and_(self, meta, left, right):
        return ast.And(left, right, _pos(meta))

    def or_(self, meta, left, right):
        return ast.Or(left, right, _pos(meta))

    def not_(self, meta, operand):
        return ast.Not(operand, _pos(meta))

    def exists(self, meta, var, cls, body):
        return ast.Quantifier("exists", str(var), str(cls), body, _pos(meta))

    def forall(self, meta, var, cls, body):
        return ast.Quantifier("forall", str(var), str(cls), body, _pos(meta))

    # effects
    def effects(self, meta, *items):
        return tuple(items)

    def block(self, meta, effs):
        return effs

    def assign(self, meta, target, value):
        return ast.Assign(target, value, _pos(meta))

    def elif_(self, meta, cond, body):
        return (cond, body)

    def if_(self, meta, cond, body, *rest):
        *elifs, orelse = rest
        return ast.If(((cond, body),) + tuple(elifs), orelse or (), _pos(meta))

    def first(self, meta, var, cls, cond, body, orelse):
        return ast.First(str(var), str(cls), cond, body, orelse or (), _pos(meta))

    def foreach(self, meta, var, cls, cond, body):
        return ast.ForEach(str(var), str(cls), cond, body, _pos(meta))

    def add(self, meta, target, *inits):
        return ast.Add(target, tuple(i for i in inits if i is not None), _pos(meta))

    def init(self, meta, name, value):
        return (str(name), value)

    def remove(self, meta, target):
        return ast.Remove(target, _pos(meta))


# lark names the rule `elif`, a Python keyword: route it to `elif_`.
setattr(_ToAst, "elif", _ToAst.elif_)


def parse_expression(text: str, where: Origin) -> ast.Node:
    return _parse(text, "start_expr", where)


def parse_effects(text: str, where: Origin) -> tuple[ast.Node, ...]:
    return _parse(text, "start_effects", where)


def _parse(text: str, start: str, where: Origin):
    if not isinstance(text, str):
        raise where.error(f"expected an expression as text, found {type(text).__name__} {text!r}")
    if not text.strip():
        raise where.error("empty expression")
    try:
        tree = _parser().parse(text, start=start)
        return _ToAst().transform(tree)
    except UnexpectedInput as exc:
        raise _syntax_error(exc, text, where) from None
    except VisitError as exc:  # pragma: no cover - the transformer raises nothing itself
        raise where.error(f"cannot read expression: {exc.orig_exc}") from None


def _syntax_error(exc: UnexpectedInput, text: str, where: Origin) -> BccError:
    # `accepts` (lark >= 1.0) is what the parser can really take here; `expected` may list
    # tokens of states reached only by default reductions.
    names = getattr(exc, "accepts", None) or getattr(exc, "expected", None) or getattr(exc, "allowed", None) or ()
    expected = sorted({_spell(t) for t in names})
    want = f"; expected {', '.join(expected[:6])}{' ...' if len(expected) > 6 else ''}" if expected else ""
    if isinstance(exc, UnexpectedToken) and exc.token.type == "$END" or isinstance(exc, UnexpectedEOF):
        lines = text.rstrip().splitlines() or [""]
        return where.error(f"syntax error: the expression ends too early{want}",
                           len(lines), len(lines[-1]) + 1)
    if isinstance(exc, UnexpectedToken):
        tok: Token = exc.token
        return where.error(f"syntax error: unexpected {str(tok)!r}{want}", tok.line, tok.column)
    if isinstance(exc, UnexpectedCharacters):
        return where.error(f"syntax error: unexpected character {text[exc.pos_in_stream]!r}{want}",
                           exc.line, exc.column)
    return where.error(f"syntax error: {exc}")
