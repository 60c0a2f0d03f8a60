"""Delete-relaxation heuristics over the model's relaxed view (relaxed_task.py).

- `hmax`: the costliest goal fact, each fact costing its costliest precondition plus
  the operator; admissible and consistent.
- `hadd`: costs added instead of maxed; informative, not admissible.
- `hff`: the cost of a relaxed plan read off hadd's best supporters (Hoffmann & Nebel
  2001); not admissible. Its *preferred actions* (the relaxed plan's first steps, that
  apply in the state) steer gbfs.
- `lmcut`: LM-cut (Helmert & Domshlak 2009): repeatedly compute hmax, cut the
  justification graph in front of the goal, add the cheapest cut operator's cost and
  discount the cut; admissible, and usually far stronger than hmax.

All four run the one exploration over facts (relaxed_explore.py): hmax, hadd and hff
its fast form, kept from state to state; LM-cut its plain form, then its update after
each cut. A state is turned into facts by the view's one state reader.
"""
from __future__ import annotations

import functools
import math

from .relaxed_explore import Exploration

INF = math.inf


class Relaxed:
    """Precomputed indices over a RelaxedTask, and the four heuristics."""

    def __init__(self, task, facts_of):
        self.task = task
        self.facts_of = facts_of   # a model's state -> the facts that hold in it
        self.n_facts, self.n_ops = task.n_facts, len(task.pre)
        self.pre, self.add, self.cost, self.action = task.pre, task.add, task.cost, task.action
        self.pre_of = [[] for _ in range(self.n_facts)]
        for i, pre in enumerate(self.pre):
            for p in pre:
                self.pre_of[p].append(i)
        self.n_pre = [len(p) for p in self.pre]
        self.free = [i for i, p in enumerate(self.pre) if not p]
        self.goal = task.goal
        self.goal_set = set(task.goal or ())
        self.is_goal_fact = bytearray(self.n_facts)
        for g in self.goal_set:
            self.is_goal_fact[g] = 1
        self.achievers = [[] for _ in range(self.n_facts)]
        for i, add in enumerate(self.add):
            for f in add:
                self.achievers[f].append(i)
        self.preferred: frozenset = frozenset()
        self._fast = self._exact = None   # the explorations (fast, exact), built on first use
        # The guiding view's steps of a count (relaxed_build.py, fire_effects) each cost their
        # action; an action's own operator in a relaxed plan is one execution of it, and
        # makes one of those steps: hff charges only the steps beyond those (_step_savings).
        chained = set(getattr(task, "chained", ()))
        self.step_of = {}    # step operator -> the fired fact it steps
        self.pays = {}       # operator of an action, costing > 0 -> the chained fired facts it adds
        if chained:
            for i, (pre, add, c, a) in enumerate(zip(self.pre, self.add, self.cost, self.action)):
                if a < 0 and c > 0:
                    fired = [p for p in pre if p in chained]
                    if len(fired) == 1:
                        self.step_of[i] = fired[0]
                elif a >= 0 and c > 0:
                    fired = [g for g in add if g in chained]
                    if fired:
                        self.pays[i] = fired
        # hadd and hff ask `guide`, the view whose goal is reached by a last action
        # (relaxed_last.py), when there is one; a state where the goal holds needs
        # no last action, so there `holds` (the model's goal test) answers 0.
        self.guide = None
        self.holds = None

    # ---- exploration (relaxed_explore.py) ----------------------------------------------------
    def fast(self) -> Exploration:
        """The exploration every hmax, hadd and hff evaluation runs (shared preconditions
        folded, counters kept from the last state), built on first use. The costs of the
        view's facts are those any exploration gives; supporters may be its node
        operators (>= n_ops)."""
        if self._fast is None:
            self._fast = Exploration(self.n_facts, self.pre, self.add, self.goal_set)
        return self._fast

    def exact(self) -> Exploration:
        """The plain exploration LM-cut runs (every fact in order, its cuts' order)."""
        if self._exact is None:
            self._exact = Exploration(self.n_facts, self.pre, self.add, self.goal_set, share=False, incremental=False)
        return self._exact

    def goal_cost(self, cost, additive: bool):
        if self.goal is None:
            return INF
        if not self.goal:
            return 0
        values = [cost[g] for g in self.goal]
        return sum(values) if additive else max(values)

    # ---- heuristics ---------------------------------------------------------------------------
    def hmax(self, state) -> float:
        cost, _, _ = self.fast().explore(self.facts_of(state), self.cost, additive=False)
        return self.goal_cost(cost, False)

    def hadd(self, state) -> float:
        if self.guide is not None:
            h = self.guide.hadd(state)
            if h != INF:
                return h
            # The guiding view reads fired effects as changing (relaxed_last.py): it may
            # miss a last action the plain view has, never declare a dead end for it.
        if self.holds is not None and self.holds(state):
            return 0
        cost, _, _ = self.fast().explore(self.facts_of(state), self.cost)
        return self.goal_cost(cost, True)

    def hff(self, state) -> float:
        """Relaxed plan cost; sets `self.preferred` to the grounded actions of the plan's
        operators that apply in `state` (all preconditions reached at cost 0)."""
        if self.guide is not None:
            h = self.guide.hff(state)
            self.preferred = self.guide.preferred
            if h != INF:
                return h
        if self.holds is not None and self.holds(state):
            self.preferred = frozenset()
            return 0
        cost, sup, _ = self.fast().explore(self.facts_of(state), self.cost)
        if self.goal is None or any(cost[g] == INF for g in self.goal):
            self.preferred = frozenset()
            return INF
        plan, stack, seen = set(), [g for g in self.goal if cost[g] > 0], set()
        pre = self.fast().pre   # with the node operators that stand for shared preconditions
        while stack:
            f = stack.pop()
            if f in seen:
                continue
            seen.add(f)
            i = sup[f]
            if i < 0 or i in plan:
                continue
            plan.add(i)
            stack.extend(p for p in pre[i] if cost[p] > 0)
        n_ops = self.n_ops
        plan = {i for i in plan if i < n_ops}
        preferred = set()
        for i in plan:
            if all(cost[p] == 0 for p in self.pre[i]):
                preferred.update(self._actions_of(i, cost))
        self.preferred = frozenset(preferred)
        h = sum(self.cost[i] for i in plan)
        return h - self._step_savings(plan) if self.step_of else h

    def _step_savings(self, plan) -> float:
        """What the plan's steps cost that its own action operators already paid: each
        plan operator of an action that fires a count's steps makes one step (the
        cheapest ones are counted as paid). Without this, putting one thing down cost
        two (the action and its step), and holding k things k + 1."""
        paid: dict = {}
        steps: dict = {}
        for i in plan:
            fired = self.step_of.get(i)
            if fired is not None:
                steps.setdefault(fired, []).append(self.cost[i])
            for f in self.pays.get(i, ()):
                paid[f] = paid.get(f, 0) + 1
        return sum(sum(sorted(costs)[:paid[f]]) for f, costs in steps.items() if f in paid)

    def _actions_of(self, i, cost):
        """The grounded actions behind operator i (an auxiliary one stands for the actions
        that fired it, among the operators applicable now)."""
        if self.action[i] >= 0:
            return (self.action[i],)
        out = []
        for p in self.pre[i]:
            for j in self.achievers[p]:
                if self.action[j] >= 0 and self.cost[j] > 0 and all(cost[q] == 0 for q in self.pre[j]):
                    out.append(self.action[j])
        return out

    def lmcut(self, state) -> float:
        init = self.facts_of(state)
        if self.goal is None:
            return INF
        if not self.goal:
            return 0
        costs = list(self.cost)
        goal, pre, add, pre_of, achievers = self.goal, self.pre, self.add, self.pre_of, self.achievers
        init_set = set(init)
        total = 0
        exploration = self.exact()
        cost, _, pcf = exploration.explore(init, costs, additive=False, stop_at_goal=False)
        while True:
            gmax = max(goal, key=cost.__getitem__)
            if cost[gmax] == INF:
                return INF
            if cost[gmax] == 0:
                return total
            # Goal zone: facts from which the goal is reached by zero-cost justification edges.
            zone = {gmax}
            stack = [gmax]
            while stack:
                f = stack.pop()
                for i in achievers[f]:
                    p = pcf[i]
                    if p >= 0 and costs[i] == 0 and p not in zone:
                        zone.add(p)
                        stack.append(p)
            # Forward from the state, not entering the zone: operators crossing into it form the cut.
            cut = []
            reached = set()
            stack = []
            for i in self.free:
                for g in add[i]:
                    if g in zone:
                        cut.append(i)
                        break
                else:
                    for g in add[i]:
                        if g not in reached:
                            reached.add(g)
                            stack.append(g)
            for f in init_set:
                if f not in reached and f not in zone:
                    reached.add(f)
                    stack.append(f)
            while stack:
                f = stack.pop()
                for i in pre_of[f]:
                    if pcf[i] != f:
                        continue
                    crosses = False
                    for g in add[i]:
                        if g in zone:
                            crosses = True
                        elif g not in reached:
                            reached.add(g)
                            stack.append(g)
                    if crosses:
                        cut.append(i)
            cut = set(cut)
            m = min(costs[i] for i in cut)
            if m <= 0:  # cannot happen with a correct cut; guard against an endless loop
                return total
            total += m
            for i in cut:
                costs[i] -= m
            exploration.lower(cut, costs, cost, pcf)


