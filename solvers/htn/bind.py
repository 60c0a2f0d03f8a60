"""Binding a lifted condition against the state: every assignment of its free variables
under which it holds, found by a join compiled once per method, action and effect.

Why compiled joins: a method such as "place the next block of a row" is applied tens of
thousands of times, each time binding one or two variables through a fact whose other
arguments are known. The join orders the condition's positive atoms so that each is
looked up by the arguments already bound (an index of facts.py), tests negative
literals, equalities and anything quantified as soon as their variables are bound, and
enumerates a variable no atom binds over the objects of its type.

Formulas are those of pddl_io/lifted.py; a term starting with "?" is a variable.
"""
from __future__ import annotations

from ...pddl_io.lifted_types import conjuncts, is_a


def is_var(term: str) -> bool:
    return term[:1] == "?"


def free_vars(f, acc: set) -> set:
    kind = f[0]
    if kind == "atom":
        acc.update(t for t in f[2] if is_var(t))
    elif kind == "=":
        acc.update(t for t in f[1:] if is_var(t))
    elif kind in ("and", "or"):
        for g in f[1]:
            free_vars(g, acc)
    elif kind == "not":
        free_vars(f[1], acc)
    elif kind in ("exists", "forall"):
        inner = free_vars(f[2], set())
        acc.update(inner - {v for v, _ in f[1]})
    return acc


class Objects:
    """The problem's objects by type: `of(types)` in declaration order, `fits` as a set."""

    def __init__(self, objects: dict, parents: dict):
        self.objects, self.parents = objects, parents
        self.cache: dict = {}

    def of(self, types: frozenset) -> tuple:
        found = self.cache.get(types)
        if found is None:
            found = tuple(o for o, t in self.objects.items() if any(is_a(t, w, self.parents) for w in types))
            self.cache[types] = found
            self.cache[("set", types)] = frozenset(found)
        return found

    def fits(self, types: frozenset) -> frozenset:
        self.of(types)
        return self.cache[("set", types)]


def holds(f, env: dict, facts, objects: Objects) -> bool:
    """Does formula `f` hold in `facts` with its free variables as in `env`?"""
    kind = f[0]
    if kind == "atom":
        return (f[1], tuple(env[t] if is_var(t) else t for t in f[2])) in facts.facts
    if kind == "not":
        return not holds(f[1], env, facts, objects)
    if kind == "and":
        return all(holds(g, env, facts, objects) for g in f[1])
    if kind == "or":
        return any(holds(g, env, facts, objects) for g in f[1])
    if kind == "=":
        a, b = (env[t] if is_var(t) else t for t in f[1:])
        return a == b
    if kind in ("exists", "forall"):
        return _quantified(kind == "forall", f[1], 0, f[2], dict(env), facts, objects)
    return kind == "true"


def _quantified(universal: bool, params: tuple, i: int, body, env: dict, facts, objects: Objects) -> bool:
    if i == len(params):
        return holds(body, env, facts, objects)
    var, types = params[i]
    for o in objects.of(types):
        env[var] = o
        if _quantified(universal, params, i + 1, body, env, facts, objects) != universal:
            return not universal
    return universal


