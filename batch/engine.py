"""The Python API: `map_runs` for any work function, `run_batch` for sweeps of solves.

    from bcc.batch import map_runs, run_batch, build_runs, Limits

    for outcome in map_runs(my_function, items, workers=2, limits=Limits(wall_seconds=60)):
        ...                               # outcome.index, .value, .error, .limit

    summary = run_batch(runs, out="results.jsonl", backend="local", workers=2)

Both backends give the same outcomes for the same items; only the order of completion
and the timings differ.
"""
from __future__ import annotations

import os
import time
from typing import Callable, Iterable, Iterator

from ..errors import BccError
from ..run.children import Limits, Outcome
from .runs import Run

BACKENDS = ("local", "ray")


def map_runs(function: Callable, items: Iterable, *, backend: str = "local", workers: int | None = None,
             address: str | None = None, limits: Limits | Callable | None = None,
             prepare: Callable | None = None) -> Iterator[Outcome]:
    """Run function(item) for every item, each in a fresh process under hard `limits` (one
    `Limits`, or a function item -> Limits); yield an `Outcome` per item as it finishes.
    `prepare(item)`, if given, runs in the process that forks the item's child, just
    before: import there what the work needs, and every child inherits it.

    local: `workers` processes at once (default: the CPUs). ray: Ray tasks, at most
    `workers` in flight (default: the cluster's CPUs), on the cluster at `address`, or a
    local Ray started for the call. For ray, `function` and the items must be picklable
    and importable on the workers (module-level functions of installed packages)."""
    items = list(items)
    limits_of = limits if callable(limits) else (lambda item, fixed=limits or Limits(): fixed)
    if workers is not None and workers < 1:
        raise BccError(f"workers must be at least 1, got {workers}")
    check_backend(backend, address)
    if backend == "local":
        from ..run.pool import map_local
        return map_local(function, items, workers or os.cpu_count() or 1, limits_of, prepare)
    from .ray_backend import map_ray
    return map_ray(function, items, workers, limits_of, address, prepare)


def check_backend(backend: str, address: str | None) -> None:
    """Bad backend settings, or a missing Ray, are errors before anything runs."""
    if backend not in BACKENDS:
        raise BccError(f"unknown backend {backend!r}; backends: {', '.join(BACKENDS)}")
    if backend == "local" and address:
        raise BccError("--address applies to the ray backend only (add --backend ray)")
    if backend == "ray":
        from .ray_backend import import_ray
        import_ray()


def limits_for(run: Run) -> Limits:
    budget = run.budget()
    return Limits.around(budget.time_limit, budget.max_memory_mb)


def solve_runs(runs: list[Run], *, backend: str = "local", workers: int | None = None,
               address: str | None = None) -> list[dict]:
    """The result rows of `runs`, in their order, without a results file (for scripts
    that keep their own records, e.g. bench/run.py)."""
    from .rows import failed_row, solve_run, warm_up
    rows: list = [None] * len(runs)
    for outcome in map_runs(solve_run, runs, backend=backend, workers=workers, address=address, limits=limits_for,
                            prepare=warm_up):
        rows[outcome.index] = outcome.value if outcome.ok else failed_row(runs[outcome.index], outcome)
    return rows


def run_batch(runs: list[Run], *, out: str, backend: str = "local", workers: int | None = None,
              address: str | None = None, progress=None) -> dict:
    """Solve every run not yet in `out` and append its row there; return a summary.

    Rerunning with the same runs skips the ones already recorded (by `Run.key`), so an
    interrupted sweep resumes where it stopped. `progress` is an object with
    `update(solved)` and `close()` (see `ProgressBar`), or None."""
    from .rows import failed_row, solve_run, warm_up
    from .store import ResultsFile, read_rows
    start = time.monotonic()
    check_backend(backend, address)
    before = read_rows(out)
    before.check_is_results(out)
    recorded = {row.get("key"): row for row in before.rows}
    todo = [run for run in runs if run.key not in recorded]
    if todo:
        outcomes = map_runs(solve_run, todo, backend=backend, workers=workers, address=address, limits=limits_for,
                            prepare=warm_up)
    else:  # nothing left: no pool, and no Ray to start or join
        outcomes = (o for o in ())
    with ResultsFile(out) as results:
        try:
            for outcome in outcomes:
                row = outcome.value if outcome.ok else failed_row(todo[outcome.index], outcome)
                results.append(row)
                recorded[row["key"]] = row
                if progress is not None:
                    progress.update(bool(row["solved"]))
        finally:
            outcomes.close()
            if progress is not None:
                progress.close()
    rows = [recorded[run.key] for run in runs]
    if backend == "local":
        workers = workers or os.cpu_count() or 1
    return {"out": out, "backend": backend, "workers": workers, "runs": len(runs),
            "skipped": len(runs) - len(todo), "ran": len(todo),
            "solved": sum(1 for r in rows if r["solved"]),
            "no_solution": sum(1 for r in rows if r["status"] == "no_solution"),
            "budget_exhausted": sum(1 for r in rows if r["status"] == "budget"),
            "errors": sum(1 for r in rows if r["error"]),
            "seconds": round(time.monotonic() - start, 3),
            "ignored_lines": before.bad_lines, "torn_bytes_dropped": before.torn_tail}