def relaxed_of(model, time_limit: float | None = None) -> Relaxed | None:
    """The model's Relaxed heuristics (built once per model, kept in `model.memo`), or
    None when the relaxed view cannot be built within its limits (or `time_limit` seconds)."""
    r = model.memo.get("relaxed")
    if r is None:
        task = model.data("relaxed_task", time_limit=time_limit)
        if task is None:
            return None
        read = task.reader.facts
        if task.reader.reads_dense:
            dense = model.dense   # a model's state stores only its changed cells (issue 18)

            def facts_of(state):
                return read(dense(state))
        else:
            facts_of = read
        r = model.memo["relaxed"] = Relaxed(task, facts_of)
        if task.guide is not None:
            r.guide = Relaxed(task.guide, facts_of)
            r.guide.holds = model.is_goal
    return r


# The heuristics' `make`s (registry.py): the relaxed view's absence is handled there (blind).
def hmax(model, time_limit: float | None = None):
    return relaxed_of(model, time_limit).hmax


def hadd(model, time_limit: float | None = None):
    return relaxed_of(model, time_limit).hadd


def hff(model, time_limit: float | None = None):
    """hff, with `h.preferred()`: the preferred actions of the state last evaluated."""
    r = relaxed_of(model, time_limit)
    h = functools.partial(Relaxed.hff, r)
    h.preferred = lambda: r.preferred
    return h


def lmcut(model, time_limit: float | None = None):
    return relaxed_of(model, time_limit).lmcut
