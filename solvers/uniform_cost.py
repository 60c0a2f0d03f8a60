"""Blind A* when actions cost different amounts: a search by cost (Dijkstra) in buckets.

Why not A*'s general loop: with h = 0 the open list is ordered by g alone, so states are
kept per g (a bucket) and a whole bucket is expanded by one generated call
(`Model.data("cost_expander")`: one loop over a run of states, each next state's cost
compared and stored in the generated code), where the general loop builds a list of
(action, state) pairs per state and handles each pair in Python (barman: 4.6 against
5.8 us an expansion; transport p03: 3.0 against 3.9 s). Exactness: buckets are taken in increasing g, so when bucket g is taken every
state of cost g is in it or reached from it by actions of cost 0 (expanded in the same
round, until none is left); an entry whose state was since reached more cheaply is
stale and skipped. Every state of a bucket is goal-tested before the bucket is expanded:
the first goal met is a cheapest one, as Fast Downward's blind A* finds.
"""
from __future__ import annotations

import heapq

from ..model import Model
from .base import Meter, Result, parent_plan
from .layers import run_length


def uniform_cost(model: Model, meter: Meter, name: str, expander, levels: tuple) -> Result:
    """Search `model` by cost with `expander` (see the module docstring); `levels`: the
    distinct action costs, smallest first (the expander's `outs[r]` holds states made by
    actions of cost levels[r])."""
    fields = {"heuristic": "blind", "initial_h": 0}
    start, budget = model.initial, meter.budget
    nodes = {start: (0, None)}        # state -> (cheapest g found, parent)
    is_goal = model.is_goal
    max_states = budget.max_states
    widest = max(1, len(model.search_actions))
    buckets: dict = {0: [start]}
    keys = [0]
    expanded = generated = 0
    zero = levels[0] == 0
    while keys:
        g = heapq.heappop(keys)
        pending = buckets.pop(g)
        while pending:
            states = [s for s in pending if nodes[s][0] == g]     # stale entries left out
            goal = next(filter(is_goal, states), None)
            if goal is not None:
                return _solved(model, meter, name, nodes, goal, expanded + states.index(goal), generated, fields)
            outs = [[] for _ in levels]
            at = 0
            while at < len(states):
                chunk = states[at:at + run_length(meter, max_states, len(nodes), widest)]
                at += len(chunk)
                generated += expander(chunk, g, nodes, outs)
                expanded += len(chunk)
                stopped = meter.stop(expanded, generated, len(nodes), **fields)
                if stopped:
                    return stopped
            for cost, out in zip(levels, outs):
                if cost and out:
                    bucket = buckets.get(g + cost)
                    if bucket is None:
                        buckets[g + cost] = out
                        heapq.heappush(keys, g + cost)
                    else:
                        bucket.extend(out)
            pending = outs[0] if zero else None
    return meter.finish(Result(solver=name, solved=False, status="no_solution", expanded=expanded,
                               generated=generated, stored=len(nodes), **fields,
                               message="no plan exists: every reachable state was explored"))


def _solved(model, meter, name, nodes, goal, expanded, generated, fields) -> Result:
    parents = {}
    state = goal
    while state is not None:
        parent = nodes[state][1]
        parents[state] = parent
        state = parent
    plan, cost = parent_plan(model, parents, goal)
    return meter.finish(Result(solver=name, solved=True, status="solved", plan=plan, cost=cost, expanded=expanded,
                               generated=generated, stored=len(nodes), **fields))
