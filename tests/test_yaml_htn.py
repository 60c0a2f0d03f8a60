"""Compound tasks and methods in YAML domains (compiler/tasks.py, compiler/hierarchy.py),
tasks as goals (`task:`, --task) and the htn solver on compiled dungeons
(solvers/htn/model_network.py). Plans below are derived by hand from the methods."""
from __future__ import annotations

import json
import textwrap
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from bcc.compiler import compile_dungeon
from bcc.compiler.domain import load_domain
from bcc.errors import BccError
from bcc.simulate import replay
from bcc.solvers import Budget, default_solver, get_solver

HERE = Path(__file__).resolve().parent
YARD = str(HERE / "htn_yaml" / "yard.yaml")


@pytest.fixture
def cli():
    """`bcc ARGS...` in this process: exit_code, output (stdout and stderr), stdout."""
    from click.testing import CliRunner
    from bcc.cli import main
    return lambda *args: CliRunner().invoke(main, [str(a) for a in args], catch_exceptions=False)


def plan_of(model) -> list:
    result = get_solver("htn")(model, Budget(time_limit=60))
    assert result.solved, result.message
    return result.plan


def valid(model, plan) -> bool:
    return replay(model, [(a, 1, 1) for a in plan]).valid


# ---- plans derived by hand ------------------------------------------------------------

def test_one_ring_is_climb_then_four_rows_clockwise():
    # walls(1, 3, 3, bricks) from the corner (0, 1, 0): ring_clockwise climbs (a block
    # where the feet were), then rows east 2, south 2, west 2, north 2; each lay places
    # one below the feet in front and steps onto it, except the last of the north row,
    # which finds the block climbed onto and only steps: 1 + 2 * 7 + 1 = 16 actions.
    model = compile_dungeon(YARD)
    lay = lambda d: [f"place_down_{d}", f"move_{d}"]  # noqa: E731
    expected = ["climb"] + lay("east") * 2 + lay("south") * 2 + lay("west") * 2 + lay("north") + ["move_north"]
    plan = plan_of(model)
    assert plan == expected
    assert valid(model, plan)        # the ring's structure goal holds after the last step


def test_a_method_that_fails_late_is_backtracked():
    # detour_east (estimate 1 + 2) is tried before detour_south (1 + 3); its descend
    # cannot apply on bedrock, so the search undoes move_east and takes detour_south.
    model = compile_dungeon(YARD, task="detour()", goal="true")
    assert plan_of(model) == ["move_south", "move_north", "move_south"]


def test_a_variable_is_bound_by_its_range_and_one_by_an_equality():
    # step_free: d = 0 (north) leaves the world at z = -1; d = 1 (east) is free.
    assert plan_of(compile_dungeon(YARD, task="step_free()", goal="true")) == ["move_east"]
    # two_east: tx == agent.x + 2 = 2, then go_x(2) steps east twice.
    assert plan_of(compile_dungeon(YARD, task="two_east()", goal="true")) == ["move_east", "move_east"]


def test_recursion_with_arithmetic_in_the_arguments():
    # count_down(n) steps south on odd n, east on even n, then count_down(n - 1).
    plan = plan_of(compile_dungeon(YARD, task="count_down(4)", goal="true"))
    assert plan == ["move_east", "move_south", "move_east", "move_south"]


def test_the_goal_beside_a_task_must_hold_after_it():
    # go_x(2) ends at x = 2 by its only decomposition: a goal x == 3 cannot hold after it.
    model = compile_dungeon(YARD, task="go_x(2)", goal="agent.x == 3")
    result = get_solver("htn")(model, Budget(time_limit=60))
    assert not result.solved and result.status == "no_solution"
    assert plan_of(compile_dungeon(YARD, task="go_x(2)", goal="agent.x == 2")) == ["move_east", "move_east"]


def test_bcc_solve_picks_htn_for_a_task_and_the_json_has_the_tree(cli):
    model = compile_dungeon(YARD)
    assert default_solver(model) == "htn"
    out = cli("solve", YARD, "--task", "two_east()", "--goal", "true", "--json")
    assert out.exit_code == 0, out.output
    data = json.loads(out.stdout)
    assert data["solver"] == "htn" and data["plan"] == ["move_east", "move_east"]
    tree = data["decomposition"]
    # actions 0, 1; then two_east() (2) -> go_x(2) (3) -> step(1) (4), go_x(2) (5) -> ...
    by_id = {t["id"]: t for t in tree["tasks"]}
    (top,) = tree["root"]
    assert by_id[top]["task"] == "two_east()" and by_id[top]["method"] == "two_east_x"
    (go,) = by_id[top]["subtasks"]
    assert by_id[go]["task"] == "go_x(2)" and by_id[go]["method"] == "go_x_east"


