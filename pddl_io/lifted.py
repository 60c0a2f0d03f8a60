"""PDDL domain and problem, from s-expressions (read.py) to checked, lifted tasks.

Why a separate step: every name is resolved and every construct judged here, once, with
its position, so grounding (ground.py) never meets bad input. What is read: STRIPS with
`:typing` (`either` included), constants, `=`, negative preconditions, `:action-costs`
(`(increase (total-cost) N)` with N a number or a static function of the problem's
`:init`), and ADL: `or`, `imply`, `exists`, `forall` in conditions, `when` and `forall`
in effects, and derived predicates (`:derived`) that do not depend on themselves: each
use of one is replaced by its definition (the `or` of its rules, their quantified
variables renamed apart), so grounding and search never meet them. Anything else stops
at its position with "... is not supported" (a recursive derived predicate too).

The task's types and formulas are in lifted_types.py (its readers import them from there),
derived predicates in derived.py.
"""
from __future__ import annotations

import itertools
from dataclasses import replace

from ..errors import BccError
from .derived import check_derived, inline_derived
from .lifted_types import TRUE, Action, Domain, Effect, Problem, err, unsupported
from .read import SList, read_sexpr

KNOWN_REQUIREMENTS = {
    ":strips", ":typing", ":negative-preconditions", ":disjunctive-preconditions", ":equality",
    ":existential-preconditions", ":universal-preconditions", ":quantified-preconditions",
    ":conditional-effects", ":adl", ":action-costs",
    # declared by many IPC files without being used; a construct that needs them is refused where it occurs
    ":fluents", ":numeric-fluents", ":object-fluents", ":derived-predicates", ":durative-actions",
    ":duration-inequalities", ":continuous-effects", ":timed-initial-literals", ":preferences",
    ":constraints", ":action-expansions", ":foreach-expansions", ":dag-expansions", ":domain-axioms",
    ":subgoal-through-axioms", ":safety-constraints", ":expression-evaluation", ":open-world",
    ":true-negation", ":ucpop",
}


class Reader:
    """Shared helpers: typed lists, terms and formulas over a scope of names."""

    def __init__(self, path: str):
        self.path = path

    def fail(self, node, message: str):
        raise err(node, message, self.path)

    def expect_list(self, node, what: str) -> SList:
        if not isinstance(node, SList):
            self.fail(node, f"expected {what} in parentheses, found {node!r}")
        return node

    def name(self, node, what: str) -> str:
        if isinstance(node, SList) or node.type != "NAME":
            self.fail(node, f"expected {what}, found {_show(node)}")
        return str(node)

    def typed_list(self, items, kind: str, types: dict | None) -> list:
        """`a b - t c - (either u v)` -> [(a, frozenset{t}), (b, ...), (c, frozenset{u, v})]."""
        out, pending = [], []
        i = 0
        while i < len(items):
            item = items[i]
            if not isinstance(item, SList) and item == "-":
                if i + 1 >= len(items):
                    self.fail(item, "a '-' must be followed by a type")
                t = self.type_ref(items[i + 1], types)
                out += [(p, t) for p in pending]
                pending = []
                i += 2
                continue
            if isinstance(item, SList):
                self.fail(item, f"expected a {kind}, found a list")
            if kind == "variable" and item.type != "VARIABLE":
                self.fail(item, f"expected a variable (?name), found {_show(item)}")
            if kind != "variable" and item.type != "NAME":
                self.fail(item, f"expected a {kind} name, found {_show(item)}")
            pending.append(item)
            i += 1
        out += [(p, frozenset({"object"})) for p in pending]
        return out

    def type_ref(self, node, types: dict | None) -> frozenset:
        if isinstance(node, SList):
            if not node or node[0] != "either":
                self.fail(node, "expected a type name or (either type ...)")
            return frozenset().union(*(self.type_ref(t, types) for t in node[1:]))
        name = self.name(node, "a type")
        if types is not None and name not in types:
            self.fail(node, f"unknown type {name!r}")
        return frozenset({name})


