"""A* search, and its weighted variant: f = g + w * h.

With w = 1 and an admissible heuristic the plan is optimal; w > 1 (`wastar`, `--weight`)
trades optimality for speed (cost at most w times the optimum). Open list: a heap of
(f, h, tie, g, state) -- among equal f, lower h first. Duplicates are detected on the
packed states before the heuristic is computed; a state reached again more cheaply is
re-queued and its older entries are skipped when popped (lazy deletion), so a merely
admissible heuristic stays optimal.

Heuristic `auto` (the default) starts with the cheap `manhattan` and, if the search is
still running after SWITCH_AFTER expansions, builds the pattern database and re-sorts the
open list by it. Both are consistent, so optimality is kept: every closed state already
has its optimal g, and the open list still holds a state of some optimal path. A budget
check or the switch never skips work: the state popped on that expansion is expanded.
"""
from __future__ import annotations

import heapq
import math

from ..model import Model
from .base import CHECK_EVERY, Budget, Meter, Result, budget_result
from .heuristics import HEURISTICS
from .options import Option, declare, heuristic_option

SWITCH_AFTER = 4096


def weight_option(default: float) -> Option:
    return Option("weight", float, default, "f = g + W h; W > 1 is faster, cost <= W x optimal", low=1)


@declare(heuristic_option("auto"), weight_option(1.0), optimal=True)
def solve(model: Model, budget: Budget, progress=None, heuristic: str = "auto", weight: float = 1.0,
          name: str = "astar", **options) -> Result:
    meter = Meter(budget, progress)
    switching = heuristic == "auto"
    used = "manhattan" if switching else heuristic
    if switching and model.goal_positions is None and model.data("pattern_database") is None:
        # No agent position (e.g. imported PDDL): LM-cut on the relaxed view if there is one.
        switching, used = False, "lmcut" if "relaxed_task" in model.lazy else "blind"
    h = HEURISTICS[used](model)
    start = model.initial
    h0 = h(start)
    # One map for everything known about a state: (g, parent state, action). A state is
    # expanded when popped with its current g; an entry with a larger g is stale (lazy
    # deletion), so no closed set is kept.
    nodes = {start: (0, None, None)}
    costs = model.action_costs
    successors, is_goal, is_failure = model.successors, model.is_goal, model.is_failure
    push, pop = heapq.heappush, heapq.heappop

    def result(**kw) -> Result:
        return meter.finish(Result(solver=name, heuristic=used, initial_h=h0, stored=len(nodes), **kw))

    if h0 == math.inf:
        return result(solved=False, status="no_solution",
                      message="no plan exists: the goal cannot hold at any reachable position")
    tie = 0
    open_heap = [(weight * h0, h0, tie, 0, start)]
    expanded = generated = 0
    max_states = budget.max_states
    while open_heap:
        f, hs, _, g, state = pop(open_heap)
        if nodes[state][0] < g:
            continue
        if is_goal(state):
            plan, cost = _plan(model, nodes, state)
            return result(solved=True, status="solved", plan=plan, cost=cost, expanded=expanded, generated=generated)
        expanded += 1
        if expanded % CHECK_EVERY == 0 or max_states is not None and len(nodes) > max_states:
            which = meter.check(expanded, generated, len(nodes))
            if which:
                r = budget_result(name, which, meter, expanded, generated, len(nodes))
                r.heuristic, r.initial_h = used, h0
                return r
            if switching and expanded >= SWITCH_AFTER:
                switching = False
                h = HEURISTICS["pdb"](model)
                used = "auto (manhattan, then pdb)"
                open_heap = _resort(open_heap, nodes, h, weight)
                # no `continue`: `state` is expanded and counted, so its successors are
                # generated now (skipping them lost optimal paths through it)
        for action, nxt in successors(state):
            generated += 1
            g2 = g + costs[action]
            old = nodes.get(nxt)
            if old is not None and old[0] <= g2:
                continue
            if is_failure(nxt):
                continue
            hn = h(nxt)
            if hn == math.inf:
                continue
            nodes[nxt] = (g2, state, action)
            tie += 1
            push(open_heap, (g2 + weight * hn, hn, tie, g2, nxt))
    return result(solved=False, status="no_solution", expanded=expanded, generated=generated,
                  message="no plan exists: every reachable state was explored")


def _plan(model: Model, nodes: dict, state) -> tuple[list[str], int]:
    actions = []
    _, parent, action = nodes[state]
    while parent is not None:
        actions.append(action)
        _, parent, action = nodes[parent]
    actions.reverse()
    return [model.action_names[a] for a in actions], sum(model.action_costs[a] for a in actions)


def _resort(open_heap, nodes, h, weight) -> list:
    """The open list under a new heuristic (stale, duplicate and dead-end entries dropped)."""
    fresh, seen = [], set()
    for _, _, tie, g, state in open_heap:
        if nodes[state][0] < g or state in seen:
            continue
        seen.add(state)
        hn = h(state)
        if hn != math.inf:
            fresh.append((g + weight * hn, hn, tie, g, state))
    heapq.heapify(fresh)
    return fresh


@declare(heuristic_option("auto"), weight_option(2.0))
def solve_weighted(model: Model, budget: Budget, progress=None, weight: float = 2.0, **options) -> Result:
    """Weighted A* (default w = 2): usually much faster, cost at most w x optimal."""
    return solve(model, budget, progress, weight=weight, name="wastar", **options)
