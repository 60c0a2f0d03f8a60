"""Fuzzing through the CLI: mutated domain and dungeon files and random goals give a result
(exit 0 or 1) or bad input (exit 2, one line `file:line:col: message`), never an internal
error, a traceback or a hang.

The inputs are `fuzz_harness.make_case(seed)` (text, structure and expression mutations of
every shipped file, mutated domains, random `--goal`s) and `make_pddl_case(seed)` (mutated
s-expression trees of the PDDL test pairs through `bcc import pddl`), the same as
bench/fuzz.py, which runs 10,000+ of them. Here: 150 + 120 seeds in the quick loop and
600 + 480 marked slow, each under a time budget. A failing seed reproduces with
`python bench/fuzz.py [--pddl] --show SEED --out DIR`.
"""
from __future__ import annotations

import _thread
import threading
import time

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bcc.compiler.parse import parse_effects, parse_expression
from bcc.compiler.source import Origin, load_yaml_text
from bcc.errors import BccError
from fuzz_harness import Outcome, make_case, make_pddl_case, run_case

BUDGET_S = 60  # per input; a solve stops itself at 3 s, a compile takes well under 1 s


def run_with_budget(case, tmp_path):
    """The outcome, or "hang" past the budget. A thread interrupts the run (the CLI exits 130
    on an interrupt); no SIGALRM, which `bcc solve`'s own budget timer uses."""
    timer = threading.Timer(BUDGET_S, _thread.interrupt_main)
    start = time.monotonic()
    timer.start()
    try:
        outcome = run_case(case, tmp_path)
    except KeyboardInterrupt:
        outcome = None
    finally:
        timer.cancel()
    if outcome is None or time.monotonic() - start > BUDGET_S:
        return Outcome("hang", f"ran past {BUDGET_S} s")
    return outcome


def check_seeds(seeds, tmp_path_factory, make=make_case, solved_share=20):
    failures, kinds = [], {}
    for seed in seeds:
        case = make(seed)
        outcome = run_with_budget(case, tmp_path_factory.mktemp(f"case{seed}"))
        kinds[outcome.kind] = kinds.get(outcome.kind, 0) + 1
        if outcome.kind not in ("ok", "no-plan", "bad-input"):
            failures.append((seed, case.label, outcome.kind, outcome.site or outcome.detail))
    assert not failures, failures
    # The mutator reaches every stage: some inputs still compile and solve (at least one in
    # `solved_share`), most are refused.
    assert kinds.get("bad-input", 0) > len(seeds) // 3, kinds
    assert kinds.get("ok", 0) + kinds.get("no-plan", 0) > len(seeds) // solved_share, kinds


def test_mutated_inputs_give_a_result_or_bad_input(tmp_path_factory):
    check_seeds(range(150), tmp_path_factory)


@pytest.mark.slow
def test_many_mutated_inputs_give_a_result_or_bad_input(tmp_path_factory):
    check_seeds(range(150, 750), tmp_path_factory)  # bench/fuzz.py runs 10,000+


def test_mutated_pddl_gives_a_result_or_bad_input(tmp_path_factory):
    check_seeds(range(120), tmp_path_factory, make_pddl_case, solved_share=40)  # about 1 in 12 solve


@pytest.mark.slow
def test_many_mutated_pddl_files_give_a_result_or_bad_input(tmp_path_factory):
    check_seeds(range(120, 600), tmp_path_factory, make_pddl_case, solved_share=40)  # bench/fuzz.py --pddl runs thousands


def test_the_mutator_is_deterministic():
    assert make_case(7) == make_case(7)
    assert make_case(7) != make_case(8)
    assert make_pddl_case(7) == make_pddl_case(7)
    assert make_pddl_case(7) != make_pddl_case(8)


# ---- the parser and the loader directly, with hypothesis -------------------------------
WHERE = Origin("x.yaml", 3, 7)
EXPR_ALPHABET = st.sampled_from(["a", "b", "x", "1", "99999999999", "(", ")", "[", "]", "{", "}", ".", ",", ";",
                                 " and ", " or ", "not ", " + ", " - ", " * ", " // ", " == ", " < ", "exists v in c . ",
                                 "if ", "else ", "first ", " where ", "add ", "remove ", "=", "-", "true", "#", "\n"])


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(EXPR_ALPHABET, max_size=60), st.integers(0, 250))
def test_any_expression_text_parses_or_is_a_positioned_error(parts, repeat):
    text = "".join(parts)
    for candidate in (text, "not " * repeat + text, "(" * repeat + text + ")" * repeat,
                      " and ".join([text or "a"] * (repeat + 1))):
        for parse in (parse_expression, parse_effects):
            try:
                parse(candidate, WHERE)
            except BccError as exc:
                assert exc.path == "x.yaml" and exc.line >= 3 and exc.col >= 1, str(exc)
                assert "\n" not in str(exc)


YAML_ALPHABET = st.sampled_from(["a", ": ", "- ", "[", "]", "{", "}", ",", "\n", "  ", "&x ", "*x", "!!str ",
                                 "!!timestamp ", "!!binary ", "!!set ", "? ", "|", ">", "'", '"', "\\ud800", "\\x00",
                                 "1", "99999999999999999999999999999999999999999999", "0x1F", "1:30", "~", "#", "%",
                                 "<<: ", "---", "\t", "\x00", "\x1b", "é"])


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(YAML_ALPHABET, max_size=80))
def test_any_yaml_text_loads_or_is_an_error_with_a_place(parts):
    try:
        load_yaml_text("".join(parts), "y.yaml")
    except BccError as exc:
        assert exc.path == "y.yaml", str(exc)
        assert "\n" not in str(exc)
