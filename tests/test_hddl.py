"""The HDDL front end (hddl/read.py, grammar/hddl.lark): the hand-made examples in
tests/hddl/ read as written, every refusal is one positioned error, and properties:
the two readers of grammar/hddl.lark agree on any text, mutated files are read or
refused with a BccError, and any chain of `(< a b)` pairs is read in its one order."""
from __future__ import annotations

import random
import string
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bcc.errors import BccError
from bcc.hddl.read import GRAMMAR, read_hddl

HERE = Path(__file__).parent / "hddl"
SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
SHELVES = HERE / "shelves-domain.hddl"


def test_the_examples_read_as_written():
    htn = read_hddl(str(HERE / "delivery-domain.hddl"), str(HERE / "delivery-1.hddl"))
    assert set(htn.tasks) == {"deliver", "get-to"}
    assert [m.name for m in htn.methods] == ["m-deliver", "m-there", "m-drive", "m-via"]
    deliver = htn.methods[0]
    assert deliver.subtasks == (("get-to", ("?t", "?from")), ("load", ("?t", "?p", "?from")),
                                ("get-to", ("?t", "?to")), ("unload", ("?t", "?p", "?to")))
    assert htn.network.subtasks == (("deliver", ("p1", "d")),)
    assert htn.report == {"tasks": 2, "methods": 4, "actions": 3, "objects": 6, "facts": 8}


def test_subtasks_follow_the_ordering_and_constraints_join_the_precondition():
    htn = read_hddl(str(SHELVES), str(HERE / "shelves-1.hddl"))
    store = htn.methods[0]
    # listed check-then-move, ordered (< t1 t2): move comes first
    assert [s[0] for s in store.subtasks] == ["move", "check"]
    assert store.pre == ("and", (("and", (("atom", "on", ("?i", "bin")), ("atom", "free", ("?s",)))),
                                 ("not", ("=", "?s", "bin"))))
    assert htn.network.subtasks == (("store", ("i1",)), ("tidy", ()))
    assert htn.problem.objects["bin"] == "slot"   # the domain's constant


def _write(tmp_path, domain: str, problem: str | None = None):
    d, p = tmp_path / "d.hddl", tmp_path / "p.hddl"
    d.write_text(domain)
    p.write_text(problem if problem is not None else (HERE / "shelves-1.hddl").read_text())
    return str(d), str(p)


def _error(tmp_path, domain: str, problem: str | None = None) -> BccError:
    with pytest.raises(BccError) as info:
        read_hddl(*_write(tmp_path, domain, problem))
    return info.value


def _where(text: str, fragment: str) -> tuple[int, int]:
    """1-based line and column of `fragment`'s first occurrence in `text`."""
    k = text.index(fragment)
    return text.count("\n", 0, k) + 1, k - (text.rfind("\n", 0, k) + 1) + 1


SHELVES_TEXT = SHELVES.read_text()


@pytest.mark.parametrize("old,new,at,message", [
    # a network that is not totally ordered is refused at its :ordering
    (":ordering (and (< t1 t2))", ":ordering (and)", "(and)", "leaves subtasks t2 and t1 unordered"),
    (":ordering (and (< t1 t2))", "", ":subtasks (and (t2", ":subtasks has 2 subtasks and no :ordering"),
    (":ordering (and (< t1 t2))", ":ordering (and (< t1 t2) (< t2 t1))", "(and (< t1 t2) (< t2 t1))",
     "the ordering has a cycle"),
    ("(< t1 t2)", "(< t1 t3)", "t3)", "'t3' is not the id of a subtask"),
    ("(t2 (check ?s))", "(t2 (inspect ?s))", "inspect", "'inspect' is neither a task nor an action"),
    ("(t2 (check ?s))", "(t2 (check ?s ?s))", "(check ?s ?s)", "check takes 1 arguments, found 2"),
    (":task (store ?i)\n    :precondition (and (on ?i bin) (free ?s))",
     ":task (check ?s)\n    :precondition (and (on ?i bin) (free ?s))", "(check ?s)", "'check' is an action"),
    ("(free ?s))\n    :subtasks", "(free ?z))\n    :subtasks", "?z", "unknown variable '?z'"),
    (":method-preconditions)", ":method-preconditions :fancy)", ":fancy", "requirement ':fancy' is not supported"),
    (":constraints (not (= ?s bin)))", ":effect (not (= ?s bin)))", ":effect", ":effect in a method is not supported"),
    ("(:task tidy :parameters ())", "(:task tidy :parameters ())\n  (:task tidy :parameters ())",
     "(:task tidy :parameters ())\n\n", "'tidy' is declared twice"),   # at the second
])
def test_refusals_are_one_line_at_their_place(tmp_path, old, new, at, message):
    assert old in SHELVES_TEXT
    text = SHELVES_TEXT.replace(old, new, 1)
    err = _error(tmp_path, text)
    assert message in err.message, err.message
    assert (err.path, err.line, err.col) == (str(tmp_path / "d.hddl"), *_where(text, at)), str(err)


