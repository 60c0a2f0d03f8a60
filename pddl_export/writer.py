"""PDDL text of a grounded task: `domain.pddl` and `problem.pddl`.

Plain STRIPS (untyped, constants in the domain); `:action-costs` with `total-cost` only
when needed: non-unit action costs, or a goal that is a disjunction (then zero-cost
`reach_goal__k` operators achieve `(goal-reached)`, because Fast Downward compiles a
disjunctive goal into an axiom, which its optimal heuristics do not support).
"""
from __future__ import annotations

from .. import __version__
from .task import GOAL_ACTION, Task


def _header(task: Task, what: str) -> str:
    return (f"; {what} for dungeon {task.model_name} (domain {task.domain_name}), written by bcc {__version__}\n"
            f"; goal: {task.goal_text}\n"
            f"; grounded STRIPS: operator NAME__K is the K-th case of bcc action NAME; "
            f"{GOAL_ACTION}__K operators are not bcc actions\n")


def _conj(atoms: list, indent: str) -> str:
    if not atoms:
        return "(and)"
    return "(and " + (" ".join(atoms) if len(atoms) <= 4 else ("\n" + indent + ("\n" + indent).join(atoms))) + ")"


def domain_text(task: Task, only: set | None = None, flat: bool = False) -> str:
    """The domain text.

    The variant for validators: `only` (operator names) keeps just those operators, since
    a plan's validity depends only on the operators it names, the initial state and the
    goal; `flat` writes each fact as a 0-ary predicate, `(cell_x1_y0_z3_lava)`, because
    unified-planning enumerates every grounding of an untyped predicate over all
    constants (`cell` has 4 arguments: tens of millions) before it simulates a plan."""
    consts = sorted({v for names in task.value_names.values() for v in names}
                    | {a for _, args in task.predicates.values() for a in args})
    preds = {}
    for pred, args in task.predicates.values():
        preds.setdefault(pred, len(args) + 1)
    req = ":strips" + (" :action-costs" if task.use_costs else "")
    lines = [_header(task, "PDDL domain"), f"(define (domain bcc-{task.name})", f"  (:requirements {req})"]
    if flat:
        consts = []
        pred_lines = [task.atom((i, v), True) for i, vs in enumerate(task.domains.values) for v in vs]
    else:
        pred_lines = [f"({p} {' '.join(f'?a{k}' for k in range(n))})" for p, n in preds.items()]
    if consts:
        lines.append("  (:constants\n    " + "\n    ".join(" ".join(consts[i:i + 12]) for i in range(0, len(consts), 12)) + ")")
    if len(task.goal_terms) != 1:
        pred_lines.append("(goal-reached)")
    lines.append("  (:predicates\n    " + "\n    ".join(pred_lines) + ")")
    if task.use_costs:
        lines.append("  (:functions (total-cost) - number)")
    for op in task.operators:
        if only is not None and op.name not in only:
            continue
        pre = [task.atom(f, flat) for f in op.pre]
        eff = [f"(not {task.atom(f, flat)})" for f in op.delete] + [task.atom(f, flat) for f in op.add]
        if op.action < 0:
            eff.append("(goal-reached)")
        if task.use_costs:
            eff.append(f"(increase (total-cost) {op.cost})")
        lines.append(f"  (:action {op.name}\n    :parameters ()\n    :precondition {_conj(pre, '      ')}\n"
                     f"    :effect {_conj(eff, '      ')})")
    lines.append(")")
    return "\n".join(lines) + "\n"


def problem_text(task: Task, flat: bool = False) -> str:
    init = [task.atom(f, flat) for f in task.init]
    if task.use_costs:
        init.append("(= (total-cost) 0)")
    if len(task.goal_terms) == 1:
        goal = _conj([task.atom(f, flat) for f in task.goal_terms[0]], "      ")
    else:
        goal = "(and (goal-reached))"
    lines = [_header(task, "PDDL problem"), f"(define (problem bcc-{task.name}-problem)",
             f"  (:domain bcc-{task.name})",
             "  (:init\n    " + "\n    ".join(init) + ")",
             f"  (:goal {goal})"]
    if task.use_costs:
        lines.append("  (:metric minimize (total-cost))")
    lines.append(")")
    return "\n".join(lines) + "\n"
