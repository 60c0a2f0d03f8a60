"""Breadth-first search: optimal when every action costs the same (unit costs).

With differing costs it finds a plan of fewest steps; its reported cost is still the
plan's true sum of costs, and its message says it may not be the cheapest.

The goal test runs when a state is generated, one layer earlier than at expansion.
Successors come from `Model.search_successors`: states in which the episode fails (e.g.
the agent died) are left out there, unless they are goals, and so are self-loops.
"""
from __future__ import annotations

from collections import deque

from ..model import Model
from .base import Budget, Meter, Result, budget_result, extract_plan
from .options import declare


@declare(optimal=True)   # no options; optimal for unit costs
def solve(model: Model, budget: Budget, progress=None, **options) -> Result:
    meter = Meter(budget, progress)
    mask = meter.mask
    start = model.initial
    parents = {start: None}
    if model.is_goal(start):
        return meter.finish(Result(solver="bfs", solved=True, status="solved", plan=[], cost=0, expanded=0,
                                   generated=1, stored=1))
    successors, is_goal = model.search_successors(), model.is_goal
    frontier = deque([start])
    append, popleft = frontier.append, frontier.popleft
    expanded = generated = 0
    while frontier:
        state = popleft()
        expanded += 1
        if not expanded & mask or budget.max_states is not None and len(parents) > budget.max_states:
            which = meter.check(expanded, generated, len(parents))
            mask = meter.mask
            if which:
                return budget_result("bfs", which, meter, expanded, generated, len(parents))
        nexts = successors(state)
        generated += len(nexts)
        for action, nxt in nexts:
            if nxt in parents:
                continue
            parents[nxt] = (state, action)
            if is_goal(nxt):
                plan, cost = extract_plan(model, parents, nxt)
                note = "" if len(set(model.action_costs)) <= 1 else \
                    "fewest steps; actions' costs differ, so a cheaper plan may exist (astar finds it)"
                return meter.finish(Result(solver="bfs", solved=True, status="solved", plan=plan, cost=cost,
                                           expanded=expanded, generated=generated, stored=len(parents),
                                           message=note))
            append(nxt)
    return meter.finish(Result(solver="bfs", solved=False, status="no_solution", expanded=expanded,
                               generated=generated,
                               stored=len(parents), message="no plan exists: every reachable state was explored"))
