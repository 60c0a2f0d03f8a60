"""Which next states a layered search (breadth-first, blind with equal costs) need not
build from a state t, knowing the action a that first made t from its parent p.

- **Inverses.** b undoes a when b(a(s)) == s for every state s where a applies and
  changes something (turn left / turn right, look down / look ahead, a toggle with
  itself). b(t) is then p, already known: a certain duplicate.
- **Commuting actions, in a fixed order.** a and b commute when, on every state, a then
  b applies exactly where b then a does, with the same result (turning and looking down).
  From t = a(p), b is skipped when b comes before a in the action order: b(t) = a(b(p)),
  and b(p) (a child of p, so no deeper than t) makes it, unless a is skipped there in
  turn -- only if a undoes b(p)'s own maker c (the state is then known) or commutes with
  c and comes before it; following that chain the skipped action's index grows, so it
  ends in a state that is built, no deeper than t's layer. Every state of a layer is
  therefore reached by the end of the layer before it, as without skipping, and the first
  goal is still found at its cheapest depth. A state that fails is never expanded: b is
  skipped after a only if b(p) cannot fail (b writes nothing the failure test reads) or
  a(b(p)) must fail and be no goal with it (a writes nothing the failure test or the goal
  reads).

Proven, not guessed: two actions commute when neither writes anything the other reads
or writes (the grid counted as one thing: moving reads cells, looking down does not
touch them), or, when both touch fixed variables only (no cell, no keyed attribute),
by trying every combination of those bytes' values through the compiled `apply`
functions; inverses are found the second way only.
"""
from __future__ import annotations

import itertools

from . import access, ir
from .access import CELLS

MAX_COMBINATIONS = 1 << 12   # value combinations tried per pair, at most
MAX_COMMUTING = 48           # actions tried for commuting pairs, at most


def _access(action) -> tuple[set, set]:
    """(reads, writes) of a ground action as access.py finds them, every `let` value read
    (used or not) and locals not followed."""
    r: set = set()
    for _, value in action.lets:
        access.reads(value, acc=r)
    for cond in action.pre:
        access.reads(cond, acc=r)
    return access.effect_access(action.effects, r=r)


def footprint(action, layout) -> tuple[frozenset, frozenset] | None:
    """(state indices written, state indices read) of a ground action whose preconditions,
    lets and effects touch fixed variables only; else None."""
    reads, writes = _access(action)
    if not writes or any(not isinstance(v, ir.StateVar) or v not in layout.by_var for v in writes | reads):
        return None
    index = lambda vs: frozenset(layout.by_var[v].index for v in vs)
    return index(writes), index(reads)


def undoes(apply_a, apply_b, slots: list, size: int) -> bool:
    """Does b(a(s)) == s hold for every value combination of `slots` ([(index, span)]) where
    a applies and changes the state? Other bytes are never read, so zeros stand in."""
    state = bytearray(size)
    indices = [i for i, _ in slots]
    changed = False
    for values in itertools.product(*(range(span + 1) for _, span in slots)):
        for i, v in zip(indices, values):
            state[i] = v
        s = bytes(state)
        try:
            t = apply_a(s)
            if t is None or t == s:
                continue
            changed = True
            if apply_b(t) != s:
                return False
        except Exception:   # a run-time model error on some combination: not proven
            return False
    return changed


def commute(apply_a, apply_b, slots: list, size: int) -> bool:
    """Do a then b and b then a apply on the same value combinations of `slots`, with the
    same results (a state that only one order reaches, or reaches differently, refutes it)?"""
    state = bytearray(size)
    indices = [i for i, _ in slots]
    for values in itertools.product(*(range(span + 1) for _, span in slots)):
        for i, v in zip(indices, values):
            state[i] = v
        s = bytes(state)
        try:
            ta, tb = apply_a(s), apply_b(s)
            ab = None if ta is None else apply_b(ta)
            ba = None if tb is None else apply_a(tb)
        except Exception:   # a run-time model error on some combination: not proven
            return False
        if ab != ba:
            return False
    return True


