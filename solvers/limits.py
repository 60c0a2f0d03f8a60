"""Budgets that hold for a whole command, not only inside a search loop.

Solvers check their `Budget` cooperatively, every so many expansions. That misses work
done outside the loop -- compiling, building a heuristic's table, a reference search, an
expensive goal test between two checks. `hard_limits` backs the budget up for the whole
command: the time limit becomes a timer (SIGALRM) that interrupts whatever runs once the
limit is spent plus a small grace, and the memory budget becomes a cap on the address
space (RLIMIT_AS), so an allocation past it fails at once with MemoryError instead of
the machine swapping. Both end as `BudgetExceeded`, which commands report like any
budget stop (exit 1). `Deadline` splits one command's time between its phases.
"""
from __future__ import annotations

import contextlib
import signal
import threading
import time

from .base import BUDGET_WORDS, Budget, Meter, Result
from .memory import arm_cap, disarm_cap, peak_rss_mb

# The cooperative check normally stops first; the timer only backs it up, after a grace of
# 0.5 s or 2 % of the limit, whichever is longer: on a busy machine a process may get a
# fifth of a core, and one step between two checks (a big table's resize) then takes
# seconds of wall time, which lost a 150 s run's counters to the timer.
GRACE_SECONDS = 0.5
GRACE_SHARE = 0.02
REPEAT_SECONDS = 0.25  # how often the timer fires again once the limit is spent


class BudgetExceeded(BaseException):
    """A budget ran out outside a solver's own checks; `which` names it like Result.budget.

    A BaseException, as KeyboardInterrupt is: the timer raises it wherever the process
    is, and code that keeps an `except Exception` (the PDDL export records per-value
    errors that way) must not swallow it."""

    def __init__(self, which: str):
        super().__init__(which)
        self.which = which


@contextlib.contextmanager
def hard_limits(budget: Budget, grace: float | None = None):
    """Enforce `budget`'s time and memory on everything run inside (main thread only;
    elsewhere, or without /proc and rlimits, the solvers' own checks still apply)."""
    timer = budget.time_limit is not None and threading.current_thread() is threading.main_thread()
    if timer:
        if grace is None:
            grace = max(GRACE_SECONDS, GRACE_SHARE * budget.time_limit)
        def expire(signum, frame):
            raise BudgetExceeded("time_limit")
        old_handler = signal.signal(signal.SIGALRM, expire)
        # Repeating: a raise inside a gc callback or a __del__ is printed and dropped by
        # Python, so the timer fires again until the limit really ends the command.
        signal.setitimer(signal.ITIMER_REAL, budget.time_limit + grace, REPEAT_SECONDS)
    old_cap = arm_cap(budget.max_memory_mb) if budget.max_memory_mb is not None else None
    start = time.monotonic()
    try:
        yield
    except MemoryError:
        raise BudgetExceeded("max_memory") from None
    except ImportError as exc:
        # The timer's raise inside an extension module's initialisation comes out as
        # "ImportError: initialization failed" (seen in CI: `bcc train --time-limit 0.5`
        # exited 3), with or without the raise chained to it.
        which = _budget_in(exc)
        if which is None and timer and time.monotonic() - start >= budget.time_limit:
            which = "time_limit"
        if which is None:
            raise
        raise BudgetExceeded(which) from None
    finally:
        if timer:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, old_handler)
        if old_cap is not None:
            disarm_cap(old_cap)


def _budget_in(exc: BaseException) -> str | None:
    """The budget named by a BudgetExceeded (or a MemoryError) that `exc` was raised from."""
    seen = set()
    while exc is not None and id(exc) not in seen:
        seen.add(id(exc))
        if isinstance(exc, BudgetExceeded):
            return exc.which
        if isinstance(exc, MemoryError):
            return "max_memory"
        exc = exc.__cause__ or exc.__context__
    return None


class Deadline:
    """One command's budget, shared by its phases: each phase gets the time left."""

    def __init__(self, budget: Budget):
        self.budget = budget
        self.start = time.perf_counter()

    def elapsed(self) -> float:
        return time.perf_counter() - self.start

    def remaining(self, share: float = 1.0) -> Budget:
        """The budget for the next phase: `share` of the time left (states and memory are
        whole-process limits, so they pass unchanged)."""
        b = self.budget
        if b.time_limit is None:
            return b
        left = max(b.time_limit - self.elapsed(), 1e-3)
        return Budget(max_states=b.max_states, time_limit=left * share, max_memory_mb=b.max_memory_mb)


def exceeded_result(solver: str, which: str, deadline: Deadline) -> Result:
    """The result of a run stopped by `hard_limits`: the search's own counters went with
    it, so those of its last budget check stand in (zeros if no search began)."""
    meter = Meter.latest
    expanded, generated, stored = meter.counts if meter is not None and meter.start >= deadline.start else (0, 0, 0)
    return Result(solver=solver, solved=False, status="budget", budget=which, seconds=round(deadline.elapsed(), 6),
                  expanded=expanded, generated=generated, stored=stored,
                  peak_mb=round(peak_rss_mb(), 1), message=f"stopped: {BUDGET_WORDS[which]} ran out")
