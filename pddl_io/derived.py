"""Derived predicates (`:derived`) inlined: each use replaced by the `or` of its rules.

Why inline: grounding and search then never meet a derived predicate; the price is that
one may not depend on itself (refused at its place) and no action may change one.
"""
from __future__ import annotations

from ..errors import BccError
from .lifted_types import Domain, is_a, unsupported


def check_derived(dom: Domain, where: dict, path: str) -> None:
    """No action may change a derived predicate, and none may depend on itself."""
    for a in dom.actions:
        for e in a.effects:
            if e.pred in dom.derived:
                raise BccError(f"action {a.name!r} changes {e.pred!r}, a derived predicate", path, *a.where)
    uses = {name: {p for _, body in rules for p in _predicates_in(body) if p in dom.derived}
            for name, rules in dom.derived.items()}
    for name in uses:
        todo, seen = list(uses[name]), set()
        while todo:
            p = todo.pop()
            if p == name:
                raise unsupported(where[name], f"a recursive derived predicate ({name!r} depends on itself)", path)
            if p not in seen:
                seen.add(p)
                todo.extend(uses[p])


def _predicates_in(f) -> set:
    kind = f[0]
    if kind == "atom":
        return {f[1]}
    if kind in ("and", "or"):
        return set().union(*(_predicates_in(g) for g in f[1]))
    if kind == "not":
        return _predicates_in(f[1])
    if kind in ("exists", "forall"):
        return _predicates_in(f[2])
    return set()


def inline_derived(f, dom: Domain, fresh, scope: dict, objects: dict):
    """`f` with each atom of a derived predicate replaced by the `or` of its rules'
    conditions, the rule's parameters bound to the atom's terms (definitions do not
    depend on themselves: check_derived). `scope` gives the variables' types, `objects`
    the objects': a term whose type the rule's parameter may not include gets a test
    that it does (`exists ?t - T (= ?t term)`), as the typed axiom would."""
    kind = f[0]
    if kind == "atom" and f[1] in dom.derived:
        parts = []
        for params, body in dom.derived[f[1]]:
            tests = [_type_test(term, want, dom, fresh, scope, objects) for (_, want), term in zip(params, f[2])]
            bound = _bind(body, dict(zip((v for v, _ in params), f[2])), fresh)
            tests = [t for t in tests if t is not None]
            parts.append(inline_derived(("and", (*tests, bound)) if tests else bound, dom, fresh, scope, objects))
        return parts[0] if len(parts) == 1 else ("or", tuple(parts))
    if kind in ("and", "or"):
        return (kind, tuple(inline_derived(g, dom, fresh, scope, objects) for g in f[1]))
    if kind == "not":
        return ("not", inline_derived(f[1], dom, fresh, scope, objects))
    if kind in ("exists", "forall"):
        return (kind, f[1], inline_derived(f[2], dom, fresh, {**scope, **dict(f[1])}, objects))
    return f


def _type_test(term: str, want: frozenset, dom: Domain, fresh, scope: dict, objects: dict):
    """None where `term` is of a type in `want` whatever it stands for; else the test."""
    have = scope.get(term) if term.startswith("?") else \
        (frozenset({objects[term]}) if term in objects else None)
    if have is not None and all(any(is_a(t, w, dom.parents) for w in want) for t in have):
        return None
    v = f"?type~{next(fresh)}"
    return ("exists", ((v, want),), ("=", v, term))


def _bind(f, env: dict, fresh):
    """A rule's condition with its parameters replaced by terms (`env`) and its quantified
    variables renamed apart (`?x~7`), so that none captures a variable of the place it
    is used in."""
    kind = f[0]
    if kind == "atom":
        return ("atom", f[1], tuple(env.get(t, t) for t in f[2]))
    if kind == "=":
        return ("=", env.get(f[1], f[1]), env.get(f[2], f[2]))
    if kind in ("and", "or"):
        return (kind, tuple(_bind(g, env, fresh) for g in f[1]))
    if kind == "not":
        return ("not", _bind(f[1], env, fresh))
    if kind in ("exists", "forall"):
        renamed = tuple((f"{v}~{next(fresh)}", t) for v, t in f[1])
        inner = dict(env)
        inner.update((v, new) for (v, _), (new, _) in zip(f[1], renamed))
        return (kind, renamed, _bind(f[2], inner, fresh))
    return f
