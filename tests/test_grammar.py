"""The expression language's parser: precedence, effects, syntax-error positions and messages.

Unit tests pin the shape of the syntax tree for each construct of grammar/expressions.lark;
property tests (hypothesis) print random trees fully parenthesised and parse them back, and
feed the parser garbage, which must either parse or raise a one-line `BccError`.
AST nodes compare without their positions, so trees are built here without positions.
"""
from __future__ import annotations

import re
import string

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bcc.compiler import ast
from bcc.compiler.ast import (Add, And, Assign, Attr, BinOp, Bool, Call, Compare, First, ForEach, If, Index,
                              Int, Name, Neg, Not, Or, Quantifier, Remove)
from bcc.compiler.parse import parse_effects, parse_expression
from bcc.compiler.source import Origin
from bcc.errors import BccError

HERE = Origin("test.yaml", 1, 1)


def E(text: str):
    return parse_expression(text, HERE)


def F(text: str):
    return parse_effects(text, HERE)


def err(text: str, where: Origin = HERE, effects: bool = False) -> BccError:
    with pytest.raises(BccError) as info:
        (parse_effects if effects else parse_expression)(text, where)
    return info.value


a, b, c, d, x, y, z = (Name(n) for n in "abcdxyz")


# ---- precedence ----------------------------------------------------------------------
@pytest.mark.parametrize("text,tree", [
    ("not a and b or c", Or(And(Not(a), b), c)),
    ("a or b and c", Or(a, And(b, c))),
    ("a and b and c", And(And(a, b), c)),
    ("a or b or c", Or(Or(a, b), c)),
    ("not not a", Not(Not(a))),
    ("not a or not b", Or(Not(a), Not(b))),
    ("(a or b) and c", And(Or(a, b), c)),
    ("not (a and b)", Not(And(a, b))),
    # `not` is looser than comparisons and arithmetic
    ("not a == b", Not(Compare((a, b), ("==",)))),
    ("not a + 1 < b", Not(Compare((BinOp("+", a, Int(1)), b), ("<",)))),
    ("a == b and c != d", And(Compare((a, b), ("==",)), Compare((c, d), ("!=",)))),
    ("true and false", And(Bool(True), Bool(False))),
])
def test_boolean_precedence(text, tree):
    assert E(text) == tree


@pytest.mark.parametrize("text,tree", [
    ("0 < x < 3", Compare((Int(0), x, Int(3)), ("<", "<"))),
    ("a == b != c <= d", Compare((a, b, c, d), ("==", "!=", "<="))),
    ("a >= b > c", Compare((a, b, c), (">=", ">"))),
    ("a + 1 < b * 2", Compare((BinOp("+", a, Int(1)), BinOp("*", b, Int(2))), ("<",))),
    ("(a < b) == c", Compare((Compare((a, b), ("<",)), c), ("==",))),
])
def test_comparison_chains(text, tree):
    assert E(text) == tree


def test_chains_keep_their_shape_and_only_long_ones_are_balanced():
    """`a or b or c or d` and its fully bracketed form are the same left-nested tree (a
    CI run of the round-trip property found a 4-term chain rebuilt as (a or b) or (c or d));
    only chains longer than KEEP_SHAPE are balanced, to bound their depth."""
    from bcc.compiler.parse import KEEP_SHAPE
    left_nested = Or(Or(Or(a, b), c), d)
    assert E("a or b or c or d") == E("(((a) or (b)) or (c)) or (d)") == left_nested
    assert E("a + b + c + d") == BinOp("+", BinOp("+", BinOp("+", a, b), c), d)

    def depth(n):
        return 1 + max(depth(n.left), depth(n.right)) if isinstance(n, (And, BinOp)) else 0
    long = E(" and ".join(["a"] * (4 * KEEP_SHAPE)))
    assert depth(long) < 2 * KEEP_SHAPE   # log2(4) levels of splitting over chains of at most KEEP_SHAPE


def _value(node) -> int:
    """Whole-number value of a parsed +, -, * tree over numbers (an evaluator written here)."""
    if isinstance(node, Int):
        return node.value
    if isinstance(node, Neg):
        return -_value(node.operand)
    left, right = _value(node.left), _value(node.right)
    return {"+": left + right, "-": left - right, "*": left * right}[node.op]


def test_mixed_plus_minus_chains_keep_their_shape_and_long_ones_stay_shallow():
    from bcc.compiler.parse import KEEP_SHAPE, MAX_EXPRESSION_DEPTH
    assert E("a + b - c + d") == BinOp("+", BinOp("-", BinOp("+", a, b), c), d)
    # 150 subtractions used to count as 150 levels and were refused; now
    # (10 + ...) - (1 + 1 + ...) with both sums balanced: about log2(150) levels.
    long = E("10" + " - 1" * 150)
    assert _value(long) == 10 - 150
    assert "nested" not in str(E("x == 10" + " - 1" * 150 + " + 2" * 40))  # parses, no error
    assert 4 * KEEP_SHAPE < 150 and MAX_EXPRESSION_DEPTH < 150


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(["+", "-", "*"]), st.integers(-9, 9)), min_size=1, max_size=80),
       st.integers(-9, 9))
