"""A* `auto` on an imported task: LM-cut for a short slice of the time, then blind.

Why a portfolio: on the IPC benchmark neither heuristic covers the other. LM-cut solves
ferry with 7 cars in 45 expansions where blind search needs millions of states, but on
driverlog, freecell, elevators, transport or scanalyzer it costs milliseconds a state and
blind search finishes first. LM-cut's wins come after few expansions, so it gets
LMCUT_SHARE of the time (at most LMCUT_SECONDS); if that runs out, blind A* searches
with the time left. Both are optimal, so the portfolio is: its plan is the first
phase's that finds one. States, memory and the time limit bound the two phases together.
"""
from __future__ import annotations

import time

LMCUT_SHARE = 1 / 6
LMCUT_SECONDS = 10.0


def solve(model, budget, progress=None, **options):
    from ..solvers import Budget, get_solver
    astar = get_solver("astar")
    start = time.perf_counter()
    limit = budget.time_limit
    first_limit = min(LMCUT_SECONDS, limit * LMCUT_SHARE) if limit is not None else LMCUT_SECONDS
    first = astar(model, Budget(budget.max_states, first_limit, budget.max_memory_mb), progress, heuristic="lmcut")
    if first.solved or first.status != "budget" or first.budget != "time_limit":
        return first       # solved, proved unsolvable, or out of states or memory (blind stores more)
    left = None if limit is None else max(limit - (time.perf_counter() - start), 1e-3)
    second = astar(model, Budget(budget.max_states, left, budget.max_memory_mb), progress, heuristic="blind")
    second.expanded += first.expanded
    second.generated += first.generated
    second.stored = max(first.stored, second.stored)
    second.seconds = round(time.perf_counter() - start, 6)
    second.peak_mb = max(first.peak_mb, second.peak_mb)
    second.heuristic = "auto (lmcut, then blind)"
    second.initial_h = first.initial_h
    return second
