"""Breadth-first search: optimal when every action costs the same (unit costs).

With differing costs it finds a plan of fewest steps; its reported cost is still the
plan's true sum of costs, and its message says it may not be the cheapest.

Layer by layer (solvers/layers.py), first in, first out: the goal test runs when a state
is generated, one layer earlier than at expansion; states in which the episode fails
(e.g. the agent died) are left out unless they are goals, and so are self-loops. Only
each state's parent is kept; the plan's actions are recovered at the end.
"""
from __future__ import annotations

from ..model import Model
from .base import Budget, Meter, Result
from .layers import layered
from .options import declare


@declare(optimal=True)   # no options; optimal for unit costs
def solve(model: Model, budget: Budget, progress=None, **options) -> Result:
    meter = Meter(budget, progress, "bfs")
    if model.is_goal(model.initial):
        return meter.finish(Result(solver="bfs", solved=True, status="solved", plan=[], cost=0, expanded=0,
                                   generated=1, stored=1))
    result = layered(model, meter, "bfs", lifo=False)
    if result.solved and len(set(model.action_costs)) > 1:
        result.message = "fewest steps; actions' costs differ, so a cheaper plan may exist (astar finds it)"
    return result
