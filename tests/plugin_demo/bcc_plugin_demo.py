"""A demonstration bcc solver plugin: iterative depth-first search.

Registered in the `bcc.solvers` entry-point group as `dfs` (see pyproject.toml). It
follows the contract of every bcc solver, `solve(model, budget, progress=None,
**options) -> Result`, and uses only the public pieces of `bcc.solvers.base` and
`bcc.model`. The plan it returns is valid but not necessarily optimal.
"""
from __future__ import annotations

from bcc.model import Model
from bcc.solvers.base import CHECK_EVERY, Budget, Meter, Result, budget_result, extract_plan

NAME = "dfs"


def solve(model: Model, budget: Budget, progress=None, **options) -> Result:
    """Depth-first search, a demonstration plugin (not optimal)."""
    meter = Meter(budget, progress)
    start = model.initial
    parents = {start: None}  # state -> (previous state, action index); doubles as the visited set
    if model.is_goal(start):
        return meter.finish(Result(solver=NAME, solved=True, status="solved", plan=[], cost=0, expanded=0,
                                   generated=1, stored=1))
    successors, is_goal, is_failure = model.successors, model.is_goal, model.is_failure
    stack = [start]
    expanded = generated = 0
    while stack:
        state = stack.pop()
        expanded += 1
        if expanded % CHECK_EVERY == 0 or budget.max_states is not None and len(parents) > budget.max_states:
            which = meter.check(expanded, generated, len(parents))
            if which:
                return budget_result(NAME, which, meter, expanded, generated, len(parents))
        children = []
        for action, nxt in successors(state):
            generated += 1
            if nxt in parents:
                continue
            parents[nxt] = (state, action)
            if is_goal(nxt):
                plan, cost = extract_plan(model, parents, nxt)
                return meter.finish(Result(solver=NAME, solved=True, status="solved", plan=plan, cost=cost,
                                           expanded=expanded, generated=generated, stored=len(parents)))
            if not is_failure(nxt):  # states in which the episode failed are never expanded
                children.append(nxt)
        stack.extend(reversed(children))  # the first successor is explored first
    return meter.finish(Result(solver=NAME, solved=False, status="no_solution", expanded=expanded,
                               generated=generated,
                               stored=len(parents), message="no plan exists: every reachable state was explored"))
