"""Search on a lifted PDDL task (lifted_states.py): successors by joins, a greedy search with novelty.

Why this search: a relaxed-plan heuristic needs the grounding that the task is too big
for. Here the heuristic is read off the action schemas without grounding: the missing
landmarks (lifted_landmarks.py: the goal's conjuncts, the precondition of a goal atom's
only achiever, and what every achiever of a landmark needs), each with the false
conditions of its cheapest achiever, and once, the movers' distance to the nearest
place where work can be done (lifted_distances.py: along domain transition graphs to
where an achiever can act, plus what the last step onto that place needs: a block to
stand on). Moves are counted once, not once per landmark: summed, a step away from a
cluster of five goals cost five, and fetching a block from two cells away looked worse
than any detour. A counter that every achiever of several landmarks steps down ("holds
one T") costs the steps it lacks (lifted_landmarks.supply); while it is short, or a
need is unmet, the way to the nearest place to step it up (break a block of T, pick one
up) that undoes no landmark met, and on from there to an achiever's place, is a way to
work too (lifted_supplies.py): without the way on, fetching the last block looked worse
than staying beside the goal, and putting a block down to take it back looked like
progress. A goal that is any of several values of a counter ("holds 5 or more T", an
`or`) costs the counter's distance to the nearest of them, and its nearest refill is a
place to go too (`_direct`). (The block-building benchmark's plus shape of five blocks: stuck at 13 with
the sum; at 3 with the moves shared, its last block wanting a count spent on a support;
solved with supplies too.)

States wait in two queues, taken from in turn (as LAMA alternates its queues): one by
that estimate first, then by *novelty* (Lipovetzky and Geffner's best-first width
search), the other by novelty first, then the estimate. Novelty: w = 1 when a state
makes true an atom no earlier state with the same number of missing landmarks did, 2
when it makes a new pair of atoms of one object (an agent's x and z), else 3. By the
estimate alone the search sank into plateaus of blocks put anywhere (each new, none
closer): the plus shape gathered from the world (Collect_Build_Shape) and the cross
(Build_Cross) were not solved in 60 s; by turns in 1,854 and 2,185 expansions. Every
state is queued, so the search is complete; it is not optimal.

Novelty is judged on the atoms an action makes true (not all of a state's atoms: a
state can hold tens of thousands of atoms, and its parent's were judged already).
"""
from __future__ import annotations

import heapq
import itertools

from .base import Budget, Meter, Result, budget_result
from ..pddl_io.lifted_types import TRUE, Domain, Problem, conjuncts
from ..pddl_io.lifted_joins import JoinCompiler
from ..heuristics.lifted_distances import Distances
from ..heuristics.lifted_landmarks import landmarks, supply
from ..heuristics.lifted_supplies import counter, refills, undoes
from ..pddl_io.lifted_states import LiftedTask


WIDTH = 2     # novelty judged on single atoms (1) or also on pairs of atoms of one object (2)


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


def solve(dom: Domain, prob: Problem, budget: Budget, progress=None, optimal: bool = False,
          solver: str = "gbfs") -> Result:
    """BFWS (see the module docstring), or with `optimal` a search by cost (uniform cost,
    first in first out among equals: breadth-first when every action costs 1), whose
    first plan is a cheapest one. Both use the symmetry rule, which keeps costs."""
    task = LiftedTask(dom, prob)
    succ, h, count = _landmark_heuristic(task, prob, optimal)
    heuristic = "blind" if optimal else "bfws-landmarks"
    goal_test = succ.tests[0]
    meter = Meter(budget, progress)
    start = frozenset()
    h0 = h(start)
    seen: set = set()             # (landmark count, atom) pairs some state made true
    c0 = count(start)
    for i in task.true_atoms(start):
        seen.add((c0, i))
    novelty = _novelty(task, seen)
    parents = {start: None}
    best_g = {start: 0}           # (optimal) the cheapest known cost of each state
    tie = itertools.count()
    queue = [(0 if optimal else h0, 1, next(tie), start)]
    expanded = generated = 0
    mask = meter.mask

    def finish(**kw) -> Result:
        return meter.finish(Result(solver=solver, stored=len(parents), heuristic=heuristic,
                                   initial_h=h0, expanded=expanded, generated=generated, **kw))

    closed: set = set()
    other: list = [] if optimal else [(1, h0, next(tie), start)]      # the same states by (novelty, h)
    turn = 0
    while queue or other:
        turn += 1
        if other and (not queue or turn & 1):
            w, key, _, s = heapq.heappop(other)
        else:
            if not queue:
                break
            key, _, _, s = heapq.heappop(queue)
        if s in closed or optimal and key > best_g[s]:
            continue
        closed.add(s)
        succ.begin(s)
        if goal_test(s):
            plan, cost = _plan_to(s, parents)
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
            w = novelty(s, t, count(t))
            heapq.heappush(queue, (ht, w, next(tie), t))
            heapq.heappush(other, (w, ht, next(tie), t))
    return finish(solved=False, status="no_solution", message="no plan exists: every reachable state was explored")


