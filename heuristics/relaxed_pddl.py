"""The delete-relaxed view of an imported PDDL task, for the relaxed heuristics.

Why its own: a ground PDDL task already is a set of boolean facts, so the view is read
straight off it (as in Fast Downward and pyperplan) instead of being rebuilt from the IR
by relaxed_view.py. Fact i is "atom i holds". An operator's preconditions are the
positive atoms of its precondition's conjunction (negative atoms and disjunctions are
dropped: a relaxation may only weaken them), its adds are its unconditional add effects.
A conditional effect becomes a zero-cost operator of its own, enabled by a "fired" fact
that its action adds: so hmax and LM-cut stay admissible. The goal is its positive atoms.
"""
from __future__ import annotations

from ..pddl_io.ground import GroundTask
from .relaxed_task import RelaxedTask


class AtomReader:
    """A state (an int, bit i is atom i: pddl_io/compile.py) -> the facts that hold in it.
    An imported state has one layout, read as it is."""
    reads_dense = False

    def facts(self, state) -> list:
        out = []
        while state:
            low = state & -state
            out.append(low.bit_length() - 1)
            state ^= low
        return out


def _positives(f) -> list:
    if isinstance(f, int):
        return [f]
    if f[0] == "and":
        return [a for g in f[1] for a in _positives(g)]
    return []               # not, or, true: nothing a relaxed operator must require


def relaxed_task(task: GroundTask):
    n = len(task.atoms)
    pre, add, cost, action, labels = [], [], [], [], [task.atom_text(i) for i in range(n)]
    n_facts = n
    for k, a in enumerate(task.actions):
        p = sorted(set(_positives(a.pre)))
        adds = sorted({atom for cond, atom, is_add in a.effects if is_add and cond == ("true",)})
        conditional = [(cond, atom) for cond, atom, is_add in a.effects if is_add and cond != ("true",)]
        fired = None
        if conditional:
            fired = n_facts
            n_facts += 1
            labels.append(f"fired {a.name}")
            adds.append(fired)
        pre.append(p)
        add.append(adds)
        cost.append(a.cost)
        action.append(k)
        for cond, atom in conditional:
            pre.append(sorted({fired, *_positives(cond)}))
            add.append([atom])
            cost.append(0)
            action.append(-1)
    goal = None if task.goal == ("false",) else tuple(sorted(set(_positives(task.goal))))
    out = RelaxedTask(n_facts, pre, add, cost, action, goal, labels, AtomReader())
    out.stats = {"facts": n_facts, "operators": len(pre)}
    return out
