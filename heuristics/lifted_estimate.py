"""The landmark estimate of the lifted search, read off the action schemas without grounding.

What it counts (the search's module docstring says why): each missing landmark 1, plus
1 per missing need, plus the false conditions of its cheapest achiever, plus the steps
its counter lacks (lifted_landmarks.supply); and once, the movers' distance to the
nearest place where work can be done: an achiever's place (lifted_distances.py) with
what stepping there needs, or a place to step a short counter up (lifted_supplies.py)
and on from there to an achiever's place.

The formulas it reads (the goal, the landmarks, their needs and achievers' conditions)
are compiled as tests with the successor function (pddl_io/lifted_successors.py), test 0
being the goal; what stepping onto a place needs is worked out, and its tests compiled,
when the estimate first looks at that place.
"""
from __future__ import annotations

from ..pddl_io.lifted_states import LiftedTask
from ..pddl_io.lifted_successors import Successors
from ..pddl_io.lifted_types import Problem, conjuncts
from .lifted_distances import Distances
from .lifted_landmarks import landmarks, supply
from .lifted_supplies import counter, refills, undoes


class LandmarkEstimate:
    """`h(s)`, the estimate (none when `optimal`: the search is blind); `count(s)`, the
    number of missing landmarks (novelty is judged per count); `succ`, the successor
    function, which also holds the tests."""

    def __init__(self, task: LiftedTask, prob: Problem, optimal: bool):
        self.task = task
        self.marks = marks = [] if optimal else landmarks(task)
        self.dist = Distances(task)
        self.formulas: dict = {prob.goal: 0}      # formula -> its test
        self.plan_h = []      # per landmark: (its test, [need tests], direct or None, [(functions, other tests, places)], supply)
        self.supplies: dict = {}   # supply (lifted_landmarks.supply) -> steps(s, k): the counter's steps left, up to k
        self.fill: dict = {}       # supply -> [(relaxed join, its parameters, the mover's dropped atoms, deletes)]
        self.relaxed: list = []    # (precondition, parameters, types) of the refills' relaxed joins
        for m, ns in marks:
            self._add_landmark(m, ns)
        self.goal_marks = [(m, self.test_of(m)) for m, _ in marks]
        self.succ = Successors(task, list(self.formulas), self.relaxed)
        self.tests, self.relaxed_fns = self.succ.tests, self.succ.relaxed
        self.entry_tests: dict = {}   # (object, wanted values) -> [[test]] of each way to step there

    def test_of(self, f) -> int:
        return self.formulas.setdefault(f, len(self.formulas))

    def _add_landmark(self, m, ns) -> None:
        task, dist = self.task, self.dist
        direct = _direct(task, dist, m)
        if direct is not None and direct[3] is not None:
            self._add_fill(direct[3])
        inst = [] if direct or not ns else [(fs, [self.test_of(o) for o in others], _entry_groups(fs))
                                            for fs, others in dist.instances(m)]
        sup = supply(task, m) if ns and not direct else None
        if sup is not None and sup not in self.supplies:
            self.supplies[sup] = counter(task, sup)
            self._add_fill(sup)
        self.plan_h.append((self.test_of(m), [self.test_of(n) for n in ns], direct, inst, sup))

    def _add_fill(self, sup) -> None:
        if sup not in self.fill:
            self.fill[sup] = []
            for pre, params, types, dropped, deletes in refills(self.task, self.dist, sup):
                self.fill[sup].append((len(self.relaxed), params, dropped, deletes))
                self.relaxed.append((pre, params, types))

    def value(self, s, pred, obj, cache):
        """The value of a functional atom P(obj, v) in s (kept in `cache` for this state)."""
        got = cache.get((pred, obj))
        if got is None:
            n_init = self.task.n_init
            got = next((args[1] for i, args in self.task.index.get((pred, 0, obj), ()) if (i < n_init) != (i in s)),
                       None)
            cache[(pred, obj)] = got
        return got

    def h(self, s) -> int:
        """The missing landmarks' cost plus, once, the distance to the nearest place to work."""
        self.succ.begin(s)
        tests, dist, value, refill = self.tests, self.dist, self.value, self.refill
        total, cache, filled = 0, {}, {}
        near = []                  # (distance before entries, tie, entry groups): where to go next
        wanted: dict = {}          # supply -> [landmarks that spend it, of them with the need false]
        spending: dict = {}        # supply -> [(instance rows, base)] of the landmarks that spend it
        for mt, nts, direct, inst, sup in self.plan_h:
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
                near.append((r[0] + self.carry(s, r[1], [(rows, base)], cache), len(near), ()))
                continue
            for b, d, moving, _ in rows:
                near.append((b - base + d, len(near), moving))
        for sup, (k, unmet) in wanted.items():
            if k > 1:
                # k landmarks each take a step of the counter; those whose need is false
                # were counted already
                short = max(0, k - self.supplies[sup](s, k) - unmet)
                total += short
                r = refill(s, sup, cache, filled) if short else None
                if r is not None:
                    near.append((r[0] + self.carry(s, r[1], spending.get(sup, ()), cache), len(near), ()))
        return total + self._nearest(s, near)

    def _nearest(self, s, near: list) -> int:
        """The least distance over `near`, each place's entries looked at only while it
        could still be the nearest."""
        near.sort()
        reach, entered = None, {}
        for c, _, moving in near:
            if reach is not None and c >= reach:
                break
            for g in moving:
                c += self.entry(s, g, entered)
            if reach is None or c < reach:
                reach = c
        return reach or 0

    def carry(self, s, pos: dict, landmarks_rows, cache) -> int:
        """From the place `pos` ((pred, object) -> value), the moves to the nearest
        achiever's place of the given landmarks, plus its other false conditions."""
        best = None
        for rows, base in landmarks_rows:
            for b, _, _, groups in rows:
                c = b - base
                for g in groups:
                    for p, o, v in g[1]:
                        c += self.dist.distance(p, o, pos.get((p, o)) or self.value(s, p, o, cache), v)
                if best is None or c < best:
                    best = c
        return best or 0

    def refill(self, s, sup, cache, filled):
        """(the movers' distance, their place there) of the nearest place where the
        supply's counter can be stepped up in s (lifted_supplies.refills), or None."""
        if sup in filled:
            return filled[sup]
        found = []
        for k, params, dropped, deletes in self.fill.get(sup, ()):
            for binding in self.relaxed_fns[k](s, []):
                env = dict(zip(params, binding))
                d = 0
                for p, o, v in dropped:
                    o = env.get(o, o)
                    d += self.dist.distance(p, o, self.value(s, p, o, cache), env.get(v, v))
                found.append((d, len(found), env, deletes, dropped))
        found.sort()
        met = None
        best = None
        for d, _, env, deletes, dropped in found:          # the nearest that undoes no landmark met
            if met is None:
                met = [m for m, mt in self.goal_marks if self.tests[mt](s)]
            deleted = [(p, tuple(env.get(t, t) for t in args)) for p, args in deletes]
            if not any(undoes(self.task, s, m, deleted) for m in met):
                best = (d, {(p, env.get(o, o)): env.get(v, v) for p, o, v in dropped})
                break
        filled[sup] = best
        return best

    def ways_in(self, key) -> list:
        """The tests of each way to step onto a place, worked out and compiled when the
        estimate first looks at the place (472 places of a large build took most of the
        time before the first expansion when all were worked out at the start)."""
        got = self.entry_tests.get(key)
        if got is None:
            ways = self.dist.entries(*key)
            known = len(self.formulas)
            got = self.entry_tests[key] = [[self.test_of(c) for c in e] for e in ways]
            if len(self.formulas) > known:
                self.succ.more_tests(list(self.formulas)[known:])
        return got

    def entry(self, s, group, entered) -> int:
        """The false conjuncts of the cheapest way to step onto the group's values."""
        got = entered.get(group[0])
        if got is None:
            tests = self.tests
            for e in self.ways_in(group[0]):
                c = sum(1 for k in e if not tests[k](s))
                if got is None or c < got:
                    got = c
                    if not c:
                        break
            got = entered[group[0]] = got or 0
        return got

    def count(self, s) -> int:
        tests = self.tests
        return sum(1 for mt, *_ in self.plan_h if not tests[mt](s))


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