def test_long_arithmetic_chains_keep_their_value(tail, first):
    """Any chain of + - * over numbers parses to a tree with Python's value for the text
    (* binds tighter; balancing and the +/- split must not change the result)."""
    text = str(first) + "".join(f" {op} {n}" if n >= 0 else f" {op} ({n})" for op, n in tail)
    assert _value(E(text)) == eval(text)  # noqa: S307 - digits and + - * only, built above


@pytest.mark.parametrize("text,tree", [
    ("a + b * c", BinOp("+", a, BinOp("*", b, c))),
    ("a * b + c", BinOp("+", BinOp("*", a, b), c)),
    ("a - b - c", BinOp("-", BinOp("-", a, b), c)),
    ("a // b % c", BinOp("%", BinOp("//", a, b), c)),
    ("a - b // c", BinOp("-", a, BinOp("//", b, c))),
    ("(a - b) * c", BinOp("*", BinOp("-", a, b), c)),
    ("-a * b", BinOp("*", Neg(a), b)),
    ("a - -b", BinOp("-", a, Neg(b))),
    ("- - 3", Neg(Neg(Int(3)))),
    ("-a.x", Neg(Attr(a, "x"))),
    ("(a.rotationalDirection + 3) % 4", BinOp("%", BinOp("+", Attr(a, "rotationalDirection"), Int(3)), Int(4))),
    ("10 // 3", BinOp("//", Int(10), Int(3))),
])
def test_arithmetic(text, tree):
    assert E(text) == tree


@pytest.mark.parametrize("text,tree", [
    ("a.b", Attr(a, "b")),
    ("a.b.c", Attr(Attr(a, "b"), "c")),
    ("block[x, y, z]", Index(Name("block"), (x, y, z))),
    ("block[x, y, z].blockType", Attr(Index(Name("block"), (x, y, z)), "blockType")),
    ("block[a.x + 1, a.y - 1, a.z].blockType.solid",
     Attr(Attr(Index(Name("block"), (BinOp("+", Attr(a, "x"), Int(1)), BinOp("-", Attr(a, "y"), Int(1)),
                                     Attr(a, "z"))), "blockType"), "solid")),
    ("dx[a.rotationalDirection]", Index(Name("dx"), (Attr(a, "rotationalDirection"),))),
    ("t[1][2]", Index(Index(Name("t"), (Int(1),)), (Int(2),))),
    ("f()", Call("f", ())),
    ("f(a)", Call("f", (a,))),
    ("agentOnBlock(agent, gold)", Call("agentOnBlock", (Name("agent"), Name("gold")))),
    ("f(a, g(b), c.d)", Call("f", (a, Call("g", (b,)), Attr(c, "d")))),
    ("f(x).y", Attr(Call("f", (x,)), "y")),
    ("f(x)[1]", Index(Call("f", (x,)), (Int(1),))),
    ("f(a or b, not c)", Call("f", (Or(a, b), Not(c)))),
    ("(a)", a),
    ("((a))", a),
    ("true", Bool(True)),
    ("false", Bool(False)),
    ("42", Int(42)),
])
def test_postfix_atoms_and_calls(text, tree):
    assert E(text) == tree


def Q(kind, var, cls, body):
    return Quantifier(kind, var, cls, body)


@pytest.mark.parametrize("text,tree", [
    ("exists b in block . p", Q("exists", "b", "block", Name("p"))),
    ("forall i in inventoryBlock . p", Q("forall", "i", "inventoryBlock", Name("p"))),
    # the body extends as far right as possible
    ("exists b in block . p and q or r", Q("exists", "b", "block", Or(And(Name("p"), Name("q")), Name("r")))),
    ("a and exists b in block . p or q", And(a, Q("exists", "b", "block", Or(Name("p"), Name("q"))))),
    ("a or exists b in block . p", Or(a, Q("exists", "b", "block", Name("p")))),
    ("not exists b in block . p and q", Not(Q("exists", "b", "block", And(Name("p"), Name("q"))))),
    ("(exists b in block . p) or q", Or(Q("exists", "b", "block", Name("p")), Name("q"))),
    ("exists b in block . exists c in block . b.x == c.x",
     Q("exists", "b", "block", Q("exists", "c", "block", Compare((Attr(b, "x"), Attr(c, "x")), ("==",))))),
    ("exists i in inventoryBlock . i.blockType == t and i.count > 0",
     Q("exists", "i", "inventoryBlock", And(Compare((Attr(Name("i"), "blockType"), Name("t")), ("==",)),
                                            Compare((Attr(Name("i"), "count"), Int(0)), (">",))))),
])
def test_quantifiers(text, tree):
    assert E(text) == tree


@pytest.mark.parametrize("text", [
    "exists b in block . b.x == 1 and p",
    "forall a in agent . a.alive or q",
    "x and exists b in block . p or not q",
])
def test_quantifier_colon_and_in_are_the_same(text):
    assert E(text.replace(" in ", ": ", 1)) == E(text)
    assert E(text.replace(" in ", " : ", 1)) == E(text)


@pytest.mark.parametrize("text", [
    "exists b in block . b.x == 1 and p",
    "forall a in agent . (a.alive or q)",
])
def test_a_quantifier_body_may_follow_a_colon(text):
    # Python's `for x in C:`; the class name ends before the colon, so `.`/`:` never mix up.
    assert E(text.replace(" . ", ": ", 1)) == E(text)
    assert E(text.replace(" in ", ": ", 1).replace(" . ", " : ", 1)) == E(text)


