"""Text -> syntax tree, with lark (LALR) and the grammar in grammar/expressions.lark.

Syntax errors become one-line BccErrors that say what was expected and what was found,
positioned in the file the text came from (via an `Origin`).

The tree becomes an AST without recursion (`_build`), so no text can exhaust Python's
stack here: chains of one associative operator (`a and b and ...`, `x + y + ...`) become
balanced trees, and any other nesting deeper than `MAX_EXPRESSION_DEPTH` is bad input.
"""
from __future__ import annotations

import re
from functools import lru_cache

from lark import Lark, Token, Tree
from lark.lark import PostLex
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, UnexpectedToken

from ..errors import BccError
from ..grammar import GRAMMAR_FILE
from . import ast
from .limits import MAX_EXPRESSION_DEPTH, int_error, number_error, shorten
from .names import MAX_NAME
from .source import Origin

# Spellings of the grammar's anonymous terminals, so errors never say "LPAR" or "__ANON_0".
_SPELLING = {
    "LPAR": "'('", "RPAR": "')'", "LSQB": "'['", "RSQB": "']'", "LBRACE": "'{'", "RBRACE": "'}'",
    "COMMA": "','", "DOT": "'.'", "COLON": "':'", "SEMICOLON": "';'", "EQUAL": "'='",
    "MINUS": "'-'", "CMP_OP": "a comparison", "ADD_OP": "'+' or '-'", "MUL_OP": "'*', '//' or '%'",
    "AUG_OP": "'+=', '-=', '*=', '//=' or '%='",
    "NAME": "a name", "INT": "a number", "$END": "the end of the text",
}


class _WholeWords(PostLex):
    """Names are lexed in every parser state, so a word is never split at a keyword it
    starts with: after `v.traded = true` and a line break, `inventoryBlock` is one name
    (an unexpected one, so the line break ends the effect), not the keyword `in` and
    `ventoryBlock`."""
    always_accept = ("NAME",)

    def process(self, stream):
        return stream


@lru_cache(maxsize=1)
def _parser() -> Lark:
    return Lark(GRAMMAR_FILE.read_text(encoding="utf-8"), start=["start_expr", "start_effects"],
                parser="lalr", propagate_positions=True, maybe_placeholders=True, postlex=_WholeWords(),
                cache=True)  # lark keys its cache on the grammar text: a changed grammar rebuilds


def _spell(terminal: str) -> str:
    if terminal in _SPELLING:
        return _SPELLING[terminal]
    pattern = _parser().get_terminal(terminal).pattern
    return repr(pattern.value) if pattern.type == "str" else terminal.lower()


def _pos(meta_or_token) -> ast.Pos:
    return (getattr(meta_or_token, "line", 1) or 1, getattr(meta_or_token, "column", 1) or 1)


