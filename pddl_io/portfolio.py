"""A* `auto` on an imported task: blind for a short slice, LM-cut for a longer one, then blind.

Why a portfolio: on the IPC benchmark neither heuristic covers the other. LM-cut solves
ferry with 7 cars in 45 expansions where blind search needs millions of states, but on
driverlog, elevators, gripper, scanalyzer or grid it costs up to milliseconds a state and
blind search finishes first (scanalyzer p02: 9.5 s against 0.5 s). Most tasks are small:
blind search solves them in well under a second, and there no heuristic can save more
than that second. So blind search runs first for BLIND_SECONDS (at most BLIND_SHARE of the
limit): every task it solves in that slice costs exactly what blind search costs. Then
LM-cut gets LMCUT_SHARE of the time (at most LMCUT_SECONDS): its wins come after few
expansions. If that runs out too, blind A* searches again with the time left. All phases
are optimal, so the portfolio is: its plan is the first phase's that finds one. States,
memory and the time limit bound the phases together; each phase starts afresh (a phase
that ran out of time leaves nothing the next can use).
"""
from __future__ import annotations

import time

BLIND_SECONDS = 1.0
BLIND_SHARE = 1 / 20
LMCUT_SHARE = 1 / 6
LMCUT_SECONDS = 10.0


def phases(limit: float | None) -> list[tuple[str, float | None]]:
    """(heuristic, seconds) in order; the last phase has whatever time is left (None: no limit)."""
    if limit is None:
        return [("blind", BLIND_SECONDS), ("lmcut", LMCUT_SECONDS), ("blind", None)]
    return [("blind", min(BLIND_SECONDS, limit * BLIND_SHARE)), ("lmcut", min(LMCUT_SECONDS, limit * LMCUT_SHARE)),
            ("blind", None)]


def solve(model, budget, progress=None, **options):
    from ..solvers import Budget, get_solver
    astar = get_solver("astar")
    start = time.perf_counter()
    limit = budget.time_limit
    plan = phases(limit)
    used: list[str] = []
    results = []
    for k, (heuristic, seconds) in enumerate(plan):
        left = None if limit is None else max(limit - (time.perf_counter() - start), 1e-3)
        share = left if seconds is None else seconds if left is None else min(seconds, left)
        result = astar(model, Budget(budget.max_states, share, budget.max_memory_mb), progress, heuristic=heuristic)
        results.append(result)
        used.append(heuristic)
        last = k == len(plan) - 1 or (left is not None and share >= left)
        if result.solved or result.status != "budget" or last:
            break      # solved, proved unsolvable, or the whole budget is spent
        if result.budget != "time_limit" and heuristic != "blind":
            break      # out of states or memory with LM-cut: blind search would store more
    if len(results) == 1:
        result.heuristic = f"auto ({heuristic})"
        return result
    result.expanded = sum(r.expanded for r in results)
    result.generated = sum(r.generated for r in results)
    result.stored = max(r.stored for r in results)
    result.seconds = round(time.perf_counter() - start, 6)
    result.peak_mb = max(r.peak_mb for r in results)
    result.heuristic = "auto (" + ", ".join(used[:-1]) + f", then {used[-1]})"
    result.initial_h = max(r.initial_h for r in results if r.initial_h is not None) \
        if any(r.initial_h is not None for r in results) else None
    return result
