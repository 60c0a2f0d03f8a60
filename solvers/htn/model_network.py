"""A compiled dungeon's task network as the search (search.py) plans it: its methods'
generated functions (compiler/hierarchy.py) and its actions' `apply` functions, over
the model's own compact states.

Why a stack of states: a model's state is immutable bytes, so "changing it in place" is
pushing the next one, and undoing to a mark is dropping what was pushed since; the
hash of bytes is computed once per state and kept by Python.
"""
from __future__ import annotations

import math

from .estimate import method_cost, task_costs


class StateStack:
    """The states along the current path (the search's `state`)."""

    __slots__ = ("states",)

    def __init__(self, initial: bytes):
        self.states = [initial]

    @property
    def current(self) -> bytes:
        return self.states[-1]

    @property
    def hash(self) -> int:
        return hash(self.states[-1])

    def mark(self) -> int:
        return len(self.states)

    def undo(self, mark: int) -> None:
        del self.states[mark:]


class _Shape:
    """A method as the estimate reads it: its task's name and its subtasks' names."""

    __slots__ = ("task", "subtasks")

    def __init__(self, task: str, subtasks: tuple):
        self.task, self.subtasks = (task,), subtasks


class ModelNetwork:
    """What the search asks of a compiled dungeon with a task network."""

    def __init__(self, model, hierarchy):
        self.model, self.hierarchy = model, hierarchy
        self.actions = frozenset(range(len(model.action_names)))
        self.apply_fns, self.is_goal, self.is_failure = model.apply_fns, model.is_goal, model.is_failure
        self.derive = hierarchy.derive or (lambda s, t: None)
        shapes = [_Shape(v.task, v.shape) for vs in hierarchy.variants.values() for v in vs]
        costs = task_costs(shapes, self.actions)
        self.methods: dict = {}
        for task, variants in hierarchy.variants.items():
            for v in variants:
                est = method_cost(_Shape(v.task, v.shape), costs, self.actions)
                if est < math.inf:   # else it can never be reduced to actions
                    self.methods.setdefault(task, []).append((est, v, v.objects, v.values, v.fn))
        root = hierarchy.root
        self.root = [(0, root, (), (), root.fn)]
        self.goal_atoms = []   # a dungeon's goal is a state condition: goal_reach.py cuts nothing (and asks nothing more)

    def expansions(self, name, args: tuple, state: StateStack) -> list:
        """(estimate, method, ground subtasks) for every way to decompose the task here,
        the least estimate first (ties in the file's order); name None: the dungeon's network."""
        out = []
        s = state.current
        for est, variant, objects, values, fn in self.methods.get(name, ()) if name is not None else self.root:
            if objects and any(args[i] != obj for i, obj in objects):
                continue
            given = args if len(values) == len(args) else tuple(args[i] for i in values)
            for subtasks in fn(s, *given):
                out.append((est, variant, subtasks))
        if len(out) > 1:   # the same subtasks by the same method (two bindings alike) are one choice
            seen, unique = set(), []
            for alt in out:
                key = (alt[1].method, alt[2])
                if key not in seen:
                    seen.add(key)
                    unique.append(alt)
            out = sorted(unique, key=lambda alt: alt[0])
        return out

    def apply(self, name: int, args: tuple, state: StateStack) -> bool:
        """Apply the action if its preconditions hold and it does not end the episode in
        failure (as every search of bcc leaves failure states out, unless they are goals)."""
        s = state.current
        nxt = self.apply_fns[name](s)
        if nxt is None or self.is_failure(nxt) and not self.is_goal(nxt):
            return False
        self.derive(s, nxt)
        state.states.append(nxt)
        return True

    def goal_holds(self, state: StateStack) -> bool:
        return self.is_goal(state.current)

    def action_text(self, name: int, args: tuple) -> str:
        return self.model.action_names[name]

    def task_text(self, name: str, args: tuple) -> str:
        return self.hierarchy.task_text(name, args)
