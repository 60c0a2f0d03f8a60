"""The run set of a sweep: dungeons x solver settings x seeds, each run with a stable key.

A run's key hashes what determines its result (dungeon name, goal, solver, options,
seed and the budgets the user gave), so rerunning the same command finds the runs
already in the results file, whatever the backend or the number of workers.
"""
from __future__ import annotations

import hashlib
import itertools
import json
from dataclasses import dataclass

from ..errors import BccError

SEEDED = ("rmax", "qlearning")          # solvers whose result depends on a seed
# option -> (solvers it applies to or None for informed ones, check, what it must be)
OPTIONS = ("heuristic", "weight", "model", "episodes")
BUDGETS = ("time_limit", "max_states", "max_memory")


@dataclass(frozen=True)
class Run:
    """One solve of a sweep. `options` and `limits` are sorted (name, value) pairs; limits
    holds only the budgets the user gave (None values are left out)."""
    dungeon: str
    solver: str
    seed: int | None = None
    options: tuple = ()
    limits: tuple = ()
    goal: str | None = None

    @property
    def key(self) -> str:
        ident = {"dungeon": self.dungeon, "goal": self.goal, "solver": self.solver, "seed": self.seed,
                 "options": dict(self.options), "limits": dict(self.limits)}
        return hashlib.sha256(json.dumps(ident, sort_keys=True).encode()).hexdigest()[:16]

    def budget(self):
        """The solver's budget. Without a memory budget: half the memory of the machine it
        runs on, shared by as many runs as that machine has CPUs."""
        import os
        from ..solvers import Budget
        limits = dict(self.limits)
        memory = limits.get("max_memory") or Budget.default().max_memory_mb / (os.cpu_count() or 1)
        return Budget(max_states=limits.get("max_states"), time_limit=limits.get("time_limit"),
                      max_memory_mb=memory)

    def label(self) -> str:
        """The solver and its options, e.g. `astar heuristic=manhattan` (report rows)."""
        return " ".join([self.solver] + [f"{k}={v}" for k, v in self.options])


def check_options(solver: str, options: dict) -> None:
    """The same rules as `bcc solve`: an option a solver does not take is an error."""
    from ..solvers import list_solvers
    from ..solvers.heuristics import HEURISTICS
    from ..compiler.source import suggest
    solvers = list_solvers()
    if solver not in solvers:
        raise BccError(f"unknown solver {solver!r}{suggest(solver, solvers)}; available: {', '.join(solvers)}")
    for name, value in options.items():
        if name not in OPTIONS:
            raise BccError(f"unknown option {name!r}{suggest(name, OPTIONS + BUDGETS)}; "
                           f"options: {', '.join(OPTIONS)}")
        if name == "heuristic":
            if value != "auto" and value not in HEURISTICS:
                raise BccError(f"unknown heuristic {value!r}; available: auto, {', '.join(HEURISTICS)}")
            if solver == "bfs" or solver in SEEDED:
                raise BccError(f"{solver} uses no heuristic")
        elif name == "weight":
            if solver not in ("astar", "wastar"):
                raise BccError("weight applies to astar and wastar only")
            if isinstance(value, bool) or not isinstance(value, (int, float)) or value < 1:
                raise BccError(f"weight must be a number >= 1, got {value!r}")
        elif name == "model":
            if solver != "rmax":
                raise BccError("model applies to rmax only")
            if value not in ("tabular", "oo"):
                raise BccError(f"model must be tabular or oo, got {value!r}")
        elif name == "episodes":
            if solver not in SEEDED:
                raise BccError("episodes applies to the learning solvers (rmax, qlearning)")
            if isinstance(value, bool) or not isinstance(value, int) or value < 1:
                raise BccError(f"episodes must be a whole number >= 1, got {value!r}")


def check_limits(limits: dict) -> dict:
    out = {}
    for name, value in limits.items():
        if value is None:
            continue
        if name not in BUDGETS:
            raise BccError(f"unknown budget {name!r}; budgets: {', '.join(BUDGETS)}")
        whole = name == "max_states"
        if isinstance(value, bool) or not isinstance(value, int if whole else (int, float)) or value <= 0:
            raise BccError(f"{name} must be a {'whole ' if whole else ''}number > 0, got {value!r}")
        out[name] = value
    return out


def build_runs(dungeons: list[str], settings: list[tuple[str, dict, dict]], seeds: list[int],
               goal: str | None = None) -> list[Run]:
    """The product dungeons x settings x seeds, in that nesting order. A setting is
    (solver, options, limits); seeds multiply only the seeded solvers (the others are
    deterministic: one run each, seed null)."""
    runs, seen = [], set()
    for dungeon, (solver, options, limits) in itertools.product(dungeons, settings):
        for seed in (seeds if solver in SEEDED else [None]):
            run = Run(dungeon, solver, seed, tuple(sorted(options.items())), tuple(sorted(limits.items())), goal)
            if run.key not in seen:
                seen.add(run.key)
                runs.append(run)
    return runs
