"""A* search, and its weighted variant: f = g + w * h.

With w = 1 and an admissible heuristic the plan is optimal; w > 1 (`wastar`, `--weight`)
trades optimality for speed (cost at most w times the optimum). Among equal f, lower h
first. Duplicates are detected on the packed states before the heuristic is computed; a
state reached again more cheaply is re-queued and its older entries are skipped when
popped (lazy deletion), so a merely admissible heuristic stays optimal.

The open list is bucketed: a small heap of the distinct keys (f, h) and, per key, a list
of states (the last in is expanded first). With integer costs and w = 1 a key is one int
(f << 32 | h; a fractional h is rounded up, which keeps it admissible since every plan
costs an integer), so a push is an append and a pop a list pop; the heap only orders the
few distinct keys. A state's g is read back from its key, so entries are bare states.
Blind search with equal action costs expands the same states in the same order with no
keys at all (`_layered`): layer by layer, over `Model.search_layers`.

Heuristic `auto` (the default) starts with the cheap `manhattan` and, if the search is
still running after SWITCH_AFTER expansions, builds the pattern database and re-sorts the
open list by it. Both are consistent, so optimality is kept: every closed state already
has its optimal g, and the open list still holds a state of some optimal path. A budget
check or the switch never skips work: the state popped on that expansion is expanded.
Where the goal needs cells of the grid changed (carrying things somewhere), `auto` uses
the counting abstraction (heuristics/counting.py) instead, if it can be built.
"""
from __future__ import annotations

import heapq
import math

from ..model import Model
from .base import Budget, Meter, Result
from ..heuristics.position import position_blind
from ..heuristics.registry import HEURISTICS, make, serves
from .layers import layered
from .options import Option, declare, heuristic_option

SWITCH_AFTER = 4096
SHIFT = 32            # packed key: f << SHIFT | h
LOW = (1 << SHIFT) - 1


def weight_option(default: float) -> Option:
    return Option("weight", float, default, "f = g + W h; W > 1 is faster, cost <= W x optimal", low=1)


@declare(heuristic_option("auto"), weight_option(1.0), optimal=True)
def solve(model: Model, budget: Budget, progress=None, heuristic: str = "auto", weight: float = 1.0,
          **options) -> Result:
    return _search(model, Meter(budget, progress, "astar"), heuristic, weight)


def _choose(model: Model, heuristic: str, time_limit: float | None) -> tuple:
    """(h, its name, whether `auto` may still switch to the pattern database)."""
    switching = heuristic == "auto"
    used = "manhattan" if switching else heuristic
    if switching and model.data("counting_wanted"):
        # The goal needs cells of the grid changed: the counting abstraction sees that (and
        # the agent's position, which it keeps); past its limits, the choices below.
        h = make("counting", model, time_limit)
        if not getattr(h, "fallback", None):
            return h, "counting", False
    if switching and model.goal_positions is None and model.data("pattern_database") is None:
        # No agent position (e.g. imported PDDL): LM-cut on the relaxed view if it serves the model.
        switching, used = False, "lmcut" if serves("lmcut", model) else "blind"
    elif switching and position_blind(model):
        # The goal does not pin the agent's position: manhattan and the pattern database
        # are 0 everywhere, so they would only slow a blind search down.
        switching, used = False, "blind"
    return make(used, model), used, switching


