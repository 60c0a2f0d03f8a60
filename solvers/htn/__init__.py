"""The `htn` solver: total-order HTN planning by progression (search.py), for the task
networks of `bcc import hddl` and of dungeons that give a `task:` (or `bcc solve --task`).

Its input is an `HtnProblem` (hddl/task.py), planned over lifted facts
(hddl_network.py), or a compiled dungeon with a task network, planned over its own
states with its generated code (model_network.py); one search (search.py) plans both.
A dungeon without a task has nothing to decompose: `--solver htn` is refused there.
Its plan is the action sequence; `Result.decomposition` holds the decomposition tree
(the IPC plan format's content: hddl/plan.py writes it).
"""
from __future__ import annotations

import functools
import gc
from dataclasses import dataclass

from ...errors import BccError
from ...model import Model
from ..base import Budget, Meter, Result, budget_result
from ..options import declare
from .search import run_search

NAME = "htn"


@dataclass
class HtnResult(Result):
    decomposition: dict | None = None   # {"root": [ids], "tasks": [{id, task, method, subtasks}]}; actions: 0..n-1


def takes_task_network(solve):
    """Marks a solver whose input is a task network (`bcc import hddl`, or a dungeon with a
    task), not a goal alone."""
    solve.input = "task network"
    return solve


@takes_task_network
@declare()   # one configuration for every domain
def solve(model, budget: Budget, progress=None, **options) -> Result:
    """Total-order HTN progression: depth first over (state, task network), methods bound
    against the state as they are applied, tried least-work-first, loops cut."""
    meter = Meter(budget, progress)
    if isinstance(model, Model):   # (tested first: the HDDL front end is imported only for its problems)
        hierarchy = model.data("hierarchy")
        if hierarchy is None or hierarchy.root is None:
            raise BccError("the htn solver plans task networks: give the dungeon a `task:` (or bcc solve --task "
                           "TASK), or an HDDL domain and problem (bcc import hddl DOMAIN PROBLEM)")
        from .model_network import ModelNetwork, StateStack
        compiled = ModelNetwork(model, hierarchy)
        facts = StateStack(model.initial)
    else:
        from ...hddl.task import HtnProblem
        if not isinstance(model, HtnProblem):
            raise BccError("the htn solver plans task networks: a dungeon with a task, or an HDDL problem")
        from .facts import Facts
        from .hddl_network import HddlNetwork
        compiled = HddlNetwork(model)
        facts = Facts(compiled.init, compiled.patterns)
    was = gc.isenabled()
    gc.disable()   # the search's tuples form no cycles; a full collection would rescan them all
    try:
        out = run_search(compiled, facts, meter, budget)
    finally:
        if was:
            gc.enable()
    if out.status == "budget":
        return budget_result(NAME, out.budget, meter, out.expanded, out.generated, out.stored)
    if out.status != "solved":
        return meter.finish(Result(solver=NAME, solved=False, status="no_solution", expanded=out.expanded,
                                   generated=out.generated, stored=out.stored,
                                   message="no plan exists: every decomposition was tried"))
    plan = [compiled.action_text(name, args) for _, name, args in out.plan]
    costs = getattr(model, "action_costs", None)
    cost = len(plan) if costs is None else sum(costs[name] for _, name, _ in out.plan)
    return meter.finish(HtnResult(solver=NAME, solved=True, status="solved", plan=plan, cost=cost,
                                  expanded=out.expanded, generated=out.generated, stored=out.stored,
                                  decomposition=_tree(out, compiled.task_text)))


def _tree(out, text) -> dict:
    """The decomposition with the IPC format's numbering: actions 0..n-1 in plan order,
    then the compound tasks in the order they were decomposed."""
    text = functools.lru_cache(maxsize=None)(text)   # most tasks recur (a step east, a block of one material)
    ids = {uid: i for i, (uid, _, _) in enumerate(out.plan)}
    for uid, *_ in out.decompositions[1:]:
        ids[uid] = len(ids)
    root = [ids[u] for u in out.decompositions[0][4]] if out.decompositions else []
    tasks = [{"id": ids[uid], "task": text(name, args), "method": method,
              "subtasks": [ids[c] for c in children]}
             for uid, name, args, method, children in out.decompositions[1:]]
    return {"root": root, "tasks": tasks}
