"""IDA*: depth-first iterations with a growing f bound. Memory is the path, not the space.

Optimal with an admissible heuristic. Only the current path is checked for cycles, so
transpositions are searched again: slower than A* where A* fits in memory, but it never
runs out of it. `stored` reports the deepest path; since that stays small, the state
budget (--max-states) bounds the states it expands instead.
"""
from __future__ import annotations

import math

from ..model import Model
from .base import Budget, Meter, Result, budget_result
from ..heuristics.registry import make
from .options import declare, heuristic_option


class _Stop(Exception):
    def __init__(self, result: Result):
        self.result = result


@declare(heuristic_option("pdb"), optimal=True)
def solve(model: Model, budget: Budget, progress=None, heuristic: str = "pdb", **options) -> Result:
    meter = Meter(budget, progress, "idastar")
    h = make("pdb" if heuristic == "auto" else heuristic, model)
    # search successors: self-loops and failure states (unless goals) are left out there
    costs, successors, is_goal = model.action_costs, model.search_successors(), model.is_goal
    start = model.initial
    max_states = budget.max_states
    counters = {"expanded": 0, "generated": 0, "depth": 0}
    path_states, path_actions = [start], []
    on_path = {start}

    def dfs(state, g, bound):
        f = g + h(state)
        if f > bound:
            return f
        if is_goal(state):
            return True
        counters["expanded"] += 1
        expanded = counters["expanded"]
        if max_states is not None and expanded > max_states:   # it stores only its path: the budget counts expansions
            raise _Stop(budget_result("idastar", "max_states", meter, expanded, counters["generated"],
                                      counters["depth"], heuristic=heuristic, initial_h=h0))
        if not expanded & meter.mask:
            stopped = meter.stop(expanded, counters["generated"], counters["depth"], heuristic=heuristic, initial_h=h0)
            if stopped:
                raise _Stop(stopped)
        smallest = math.inf
        children = []
        nexts = successors(state)
        counters["generated"] += len(nexts)
        for action, nxt in nexts:
            if nxt in on_path:
                continue
            children.append((h(nxt) + costs[action], action, nxt))
        children.sort(key=lambda c: c[0])  # most promising first
        for _, action, nxt in children:
            path_states.append(nxt)
            path_actions.append(action)
            on_path.add(nxt)
            counters["depth"] = max(counters["depth"], len(path_states))
            t = dfs(nxt, g + costs[action], bound)
            if t is True:
                return True
            path_states.pop()
            path_actions.pop()
            on_path.discard(nxt)
            smallest = min(smallest, t)
        return smallest

    import sys
    sys.setrecursionlimit(max(sys.getrecursionlimit(), 100_000))
    bound = h(start)
    h0 = bound
    try:
        while bound != math.inf:
            t = dfs(start, 0, bound)
            if t is True:
                plan = [model.action_names[a] for a in path_actions]
                return meter.finish(Result(solver="idastar", solved=True, status="solved", plan=plan,
                                           cost=sum(costs[a] for a in path_actions),
                                           expanded=counters["expanded"], generated=counters["generated"],
                                           stored=counters["depth"],
                                           heuristic=heuristic, initial_h=h0))
            bound = t
    except _Stop as stop:
        return stop.result
    return meter.finish(Result(solver="idastar", solved=False, status="no_solution", expanded=counters["expanded"],
                               generated=counters["generated"], stored=counters["depth"], heuristic=heuristic,
                               initial_h=h0, message="no plan exists: no path within any bound"))
