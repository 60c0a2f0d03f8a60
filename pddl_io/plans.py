"""bcc plans <-> PDDL plans of an export, and an independent PDDL plan validator.

Why: a bcc plan names canonical actions; the export's operators are their grounded
cases. Translating a plan replays it on the export's own STRIPS semantics (task.py),
picking in each state the one operator of that action that applies (the cases of an
action partition the states, so there is exactly one). The validator is
unified-planning's `SequentialPlanValidator`, which knows nothing of bcc.
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


def validate(domain_file: str, problem_file: str, plan_file: str) -> tuple[bool, str]:
    """(valid, reason) from unified-planning's sequential plan validator."""
    try:
        import unified_planning.shortcuts as ups
        from unified_planning.engines import SequentialPlanValidator
        from unified_planning.io import PDDLReader
    except ImportError:
        raise BccError('validating PDDL plans needs unified-planning: pip install "bcc[pddl]"') from None
    ups.get_environment().credits_stream = None
    reader = PDDLReader()
    problem = reader.parse_problem(domain_file, problem_file)
    plan = reader.parse_plan(problem, plan_file)
    result = SequentialPlanValidator().validate(problem, plan)
    return result.status.name == "VALID", str(result.reason or result.status.name)
