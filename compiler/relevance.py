"""Backward relevance: actions that can never matter for the goal are left out of search.

A variable is relevant if the goal or the failure test reads it, or a relevant action's
preconditions, lets, conditions or assigned values read it; an action is relevant if it
may write a relevant variable. An irrelevant action changes only variables nothing
relevant ever reads, so dropping it keeps every optimal plan (after dropping those
steps) valid and optimal. The grid counts as one variable, "cells".
"""
from __future__ import annotations

from . import ir

CELLS = "cells"


def reads(node, an, lets: dict, acc: set) -> set:
    if isinstance(node, ir.Var):
        acc.add(node.var)
    elif isinstance(node, ir.VarAt):
        acc.update(an.vars_of(node.cls, node.attr))
    elif isinstance(node, ir.Cell):
        acc.add(CELLS)
    elif isinstance(node, ir.Local) and node.name in lets:
        reads(lets[node.name], an, lets, acc)
    for child in ir.children(node):
        reads(child, an, lets, acc)
    return acc


def effect_reads_writes(effects, an, lets: dict, r: set, w: set) -> None:
    for e in effects:
        if isinstance(e, ir.When):
            reads(e.cond, an, lets, r)
            effect_reads_writes(e.then, an, lets, r, w)
            effect_reads_writes(e.orelse, an, lets, r, w)
        elif isinstance(e, ir.SetVar):
            w.add(e.var)
            reads(e.value, an, lets, r)
        elif isinstance(e, ir.SetVarAt):
            w.update(an.vars_of(e.cls, e.attr))
            reads(e.key, an, lets, r)
            reads(e.value, an, lets, r)
        elif isinstance(e, ir.SetCell):
            w.add(CELLS)
            for part in (e.x, e.y, e.z, e.value):
                reads(part, an, lets, r)


def relevant_actions(actions, candidates, goal, failure, an) -> set:
    """Indices (among `candidates`) of the actions that may matter for reaching the goal."""
    info = {}
    for i in candidates:
        a = actions[i]
        lets = {loc.name: value for loc, value in a.lets}
        r, w = set(), set()
        for c in a.pre:
            reads(c, an, lets, r)
        effect_reads_writes(a.effects, an, lets, r, w)
        info[i] = (r, w)
    relevant_vars = reads(goal, an, {}, set()) | reads(failure, an, {}, set())
    relevant: set = set()
    changed = True
    while changed:
        changed = False
        for i, (r, w) in info.items():
            if i not in relevant and w & relevant_vars:
                relevant.add(i)
                relevant_vars |= r
                changed = True
    return relevant