def x_is(op: str, *values: str):
    return [Compare((Attr(a, "x"), Name(v) if v.isalpha() else Int(int(v))), (op,)) for v in values]


@pytest.mark.parametrize("text,tree", [
    ("a.x in [1, b]", Or(*x_is("==", "1", "b"))),
    ("a.x in {1, b}", Or(*x_is("==", "1", "b"))),
    ("a.x in (1, b, c)", Or(Or(*x_is("==", "1", "b")), x_is("==", "c")[0])),
    ("a.x in [1]", x_is("==", "1")[0]),
    ("a.x not in [1, b]", And(*x_is("!=", "1", "b"))),
    # `not` before the whole membership negates it; `not in` is the membership's own operator
    ("not a.x in [1, b]", Not(Or(*x_is("==", "1", "b")))),
    ("p and a.x in [1, b] or q", Or(And(Name("p"), Or(*x_is("==", "1", "b"))), Name("q"))),
])
def test_membership_is_a_disjunction_of_equalities(text, tree):
    assert E(text) == tree


def test_long_membership_lists_stay_shallow():
    # 2,000 choices: as a left-nested `or` chain this would be 2,000 levels deep, past the
    # 40-level limit; balanced, it is about 11.
    choices = ", ".join(str(i) for i in range(2000))
    assert isinstance(E(f"a.x in [{choices}]"), Or)
    assert isinstance(E(f"a.x not in [{choices}]"), And)


@pytest.mark.parametrize("text", ["a.x in []", "a.x in [1,]", "a.x in 3", "a.x : [1]", "a.x not [1]"])
def test_bad_membership_is_a_syntax_error(text):
    assert err(text).message.startswith("syntax error: ")


def test_comments_and_newlines_are_whitespace():
    assert E("a and  # why\n  b\n# done") == And(a, b)
    assert F("a.x = 1;  # first\n\n  a.y = 2  # second\n") == F("a.x = 1; a.y = 2")


def test_names_that_start_like_keywords_are_names():
    assert E("notx and andy or order") == Or(And(Name("notx"), Name("andy")), Name("order"))
    assert E("exists_b and true_") == And(Name("exists_b"), Name("true_"))


def test_node_positions_are_recorded_but_not_compared():
    tree = E("a and\n   bb")
    assert tree.right.pos == (2, 4)
    assert tree.left.pos == (1, 1)
    call = E("  f(x, y)")
    assert call.pos == (1, 3)
    assert call.args[1].pos == (1, 8)
    assert E("a    and b") == E("a and\n\n\t b")


# ---- effects -------------------------------------------------------------------------
def A(target, value):
    return Assign(target, value)


def test_assignment_and_sequences():
    assert F("a.x = 1") == (A(Attr(a, "x"), Int(1)),)
    assert F("a.x = 1;") == (A(Attr(a, "x"), Int(1)),)
    assert F("a.x = tx; a.z = tz") == (A(Attr(a, "x"), Name("tx")), A(Attr(a, "z"), Name("tz")))
    assert F("a.r = (a.r + 3) % 4") == (A(Attr(a, "r"), BinOp("%", BinOp("+", Attr(a, "r"), Int(3)), Int(4))),)
    assert F("inventoryBlock[a.s].count = inventoryBlock[a.s].count - 1") == (
        A(Attr(Index(Name("inventoryBlock"), (Attr(a, "s"),)), "count"),
          BinOp("-", Attr(Index(Name("inventoryBlock"), (Attr(a, "s"),)), "count"), Int(1))),)
    assert F("a.alive = not a.alive or false") == (A(Attr(a, "alive"), Or(Not(Attr(a, "alive")), Bool(False))),)


def test_if_elif_else():
    one, two, three = (A(Attr(a, "x"), Int(i)) for i in (1, 2, 3))
    assert F("if p { a.x = 1 }") == (If(((Name("p"), (one,)),), ()),)
    assert F("if p { a.x = 1 } else { a.x = 2 }") == (If(((Name("p"), (one,)),), (two,)),)
    assert F("if p { a.x = 1 } elif q { a.x = 2 } elif r { a.x = 3 } else { a.x = 1; a.x = 2 }") == (
        If(((Name("p"), (one,)), (Name("q"), (two,)), (Name("r"), (three,))), (one, two)),)
    assert F("if p and q { a.x = 1 } elif not r { a.x = 2 }") == (
        If(((And(Name("p"), Name("q")), (one,)), (Not(Name("r")), (two,))), ()),)
    # an if is one effect in a sequence
    assert F("if p { a.x = 1 }; a.x = 2") == (If(((Name("p"), (one,)),), ()), two)
    # nested
    assert F("if p { if q { a.x = 1 } else { a.x = 2 } }") == (
        If(((Name("p"), (If(((Name("q"), (one,)),), (two,)),)),), ()),)


def test_first_with_else():
    inc = A(Attr(Name("i"), "count"), BinOp("+", Attr(Name("i"), "count"), Int(1)))
    cond = And(Compare((Attr(Name("i"), "blockType"), Name("t")), ("==",)),
               Compare((Int(0), Attr(Name("i"), "count"), Int(64)), ("<", "<")))
    text = "first i in inventoryBlock where i.blockType == t and 0 < i.count < 64 { i.count = i.count + 1 }"
    assert F(text) == (First("i", "inventoryBlock", cond, (inc,), ()),)
    fill = A(Attr(Name("j"), "count"), Int(1))
    inner = First("j", "inventoryBlock", Compare((Attr(Name("j"), "count"), Int(0)), ("==",)), (fill,), ())
    assert F(text + " else { first j: inventoryBlock where j.count == 0 { j.count = 1 } }") == (
        First("i", "inventoryBlock", cond, (inc,), (inner,)),)


