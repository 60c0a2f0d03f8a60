"""The one relaxed task type: facts, operators (preconditions, adds, cost, the action
they relax), a goal, and the reader that turns a state into its facts. Built from a
compiled dungeon (relaxed_view.py) or an imported PDDL task (relaxed_pddl.py), explored
by the relaxed heuristics (relaxed.py)."""
from __future__ import annotations

from dataclasses import dataclass, field


class Reachability:
    """Relaxed reachability over facts from a start: the facts and the operators that a
    relaxed plan can reach, kept up to date as operators are added (the view builds its
    operators lazily, as their context facts become reachable, and prunes the ones that
    can never fire with the same fixpoint). An operator fires once every fact of its
    precondition is reached; its adds are then reached."""

    def __init__(self, init):
        self.reached: set = set()
        self.fired: set = set()      # the names given to `add` of the operators that fired
        self.waiting: dict = {}      # fact -> operators still missing it: [count missing, adds, name]
        self.fresh: list = []
        self._fire(None, tuple(init))

    def add(self, pre, add, name=None) -> None:
        missing = [p for p in pre if p not in self.reached]
        if not missing:
            self._fire(name, add)
            return
        entry = [len(missing), add, name]
        for p in missing:
            self.waiting.setdefault(p, []).append(entry)

    def _fire(self, name, add) -> None:
        stack = [(name, add)]
        while stack:
            name, add = stack.pop()
            if name is not None:
                self.fired.add(name)
            for f in add:
                if f not in self.reached:
                    self.reached.add(f)
                    self.fresh.append(f)
                    for entry in self.waiting.pop(f, ()):
                        entry[0] -= 1
                        if entry[0] == 0:
                            stack.append((entry[2], entry[1]))

    def take(self) -> list:
        """The facts reached since the last call."""
        out, self.fresh = self.fresh, []
        return out


class RelaxedTooBig(Exception):
    """The relaxed view would exceed its limits (contexts, time); heuristics fall back."""


@dataclass
class RelaxedTask:
    """Facts 0..n_facts-1; operator i: pre[i] (facts), add[i] (facts), cost[i], action[i]
    (the grounded action it relaxes, or -1 for an auxiliary zero-cost operator)."""
    n_facts: int
    pre: list
    add: list
    cost: list
    action: list
    goal: tuple                      # facts; None when the goal can never hold
    labels: list                     # a readable name per fact (debugging, tests)
    reader: "StateReader"
    stats: dict = field(default_factory=dict)
    guide: "RelaxedTask | None" = None   # the goal reached by a last action (relaxed_last.py), for hadd/hff
    chained: tuple = ()              # fired facts whose steps cost their action here (Builder.fire_effects)

    def state_facts(self, state) -> list:
        """The facts of a state in the reader's layout (a dense one, for a dungeon)."""
        return self.reader.facts(state)


@dataclass
class StateReader:
    """The one place that reads a state's variable values and cell contents. It reads the
    dense layout of compiler/layout.py (variables, then every mutable-layer cell): a
    model's state, which stores only the changed cells, is read through `model.dense`
    (relaxed.relaxed_of). Plain data, so a built view can be kept in the on-disk cache
    (tables.py)."""

    groups: list        # per group: the state indices of its variables
    bases: list         # per group: its first fact
    strides: list       # per group: each variable's stride in the group's facts
    grid_base: int      # the state index of the first mutable cell
    cell_base: int      # the first cell fact
    n_values: int       # facts per cell
    n_cells: int

    reads_dense = True  # a class attribute (not a field): states go through `model.dense`

    @classmethod
    def of(cls, layout, groups, fact_base, strides, cell_base, n_values) -> "StateReader":
        return cls([[layout.by_var[v].index for v in g] for g in groups], fact_base, strides, layout.grid_base,
                   cell_base, n_values, len(layout.layers) * layout.width * layout.depth)

    def facts(self, state) -> list:
        out = []
        for idxs, base, strides in zip(self.groups, self.bases, self.strides):
            f = base
            for i, st in zip(idxs, strides):
                f += state[i] * st
            out.append(f)
        gb, cb, nv = self.grid_base, self.cell_base, self.n_values
        out.extend(cb + k * nv + state[gb + k] for k in range(self.n_cells))
        return out


