"""A guiding variant of the relaxed view: the goal must be reached by a *last action*.

A delete relaxation forgets that the action which makes one goal fact true may make
another false: its relaxed plans may end by emptying a hand anywhere although the goal
wants the thing elsewhere, so hadd and hff do not see the walk there. In this variant
the goal is one new fact, `goal-last`, added only by one operator per possible last
action: a real operator that writes some goal atom with a value that leaves every goal
part it touches satisfiable. Its preconditions are the action's own plus every goal part
on atoms it does not write (those must already hold before it). This is one conjunction,
the goal, of Haslum's P^C compilation (2012).

The view does not know every written value exactly: an effect split apart ("fired") can
give an atom any of several values, or leave it. Here such an atom counts as *changed* to
one of those values; leaving it unchanged is not considered, so this variant is for
guidance (hadd, hff and their preferred actions), never for the admissible heuristics.
Heuristics using it answer 0 themselves where the goal already holds (no last action
is needed there).
"""
from __future__ import annotations


def last_step_operators(ops: list, goal: tuple, atom_of, or_minterms: dict, new_fact):
    """(extra operators, new goal), or None when the goal cannot be read per atom.
    `atom_of(f)` is (atom, facts) with the facts the atom may take when an operator adds
    f (one for a plain fact; the candidate values for a fired one), None for auxiliary
    facts; `or_minterms[f]` lists the minterms (fact tuples) of an or-fact."""
    parts = []   # (goal fact, its atoms, minterms as {atom: fact})
    for f in goal:
        if f in or_minterms:
            ms = []
            for m in or_minterms[f]:
                d = {}
                for g in m:
                    a = atom_of(g)
                    if a is None:
                        return None
                    d[a[0]] = g
                ms.append(d)
        else:
            a = atom_of(f)
            if a is None or a[1] != {f}:
                return None
            ms = [{a[0]: f}]
        parts.append((f, set().union(*(m.keys() for m in ms)), ms))
    goal_atoms = set().union(*(p[1] for p in parts)) if parts else set()
    if not goal_atoms:
        return None
    last = new_fact("goal-last")
    extra, seen = [], set()
    rest: dict = {}   # goal parts required before the last action -> one auxiliary fact for them
    for pre, add, cost, action in ops:
        if action < 0:
            continue
        writes: dict = {}
        for f in add:
            a = atom_of(f)
            if a is not None:
                writes.setdefault(a[0], set()).update(a[1])
        if not writes.keys() & goal_atoms:
            continue
        need = []
        ok = True
        for f, atoms, ms in parts:
            touched = atoms & writes.keys()
            if not touched:
                need.append(f)
            elif not any(all(a not in m or m[a] in writes[a] for a in touched) for m in ms):
                ok = False   # whatever it writes falsifies this goal part
                break
        if ok:
            # The goal parts shared by many last actions are reached once, by one zero-cost
            # operator, so each last action has one more precondition instead of dozens.
            need = tuple(need)
            aux = rest.get(need)
            if aux is None:
                aux = rest[need] = new_fact(f"goal-rest#{len(rest)}")
                extra.append((need, (aux,), 0, -1))
            key = (tuple(sorted(set(pre) | {aux})), cost, action)
            if key not in seen:
                seen.add(key)
                extra.append((key[0], (last,), cost, action))
    return extra, (last,)