def _landmark_heuristic(task: LiftedTask, prob: Problem, optimal: bool):
    """The successor function, which also tests the goal (its test 0) and the landmarks;
    `h(s)`, the landmark estimate (none when `optimal`: the search is blind); and
    `count(s)`, the number of missing landmarks (novelty is judged per count)."""
    marks = [] if optimal else landmarks(task)
    dist = Distances(task)
    formulas: dict = {prob.goal: 0}

    def test_of(f) -> int:
        return formulas.setdefault(f, len(formulas))

    plan_h = []       # per landmark: (its test, [need tests], distance or None, [(functions, other tests)], supply)
    supplies: dict = {}   # supply (lifted_landmarks.supply) -> steps(s, k): the counter's steps left, up to k
    fill: dict = {}       # supply -> [(relaxed join, its parameters, the mover's dropped atoms)]: its refills
    relaxed: list = []
    def add_fill(sup):
        if sup not in fill:
            fill[sup] = []
            for pre, params, types, dropped, deletes in refills(task, dist, sup):
                fill[sup].append((len(relaxed), params, dropped, deletes))
                relaxed.append((pre, params, types))

    for m, ns in marks:
        direct = _direct(task, dist, m)
        if direct is not None and direct[3] is not None:
            add_fill(direct[3])
        inst = [] if direct or not ns else [(fs, [test_of(o) for o in others], _entry_groups(fs))
                                            for fs, others in dist.instances(m)]
        sup = supply(task, m) if ns and not direct else None
        if sup is not None and sup not in supplies:
            supplies[sup] = counter(task, sup)
            add_fill(sup)
        plan_h.append((test_of(m), [test_of(n) for n in ns], direct, inst, sup))
    goal_marks = [(m, test_of(m)) for m, _ in marks]
    succ = Successors(task, list(formulas), relaxed)
    tests, relaxed_fns = succ.tests, succ.relaxed
    index, n_init = task.index, task.n_init

    def value(s, pred, obj, cache):
        got = cache.get((pred, obj))
        if got is None:
            got = next((args[1] for i, args in index.get((pred, 0, obj), ()) if (i < n_init) != (i in s)), None)
            cache[(pred, obj)] = got
        return got

    def h(s) -> int:
        """The missing landmarks (see lifted_landmarks.py, lifted_distances.py): each 1,
        plus 1 per missing need, plus the false conditions of its cheapest achiever, plus
        the steps its counter lacks; and once, the movers' distance to the nearest place
        where work can be done (an achiever's, with what stepping there needs, or a refill's)."""
        succ.begin(s)
        total, cache, entered, filled = 0, {}, {}, {}
        near = []                  # (distance before entries, tie, entry groups): where to go next
        wanted: dict = {}          # supply -> [landmarks that spend it, of them with the need false]
        spending: dict = {}        # supply -> [(instance rows, base)] of the landmarks that spend it
        for mt, nts, direct, inst, sup in plan_h:
            if tests[mt](s):
                continue
            if direct is not None:
                now = value(s, direct[0], direct[1], cache)
                d = min(dist.distance(direct[0], direct[1], now, v) for v in direct[2])
                total += d
                r = refill(s, direct[3], cache, filled) if d and direct[3] is not None else None
                if r is not None:       # where the count can be stepped toward the goal
                    near.append((r[0], len(near), ()))
                continue
            missing = sum(1 for n in nts if not tests[n](s))
            total += 1 + missing
            if sup is not None:
                w = wanted.setdefault(sup, [0, 0])
                w[0] += 1
                w[1] += 1 if missing else 0
            if not inst:
                continue
            rows = []
            for fs, others, groups in inst:
                d, moving = 0, []
                for g in groups:
                    gd = sum(dist.distance(p, o, value(s, p, o, cache), v) for p, o, v in g[1])
                    if gd:
                        d += gd
                        moving.append(g)
                rows.append((sum(1 for k in others if not tests[k](s)), d, moving, groups))
            base = min(row[0] for row in rows)
            total += base
            if sup is not None:
                spending.setdefault(sup, []).append((rows, base))
            r = refill(s, sup, cache, filled) if missing and sup is not None else None
            if r is not None:      # it lacks what it spends: first where to get more, then here
                near.append((r[0] + carry(s, r[1], [(rows, base)], cache), len(near), ()))
                continue
            for b, d, moving, _ in rows:
                near.append((b - base + d, len(near), moving))
        for sup, (k, unmet) in wanted.items():
            if k > 1:
                # k landmarks each take a step of the counter; those whose need is false
                # were counted already
                short = max(0, k - supplies[sup](s, k) - unmet)
                total += short
                r = refill(s, sup, cache, filled) if short else None
                if r is not None:
                    near.append((r[0] + carry(s, r[1], spending.get(sup, ()), cache), len(near), ()))
        # the nearest place, its entries looked at only while it could still be the nearest
        near.sort()
        reach = None
        for c, _, moving in near:
            if reach is not None and c >= reach:
                break
            for g in moving:
                c += entry(s, g, entered)
            if reach is None or c < reach:
                reach = c
        return total + (reach or 0)

    def carry(s, pos: dict, landmarks_rows, cache) -> int:
        """From the place `pos` ((pred, object) -> value), the moves to the nearest
        achiever's place of the given landmarks, plus its other false conditions."""
        best = None
        for rows, base in landmarks_rows:
            for b, _, _, groups in rows:
                c = b - base
                for g in groups:
                    for p, o, v in g[1]:
                        c += dist.distance(p, o, pos.get((p, o)) or value(s, p, o, cache), v)
                if best is None or c < best:
                    best = c
        return best or 0

    def refill(s, sup, cache, filled):
        """(the movers' distance, their place there) of the nearest place where the
        supply's counter can be stepped up in s (lifted_supplies.refills), or None."""
        if sup in filled:
            return filled[sup]
        found = []
        for k, params, dropped, deletes in fill.get(sup, ()):
            for binding in relaxed_fns[k](s, []):
                env = dict(zip(params, binding))
                d = 0
                for p, o, v in dropped:
                    o = env.get(o, o)
                    d += dist.distance(p, o, value(s, p, o, cache), env.get(v, v))
                found.append((d, len(found), env, deletes, dropped))
        found.sort()
        met = None
        best = None
        for d, _, env, deletes, dropped in found:          # the nearest that undoes no landmark met
            if met is None:
                met = [m for m, mt in goal_marks if tests[mt](s)]
            deleted = [(p, tuple(env.get(t, t) for t in args)) for p, args in deletes]
            if not any(undoes(task, s, m, deleted) for m in met):
                best = (d, {(p, env.get(o, o)): env.get(v, v) for p, o, v in dropped})
                break
        filled[sup] = best
        return best

    entry_tests: dict = {}     # (object, wanted values) -> [[test]] of each way to step there

    def ways_in(key) -> list:
        """The tests of each way to step onto a place, worked out and compiled when the
        estimate first looks at the place (472 places of a large build took most of the
        time before the first expansion when all were worked out at the start)."""
        got = entry_tests.get(key)
        if got is None:
            ways = dist.entries(*key)
            known = len(formulas)
            got = entry_tests[key] = [[test_of(c) for c in e] for e in ways]
            if len(formulas) > known:
                succ.more_tests(list(formulas)[known:])
        return got

    def entry(s, group, entered) -> int:
        """The false conjuncts of the cheapest way to step onto the group's values."""
        got = entered.get(group[0])
        if got is None:
            got = None
            for e in ways_in(group[0]):
                c = sum(1 for k in e if not tests[k](s))
                if got is None or c < got:
                    got = c
                    if not c:
                        break
            got = entered[group[0]] = got or 0
        return got

    def count(s) -> int:
        return sum(1 for mt, *_ in plan_h if not tests[mt](s))
    return succ, h, count


