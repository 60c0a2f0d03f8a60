"""An HTN plan verifier for the IPC 2020 plan format, written apart from the planner.

Why apart: a planner checked by its own code agrees with itself. This module shares only
the HDDL reader with `solvers/htn`: it executes the actions with its own evaluator, and
checks the decomposition tree top-down against the methods, by the definition of a
solution to a totally ordered HTN problem:

- every action line is an action of the domain, with objects of the right types, and
  the sequence is executable from the initial state (conditional and universal effects
  read in the state before, deletes then adds);
- `root` lists tasks that match the problem's network (its :htn parameters bound by
  some objects satisfying its constraints);
- each compound line names a task of the domain and a method of that task, and some
  binding of the method's variables maps its task onto the line's task, its subtasks, in
  order, onto the line's children, and makes its precondition true in the state where it
  is applied (before the first action below it);
- every line is used once, and the actions below the root, left to right, are the plan;
- the problem's goal, if any, holds at the end.

`verify(htn, text)` returns None for a valid plan, else the first reason it is not.
"""
from __future__ import annotations

from ..pddl_io.lifted_types import is_a


class Invalid(Exception):
    pass


def parse_ipc(text: str) -> tuple[list, list, dict]:
    """(actions [(id, name, args)], root ids, compound {id: (name, args, method, children)})."""
    lines = [line.strip().lower() for line in text.splitlines() if line.strip() and not line.startswith(";")]
    if "==>" not in lines or "<==" not in lines:
        raise Invalid("the plan must sit between a line ==> and a line <==")
    body = lines[lines.index("==>") + 1:lines.index("<==")]
    actions, root, compound = [], None, {}
    ids: set = set()           # every line id so far (a scan of the actions per line was quadratic)
    for line in body:
        words = line.split()
        if words[0] == "root":
            if root is not None:
                raise Invalid("a second root line")
            root = [_id(w) for w in words[1:]]
            continue
        i = _id(words[0])
        if i in ids:
            raise Invalid(f"id {i} is used for two lines")
        ids.add(i)
        if "->" in words:
            arrow = words.index("->")
            if arrow < 2 or len(words) < arrow + 2:
                raise Invalid(f"line {line!r}: expected ID TASK ARGS -> METHOD IDS")
            compound[i] = (words[1], tuple(words[2:arrow]), words[arrow + 1], [_id(w) for w in words[arrow + 2:]])
        elif root is not None:
            raise Invalid(f"line {line!r}: an action after the root line")
        else:
            actions.append((i, words[1], tuple(words[2:])))
    if root is None:
        raise Invalid("no root line")
    return actions, root, compound


def _id(word: str) -> int:
    if not word.isdigit():
        raise Invalid(f"{word!r} is not a line id")
    return int(word)


