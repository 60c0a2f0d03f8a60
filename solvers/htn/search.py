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

The network is a linked list (hash, name, args, id, rest, mask): pushing a method's
subtasks shares the rest, and each node's hash covers the tasks below it, its mask the
goal atoms they may still add (goal_reach.py).

The search is the one for both front ends. What it plans with (`net`) answers these
questions, and what it changes (`state`) is undone by marks:

    net.actions                      the names of actions (anything else is a compound task)
    net.apply(name, args, state)     apply the ground action if it applies; True if it did
    net.expansions(name, args, state)  [(estimate, method, ground subtasks)], least first;
                                     name None: the initial network's
    net.goal_holds(state)            whether the goal holds once the network is done
    net.goal_atoms                   goal_reach.py's cut: the atoms the goal needs; where
                                     there are any, also:
    net.task_mask(name, args)        those a task or action may add
    net.unmet(state)                 those that do not hold now (a network whose tasks'
                                     masks miss one is dropped)
    state.hash, state.mark(), state.undo(mark)

HDDL problems answer them with lifted facts (hddl_network.py, facts.py), compiled
dungeons with their generated code (model_network.py).
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass
class Outcome:
    status: str                 # "solved" | "no_solution" | "budget"
    plan: list                  # [(id, name, args)]
    decompositions: list        # [(id, name, args, method, [child ids])], the root's first
    expanded: int
    generated: int
    stored: int
    budget: str | None = None


ROOT_ID = -1


def run_search(c, facts, meter, budget) -> Outcome:
    """Depth-first progression from the problem's network; see the module's docstring."""
    return _DepthFirst(c, facts).run(meter, budget.max_states)


class _DepthFirst:
    """The search's path: the plan and decompositions so far, the choice points to
    backtrack to, and the compound tasks open since the last action."""

    def __init__(self, c, facts):
        self.c, self.facts = c, facts
        self.plan: list = []
        self.decomps: list = []
        self.choices: list = []   # [alternatives, next, undo mark, len(plan), len(decomps), network node, open]
        self.counter = 0
        # The compound tasks being decomposed since the last action on this path: one met
        # again there (same arguments, same state) is cut, which ends left recursion (a
        # method whose first subtask is its own task again, with other arguments each time).
        self.open_tasks = frozenset()
        self.cut = bool(c.goal_atoms)   # goal_reach.py: a network that can no longer add an unmet goal atom
        self.task_mask = c.task_mask if self.cut else (lambda name, args: 0)

    def push(self, subtasks, rest):
        """The network with `subtasks` on top of `rest`, and their new ids."""
        ids = []
        net = rest
        task_mask = self.task_mask
        for name, args in reversed(subtasks):
            self.counter += 1
            ids.append(self.counter)
            net = (hash((name, args, net[0] if net else 0)), name, args, self.counter, net,
                   task_mask(name, args) | (net[5] if net else 0))
        ids.reverse()
        return net, ids

    def take(self, choice):
        """The network after the choice's next alternative, its decomposition recorded."""
        alts, i, _, _, _, node, before = choice
        choice[1] = i + 1
        _, m, subtasks = alts[i]
        self.open_tasks = before | {(node[1], node[2])}
        net, ids = self.push(subtasks, node[4])
        self.decomps.append((node[3], node[1], node[2], m.name, ids))
        return net

    def backtrack(self):
        """The network after the latest choice point's next alternative (False: none is left)."""
        choices = self.choices
        while choices:
            choice = choices[-1]
            if choice[1] < len(choice[0]):
                self.facts.undo(choice[2])
                del self.plan[choice[3]:]
                del self.decomps[choice[4]:]
                return self.take(choice)
            choices.pop()
        return False

    def run(self, meter, max_states) -> Outcome:
        c, facts, plan, choices = self.c, self.facts, self.plan, self.choices
        take, backtrack, cut = self.take, self.backtrack, self.cut
        visited: set = set()
        expanded = generated = 0
        root = (0, None, (), ROOT_ID, None, 0)   # the problem's network, decomposed by its one "method"
        alts = c.expansions(None, (), facts)
        net = False
        if alts:
            choices.append([alts, 0, facts.mark(), 0, 0, root, frozenset()])
            net = take(choices[-1])
        while net is not False:
            if net is None:
                if c.goal_holds(facts):
                    return Outcome("solved", plan, self.decomps, expanded, generated, len(visited))
                net = backtrack()
                continue
            _, name, args, uid, rest, mask = net
            if cut and c.unmet(facts) & ~mask:
                net = backtrack()
                continue
            if name in c.actions:
                if c.apply(name, args, facts):
                    plan.append((uid, name, args))
                    self.open_tasks = frozenset()
                    net = rest
                else:
                    net = backtrack()
                continue
            key = (facts.hash, net[0])
            if key in visited or (name, args) in self.open_tasks:
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
            choices.append([alts, 0, facts.mark(), len(plan), len(self.decomps), net, self.open_tasks])
            net = take(choices[-1])
        return Outcome("no_solution", [], [], expanded, generated, len(visited))
