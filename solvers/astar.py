"""A* search: optimal with an admissible heuristic (default: manhattan).

Open list: a heap of (f, h, tie, state) -- among equal f, lower h (closer to the goal)
first. Duplicates are detected on the packed states; a state reached again more cheaply
is re-queued (lazy deletion), so a merely admissible heuristic stays optimal.
"""
from __future__ import annotations

import heapq
import math

from ..model import Model
from .base import CHECK_EVERY, Budget, Meter, Result, budget_result, extract_plan
from .heuristics import HEURISTICS


def solve(model: Model, budget: Budget, progress=None, heuristic: str = "manhattan", weight: float = 1.0,
          **options) -> Result:
    name = "astar"
    meter = Meter(budget, progress)
    h = HEURISTICS[heuristic](model)
    start = model.initial
    h0 = h(start)
    parents = {start: None}
    g_of = {start: 0}
    costs = model.action_costs
    successors, is_goal, is_failure = model.successors, model.is_goal, model.is_failure
    if h0 == math.inf:
        return meter.finish(Result(name, False, "no_solution", stored=1, heuristic=heuristic, initial_h=h0,
                                   message="no plan exists: the goal cannot hold at any reachable position"))
    tie = 0
    open_heap = [(weight * h0, h0, tie, start)]
    closed = set()
    expanded = generated = 0
    while open_heap:
        f, hs, _, state = heapq.heappop(open_heap)
        if state in closed:
            continue
        g = g_of[state]
        if is_goal(state):
            plan, cost = extract_plan(model, parents, state)
            return meter.finish(Result(name, True, "solved", plan, cost, expanded, generated, len(parents),
                                       heuristic=heuristic, initial_h=h0))
        closed.add(state)
        expanded += 1
        if expanded % CHECK_EVERY == 0:
            which = meter.check(expanded, generated, len(parents))
            if which:
                r = budget_result(name, which, meter, expanded, generated, len(parents))
                r.heuristic, r.initial_h = heuristic, h0
                return r
        for action, nxt in successors(state):
            generated += 1
            g2 = g + costs[action]
            old = g_of.get(nxt)
            if old is not None and old <= g2:
                continue
            if is_failure(nxt):
                continue
            hn = h(nxt)
            if hn == math.inf:
                continue
            g_of[nxt] = g2
            parents[nxt] = (state, action)
            closed.discard(nxt)
            tie += 1
            heapq.heappush(open_heap, (g2 + weight * hn, hn, tie, nxt))
    return meter.finish(Result(name, False, "no_solution", expanded=expanded, generated=generated,
                               stored=len(parents), heuristic=heuristic, initial_h=h0,
                               message="no plan exists: every reachable state was explored"))
