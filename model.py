"""The compiled OO-MDP: immutable data plus generated functions. Solvers see only this.

A state is `bytes` (see compiler/layout.py): the dynamic variables, one byte each at
`Variable.index`, then only the grid cells that differ from the start. Read a state's
cells through `Model.view` (the one accessor that knows the layout). Names and JSON
appear only at the edges: `decode`, `describe`, `action_names`.
"""
from __future__ import annotations

import array
import functools
import sys
from dataclasses import dataclass, field
from typing import Callable, Iterable



@dataclass(frozen=True)
class Variable:
    label: str            # e.g. "agent.x", "inventoryBlock[0].count"
    index: int
    lo: int
    hi: int
    type: str             # "int", "bool" or an enumeration name
    names: tuple = ()     # value names for enumerations


def cell_entries(diff) -> Iterable[int]:
    """The changed-cell entries of a state's tail (`state[grid.base:]`), each the int
    (mutable cell index << 8) | value; stored as 4 little-endian bytes, sorted by index."""
    if sys.byteorder == "little":
        return memoryview(diff).cast("I")
    a = array.array("I", bytes(diff))
    a.byteswap()
    return a


def pack_entry(index: int, value: int) -> bytes:
    return ((index << 8) | value).to_bytes(4, "little")


def fresh_from(live: Callable, s: bytes, seen: dict, out: list) -> int:
    """`Model.search_fresh` over a function listing (action, next state) pairs: for models
    without a generated one, and for states that already fail."""
    nexts = live(s)
    for _, t in nexts:
        if t not in seen:
            seen[t] = s
            out.append(t)
    return len(nexts)


def _expand_fresh(fresh: Callable, is_goal: Callable, states, seen: dict, outs) -> int:
    """`Model.search_layers` for models without generated expanders: one group."""
    out = outs[0]
    k = 0
    for s in states:
        known = len(out)
        k += fresh(s, seen, out)
        if len(out) > known and any(map(is_goal, out[known:])):
            i = next(i for i in range(known, len(out)) if is_goal(out[i]))
            out[i], out[-1] = out[-1], out[i]
            return ~k
    return k


@dataclass(frozen=True)
class Grid:
    width: int
    depth: int
    height: int
    base: int                     # the number of variables: a state's changed cells start here
    layers: tuple                 # mutable y layers
    static: bytes                 # the initial grid [y][z][x] (static layers are read from here)
    value_names: tuple            # dense value index -> name
    default: int

    def mutable_index(self, x: int, y: int, z: int) -> int | None:
        """The mutable cell index of (x, y, z), or None when no action changes that cell."""
        if y not in self.layers or not (0 <= x < self.width and 0 <= z < self.depth):
            return None
        return (self.layers.index(y) * self.depth + z) * self.width + x

    def cell(self, state: bytes, x: int, y: int, z: int) -> int:
        if not (0 <= x < self.width and 0 <= z < self.depth and 0 <= y < self.height):
            return self.default
        start = self.static[(y * self.depth + z) * self.width + x]
        k = self.mutable_index(x, y, z)
        if k is None or len(state) == self.base:
            return start
        for e in cell_entries(state[self.base:]):
            if e >> 8 == k:
                return e & 255
        return start

    def changed(self, state: bytes) -> dict:
        """{(x, y, z): value} of the cells that differ from the start."""
        out, area = {}, self.width * self.depth
        for e in cell_entries(state[self.base:]):
            layer, rest = divmod(e >> 8, area)
            z, x = divmod(rest, self.width)
            out[(x, self.layers[layer], z)] = e & 255
        return out

    def array(self, state: bytes) -> "numpy.ndarray":
        """Every cell's value, shape (height, depth, width), indexed [y, z, x]."""
        import numpy as np
        w = np.frombuffer(self.static, dtype=np.uint8).reshape(self.height, self.depth, self.width).copy()
        for (x, y, z), v in self.changed(state).items():
            w[y, z, x] = v
        return w


class StateView:
    """One state, read: its variables and cells, without knowing the state layout."""

    __slots__ = ("model", "state")

    def __init__(self, model: "Model", state: bytes):
        self.model, self.state = model, state

    def raw(self, i: int) -> int:
        """Variable i's stored offset, value - lo (also `state[model.variables[i].index]`)."""
        return self.state[self.model.variables[i].index]

    def var(self, i: int) -> int:
        """Variable i's value (lo added; an enumeration's index; a bool as 0/1)."""
        v = self.model.variables[i]
        return self.state[v.index] + v.lo

    def cell(self, x: int, y: int, z: int) -> int:
        """The cell's value index (`grid.value_names`); `grid.default` outside the grid."""
        return self.model.grid.cell(self.state, x, y, z)

    def changed(self) -> dict:
        """{(x, y, z): value} of the mutable cells that differ from the start."""
        return self.model.grid.changed(self.state)

    def grid(self) -> "numpy.ndarray":
        """Every cell's value as a uint8 array [y][z][x]."""
        return self.model.grid.array(self.state)


