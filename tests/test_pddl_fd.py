"""Cross-checks with the planning field's tools (needs the `pddl` extra; skipped without).

- Fast Downward, optimal (astar(lmcut()), or astar(blind()) where lmcut is slow per
  state: the stone mazes), on the export finds plans of exactly bcc A*'s cost, on the
  five reference dungeons and on 22 generated mazes; its plans, mapped back to bcc
  actions, replay to the goal in bcc (simulate.replay).
- On every one of them, bcc's optimal plan (and, on the references, Fast Downward's plan)
  is valid in the export according to an independent validator (pddl-pyvalidator, else
  unified-planning's), on the validator variant of the export (plans.validation_files).
- Imported STRIPS problems: bcc's cost equals Fast Downward's on the same files.
"""
import os
from pathlib import Path

import pytest

from bcc.compiler import compile_dungeon
from bcc.generate import generate_maze
from bcc.solvers import fast_downward
from bcc.simulate import replay
from bcc.solvers import Budget, get_solver

pytestmark = pytest.mark.skipif(not fast_downward.available(),
                                reason='Fast Downward not installed: pip install ".[pddl]"')

HERE = Path(__file__).parent / "pddl"
BLIND = "astar(blind())"  # optimal too; lmcut's per-state cost dominates on the stone mazes
REFERENCES = [("grid", None), ("bridge", None), ("easy_maze", None), ("four_rooms", None), ("tough_maze", BLIND)]
MAZES = [(w, stones, lava, seed) for seed, (w, stones, lava) in enumerate(
    [(7, 0, 0), (7, 1, 0), (7, 0, 1), (7, 1, 1), (9, 0, 0), (9, 1, 0), (9, 0, 1), (9, 1, 1), (11, 0, 0),
     (11, 0, 1), (7, 0, 0), (7, 1, 0), (7, 0, 1), (7, 1, 1), (9, 0, 0), (9, 1, 0), (9, 0, 1), (11, 0, 0),
     (13, 0, 0), (15, 0, 0)])] + [(9, 2, 1, 20), (11, 2, 1, 21)]


def export(model, tmp_path):
    from bcc.pddl_export.task import build_task
    from bcc.pddl_export.writer import domain_text, problem_text
    task = build_task(model)
    d, p = tmp_path / "domain.pddl", tmp_path / "problem.pddl"
    d.write_text(domain_text(task))
    p.write_text(problem_text(task))
    return task, str(d), str(p)


def check_plan_validates(task, ops, directory):
    from bcc.pddl_export.plans import validate, validation_files
    directory.mkdir(exist_ok=True)
    assert validate(*validation_files(task, ops, str(directory))) == (True, "VALID")


def check_fd_equals_astar(model, tmp_path, search=None, validate_fd=False):
    from bcc.pddl_export.plans import to_pddl_plan
    task, d, p = export(model, tmp_path)
    fd = fast_downward.run(d, p, search=search, time_limit=120)
    astar = get_solver("astar")(model, Budget(time_limit=120))
    assert fd.solved and astar.solved
    assert fd.cost == astar.cost
    plan = [a for a in (task.action_of(op) for op in fd.plan) if a is not None]
    result = replay(model, [(a, k + 1, 1) for k, a in enumerate(plan)])
    assert result.valid, result.message
    check_plan_validates(task, to_pddl_plan(task, astar.plan), tmp_path / "astar")
    if validate_fd:  # each validation parses PDDL for 1-2 s: Fast Downward's plans on the references only
        check_plan_validates(task, fd.plan, tmp_path / "fd")
    return task, d, p, astar


@pytest.mark.parametrize("dungeon,search", REFERENCES)
def test_fd_cost_equals_astar_on_references(dungeon, search, tmp_path):
    check_fd_equals_astar(compile_dungeon(dungeon), tmp_path, search, validate_fd=True)


@pytest.mark.parametrize("width,stones,lava,seed", MAZES)
def test_fd_cost_equals_astar_on_generated_mazes(width, stones, lava, seed, tmp_path):
    path = tmp_path / "maze.yaml"
    path.write_text(generate_maze(width, width, stones=stones, lava=lava, seed=seed))
    check_fd_equals_astar(compile_dungeon(str(path)), tmp_path, BLIND if stones > 1 else None)


