"""Check a plan on a PDDL task by replaying it lifted: no grounding, no translation.

Why: VAL-style validators in Python (pddl-pyvalidator, unified-planning) ground or
instantiate quantifiers over every object and take minutes on tasks with ten thousand
objects, where a plan of a thousand steps touches a few of them. Here each step's
precondition is evaluated with its parameters bound; a quantifier `exists ?v - T (and
... (p ?v c) ...)` draws its candidates from the facts that match a literal of its body
with the other arguments known (an index by predicate, argument place and value), else
from every object of type T. Effects (with `forall` and `when`) read the state before the
step, deletes apply before adds (PDDL). STRIPS with types, negative and disjunctive
preconditions, quantifiers, equality and conditional effects; no numbers, no axioms.
"""
from __future__ import annotations

from collections import defaultdict

from ..errors import BccError
from .read import read_sexpr


def _typed(items) -> list:
    out, pending, i = [], [], 0
    while i < len(items):
        if items[i] == "-" and i + 1 < len(items):
            out += [(str(n), str(items[i + 1])) for n in pending]
            pending, i = [], i + 2
        else:
            pending.append(items[i])
            i += 1
    return out + [(str(n), "object") for n in pending]


def _sections(tree) -> dict:
    return {part[0]: part for part in tree[2:] if isinstance(part, list) and part}


class Task:
    def __init__(self, domain_path: str, problem_path: str):
        domain, problem = read_sexpr(domain_path)[0], read_sexpr(problem_path)[0]
        ds, ps = _sections(domain), _sections(problem)
        self.parent = {n: t for n, t in _typed(ds.get(":types", [None])[1:])}
        objects = _typed(ds.get(":constants", [None])[1:]) + _typed(ps.get(":objects", [None])[1:])
        self.type_of = dict(objects)
        self.by_type: dict = defaultdict(list)
        for name, t in objects:
            while t is not None:
                self.by_type[t].append(name)
                t = self.parent.get(t, "object") if t != "object" else None
        self.actions = {}
        for part in domain[2:]:
            if isinstance(part, list) and part[:1] == [":action"]:
                keys = {part[i]: part[i + 1] for i in range(2, len(part) - 1, 2)}
                self.actions[str(part[1])] = (_typed(keys.get(":parameters", [])),
                                              keys.get(":precondition", ["and"]), keys.get(":effect", ["and"]))
        self.state: set = set()
        self.index: dict = defaultdict(set)
        for fact in ps[":init"][1:]:
            if isinstance(fact, list) and fact and fact[0] != "not":
                self.add(tuple(map(str, fact)))
        self.goal = ps[":goal"][1]

    def add(self, fact: tuple) -> None:
        if fact not in self.state:
            self.state.add(fact)
            for i, v in enumerate(fact[1:]):
                self.index[(fact[0], i, v)].add(fact)

    def delete(self, fact: tuple) -> None:
        if fact in self.state:
            self.state.discard(fact)
            for i, v in enumerate(fact[1:]):
                self.index[(fact[0], i, v)].discard(fact)

    def is_a(self, obj: str, t: str) -> bool:
        return obj in self.by_type.get(t, ())

    # ---- formulas ----------------------------------------------------------------------
    def holds(self, f, env: dict) -> bool:
        head = f[0]
        if head == "and":
            return all(self.holds(g, env) for g in f[1:])
        if head == "or":
            return any(self.holds(g, env) for g in f[1:])
        if head == "not":
            return not self.holds(f[1], env)
        if head == "imply":
            return not self.holds(f[1], env) or self.holds(f[2], env)
        if head == "=":
            return self.term(f[1], env) == self.term(f[2], env)
        if head in ("exists", "forall"):
            variables = _typed(f[1])
            want = head == "exists"
            for b in self.bindings(variables, f[2], env):
                if self.holds(f[2], b) == want:
                    return want
            return not want
        return (str(head), *(self.term(a, env) for a in f[1:])) in self.state

    def term(self, a, env: dict) -> str:
        return env[str(a)] if str(a).startswith("?") else str(a)

    def bindings(self, variables: list, body, env: dict):
        """Every binding of `variables` worth trying for `body` (see the module docstring)."""
        if not variables:
            yield env
            return
        (var, t), rest = variables[0], variables[1:]
        for value in self.candidates(var, t, body, env):
            yield from self.bindings(rest, body, {**env, var: value})

    def candidates(self, var: str, t: str, body, env: dict):
        best = None
        literals = body[1:] if body[:1] == ["and"] else [body]
        for lit in literals:
            if not isinstance(lit, list) or not lit or lit[0] in ("and", "or", "not", "imply", "exists", "forall", "="):
                continue
            args = [str(a) for a in lit[1:]]
            if var not in args:
                continue
            known = [(i, self.term(a, env)) for i, a in enumerate(args)
                     if a != var and (not a.startswith("?") or a in env)]
            if not known:
                continue
            facts = min((self.index.get((str(lit[0]), i, v), ()) for i, v in known), key=len)
            place = args.index(var)
            found = {fact[place + 1] for fact in facts}
            if best is None or len(found) < len(best):
                best = found
        pool = self.by_type.get(t, ())
        return [v for v in best if self.is_a(v, t)] if best is not None else list(pool)

    # ---- effects -----------------------------------------------------------------------
    def effects(self, e, env: dict, adds: list, dels: list) -> None:
        head = e[0]
        if head == "and":
            for g in e[1:]:
                self.effects(g, env, adds, dels)
        elif head == "not":
            dels.append((str(e[1][0]), *(self.term(a, env) for a in e[1][1:])))
        elif head == "forall":
            for b in self.bindings(_typed(e[1]), ["and"], env):
                self.effects(e[2], b, adds, dels)
        elif head == "when":
            if self.holds(e[1], env):
                self.effects(e[2], env, adds, dels)
        else:
            adds.append((str(head), *(self.term(a, env) for a in e[1:])))

    def step(self, number: int, text: str) -> None:
        words = text.strip().strip("()").split()
        if not words or words[0].lower() not in self.actions:
            raise BccError(f"step {number}: unknown action in {text.strip()!r}")
        params, pre, eff = self.actions[words[0].lower()]
        args = [w.lower() for w in words[1:]]
        if len(args) != len(params):
            raise BccError(f"step {number}: {words[0]} takes {len(params)} arguments, {len(args)} given")
        for (var, t), a in zip(params, args):
            if not self.is_a(a, t):
                raise BccError(f"step {number}: {a} is not a {t} ({var} of {words[0]})")
        env = {var: a for (var, _), a in zip(params, args)}
        if not self.holds(pre, env):
            raise BccError(f"step {number}: the precondition of {text.strip()} does not hold")
        adds, dels = [], []
        self.effects(eff, env, adds, dels)
        for f in dels:
            self.delete(f)
        for f in adds:
            self.add(f)


def replay(domain_path: str, problem_path: str, plan: list) -> tuple[bool, str]:
    """(valid, reason): the plan (PDDL actions, one a line; `;` comments) replayed on the task."""
    task = Task(domain_path, problem_path)
    steps = [line.split(";", 1)[0] for line in plan]
    steps = [s for s in steps if s.strip()]
    try:
        for number, text in enumerate(steps, 1):
            task.step(number, text)
    except BccError as exc:
        return False, exc.message
    if not task.holds(task.goal, {}):
        return False, f"the goal does not hold after step {len(steps)}"
    return True, f"valid: the goal holds after step {len(steps)}"