def test_plans_replay_in_bcc_validate(cli, tmp_path):
    plan = tmp_path / "plan.txt"
    out = cli("solve", YARD, "-o", str(plan))
    assert out.exit_code == 0, out.output
    assert len(plan.read_text().splitlines()) == 16 and plan.read_text().startswith("climb\n")
    check = cli("validate", YARD, str(plan))
    assert check.exit_code == 0 and "goal holds after the last" in check.output
    plan.write_text("".join(a + "\n" for a in plan.read_text().splitlines()[:-3]))   # the last block not laid
    assert cli("validate", YARD, str(plan)).exit_code == 1


def test_a_dungeon_without_a_task_is_refused_by_htn(cli):
    out = cli("solve", "bridge", "--solver", "htn")
    assert out.exit_code == 2 and "task" in out.output


def test_compile_json_lists_tasks_and_methods(cli):
    out = cli("compile", YARD, "--json")
    data = json.loads(out.stdout)
    assert data["task"] == ["walls(1, 3, 3, bricks)"]
    assert data["tasks"]["count_down"] == ["n: int"] and "house" in data["tasks"]
    assert data["methods"]["two_east_x"] == {"task": "two_east", "vars": ["tx: int"], "pre": ["tx == agent.x + 2"],
                                             "subtasks": ["go_x(tx)"]}


@pytest.mark.parametrize("size", [(3, 3, 2), (5, 4, 3)])
def test_a_generated_house_is_one_task(cli, tmp_path, size):
    w, l, h = size
    path = tmp_path / "house.yaml"
    assert cli("generate", "house", "--width", str(w), "--length", str(l), "--height", str(h), "--as-task",
               "-o", str(path)).exit_code == 0
    assert f"task: house(2, 2, {w}, {l}, {h}, planks)" in path.read_text()
    model = compile_dungeon(str(path))
    plan = plan_of(model)
    assert valid(model, plan)        # the blueprint (door and inside air included) holds at the end
    # the walls are laid from on top: one climb per layer and one for the roof's rim
    assert plan.count("climb") == h + 1 and plan[-2:] == ["break_north", "break_up_north"]


# ---- positioned refusals ----------------------------------------------------------------

def domain_file(tmp_path, body: str) -> Path:
    """A domain extending mason: two lines, then `body` (so body line n is file line n + 2)."""
    path = tmp_path / "d.yaml"
    path.write_text("domain: d\nextends: mason\n" + textwrap.dedent(body))
    return path


def dungeon_file(tmp_path, task: str = "t()") -> Path:
    text = (HERE / "htn_yaml" / "yard.yaml").read_text().replace("domain: errands.yaml", "domain: d.yaml")
    text = text.replace("task: walls(1, 3, 3, bricks)", f"task: {task}")
    path = tmp_path / "yard.yaml"
    path.write_text(text)
    return path


LOAD_ERRORS = [
    ("methods:\n  m: {task: nothere, subtasks: []}\n", 2, "unknown task 'nothere'"),
    ("tasks:\n  t: {}\nmethods:\n  m: {task: t, subtasks: [move_east(agent), t(1)]}\n", 4, "t takes 0 argument(s), found 1"),
    ("tasks:\n  t: {}\nmethods:\n  m:\n    task: t\n    subtasks:\n      - jump(agent)\n", 7,
     "unknown task or action 'jump'"),
    ("tasks:\n  t: {}\nmethods:\n  m: {task: move_east, subtasks: []}\n", 4, "it is an action"),
    ("tasks:\n  move_east: {}\n", 2, "both a task and an action"),
    ("tasks:\n  t: {params: {n: int}}\nmethods:\n  m: {task: t, vars: {n: int}, subtasks: []}\n", 4,
     "already a parameter"),
    ("tasks:\n  t: {}\nmethods:\n  m: {task: t, subtasks: [step(1, 2)]}\n", 4, "YAML splits calls"),
    ("tasks:\n  t: {}\nmethods:\n  m: {task: t, pre: [free(1, 2, 3)], subtasks: []}\n", 4, "YAML splits calls"),
    ("tasks:\n  t: {}\nmethods:\n  m: {task: t, subtasks: [1 + 2]}\n", 4, "a subtask is a call"),
    ("tasks:\n  t: {params: {n: integer}}\n", 2, "unknown type or class 'integer'"),
    ("tasks:\n  t: {}\nmethods:\n  m: {task: t, subtask: []}\n", 4, "unknown key 'subtask'"),
    ("tasks:\n  t: {}\nmethods:\n  m: {task: t, subtasks: [], vars: {" + ", ".join(f"v{i}: bool" for i in range(17))
     + "}}\n", 4, "17 variables; at most 16"),
]


