"""What every solver shares: budgets, the result record, plan extraction, memory probes.

Every solver is `solve(model, budget, progress=None, **options) -> Result`. Hitting a
budget ends the run cleanly with `status="budget"` and `budget` naming which one.
"""
from __future__ import annotations

import time
from dataclasses import asdict, dataclass, field
from typing import Callable

from ..model import Model
from .memory import current_rss_mb, memory_check, peak_rss_mb, physical_memory_mb

CHECK_EVERY = 1024  # expansions between time/memory checks, at most
CHECK_GAP = 0.1     # seconds between checks, at most, once the loop has adapted


@dataclass(frozen=True)
class Budget:
    """Limits of one run. max_states counts distinct states stored; None = no limit."""
    max_states: int | None = None
    time_limit: float | None = None
    max_memory_mb: float | None = None

    @staticmethod
    def default() -> "Budget":
        # Half the machine: a search must stop cleanly long before the OS kills it.
        return Budget(max_states=None, time_limit=None, max_memory_mb=physical_memory_mb() * 0.5)


@dataclass
class Result:
    solver: str
    solved: bool
    status: str                    # "solved" | "no_solution" | "budget"
    plan: list = field(default_factory=list)
    cost: int | None = None
    expanded: int = 0
    generated: int = 0
    stored: int = 0
    seconds: float = 0.0
    peak_mb: float = 0.0
    budget: str | None = None      # which budget ran out: "max_states" | "time_limit" | "max_memory"
    message: str = ""
    heuristic: str | None = None
    initial_h: float | None = None
    episodes: list = field(default_factory=list)   # learning solvers: [{"steps", "return", "success"}, ...]
    converged_episode: int | None = None           # learning solvers: first episode after which all are optimal
    lower_bound: int | None = None                 # build: an admissible lower bound on the cost from the start

    def to_json(self) -> dict:
        return asdict(self)


def table_growth_mb(stored: int, growth: int, tables: int = 2) -> float:
    """Memory the search's hash tables (a parent map, a cost map) take at once when they
    grow before the next check, else 0. With small states a table's resize is the
    biggest single allocation: a dict of n entries moves to a new table of about 40 bytes
    per slot, twice its old size, when it is 2/3 full (CPython)."""
    slots = 8
    while slots * 2 // 3 < stored:
        slots *= 2
    if stored + 2 * growth < slots * 2 // 3:
        return 0.0
    return tables * 40 * slots / 2**20


