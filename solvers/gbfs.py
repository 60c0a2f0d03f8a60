"""Greedy best-first search: always expand the state with the lowest h. Fast, not optimal."""
from __future__ import annotations

import heapq
import math

from ..model import Model
from .base import CHECK_EVERY, Budget, Meter, Result, budget_result, extract_plan
from .heuristics import HEURISTICS


def solve(model: Model, budget: Budget, progress=None, heuristic: str = "pdb", **options) -> Result:
    meter = Meter(budget, progress)
    h = HEURISTICS["pdb" if heuristic == "auto" else heuristic](model)
    start = model.initial
    parents = {start: None}
    h0 = h(start)
    if h0 == math.inf:
        return meter.finish(Result("gbfs", False, "no_solution", stored=1, heuristic=heuristic, initial_h=h0,
                                   message="no plan exists: the goal cannot hold at any reachable position"))
    heap = [(h0, 0, start)]
    tie = expanded = generated = 0
    while heap:
        _, _, state = heapq.heappop(heap)
        if model.is_goal(state):
            plan, cost = extract_plan(model, parents, state)
            return meter.finish(Result("gbfs", True, "solved", plan, cost, expanded, generated, len(parents),
                                       heuristic=heuristic, initial_h=h0))
        expanded += 1
        if expanded % CHECK_EVERY == 0 or budget.max_states is not None and len(parents) > budget.max_states:
            which = meter.check(expanded, generated, len(parents))
            if which:
                return budget_result("gbfs", which, meter, expanded, generated, len(parents))
        for action, nxt in model.successors(state):
            generated += 1
            if nxt in parents or model.is_failure(nxt):
                continue
            hn = h(nxt)
            if hn == math.inf:
                continue
            parents[nxt] = (state, action)
            tie += 1
            heapq.heappush(heap, (hn, tie, nxt))
    return meter.finish(Result("gbfs", False, "no_solution", expanded=expanded, generated=generated,
                               stored=len(parents), heuristic=heuristic, initial_h=h0,
                               message="no plan exists: every reachable state was explored"))
