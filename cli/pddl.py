"""`bcc export pddl` and `bcc import pddl`: the PDDL edge of the command line."""
from __future__ import annotations

import os
import sys
from typing import NamedTuple

import click

from .shared import (budget_options, clear_progress, compile_model, emit_json, goal_option, json_option,
                          max_memory_option, print_result, progress_enabled, solver_flags, solver_given,
                          time_limit_option, within_budget)


SEARCH_SHARE = 0.97   # of the time left after importing: the rest frees the search's tables
# Steps (candidate atoms joined, objects of quantified variables) grounding may take under
# --grounding auto before the task is searched lifted instead (about 4 s of CPU). Every
# test task grounds in a few hundred (gripper 33, sokoban 221); a world of blocks with
# inventory counts (MinePlanner's tasks) needs far more.
MAX_GROUND_WORK = 600_000
OPTIMAL_SOLVERS = ("astar", "bfs", "idastar")   # on a lifted task: a search by cost (with weight 1)


class Lifted(NamedTuple):
    """A PDDL task searched without grounding (solvers/lifted_search.py)."""
    domain: object
    problem: object


@click.group("export")
def export_group():
    """Export a compiled dungeon to other formats."""


@export_group.command("pddl")
@click.argument("dungeon")
@click.option("-o", "--output", "out_dir", required=True, type=click.Path(file_okay=False),
              help="Directory for domain.pddl and problem.pddl (created if missing).")
@click.option("--max-states", type=click.IntRange(min=1), default=None,
              help="Abstract states the export may explore to bound each variable's values [default: 300000].")
@budget_options
@json_option
@goal_option
def export_pddl_cmd(dungeon, out_dir, max_states, time_limit, max_memory, as_json, goal):
    """Write DUNGEON as grounded STRIPS PDDL: DIR/domain.pddl and DIR/problem.pddl."""
    from ..atomic import write_text
    from ..pddl_export.task import build_task
    from ..pddl_export.writer import domain_text, problem_text
    with within_budget(time_limit, max_memory, as_json, dungeon):
        model = compile_model(dungeon, goal)
        task = build_task(model, max_states)
        texts = {"domain.pddl": domain_text(task), "problem.pddl": problem_text(task)}   # both before either is written
    os.makedirs(out_dir, exist_ok=True)
    files = {}
    for name, text in texts.items():
        path = os.path.join(out_dir, name)
        write_text(path, text)
        files[name] = {"path": path, "bytes": len(text.encode())}
    info = {"dungeon": model.name, "goal": model.goal_text, **task.stats, "action_costs": task.use_costs,
            "files": files}
    if as_json:
        emit_json(info)
        return
    click.echo(f"wrote {files['domain.pddl']['path']} and {files['problem.pddl']['path']}: "
               f"{task.stats['operators']} operators over {task.stats['facts']} facts "
               f"(value domains: a fixpoint over {task.stats['abstract_states']:,} abstract states)")


@click.group("import")
def import_group():
    """Import problems from other formats and solve them with bcc's solvers."""


@import_group.command("pddl")
@click.argument("domain", type=click.Path(dir_okay=False))
@click.argument("problem", type=click.Path(dir_okay=False))
@click.option("--solver", default="astar", show_default=True, help="A bcc solver (see `bcc solvers`), or fd.")
@time_limit_option("Stop after this many seconds (reading, grounding and search together).")
@click.option("--max-states", type=click.IntRange(min=1), help="Stop the search after storing this many states.")
@max_memory_option()
@click.option("-o", "--output", type=click.Path(dir_okay=False, writable=True),
              help="Write the plan to FILE, one action a line (atomically).")
@click.option("--grounding", type=click.Choice(["auto", "full", "lifted"]), default="auto", show_default=True,
              help="full: ground the task; lifted: search it without grounding (joins in each state); "
                   "auto: ground unless that takes too long, else lifted.")