class Meter:
    """Time, memory and progress bookkeeping for a search loop, and its one budget check.

    Every loop calls `stop` the same way, on the expansions `mask` picks and whenever the
    states stored pass the state budget (exact), testing nothing else per expansion:

        mask, max_states = meter.mask, budget.max_states
        ...
        expanded += 1
        if not expanded & mask or max_states is not None and stored > max_states:
            stopped = meter.stop(expanded, generated, stored, heuristic=...)
            if stopped:
                return stopped
            mask = meter.mask

    The learners call it every so many steps instead (a step is cheap, planning is not).
    """

    # The newest Meter of this process: a run stopped outside its loop's checks (by
    # `limits.hard_limits`) still reports the counters of its last check.
    latest: "Meter | None" = None

    def __init__(self, budget: Budget, progress: Callable | None = None, solver: str = ""):
        self.budget, self.progress, self.solver = budget, progress, solver
        self.start = time.perf_counter()
        self.base_mb = current_rss_mb()
        self.peak_mb = self.base_mb
        self.last_report = self.last_check = self.start
        self.last_stored = 0
        # Expansions between checks, less one (a loop tests `not expanded & mask`): from 0,
        # doubled while checks come close together, up to CHECK_EVERY - 1, and halved while
        # they come more than CHECK_GAP apart (a costly heuristic expands a few hundred
        # states a second), so a limit is seen within about CHECK_GAP.
        self.mask = 0
        self.counts = (0, 0, 0)   # (expanded, generated, stored) at the last check
        Meter.latest = self

    def elapsed(self) -> float:
        return time.perf_counter() - self.start

    def check(self, expanded: int, generated: int, stored: int) -> str | None:
        """Called when `expanded & self.mask` is 0: the exhausted budget's name, or None."""
        b = self.budget
        self.counts = (expanded, generated, stored)
        if b.max_states is not None and stored > b.max_states:
            return "max_states"
        now = time.perf_counter()
        gap, self.last_check = now - self.last_check, now
        if gap > CHECK_GAP and self.mask:
            self.mask >>= 1
        elif gap < CHECK_GAP / 8 and self.mask < CHECK_EVERY - 1:
            self.mask = self.mask * 2 + 1
        if b.time_limit is not None and now - self.start > b.time_limit:
            return "time_limit"
        growth, self.last_stored = stored - self.last_stored, stored
        mb, fits = memory_check(b.max_memory_mb, table_growth_mb(stored, growth))
        self.peak_mb = max(self.peak_mb, mb)
        if not fits:
            return "max_memory"
        if self.progress is not None and now - self.last_report >= 0.5:
            self.last_report = now
            self.progress(expanded=expanded, generated=generated, stored=stored, seconds=now - self.start)
        return None

    def stop(self, expanded: int, generated: int, stored: int, **fields) -> Result | None:
        """`check`, and the Result to return when a budget ran out (status "budget", the
        solver named at construction, `fields` added: the heuristic, a learner's
        episodes), else None."""
        which = self.check(expanded, generated, stored)
        if which is None:
            return None
        return budget_result(self.solver, which, self, expanded, generated, stored, **fields)

    def finish(self, result: Result) -> Result:
        result.seconds = round(self.elapsed(), 6)
        self.peak_mb = max(self.peak_mb, current_rss_mb(), peak_rss_mb())
        result.peak_mb = round(self.peak_mb, 1)
        return result


BUDGET_WORDS = {
    "max_states": "the state budget (--max-states)",
    "time_limit": "the time limit (--time-limit)",
    "max_memory": "the memory budget (--max-memory)",
}


def budget_result(solver: str, which: str, meter: Meter, expanded: int, generated: int, stored: int,
                  **fields) -> Result:
    """The result of a run its budget stopped; `fields` are further Result fields (the
    heuristic, a learner's episodes)."""
    return meter.finish(Result(solver=solver, solved=False, status="budget", expanded=expanded,
                               generated=generated, stored=stored, **fields,
                               budget=which, message=f"stopped: {BUDGET_WORDS[which]} ran out"))


def without_actions(model: Model, meter: Meter, solver: str, **fields) -> Result:
    """A learner's result on a model with no actions (a domain may declare none): the
    start is the only state, reached by the empty plan if it is a goal."""
    done = model.is_goal(model.initial)
    return meter.finish(Result(solver=solver, solved=done, status="solved" if done else "no_solution",
                               cost=0 if done else None, stored=1, **fields,
                               message="" if done else "no plan exists: the domain has no actions"))


def extract_plan(model: Model, parents: dict, state: bytes) -> tuple[list[str], int]:
    """Follow parent links (state -> (previous state, action index)) back to the start."""
    actions = []
    while True:
        prev = parents[state]
        if prev is None:
            break
        state, a = prev
        actions.append(a)
    actions.reverse()
    return [model.action_names[a] for a in actions], sum(model.action_costs[a] for a in actions)


def parent_plan(model: Model, parents: dict, state: bytes) -> tuple[list[str], int]:
    """The plan to `state` from a map that keeps only each state's parent (state -> previous
    state, None at the start; see `Model.search_fresh`): each step's action is recovered
    as the cheapest one leading from the parent to the child."""
    costs, chain = model.action_costs, []
    while True:
        parent = parents[state]
        if parent is None:
            break
        chain.append(min((a for a, n in model.successors(parent) if n == state), key=lambda a: (costs[a], a)))
        state = parent
    chain.reverse()
    return [model.action_names[a] for a in chain], sum(costs[a] for a in chain)