def _show(node) -> str:
    return "a list" if isinstance(node, SList) else repr(str(node))


def _define(tree, kind: str, path: str) -> SList:
    lists = [t for t in tree if isinstance(t, SList)]
    for t in tree:
        if not isinstance(t, SList):
            raise err(t, f"expected (define ({kind} ...) ...), found {_show(t)}", path)
    if len(lists) != 1:
        message = f"expected one (define ({kind} ...) ...) in the file, found {len(lists)}"
        if not lists:   # nothing to point at: the file's start
            raise BccError(message, path, 1, 1)
        raise err(lists[1], message, path)
    d = lists[0]
    if len(d) < 2 or d[0] != "define" or not isinstance(d[1], SList) or len(d[1]) != 2 or d[1][0] != kind:
        other = "problem" if kind == "domain" else "domain"
        swapped = (len(d) >= 2 and d[0] == "define" and isinstance(d[1], SList) and len(d[1]) == 2
                   and d[1][0] == other)
        hint = f": this file defines a {other} (the domain file comes first: DOMAIN PROBLEM)" if swapped else ""
        raise err(d, f"expected (define ({kind} NAME) ...){hint}", path)
    return d


# ---- the domain ----------------------------------------------------------------------
def read_domain(path: str) -> Domain:
    return domain_from(_define(read_sexpr(path), "domain", path), path)


def domain_from(d: SList, path: str, requirements: frozenset = frozenset()) -> Domain:
    """The domain of a `(define (domain ...) ...)` list; `requirements` are further ones
    a front end built on this one accepts (HDDL's :hierarchy)."""
    r = Reader(path)
    dom = Domain(name=r.name(d[1][1], "the domain's name"), path=path, parents={"object": ()}, constants={},
                 predicates={}, functions={}, actions=[])
    sections = {}
    for sec in d[2:]:
        sec = r.expect_list(sec, "a domain section")
        head = sec[0] if sec else None
        if head is None or isinstance(head, SList):
            r.fail(sec, "expected a domain section such as (:predicates ...)")
        if head in (":action", ":derived"):
            continue
        if head in (":durative-action", ":process", ":event", ":constraints"):
            raise unsupported(head, head, path)
        if head not in (":requirements", ":types", ":constants", ":predicates", ":functions"):
            r.fail(head, f"unknown domain section {str(head)!r}")
        if head in sections:
            r.fail(head, f"a second {head} section")
        sections[head] = sec
    for req in sections.get(":requirements", [None])[1:]:
        if isinstance(req, SList) or req.type != "KEYWORD" or req not in KNOWN_REQUIREMENTS | requirements:
            raise unsupported(req, f"requirement {_show(req)}", path)
    if ":types" in sections:
        for t, parents in r.typed_list(sections[":types"][1:], "type", None):
            if t == "object":
                continue
            dom.parents[str(t)] = tuple(sorted(set(dom.parents.get(str(t), ())) | parents))
        for t in list(dom.parents):
            for p in dom.parents[t]:
                dom.parents.setdefault(p, ("object",) if p != "object" else ())
        _check_acyclic(dom.parents, sections[":types"], path)
    if ":constants" in sections:
        for c, t in r.typed_list(sections[":constants"][1:], "constant", dom.parents):
            dom.constants[str(c)] = _one_type(t, c, dom, path)
    for p in sections.get(":predicates", [None])[1:]:
        p = r.expect_list(p, "a predicate")
        name = r.name(p[0] if p else p, "a predicate name")
        if name in dom.predicates:
            r.fail(p, f"predicate {name!r} is declared twice")
        dom.predicates[name] = tuple(t for _, t in r.typed_list(p[1:], "variable", dom.parents))
    if ":functions" in sections:
        _functions(r, sections[":functions"], dom)
    where = {}
    for sec in d[2:]:
        if sec and sec[0] == ":derived":
            name = _derived(r, sec, dom)
            where.setdefault(name, sec)
    for sec in d[2:]:
        if sec and sec[0] == ":action":
            dom.actions.append(_action(r, sec, dom))
    seen = set()
    for a in dom.actions:
        if a.name in seen:
            raise BccError(f"action {a.name!r} is declared twice", path, *a.where)
        seen.add(a.name)
    if dom.derived:
        check_derived(dom, where, path)
        fresh = itertools.count()
        for a in dom.actions:
            scope = dict(a.params)
            a.pre = inline_derived(a.pre, dom, fresh, scope, dom.constants)
            a.effects = [replace(e, cond=inline_derived(e.cond, dom, fresh, {**scope, **dict(e.params)},
                                                        dom.constants)) for e in a.effects]
    return dom


