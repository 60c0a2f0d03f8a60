"""Solvers: one module per algorithm, all `solve(model, budget, progress=None, **options)`.

Built-ins are listed here as "module:function" strings and imported only when used;
installed packages add solvers through the `bcc.solvers` entry-point group. A plugin
that fails to load is reported by name and never breaks the built-ins.
"""
from __future__ import annotations

import importlib
from importlib.metadata import entry_points

from ..errors import BccError
from .base import Budget, Result

BUILTIN = {
    "bfs": ("bcc.solvers.bfs:solve", "breadth-first search (optimal for unit costs)"),
    "astar": ("bcc.solvers.astar:solve", "A* (optimal; --heuristic auto|pdb|manhattan|blind, --weight W > 1 for weighted)"),
    "wastar": ("bcc.solvers.astar:solve_weighted", "weighted A*, f = g + w h (--weight, default 2; cost <= w x optimal)"),
    "gbfs": ("bcc.solvers.gbfs:solve", "greedy best-first search (fast, not optimal)"),
    "idastar": ("bcc.solvers.idastar:solve", "IDA* (optimal, memory-bounded: keeps only the current path)"),
    "rmax": ("bcc.solvers.rmax:solve", "R-max reinforcement learning (--model tabular|oo, --episodes, --seed, --gamma, --delta, --known-after, --max-steps)"),
    "qlearning": ("bcc.solvers.qlearning:solve", "tabular Q-learning, a model-free RL baseline (--episodes, --seed, --gamma, --max-steps)"),
}

__all__ = ["Budget", "Result", "get_solver", "list_solvers", "optimal_cost", "LEARNING"]

LEARNING = ("rmax", "qlearning")   # learn from episodes; report `converged_episode` against A*


def learning_options(solver: str, given: dict, spelled: dict) -> dict:
    """The learning solvers' options among `given` (option -> value, None when not given),
    checked for `solver`; a BccError names an option that does not apply as the user
    spelled it (`spelled`: a flag, a JSON field)."""
    out = {}
    for key in ("learner", "delta", "m"):
        if given.get(key) is not None:
            if solver != "rmax":
                raise BccError(f"{spelled[key]} applies to rmax only")
            out[key] = given[key]
    rest = [key for key in ("episodes", "seed", "gamma", "max_steps") if given.get(key) is not None]
    if rest and solver not in LEARNING:
        raise BccError(f"{', '.join(spelled[key] for key in rest)}: for the learning solvers (rmax, qlearning) only")
    out.update((key, given[key]) for key in rest)
    return out


def optimal_cost(model, budget: Budget | None = None) -> int | None:
    """A*'s cost, the yardstick of a learning solver's `converged_episode` (None when A*
    finds no plan within `budget`: by default 60 s and half the RAM). Callers pass a share
    of the user's own budget, so the yardstick never outlives the command's limits."""
    if budget is None:
        budget = Budget(time_limit=60, max_memory_mb=Budget.default().max_memory_mb)
    reference = get_solver("astar")(model, budget)
    return reference.cost if reference.solved else None


def _plugins() -> dict:
    try:
        return {ep.name: ep for ep in entry_points(group="bcc.solvers")}
    except Exception:  # noqa: BLE001 - a broken installation must not break the built-ins
        return {}


def list_solvers() -> dict[str, str]:
    out = {name: doc for name, (_, doc) in BUILTIN.items()}
    for name, ep in _plugins().items():
        out.setdefault(name, f"plugin from {ep.value}")
    return out


def describe_solvers() -> dict[str, str]:
    """`list_solvers`, with each plugin described by the first line of its docstring
    (loading it; a plugin that fails to load says so)."""
    out = list_solvers()
    for name, ep in _plugins().items():
        if name in BUILTIN:
            continue
        try:
            doc = (ep.load().__doc__ or "").strip().splitlines()
        except Exception as exc:  # noqa: BLE001 - described, not raised: `bcc solvers` lists the rest
            out[name] = f"plugin from {ep.value} (fails to load: {exc})"
            continue
        out[name] = f"{doc[0].rstrip('.')} (plugin: {ep.value})" if doc else f"plugin from {ep.value}"
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
    close = difflib.get_close_matches(name, list(list_solvers()), n=1)
    hint = f" (did you mean {close[0]!r}?)" if close else ""
    raise BccError(f"unknown solver {name!r}{hint}; available: {', '.join(list_solvers())}")
