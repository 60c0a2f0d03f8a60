"""bcc plans <-> PDDL plans of an export, and an independent PDDL plan validator.

Why: a bcc plan names canonical actions; the export's operators are their grounded
cases. Translating a plan replays it on the export's own STRIPS semantics (task.py),
picking in each state the one operator of that action that applies (the cases of an
action partition the states, so there is exactly one). The validator is
pddl-pyvalidator (`pyval`), else unified-planning's `SequentialPlanValidator`; neither
knows anything of bcc. They read the validator-friendly variant of the export
(`validation_files`): the plan's operators only, facts as 0-ary predicates.
"""
from __future__ import annotations

from ..errors import BccError


def to_pddl_plan(task, plan: list) -> list:
    """Operator names for a bcc plan; BccError at the first action with no applicable case."""
    facts = frozenset(task.init)
    out = []
    for step, name in enumerate(plan, 1):
        cases = [(op, nxt) for op, nxt in task.successors(facts) if task.action_names[op.action] == name]
        if len(cases) != 1:
            raise BccError(f"step {step}: {name} has {len(cases)} applicable cases in the export")
        op, facts = cases[0]
        out.append(op.name)
    if not task.is_goal(facts):
        raise BccError("the plan does not reach the export's goal")
    if len(task.goal_terms) != 1:  # the goal is reached through a zero-cost goal operator
        goal_ops = [op for op in task.operators if op.action < 0 and all(f in facts for f in op.pre)]
        out.append(goal_ops[0].name)
    return out


def plan_text(ops: list) -> str:
    return "".join(f"({op})\n" for op in ops)


def validation_files(task, ops: list, directory: str) -> tuple[str, str, str]:
    """Write the validator variant of the export and the plan to `directory`: 3 paths."""
    import os

    from ..atomic import write_text
    from .writer import domain_text, problem_text
    paths = tuple(os.path.join(directory, n) for n in ("domain.pddl", "problem.pddl", "plan"))
    write_text(paths[0], domain_text(task, only=set(ops), flat=True))
    write_text(paths[1], problem_text(task, flat=True))
    write_text(paths[2], plan_text(ops))
    return paths


def validate(domain_file: str, problem_file: str, plan_file: str) -> tuple[bool, str]:
    """(valid, reason) from pddl-pyvalidator, else unified-planning's sequential plan validator."""
    try:
        import unified_planning.shortcuts as ups
    except ImportError:
        from ..extras import missing
        raise missing("validating PDDL plans", "unified-planning", "pddl") from None
    ups.get_environment().credits_stream = None
    try:
        from pyval import PDDLValidator
    except ImportError:
        PDDLValidator = None
    if PDDLValidator is not None:
        result = PDDLValidator().validate(domain_file, problem_file, plan_file)
        if result.is_valid:
            return True, "VALID"
        if result.failed_step is not None:
            return False, f"{result.status}: step {result.failed_step} is not applicable"
        return False, f"{result.status}: the goal does not hold after the plan"
    from unified_planning.engines import SequentialPlanValidator
    from unified_planning.io import PDDLReader
    reader = PDDLReader()
    problem = reader.parse_problem(domain_file, problem_file)
    plan = reader.parse_plan(problem, plan_file)
    result = SequentialPlanValidator().validate(problem, plan)
    return result.status.name == "VALID", str(result.reason or result.status.name)
