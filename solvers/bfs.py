"""Breadth-first search: optimal when every action costs the same (unit costs).

With differing costs it finds a plan of fewest steps; its reported cost is still the
plan's true sum of costs, and its message says it may not be the cheapest.

The goal test runs when a state is generated, one layer earlier than at expansion.
Successors come from `Model.search_fresh`, which also drops those seen before: states in
which the episode fails (e.g. the agent died) are left out there, unless they are goals,
and so are self-loops. Only each state's parent is kept; the plan's actions are recovered
at the end.
"""
from __future__ import annotations

from collections import deque

from ..model import Model
from .base import Budget, Meter, Result, budget_result, parent_plan
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
    fresh, is_goal = model.search_fresh(), model.is_goal
    frontier = deque([start])
    extend, popleft = frontier.extend, frontier.popleft
    expanded = generated = 0
    new: list = []   # this expansion's next states not seen before
    while frontier:
        state = popleft()
        expanded += 1
        if not expanded & mask or budget.max_states is not None and len(parents) > budget.max_states:
            which = meter.check(expanded, generated, len(parents))
            mask = meter.mask
            if which:
                return budget_result("bfs", which, meter, expanded, generated, len(parents))
        generated += fresh(state, parents, new)
        if new:
            for nxt in new:
                if is_goal(nxt):
                    plan, cost = parent_plan(model, parents, nxt)
                    note = "" if len(set(model.action_costs)) <= 1 else \
                        "fewest steps; actions' costs differ, so a cheaper plan may exist (astar finds it)"
                    return meter.finish(Result(solver="bfs", solved=True, status="solved", plan=plan, cost=cost,
                                               expanded=expanded, generated=generated, stored=len(parents),
                                               message=note))
            extend(new)
            new.clear()
    return meter.finish(Result(solver="bfs", solved=False, status="no_solution", expanded=expanded,
                               generated=generated,
                               stored=len(parents), message="no plan exists: every reachable state was explored"))
