"""The successor function of a lifted task: every binding of every action schema whose
precondition holds in a state, found by joins compiled to Python (lifted_joins.py), and
the next states; besides, tests of ground formulas and the bindings of further
preconditions, compiled with them (the lifted search's estimate reads its landmarks
through those), and more tests compiled later into the same code.
"""
from __future__ import annotations

import itertools

from .lifted_joins import JoinCompiler
from .lifted_states import LiftedTask
from .lifted_types import TRUE


class Successors:
    """`successors(s)`: [(action text, cost, next state)] of every binding of every
    action schema whose precondition holds in s; `tests[k](s)`: does ground formula k hold;
    `relaxed[k](s, [])`: the bindings of further preconditions (the heuristic's refills)."""

    def __init__(self, task: LiftedTask, formulas: list = (), relaxed: list = ()):
        self.task = task
        dom, prob = task.dom, task.prob
        jc = JoinCompiler(task)
        self.schemas = []
        for k, a in enumerate(dom.actions):
            types = dict(a.params)
            params = tuple(v for v, _ in a.params)
            jc.schema_function(f"A{k}", a.pre, params, types)
            effects = []
            for e in a.effects:
                etypes = {**types, **dict(e.params)}
                cond = None if e.cond == TRUE else jc.test_function(e.cond, etypes)
                effects.append((e, cond))
            self.schemas.append((a, params, f"A{k}", effects))
        tests = [jc.test_function(f, {}) for f in formulas]
        for k, (pre, params, types) in enumerate(relaxed):
            jc.schema_function(f"R{k}", pre, params, types)
        self.ns = ns = jc.compile()
        self.joins = jc
        self.relaxed = [ns[f"R{k}"] for k in range(len(relaxed))]    # bindings of other preconditions
        self.source = jc.source
        self.memo = ns["MEMO"]
        self.last = None
        self.schemas = [(a, params, ns[fn], [(e, None if c is None else (ns[c[0]], c[1])) for e, c in effects])
                        for a, params, fn, effects in self.schemas]
        self.tests = [ns[name] for name, _ in tests]
        self.use_costs = prob.metric

    def more_tests(self, formulas: list) -> None:
        """Compile tests of further ground formulas; they follow the others in `tests`."""
        names = [self.joins.test_function(f, {}) for f in formulas]
        ns = self.joins.compile_more()
        self.source = self.joins.source
        self.tests.extend(ns[name] for name, _ in names)

    def begin(self, s) -> None:
        """The answers kept by `exists` functions are for one state: forget them on a new one."""
        if s is not self.last:
            self.last = s
            self.memo.clear()

    def cost(self, a, env) -> int:
        if not self.use_costs:
            return 1
        if a.cost is None:
            return 0
        if isinstance(a.cost, int):
            return a.cost
        fname, args = a.cost
        return self.task.prob.function_values.get((fname, tuple(env.get(t, t) for t in args)), 0)

    def __call__(self, s) -> list:
        self.begin(s)
        out = []
        for a, params, match, effects in self.schemas:
            for binding in match(s, []):
                env = dict(zip(params, binding))
                nxt = self.apply(effects, env, s)
                if nxt is not None:
                    out.append(("(" + " ".join((a.name, *binding)) + ")", self.cost(a, env), nxt))
        return out

    def apply(self, effects, env: dict, s):
        """The next state, or None when nothing changes (a self-loop)."""
        task = self.task
        adds, dels = {}, {}                  # dicts: the effects' order, whatever the names
        for e, cond in effects:
            envs = [env]
            if e.params:
                envs = []
                for combo in itertools.product(*(task.domain(t) for _, t in e.params)):
                    env2 = dict(env)
                    env2.update(zip((v for v, _ in e.params), combo))
                    envs.append(env2)
            for env2 in envs:
                if cond is not None and not cond[0](s, *(env2[v] for v in cond[1])):
                    continue
                atom = (e.pred, tuple(env2.get(t, t) for t in e.args))
                (adds if e.add else dels)[atom] = True
        flips = []
        n = task.n_init
        for atom in adds:
            i = task.intern(atom)
            if (i < n) == (i in s):          # false now
                flips.append(i)
        for atom in dels:
            if atom in adds:
                continue
            i = task.ids.get(atom)
            if i is not None and (i < n) != (i in s):
                flips.append(i)
        return s.symmetric_difference(flips) if flips else None
