"""Landmarks of a lifted task: formulas every plan makes true, for best-first width search.

Why: a goal such as `(done)` reached by one `finish` action says nothing until the end;
what `finish` needs says more. Two steps, both read off the action schemas:

- A goal atom that exactly one schema adds, binding all its parameters (`(done)` by
  `(finish)`): the last step that makes it true is that action, so every conjunct of its
  precondition holds just before. Those conjuncts become landmarks of their own.
- For a landmark that is false in the start (an atom, or `exists ?b (and atoms...)`,
  "some block of type T on this cell"), its *achievers* are the schemas with an add
  effect that can make one of its atoms true; each is bound as far as the atom binds it.
  A precondition conjunct that every achiever shares (after binding, the same text) must
  hold for some binding just before the landmark is first made true: their conjunction,
  its unbound variables existentially quantified, is the landmark's *need* ("holds at
  least one T").

The search counts a missing landmark as 1, plus 1 while its need is missing too. When
the need is a step down a counter ("holds at least one T": the count and the static
relation to the next lower count) that every achiever takes (`supply`), k missing
landmarks sharing it need k steps: a count of one meets the need of each, not of all.
"""
from __future__ import annotations

from ..pddl_io.lifted_types import TRUE, conjuncts
from ..pddl_io.lifted_states import LiftedTask, free_vars, substitute


def landmarks(task: LiftedTask) -> list:
    """[(landmark, [needs])], ground formulas (no free variables)."""
    out, regressed = [], set()
    for g in conjuncts(task.prob.goal):
        out.append(g)
        if g[0] != "atom" or g[1] not in task.fluent or task.holds_atom(frozenset(), g[1], g[2]):
            continue
        achievers = [(a, e) for a in task.dom.actions for e in a.effects if e.add and e.pred == g[1]]
        if len(achievers) != 1:
            continue
        a, e = achievers[0]
        if e.params or e.cond != TRUE or {v for v, _ in a.params} - set(e.args):
            continue
        env: dict = {}
        for t, o in zip(e.args, g[2]):
            if env.setdefault(t, o) != o if t.startswith("?") else t != o:
                break
        else:
            out.extend(c for c in conjuncts(substitute(a.pre, env)) if not free_vars(c))
            regressed.add(g)      # its need is those landmarks already
    return [(m, [] if m in regressed else needs(task, m)) for m in out]


def needs(task: LiftedTask, mark) -> list:
    """The shared precondition of the landmark's achievers (see the module docstring), or []."""
    qtypes, atoms = _mark_atoms(mark)
    if atoms is None:
        return []
    if not atoms or all(task.holds_atom(frozenset(), a[1], a[2]) for a in atoms if not free_vars(a)) and \
            not free_vars(mark) and mark[0] == "atom":
        return []
    bound = _achievers(task, mark)
    if not bound:
        return []
    shared = None
    for a, env, _ in bound:
        here = [substitute(c, env) for c in conjuncts(a.pre)]
        shared = here if shared is None else [c for c in shared if c in here]
    types0 = {v: t for v, t in bound[0][2].items() if v not in bound[0][1]}
    keep = []
    for c in shared:
        vs = free_vars(c)
        if all(all(types.get(v) == types0.get(v) for v in vs) for _, env, types in bound):
            keep.append(c)
    if not keep:
        return []
    vs = sorted(set().union(*(free_vars(c) for c in keep)))
    body = keep[0] if len(keep) == 1 else ("and", tuple(keep))
    return [("exists", tuple((v, types0[v]) for v in vs), body) if vs else body]


def _mark_atoms(mark):
    """(the types of its quantified variables, its atoms) of an `exists` or `atom`
    landmark; ({}, None) for any other."""
    if mark[0] == "exists":
        return dict(mark[1]), [c for c in conjuncts(mark[2]) if c[0] == "atom"]
    if mark[0] == "atom":
        return {}, [mark]
    return {}, None


def _achievers(task: LiftedTask, mark) -> list:
    """[(schema, binding, types)]: the schemas whose add effect can make one of the
    landmark's atoms true, bound as far as that atom binds them."""
    qtypes, atoms = _mark_atoms(mark)
    if atoms is None:
        return []
    bound = []
    for a in task.dom.actions:
        types = dict(a.params)
        for e in a.effects:
            if not e.add or e.params or e.cond != TRUE:
                continue
            for atom in atoms:
                if atom[1] != e.pred:
                    continue
                env = _unify(task, e.args, atom[2], types, qtypes)
                if env is not None:
                    bound.append((a, env, types))
    return bound


def supply(task: LiftedTask, mark) -> tuple | None:
    """How a landmark's achievers spend what they need, when each one takes a step down a
    counter: (pred, binary static relation, the position of v in it) such that every
    achiever needs `pred(..., v)` and `rel(w, v)` (or `rel(v, w)`, the same for all) and
    replaces `pred(..., v)` by `pred(..., w)` (the same other arguments). Then k
    landmarks that share the need are not all met by one step left on the counter
    ("holds one T" for five blocks of T); the search counts the steps that are missing
    (lifted_search.py). None when the achievers differ."""
    found = None
    for a, env, types in _achievers(task, mark):
        pre = conjuncts(a.pre)
        here = set()
        for d in a.effects:
            if d.add or d.params or d.cond != TRUE or not d.args:
                continue
            o, v = d.args[:-1], d.args[-1]
            for e in a.effects:
                if not e.add or e.pred != d.pred or e.params or e.cond != TRUE or e.args[:-1] != o or e.args[-1] == v:
                    continue
                w = e.args[-1]
                if ("atom", d.pred, d.args) not in pre or not v.startswith("?") or not w.startswith("?"):
                    continue
                for c in pre:
                    if c[0] == "atom" and c[1] not in task.fluent and len(c[2]) == 2 and set(c[2]) == {v, w}:
                        here.add((d.pred, c[1], c[2].index(v)))
        found = here if found is None else found & here
        if not found:
            return None
    return next(iter(found)) if found and len(found) == 1 else None


def _unify(task: LiftedTask, effect_args: tuple, atom_args: tuple, types: dict, qtypes: dict) -> dict | None:
    """Bind the effect's variables to the atom's objects; a quantified variable of the atom
    binds nothing but must share an object with the effect variable's type."""
    env: dict = {}
    for te, ta in zip(effect_args, atom_args):
        if ta in qtypes:
            if te.startswith("?"):
                if not any(task.fits(o, types[te]) for o in task.domain(qtypes[ta])):
                    return None
            elif not task.fits(te, qtypes[ta]):
                return None
            continue
        if te.startswith("?"):
            if env.setdefault(te, ta) != ta or not task.fits(ta, types[te]):
                return None
        elif te != ta:
            return None
    return env