def _derived(r: Reader, sec: SList, dom: Domain) -> str:
    """One rule `(:derived (P ?x - t ...) condition)`: P holds where the condition does."""
    if len(sec) != 3:
        r.fail(sec, "expected (:derived (predicate ?x ...) condition)")
    head = r.expect_list(sec[1], "the derived predicate")
    name = r.name(head[0] if head else head, "a predicate name")
    if name not in dom.predicates:
        r.fail(head, f"{name!r} is not a predicate of the domain (declare it in :predicates)")
    params = tuple((str(v), t) for v, t in r.typed_list(head[1:], "variable", dom.parents))
    if len(params) != len(dom.predicates[name]):
        r.fail(head, f"{name} takes {len(dom.predicates[name])} arguments, found {len(params)}")
    body = Formulas(r, dom, None).formula(sec[2], dict(params))
    dom.derived.setdefault(name, []).append((params, body))
    return name


def _check_acyclic(parents: dict, node, path: str):
    for t in parents:
        seen, todo = set(), list(parents[t])
        while todo:
            p = todo.pop()
            if p == t:
                raise err(node, f"type {t!r} is its own ancestor", path)
            if p not in seen:
                seen.add(p)
                todo.extend(parents.get(p, ()))


def _one_type(types: frozenset, node, dom: Domain, path: str) -> str:
    if len(types) != 1:
        raise unsupported(node, "an object of an `either` type", path)
    return next(iter(types))


def _functions(r: Reader, sec: SList, dom: Domain):
    items = list(sec[1:])
    i = 0
    while i < len(items):
        f = items[i]
        if not isinstance(f, SList):
            r.fail(f, f"expected a function declaration (name ?x ...), found {_show(f)}")
        i += 1
        if i < len(items) and not isinstance(items[i], SList) and items[i] == "-":
            if i + 1 >= len(items) or items[i + 1] != "number":
                raise unsupported(items[i + 1] if i + 1 < len(items) else items[i], "a function of a non-number type",
                                  r.path)
            i += 2
        name = r.name(f[0] if f else f, "a function name")
        dom.functions[name] = tuple(t for _, t in r.typed_list(f[1:], "variable", dom.parents))


def _action(r: Reader, sec: SList, dom: Domain) -> Action:
    if len(sec) < 2:
        r.fail(sec, "an action needs a name")
    name = r.name(sec[1], "the action's name")
    parts = {}
    i = 2
    while i < len(sec):
        key = sec[i]
        if isinstance(key, SList) or key.type != "KEYWORD":
            r.fail(key, f"expected :parameters, :precondition or :effect, found {_show(key)}")
        if key not in (":parameters", ":precondition", ":effect"):
            raise unsupported(key, f"{key} in an action", r.path)
        if i + 1 >= len(sec):
            r.fail(key, f"{key} needs a value")
        parts[str(key)] = sec[i + 1]
        i += 2
    params = ()
    if ":parameters" in parts:
        plist = r.expect_list(parts[":parameters"], "the parameters")
        params = tuple((str(v), t) for v, t in r.typed_list(plist, "variable", dom.parents))
        names = [v for v, _ in params]
        if len(set(names)) != len(names):
            r.fail(plist, "a parameter is named twice")
    scope = {v: t for v, t in params}
    pre = TRUE
    if ":precondition" in parts:
        pre = Formulas(r, dom, None).formula(parts[":precondition"], scope)
    effects, costs = [], []
    if ":effect" in parts:
        Formulas(r, dom, None).effects(parts[":effect"], scope, (), TRUE, effects, costs)
    if len(costs) > 1:
        r.fail(costs[1][1], "an action may increase total-cost once")
    cost = costs[0][0] if costs else None
    if costs:
        dom.uses_costs = True
    a = Action(name, params, pre, effects, cost, (sec.line, sec.column))
    return a


