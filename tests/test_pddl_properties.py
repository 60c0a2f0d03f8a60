"""Property tests of the PDDL front-end (hypothesis).

- The reader: generated s-expressions, printed with any spacing, comments and letter
  case, read back as the same lists; any text at all is read or refused with a BccError
  at a position inside the file, never another exception.
- The whole import: one-character mutations of a valid domain import or give a
  BccError, never a crash.
- Grounding and compiling: random small STRIPS tasks with negative preconditions,
  equality, constants and action costs; bcc's A* cost equals the optimum found by an
  independent brute-force planner written here (every binding of every action over all
  objects, PDDL semantics on sets of atoms, Dijkstra), and is None exactly when that
  planner finds no plan. Where Fast Downward is installed, a few tasks are also compared
  with its astar(blind()).
"""
from __future__ import annotations

import heapq
import itertools
import string
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bcc.errors import BccError
from bcc.pddl_io.importer import import_pddl
from bcc.pddl_io.read import SList, read_sexpr
from bcc.solvers import Budget, get_solver

HERE = Path(__file__).parent / "pddl"
SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])

# ---- the reader --------------------------------------------------------------------------
names = st.text(string.ascii_letters, min_size=1, max_size=1).flatmap(
    lambda first: st.text(string.ascii_letters + string.digits + "-_", max_size=6).map(lambda rest: first + rest))
atoms = st.one_of(names, names.map(lambda n: "?" + n), names.map(lambda n: ":" + n),
                  st.integers(0, 999).map(str))
trees = st.recursive(atoms, lambda inner: st.lists(inner, max_size=4), max_leaves=25)
gaps = st.sampled_from([" ", "  ", "\n", "\t", " ; a comment (with parens)\n", "\n\n  "])


def render(tree, draw_gap) -> str:
    if isinstance(tree, str):
        return tree
    return "(" + draw_gap() + draw_gap().join(render(t, draw_gap) for t in tree) + draw_gap() + ")"


def plain(tree):
    if isinstance(tree, str):
        return tree.lower()
    return [plain(t) for t in tree]


@SETTINGS
@given(st.lists(st.lists(trees, max_size=4), min_size=1, max_size=3), st.data())
def test_printed_sexpressions_read_back_the_same(tmp_path, forest, data):
    def gap():
        return data.draw(gaps)

    text = gap().join(render(t, gap) for t in forest)
    path = tmp_path / "x.pddl"
    path.write_text(text)
    got = read_sexpr(str(path))
    assert [plain(t) for t in got] == [plain(t) for t in forest]
    assert all(isinstance(t, SList) and t.line >= 1 and t.column >= 1 for t in got)


@SETTINGS
@given(st.text(alphabet=string.printable + "é(())", max_size=200))
def test_any_text_is_read_or_refused_at_a_position(tmp_path, text):
    path = tmp_path / "x.pddl"
    path.write_text(text)
    try:
        read_sexpr(str(path))
    except BccError as err:
        # lines as the reader (and an editor) counts them: "\r", "\r\n" and "\n" each end one
        lines = text.replace("\r\n", "\n").replace("\r", "\n").split("\n")
        assert err.line is not None and 1 <= err.line <= len(lines) + 1
        assert err.col is not None and 1 <= err.col <= len(lines[err.line - 1]) + 2 if err.line <= len(lines) else True


def _shape(item):
    """A read item with everything the front-end looks at: text, terminal and position."""
    if isinstance(item, SList):
        return ("list", item.line, item.column, [_shape(x) for x in item])
    return (str(item), item.type, item.line, item.column)


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet=" \n\t\x0b\xa0;()?:-_.=<>+*/aZ09é", max_size=60))
def test_the_fast_reader_agrees_with_lark_on_any_text(text):
    # read.py reads with a scanner made of the grammar's terminals and leaves what it
    # cannot read to lark's parser of grammar/pddl.lark: both must see the same items at
    # the same positions, and refuse the same texts (a refusal's message comes from lark).
    from lark.exceptions import UnexpectedInput

    from bcc.pddl_io.read import _parser, _scan
    text = text.lower()
    try:
        theirs = [_shape(x) for x in _parser().parse(text)]
    except UnexpectedInput:
        theirs = None
    ours = _scan(text)
    assert (None if ours is None else [_shape(x) for x in ours]) == theirs