@pytest.mark.parametrize("body,line,message", LOAD_ERRORS)
def test_bad_tasks_and_methods_are_refused_at_their_place(tmp_path, body, line, message):
    path = domain_file(tmp_path, body)
    with pytest.raises(BccError) as exc:
        load_domain(path)
    assert message in exc.value.message
    assert exc.value.path == str(path) and exc.value.line == line + 2


COMPILE_ERRORS = [
    # an int variable nothing binds
    ("tasks:\n  t: {}\nmethods:\n  m: {task: t, vars: {v: int}, pre: v > 0, subtasks: []}\n", "t()", 4,
     "variable 'v' of method 'm' is not bound"),
    # a name no one declared
    ("tasks:\n  t: {}\nmethods:\n  m: {task: t, pre: q > 0, subtasks: []}\n", "t()", 4, "unknown name 'q'"),
    # an argument of the wrong type
    ("tasks:\n  t: {params: {n: int}}\nmethods:\n  m: {task: t, subtasks: [t(agent)]}\n", "t(1)", 4,
     "argument 'n' of t is int, found agent"),
    # an action's argument that is not an object
    ("tasks:\n  t: {}\nmethods:\n  m: {task: t, subtasks: [move_east(3)]}\n", "t()", 4,
     "must be an object of the class 'agent'"),
]


@pytest.mark.parametrize("body,task,line,message", COMPILE_ERRORS)
def test_method_type_errors_are_refused_when_a_dungeon_is_compiled(cli, tmp_path, body, task, line, message):
    domain_file(tmp_path, body)
    path = dungeon_file(tmp_path, task)
    out = cli("compile", str(path))
    assert out.exit_code == 2
    first = out.output.strip().splitlines()[0]
    assert message in first and first.startswith(f"{tmp_path / 'd.yaml'}:{line + 2}:"), first


def test_a_method_dividing_by_zero_is_a_domain_error_at_its_place(cli, tmp_path):
    # agent.x - agent.x is 0 in every state and no constant the compiler folds
    domain_file(tmp_path, "tasks:\n  t: {}\nmethods:\n  m: {task: t, pre: 1 // (agent.x - agent.x) == 0, subtasks: []}\n")
    out = cli("solve", str(dungeon_file(tmp_path, "t()")))
    assert out.exit_code == 2, out.output
    assert f"{tmp_path / 'd.yaml'}:6:" in out.output and "`//` by zero" in out.output


def test_a_bad_task_in_a_dungeon_is_refused_at_its_place(cli, tmp_path):
    domain_file(tmp_path, "tasks:\n  t: {params: {n: int}}\nmethods:\n  m: {task: t, subtasks: []}\n")
    path = dungeon_file(tmp_path, "t(1, 2)")
    out = cli("compile", str(path))
    assert out.exit_code == 2 and "t takes 1 argument(s), found 2" in out.output
    assert out.output.startswith(f"{path}:")
    path = dungeon_file(tmp_path, "3 + 4")
    out = cli("compile", str(path))
    assert out.exit_code == 2 and "a task is a call" in out.output


# ---- the parser piece, as a property ----------------------------------------------------

NAMES = st.sampled_from(["t", "u", "row", "move_east", "step", "x1"])
ARG = st.one_of(st.integers(0, 9).map(str), st.sampled_from(["n", "n - 1", "agent", "agent.x + 1", "k", "("]))
CALL = st.builds(lambda f, args: f"{f}({', '.join(args)})", NAMES, st.lists(ARG, max_size=3))


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(task_params=st.lists(st.sampled_from(["int", "bool", "material", "agent", "nonsense"]), max_size=3),
       calls=st.lists(st.one_of(CALL, st.sampled_from(["", "t(", "1 +", "not"])), max_size=4),
       pre=st.sampled_from([None, "n > 0", "n >", "true", "[1, 2]"]))