def test_forall_effect():
    reset = A(Attr(Name("i"), "count"), Int(0))
    assert F("forall i in inventoryBlock { i.count = 0 }") == (ForEach("i", "inventoryBlock", None, (reset,)),)
    assert F("forall i: inventoryBlock where i.count > 9 { i.count = 0 }") == (
        ForEach("i", "inventoryBlock", Compare((Attr(Name("i"), "count"), Int(9)), (">",)), (reset,)),)


def test_add_and_remove():
    cell = Index(Name("block"), (Name("tx"), BinOp("-", Attr(a, "y"), Int(1)), Name("tz")))
    assert F("add block[tx, a.y - 1, tz] {blockType = t}") == (Add(cell, (("blockType", Name("t")),)),)
    assert F("add block[tx, a.y - 1, tz] {}") == (Add(cell, ()),)
    assert F("add block[tx, a.y - 1, tz] {blockType = t, hp = 3 + 1}") == (
        Add(cell, (("blockType", Name("t")), ("hp", BinOp("+", Int(3), Int(1))))),)
    assert F("remove block[tx, a.y - 1, tz]") == (Remove(cell),)
    assert F("remove block[1, 2, 3]; add block[1, 2, 3] {blockType = gold}") == (
        Remove(Index(Name("block"), (Int(1), Int(2), Int(3)))),
        Add(Index(Name("block"), (Int(1), Int(2), Int(3))), (("blockType", Name("gold")),)))


def test_the_shipped_place_block_effect():
    text = """if floor.fillable { add block[tx, a.y - 1, tz] {blockType = t} }
else { add block[tx, a.y, tz] {blockType = t} };
inventoryBlock[a.selectedItem].count = inventoryBlock[a.selectedItem].count - 1;
"""
    effs = F(text)
    assert [type(e) for e in effs] == [If, Assign]
    assert isinstance(effs[0].branches[0][1][0], Add) and isinstance(effs[0].orelse[0], Add)


# ---- syntax errors: positions --------------------------------------------------------
def test_error_position_unexpected_token():
    text = "agentOnBlock(agent,, gold)"
    e = err(text)
    assert (e.path, e.line, e.col) == ("test.yaml", 1, text.index(",,") + 2)
    # the same text after `goal: ` on line 27 of a file
    e = err(text, Origin("d.yaml", 27, 7))
    assert (e.path, e.line, e.col) == ("d.yaml", 27, 7 + text.index(",,") + 1)
    assert str(e).startswith("d.yaml:27:26: ")


def test_error_position_unexpected_character():
    text = "a and b $ c"
    e = err(text, Origin("d.yaml", 4, 10))
    assert (e.line, e.col) == (4, 10 + text.index("$"))
    assert "'$'" in e.message


def test_error_position_text_ends_too_early():
    text = "agentOnBlock(agent, gold) and"
    e = err(text, Origin("d.yaml", 3, 7))
    assert (e.line, e.col) == (3, 7 + len(text))  # just after the last character
    assert "ends too early" in e.message
    e = err("a or   \n\n")  # trailing blank space and lines do not move the position
    assert (e.line, e.col) == (1, 5)


def test_error_position_in_a_block_scalar_uses_the_indent():
    # goal: |
    #     agentOnBlock(agent, gold) and
    #       agentHasBlock(agent, $)
    # The text starts on file line 8 at column 5; further lines start at column 5 too
    # (YAML removed the 4-space indentation from every line of the text).
    text = "agentOnBlock(agent, gold) and\n  agentHasBlock(agent, $)\n"
    where = Origin("d.yaml", 8, 5, indent=5)
    e = err(text, where)
    assert (e.line, e.col) == (9, 5 + text.splitlines()[1].index("$"))
    assert str(e).startswith("d.yaml:9:28: ")


def test_error_position_block_scalar_ends_too_early():
    text = "agentOnBlock(agent,\n   gold) and\n\n"
    e = err(text, Origin("d.yaml", 20, 3, indent=3))
    assert (e.line, e.col) == (21, 3 + len("   gold) and"))


def test_error_position_of_effects():
    text = "a.x = 1;\nif p { a.x = 1 } b.y = 2"
    e = err(text, Origin("dom.yaml", 40, 7, indent=7), effects=True)
    assert (e.line, e.col) == (41, 7 + text.splitlines()[1].index("b.y"))
    assert "'b'" in e.message


def test_origin_locate():
    o = Origin("f", 10, 7, indent=3)
    assert o.locate(1, 1) == (10, 7)
    assert o.locate(1, 5) == (10, 11)
    assert o.locate(2, 1) == (11, 3)
    assert o.locate(4, 6) == (13, 8)
    e = o.error("boom", 2, 4)
    assert (e.path, e.line, e.col, e.message) == ("f", 11, 6, "boom")
    assert str(e) == "f:11:6: boom"