@json_option
@solver_flags
def import_pddl_cmd(domain, problem, solver, time_limit, max_states, max_memory, output, grounding, as_json,
                    **solver_options):
    """Compile a PDDL DOMAIN + PROBLEM with bcc's own front-end and solve it.

    The plan is printed in PDDL form, one `(action arg ...)` a line; its cost is the sum
    of the actions' costs (`:action-costs`). A task too big to ground (--grounding auto)
    is searched lifted: a solver that is optimal searches by cost, any other runs
    best-first width search (docs/pddl.md)."""
    from ..atomic import check_writable, write_text
    from ..run import Request, run
    from ..solvers import Budget, get_solver
    from ..solvers.options import check_options
    given, spell = solver_given(solver_options)
    options = check_options(solver, given, spell)   # typed, to choose the search below; the run checks `given` too
    solve = get_solver(solver)
    if options.get("heuristic") in (None, "auto") and solver in ("gbfs", "wastar"):
        given["heuristic"] = "hff"   # the grid's pattern database is blind on PDDL: the relaxed plan is not
    elif solver == "astar" and options.get("heuristic") in (None, "auto") and options.get("weight", 1) == 1:
        from ..solvers.portfolio import solve   # blind, LM-cut, then blind, each for a slice (all optimal)
    optimal = solver in OPTIMAL_SOLVERS and options.get("weight", 1) == 1
    if output:
        check_writable(output)

    def load():
        from ..pddl_io.ground import TooBig
        from ..pddl_io.importer import import_pddl
        from ..pddl_io.lifted import read_task
        if grounding == "lifted":
            return Lifted(*read_task(domain, problem))
        try:
            return import_pddl(domain, problem, max_work=MAX_GROUND_WORK if grounding == "auto" else None)
        except TooBig as exc:
            return Lifted(*exc.task)

    def search(task, budget, progress=None, **options):
        if isinstance(task, Lifted):
            from ..solvers.lifted_search import solve as lifted_solve
            return _without_cycle_collector(lifted_solve, task.domain, task.problem, budget, progress=progress,
                                            optimal=optimal, solver=solver)
        return _without_cycle_collector(solve, task, budget, progress=progress, **options)

    progress = progress_enabled()
    # The search stops a little early: freeing millions of states when it returns takes
    # time too, and the hard timer would otherwise drop its result (and counters).
    ran = run(Request(load, solver, given, Budget(max_states, time_limit, max_memory), progress, spell=spell,
                      solve=search, search_share=SEARCH_SHARE))
    clear_progress(progress)
    result = ran.result
    lifted = ran.model if isinstance(ran.model, Lifted) else None
    model = None if lifted is not None else ran.model
    if output and result.solved:
        write_text(output, "".join(a + "\n" for a in result.plan))
    report = model.report if model is not None else {}
    name = model.name if model is not None else problem
    if lifted is not None:
        name = lifted.problem.name
        sys.exit(print_result(result, name, problem, as_json,
                              {"problem": name, "atoms": None, "grounded_actions": None,
                               "action_costs": lifted.problem.metric, "lifted": True},
                              details="; searched lifted"))
    sys.exit(print_result(result, name, problem, as_json,
                          {"problem": name, "atoms": report.get("atoms"),
                           "grounded_actions": report.get("grounded_actions"),
                           "action_costs": report.get("action_costs"), "lifted": False},
                          details=f"; {report.get('grounded_actions')} grounded actions, {report.get('atoms')} atoms"))


def _without_cycle_collector(solve, *args, **kwargs):
    """Run a search with Python's cyclic garbage collector off. A search stores millions of
    tuples and bytes that form no cycles; the collector would re-scan all of them at each
    full collection (mystery p02, blind: 38% more expansions in 8 s without it). Memory is
    still bounded: reference counting frees everything acyclic, and --max-memory holds."""
    import gc
    was = gc.isenabled()
    gc.disable()
    try:
        return solve(*args, **kwargs)
    finally:
        if was:
            gc.enable()


COMMANDS = [export_group, import_group]


def _add_mineplanner():
    """`bcc import mineplanner` (cli/mineplanner.py, for the mineplanner/ edge) joins the group."""
    from .mineplanner import import_mineplanner_cmd
    import_group.add_command(import_mineplanner_cmd)


_add_mineplanner()


def _with_hddl():
    """`bcc import hddl` joins `bcc import` (its module imports nothing heavy)."""
    from .hddl import import_hddl_cmd
    import_group.add_command(import_hddl_cmd)


_with_hddl()