class Formulas:
    """Conditions and effects over the predicates of `dom`; objects from `objects` (a
    problem's, for its goal) or the domain's constants."""

    def __init__(self, r: Reader, dom: Domain, objects: dict | None):
        self.r, self.dom = r, dom
        self.objects = dom.constants if objects is None else objects
        self.loose = dom.loose_names if objects is None else None

    def term(self, node, scope: dict):
        if isinstance(node, SList):
            raise unsupported(node, "a function term here", self.r.path)
        if node.type == "VARIABLE":
            if str(node) not in scope:
                self.r.fail(node, f"unknown variable {str(node)!r}")
            return str(node)
        if node.type != "NAME":
            self.r.fail(node, f"expected a variable or an object, found {_show(node)}")
        if str(node) not in self.objects:
            if self.loose is None:
                self.r.fail(node, f"unknown object or constant {str(node)!r}")
            # Many IPC domains use an object of their problems as a constant without
            # declaring it (Fast Downward accepts this); the problem must declare it.
            self.loose.setdefault(str(node), node)
        return str(node)

    def params(self, node, scope: dict):
        plist = self.r.expect_list(node, "the quantified variables")
        params = tuple((str(v), t) for v, t in self.r.typed_list(plist, "variable", self.dom.parents))
        inner = dict(scope)
        inner.update(params)
        return params, inner

    def atom(self, node: SList, scope: dict):
        if not node:
            self.r.fail(node, "expected an atom (predicate args...), found ()")
        head = node[0]
        if isinstance(head, SList) or head.type != "NAME":
            self.r.fail(node, f"expected a predicate, found {_show(head)}")
        name = str(head)
        if name == "=":
            if len(node) != 3:
                self.r.fail(node, "= takes two terms")
            return ("=", self.term(node[1], scope), self.term(node[2], scope))
        if name in ("<", ">", "<=", ">="):
            raise unsupported(head, f"the numeric comparison {name}", self.r.path)
        if name not in self.dom.predicates:
            what = "a function" if name in self.dom.functions else "an undeclared predicate"
            self.r.fail(head, f"{name!r} is {what}, not a predicate of the domain")
        want = self.dom.predicates[name]
        if len(node) - 1 != len(want):
            self.r.fail(node, f"{name} takes {len(want)} arguments, found {len(node) - 1}")
        return ("atom", name, tuple(self.term(a, scope) for a in node[1:]))

    def formula(self, node, scope: dict):
        r = self.r
        if not isinstance(node, SList):
            r.fail(node, f"expected a condition in parentheses, found {_show(node)}")
        if not node:
            return TRUE
        head = node[0]
        if head == "and":
            return ("and", tuple(self.formula(f, scope) for f in node[1:]))
        if head == "or":
            return ("or", tuple(self.formula(f, scope) for f in node[1:]))
        if head == "not":
            if len(node) != 2:
                r.fail(node, "not takes one condition")
            return ("not", self.formula(node[1], scope))
        if head == "imply":
            if len(node) != 3:
                r.fail(node, "imply takes two conditions")
            return ("or", (("not", self.formula(node[1], scope)), self.formula(node[2], scope)))
        if head in ("exists", "forall"):
            if len(node) != 3:
                r.fail(node, f"{head} takes a variable list and a condition")
            params, inner = self.params(node[1], scope)
            return (str(head), params, self.formula(node[2], inner))
        if not isinstance(head, SList) and head.type == "KEYWORD":
            raise unsupported(head, str(head), r.path)
        return self.atom(node, scope)

    def effects(self, node, scope: dict, params: tuple, cond, out: list, costs: list):
        r = self.r
        if not isinstance(node, SList):
            r.fail(node, f"expected an effect in parentheses, found {_show(node)}")
        if not node:
            return
        head = node[0]
        if head == "and":
            for e in node[1:]:
                self.effects(e, scope, params, cond, out, costs)
        elif head == "forall":
            if len(node) != 3:
                r.fail(node, "forall takes a variable list and an effect")
            more, inner = self.params(node[1], scope)
            self.effects(node[2], inner, params + more, cond, out, costs)
        elif head == "when":
            if len(node) != 3:
                r.fail(node, "when takes a condition and an effect")
            c = self.formula(node[1], scope)
            self.effects(node[2], scope, params, c if cond == TRUE else ("and", (cond, c)), out, costs)
        elif head == "not":
            if len(node) != 2 or not isinstance(node[1], SList) or not node[1]:
                r.fail(node, "not in an effect takes one atom")
            a = self.atom(node[1], scope)
            if a[0] == "=":
                raise unsupported(node[1], "an effect on =", r.path)
            out.append(Effect(params, cond, False, a[1], a[2]))
        elif head == "increase":
            costs.append((self.cost(node, scope, params, cond), node))
        elif head in ("decrease", "assign", "scale-up", "scale-down"):
            raise unsupported(head, f"the numeric effect {head}", r.path)
        elif not isinstance(head, SList) and head.type == "KEYWORD":
            raise unsupported(head, str(head), r.path)
        else:
            a = self.atom(node, scope)
            if a[0] == "=":
                raise unsupported(node, "an effect on =", r.path)
            out.append(Effect(params, cond, True, a[1], a[2]))

    def cost(self, node: SList, scope: dict, params: tuple, cond):
        r = self.r
        if len(node) != 3 or not isinstance(node[1], SList) or list(node[1]) != ["total-cost"]:
            raise unsupported(node, "an increase of anything but (total-cost)", r.path)
        if params or cond != TRUE:
            raise unsupported(node, "a total-cost increase under forall or when", r.path)
        value = node[2]
        if not isinstance(value, SList):
            if value.type != "NUMBER" or "." in value or value.startswith("-"):
                if value.type == "NUMBER":
                    raise unsupported(value, f"the cost {str(value)} (costs are whole numbers >= 0)", r.path)
                r.fail(value, f"expected a cost (a number or a function), found {_show(value)}")
            return int(value)
        if not value or isinstance(value[0], SList) or str(value[0]) not in self.dom.functions:
            raise unsupported(value, "a cost that is not a number or a declared function", r.path)
        fname = str(value[0])
        if len(value) - 1 != len(self.dom.functions[fname]):
            r.fail(value, f"{fname} takes {len(self.dom.functions[fname])} arguments, found {len(value) - 1}")
        return (fname, tuple(self.term(a, scope) for a in value[1:]))