def _direct(task: LiftedTask, dist: Distances, m):
    """A landmark that is a value of a functional atom, P(o, v), or any of several,
    (or P(o, v1) P(o, v2) ...) ("holds at least 5 T"): (P, o, values, toward), its cost
    the distance to the nearest value; `toward`, for several values, is the counter step
    (a supply key, lifted_supplies.refills) that leads toward them from the start, so
    the nearest place to take one is where to go. None for any other landmark."""
    if m[0] == "atom" and len(m[2]) == 2 and dist.functional(m[1], m[2][0]):
        return (m[1], m[2][0], (m[2][1],), None)
    if m[0] != "or" or not m[1] or any(c[0] != "atom" or len(c[2]) != 2 for c in m[1]):
        return None
    pred, obj = m[1][0][1], m[1][0][2][0]
    if any(c[1] != pred or c[2][0] != obj for c in m[1]) or not dist.functional(pred, obj):
        return None
    values = tuple(c[2][1] for c in m[1])
    start = next((args[1] for i, args in task.index.get((pred, 0, obj), ()) if i < task.n_init), None)
    if start is None:
        return (pred, obj, values, None)
    far = min(dist.distance(pred, obj, start, v) for v in values)
    toward = None
    for a in task.dom.actions:
        for d in a.effects:
            if d.add or d.pred != pred or len(d.args) != 2:
                continue
            for e in a.effects:
                if not e.add or e.pred != pred or e.args[0] != d.args[0] or e.args[1] == d.args[1]:
                    continue
                for c in conjuncts(a.pre):
                    if c[0] != "atom" or c[1] in task.fluent or len(c[2]) != 2 or set(c[2]) != {d.args[1], e.args[1]}:
                        continue
                    pos = c[2].index(e.args[1])
                    nxt = [f[pos] for f in task.static_all.get(c[1], ()) if f[1 - pos] == start]
                    if toward is None and any(min(dist.distance(pred, obj, w, v) for v in values) < far for w in nxt):
                        toward = (pred, c[1], pos)
    return (pred, obj, values, toward)


def _entry_groups(fs: list) -> list:
    """An instance's functional atoms by object: [(key, [(pred, obj, value)])], the key
    (object, wanted values) naming the place whose entries (lifted_distances.Distances.entries:
    what stepping onto those values needs) the estimate reads when it first looks there."""
    by_obj: dict = {}
    for p, o, v in fs:
        by_obj.setdefault(o, []).append((p, o, v))
    return [((o, tuple(sorted((p, v) for p, _, v in group))), group) for o, group in by_obj.items()]


def _novelty(task: LiftedTask, seen: set):
    """`novelty(s, t, ht)`, judged against and recorded in `seen`."""
    atoms, of_object, width, n_init = task.atoms, task.of_object, WIDTH, task.n_init

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
    return novelty


def _plan_to(s, parents: dict) -> tuple[list, int]:
    """The actions from the start to `s` along `parents`, and their cost."""
    plan, cost = [], 0
    while parents[s] is not None:
        s, name, c = parents[s]
        plan.append(name)
        cost += c
    plan.reverse()
    return plan, cost
