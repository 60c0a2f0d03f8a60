"""The contract of every registered solver, in the spirit of Gymnasium's `check_env`:
the signature `solve(model, budget, progress=None, **options) -> Result`, declared options
that match it, budgets respected, plans that replay to the goal at the reported cost,
BFS's cost for every solver that declares itself optimal, and `Result` built with keywords.

Every solver `list_solvers()` names is checked, plugins included; one that cannot run here
(e.g. `fd` without Fast Downward) is skipped with its own reason.
"""
from __future__ import annotations

import ast
import inspect
import textwrap

import pytest

from bcc.cli.shared import SOLVER_FLAGS
from bcc.simulate import replay
from bcc.solvers import BUILTIN, Budget, Result, get_solver, list_solvers
from bcc.solvers.options import Option, check_options, keywords_of, options_of, unavailable
from conftest import compiled

SOLVERS = list(list_solvers())
# Settings that learn the grid (both) and the bridge (R-max) within seconds; Q-learning
# needs far more episodes for the bridge, where its run is skipped when it has not learned.
QUICK = {"rmax": {"model": "oo", "episodes": 8}, "qlearning": {"episodes": 1000}}


def runnable(name: str):
    solve = get_solver(name)
    why = unavailable(solve)
    if why:
        pytest.skip(f"{name}: {why}")
    if getattr(solve, "input", None) == "task network":
        pytest.skip(f"{name} plans task networks, not dungeons (tests/test_htn.py holds it to its contract)")
    return solve


@pytest.mark.parametrize("name", SOLVERS)
def test_signature(name):
    solve = get_solver(name)
    solve = getattr(solve, "__wrapped__", solve)
    params = list(inspect.signature(solve).parameters.values())
    assert [p.name for p in params[:3]] == ["model", "budget", "progress"], name
    assert params[2].default is None
    assert params[-1].kind is inspect.Parameter.VAR_KEYWORD, f"{name}: solve must accept **options"
    for option in options_of(solve):
        assert isinstance(option, Option)
        assert option.check(option.default, option.name) == option.default, f"{name}: default of {option.name}"
        param = inspect.signature(solve).parameters.get(option.argument)
        if param is not None and param.default is not inspect.Parameter.empty and param.default is not None:
            assert param.default == option.default, f"{name}: {option.name} declared {option.default}, " \
                                                    f"solve's default {param.default}"


@pytest.mark.parametrize("name", [n for n in SOLVERS if n in BUILTIN])
def test_the_declaration_lists_every_keyword(name):
    """A built-in solver takes no keyword it does not declare (those only bcc passes, such
    as the run path's optimal_cost, are declared `internal`): the declaration is the
    whole interface, and each declared default is the signature's."""
    solve = get_solver(name)
    params = {p.name: p.default for p in inspect.signature(solve).parameters.values()
              if p.kind is not inspect.Parameter.VAR_KEYWORD}
    keywords = set(params) - {"model", "budget", "progress"}
    assert keywords == set(keywords_of(solve)), name
    for option in solve.options:
        assert params[option.argument] == option.default, f"{name}: {option.name}"


@pytest.mark.parametrize("name", [n for n in SOLVERS if n in BUILTIN])
def test_every_builtin_option_has_a_flag(name):
    for option in options_of(get_solver(name)):
        assert option.name in SOLVER_FLAGS, f"{name}: --{option.name} is not a flag of bcc solve"


@pytest.mark.parametrize("name", SOLVERS)
def test_results_are_built_with_keywords(name):
    module = inspect.getmodule(get_solver(name))
    tree = ast.parse(textwrap.dedent(inspect.getsource(module)))
    positional = [node.lineno for node in ast.walk(tree)
                  if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "Result" and node.args]
    assert not positional, f"{module.__name__}: Result(...) with positional arguments at lines {positional}"


@pytest.mark.parametrize("name", SOLVERS)
@pytest.mark.parametrize("dungeon", ["grid", "bridge"])
def test_plans_replay_at_their_cost(name, dungeon):
    solve = runnable(name)
    model = compiled(dungeon)
    options = check_options(name, QUICK.get(name, {}))
    result = solve(model, Budget(time_limit=120), **options)
    assert isinstance(result, Result) and result.solver == name
    assert result.status in ("solved", "no_solution", "budget")
    assert result.solved == (result.status == "solved")
    if name in QUICK and not result.solved:
        pytest.skip(f"{name} did not learn {dungeon} in {QUICK[name]['episodes']} episodes")
    assert result.solved, result.message
    replayed = replay(model, [(a, i + 1, 1) for i, a in enumerate(result.plan)], "<plan>")
    assert replayed.valid, replayed.message
    assert result.cost == sum(model.action_costs[model.action_index(a)] for a in result.plan)
    if getattr(solve, "optimal", False):
        bfs = get_solver("bfs")(model, Budget(time_limit=120))
        assert result.cost == bfs.cost, f"{name} claims optimality: cost {result.cost}, BFS {bfs.cost}"


LIMIT = 0.02   # seconds: less than any solver needs for tough_maze's plan (BFS stores ~10^5 states)
SLACK = 3.0    # a solver checks its budget every CHECK_EVERY expansions; heuristics are built first


@pytest.mark.parametrize("name", SOLVERS)
def test_a_time_limit_is_respected(name):
    solve = runnable(name)
    options = check_options(name, {"episodes": 10_000} if name in QUICK else {})
    result = solve(compiled("tough_maze"), Budget(time_limit=LIMIT), **options)
    assert result.seconds < LIMIT + SLACK, f"{name} ran {result.seconds} s on a {LIMIT} s budget"
    if not result.solved:
        assert result.status == "budget" and result.budget == "time_limit", result


@pytest.mark.parametrize("name", [n for n in SOLVERS if n not in QUICK])
def test_a_state_budget_is_respected(name):
    """`stored` counts what the solver keeps (IDA*: the path); a run that kept more than
    the budget allows must have stopped for it."""
    if name == "fd":
        pytest.skip("Fast Downward runs in its own process and stores no bcc states: --max-states cannot bind it "
                    "(on the tough maze it stops at the time limit instead)")
    solve = runnable(name)
    result = solve(compiled("tough_maze"), Budget(max_states=200, time_limit=60))
    if result.stored > 200:
        assert result.status == "budget" and result.budget == "max_states", result
    assert result.status != "budget" or result.budget == "max_states", result


@pytest.mark.parametrize("name", [n for n in SOLVERS if n in BUILTIN])
def test_every_builtin_option_is_a_field_of_post_solve(name):
    pytest.importorskip("pydantic")
    from bcc.serve.options import option_fields
    from bcc.serve.schemas import SolveRequest
    fields = option_fields(SolveRequest)
    for option in options_of(get_solver(name)):
        assert option.name in fields, f"{name}: POST /solve has no field {option.name!r}"


def test_idastar_state_budget_bounds_what_it_expands():
    """IDA* keeps only its path, so --max-states bounds the states it expands: without
    that, a state budget never stopped it (the tough maze needs far more than 300)."""
    result = runnable("idastar")(compiled("tough_maze"), Budget(max_states=300, time_limit=60))
    assert result.status == "budget" and result.budget == "max_states", result
    assert result.expanded == 301
