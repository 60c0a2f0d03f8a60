"""A delete-relaxed view of a compiled model, built from the grounded IR (no domain words).

Facts are `group = values` and `cell (x, y, z) = value`. A group is a set of state
variables that some action writes side by side (a position's x and z), so a relaxed
plan cannot mix coordinates of two places; cells are those of the mutable layers, static
cells and attributes being constants already. Each grounded action is split by its
*context*, the values of the variables that choose which cells and keyed objects it
touches (e.g. a position, a facing, a selected slot). In a context, expressions are
partially evaluated (relaxed_eval.py): each precondition becomes facts, a disjunction
becomes an auxiliary fact with one zero-cost achiever per alternative, and the effects
are split by the atoms they read (a decision tree: exact), or, when that tree is too big,
the action adds an auxiliary "fired" fact and each conditional effect becomes a zero-cost
operator of its own. Everything over-approximates: a relaxed operator's preconditions
hold whenever the action's do, and it adds at least what the action makes true; so hmax
and LM-cut on this view stay admissible. Operators that cannot fire from the start, or
add nothing the goal needs, are dropped (relevance, as pyperplan and Fast Downward do).
"""
from __future__ import annotations

import math
import time

from .relaxed_build import Builder
from .relaxed_last import last_step_operators
from .relaxed_task import Reachability, RelaxedTask, RelaxedTooBig, StateReader  # noqa: F401 - RelaxedTooBig: raised by build (Builder)


def build(layout, actions, search, goal, reach, n_values, initial, time_limit: float | None = None) -> RelaxedTask:
    """The relaxed view; raises RelaxedTooBig past MAX_CONTEXTS or `time_limit` seconds."""
    start = time.perf_counter()
    b = Builder(layout, actions, search, goal, reach, n_values,
                math.inf if time_limit is None else start + time_limit)
    reader = StateReader.of(layout, b.groups, b.bases, b.strides, b.cell_base, n_values)
    b.build_actions(reader.facts(initial))
    goal_facts = b.build_goal()
    all_ops = list(b.ops)
    built = len(all_ops)
    init_facts = reader.facts(initial)
    last = (last_step_operators(all_ops, goal_facts, b.atom_of, b.or_minterms(), b.new_fact, b.fired_steps.get)
            if goal_facts else None)
    ops = _prune(all_ops, init_facts, goal_facts, b.n_facts)
    labels = [b.labels.get(f, f"#{f}") for f in range(b.n_facts)]
    task = RelaxedTask(b.n_facts, [o[0] for o in ops], [o[1] for o in ops], [o[2] for o in ops],
                       [o[3] for o in ops], goal_facts, labels, reader)
    if last is not None:
        steps = b.step_costs
        guide_ops = _prune([(o[0], o[1], steps.get(o, o[2]), o[3]) for o in all_ops] + last[0],
                           init_facts, last[1], b.n_facts)
        task.guide = RelaxedTask(b.n_facts, [o[0] for o in guide_ops], [o[1] for o in guide_ops],
                                 [o[2] for o in guide_ops], [o[3] for o in guide_ops], last[1], labels, reader,
                                 chained=tuple(sorted(b.chained)))
    task.stats = {"facts": b.n_facts, "operators_built": built, "operators": len(ops),
                  "groups": [[v.label for v in g] for g in b.groups],
                  "seconds": round(time.perf_counter() - start, 3)}
    return task


def _prune(ops, init_facts, goal, n_facts) -> list:
    """Keep operators that can fire from the start (relaxed reachability: a fact of any
    reachable state is reachable in the relaxation) and add a fact the goal may need."""
    reach = Reachability(init_facts)
    for i, (pre, add, _, _) in enumerate(ops):
        reach.add(pre, add, i)
    fireable = reach.fired
    if goal is None:
        return []
    needed = bytearray(n_facts)
    for f in goal:
        needed[f] = 1
    by_add: dict = {}
    for i in fireable:
        for f in ops[i][1]:
            by_add.setdefault(f, []).append(i)
    stack = list(goal)
    relevant = set()
    while stack:
        f = stack.pop()
        for i in by_add.get(f, ()):
            if i not in relevant:
                relevant.add(i)
                for p in ops[i][0]:
                    if not needed[p]:
                        needed[p] = 1
                        stack.append(p)
    return [ops[i] for i in sorted(relevant)]
