"""Greedy action elimination (Nakhost and Mueller 2010): a plan made shorter by removing
an action together with every later action that no longer applies, kept when the rest
still reaches the goal. The build solver's plans carry detours (a supply gathered twice,
a footing put down and never stood on); this takes them out without knowing what they are.
"""
from __future__ import annotations

from ..errors import ModelError


def _apply(model, a, s):
    try:
        return model.apply_fns[a](s)
    except ModelError:
        return None


def eliminate(model, plan: list, spent=lambda: False) -> list:
    """A plan (action indices) no longer than `plan` that still reaches the goal from the
    model's start; `spent()` stops early (what was removed so far is kept)."""
    plan = list(plan)
    states = [model.initial]
    for a in plan:
        states.append(_apply(model, a, states[-1]))
    i = 0
    while i < len(plan):
        if spent():
            break
        s, kept = states[i], []
        for a in plan[i + 1:]:
            n = _apply(model, a, s)
            if n is None or model.is_failure(n):
                continue
            kept.append(a)
            s = n
        if model.is_goal(s) and len(kept) < len(plan) - i:
            plan = plan[:i] + kept
            del states[i + 1:]
            for a in kept:
                states.append(_apply(model, a, states[-1]))
            continue      # the same index again: its new action may go too
        i += 1
    return plan