def test_the_fast_reader_reads_the_grammars_terminals():
    # "-5" is a NUMBER (priority 2 beats NAME's "-"), "<=" two NAMEs as lark's regex has it,
    # a comment and whitespace are skipped, positions are 1-based.
    from bcc.pddl_io.read import _scan
    got = _scan("(a -5 <= ?x :k ; note\n  (b))")
    assert [(str(x), x.type, x.line, x.column) for x in got[0][:6]] == [
        ("a", "NAME", 1, 2), ("-5", "NUMBER", 1, 4), ("<", "NAME", 1, 7), ("=", "NAME", 1, 8),
        ("?x", "VARIABLE", 1, 10), (":k", "KEYWORD", 1, 13)]
    assert (got[0][6].line, got[0][6].column) == (2, 3)
    assert _scan("(a") is None and _scan("a)") is None and _scan("a.b") is None


@SETTINGS
@given(st.data())
def test_mutated_domains_import_or_give_one_error(tmp_path, data):
    text = (HERE / "briefcase-domain.pddl").read_text()
    k = data.draw(st.integers(0, len(text) - 1))
    how = data.draw(st.sampled_from(["delete", "insert", "replace"]))
    ch = data.draw(st.sampled_from(list("()?-: ax=\n;")))
    if how == "delete":
        text = text[:k] + text[k + 1:]
    elif how == "insert":
        text = text[:k] + ch + text[k:]
    else:
        text = text[:k] + ch + text[k + 1:]
    (tmp_path / "d.pddl").write_text(text)
    try:
        import_pddl(str(tmp_path / "d.pddl"), str(HERE / "briefcase-1.pddl"))
    except BccError as err:
        assert "\n" not in str(err)


# ---- random STRIPS tasks against a brute-force planner -----------------------------------
OBJECTS = ["o1", "o2", "o3"]
PREDICATES = {"p": 1, "q": 2, "r": 0}


@st.composite
def literals(draw, params, allow_eq):
    pred = draw(st.sampled_from(sorted(PREDICATES)))
    terms = params + ["o1"]                           # o1 is also a domain constant
    args = tuple(draw(st.sampled_from(terms)) for _ in range(PREDICATES[pred]))
    if allow_eq and len(params) >= 2 and draw(st.booleans()) and draw(st.booleans()):
        return ("=", params[0], params[1]), draw(st.booleans())
    return (pred, args), draw(st.booleans())


@st.composite
def tasks(draw):
    actions = []
    for k in range(draw(st.integers(1, 3))):
        params = ["?x", "?y"][:draw(st.integers(0, 2))]
        pre = draw(st.lists(literals(params, True), max_size=3))
        eff = draw(st.lists(literals(params, False), min_size=1, max_size=3))
        cost = draw(st.integers(0, 3))
        actions.append((f"a{k}", params, pre, eff, cost))
    all_atoms = [(p, args) for p, n in PREDICATES.items() for args in itertools.product(OBJECTS, repeat=n)]
    init = draw(st.sets(st.sampled_from(all_atoms), max_size=4))
    goal = draw(st.lists(st.tuples(st.sampled_from(all_atoms), st.booleans()), min_size=1, max_size=3))
    return actions, init, goal


def atom_text(atom) -> str:
    pred, args = atom
    return "(" + " ".join((pred, *args)) + ")"


