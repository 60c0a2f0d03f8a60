"""Which actions undo which: b is an inverse of a when b(a(s)) == s for every state s
where a applies and changes something (turn left / turn right, look down / look ahead, a
toggle with itself).

A blind layered search keeps, for each new state, the action that first made it from its
parent; that parent is already known, so an inverse's next state is a certain duplicate
and `expand` (emit.py) need not build it. Proven, not guessed: a pair is only considered
when both actions write fixed variables only and read nothing but fixed variables (no
cell, no keyed attribute); their outcome then depends on those few bytes alone, and
every combination of their values is tried through the compiled `apply` functions.
"""
from __future__ import annotations

import itertools

from . import ir

MAX_COMBINATIONS = 1 << 12   # value combinations tried per pair, at most


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