@pytest.mark.parametrize("dungeon", ["grid", "bridge"])
def test_the_validator_rejects_broken_plans(dungeon, tmp_path):
    from bcc.pddl_export.plans import to_pddl_plan, validate, validation_files
    model = compile_dungeon(dungeon)
    task, d, p = export(model, tmp_path)
    ops = to_pddl_plan(task, get_solver("astar")(model, Budget(time_limit=60)).plan)
    assert validate(*validation_files(task, ops, str(tmp_path))) == (True, "VALID")
    valid, reason = validate(*validation_files(task, ops[:-1], str(tmp_path)))  # one step short of the goal
    assert not valid and "goal" in reason
    # the first two steps swapped: a precondition fails (the first step is the only
    # applicable case of its action in the start state, the second is not)
    valid, reason = validate(*validation_files(task, [ops[1], ops[0]] + ops[2:], str(tmp_path)))
    assert not valid and "step" in reason


def test_fd_solver_returns_a_bcc_result():
    model = compile_dungeon("bridge")
    result = fast_downward.solve(model, Budget(time_limit=60), search="astar(blind())")
    reference = get_solver("bfs")(model, Budget(time_limit=60))
    assert result.solved and result.cost == reference.cost
    assert replay(model, [(a, k + 1, 1) for k, a in enumerate(result.plan)]).valid
    # Fast Downward's own counters: A* expands every state of the plan but the last
    assert result.expanded >= result.cost and result.generated >= result.expanded


@pytest.mark.parametrize("domain,problem", [("gripper-domain", "gripper-3"), ("blocksworld-domain", "blocksworld-4"),
                                            ("logistics-domain", "logistics-2"), ("lights-domain", "lights-2")])
def test_imported_problems_cost_equals_fd(domain, problem):
    from bcc.pddl_io.importer import import_pddl
    d, p = str(HERE / f"{domain}.pddl"), str(HERE / f"{problem}.pddl")
    model = import_pddl(d, p)
    fd = fast_downward.run(d, p, time_limit=60)
    for solver in ("astar", "bfs"):
        assert get_solver(solver)(model, Budget(time_limit=60)).cost == fd.cost


def test_a_bad_search_is_one_line_naming_what_fast_downward_did_not_know():
    from bcc.errors import BccError
    with pytest.raises(BccError) as caught:
        fast_downward.solve(compile_dungeon("grid"), Budget(time_limit=60), search="astar(nosuch())")
    line, = str(caught.value).strip().splitlines()
    assert line.startswith("Fast Downward failed") and "'nosuch'" in line
    assert "|  |" not in line and ":  |" not in line   # no empty piece where FD drew its caret


def test_fast_downwards_counters_are_its_last_report():
    out = ("[t=0.01s, 9 KB] Expanded 3 state(s).\n[t=0.02s, 9 KB] Generated 7 state(s).\n"
           "[t=0.03s, 9 KB] Expanded 12 state(s).\n[t=0.03s, 9 KB] Generated 30 state(s).\n")
    assert fast_downward._counter(out, "Expanded") == 12 and fast_downward._counter(out, "Generated") == 30
    assert fast_downward._counter("Solution found!", "Expanded") == 0


def test_a_task_with_axioms_falls_back_from_lmcut_to_blind_search():
    # Fast Downward's LM-cut refuses derived predicates; its default search then reruns blind
    fd = fast_downward.run(str(HERE / "lights-domain.pddl"), str(HERE / "lights-2.pddl"), time_limit=60)
    assert fd.solved and fd.cost == 5 and fd.search == fast_downward.AXIOMS_SEARCH
    asked = fast_downward.run(str(HERE / "lights-domain.pddl"), str(HERE / "lights-2.pddl"),
                              search="astar(lmcut())", time_limit=60)
    assert asked.search == fast_downward.AXIOMS_SEARCH   # the default, named: the same fallback
    other = fast_downward.run(str(HERE / "lights-domain.pddl"), str(HERE / "lights-2.pddl"),
                              search="astar(hmax())", time_limit=60)
    assert other.solved and other.cost == 5 and other.search == "astar(hmax())"   # another search runs as asked