class _ToAst:
    """One method per grammar rule (or alias): (meta, *children) -> AST node."""

    def start_expr(self, meta, e):
        return e

    def start_effects(self, meta, effs):
        return effs

    # expressions
    def int(self, meta, tok):
        problem = number_error(str(tok)) or int_error(int(tok))
        if problem:
            raise _Refused(problem, _pos(tok))
        return ast.Int(int(tok), _pos(tok))

    def true(self, meta):
        return ast.Bool(True, _pos(meta))

    def false(self, meta):
        return ast.Bool(False, _pos(meta))

    def name(self, meta, tok):
        return ast.Name(_name(tok), _pos(tok))

    def attr(self, meta, obj, name):
        return ast.Attr(obj, _name(name), _pos(name))

    def index(self, meta, obj, args):
        return ast.Index(obj, args, _pos(meta))

    def call(self, meta, name, args):
        return ast.Call(_name(name), args or (), _pos(name))

    def args(self, meta, *items):
        return tuple(items)

    def neg(self, meta, operand):
        return ast.Neg(operand, _pos(meta))

    def binop(self, meta, left, op, right):
        return ast.BinOp(str(op), left, right, _pos(op))

    def compare(self, meta, *items):
        return ast.Compare(tuple(items[0::2]), tuple(str(t) for t in items[1::2]), _pos(items[1]))

    def member(self, meta, value, choices):
        """`x in [a, b]`: `x == a or x == b` (x is an expression without effects, so reading
        it once per choice changes nothing); a long list becomes a balanced tree."""
        tests = [ast.Compare((value, c), ("==",), c.pos) for c in choices]
        return _balanced("or_", tests, [None] * (len(tests) - 1))

    def not_member(self, meta, value, choices):
        """`x not in [a, b]`: `x != a and x != b`."""
        tests = [ast.Compare((value, c), ("!=",), c.pos) for c in choices]
        return _balanced("and_", tests, [None] * (len(tests) - 1))

    def and_(self, meta, left, right):
        return ast.And(left, right, _pos(meta))

    def or_(self, meta, left, right):
        return ast.Or(left, right, _pos(meta))

    def not_(self, meta, operand):
        return ast.Not(operand, _pos(meta))

    def exists(self, meta, var, cls, body):
        return ast.Quantifier("exists", _name(var), _name(cls), body, _pos(meta))

    def forall(self, meta, var, cls, body):
        return ast.Quantifier("forall", _name(var), _name(cls), body, _pos(meta))

    # effects
    def effects(self, meta, *items):
        return tuple(items)

    def block(self, meta, effs):
        return effs

    def assign(self, meta, target, value):
        return ast.Assign(target, value, _pos(meta))

    def augassign(self, meta, target, op, value):
        return ast.Assign(target, ast.BinOp(str(op)[:-1], target, value, _pos(op)), _pos(meta))

    def elif_(self, meta, cond, body):
        return (cond, body)

    def if_(self, meta, cond, body, *rest):
        *elifs, orelse = rest
        return ast.If(((cond, body),) + tuple(elifs), orelse or (), _pos(meta))

    def first(self, meta, var, cls, cond, body, orelse):
        return ast.First(_name(var), _name(cls), cond, body, orelse or (), _pos(meta))

    def foreach(self, meta, var, cls, cond, body):
        return ast.ForEach(_name(var), _name(cls), cond, body, _pos(meta))

    def add(self, meta, target, *inits):
        return ast.Add(target, tuple(i for i in inits if i is not None), _pos(meta))

    def init(self, meta, name, value):
        return (_name(name), value)

    def remove(self, meta, target):
        return ast.Remove(target, _pos(meta))


# lark names the rule `elif`, a Python keyword: route it to `elif_`.
setattr(_ToAst, "elif", _ToAst.elif_)
_TO_AST = _ToAst()


class _Refused(Exception):
    """Bad input found while building the AST, at a position inside the text."""

    def __init__(self, message: str, pos: ast.Pos):
        super().__init__(message)
        self.message, self.pos = message, pos


def _name(tok: Token) -> str:
    if len(tok) > MAX_NAME:
        raise _Refused(f"the name {shorten(str(tok), 40)} is longer than {MAX_NAME} characters", _pos(tok))
    return str(tok)


# Rules that only group their children add no nesting of their own.
_FLAT = {"args", "effects", "block", "elif", "init", "start_expr", "start_effects"}
# `x in [...]` and `x not in [...]`: the comparisons they become are a chain of or / and.
_MEMBERSHIP = {"member", "not_member"}
# Chains of one operator, rebuilt as balanced trees: rule -> operator (None: the rule is the operator).
_CHAINS = {"and_": None, "or_": None}
# Binary operators whose chains are rebuilt: `+` and `-` are one family (a long
# `a - b + c - d ...` becomes (a + c + ...) - (b + d + ...), both sums balanced; exact on
# whole numbers, and interval bounds come out the same), `*` its own.
_FAMILY = {"+": "+-", "-": "+-", "*": "*"}


