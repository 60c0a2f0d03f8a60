"""Bad or unsupported PDDL: one line `file:line:col: message`, exit 2, never a traceback.

Each case changes one thing in a small valid domain; the expected position is counted by
hand in the text (line, then column of the first character of the offending token).
"""
import subprocess
import sys
from pathlib import Path

import pytest

from bcc.errors import BccError
from bcc.pddl_io.importer import import_pddl

HERE = Path(__file__).parent / "pddl"

DOMAIN = """(define (domain d)
  (:requirements :strips :typing)
  (:types box place)
  (:predicates (at ?b - box ?p - place) (open))
  (:action carry
    :parameters (?b - box ?from ?to - place)
    :precondition (and (at ?b ?from) (open))
    :effect (and (not (at ?b ?from)) (at ?b ?to))))
"""
PROBLEM = """(define (problem p)
  (:domain d)
  (:objects b1 - box x y - place)
  (:init (at b1 x) (open))
  (:goal (at b1 y)))
"""


def run(tmp_path, domain=DOMAIN, problem=PROBLEM):
    (tmp_path / "d.pddl").write_text(domain)
    (tmp_path / "p.pddl").write_text(problem)
    return subprocess.run([sys.executable, "-m", "bcc", "import", "pddl", str(tmp_path / "d.pddl"),
                           str(tmp_path / "p.pddl")], capture_output=True, text=True)


def test_the_base_case_solves(tmp_path):
    r = run(tmp_path)
    assert r.returncode == 0 and r.stdout.splitlines() == ["(carry b1 x y)"]


CASES = [
    # (what, replace in domain, replace in problem, file, line, col, message)
    ("a durative action", ("(:action carry", "(:durative-action carry"), None, "d", 5, 4,
     ":durative-action is not supported"),
    ("a recursive derived predicate", ("  (:action carry", "  (:derived (open) (open))\n  (:action carry"), None,
     "d", 5, 3, "a recursive derived predicate ('open' depends on itself) is not supported"),
    ("a derived predicate an action changes",
     ("  (:action carry", "  (:derived (at ?b - box ?p - place) (open))\n  (:action carry"), None,
     "d", 6, 3, "action 'carry' changes 'at', a derived predicate"),
    ("a derived predicate in :init", ("  (:action carry", "  (:derived (open) (exists (?b - box) (at ?b y)))\n"
                                      "  (:action carry"), None, "p", 4, 20,
     "'open' is a derived predicate: it holds where its rules say, never by :init"),
    ("a derived predicate not declared", ("  (:action carry", "  (:derived (shut) (open))\n  (:action carry"), None,
     "d", 5, 13, "'shut' is not a predicate of the domain (declare it in :predicates)"),
    ("a numeric effect", ("(at ?b ?to))))", "(at ?b ?to) (decrease (fuel) 1))))"), None, "d", 8, 51,
     "the numeric effect decrease is not supported"),
    ("a numeric comparison", ("(open))\n    :effect", "(< 1 2))\n    :effect"), None, "d", 7, 39,
     "the numeric comparison < is not supported"),
    ("an unknown requirement", (":typing)", ":typing :magic)"), None, "d", 2, 34,
     "requirement ':magic' is not supported"),
    ("an unknown predicate", ("(open))\n    :effect", "(opened))\n    :effect"), None, "d", 7, 39,
     "'opened' is an undeclared predicate, not a predicate of the domain"),
    ("a wrong arity", ("(and (at ?b ?from) (open))", "(and (at ?b) (open))"), None, "d", 7, 24,
     "at takes 2 arguments, found 1"),
    ("an unknown type", ("(?b - box ?from", "(?b - crate ?from"), None, "d", 6, 23, "unknown type 'crate'"),
    ("an unknown variable", ("(at ?b ?to))))", "(at ?b ?where))))"), None, "d", 8, 45, "unknown variable '?where'"),
    ("a missing parenthesis", ("(and (at ?b ?from) (open))", "(and (at ?b ?from) (open)"), None, "d", 7, 19,
     "this '(' is never closed"),
    ("a stray parenthesis", ("(open))\n  (:action", "(open)))\n  (:action"), None, "d", 4, 48,
     "this ')' closes the file's first list, but more text follows: one ')' too many before it"),
    ("an unexpected character", ("(open))\n  (:action", "(open) {)\n  (:action"), None, "d", 4, 48,
     "unexpected character '{' in PDDL"),
    ("an unknown object", None, ("(at b1 y)", "(at b9 y)"), "p", 5, 14, "unknown object or constant 'b9'"),
    ("a timed initial literal", None, ("(open))", "(at 10 (open)))"), "p", 4, 20, "a timed initial literal is not supported"),
    ("a metric other than total-cost", None, ("(at b1 y)))", "(at b1 y))\n  (:metric maximize (total-cost)))"),
     "p", 6, 3, "a metric other than (minimize (total-cost)) is not supported"),
    ("a missing goal", None, ("  (:goal (at b1 y)))", ")"), "p", 1, 1, "the problem has no :goal"),
]


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_bad_pddl_is_one_positioned_line_and_exit_2(tmp_path, case):
    _, in_domain, in_problem, which, line, col, message = case
    domain, problem = DOMAIN, PROBLEM
    if in_domain:
        assert in_domain[0] in domain
        domain = domain.replace(in_domain[0], in_domain[1], 1)
    if in_problem:
        assert in_problem[0] in problem
        problem = problem.replace(in_problem[0], in_problem[1], 1)
    r = run(tmp_path, domain, problem)
    assert r.returncode == 2, r.stderr
    assert r.stdout == ""
    assert r.stderr.strip().splitlines() == [f"{tmp_path / (which + '.pddl')}:{line}:{col}: {message}"]