def resources(action, layout) -> tuple[frozenset, frozenset] | None:
    """(written, read) of a ground action: state indices, and CELLS for the grid (one
    resource: an action reading any cell, one writing any); None when it touches a keyed
    attribute (its index is chosen at run time and may alias a variable)."""
    reads, writes = _access(action)
    if any(v != CELLS and v not in layout.by_var for v in writes | reads):
        return None
    index = lambda vs: frozenset(v if v == CELLS else layout.by_var[v].index for v in vs)
    return index(writes), index(reads)


def find_skips(actions: list, search: list, layout, apply_fns, failure_reads: set | None,
               undo: dict | None = None, goal_reads: set | None = None) -> dict:
    """{action a: frozenset of the search actions a layered search skips in states a made}:
    a's inverses, and each action b before a in `search`'s order that commutes with it:
    proven by trying every value of what they touch (both touch fixed variables only),
    or because neither writes anything the other reads or writes.
    `failure_reads` and `goal_reads`: the state indices the failure test and the goal
    read (None when they read more than variables and fixed cells). With a failure
    test that reads more, no pair is skipped. Where b writes what the failure test reads,
    b(p) may fail and never be expanded; a(b(p)) then fails and is no goal as well when
    a writes nothing either test reads, so only then is b skipped after a.
    `undo`: `find_inverses`'s answer, if already known."""
    if undo is None:
        undo = find_inverses(actions, search, layout, apply_fns)
    out = {a: set(bs) for a, bs in undo.items()}
    if failure_reads is None:
        return {a: frozenset(bs) for a, bs in out.items()}
    prints = {i: footprint(actions[i], layout) for i in search}
    uses = {i: resources(actions[i], layout) for i in search}
    span = {s.index: s.hi - s.lo for s in layout.slots}
    tests = None if goal_reads is None else failure_reads | goal_reads
    candidates = [i for i in search if uses[i] is not None][:MAX_COMMUTING]   # pairs grow as the square
    for k, a in enumerate(candidates):
        wa, ra = uses[a]
        for b in candidates[:k]:
            wb, rb = uses[b]
            if wb & failure_reads and (tests is None or wa & tests):
                continue
            if wa & (wb | rb) or wb & ra:   # they interfere: only an exhaustive trial proves it
                if prints[a] is None or prints[b] is None:
                    continue
                touched = sorted(prints[a][0] | prints[a][1] | prints[b][0] | prints[b][1])
                combos = 1
                for i in touched:
                    combos *= span[i] + 1
                if combos > MAX_COMBINATIONS or not commute(apply_fns[a], apply_fns[b],
                                                            [(i, span[i]) for i in touched], layout.grid_base):
                    continue
            out.setdefault(a, set()).add(b)
    return {a: frozenset(bs) for a, bs in out.items()}


def find_inverses(actions: list, search: list, layout, apply_fns) -> dict:
    """{action index: frozenset of search actions that undo it} over the search actions."""
    prints = {i: footprint(actions[i], layout) for i in search}
    by_writes: dict = {}
    for i, fp in prints.items():
        if fp is not None:
            by_writes.setdefault(fp[0], []).append(i)
    span = {s.index: s.hi - s.lo for s in layout.slots}
    out: dict = {}
    for members in by_writes.values():
        for a in members:
            undo = set()
            for b in members:
                touched = sorted(prints[a][0] | prints[a][1] | prints[b][1])
                combos = 1
                for i in touched:
                    combos *= span[i] + 1
                if combos > MAX_COMBINATIONS:
                    continue
                if undoes(apply_fns[a], apply_fns[b], [(i, span[i]) for i in touched], layout.grid_base):
                    undo.add(b)
            if undo:
                out[a] = frozenset(undo)
    return out