def test_a_partially_ordered_initial_network_is_refused_at_its_ordering(tmp_path):
    problem = (HERE / "shelves-1.hddl").read_text().replace("(and (< first later))", "()")
    err = _error(tmp_path, SHELVES_TEXT, problem)
    assert "unordered" in err.message and err.path.endswith("p.hddl")
    assert (err.line, err.col) == _where(problem, "())")


def test_a_problem_file_given_as_domain_says_so(tmp_path):
    err = _error(tmp_path, (HERE / "shelves-1.hddl").read_text())
    assert "this file defines a problem" in err.message


# ---- properties ----------------------------------------------------------------------------
def _shape(item):
    from bcc.pddl_io.read import SList
    if isinstance(item, SList):
        return ("list", item.line, item.column, [_shape(x) for x in item])
    return (str(item), item.type, item.line, item.column)


@settings(max_examples=200, deadline=None)
@given(st.text(alphabet=" \n\t;()?:-_.=<>+*/aZ09é", max_size=60))
def test_the_fast_reader_agrees_with_lark_on_hddl_text(text):
    from lark.exceptions import UnexpectedInput

    from bcc.pddl_io.read import _parser, _scan
    text = text.lower()
    try:
        theirs = [_shape(x) for x in _parser(GRAMMAR).parse(text)]
    except UnexpectedInput:
        theirs = None
    ours = _scan(text, GRAMMAR)
    assert (None if ours is None else [_shape(x) for x in ours]) == theirs


@SETTINGS
@given(st.data())
def test_mutated_hddl_is_read_or_refused_with_one_error(tmp_path, data):
    text = SHELVES_TEXT
    k = data.draw(st.integers(0, len(text) - 1))
    how = data.draw(st.sampled_from(["delete", "insert", "replace"]))
    ch = data.draw(st.sampled_from(list("()?-: ax=<\n;")))
    text = {"delete": text[:k] + text[k + 1:], "insert": text[:k] + ch + text[k:],
            "replace": text[:k] + ch + text[k + 1:]}[how]
    try:
        read_hddl(*_write(tmp_path, text))
    except BccError as err:
        assert err.line is not None and err.col is not None, str(err)


@SETTINGS
@given(st.integers(2, 7), st.randoms(use_true_random=False), st.booleans())
def test_any_chain_of_ordering_pairs_is_read_in_its_one_order(tmp_path, n, rnd, drop):
    """n subtasks listed shuffled, ordered by the chain's consecutive pairs plus random
    implied pairs: read in the chain's order; without one consecutive pair (and no pair
    implying it), refused as unordered."""
    chain = [f"s{i}" for i in range(n)]
    pairs = {(chain[i], chain[i + 1]) for i in range(n - 1)}
    pairs |= {(chain[i], chain[j]) for i in range(n) for j in range(i + 2, n) if rnd.random() < 0.3}
    if drop:
        gap = rnd.randrange(n - 1)
        pairs = {(a, b) for a, b in pairs if not (chain.index(a) <= gap < chain.index(b))}
    listed = chain[:]
    rnd.shuffle(listed)
    ordering = " ".join(f"(< {a} {b})" for a, b in sorted(pairs))
    subtasks = " ".join(f"({label} (check {'s1' if label == chain[0] else 's2'}))" for label in listed)
    problem = (HERE / "shelves-1.hddl").read_text().replace(
        "(and (later (tidy)) (first (store i1)))", f"(and {subtasks})").replace(
        "(and (< first later))", f"(and {ordering})")
    d, p = _write(tmp_path, SHELVES_TEXT, problem)
    if drop:
        with pytest.raises(BccError, match="unordered"):
            read_hddl(d, p)
    else:
        assert [args for _, args in read_hddl(d, p).network.subtasks] == [("s1",)] + [("s2",)] * (n - 1)


def test_the_docs_example_is_the_shipped_one():
    """docs/hddl.md writes the delivery files its commands run on: the same as tests/hddl/."""
    page = (Path(__file__).parent.parent / "docs" / "hddl.md").read_text()
    for name in ("delivery-domain.hddl", "delivery-1.hddl"):
        block = page.split(f"<!-- file: {name} -->\n```lisp\n", 1)[1].split("```", 1)[0]
        assert block == (HERE / name).read_text()
