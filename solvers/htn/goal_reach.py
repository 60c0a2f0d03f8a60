"""Which of the goal's atoms a task can still make true: a cut for networks that cannot
reach the goal.

A problem may give a state goal beside its task network (plan recognition does: the
observed actions set flags one after another, and the goal is the last flag). The
progression search (search.py) learns only once the network is empty whether the goal
holds, after decomposing every task in it. But an atom of the goal that does not hold now
can hold at the end only if some action the remaining network may still produce adds it,
and which actions a task may produce is fixed by the domain: the task decomposition
graph (task name -> its methods' subtasks, closed; an action produces itself). So each
task name gets a mask of the goal atoms some reachable action may add (ignoring
arguments and preconditions: an over-estimate, so the cut is sound), a network's mask
is the union over its tasks, and a network whose mask misses an atom that does not hold
is abandoned at once.

Only the goal's positive ground atoms are used; a goal of any other shape cuts nothing.
"""
from __future__ import annotations

from ...pddl_io.lifted_types import conjuncts
from .bind import is_var


def goal_atoms(goal) -> list:
    """The goal's positive ground atoms [(predicate, arguments)]."""
    return [(f[1], tuple(f[2])) for f in conjuncts(goal)
            if f[0] == "atom" and not any(is_var(t) for t in f[2])]


def _adds(effect, atom) -> bool:
    """Whether the (lifted) add effect may add the ground atom."""
    pred, args = atom
    return effect.add and effect.pred == pred and len(effect.args) == len(args) and \
        all(is_var(t) or t == a for t, a in zip(effect.args, args))


def reach_masks(actions: dict, methods: dict, atoms: list) -> dict:
    """{task or action name: bitmask of the `atoms` some action it may produce adds}.
    `actions`: name -> its effects; `methods`: task name -> [subtask names of one
    method, ...]."""
    masks = {}
    for name, effects in actions.items():
        masks[name] = sum(1 << i for i, atom in enumerate(atoms) if any(_adds(e, atom) for e in effects))
    for task in methods:
        masks.setdefault(task, 0)
    changed = True
    while changed:   # a fixpoint over the decomposition graph (it may be recursive)
        changed = False
        for task, ways in methods.items():
            mask = masks[task]
            for subtasks in ways:
                for name in subtasks:
                    mask |= masks.get(name, 0)
            if mask != masks[task]:
                masks[task] = mask
                changed = True
    return masks


def unmet(atoms: list, facts: set) -> int:
    """The bitmask of the `atoms` that do not hold in `facts`."""
    out = 0
    for i, atom in enumerate(atoms):
        if atom not in facts:
            out |= 1 << i
    return out
