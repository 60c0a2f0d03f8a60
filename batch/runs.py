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

BUDGETS = ("time_limit", "max_states", "max_memory")
# The most runs one batch holds: its run list, keys and rows are in memory, and 100,000
# runs of a second each are a day of a machine. Every axis is checked before it is
# built, so `seed=0..99999999` is one error line, not gigabytes of run records.
MAX_RUNS = 100_000


def check_size(count: int, what: str) -> None:
    """Refuse an axis or product of `count` runs past MAX_RUNS, before building it."""
    if count > MAX_RUNS:
        raise BccError(f"{what} makes {count:,} runs; one batch runs at most {MAX_RUNS:,}: split the sweep")


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


def seeded(solver: str) -> bool:
    """Whether the solver's result depends on a seed: it declares a `seed` option."""
    from ..solvers import get_solver
    from ..solvers.options import options_of
    return any(o.name == "seed" for o in options_of(get_solver(solver)))


def check_options(solver: str, options: dict) -> dict:
    """The solver's keyword arguments for a run's options, checked by the solver's own
    declaration (the one check `bcc solve` and `POST /solve` use). The seed is swept by
    `seeds`, not given as an option."""
    from ..solvers.options import check_options as check
    if "seed" in options:
        raise BccError("seeds are swept with `seeds:` at the top of a sweep (or --seeds), not per solver")
    return check(solver, options)


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
    check_size(len(dungeons) * sum(len(seeds) if seeded(s) else 1 for s, _, _ in settings),
               "the sweep (dungeons x solvers x seeds)")
    runs, seen = [], set()
    for dungeon, (solver, options, limits) in itertools.product(dungeons, settings):
        for seed in (seeds if seeded(solver) else [None]):
            run = Run(dungeon, solver, seed, tuple(sorted(options.items())), tuple(sorted(limits.items())), goal)
            if run.key not in seen:
                seen.add(run.key)
                runs.append(run)
    return runs