def test_empty_and_non_text_expressions_are_errors_at_the_origin():
    for text in ("", "   ", "\n\n"):
        e = err(text, Origin("d.yaml", 5, 7))
        assert (e.line, e.col) == (5, 7)
    with pytest.raises(BccError) as info:
        parse_expression(None, Origin("d.yaml", 5, 7))  # type: ignore[arg-type]
    assert (info.value.line, info.value.col) == (5, 7)
    with pytest.raises(BccError):
        parse_effects(["a.x = 1"], Origin("d.yaml", 5, 7))  # type: ignore[arg-type]


# ---- syntax errors: messages ---------------------------------------------------------
# Lark's internal terminal names must never reach the user.
TERMINAL_NAME = re.compile(r"\b(LPAR|RPAR|LSQB|RSQB|LBRACE|RBRACE|COMMA|DOT|COLON|SEMICOLON|EQUAL|MINUS|"
                           r"CMP_OP|ADD_OP|MUL_OP|NAME|INT|WS|COMMENT|OR|AND|NOT|EXISTS|FORALL|TRUE|FALSE|"
                           r"IF|ELIF|ELSE|FIRST|WHERE|ADD|REMOVE|_IN)\b|__ANON|\$END|\bTerminal\(")

BAD_EXPRESSIONS = [
    ("a or", ["ends too early"]),
    ("1 +", ["ends too early", "a number", "a name"]),
    ("(a", ["ends too early", "')'"]),
    ("f(a, b", ["ends too early", "')'"]),
    ("block[1, 2", ["ends too early", "']'"]),
    ("a.", ["ends too early", "a name"]),
    ("a..b", ["'.'", "a name"]),
    ("a == == b", ["'=='"]),
    ("1 < < 2", ["'<'"]),
    ("a $ b", ["'$'"]),
    ("f(a))", ["')'", "the end of the text"]),
    ("agentOnBlock(agent,, gold)", ["','"]),
    ("exists b in block p", ["'p'", "'.'"]),
    ("exists in block . p", []),
    ("a = b", ["'='"]),
    ("not", ["ends too early"]),
    ("[1]", ["'['"]),
    ("a.1", ["'1'", "a name"]),
]


@pytest.mark.parametrize("text,needles", BAD_EXPRESSIONS)
def test_syntax_error_messages_say_what_was_expected(text, needles):
    e = err(text)
    assert e.message.startswith("syntax error: ")
    if not needles or needles[0] != "ends too early":
        assert "expected" in e.message
    for needle in needles:
        assert needle in e.message
    assert not TERMINAL_NAME.search(e.message), e.message
    assert "\n" not in str(e)


# Spellings from other languages get bcc's spelling, at the character that needs it.
FOREIGN = [
    ("p && q", (1, 3), "bcc writes `and`"),
    ("p & q", (1, 3), "bcc writes `and`"),
    ("p || q", (1, 3), "bcc writes `or`"),
    ("p | q", (1, 3), "bcc writes `or`"),
    ("!p", (1, 1), "bcc writes `not`"),
    ("p and !q", (1, 7), "bcc writes `not`"),
    ("p AND q", (1, 3), "keywords are lowercase: write `and`"),
    ("p Or q", (1, 3), "keywords are lowercase: write `or`"),
    ("NOT p", (1, 1), "keywords are lowercase: write `not`"),
    ("p and\n  Not q", (2, 3), "keywords are lowercase: write `not`"),
    ("f(a, 'red')", (1, 6), "names are written without quotes"),
    ('f(a, "red")', (1, 6), "names are written without quotes"),
    ("f(a, \u201cred\u201d)", (1, 6), "names are written without quotes"),
    ("a.x = 3", (1, 5), "compare with `==`"),
    ("for all b in block . p", (1, 1), "bcc writes `forall b in block . condition`"),
    ("for each b in block: p", (1, 1), "bcc writes `forall"),
    ("q and any b in block . p", (1, 7), "bcc writes `exists b in block . condition`"),
    ("every b in block . p", (1, 1), "bcc writes `forall"),
    ("ForAll b in block . p", (1, 1), "keywords are lowercase: write `forall`"),
    ("Exists b in block . p", (1, 1), "keywords are lowercase: write `exists`"),
    ("a.x IN [1]", (1, 5), "keywords are lowercase: write `in`"),
    ("go to the red room", (1, 4), "words in a row are not an expression"),
    ("agent in red room", (1, 10), "words in a row are not an expression"),
]


@pytest.mark.parametrize("text,where,hint", FOREIGN)
def test_spellings_from_other_languages_get_a_hint(text, where, hint):
    e = err(text)
    assert (e.line, e.col) == where and hint in e.message, e.message


def test_a_value_then_a_name_is_not_taken_for_words():
    assert "words in a row" not in err("a.x == 1 b").message
    assert "words in a row" not in err("f(a) b").message


def test_a_not_equal_is_not_taken_for_a_foreign_not():
    assert parse_expression("a != b", HERE) is not None
    assert "bcc writes" not in err("a != != b").message


@pytest.mark.parametrize("short,long", [
    ("a.x += 1", "a.x = a.x + 1"),
    ("a.x -= b.y * 2", "a.x = a.x - b.y * 2"),
    ("inv[s].count *= 2; a.y //= 3; a.z %= 4", "inv[s].count = inv[s].count * 2; a.y = a.y // 3; a.z = a.z % 4"),
    ("a.x += 1 + 2", "a.x = a.x + (1 + 2)"),   # the whole right-hand side, as in Python
    ("if p { a.x = 1 } else if q { a.x = 2 } else { a.x = 3 }",
     "if p { a.x = 1 } elif q { a.x = 2 } else { a.x = 3 }"),
])
def test_augmented_assignment_and_else_if_are_the_long_forms(short, long):
    assert F(short) == F(long)


