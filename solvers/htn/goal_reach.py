"""Which of the goal's atoms a task can still make true: a cut for networks that cannot
reach the goal.

A problem may give a state goal beside its task network (plan recognition does: the
observed actions set flags one after another, and the goal is the last flag). The
progression search (search.py) learns only once the network is empty whether the goal
holds, after decomposing every task in it. But an atom of the goal that does not hold now
can hold at the end only if some action the remaining network may still produce adds it.
Which actions a task may produce is fixed by the domain: the task decomposition graph
(a task -> its methods' subtasks, closed; an action produces itself), read here with the
arguments a task has: a method whose task arguments or equality constraints
(`(= ?v c)`) disagree with them is not a way, and its subtasks get the arguments they
are known to have (the others are unknown: any value). So each task gets a mask of the
goal atoms some action it may produce adds (an over-estimate, so the cut is sound), a
network's mask is the union over its tasks, and a network whose mask misses an atom that
is needed and does not hold is abandoned at once.

*Needed*: the goal's atoms, and, for a needed atom that does not hold, every atom that
each action able to add it requires (a precondition atom, ground once the effect is
matched to the atom): the observed actions' chain of flags, so a network that can no
longer produce the next observed action is dropped, not only one that misses the last.

Only positive ground atoms are used; a goal of any other shape cuts nothing.
"""
from __future__ import annotations

from ...pddl_io.lifted_types import conjuncts
from .bind import is_var


def _ground_atoms(formula, env: dict) -> list:
    """The formula's positive atom conjuncts that are ground under `env`."""
    out = []
    for f in conjuncts(formula):
        if f[0] == "atom":
            args = tuple(env.get(t) if is_var(t) else t for t in f[2])
            if None not in args:
                out.append((f[1], args))
    return out


def _match(effect, atom):
    """The binding of the add effect's variables under which it adds the ground atom, or None."""
    pred, args = atom
    if not effect.add or effect.pred != pred or len(effect.args) != len(args):
        return None
    env = {}
    for t, a in zip(effect.args, args):
        if is_var(t):
            if env.setdefault(t, a) != a:
                return None
        elif t != a:
            return None
    return env


def needed_atoms(goal, actions) -> tuple:
    """([(predicate, arguments)], [index of the atom each one is needed for, or -1 for
    the goal's own]): the goal's positive ground atoms, then what every adder of a needed
    atom requires, breadth first."""
    atoms = list(dict.fromkeys(_ground_atoms(goal, {})))
    parent = [-1] * len(atoms)
    index = {a: i for i, a in enumerate(atoms)}
    i = 0
    while i < len(atoms):
        common = None
        for a in actions:
            for e in a.effects:
                env = _match(e, atoms[i])
                if env is not None:   # (a forall effect too: its instance that adds the atom has these bindings)
                    pre = set(_ground_atoms(a.pre, env)) | set(_ground_atoms(e.cond, env))
                    common = pre if common is None else common & pre
        for f in sorted(common or ()):
            if f not in index:
                index[f] = len(atoms)
                atoms.append(f)
                parent.append(i)
        i += 1
    return atoms, parent


class GoalReach:
    """The masks and the cut for one problem (see the module's docstring)."""

    def __init__(self, goal, actions: list, methods: dict):
        """`actions`: the domain's actions; `methods`: task name -> [Method]."""
        self.atoms, self.parent = needed_atoms(goal, actions)
        self.action_masks = {a.name: sum(1 << i for i, atom in enumerate(self.atoms)
                                         if any(_match(e, atom) is not None for e in a.effects))
                             for a in actions}
        self.methods = methods
        self.by_name = self._by_name()
        self.memo: dict = {}

    def _by_name(self) -> dict:
        """{task name: mask} over the decomposition graph with arguments ignored (a
        fixpoint: it may be recursive): what a task met again inside itself is given."""
        masks = {name: 0 for name in self.methods}
        changed = True
        while changed:
            changed = False
            for name, ways in self.methods.items():
                mask = masks[name]
                for m in ways:
                    for sub, _ in m.subtasks:
                        mask |= self.action_masks.get(sub, masks.get(sub, 0))
                if mask != masks[name]:
                    masks[name], changed = mask, True
        return masks

    def mask(self, name: str, args: tuple) -> int:
        """The goal atoms that the task or action (name, args) may still add; an argument
        None is not known."""
        got = self.action_masks.get(name)
        if got is not None:
            return got
        key = (name, args)
        got = self.memo.get(key)
        if got is not None:
            return got
        self.memo[key] = self.by_name.get(name, 0)   # met again while being worked out (recursion)
        out = 0
        for m in self.methods.get(name, ()):
            env = _bind(m, args)
            if env is None:
                continue
            for sub, terms in m.subtasks:
                out |= self.mask(sub, tuple(env.get(t) if is_var(t) else t for t in terms))
        self.memo[key] = out
        return out

    def unmet(self, facts: set) -> int:
        """The needed atoms that do not hold in `facts`: a goal atom, or an atom required
        to add an unmet one."""
        out = 0
        for i, atom in enumerate(self.atoms):
            p = self.parent[i]
            if atom not in facts and (p < 0 or out >> p & 1):
                out |= 1 << i
        return out


def _bind(m, args: tuple):
    """The method's variables bound by the task's known arguments, or None when they or its
    equality constraints disagree."""
    env = {}
    for term, value in zip(m.task[1], args):
        if value is None:
            continue
        if is_var(term):
            if env.setdefault(term, value) != value:
                return None
        elif term != value:
            return None
    for f in conjuncts(m.pre):
        negated = f[0] == "not"
        g = f[1] if negated else f
        if g[0] != "=":
            continue
        a, b = (env.get(t) if is_var(t) else t for t in g[1:])
        if a is not None and b is not None and (a == b) == negated:
            return None
    return env