def write_task(tmp_path, task):
    actions, init, goal = task
    lines = ["(define (domain rnd) (:requirements :strips :negative-preconditions :equality :action-costs)",
             "(:constants o1) (:predicates (p ?a) (q ?a ?b) (r)) (:functions (total-cost))"]
    for name, params, pre, eff, cost in actions:
        def lit(l):
            atom, positive = l
            text = f"(= {atom[1]} {atom[2]})" if atom[0] == "=" else atom_text(atom)
            return text if positive else f"(not {text})"
        lines.append(f"(:action {name} :parameters ({' '.join(params)})"
                     f" :precondition (and {' '.join(lit(l) for l in pre)})"
                     f" :effect (and {' '.join(lit(l) for l in eff)} (increase (total-cost) {cost})))")
    lines.append(")")
    (tmp_path / "d.pddl").write_text("\n".join(lines))
    goal_text = " ".join(atom_text(a) if pos else f"(not {atom_text(a)})" for a, pos in goal)
    (tmp_path / "p.pddl").write_text(
        f"(define (problem rp) (:domain rnd) (:objects o2 o3) (:init {' '.join(atom_text(a) for a in init)})"
        f" (:goal (and {goal_text})) (:metric minimize (total-cost)))")
    return str(tmp_path / "d.pddl"), str(tmp_path / "p.pddl")


def brute_force(task):
    """Dijkstra over sets of atoms, with every binding of every action (no grounding tricks)."""
    actions, init, goal = task
    ground = []
    for name, params, pre, eff, cost in actions:
        for combo in itertools.product(OBJECTS, repeat=len(params)):
            env = dict(zip(params, combo))

            def sub(atom):
                if atom[0] == "=":
                    return ("=", env.get(atom[1], atom[1]), env.get(atom[2], atom[2]))
                return (atom[0], tuple(env.get(t, t) for t in atom[1]))
            ground.append(([(sub(a), pos) for a, pos in pre], [(sub(a), pos) for a, pos in eff], cost))

    def holds(lit, state):
        atom, positive = lit
        value = atom[1] == atom[2] if atom[0] == "=" else atom in state
        return value == positive

    start = frozenset(init)
    best = {start: 0}
    heap = [(0, 0, start)]
    tie = 0
    while heap:
        g, _, state = heapq.heappop(heap)
        if g > best[state]:
            continue
        if all(holds(lit, state) for lit in goal):
            return g
        for pre, eff, cost in ground:
            if all(holds(lit, state) for lit in pre):
                dels = {a for a, pos in eff if not pos}
                adds = {a for a, pos in eff if pos}
                nxt = frozenset((state - dels) | adds)
                if g + cost < best.get(nxt, float("inf")):
                    best[nxt] = g + cost
                    tie += 1
                    heapq.heappush(heap, (g + cost, tie, nxt))
    return None


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(tasks())
def test_random_strips_tasks_have_the_brute_force_optimum(tmp_path, task):
    # as drawn (costs 0-3), and with every cost 1: blind A* tests goals at generation then
    for costs in ("drawn", "unit"):
        if costs == "unit":
            task = ([(*a[:4], 1) for a in task[0]], *task[1:])
        domain, problem = write_task(tmp_path, task)
        model = import_pddl(domain, problem)
        expected = brute_force(task)
        for heuristic in ("auto", "blind"):
            result = get_solver("astar")(model, Budget(time_limit=60), heuristic=heuristic)
            if expected is None:
                assert not result.solved and result.status == "no_solution"
            else:
                assert result.solved and result.cost == expected, (costs, heuristic)
                s = model.initial
                for step in result.plan:
                    s = model.apply(model.action_index(step), s)
                assert model.is_goal(s)


@pytest.mark.slow
@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(tasks())
def test_random_strips_tasks_match_fast_downward(tmp_path, task):
    fd = pytest.importorskip("bcc.solvers.fast_downward")
    if not fd.available():
        pytest.skip('Fast Downward is not installed: pip install "bcc[pddl]"')
    domain, problem = write_task(tmp_path, task)
    model = import_pddl(domain, problem)
    mine = get_solver("astar")(model, Budget(time_limit=60))
    theirs = fd.run(domain, problem, "astar(blind())", 60)
    assert theirs.status in ("solved", "no_solution"), theirs.message
    assert mine.solved == theirs.solved
    if mine.solved:
        assert mine.cost == theirs.cost