def test_any_tasks_section_loads_or_is_refused_with_a_position(tmp_path, task_params, calls, pre):
    params = ", ".join(f"p{i}: {t}" for i, t in enumerate(task_params))
    body = f"tasks:\n  t:\n    params: {{{params}}}\n  u: {{}}\nmethods:\n  m:\n    task: t\n"
    if pre is not None:
        body += f"    pre: {json.dumps(pre)}\n"
    body += "    subtasks:\n" + "".join(f"      - {json.dumps(c)}\n" for c in calls) if calls else "    subtasks: []\n"
    path = domain_file(tmp_path, body)
    try:
        dom = load_domain(path)
    except BccError as exc:
        assert exc.path == str(path) and exc.line >= 3
        return
    # loaded: every subtask is a call of a known task or action with its arity
    m = dom.methods["m"]
    assert [e.node.func for e in m.subtasks] == [c.split("(")[0] for c in calls]
    for e in m.subtasks:
        known = dom.tasks.get(e.node.func) or dom.actions[e.node.func]
        assert len(e.node.args) == len(known.params)


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(lo=st.integers(-3, 3), span=st.integers(0, 6), m=st.integers(1, 4), r=st.integers(0, 3), a=st.integers(-3, 6),
       by_equality=st.booleans())
def test_method_bindings_are_exactly_those_the_precondition_allows(tmp_path, lo, span, m, r, a, by_equality):
    # A variable bound by its range (or by an equality) yields one decomposition per value
    # satisfying the precondition: compared with the values a brute-force loop finds.
    from bcc.solvers.htn.model_network import ModelNetwork, StateStack
    hi = lo + span
    if by_equality:
        var, pre, expected = "{e: int}", f"e == a + {r} and e % {m} == 0", \
            [a + r] if (a + r) % m == 0 else []
    else:
        var, pre, expected = f"{{e: {{type: int, range: [{lo}, {hi}]}}}}", f"e % {m} == {r} and e != a", \
            [e for e in range(lo, hi + 1) if e % m == r and e != a]
    domain_file(tmp_path, "tasks:\n  t: {params: {a: int}}\n  u: {params: {e: int}}\n"
                          f"methods:\n  m:\n    task: t\n    vars: {var}\n    pre: {pre}\n    subtasks: [u(e)]\n"
                          "  u_done: {task: u, subtasks: []}\n")   # (a task with no method is never done)
    model = compile_dungeon(str(dungeon_file(tmp_path, f"t({a})")), goal="true")
    net = ModelNetwork(model, model.data("hierarchy"))
    found = [subtasks[0][1][0] for _, _, subtasks in net.expansions("t", (a,), StateStack(model.initial))]
    assert found == expected


@pytest.mark.slow
def test_a_ten_cubed_house_is_one_task(cli, tmp_path):
    path = tmp_path / "house.yaml"
    assert cli("generate", "house", "--width", 10, "--length", 10, "--height", 10, "--as-task",
               "-o", path).exit_code == 0
    model = compile_dungeon(str(path))
    plan = plan_of(model)
    assert valid(model, plan) and plan.count("climb") == 11


def test_cells_derived_along_a_plan_equal_a_fresh_expansion():
    # ModelNetwork.apply caches each successor's expanded cells from its parent's
    # (emit.py's derive: one entry added, changed or removed); every cached expansion
    # must equal the one made from scratch from the state's changed cells.
    from bcc.model import cell_entries
    model = compile_dungeon(YARD)
    plan_of(model)
    ns = model.data("compiled").functions
    assert len(ns["_CC"]) >= 8            # the ring's 8 blocks: 8 distinct diffs at least
    for diff, cells in ns["_CC"].items():
        fresh = bytearray(ns["_S0"])
        for e in cell_entries(diff):
            fresh[e >> 8] = e & 255
        assert bytes(fresh) == cells
    derive, s0 = ns["_derive"], model.initial
    ns["_CC"].clear()
    state = s0
    for name in ["climb", "place_down_east", "move_east", "place_down_east"]:
        nxt = model.apply(model.action_index(name), state)
        derive(state, nxt)
        state = nxt
    assert len(ns["_CC"]) == 3             # climb's, then two placements' (a move changes no cell)