def _search(model: Model, meter: Meter, heuristic: str, weight: float) -> Result:
    """A* (weight 1) or weighted A* under `meter`, which names the solver."""
    name, budget, mask = meter.solver, meter.budget, meter.mask
    h, used, switching = _choose(model, heuristic, budget.time_limit)
    zero = used == "blind"
    if zero and len(set(model.action_costs)) <= 1:
        return _layered(model, meter, name)
    if zero and model.data("cost_expander"):   # a generated search by cost (imported PDDL)
        from .uniform_cost import uniform_cost
        return uniform_cost(model, meter, name, *model.data("cost_expander"))
    start = model.initial
    h0 = h(start)
    # One map for everything known about a state: (g, parent state, action). A state is
    # expanded when popped with its current g; an entry with a larger g is stale (lazy
    # deletion), so no closed set is kept.
    nodes = {start: (0, None, None)}
    costs = model.action_costs
    packed = weight == 1 and all(type(c) is int for c in costs)
    successors, is_goal = model.search_successors(), model.is_goal

    def result(**kw) -> Result:
        return meter.finish(Result(solver=name, heuristic=used, initial_h=h0, stored=len(nodes), **kw))

    if h0 == math.inf:
        return result(solved=False, status="no_solution",
                      message="no plan exists: the goal cannot hold at any reachable position")
    keys, bins = _open_list([start], nodes, h, weight, packed)
    # An admissible heuristic is 0 on every goal: a state it rates above 0 skips the goal test
    # (the auto switch moves between admissible ones)
    goal_aware = HEURISTICS[used].admissible
    get, push, pop, inf, ceil = nodes.get, heapq.heappush, heapq.heappop, math.inf, math.ceil
    expanded = generated = 0
    max_states = budget.max_states
    while keys:
        key = keys[0]
        entries = bins[key]
        state = entries.pop()
        if not entries:
            pop(keys)
            del bins[key]
        if packed:
            g = (key >> SHIFT) - (key & LOW)
        else:
            g = key[2]
        if nodes[state][0] < g:
            continue
        if (not goal_aware or not (key & LOW if packed else key[1])) and is_goal(state):
            plan, cost = _plan(model, nodes, state)
            return result(solved=True, status="solved", plan=plan, cost=cost, expanded=expanded, generated=generated)
        expanded += 1
        if not expanded & mask or max_states is not None and len(nodes) > max_states:
            stopped = meter.stop(expanded, generated, len(nodes), heuristic=used, initial_h=h0)
            if stopped:
                return stopped
            mask = meter.mask
            if switching and expanded >= SWITCH_AFTER:
                switching = False
                h = make("pdb", model)
                used = "auto (manhattan, then pdb)"
                keys, bins = _open_list(_open_states(keys, bins, nodes, packed), nodes, h, weight, packed)
                # no `continue`: `state` is expanded and counted, so its successors are
                # generated now (skipping them lost optimal paths through it)
        nexts = successors(state)
        generated += len(nexts)
        for action, nxt in nexts:
            g2 = g + costs[action]
            old = get(nxt)
            if old is not None and old[0] <= g2:
                continue
            if zero:
                hn = 0
            else:
                hn = h(nxt)
                if hn.__class__ is not int:
                    if hn == inf:
                        continue
                    if packed:
                        hn = ceil(hn)
            nodes[nxt] = (g2, state, action)
            key = ((g2 + hn) << SHIFT) | hn if packed else (g2 + weight * hn, hn, g2)
            entries = bins.get(key)
            if entries is None:
                bins[key] = [nxt]
                push(keys, key)
            else:
                entries.append(nxt)
    return result(solved=False, status="no_solution", expanded=expanded, generated=generated,
                  message="no plan exists: every reachable state was explored")


def _layered(model: Model, meter: Meter, name: str) -> Result:
    """Blind A* when every action costs the same: f = g orders states by depth, so the
    open list is the layer being expanded (last in, first out, as the buckets would) and
    the next one; a state's first path is a cheapest one (solvers/layers.py)."""
    return layered(model, meter, name, lifo=True, heuristic="blind", initial_h=0)


def _plan(model: Model, nodes: dict, state) -> tuple[list[str], int]:
    actions = []
    _, parent, action = nodes[state]
    while parent is not None:
        actions.append(action)
        _, parent, action = nodes[parent]
    actions.reverse()
    return [model.action_names[a] for a in actions], sum(model.action_costs[a] for a in actions)


def _open_states(keys: list, bins: dict, nodes: dict, packed: bool) -> list:
    """The states of the open list that are not stale, each once."""
    out, seen = [], set()
    for key in keys:
        g = (key >> SHIFT) - (key & LOW) if packed else key[2]
        for state in bins[key]:
            if nodes[state][0] == g and state not in seen:
                seen.add(state)
                out.append(state)
    return out


def _open_list(states: list, nodes: dict, h, weight: float, packed: bool) -> tuple[list, dict]:
    """A fresh open list (the key heap, and the states per key) of `states` under `h`;
    dead ends (h infinite) are dropped."""
    bins: dict = {}
    for state in states:
        g, hn = nodes[state][0], h(state)
        if hn == math.inf:
            continue
        if packed:
            hn = math.ceil(hn)
            key = ((g + hn) << SHIFT) | hn
        else:
            key = (g + weight * hn, hn, g)
        bins.setdefault(key, []).append(state)
    keys = list(bins)
    heapq.heapify(keys)
    return keys, bins


@declare(heuristic_option("auto"), weight_option(2.0))
def solve_weighted(model: Model, budget: Budget, progress=None, heuristic: str = "auto", weight: float = 2.0,
                   **options) -> Result:
    """Weighted A* (default w = 2): usually much faster, cost at most w x optimal."""
    return _search(model, Meter(budget, progress, "wastar"), heuristic, weight)
