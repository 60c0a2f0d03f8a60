"""Layer-by-layer search for searches whose first path to a state is a cheapest one:
breadth-first, and blind A* when every action costs the same.

Only each state's parent is kept (`parents`, which is also the duplicate check); plans
are recovered at the end (`parent_plan`). A layer is expanded in runs of states by the
model's generated expanders (`Model.search_layers`), which test new states for the goal
as they make them (a goal one layer down is a cheapest one, as Fast Downward's blind
heuristic, 0 only on goals, pops a generated goal next: mystery p02 has millions of
states a layer). New states are kept per group of the action that made them, so the
next layer skips what would only be duplicates: that action's inverses, and the earlier
actions it commutes with (compiler/inverses.py: why every layer still holds every
state of its depth). A run is as long as the expansions between
budget checks (`Meter.mask`), and short enough that a state budget is not overshot by
more than one expansion's next states.
"""
from __future__ import annotations

from ..model import Model
from .base import Meter, Result, parent_plan


def run_length(meter: Meter, max_states: int | None, stored: int, widest: int) -> int:
    """States to expand in one call of a generated expander: a progress report's worth,
    but no more than the state budget can take when each makes `widest` children (so a
    budget is overshot by at most one expansion's children)."""
    run = meter.mask + 1
    if max_states is not None:
        run = max(1, min(run, (max_states - stored) // widest))
    return run


def layered(model: Model, meter: Meter, name: str, lifo: bool, **fields) -> Result:
    """Search `model` layer by layer: last in, first out within a layer (`lifo`: the order
    A*'s buckets give) or first in, first out (breadth-first). `fields`: further Result
    fields (a heuristic's name)."""
    start, budget = model.initial, meter.budget
    parents = {start: None}
    is_goal = model.is_goal
    if is_goal(start):   # every other state is goal-tested when generated
        return meter.finish(Result(solver=name, solved=True, status="solved", plan=[], cost=0, expanded=0,
                                   generated=0, stored=1, **fields))
    expanders = model.search_layers()
    groups = len(expanders)
    max_states = budget.max_states
    widest = max(1, len(model.search_actions))   # next states of one expansion, at most
    expanded = generated = 0
    layer = [[start]] + [[] for _ in range(groups - 1)]
    while any(layer):
        below = [[] for _ in range(groups)]
        for expand, states in zip(expanders, layer):
            if lifo:
                states.reverse()
            at = 0
            while at < len(states):
                chunk = states[at:at + run_length(meter, max_states, len(parents), widest)]
                at += len(chunk)
                k = expand(chunk, parents, below)
                if k < 0:
                    goal = next(out[-1] for out in below if out and is_goal(out[-1]))
                    plan, cost = parent_plan(model, parents, goal)
                    expanded += chunk.index(parents[goal]) + 1
                    return meter.finish(Result(solver=name, solved=True, status="solved", plan=plan, cost=cost,
                                               expanded=expanded, generated=generated + ~k,
                                               stored=len(parents), **fields))
                expanded += len(chunk)
                generated += k
                stopped = meter.stop(expanded, generated, len(parents), **fields)
                if stopped:
                    return stopped
        layer = below
    return meter.finish(Result(solver=name, solved=False, status="no_solution", expanded=expanded,
                               generated=generated, stored=len(parents), **fields,
                               message="no plan exists: every reachable state was explored"))