class _World:
    """Ground evaluation over a set of facts (pred, args)."""

    def __init__(self, htn):
        self.dom, self.prob = htn.domain, htn.problem
        self.objects = htn.problem.objects
        self.facts = {(p, tuple(a)) for p, a in htn.problem.init}
        self.by_pred: dict = {}
        self.by_arg: dict = {}           # (pred, position, object) -> the args of such facts
        for p, a in self.facts:
            self._index(p, a)

    def _index(self, p: str, a: tuple) -> None:
        self.by_pred.setdefault(p, set()).add(a)
        for i, o in enumerate(a):
            self.by_arg.setdefault((p, i, o), set()).add(a)

    def _unindex(self, p: str, a: tuple) -> None:
        self.by_pred.get(p, set()).discard(a)   # deleting an atom that is false: no change
        for i, o in enumerate(a):
            self.by_arg.get((p, i, o), set()).discard(a)

    def of_type(self, obj: str, types) -> bool:
        t = self.objects.get(obj)
        return t is not None and any(is_a(t, w, self.dom.parents) for w in types)

    def typed(self, types) -> list:
        return [o for o in self.objects if self.of_type(o, types)]

    def value(self, term: str, env: dict) -> str:
        return env[term] if term.startswith("?") else term

    def true(self, f, env: dict) -> bool:
        kind = f[0]
        if kind == "atom":
            return (f[1], tuple(self.value(t, env) for t in f[2])) in self.facts
        if kind == "=":
            return self.value(f[1], env) == self.value(f[2], env)
        if kind == "not":
            return not self.true(f[1], env)
        if kind == "and":
            return all(self.true(g, env) for g in f[1])
        if kind == "or":
            return any(self.true(g, env) for g in f[1])
        if kind == "exists":
            return self._some(list(f[1]), f[2], dict(env), False)
        if kind == "forall":   # no assignment makes the body false
            return not self._some(list(f[1]), f[2], dict(env), True)
        return kind == "true"

    def _some(self, params: list, body, env: dict, negate: bool) -> bool:
        """Whether some assignment of `params` makes `body` true (false, if `negate`)."""
        if not params:
            return self.true(body, env) != negate
        (var, types), rest = params[0], params[1:]
        for o in self.typed(types):
            env[var] = o
            if self._some(rest, body, env, negate):
                return True
        return False

    def satisfiable(self, f, env: dict, free: list) -> bool:
        """Some values of the `free` (var, types) not in `env` make `f` true: variables
        met in a positive atom of the top conjunction are tried against the facts, the rest
        over their type's objects."""
        unbound = [(v, t) for v, t in free if v not in env]
        if not unbound:
            return self.true(f, env)
        names = {v for v, _ in unbound}
        types = dict(unbound)
        atoms = [a for a in _conjuncts(f) if a[0] == "atom" and names & set(a[2])]
        if atoms:
            atom = max(atoms, key=lambda a: sum(1 for t in a[2] if t not in names))
            known = [(i, self.value(t, env)) for i, t in enumerate(atom[2]) if t not in names]
            candidates = min((self.by_arg.get((atom[1], i, v), set()) for i, v in known), key=len) if known \
                else self.by_pred.get(atom[1], set())
            for args in list(candidates):
                if len(args) != len(atom[2]):
                    continue
                new = dict(env)
                for term, value in zip(atom[2], args):
                    if term in names and term not in new:
                        if not self.of_type(value, types[term]):
                            break
                        new[term] = value
                    elif self.value(term, new) != value:
                        break
                else:
                    if self.satisfiable(f, new, unbound):
                        return True
            return False
        var, want = unbound[0]
        for o in self.typed(want):
            if self.satisfiable(f, {**env, var: o}, unbound):
                return True
        return False

    def execute(self, action, args: tuple) -> str | None:
        if len(args) != len(action.params):
            return f"{action.name} takes {len(action.params)} arguments, found {len(args)}"
        env = {}
        for (var, types), value in zip(action.params, args):
            if not self.of_type(value, types):
                return f"{value!r} is not an object of type {'/'.join(sorted(types))}"
            env[var] = value
        if not self.true(action.pre, env):
            return "its precondition does not hold"
        adds, dels = set(), set()
        for e in action.effects:
            for b in self._effect_bindings(e, env):
                if self.true(e.cond, b):
                    (adds if e.add else dels).add((e.pred, tuple(self.value(t, b) for t in e.args)))
        self.facts -= dels - adds    # in place: a copy per action is quadratic on long plans
        self.facts |= adds
        for p, a in dels - adds:
            self._unindex(p, a)
        for p, a in adds:
            self._index(p, a)
        return None

    def _effect_bindings(self, e, env: dict):
        envs = [dict(env)]
        for var, types in e.params:
            envs = [{**b, var: o} for b in envs for o in self.typed(types)]
        return envs


def _conjuncts(f) -> list:
    # written apart from pddl_io.lifted.conjuncts on purpose: the verifier shares no code with the planner
    return [c for g in f[1] for c in _conjuncts(g)] if f[0] == "and" else [f]