def _chain(tree: Tree) -> tuple[list, list] | None:
    """The operands and operator tokens of a left-nested chain of one operator or family
    (`a and b and c` parses as and_(and_(a, b), c)), or None for any other node."""
    if tree.data in _CHAINS:
        same = lambda t: isinstance(t, Tree) and t.data == tree.data  # noqa: E731
    elif tree.data == "binop" and str(tree.children[1]) in _FAMILY:
        family = _FAMILY[str(tree.children[1])]
        same = lambda t: (isinstance(t, Tree) and t.data == "binop"  # noqa: E731
                          and _FAMILY.get(str(t.children[1])) == family)
    else:
        return None
    items, ops, node = [], [], tree
    while same(node):
        *left, right = node.children
        items.append(right)
        ops.append(left[1] if len(left) == 2 else node.meta)
        node = left[0]
    items.append(node)
    return items[::-1], ops[::-1]


KEEP_SHAPE = 16   # chains up to this long keep the parser's left-nested shape


def _split_signs(items: list, ops: list) -> tuple | None:
    """A long `+`/`-` chain's added operands and subtracted ones, each with `+` tokens to
    join them (borrowing the positions of the operators they replace); None if no `-`."""
    if not any(str(op) == "-" for op in ops):
        return None
    plus = lambda op: op if str(op) == "+" else Token.new_borrow_pos("ADD_OP", "+", op)  # noqa: E731
    pos, pos_ops, neg, neg_ops = [items[0]], [], [], []
    for op, item in zip(ops, items[1:]):
        side, side_ops = (neg, neg_ops) if str(op) == "-" else (pos, pos_ops)
        if side:
            side_ops.append(plus(op))
        side.append(item)
    minus = next(op for op in ops if str(op) == "-")
    return pos, pos_ops, neg, neg_ops, minus


def _balanced(rule: str, items: list, ops: list):
    """The tree of a chain: left-nested as written (`a and b and c` is and(and(a, b), c))
    up to KEEP_SHAPE operands, so ordinary expressions keep their shape; a longer chain is
    split at its middle operator, so its depth grows as log2 of its length."""
    def join(op, left, right):
        if rule == "binop":
            return ast.BinOp(str(op), left, right, _pos(op))
        return (ast.And if rule == "and_" else ast.Or)(left, right, left.pos)
    if len(items) <= KEEP_SHAPE:
        node = items[0]
        for op, item in zip(ops, items[1:]):
            node = join(op, node, item)
        return node
    signs = _split_signs(items, ops) if rule == "binop" else None
    if signs is not None:
        pos, pos_ops, neg, neg_ops, minus = signs
        return join(minus, _balanced(rule, pos, pos_ops), _balanced(rule, neg, neg_ops))
    mid = (len(items) + 1) // 2
    return join(ops[mid - 1], _balanced(rule, items[:mid], ops[:mid - 1]), _balanced(rule, items[mid:], ops[mid:]))


