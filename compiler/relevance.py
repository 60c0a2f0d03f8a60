"""Backward relevance: actions that can never matter for the goal are left out of search.

A variable is relevant if the goal or the failure test reads it, or a relevant action's
preconditions, lets, conditions or assigned values read it; an action is relevant if it
may write a relevant variable. An irrelevant action changes only variables nothing
relevant ever reads, so dropping it keeps every optimal plan (after dropping those
steps) valid and optimal. The grid counts as one variable, "cells".
"""
from __future__ import annotations

from .access import action_access, reads


def relevant_actions(actions, candidates, goal, failure, an) -> set:
    """Indices (among `candidates`) of the actions that may matter for reaching the goal."""
    info = {i: action_access(actions[i], an.vars_of) for i in candidates}
    relevant_vars = reads(goal, vars_of=an.vars_of) | reads(failure, vars_of=an.vars_of)
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