def verify(htn, text: str) -> str | None:
    """None if `text` (IPC format) is a solution of `htn`, else why not."""
    try:
        _verify(htn, text)
    except Invalid as exc:
        return str(exc)
    return None


def _verify(htn, text: str) -> None:
    actions, root, compound = parse_ipc(text)
    world = _World(htn)
    by_name = {a.name: a for a in htn.domain.actions}
    methods = {m.name: m for m in htn.methods}
    primitive = {i: k for k, (i, _, _) in enumerate(actions)}
    # The tree: each line used once, leaves left to right = the plan; method checks by position.
    checks: dict = {}          # position in the plan -> [(method, task args, children)]
    used: set = set()
    leaves: list = []
    checks.setdefault(0, []).append((htn.network, (), list(root)))
    order = list(reversed(root))
    while order:
        i = order.pop()
        if i in used:
            raise Invalid(f"line {i} is used twice in the tree")
        used.add(i)
        if i in primitive:
            leaves.append(i)
            continue
        if i not in compound:
            raise Invalid(f"the tree names line {i}, which does not exist")
        name, args, method_name, children = compound[i]
        method = methods.get(method_name)
        if method is None:
            raise Invalid(f"line {i}: {method_name!r} is not a method of the domain")
        if method.task[0] != name:
            raise Invalid(f"line {i}: method {method_name} decomposes {method.task[0]}, not {name}")
        checks.setdefault(len(leaves), []).append((method, args, children))
        order.extend(reversed(children))
    if len(used) != len(primitive) + len(compound):
        unused = sorted((set(primitive) | set(compound)) - used)
        raise Invalid(f"line {unused[0]} is not part of the tree below root")
    if [primitive[i] for i in leaves] != list(range(len(actions))):
        raise Invalid("the actions below root, left to right, are not the plan's order")
    for k in range(len(actions) + 1):
        for method, args, children in checks.get(k, ()):
            _check_method(world, method, args, children, actions, primitive, compound)
        if k < len(actions):
            i, name, args = actions[k]
            action = by_name.get(name)
            if action is None:
                raise Invalid(f"action {k} ({name}): no such action in the domain")
            why = world.execute(action, args)
            if why:
                raise Invalid(f"action {k} ({name} {' '.join(args)}): {why}")
    if not world.true(htn.problem.goal, {}):
        raise Invalid("the goal does not hold after the plan")


def _check_method(world: _World, method, args: tuple, children: list, actions, primitive, compound) -> None:
    where = f"method {method.name} on ({' '.join((method.task[0],) + args)})"
    if len(args) != len(method.task[1]):
        raise Invalid(f"{where}: the task has {len(method.task[1])} arguments, found {len(args)}")
    if len(children) != len(method.subtasks):
        raise Invalid(f"{where}: {len(method.subtasks)} subtasks, found {len(children)}")
    env: dict = {}
    pairs = list(zip(method.task[1], args))
    for child, (sub_name, sub_terms) in zip(children, method.subtasks):
        name, child_args = (actions[primitive[child]][1:] if child in primitive else compound[child][:2])
        if name != sub_name or len(child_args) != len(sub_terms):
            raise Invalid(f"{where}: line {child} is ({name} ...), the method's subtask is ({sub_name} ...)")
        pairs += zip(sub_terms, child_args)
    types = dict(method.params)
    for term, value in pairs:
        if not term.startswith("?"):
            if term != value:
                raise Invalid(f"{where}: {value!r} where the method has {term!r}")
        elif env.setdefault(term, value) != value:
            raise Invalid(f"{where}: {term} would be both {env[term]!r} and {value!r}")
        elif term in types and not world.of_type(value, types[term]):
            raise Invalid(f"{where}: {value!r} is not of the type of {term}")
    if not world.satisfiable(method.pre, env, list(method.params)):
        raise Invalid(f"{where}: its precondition does not hold where it is applied")