def _chain_depth(n: int, ops: list = ()) -> int:
    """The nesting `_balanced` adds over its deepest operand, for n operands."""
    if n <= KEEP_SHAPE:
        return n - 1
    minus = sum(str(op) == "-" for op in ops)
    if minus:
        return 1 + max(_chain_depth(n - minus), _chain_depth(minus))
    return 1 + _chain_depth((n + 1) // 2)


def _build(tree: Tree):
    """The AST of a lark tree, made bottom-up with explicit stacks (no recursion); deeper
    nesting than MAX_EXPRESSION_DEPTH is refused at the node that crosses it."""
    values: list = []          # (AST value, depth)
    todo: list = [("visit", tree)]
    while todo:
        step, node = todo.pop()
        if step == "visit":
            if not isinstance(node, Tree):
                values.append((node, 0))
                continue
            chain = _chain(node)
            if chain is not None:
                items, ops = chain
                todo.append(("chain", (node, ops, len(items))))
                todo.extend(("visit", item) for item in reversed(items))
            else:
                todo.append(("make", node))
                todo.extend(("visit", child) for child in reversed(node.children))
            continue
        if step == "make":
            n = len(node.children)
            args = values[len(values) - n:] if n else []
            del values[len(values) - n:]
            depth = max((d for _, d in args), default=0) + (node.data not in _FLAT)
            if node.data in _MEMBERSHIP:     # a comparison per choice, joined by a balanced chain
                depth += _chain_depth(len(args[-1][0]))
            value = getattr(_TO_AST, node.data)(node.meta, *(v for v, _ in args))
            where = node.meta
        else:  # chain
            tree_node, ops, n = node
            args = values[len(values) - n:]
            del values[len(values) - n:]
            depth = max(d for _, d in args) + _chain_depth(n, ops)
            value = _balanced(tree_node.data, [v for v, _ in args], ops)
            where = tree_node.meta
        if depth > MAX_EXPRESSION_DEPTH:
            raise _Refused(f"the expression is nested more than {MAX_EXPRESSION_DEPTH} levels deep; "
                           "name parts of it as functions", _pos(where))
        values.append((value, depth))
    return values[0][0]


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
        return _parsed(text, start)
    except UnexpectedInput as exc:
        raise _syntax_error(exc, text, where, effects=start == "start_effects") from None
    except _Refused as exc:
        raise where.error(exc.message, *exc.pos) from None


@lru_cache(maxsize=8192)
def _parsed(text: str, start: str):
    """The AST of a text, kept: the nodes are frozen and their positions count from the
    text's own start, so one text parses once per process however many files hold it (a
    domain extended by several, a batch or server compiling variants of one domain; the
    hostile-input test compiles some 3,600 variants of the shipped domains). Errors are
    not kept: each is raised again from a fresh parse, at its own file's place."""
    if start == "start_effects":
        tree = _parser().parse(text, start=start, on_error=lambda exc: _newline_ends_effect(exc, text))
    else:
        tree = _parser().parse(text, start=start)
    return _build(tree)


def _newline_ends_effect(exc: UnexpectedInput, text: str) -> bool:
    """Effects written one a line, without `;` (as in a YAML block scalar): where the parser
    is stuck at the first token of a line and a `;` would fit, the line break is that `;`
    (as JavaScript inserts its semicolons). Returns whether parsing may go on."""
    if not isinstance(exc, UnexpectedToken) or exc.token.type == "$END" or exc.token.start_pos is None:
        return False
    if not _starts_line(text, exc.token.start_pos):
        return False
    parser = exc.interactive_parser
    if "SEMICOLON" not in parser.accepts():
        return False
    parser.feed_token(Token.new_borrow_pos("SEMICOLON", ";", exc.token))
    parser.feed_token(exc.token)
    return True


def _syntax_error(exc: UnexpectedInput, text: str, where: Origin, effects: bool = False) -> BccError:
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
        before = re.search(r"([A-Za-z]+)\s*$", text[:tok.start_pos]) if tok.start_pos is not None else None
        if before and _foreign_spelling(before.group(1)):   # `NOT x`: the word before was read as a name
            word = before.group(1)
            if effects and word.lower() in ("for", "each", "every", "all"):
                return where.error(f"syntax error: unexpected {word!r}; an effect repeats with "
                                   "`forall i in C { effects }` (or `first i in C where condition { effects }`)",
                                   *_line_col(text, before.start(1)))
            return where.error(f"syntax error: unexpected {word!r}{_foreign_spelling(word)}",
                               *_line_col(text, before.start(1)))
        found = text[tok.start_pos:tok.start_pos + 2] if tok.start_pos is not None else ""
        if found in ("++", "--"):
            return where.error(f"syntax error: unexpected {found!r}; write `{found[0]}= 1`", tok.line, tok.column)
        hint = (_effect_spelling(str(tok), names) if effects else "") or _foreign_spelling(str(tok), tok.type)
        if not hint and not effects:
            hint = _condition_layout(text, tok, names)
        return where.error(f"syntax error: unexpected {str(tok)!r}{hint or want}", tok.line, tok.column)
    if isinstance(exc, UnexpectedCharacters):
        found = text[exc.pos_in_stream:exc.pos_in_stream + 2]
        found = found if found in ("&&", "||") else found[:1]
        hint = _foreign_spelling(found + ("=" if text[exc.pos_in_stream + 1:exc.pos_in_stream + 2] == "=" else ""))
        return where.error(f"syntax error: unexpected character{'s' if len(found) > 1 else ''} {found!r}{hint or want}",
                           exc.line, exc.column)
    return where.error(f"syntax error: {exc}")


# What people bring from other languages, and bcc's spelling of it.
_OPERATOR_WORDS = {"&&": "and", "&": "and", "||": "or", "|": "or", "!": "not"}
_KEYWORDS = ("and", "or", "not", "in", "exists", "forall", "if", "elif", "else", "true", "false")
_QUANTIFIER_WORDS = {"any": "exists", "some": "exists", "exist": "exists", "there": "exists",
                     "all": "forall", "every": "forall", "each": "forall", "for": "forall"}
_QUOTES = set("'\"\u2018\u2019\u201c\u201d`")


def _starts_line(text: str, offset: int | None) -> bool:
    """Whether only blanks stand between the line's start (or the text's) and `offset`."""
    if offset is None:
        return False
    before = text[:offset].rstrip(" \t")
    return not before or before.endswith("\n")


def _condition_layout(text: str, tok: Token, expected) -> str:
    """A hint for conditions laid out as lines or as words: `p` and `q` on two lines, or
    "agent in red room" (an expression wants an operator or a call between names)."""
    if _starts_line(text, tok.start_pos) and "AND" in expected:
        return "; conditions on separate lines need `and` between them (or write them as a YAML list, `- ` before each)"
    after_word = re.search(r"(?<![\w.])[A-Za-z_]\w*\s+$", text[:tok.start_pos])
    if tok.type == "NAME" and after_word and ("AND" in expected or "LSQB" in expected):
        return ("; words in a row are not an expression: write e.g. `agentInRoom(agent, red)` "
                "(a command in words is for `bcc command`)")
    return ""


def _line_col(text: str, offset: int) -> tuple[int, int]:
    return text.count("\n", 0, offset) + 1, offset - (text.rfind("\n", 0, offset) + 1) + 1


def _effect_spelling(found: str, expected) -> str:
    """A hint for effects written as in Python or Pascal (`if p:`, `then`, `:=`, `==`)."""
    if found in (":", "then") and "LBRACE" in expected:
        return "; a block of effects goes in braces, with no `:` or `then` before it: `if condition { effects }`"
    if found == ":" and "EQUAL" in expected:
        return "; assign with `=`"
    if found == "==" and "EQUAL" in expected:
        return "; an effect assigns with `=` (`==` compares)"
    return ""


def _foreign_spelling(found: str, kind: str = "") -> str:
    """A hint for a spelling from another language (`&&`, `!`, `AND`, quotes, `=` in a
    condition), or "" (the parser's list of what it expected is then the message)."""
    if found in _OPERATOR_WORDS:
        return f"; bcc writes `{_OPERATOR_WORDS[found]}` (its logical operators are the words and, or, not)"
    if found.lower() in _QUANTIFIER_WORDS:
        kind = _QUANTIFIER_WORDS[found.lower()]
        return f"; bcc writes `{kind} b in block . condition` (or `{kind} b in block: condition`)"
    if found.lower() in _KEYWORDS and found != found.lower():
        return f"; keywords are lowercase: write `{found.lower()}`"
    if found[:1] in _QUOTES:
        return "; names are written without quotes, e.g. agentInRoom(agent, red)"
    if found == "=" and kind != "CMP_OP":
        return "; compare with `==` (a single `=` assigns, in effects)"
    return ""