def test_a_cost_function_without_a_value(tmp_path):
    problem = (HERE / "road-1.pddl").read_text().replace("(= (road-length b c) 1)", "")
    (tmp_path / "p.pddl").write_text(problem)
    with pytest.raises(BccError, match=r"reads \(road-length b c\), which the problem's :init does not give"):
        import_pddl(str(HERE / "road-domain.pddl"), str(tmp_path / "p.pddl"))
    with pytest.raises(BccError) as caught:   # positioned at the action whose cost it is
        import_pddl(str(HERE / "road-domain.pddl"), str(tmp_path / "p.pddl"))
    assert caught.value.path.endswith("road-domain.pddl") and caught.value.line is not None


@pytest.mark.parametrize("text", ["", "; only a comment\n"])
def test_a_file_without_a_define_is_positioned_at_its_start(tmp_path, text):
    (tmp_path / "p.pddl").write_text(text)
    with pytest.raises(BccError, match=r"found 0") as caught:
        import_pddl(str(HERE / "road-domain.pddl"), str(tmp_path / "p.pddl"))
    assert (caught.value.line, caught.value.col) == (1, 1)


def test_a_fractional_cost_is_refused_at_its_position(tmp_path):
    problem = (HERE / "road-1.pddl").read_text().replace("(= (road-length a b) 1)", "(= (road-length a b) 1.5)")
    (tmp_path / "p.pddl").write_text(problem)
    with pytest.raises(BccError) as err:
        import_pddl(str(HERE / "road-domain.pddl"), str(tmp_path / "p.pddl"))
    assert "is not supported" in err.value.message and err.value.line == 6


def test_a_directory_or_binary_file_is_one_line(tmp_path):
    (tmp_path / "bin.pddl").write_bytes(b"\x00\xff\xfe(define")
    r = subprocess.run([sys.executable, "-m", "bcc", "import", "pddl", str(tmp_path / "bin.pddl"),
                        str(HERE / "gripper-3.pddl")], capture_output=True, text=True)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1


def test_swapped_files_say_the_domain_comes_first():
    r = subprocess.run([sys.executable, "-m", "bcc", "import", "pddl", str(HERE / "gripper-3.pddl"),
                        str(HERE / "gripper-domain.pddl")], capture_output=True, text=True)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1
    assert "gripper-3.pddl:" in r.stderr and "this file defines a problem" in r.stderr and "DOMAIN PROBLEM" in r.stderr
    # and a domain given as the problem
    with pytest.raises(BccError) as err:
        import_pddl(str(HERE / "gripper-domain.pddl"), str(HERE / "gripper-domain.pddl"))
    assert "this file defines a domain" in err.value.message
