"""The compiled OO-MDP: immutable data plus generated functions. Solvers see only this.

A state is `bytes` (see compiler/layout.py for the layout). Names and JSON appear only
at the edges: `decode`, `describe`, `action_names`.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import numpy as np


@dataclass(frozen=True)
class Variable:
    label: str            # e.g. "agent.x", "inventoryBlock[0].count"
    index: int
    lo: int
    hi: int
    type: str             # "int", "bool" or an enumeration name
    names: tuple = ()     # value names for enumerations


@dataclass(frozen=True)
class Grid:
    width: int
    depth: int
    height: int
    base: int                     # index of the first mutable cell in a state
    layers: tuple                 # mutable y layers
    static: bytes                 # the initial grid [y][z][x] (static layers are read from here)
    value_names: tuple            # dense value index -> name
    default: int

    def cell(self, state: bytes, x: int, y: int, z: int) -> int:
        if not (0 <= x < self.width and 0 <= z < self.depth and 0 <= y < self.height):
            return self.default
        area = self.width * self.depth
        if y in self.layers:
            return state[self.base + self.layers.index(y) * area + z * self.width + x]
        return self.static[y * area + z * self.width + x]


@dataclass(frozen=True)
class Model:
    name: str
    path: str
    goal_text: str
    action_names: tuple
    action_costs: tuple
    initial: bytes
    successors: Callable[[bytes], list]        # s -> [(action index, next state)]
    apply_fns: tuple                           # per action: s -> next state or None
    why_fns: tuple                             # per action: s -> index of the failing precondition or None
    pre_texts: tuple                           # per action: source text of each precondition
    is_goal: Callable[[bytes], bool]
    is_failure: Callable[[bytes], bool]
    variables: tuple
    grid: Grid
    position: tuple                            # agent position per axis: (state index, lo) or None if static
    position_static: tuple                     # the static axes' values (None for dynamic ones)
    goal_positions: np.ndarray | None          # agent positions where the goal may hold, shape (k, 3)
    report: dict = field(default_factory=dict) # compile statistics for `bcc compile`
    source: str = ""                           # the generated Python, for the curious
    display: dict = field(default_factory=dict)  # for drawing states (render.py)
    search_actions: tuple = ()                 # the actions `successors` generates (irrelevant ones pruned)
    lazy: dict = field(default_factory=dict)   # analyses computed on first use: name -> function()

    def data(self, name: str, **options):
        """A lazily computed analysis of the model, e.g. "pattern_database" (or None)."""
        make = self.lazy.get(name)
        return make(**options) if make else None

    def apply(self, action: int, state: bytes) -> bytes | None:
        return self.apply_fns[action](state)

    def why_not(self, action: int, state: bytes) -> str | None:
        """The text of the first precondition of `action` that fails in `state`, or None."""
        k = self.why_fns[action](state)
        return None if k is None else self.pre_texts[action][k]

    def action_index(self, name: str) -> int:
        return self.action_names.index(name)

    def is_terminal(self, state: bytes) -> bool:
        return self.is_goal(state) or self.is_failure(state)

    def step(self, state: bytes, action: int) -> tuple[bytes, int, str | None]:
        """The world as an RL agent meets it (spec section 3), in the shape of Gymnasium's
        functional `transition`: (next state, reward, outcome). An action whose
        preconditions fail is a no-op that still costs its step; the reward is minus the
        action's cost; the outcome is "goal", "dead" (a failure state) or None. The
        learning solvers and the Gym env all step through here."""
        nxt = self.apply_fns[action](state)
        if nxt is None:
            nxt = state
        outcome = "goal" if self.is_goal(nxt) else ("dead" if self.is_failure(nxt) else None)
        return nxt, -self.action_costs[action], outcome

    def agent_position(self, state: bytes) -> tuple:
        return tuple(state[p[0]] + p[1] if p is not None else v for p, v in zip(self.position, self.position_static))

    def column(self, state: bytes, x: int, z: int) -> tuple:
        """The cell values of column (x, z) from y = 0 up, without trailing empty cells."""
        col = [self.grid.cell(state, x, y, z) for y in range(self.grid.height)]
        while col and col[-1] == self.grid.default:
            col.pop()
        return tuple(col)

    def decode(self, state: bytes) -> dict:
        """Every dynamic variable by label, enumeration values by name."""
        out = {}
        for v in self.variables:
            raw = state[v.index] + v.lo
            out[v.label] = v.names[raw] if v.names else (bool(raw) if v.type == "bool" else raw)
        return out
