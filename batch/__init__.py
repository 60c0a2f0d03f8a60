"""`bcc batch`: sweeps of solves over dungeons x solvers x seeds, on a process pool or Ray (issue 12).

The Python API (see docs/batch.md) is imported lazily, so `bcc --help` stays fast:

    from bcc.batch import map_runs, run_batch, solve_runs, build_runs, Run, Limits, Outcome, read_rows
"""
from __future__ import annotations

_EXPORTS = {   # name -> its module, relative to this package
    "map_runs": ".engine", "run_batch": ".engine", "solve_runs": ".engine", "BACKENDS": ".engine",
    "Limits": "..run.children", "Outcome": "..run.children", "run_limited": "..run.children",
    "Run": ".runs", "build_runs": ".runs",
    "expand_dungeons": ".dungeons",
    "read_rows": ".store", "ResultsFile": ".store",
    "solve_run": ".rows",
    "load_sweep": ".sweep",
}
__all__ = sorted(_EXPORTS)


def __getattr__(name: str):
    if name in _EXPORTS:
        import importlib
        return getattr(importlib.import_module(_EXPORTS[name], __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
