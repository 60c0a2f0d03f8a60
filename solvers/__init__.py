"""Solvers: one module per algorithm, all `solve(model, budget, progress=None, **options)`.

Each solver declares its options beside its `solve` (`options.declare`), and
`options.check_options` checks a request against that declaration for every caller.
Built-ins are listed here as "module:function" strings and imported only when used;
installed packages add solvers through the `bcc.solvers` entry-point group. A plugin
that fails to load is reported by name and never breaks the built-ins.
"""
from __future__ import annotations

import importlib

from .. import heuristics  # noqa: F401 - registers the heuristics' tables as model data
from ..errors import BccError
from .base import Budget, Result
from .options import check_options, options_of, unavailable

BUILTIN = {
    "bfs": ("bcc.solvers.bfs:solve", "breadth-first search (optimal for unit costs)"),
    "astar": ("bcc.solvers.astar:solve", "A* (optimal with weight 1; weight W > 1: cost <= W x optimal)"),
    "wastar": ("bcc.solvers.astar:solve_weighted", "weighted A*, f = g + W h (cost <= W x optimal)"),
    "gbfs": ("bcc.solvers.gbfs:solve", "greedy best-first search (fast, not optimal)"),
    "build": ("bcc.solvers.build:solve", "builds a goal of many cell atoms one at a time (satisficing; reports a lower bound)"),
    "idastar": ("bcc.solvers.idastar:solve", "IDA* (optimal, memory-bounded: keeps only the current path)"),
    "rmax": ("bcc.solvers.rmax:solve", "R-max reinforcement learning: learns the dynamics from episodes"),
    "qlearning": ("bcc.solvers.qlearning:solve", "tabular Q-learning, a model-free RL baseline"),
    "htn": ("bcc.solvers.htn:solve", "total-order HTN progression over task networks (a dungeon's task, bcc import hddl)"),
}

__all__ = ["Budget", "Result", "check_options", "default_solver", "describe_solvers", "get_solver", "list_solvers", "optimal_cost"]


def optimal_cost(model, budget: Budget | None = None) -> int | None:
    """A*'s cost, the yardstick of a learning solver's `converged_episode` (the run path,
    bcc/run, gives it to every solver that declares `optimal_cost`; None when A*
    finds no plan within `budget`: by default 60 s and half the RAM). Callers pass a share
    of the user's own budget, so the yardstick never outlives the command's limits."""
    if budget is None:
        budget = Budget(time_limit=60, max_memory_mb=Budget.default().max_memory_mb)
    reference = get_solver("astar")(model, budget)
    return reference.cost if reference.solved else None


def default_solver(model) -> str:
    """`bcc solve`'s choice when no --solver is given: `htn` when the dungeon gives a task
    (its `task:`, or --task); else `build` for a goal with a cell atom to write (a
    blueprint, a conjunction of cell atoms, or one cell atom) or an amount to gather (a
    goal such as `5 <= v` the start does not meet, heuristics/supplies.py); else `astar`.
    The one place this rule lives (docs/structures.md states it)."""
    from ..heuristics.goal_cells import CellReader, goal_cells
    from ..heuristics.supplies import supplies, wanted
    if model.report.get("task"):
        return "htn"
    if model.report.get("structure"):
        return "build"
    cells = goal_cells(model)
    amounts = wanted(model)
    if cells is None and amounts:
        cells = goal_cells(model, allow_empty=True)
    if cells is None:
        return "astar"
    read = CellReader(model)
    todo = [v for p, v in cells.atoms if read(model.initial, *p) != v]
    sup = supplies(model, cells)
    return "build" if todo or (sup and sup.short(model.initial, (), amounts)) else "astar"


def _plugins() -> dict:
    try:
        from importlib.metadata import entry_points   # slow to import: only when plugins are looked up
        return {ep.name: ep for ep in entry_points(group="bcc.solvers")}
    except Exception:  # noqa: BLE001 - a broken installation must not break the built-ins
        return {}


def list_solvers() -> dict[str, str]:
    out = {name: doc for name, (_, doc) in BUILTIN.items()}
    for name, ep in _plugins().items():
        out.setdefault(name, f"plugin from {ep.value}")
    return out


def describe_solvers() -> dict[str, dict]:
    """Every solver: {description, options (from its declaration), unavailable (why it
    cannot run here, or None)}. Plugins are loaded to read their docstring's first line and
    their options; a plugin that fails to load says so and is marked unavailable."""
    out = {}
    for name, doc in list_solvers().items():
        try:
            solve = get_solver(name)
        except BccError as exc:   # a plugin that fails to load: described, not raised
            out[name] = {"description": doc + " (fails to load)", "options": [], "unavailable": exc.message}
            continue
        if name not in BUILTIN:
            lines = (solve.__doc__ or "").strip().splitlines()
            doc = f"{lines[0].rstrip('.')} (plugin: {_plugins()[name].value})" if lines else doc
        out[name] = {"description": doc, "options": [o.to_json() for o in options_of(solve)],
                     "unavailable": unavailable(solve)}
    return out


def get_solver(name: str):
    if name in BUILTIN:
        module, func = BUILTIN[name][0].split(":")
        return getattr(importlib.import_module(module), func)
    plugins = _plugins()
    if name in plugins:
        try:
            return plugins[name].load()
        except Exception as exc:  # noqa: BLE001
            raise BccError(f"the solver plugin {name!r} ({plugins[name].value}) failed to load: {exc}") from None
    import difflib
    names = list_solvers()
    close = difflib.get_close_matches(name, list(names), n=1)
    hint = f" (did you mean {close[0]!r}?)" if close else ""
    raise BccError(f"unknown solver {name!r}{hint}; available: {', '.join(names)}")
