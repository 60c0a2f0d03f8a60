"""An HDDL problem as the search (search.py) plans it: the methods and actions of the
lifted domain with their joins, bound against lifted facts (facts.py) as it goes."""
from __future__ import annotations

import math

from ...pddl_io.lifted_types import TRUE, conjuncts, is_a
from .bind import Join, Objects, holds, is_var
from .estimate import method_cost, task_costs
from .goal_reach import GoalReach


class HddlNetwork:
    """The problem's methods and actions with their joins, built once per search."""

    def __init__(self, htn):
        dom, prob = htn.domain, htn.problem
        self.objects = Objects(prob.objects, dom.parents)
        self.goal = prob.goal
        # :init in file order (a fixed order: the search's choices follow the facts')
        self.init = prob.init_order if prob.init_order is not None else sorted(prob.init)
        join = lambda f, bound, free: Join(f, bound, free, self.objects, dom.predicates, dom.parents)  # noqa: E731
        self.actions = {}
        for a in dom.actions:
            names = [v for v, _ in a.params]
            effects = [(e, join(e.cond, names, e.params) if e.params or e.cond != TRUE else None) for e in a.effects]
            self.actions[a.name] = (names, join(a.pre, names, ()), effects)
        costs = task_costs(htn.methods, set(self.actions))
        self.task_costs = costs
        self.methods: dict = {}
        for m in htn.methods:
            entry = self._method(m, htn, dom)
            if entry[3] < math.inf:   # else it can never be reduced to actions
                self.methods.setdefault(m.task[0], []).append(entry)
        self.root = self._method(htn.network, htn, dom)
        joins = [j for _, j, _ in self.actions.values()] + [j for _, _, effects in self.actions.values()
                                                            for _, j in effects if j is not None]
        joins += [entry[2] for entries in self.methods.values() for entry in entries] + [self.root[2]]
        self.patterns = {(step[1], step[2]) for j in joins for step in j.steps if step[0] == "match"}
        self.goal_reach = GoalReach(self.goal, dom.actions, {t: [e[0] for e in entries] for t, entries in self.methods.items()})
        self.goal_atoms = self.goal_reach.atoms   # goal_reach.py's cut: what the network must still add
        self.task_mask = self.goal_reach.mask

    def _method(self, m, htn, dom) -> tuple:
        """(method, how its task's arguments bind its variables, its join, its estimate)."""
        task_types = htn.tasks[m.task[0]].params if m.task[0] in htn.tasks else ()
        unify, bound = [], set()
        types = dict(m.params)
        for i, term in enumerate(m.task[1]):
            if not is_var(term) or term in bound:
                unify.append((i, term, None, False))
                continue
            want = types.get(term, frozenset({"object"}))
            have = task_types[i] if i < len(task_types) else frozenset({"object"})
            implied = "object" in want or all(any(is_a(t, w, dom.parents) for w in want) for t in have)
            unify.append((i, term, None if implied else self.objects.fits(want), True))
            bound.add(term)
        free = tuple((v, t) for v, t in m.params if v not in bound)
        pre = m.pre
        ahead = self._static_ahead(m, dom)
        if ahead:
            pre = ("and", (pre, *ahead))
        join = Join(pre, bound, free, self.objects, dom.predicates, dom.parents)
        return m, tuple(unify), join, method_cost(m, self.task_costs, set(self.actions))

    def _static_ahead(self, m, dom) -> list:
        """The static part of the preconditions of the method's actions, in its terms.

        A precondition literal over a predicate no action changes (or an equality) that
        fails now fails when the action comes: checking it with the method's own
        precondition cuts a binding at once instead of after every subtask before that
        action, and binds a variable that only the action constrains (the direction a
        calibration needs) through the facts instead of over every object of its type."""
        changed = {e.pred for a in dom.actions for e in a.effects}
        by_name = {a.name: a for a in dom.actions}
        out = []
        for name, terms in m.subtasks:
            action = by_name.get(name)
            if action is None:
                continue
            rename = dict(zip((v for v, _ in action.params), terms))
            for lit in conjuncts(action.pre):
                atom = lit[1] if lit[0] == "not" else lit
                if atom[0] == "atom" and atom[1] not in changed:
                    new = ("atom", atom[1], tuple(rename.get(t, t) for t in atom[2]))
                elif atom[0] == "=":
                    new = ("=", rename.get(atom[1], atom[1]), rename.get(atom[2], atom[2]))
                else:
                    continue
                out.append(("not", new) if lit[0] == "not" else new)
        return out

    def expansions(self, name: str, args: tuple, facts) -> list:
        """(estimate, method, ground subtasks) for every way to decompose (name, args) in
        the current state, the least estimate first (ties in the file's order); name None:
        the problem's network, under each binding of its parameters."""
        out, seen = [], set()
        for m, unify, join, est in self.methods.get(name, ()) if name is not None else (self.root,):
            env = {}
            for i, term, fits, fresh in unify:
                value = args[i]
                if fresh:
                    if fits is not None and value not in fits:
                        break
                    env[term] = value
                elif (env[term] if is_var(term) else term) != value:
                    break
            else:
                for binding in join.bindings(facts, env):
                    subtasks = tuple((n, tuple(binding[t] if is_var(t) else t for t in a)) for n, a in m.subtasks)
                    if (m.name, subtasks) not in seen:
                        seen.add((m.name, subtasks))
                        out.append((est, m, subtasks))
        out.sort(key=lambda alt: alt[0])
        return out

    def apply(self, name: str, args: tuple, facts) -> bool:
        """Apply the ground action if its precondition holds: deletes, then adds (PDDL's
        rule: an atom both deleted and added holds afterwards), every condition read in
        the state before."""
        names, pre, effects = self.actions[name]
        env = dict(zip(names, args))
        if not pre.holds(facts, env):
            return False
        adds, dels = [], []
        for e, join in effects:
            envs = [env] if join is None else join.bindings(facts, env)
            for b in envs:
                fact = (e.pred, tuple(b[t] if is_var(t) else t for t in e.args))
                (adds if e.add else dels).append(fact)
        for f in dels:
            facts.remove(f)
        for f in adds:
            facts.add(f)
        return True

    def goal_holds(self, facts) -> bool:
        return holds(self.goal, {}, facts, self.objects)

    def unmet(self, facts) -> int:
        """The goal atoms (goal_reach.py's bits) that do not hold now."""
        return self.goal_reach.unmet(facts.facts)

    @staticmethod
    def action_text(name: str, args: tuple) -> str:
        return "(" + " ".join((name,) + tuple(args)) + ")"

    @staticmethod
    def task_text(name: str, args: tuple) -> str:
        return " ".join((name,) + tuple(args))
