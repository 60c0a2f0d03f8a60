"""The heuristic that orders a task's methods: the fewest steps (decompositions and
actions) that can finish each subtask, over the lifted task decomposition graph.

Why this one: it needs no grounding and ignores preconditions, so it is cheap and never
says "impossible" wrongly; among the methods applicable in a state the search tries the
one that leaves the least work first (skip a block already in place before placing it,
stop walking where the target is in reach before walking further). A task that no
sequence of methods can ever reduce to actions gets infinity: its methods are never
tried.
"""
from __future__ import annotations

import math


def task_costs(methods: list, actions: set) -> dict:
    """task name -> fewest steps to decompose it fully (actions count 1, methods 1)."""
    cost = {m.task[0]: math.inf for m in methods}
    changed = True
    while changed:
        changed = False
        for m in methods:
            c = method_cost(m, cost, actions)
            if c < cost[m.task[0]]:
                cost[m.task[0]] = c
                changed = True
    return cost


def method_cost(m, cost: dict, actions: set) -> float:
    """1 for the decomposition, plus its subtasks' own costs."""
    return 1 + sum(1 if name in actions else cost.get(name, math.inf) for name, _ in m.subtasks)