# ---- the problem ---------------------------------------------------------------------
def read_problem(path: str, dom: Domain) -> Problem:
    return problem_from(_define(read_sexpr(path), "problem", path), path, dom)


def problem_from(d: SList, path: str, dom: Domain, requirements: frozenset = frozenset(),
                 goal_needed: bool = True, keep_order: bool = False) -> Problem:
    """The problem of a `(define (problem ...) ...)` list; an HTN problem may have no
    :goal (`goal_needed` False: its goal is then true); `keep_order`: also list the :init
    atoms in file order (`init_order`), for a search whose choices follow it."""
    r = Reader(path)
    prob = Problem(name=r.name(d[1][1], "the problem's name"), path=path, objects=dict(dom.constants), init=set(),
                   function_values={}, goal=TRUE, metric=False)
    sections = {}
    for sec in d[2:]:
        sec = r.expect_list(sec, "a problem section")
        head = sec[0] if sec else None
        if head is None or isinstance(head, SList):
            r.fail(sec, "expected a problem section such as (:init ...)")
        if head in (":constraints", ":length"):
            raise unsupported(head, head, path)
        if head not in (":domain", ":requirements", ":objects", ":init", ":goal", ":metric"):
            r.fail(head, f"unknown problem section {str(head)!r}")
        if head in sections:
            r.fail(head, f"a second {head} section")
        sections[head] = sec
    if ":domain" in sections:  # its name is not compared: IPC files often disagree (Fast Downward ignores it)
        sec = sections[":domain"]
        if len(sec) != 2:
            r.fail(sec, "expected (:domain NAME)")
        r.name(sec[1], "the domain's name")
    for req in sections.get(":requirements", [None])[1:]:
        if isinstance(req, SList) or req.type != "KEYWORD" or req not in KNOWN_REQUIREMENTS | requirements:
            raise unsupported(req, f"requirement {_show(req)}", path)
    if ":objects" in sections:
        for o, t in r.typed_list(sections[":objects"][1:], "object", dom.parents):
            name = str(o)
            t = _one_type(t, o, dom, path)
            if name in prob.objects and prob.objects[name] != t:
                r.fail(o, f"object {name!r} is declared twice with different types")
            prob.objects[name] = t
    for name, token in dom.loose_names.items():
        if name not in prob.objects:
            raise err(token, f"unknown object or constant {name!r} (neither the domain's constants nor the "
                             f"objects of {path} declare it)", dom.path)
    f = Formulas(r, dom, prob.objects)
    if keep_order:
        prob.init_order = []
    for fact in sections.get(":init", [None])[1:]:
        fact = r.expect_list(fact, "an initial fact")
        if fact and fact[0] == "=":
            _function_value(r, f, fact, prob, dom)
            continue
        if fact and fact[0] == "at" and len(fact) == 3 and not isinstance(fact[1], SList) \
                and fact[1].type == "NUMBER":
            raise unsupported(fact, "a timed initial literal", path)
        if fact and fact[0] == "not":
            continue  # closed world: false anyway
        a = f.atom(fact, {})
        if a[0] == "atom" and a[1] in dom.derived:
            r.fail(fact, f"{a[1]!r} is a derived predicate: it holds where its rules say, never by :init")
        atom = (a[1], a[2])
        if keep_order and atom not in prob.init:
            prob.init_order.append(atom)
        prob.init.add(atom)  # types are not checked here: Fast Downward does not either
    if ":goal" not in sections:
        if not goal_needed:
            return _metric(r, sections, prob, path)
        r.fail(d, "the problem has no :goal")
    g = sections[":goal"]
    if len(g) != 2:
        r.fail(g, ":goal takes one condition")
    prob.goal = inline_derived(f.formula(g[1], {}), dom, itertools.count(), {}, prob.objects)
    return _metric(r, sections, prob, path)


