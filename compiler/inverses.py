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
  goal is still found at its cheapest depth. A state that fails is never expanded, so
  only actions that do not write what the failure test reads take part (a failing b(p)
  would make b(t) fail too).

Proven, not guessed: a pair is only considered when both actions write fixed variables
only and read nothing but fixed variables (no cell, no keyed attribute); their outcome
then depends on those few bytes alone, and every combination of their values is tried
through the compiled `apply` functions.
"""
from __future__ import annotations

import itertools

from . import ir

MAX_COMBINATIONS = 1 << 12   # value combinations tried per pair, at most
MAX_COMMUTING = 48           # actions tried for commuting pairs, at most


def _reads(node, out: set) -> bool:
    """Add the variables `node` reads to `out`; False if it reads anything else (a cell,
    a keyed attribute, a cell loop), whose value the enumeration would not cover."""
    if isinstance(node, (ir.VarAt, ir.Cell, ir.CellLoop)):
        return False
    if isinstance(node, ir.Var):
        out.add(node.var)
    return all(_reads(child, out) for child in ir.children(node))


def _effects_footprint(effects, writes: set, reads: set) -> bool:
    for e in effects:
        if isinstance(e, ir.When):
            if not (_reads(e.cond, reads) and _effects_footprint(e.then, writes, reads)
                    and _effects_footprint(e.orelse, writes, reads)):
                return False
        elif isinstance(e, ir.SetVar):
            writes.add(e.var)
            if not _reads(e.value, reads):
                return False
        else:
            return False
    return True


def footprint(action, layout) -> tuple[frozenset, frozenset] | None:
    """(state indices written, state indices read) of a ground action whose preconditions,
    lets and effects touch fixed variables only; else None."""
    writes: set = set()
    reads: set = set()
    if not all(_reads(value, reads) for _, value in action.lets):
        return None
    if not all(_reads(cond, reads) for cond in action.pre):
        return None
    if not _effects_footprint(action.effects, writes, reads):
        return None
    if not writes or any(v not in layout.by_var for v in writes | reads):
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


def find_skips(actions: list, search: list, layout, apply_fns, failure_reads: set | None,
               undo: dict | None = None) -> dict:
    """{action a: frozenset of the search actions a layered search skips in states a made}:
    a's inverses, and the actions before a in `search`'s order that commute with it when
    neither writes a variable the failure test reads (`failure_reads`: their state
    indices; None when the failure test reads more than variables: no commuting pair).
    `undo`: `find_inverses`'s answer, if already known."""
    if undo is None:
        undo = find_inverses(actions, search, layout, apply_fns)
    prints = {i: footprint(actions[i], layout) for i in search}
    span = {s.index: s.hi - s.lo for s in layout.slots}
    out = {a: set(bs) for a, bs in undo.items()}
    if failure_reads is not None:
        free = [i for i in search if prints[i] is not None and not prints[i][0] & failure_reads]
        free = free[:MAX_COMMUTING]   # pairs grow as the square
        for k, a in enumerate(free):
            for b in free[:k]:
                touched = sorted(prints[a][0] | prints[a][1] | prints[b][0] | prints[b][1])
                combos = 1
                for i in touched:
                    combos *= span[i] + 1
                if combos <= MAX_COMBINATIONS and commute(apply_fns[a], apply_fns[b],
                                                          [(i, span[i]) for i in touched], layout.grid_base):
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