class Join:
    """Bindings of the variables `free` ((var, types), ...) for which `formula` holds,
    given values for the variables `bound`."""

    def __init__(self, formula, bound, free: tuple, objects: Objects, predicates: dict, parents: dict):
        self.objects = objects
        self.steps = _compile(conjuncts(formula), set(bound), dict(free), objects, predicates, parents)

    def bindings(self, facts, env: dict) -> list:
        """Every completion of `env` (copies) under which the formula holds, in a fixed order."""
        out: list = []
        self._run(0, env, facts, out)
        return out

    def holds(self, facts, env: dict) -> bool:
        """Whether some completion exists (the first found is enough)."""
        return self._run(0, dict(env), facts, None)

    def _run(self, i: int, env: dict, facts, out) -> bool:
        steps = self.steps
        while i < len(steps):
            step = steps[i]
            kind = step[0]
            if kind == "check":
                _, pred, terms, positive = step
                if ((pred, tuple(env[t] if is_var(t) else t for t in terms)) in facts.facts) != positive:
                    return False
            elif kind == "filter":
                if not holds(step[1], env, facts, self.objects):
                    return False
            elif kind == "assign":
                _, var, term, fits = step
                value = env[term] if is_var(term) else term
                if fits is not None and value not in fits:
                    return False
                env[var] = value
            elif kind == "match":
                _, pred, positions, key_terms, outs = step
                index = facts.indices.get((pred, positions)) or facts.index(pred, positions)
                bucket = index.get(tuple(env[t] if is_var(t) else t for t in key_terms))
                if not bucket:
                    return False
                found = False
                for args in list(bucket):
                    for position, var, fits, fresh in outs:
                        value = args[position]
                        if fresh:
                            if fits is not None and value not in fits:
                                break
                            env[var] = value
                        elif env[var] != value:   # a variable the atom names twice
                            break
                    else:
                        if self._run(i + 1, env, facts, out):
                            found = True
                            if out is None:
                                return True
                return found
            else:   # "each": a variable no atom binds ranges over its type
                _, var, values = step
                found = False
                for value in values:
                    env[var] = value
                    if self._run(i + 1, env, facts, out):
                        found = True
                        if out is None:
                            return True
                return found
            i += 1
        if out is not None:
            out.append(dict(env))
        return True


def _compile(parts: list, bound: set, free: dict, objects: Objects, predicates: dict, parents: dict) -> list:
    """Join steps: each positive atom looked up by its bound arguments (the atom with the
    most bound first), every other conjunct tested once its variables are bound."""
    atoms = [c for c in parts if c[0] == "atom"]
    rest = [c for c in parts if c[0] != "atom"]
    steps: list = []

    def fits(var: str, declared=None):
        """The set a new value of `var` must lie in, or None when its type says nothing more."""
        want = free.get(var)
        if want is None or "object" in want:
            return None
        if declared is not None and all(any(is_a(t, w, parents) for w in want) for t in declared):
            return None
        return objects.fits(want)

    def flush():
        changed = True
        while changed:
            changed = False
            for c in list(rest):
                if c[0] == "=" and sum(1 for t in c[1:] if is_var(t) and t not in bound) == 1:
                    var, term = (c[1], c[2]) if is_var(c[1]) and c[1] not in bound else (c[2], c[1])
                    steps.append(("assign", var, term, fits(var)))
                    bound.add(var)
                    rest.remove(c)
                    changed = True
                elif free_vars(c, set()) <= bound:
                    if c[0] == "not" and c[1][0] == "atom":
                        steps.append(("check", c[1][1], c[1][2], False))
                    else:
                        steps.append(("filter", c))
                    rest.remove(c)
                    changed = True

    flush()
    while atoms:
        def score(a):
            known = sum(1 for t in a[2] if not is_var(t) or t in bound)
            return (known == len(a[2]), known)
        atom = max(atoms, key=score)
        atoms.remove(atom)
        _, pred, terms = atom
        positions = tuple(i for i, t in enumerate(terms) if not is_var(t) or t in bound)
        if len(positions) == len(terms):
            steps.append(("check", pred, terms, True))
        else:
            declared = predicates.get(pred, ())
            outs, new = [], set()
            for i, t in enumerate(terms):
                if i in positions:
                    continue
                outs.append((i, t, fits(t, declared[i] if i < len(declared) else None), t not in new))
                new.add(t)
            steps.append(("match", pred, positions, tuple(terms[i] for i in positions), tuple(outs)))
            bound |= new
        flush()
    for var, types in free.items():
        if var not in bound:
            steps.append(("each", var, objects.of(types)))
            bound.add(var)
            flush()
    for c in rest:   # variables nothing binds (a quantifier's free variable of no declared type)
        steps.append(("filter", c))
    return steps
