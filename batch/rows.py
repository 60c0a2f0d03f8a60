"""The result rows of runs: the work of one run, done in a worker (compile the dungeon,
solve, make the row), and the row of a run that produced none.

A row has the same fields whatever happened to the run: solved (`solve_run`), budget
exhausted, an error in the dungeon, or a worker that died (`failed_row`). Timings
(`seconds`, `wall_seconds`, `peak_mb`) are the only fields that differ between two
executions of the same run.
"""
from __future__ import annotations

import time

from .runs import Run

TIMINGS = ("seconds", "wall_seconds", "peak_mb")


def base_row(run: Run) -> dict:
    return {"key": run.key, "dungeon": run.dungeon, "size": None, "solver": run.solver, "seed": run.seed,
            "options": dict(run.options), "limits": dict(run.limits), "goal": run.goal,
            "solved": False, "status": "error", "budget": None, "cost": None, "plan_length": None,
            "expanded": 0, "generated": 0, "stored": 0, "seconds": 0.0, "wall_seconds": 0.0,
            "peak_mb": 0.0, "heuristic": None, "converged_episode": None, "message": "", "error": None}


def warm_up(run: Run) -> None:
    """Import here, in the process that forks the run's child (the local pool, or a Ray
    worker), what the run needs: compiler, generator, heuristics, its solver. Every child
    then inherits it instead of importing it anew, which cost more than 0.1 s a run in
    bench/batch_scaling.py. Imports are cached, so calling this per run is cheap."""
    import importlib
    from ..errors import BccError
    from ..solvers import get_solver
    for module in ("compiler", "generate", "heuristics.registry"):
        importlib.import_module(f"{__package__.rsplit('.', 1)[0]}.{module}")
    try:
        get_solver(run.solver)
    except BccError:
        pass  # a broken plugin: each of its runs becomes an error row


def solve_run(run: Run) -> dict:
    """Compile and solve one run in this process; bad input raises (the caller records it)."""
    from ..compiler import compile_dungeon
    from ..run import Request, run as run_one
    from .dungeons import open_dungeon
    start = time.perf_counter()
    with open_dungeon(run.dungeon) as path:
        model = compile_dungeon(path, goal=run.goal)
    # the worker's child process has its own hard limits (run/children.py)
    ran = run_one(Request(lambda: model, run.solver, {**dict(run.options), "seed": run.seed}, run.budget(), hard=False))
    result = ran.result
    row = base_row(run)
    row.update(size=model.grid.width * model.grid.depth, solved=result.solved, status=result.status,
               budget=result.budget, cost=result.cost, plan_length=len(result.plan) if result.solved else None,
               expanded=result.expanded, generated=result.generated, stored=result.stored,
               seconds=result.seconds, peak_mb=result.peak_mb, heuristic=result.heuristic, message=result.message,
               converged_episode=result.converged_episode,
               wall_seconds=round(time.perf_counter() - start, 6))
    return row


def failed_row(run: Run, outcome) -> dict:
    """The row of a run that returned no row: it raised, a hard limit stopped it, or its
    worker died."""
    row = base_row(run)
    row["wall_seconds"] = round(outcome.seconds, 6)
    if outcome.limit is not None:
        row.update(status="budget", budget=outcome.limit, message=outcome.error or "")
    else:
        row.update(error=outcome.error, message=outcome.error)
    return row