@pytest.mark.parametrize("one_a_line,with_semicolons", [
    ("a.x = 1\na.y = 2", "a.x = 1; a.y = 2"),
    ("a.x = 1   # first\n   a.y = 2  # second\n", "a.x = 1; a.y = 2"),
    ("a.x = 1\n\nif p {\n  a.y = 2\n  a.z = 3\n}\nremove block[1, 2, 3]",
     "a.x = 1; if p { a.y = 2; a.z = 3 }; remove block[1, 2, 3]"),
    ("if p { a.x = 1 }\nelse { a.x = 2 }\nb.y = 1", "if p { a.x = 1 } else { a.x = 2 }; b.y = 1"),
    ("a.x = 1;\na.y = 2", "a.x = 1; a.y = 2"),
    # a line that can only continue the effect above continues it
    ("a.x = b\n  - c\na.y = 2", "a.x = b - c; a.y = 2"),
    ("a.x = f(b,\n  c)\na.y = 2", "a.x = f(b, c); a.y = 2"),
    # a name that starts with a keyword is one name, even where only the keyword could follow
    ("a.x = true\ninventoryBlock[s].count = 0", "a.x = true; inventoryBlock[s].count = 0"),
    ("a.x = b\nandroid.y = 1\norange.z = 2\nnotable.w = 3", "a.x = b; android.y = 1; orange.z = 2; notable.w = 3"),
    ("if p { a.x = 1 }\nelsewhere.y = 2\nifs.z = 3", "if p { a.x = 1 }; elsewhere.y = 2; ifs.z = 3"),
])
def test_a_line_break_separates_effects_where_a_semicolon_fits(one_a_line, with_semicolons):
    assert F(one_a_line) == F(with_semicolons)


@pytest.mark.parametrize("text,where", [
    ("a.x = 1 a.y = 2", (1, 9)),           # on one line, `;` is still needed
    ("a.x = 1\n}", (2, 1)),
    ("a.x = 1\na.y == 2", (2, 5)),
    ("a.x = 1\na.y = ", (2, 6)),
])
def test_errors_after_a_line_break_keep_their_positions(text, where):
    e = err(text, effects=True)
    assert (e.line, e.col) == where, e.message


def test_conditions_do_not_split_at_line_breaks():
    # A line break in a condition is never an `and` (a YAML list is the way to list them),
    # but the message says so.
    e = err("p(a)\n  q(b)")
    assert (e.line, e.col) == (2, 3) and "need `and` between them" in e.message
    assert "need `and`" not in err("p q").message


@pytest.mark.parametrize("text,where,hint", [
    ("if p: a.x = 1", (1, 5), "in braces, with no `:` or `then`"),
    ("if p then { a.x = 1 }", (1, 6), "in braces, with no `:` or `then`"),
    ("forall i in C: { i.x = 1 }", (1, 14), "in braces"),
    ("a.x := 1", (1, 5), "assign with `=`"),
    ("a.x == 1", (1, 5), "an effect assigns with `=`"),
    ("for i in C { i.x = 1 }", (1, 1), "`forall i in C { effects }`"),
    ("a.x = 1\n  for each i in C { i.x = 1 }", (2, 3), "`forall i in C { effects }`"),
])
def test_effects_spelled_as_in_other_languages_get_a_hint(text, where, hint):
    e = err(text, effects=True)
    assert (e.line, e.col) == where and hint in e.message, e.message


@pytest.mark.parametrize("text,hint", [("a.x++", "write `+= 1`"), ("a.x--", "write `-= 1`")])
def test_increments_point_at_augmented_assignment(text, hint):
    e = err(text, effects=True)
    assert (e.line, e.col) == (1, 4) and hint in e.message


BAD_EFFECTS = [
    ("a.x = ", ["ends too early"]),
    ("a.x == 1", ["'=='", "`=`"]),
    ("if p a.x = 1", ["'a'"]),
    ("if p { a.x = 1 } b.y = 2", ["'b'", "';'"]),
    ("if p { }", ["'}'"]),
    ("first i in C { i.x = 1 }", ["'{'", "'where'"]),
    ("forall i in C . i.x == 1", ["'.'"]),
    ("add block[1, 2, 3] {blockType t}", ["'t'", "'='"]),
    ("add block[1, 2, 3]", ["ends too early", "'{'"]),
    ("remove", ["ends too early"]),
    ("a.x = 1 a.y = 2", ["'a'"]),
    ("a.x = 1;;", ["';'"]),
]


@pytest.mark.parametrize("text,needles", BAD_EFFECTS)
def test_effect_syntax_error_messages(text, needles):
    e = err(text, effects=True)
    assert e.message.startswith("syntax error: ")
    for needle in needles:
        assert needle in e.message
    assert not TERMINAL_NAME.search(e.message), e.message


def test_missing_in_of_a_quantifier_is_spelled_out():
    e = err("exists b block . p")
    assert "_in" not in e.message
    assert "'in'" in e.message or "':'" in e.message


