"""Search on a lifted PDDL task (lifted_states.py): successors by joins, best-first width search.

Why this search: a relaxed-plan heuristic needs the grounding that the task is too big
for. Best-first width search (Lipovetzky and Geffner 2017, BFWS) needs no grounding:
it orders states by *novelty* first (w = 1 when a state makes true a fluent atom no
earlier state with the same landmark count made true, else 2), then by how many
landmarks are still missing. The landmarks are the goal's conjuncts, and, for a goal
atom that exactly one action schema adds (binding all its parameters), that action's
precondition conjuncts: the last step reaching the goal atom must be that action, so
its precondition must hold just before (a goal `(done)` reached by one `(finish)`
action counts what `finish` needs, as LAMA's landmark count would). Every state is
queued, so the search is complete; it is not optimal.

Novelty is judged on the atoms an action makes true (not all of a state's atoms: a
state can hold tens of thousands of atoms, and its parent's were judged already).
"""
from __future__ import annotations

import heapq
import itertools

from ..solvers.base import Budget, Meter, Result, budget_result
from .lifted import TRUE, Domain, Problem
from .lifted_joins import JoinCompiler
from .lifted_landmarks import landmarks
from .lifted_states import LiftedTask


WIDTH = 2     # novelty judged on single atoms (1) or also on pairs of atoms of one object (2)


class Successors:
    """`successors(s)`: [(action text, cost, next state)] of every binding of every
    action schema whose precondition holds in s; `test(f)`: s -> does ground formula f hold."""

    def __init__(self, task: LiftedTask, formulas: list = ()):
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
        self.ns = ns = jc.compile()
        self.source = jc.source
        self.memo = ns["MEMO"]
        self.last = None
        self.schemas = [(a, params, ns[fn], [(e, None if c is None else (ns[c[0]], c[1])) for e, c in effects])
                        for a, params, fn, effects in self.schemas]
        self.tests = [ns[name] for name, _ in tests]
        self.use_costs = prob.metric

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


def solve(dom: Domain, prob: Problem, budget: Budget, progress=None, optimal: bool = False,
          solver: str = "gbfs") -> Result:
    """BFWS (see the module docstring), or with `optimal` a search by cost (uniform cost,
    first in first out among equals: breadth-first when every action costs 1), whose
    first plan is a cheapest one. Both use the symmetry rule, which keeps costs."""
    task = LiftedTask(dom, prob)
    marks = [] if optimal else landmarks(task)
    succ = Successors(task, [prob.goal, *(m for m, _ in marks), *(n for _, ns in marks for n in ns)])
    goal_test, *tests = succ.tests
    mark_tests = []
    rest = iter(tests[len(marks):])
    for k, (_, ns) in enumerate(marks):
        mark_tests.append((tests[k], [next(rest) for _ in ns]))
    heuristic = "blind" if optimal else "bfws-landmarks"

    def h(s) -> int:
        succ.begin(s)
        return sum(1 + sum(1 for n in ns if not n(s)) for m, ns in mark_tests if not m(s))

    meter = Meter(budget, progress)
    start = frozenset()
    h0 = h(start)
    seen: set = set()             # (landmark count, atom) pairs some state made true
    for i in task.true_atoms(start):
        seen.add((h0, i))
    parents = {start: None}
    best_g = {start: 0}           # (optimal) the cheapest known cost of each state
    tie = itertools.count()
    queue = [(0 if optimal else 1, h0, next(tie), start)]
    expanded = generated = 0
    mask = meter.mask
    n_init = task.n_init

    def finish(**kw) -> Result:
        return meter.finish(Result(solver=solver, stored=len(parents), heuristic=heuristic,
                                   initial_h=h0, expanded=expanded, generated=generated, **kw))
    atoms, of_object, width = task.atoms, task.of_object, WIDTH

    def novelty(s, t, ht) -> int:
        """1: t makes true an atom no state of landmark count ht did; 2: a pair of atoms
        of one object (its first argument: an agent's x and z, a block's place) that no
        such state had together; else 3."""
        w = 3
        for i in t ^ s:
            if (i < n_init) == (i in t):
                continue          # made false
            if (ht, i) not in seen:
                seen.add((ht, i))
                w = 1
            if width < 2:
                continue
            args = atoms[i][1]
            if not args:
                continue
            for j in of_object[args[0]]:
                if j != i and (j < n_init) != (j in t) and atoms[j][1][:1] == args[:1]:
                    key = (ht, i, j) if i < j else (ht, j, i)
                    if key not in seen:
                        seen.add(key)
                        w = min(w, 2)
        return w if width >= 2 else min(w, 2)

    closed: set = set()
    while queue:
        g_or_w, _, _, s = heapq.heappop(queue)
        if s in closed or optimal and g_or_w > best_g[s]:
            continue
        closed.add(s)
        succ.begin(s)
        if goal_test(s):
            plan, cost = [], 0
            while parents[s] is not None:
                s, name, c = parents[s]
                plan.append(name)
                cost += c
            plan.reverse()
            return finish(solved=True, status="solved", plan=plan, cost=cost)
        expanded += 1
        if not expanded & mask or budget.max_states is not None and len(parents) > budget.max_states:
            which = meter.check(expanded, generated, len(parents))
            mask = meter.mask
            if which:
                return budget_result(solver, which, meter, expanded, generated, len(parents),
                                     heuristic=heuristic, initial_h=h0)
        gs = best_g[s] if optimal else 0
        for name, c, t in succ(s):
            generated += 1
            if optimal:
                if t in closed or best_g.get(t, gs + c + 1) <= gs + c:
                    continue
                best_g[t] = gs + c
                parents[t] = (s, name, c)
                heapq.heappush(queue, (gs + c, 0, next(tie), t))
                continue
            if t in parents:
                continue
            parents[t] = (s, name, c)
            ht = h(t)
            heapq.heappush(queue, (novelty(s, t, ht), ht, next(tie), t))
    return finish(solved=False, status="no_solution", message="no plan exists: every reachable state was explored")