# Analyses of any model that a layer above builds on first use, name -> function(model,
# **options): the heuristics' tables (bcc.heuristics registers them when imported, which
# bcc.solvers does). Base code never imports those layers; they fill this table.
PROVIDED: dict = {}


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
    goal_positions: tuple | None               # agent positions (x, y, z) where the goal may hold
    report: dict = field(default_factory=dict) # compile statistics for `bcc compile`
    source: str = ""                           # the generated Python, for the curious
    display: dict = field(default_factory=dict)  # for drawing states (render.py)
    search_actions: tuple = ()                 # the actions `successors` generates (irrelevant ones pruned)
    lazy: dict = field(default_factory=dict)   # analyses computed on first use: name -> function()
    live_successors: Callable | None = None    # successors for search (see `search_successors`)
    fresh_successors: Callable | None = None   # live fused with a duplicate check (see `search_fresh`)
    memo: dict = field(default_factory=dict, compare=False, repr=False)  # what PROVIDED analyses built for it
    # per searched action, the most it moves the agent along each dynamic axis (compiler/steps.py);
    # None: unknown (each action is taken to move along one axis by one)
    position_steps: tuple | None = None

    def data(self, name: str, **options):
        """A lazily computed analysis of the model, e.g. "pattern_database" (or None): the
        model's own (`lazy`, from its back end), else one that a layer above provides for
        every model (`PROVIDED`: the heuristics' tables)."""
        make = self.lazy.get(name)
        if make is not None:
            return make(**options)
        provide = PROVIDED.get(name)
        return provide(self, **options) if provide else None

    def search_successors(self) -> Callable[[bytes], list]:
        """`successors` as a search wants them: next states equal to the state and failure
        states that are not goals left out (an episode ends when the agent fails; the goal
        wins when both hold). Generated with the model where it can be."""
        if self.live_successors is not None:
            return self.live_successors
        successors, failure, goal = self.successors, self.is_failure, self.is_goal
        return lambda s: [(a, n) for a, n in successors(s) if n != s and (not failure(n) or goal(n))]

    def search_fresh(self) -> Callable[[bytes, dict, list], int]:
        """`fresh(s, seen, out) -> generated`: `search_successors` fused with the duplicate
        check of a search whose first path to a state is a cheapest one (breadth-first,
        blind with equal costs): each next state not yet a key of `seen` is stored there
        with `s` (its parent) and appended to `out`; it returns how many next states there
        were, duplicates included. Generated with the model where it can be."""
        if self.fresh_successors is not None and self.live_successors is not None:
            return self.fresh_successors
        return functools.partial(fresh_from, self.search_successors())

    def search_layers(self) -> tuple:
        """Expanders for a layered search (breadth-first, blind with equal costs): group
        g's `expand(states, seen, outs) -> generated` runs `search_fresh` over states all
        made by one action (group 0: the start, and states made by actions after which
        nothing is skipped), leaving out the actions whose next states are duplicates
        made elsewhere (compiler/inverses.py: that action's inverses, and the earlier
        actions it commutes with). Each new next state goes to `outs[h]`, h the group of the action that
        made it. When a new one is a goal, it returns at once the count's complement (a
        negative number), the goal being the last of its group's list. The states handed
        in must not be goals. Generated with the model where it can be (compiled on first
        use: `lazy["layer_expanders"]`); else one group over `search_fresh`."""
        made = self.data("layer_expanders") if self.live_successors is not None else None
        if made:
            return made
        return (functools.partial(_expand_fresh, self.search_fresh(), self.is_goal),)

    def view(self, state: bytes) -> StateView:
        """The one accessor for reading a state's variables and cells."""
        return StateView(self, state)

    def dense(self, state: bytes) -> bytes:
        """The state in the dense layout: the variables, then every mutable cell (layer, z, x)."""
        g = self.grid
        area = g.width * g.depth
        out = bytearray(state[:g.base])
        for y in g.layers:
            out += g.static[y * area:(y + 1) * area]
        for e in cell_entries(state[g.base:]):
            out[g.base + (e >> 8)] = e & 255
        return bytes(out)

    def compact(self, dense: bytes) -> bytes:
        """The state a dense layout describes (the inverse of `dense`)."""
        import numpy as np
        g = self.grid
        area = g.width * g.depth
        start = np.frombuffer(b"".join(g.static[y * area:(y + 1) * area] for y in g.layers), dtype=np.uint8)
        cells = np.frombuffer(dense, dtype=np.uint8, offset=g.base)
        out = bytearray(dense[:g.base])
        for k in np.flatnonzero(cells != start):
            out += pack_entry(int(k), int(cells[k]))
        return bytes(out)

    def compile_report(self) -> dict:
        """What `bcc compile --json` (and the server's /compile) print: the compile report,
        the action names, and bytes per state measured on the first states reached."""
        report = dict(self.report, action_names=list(self.action_names))
        skips = self.data("layer_skips")
        if skips is not None:
            report["layered_search"] = skips   # what breadth-first and blind search skip (compiler/inverses.py)
        if isinstance(report.get("state_bytes"), dict):
            report["state_bytes"] = {**report["state_bytes"], **self.state_sizes()}
        return report

    def state_sizes(self, limit: int = 2000) -> dict:
        """Bytes per state over the first `limit` states a breadth-first walk reaches:
        {"sampled", "typical" (the mean), "largest"}."""
        from .errors import ModelError
        seen, frontier = {self.initial}, [self.initial]
        try:
            while frontier and len(seen) < limit:
                nxt = []
                for s in frontier:
                    for _, n in self.successors(s):
                        if n not in seen and len(seen) < limit:
                            seen.add(n)
                            nxt.append(n)
                frontier = nxt
        except ModelError:
            pass  # a model error is reported when a solver meets it; the sample ends there
        sizes = [len(s) for s in seen]
        return {"sampled": len(sizes), "typical": round(sum(sizes) / len(sizes), 1), "largest": max(sizes)}

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
