"""`bcc import pddl`: a PDDL domain and problem compiled by bcc itself into a `Model`.

Why bcc's own front-end: no third-party reader or grounder at run time (unified-planning
took seconds to import and refused common PDDL), costs honoured, every refusal at its
file:line:col. The steps, one module each: read.py (the lark grammar
grammar/pddl.lark: s-expressions), lifted.py (check names and constructs), ground.py
(relaxed reachability, static folding, backward relevance), compile.py (bcc's IR and
generated code). The model has no grid, so grid heuristics are blind on it.
"""
from __future__ import annotations

import time
from pathlib import Path


def import_pddl(domain: str, problem: str, max_actions: int | None = None, max_work: int | None = None):
    """Parse, ground and compile DOMAIN + PROBLEM into a `bcc.model.Model`. With
    `max_work`, a task whose grounding would take more steps raises ground.TooBig, with
    the read task as its `task` (domain, problem): search it lifted (lifted_search.py)."""
    from .compile import to_model
    from .ground import TooBig, ground
    from .lifted import read_task
    start = time.perf_counter()
    dom, prob = read_task(domain, problem)
    parsed = time.perf_counter()
    try:
        task = ground(dom, prob, max_actions, max_work=max_work)
    except TooBig as exc:
        exc.task = (dom, prob)
        raise
    grounded = time.perf_counter()
    report = {"dungeon": prob.name, "domain": "pddl", "pddl_domain": dom.name, **task.stats,
              "atoms": len(task.atoms), "grounded_actions": len(task.actions),   # after pruning
              "action_costs": task.uses_costs,
              "files": {"domain": str(Path(domain)), "problem": str(Path(problem))}}
    model = to_model(task, problem, report, (domain, problem))
    report["seconds"] = {"parse": round(parsed - start, 4), "ground": round(grounded - parsed, 4),
                         "compile": round(time.perf_counter() - grounded, 4)}
    return model