def test_keywords_are_not_names():
    e = err("a and or b")
    assert (e.line, e.col) == (1, 7) and "'or'" in e.message
    for text in ("and", "a or and", "f(if)", "a.x == where"):
        err(text)


def test_expected_tokens_after_a_complete_expression_are_right():
    e = err("agentOnBlock(agent, gold) x")
    assert "')'" not in e.message  # no parenthesis is open
    assert "'}'" not in e.message
    assert "the end of the text" in e.message or "'and'" in e.message


def test_expected_tokens_at_the_start_of_an_effect_are_right():
    e = err("if p { }", effects=True)
    assert "'if'" in e.message or "'add'" in e.message


# ---- property tests --------------------------------------------------------------------
KEYWORDS = {"not", "and", "or", "exists", "forall", "in", "true", "false", "if", "elif", "else", "first",
            "where", "add", "remove"}
names = st.one_of(
    st.sampled_from(["a", "b", "agent", "block", "gold", "x", "notx", "and_", "If", "forall2", "_", "exists_"]),
    st.builds(str.__add__, st.sampled_from(string.ascii_letters + "_"),
              st.text(string.ascii_letters + string.digits + "_", max_size=4)).filter(lambda s: s not in KEYWORDS))
CMP = ["==", "!=", "<=", ">=", "<", ">"]
leaves = st.one_of(st.builds(Int, st.integers(0, 10**9)), st.builds(Bool, st.booleans()), st.builds(Name, names))


def _extend(children):
    some = st.lists(children, min_size=1, max_size=3).map(tuple)
    compare = st.integers(2, 4).flatmap(lambda n: st.builds(
        Compare, st.lists(children, min_size=n, max_size=n).map(tuple),
        st.lists(st.sampled_from(CMP), min_size=n - 1, max_size=n - 1).map(tuple)))
    return st.one_of(
        st.builds(Attr, children, names),
        st.builds(Index, children, some),
        st.builds(Call, names, st.lists(children, max_size=3).map(tuple)),
        st.builds(Neg, children),
        st.builds(BinOp, st.sampled_from(["+", "-", "*", "//", "%"]), children, children),
        compare,
        st.builds(And, children, children),
        st.builds(Or, children, children),
        st.builds(Not, children),
        st.builds(Quantifier, st.sampled_from(["exists", "forall"]), names, names, children),
    )


expressions = st.recursive(leaves, _extend, max_leaves=12)
small = st.recursive(leaves, _extend, max_leaves=3)  # inside effects, to keep trees quick to generate
# Whitespace the printer puts between tokens: spaces, newlines, tabs, comments.
separators = st.sampled_from([" ", "  ", "\n", "\t", " \n   ", " # note\n", "\r\n"])


def show(n, sep: str = " ", colon: bool = False) -> str:
    """Fully parenthesised text of an expression tree."""
    s = lambda m: show(m, sep, colon)  # noqa: E731
    args = lambda items: f",{sep}".join(s(i) for i in items)  # noqa: E731
    if isinstance(n, Int):
        return str(n.value)
    if isinstance(n, Bool):
        return "true" if n.value else "false"
    if isinstance(n, Name):
        return n.name
    if isinstance(n, Attr):
        return f"({s(n.obj)}).{n.name}"
    if isinstance(n, Index):
        return f"({s(n.obj)})[{args(n.args)}]"
    if isinstance(n, Call):
        return f"{n.func}({args(n.args)})"
    if isinstance(n, Neg):
        return f"(-{sep}({s(n.operand)}))"
    if isinstance(n, BinOp):
        return f"(({s(n.left)}){sep}{n.op}{sep}({s(n.right)}))"
    if isinstance(n, Compare):
        parts = [f"({s(n.operands[0])})"]
        for op, operand in zip(n.ops, n.operands[1:]):
            parts += [op, f"({s(operand)})"]
        return "(" + sep.join(parts) + ")"
    if isinstance(n, (And, Or)):
        word = "and" if isinstance(n, And) else "or"
        return f"(({s(n.left)}){sep}{word}{sep}({s(n.right)}))"
    if isinstance(n, Not):
        return f"(not{sep}({s(n.operand)}))"
    if isinstance(n, Quantifier):
        binder, then = (":", ":") if colon else ("in", ".")
        return f"({n.kind} {n.var}{sep}{binder} {n.cls}{sep}{then}{sep}({s(n.body)}))"
    raise TypeError(n)


targets = st.one_of(st.builds(Attr, small, names), st.builds(Index, small, st.lists(
    small, min_size=1, max_size=3).map(tuple)))
keyed = st.builds(Index, st.builds(Name, names), st.lists(small, min_size=1, max_size=3).map(tuple))
simple_effects = st.one_of(
    st.builds(Assign, targets, small),
    st.builds(Add, keyed, st.lists(st.tuples(names, small), max_size=3).map(tuple)),
    st.builds(Remove, keyed),
)


def _effect(depth: int):
    """An effect nested at most `depth` blocks deep."""
    if depth == 0:
        return simple_effects
    block = st.lists(_effect(depth - 1), min_size=1, max_size=2).map(tuple)
    maybe_block = st.one_of(st.just(()), block)
    return st.one_of(
        simple_effects,
        st.builds(If, st.lists(st.tuples(small, block), min_size=1, max_size=3).map(tuple), maybe_block),
        st.builds(First, names, names, small, block, maybe_block),
        st.builds(ForEach, names, names, st.one_of(st.none(), small), block),
    )


