"""A* `auto` on an imported task: blind for a short slice, LM-cut for a longer one, then blind.

Why a portfolio: on the IPC benchmark neither heuristic covers the other. LM-cut solves
ferry with 7 cars in 45 expansions where blind search needs millions of states, but on
driverlog, elevators, gripper, scanalyzer or grid it costs up to milliseconds a state and
blind search finishes first (scanalyzer p02: 9.5 s against 0.5 s). Most tasks are small:
blind search solves them in well under a second, and there no heuristic can save more
than that second. So blind search runs first for BLIND_SECONDS (at most BLIND_SHARE of the
limit): every task it solves in that slice costs exactly what blind search costs. Then
LM-cut gets LMCUT_SHARE of the time (at most LMCUT_SECONDS): its wins come after few
expansions (within 1.1 s of CPU on every IPC task it won), while a slice that runs out is
lost whole (freecell p3: 10 s of a 19 s run when the slice was 10 s; 2 s now). If that runs out too, blind A* searches again with the time left. All phases
are optimal, so the portfolio is: its plan is the first phase's that finds one. States,
memory and the time limit bound the phases together; each phase starts afresh (a phase
that ran out of time leaves nothing the next can use).
"""
from __future__ import annotations

import time

from .base import Result

BLIND_SECONDS = 1.0
BLIND_SHARE = 1 / 20
LMCUT_SHARE = 1 / 6
LMCUT_SECONDS = 2.0     # every LM-cut win on the IPC benchmark came within 1.1 s of CPU
SLICE_WALL_FACTOR = 10   # a slice also ends after this many times its CPU seconds of wall-clock time


def phases(limit: float | None) -> list[tuple[str, float | None]]:
    """(heuristic, seconds) in order; the last phase has whatever time is left (None: no limit)."""
    if limit is None:
        return [("blind", BLIND_SECONDS), ("lmcut", LMCUT_SECONDS), ("blind", None)]
    return [("blind", min(BLIND_SECONDS, limit * BLIND_SHARE)), ("lmcut", min(LMCUT_SECONDS, limit * LMCUT_SHARE)),
            ("blind", None)]


class _SliceOver(BaseException):
    """A phase's CPU slice is spent (raised from the search's progress callback). A
    BaseException, as the time-limit exceptions are: no `except Exception` may keep it."""


def solve(model, budget, progress=None, **options):
    """The slices count this process's CPU seconds (checked at the search's progress
    reports, every half second or so): on a busy machine a wall-clock second of blind
    search may be a fifth of a CPU second, and which phase solves a task would then
    depend on the machine's load. A slice also ends after SLICE_WALL_FACTOR times its
    length in wall-clock time; the time limit itself stays wall-clock time."""
    from . import Budget, get_solver
    from .base import Meter
    astar = get_solver("astar")
    start = time.perf_counter()
    limit = budget.time_limit
    plan = phases(limit)
    used: list[str] = []
    results = []
    for k, (heuristic, seconds) in enumerate(plan):
        left = None if limit is None else max(limit - (time.perf_counter() - start), 1e-3)
        cpu_start, seen = time.process_time(), {}

        def watch(_slice=seconds, _cpu_start=cpu_start, _seen=seen, **counters):
            _seen.update(counters)   # (counters has its own `seconds`: the search's wall time)
            if _slice is not None and time.process_time() - _cpu_start > _slice:
                raise _SliceOver
            if progress is not None:
                progress(**counters)
        wall = left if seconds is None else SLICE_WALL_FACTOR * seconds if left is None \
            else min(left, SLICE_WALL_FACTOR * seconds)
        try:
            result = astar(model, Budget(budget.max_states, wall, budget.max_memory_mb), watch, heuristic=heuristic)
        except _SliceOver:
            meter = Meter.latest
            result = Result(solver="astar", solved=False, status="budget", budget="time_limit", heuristic=heuristic,
                            expanded=seen.get("expanded", 0), generated=seen.get("generated", 0),
                            stored=seen.get("stored", 0), peak_mb=round(meter.peak_mb, 1) if meter else 0.0)
        results.append(result)
        used.append(heuristic)
        if result.solved or result.status != "budget" or k == len(plan) - 1 or result.budget != "time_limit" \
                and heuristic != "blind":
            break      # solved, proved unsolvable, last phase, or LM-cut out of states or memory
        if limit is not None and time.perf_counter() - start >= limit:
            break      # the whole time limit is spent
    if len(results) == 1:
        result.heuristic = f"auto ({heuristic})"
        return result
    result.expanded = sum(r.expanded for r in results)
    result.generated = sum(r.generated for r in results)
    result.stored = max(r.stored for r in results)
    result.seconds = round(time.perf_counter() - start, 6)
    result.peak_mb = max(r.peak_mb for r in results)
    result.heuristic = "auto (" + ", ".join(used[:-1]) + f", then {used[-1]})"
    known = [r.initial_h for r in results if r.initial_h is not None]
    result.initial_h = max(known) if known else None
    return result
