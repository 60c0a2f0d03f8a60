"""Counters that achievers spend, and where the search can fill them up again.

Why: a goal of five blocks of one type, with none in hand, is met only after five are
gathered: "holds at least one T" (a landmark's need, lifted_landmarks.py) says neither
how many are missing nor where one is to be had. A *supply* (lifted_landmarks.supply) is
a counter every achiever steps down; `counter` tells how many steps down it can still
go in a state, and `refills` are the schemas that step it up (breaking a block of T,
picking one up), each with its precondition *relaxed*: the movers' own functional
atoms (an agent's x, y and z: binary atoms of a functional predicate on an object of a
type with few objects) are dropped, so that a join in the state finds every place a
refill could happen, and the dropped atoms, bound, say where the mover must go. The
search goes to the nearest such place, and on to where the counter is spent, while the
counter is short (lifted_search.py); not to one that would undo a landmark already met
(`undoes`).
"""
from __future__ import annotations

from ..pddl_io.lifted_types import TRUE, conjuncts
from ..pddl_io.lifted_states import LiftedTask
from .lifted_distances import SMALL_TYPE, Distances


def counter(task: LiftedTask, sup: tuple):
    """`steps(s, k)`: how many steps down the supply's counter the best-stocked object
    could take in s, at most k."""
    pred, rel, vpos = sup
    nxt: dict = {}
    for fact in task.static_all.get(rel, ()):
        nxt.setdefault(fact[vpos], []).append(fact[1 - vpos])
    n_init = task.n_init

    def steps(s, k) -> int:
        best = 0
        for i, args in task.of_pred.get(pred, ()):
            if (i < n_init) == (i in s):
                continue
            v, n = args[-1], 0
            while n < k and len(nxt.get(v, ())) == 1:
                v = nxt[v][0]
                n += 1
            best = max(best, n)
        return best
    return steps


def refills(task: LiftedTask, dist: Distances, sup: tuple) -> list:
    """[(relaxed precondition, parameters, types, dropped [(pred, object term, value term)],
    deletes [(pred, terms)])] of the schemas that step the supply's counter up (see the
    module docstring)."""
    pred, rel, vpos = sup
    out = []
    for a in task.dom.actions:
        types = dict(a.params)
        pre = conjuncts(a.pre)
        up = False
        for d in a.effects:
            if d.add or d.pred != pred or d.params or d.cond != TRUE:
                continue
            for e in a.effects:
                if e.add and e.pred == pred and e.args[:-1] == d.args[:-1] and e.args[-1] != d.args[-1]:
                    old, new = d.args[-1], e.args[-1]
                    up = up or any(c[0] == "atom" and c[1] == rel and len(c[2]) == 2 and c[2][vpos] == new
                                   and c[2][1 - vpos] == old for c in pre)
        if not up:
            continue
        kept, dropped = [], []
        for c in pre:
            if _moves(task, dist, c, types, pred):
                dropped.append((c[1], c[2][0], c[2][1]))
            else:
                kept.append(c)
        if dropped:
            deletes = tuple((e.pred, e.args) for e in a.effects if not e.add and not e.params and e.cond == TRUE)
            out.append((("and", tuple(kept)), tuple(v for v, _ in a.params), types, dropped, deletes))
    return out


def _moves(task: LiftedTask, dist: Distances, c, types: dict, counter_pred: str) -> bool:
    """Is c a mover's own functional atom: P(?o, ?v), P functional for ?o's objects, ?o of
    a type with few objects (not the counter itself)?"""
    if c[0] != "atom" or c[1] == counter_pred or len(c[2]) != 2 or not all(t.startswith("?") for t in c[2]):
        return False
    objs = task.domain(types[c[2][0]])
    return 0 < len(objs) <= SMALL_TYPE and all(dist.functional(c[1], o) for o in objs)


def undoes(task: LiftedTask, s, mark, deleted: list) -> bool:
    """Would deleting the ground atoms `deleted` take away what makes landmark `mark`
    (an atom, or `exists` of a conjunction of atoms) true in s? True when a deleted atom
    matches one of its atoms under a binding of its quantified variables for which all
    of its atoms hold in s (a refill that takes a goal's block apart is no refill)."""
    if mark[0] == "atom":
        return (mark[1], mark[2]) in deleted
    if mark[0] != "exists":
        return False
    qvars = {v for v, _ in mark[1]}
    atoms = conjuncts(mark[2])
    if not all(c[0] == "atom" for c in atoms):
        return False
    for pred, args in deleted:
        for c in atoms:
            if c[1] != pred:
                continue
            env: dict = {}
            if not all(env.setdefault(t, o) == o if t in qvars else t == o for t, o in zip(c[2], args)):
                continue
            ground = [(a[1], tuple(env.get(t, t) for t in a[2])) for a in atoms]
            if all(not any(t in qvars for t in g[1]) and task.holds_atom(s, *g) for g in ground):
                return True
    return False