effect_lists = st.lists(_effect(2), min_size=1, max_size=3).map(tuple)


def show_effects(effs, sep: str = " ", trailing: bool = False, lines: bool = False) -> str:
    """Effects as text; with `lines`, one a line without `;` wherever the next effect cannot
    be read as continuing the one before (it does not start with `(`)."""
    s = lambda m: show(m, sep)  # noqa: E731

    def one(e) -> str:
        if isinstance(e, Assign):
            return f"{s(e.target)}{sep}={sep}({s(e.value)})"
        if isinstance(e, Add):
            inits = f",{sep}".join(f"{name} = ({s(v)})" for name, v in e.inits)
            return f"add {s(e.target)}{sep}{{{inits}}}"
        if isinstance(e, Remove):
            return f"remove {s(e.target)}"
        if isinstance(e, If):
            parts = []
            for i, (cond, body) in enumerate(e.branches):
                parts.append(f"{'if' if i == 0 else 'elif'} ({s(cond)}){sep}{{{block(body)}}}")
            if e.orelse:
                parts.append(f"else{sep}{{{block(e.orelse)}}}")
            return sep.join(parts)
        if isinstance(e, First):
            text = f"first {e.var} in {e.cls} where ({s(e.cond)}){sep}{{{block(e.body)}}}"
            return text + (f"{sep}else {{{block(e.orelse)}}}" if e.orelse else "")
        if isinstance(e, ForEach):
            where = f" where ({s(e.cond)})" if e.cond is not None else ""
            return f"forall {e.var} in {e.cls}{where}{sep}{{{block(e.body)}}}"
        raise TypeError(e)

    def join(body) -> str:
        texts = [one(e) for e in body]
        out = texts[0]
        for text in texts[1:]:
            out += ("\n" if lines and not text.startswith("(") else f";{sep}") + text
        return out

    def block(body) -> str:
        return f"{sep}" + join(body) + f"{sep}"

    return join(effs) + (";" if trailing else "")


PROPERTY = settings(max_examples=120, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow])


@PROPERTY
@given(expressions, separators, st.booleans())
def test_expression_round_trip(tree, sep, colon):
    text = show(tree, sep, colon)
    assert parse_expression(text, HERE) == tree, text


@settings(max_examples=60, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow])
@given(effect_lists, separators, st.booleans())
def test_effects_round_trip(effs, sep, trailing):
    text = show_effects(effs, sep, trailing)
    assert parse_effects(text, HERE) == effs, text


@settings(max_examples=60, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow])
@given(effect_lists, separators)
def test_effects_one_a_line_round_trip(effs, sep):
    text = show_effects(effs, sep, lines=True)
    assert parse_effects(text, HERE) == effs, text


TOKENS = ["a", "b", "f", "block", "1", "23", "true", "false", "not", "and", "or", "exists", "forall", "in",
          ":", ".", ",", "(", ")", "[", "]", "{", "}", ";", "=", "==", "!=", "<", "<=", ">", ">=", "+", "-",
          "*", "//", "%", "if", "elif", "else", "first", "where", "add", "remove", "#c\n", "\n", "$", "@",
          "'", '"', "\\", "\t", "/", "!", "&", "|", "^", "~", "`", "?", "é", "\x00"]
garbage = st.one_of(
    st.text(max_size=40),
    st.text(alphabet=st.sampled_from(list("ab01_ ()[]{}.,;:=<>!+-*/%#\n\t$'\"")), max_size=40),
    st.lists(st.sampled_from(TOKENS), max_size=25).map(" ".join),
    st.lists(st.sampled_from(TOKENS), max_size=25).map("".join),
)


def _parse_or_bcc_error(parse, text: str, where: Origin):
    try:
        result = parse(text, where)
    except BccError as exc:
        assert exc.path == where.path
        assert isinstance(exc.line, int) and exc.line >= where.line
        assert isinstance(exc.col, int) and exc.col >= 1
        assert "\n" not in str(exc) and "\r" not in str(exc), str(exc)
        assert str(exc).startswith(f"{where.path}:{exc.line}:{exc.col}: ")
        assert not re.search(r"\b(LPAR|RPAR|LSQB|RSQB|LBRACE|RBRACE|COMMA|SEMICOLON|EQUAL|CMP_OP|ADD_OP|MUL_OP)\b"
                             r"|__ANON|\$END", exc.message), exc.message
        return None
    assert isinstance(result, (ast.Node, tuple))
    return result


@settings(max_examples=200, deadline=None, database=None)
@given(garbage)
def test_garbage_parses_or_raises_bcc_error(text):
    where = Origin("g.yaml", 3, 9, indent=5)
    _parse_or_bcc_error(parse_expression, text, where)
    _parse_or_bcc_error(parse_effects, text, where)


@settings(max_examples=100, deadline=None, database=None)
@given(expressions, st.data())
def test_damaged_expressions_parse_or_raise_bcc_error(tree, data):
    text = show(tree)
    i = data.draw(st.integers(0, len(text)))
    j = data.draw(st.integers(i, min(len(text), i + 3)))
    insert = data.draw(st.sampled_from(["", "(", ")", ".", ",", " and ", "==", "[", "]", "$", "\n", "exists"]))
    _parse_or_bcc_error(parse_expression, text[:i] + insert + text[j:], Origin("g.yaml", 1, 1))