def _metric(r: Reader, sections: dict, prob: Problem, path: str) -> Problem:
    if ":metric" in sections:
        m = sections[":metric"]
        if len(m) == 3 and m[1] == "minimize" and isinstance(m[2], SList) and list(m[2]) == ["total-cost"]:
            prob.metric = True
        else:
            raise unsupported(m, "a metric other than (minimize (total-cost))", path)
    return prob


def _function_value(r: Reader, f: Formulas, fact: SList, prob: Problem, dom: Domain):
    if len(fact) != 3 or not isinstance(fact[1], SList) or not fact[1]:
        r.fail(fact, "expected (= (function args) number)")
    head = fact[1][0]
    name = str(head)
    if name == "total-cost":
        return
    if name not in dom.functions:
        r.fail(head, f"{name!r} is not a declared function")
    args = tuple(f.term(a, {}) for a in fact[1][1:])
    if len(args) != len(dom.functions[name]):
        r.fail(fact[1], f"{name} takes {len(dom.functions[name])} arguments, found {len(args)}")
    value = fact[2]
    if isinstance(value, SList) or value.type != "NUMBER":
        r.fail(value, f"expected a number, found {_show(value)}")
    if "." in value or value.startswith("-"):
        raise unsupported(value, f"the cost {str(value)} (costs are whole numbers >= 0)", r.path)
    prob.function_values[(name, args)] = int(value)


def read_task(domain_path: str, problem_path: str) -> tuple[Domain, Problem]:
    dom = read_domain(domain_path)
    return dom, read_problem(problem_path, dom)
