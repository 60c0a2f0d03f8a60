"""Total-order progression over task networks: a state and a stack of ground tasks, the
first task decomposed or executed, depth first with backtracking.

Why this search: in a totally ordered network only the first task can be worked on, so
a search node is (state, remaining tasks) and one step either applies the first task,
if it is an action whose precondition holds, or replaces it by the subtasks of one of
its methods whose precondition holds in the current state (bound now, against the
state: nothing is grounded ahead). The alternatives at a compound task are a choice
point, tried in the order of estimate.py; failing ones are undone (facts.py's log) and
the next is tried. A (state, network) pair met before -- on the current path (a loop)
or in a subtree that already failed -- is not searched again: both are recognised by
the state's and the network's incremental hashes. A compound task met again while it is
being decomposed, with no action in between (so in the same state), is cut too: that ends
left recursion (get-to = get-to somewhere else, then drive), whose networks grow without
end and never repeat. HyperTensioN cuts the same; in principle it can cut a plan whose
inner copy of the task needs the tasks queued after it, which no IPC domain here needs.

The network is a linked list (hash, name, args, id, rest): pushing a method's subtasks
shares the rest, and each node's hash covers the tasks below it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from ...pddl_io.lifted import TRUE, is_a
from ...pddl_io.lifted import conjuncts
from .bind import Join, Objects, holds, is_var
from .estimate import method_cost, task_costs


@dataclass
class Outcome:
    status: str                 # "solved" | "no_solution" | "budget"
    plan: list                  # [(id, name, args)]
    decompositions: list        # [(id, name, args, method, [child ids])], the root's first
    expanded: int
    generated: int
    stored: int
    budget: str | None = None


class Compiled:
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


ROOT_ID = -1


def run_search(c: Compiled, facts, meter, budget) -> Outcome:
    """Depth-first progression from the problem's network; see the module's docstring."""
    plan: list = []
    decomps: list = []
    visited: set = set()
    choices: list = []      # [alternatives, next, undo mark, len(plan), len(decomps), network node, open]
    counter = [0]
    # The compound tasks being decomposed since the last action on this path: one met again
    # there (same arguments, same state) is cut, which ends left recursion (a method whose
    # first subtask is its own task again, with other arguments each time).
    open_tasks = [frozenset()]
    expanded = generated = 0
    max_states = budget.max_states

    def push(subtasks, rest):
        ids = []
        net = rest
        for name, args in reversed(subtasks):
            counter[0] += 1
            ids.append(counter[0])
            net = (hash((name, args, net[0] if net else 0)), name, args, counter[0], net)
        ids.reverse()
        return net, ids

    def take(choice):
        """The network after the choice's next alternative, its decomposition recorded."""
        alts, i, _, _, _, node, before = choice
        choice[1] = i + 1
        _, m, subtasks = alts[i]
        open_tasks[0] = before | {(node[1], node[2])}
        net, ids = push(subtasks, node[4])
        decomps.append((node[3], node[1], node[2], m.name, ids))
        return net

    def backtrack():
        while choices:
            choice = choices[-1]
            if choice[1] < len(choice[0]):
                facts.undo(choice[2])
                del plan[choice[3]:]
                del decomps[choice[4]:]
                return take(choice)
            choices.pop()
        return False

    root = (0, None, (), ROOT_ID, None)   # the problem's network, decomposed by its one "method"
    alts = c.expansions(None, (), facts)
    net = False
    if alts:
        choices.append([alts, 0, facts.mark(), 0, 0, root, frozenset()])
        net = take(choices[-1])
    while net is not False:
        if net is None:
            if c.goal_holds(facts):
                return Outcome("solved", plan, decomps, expanded, generated, len(visited))
            net = backtrack()
            continue
        _, name, args, uid, rest = net
        if name in c.actions:
            if c.apply(name, args, facts):
                plan.append((uid, name, args))
                open_tasks[0] = frozenset()
                net = rest
            else:
                net = backtrack()
            continue
        key = (facts.hash, net[0])
        if key in visited or (name, args) in open_tasks[0]:
            net = backtrack()
            continue
        visited.add(key)
        expanded += 1
        if not expanded & meter.mask or max_states is not None and len(visited) > max_states:
            which = meter.check(expanded, generated, len(visited))
            if which:
                return Outcome("budget", [], [], expanded, generated, len(visited), which)
        alts = c.expansions(name, args, facts)
        generated += len(alts)
        if not alts:
            net = backtrack()
            continue
        choices.append([alts, 0, facts.mark(), len(plan), len(decomps), net, open_tasks[0]])
        net = take(choices[-1])
    return Outcome("no_solution", [], [], expanded, generated, len(visited))
