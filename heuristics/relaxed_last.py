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
give an atom any of several values, or leave it. Here such an atom counts as *changed*
by one of its steps (old value and conditions -> new value), whose preconditions the last
action then needs too (a hand is emptied by the last placing only when it held one thing);
leaving it unchanged is not considered, so this variant is for guidance (hadd, hff and
their preferred actions), never for the admissible heuristics.
Heuristics using it answer 0 themselves where the goal already holds (no last action
is needed there).
"""
from __future__ import annotations


MAX_STEP_TRIES = 1024     # steps tried when combining one operator's fired steps
MAX_STEP_CHOICES = 64     # past either, its fired atoms count as changed to any candidate


def last_step_operators(ops: list, goal: tuple, atom_of, or_minterms: dict, new_fact, steps_of=None):
    """(extra operators, new goal), or None when the goal cannot be read per atom.
    `atom_of(f)` is (atom, facts) with the facts the atom may take when an operator adds
    f (one for a plain fact; the candidate values for a fired one), None for auxiliary
    facts; `or_minterms[f]` lists the minterms (fact tuples) of an or-fact; `steps_of(f)`
    lists a fired fact's steps as (preconditions, the fact added)."""
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
    choice_cache: dict = {}
    rest: dict = {}   # goal parts required before the last action -> one auxiliary fact for them
    for pre, add, cost, action in ops:
        if action < 0:
            continue
        writes: dict = {}
        fired = []
        for f in add:
            a = atom_of(f)
            if a is None:
                continue
            steps = steps_of(f) if steps_of is not None and a[1] != {f} else None
            if steps is not None and a[0] in goal_atoms:
                fired.append((a[0], steps))
            else:
                writes.setdefault(a[0], set()).update(a[1])
        if not (writes.keys() | {a for a, _ in fired}) & goal_atoms:
            continue
        choices = _step_choices(pre, fired, atom_of, choice_cache)
        if choices is None:   # too many: the old, optimistic reading
            for f in add:
                a = atom_of(f)
                if a is not None and a[1] != {f}:
                    writes.setdefault(a[0], set()).update(a[1])
            choices = [((), ())]
        for more_pre, more_writes in choices:
            w = dict(writes)
            for atom, f in more_writes:
                w[atom] = w.get(atom, set()) | {f}
            need = []
            ok = True
            for f, atoms, ms in parts:
                touched = atoms & w.keys()
                if not touched:
                    need.append(f)
                elif not any(all(a not in m or m[a] in w[a] for a in touched) for m in ms):
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
                key = (tuple(sorted(set(pre) | set(more_pre) | {aux})), cost, action)
                if key not in seen:
                    seen.add(key)
                    extra.append((key[0], (last,), cost, action))
    return extra, (last,)


def _step_choices(pre, fired, atom_of, cache: dict):
    """Each consistent choice of one step per fired goal atom: (its preconditions, the
    (atom, fact) writes). Steps whose preconditions give an atom two values, or another
    value than the operator's own preconditions, cannot happen together. The choices of
    a set of fired facts are found once (`cache`), then checked against `pre`."""
    if not fired:
        return [((), ())]
    key = tuple(id(steps) for _, steps in fired)
    if key not in cache:
        cache[key] = _choices(fired, atom_of)
    choices = cache[key]
    if choices is None:
        return None
    fixed = {}
    for p in pre:
        a = atom_of(p)
        if a is not None:
            fixed[a[0]] = p
    out = []
    for cpre, writes, env in choices:
        if all(fixed.get(a, p) == p for a, p in env.items()):
            out.append((cpre, writes))
    return out


def _choices(fired, atom_of) -> list | None:
    """The consistent step choices (None past MAX_STEP_TRIES or MAX_STEP_CHOICES). The
    atom with the fewest steps goes first: its steps fix the values the others' steps
    must start from, found through an index by precondition."""
    order = sorted(fired, key=lambda item: len(item[1]))
    indexed = []
    for atom, steps in order:
        by_pre: dict = {}
        for spre, f in steps:
            for p in spre:
                by_pre.setdefault(p, []).append((spre, f))
        indexed.append((atom, steps, by_pre))
    out = []
    tried = 0

    class Stop(Exception):
        pass

    def walk(k, env, acc_pre, acc_writes):
        nonlocal tried
        if k == len(indexed):
            out.append((acc_pre, acc_writes, env))
            if len(out) > MAX_STEP_CHOICES:
                raise Stop()
            return
        atom, steps, by_pre = indexed[k]
        pool = steps
        for p in env.values():     # a step reading a fixed atom must start from its value
            cand = by_pre.get(p)
            if cand is not None and len(cand) < len(pool):
                pool = cand
        for spre, f in pool:
            tried += 1
            if tried > MAX_STEP_TRIES:
                raise Stop()
            e = env
            ok = True
            for p in spre:
                a = atom_of(p)
                if a is None:
                    continue
                have = e.get(a[0])
                if have is None:
                    e = {**e, a[0]: p}
                elif have != p:
                    ok = False
                    break
            if ok:
                walk(k + 1, e, acc_pre + tuple(spre), acc_writes + ((atom, f),))

    try:
        walk(0, {}, (), ())
    except Stop:
        return None
    return out
