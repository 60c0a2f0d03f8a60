"""A pattern database built from the compiled model, domain-independently.

The pattern is the agent's position variables plus every variable their new values are
computed from (here: x, z and the facing, which `move_forward` reads). The abstract state
space is the product of the pattern variables' ranges; other variables range over their
reachable values (reachability.py), grid cells over their possible values. An abstract
transition exists when an action's preconditions may hold; a backward search by cost
(backward.py) from the abstract states where the goal may hold gives h = the exact
abstract distance, which never overestimates (every real path maps to an abstract path)
and is consistent.
For a block world this is the maze distance with turns, passing mineable blocks at cost 0.
"""
from __future__ import annotations

import array
import itertools
import math
from dataclasses import dataclass

from ..compiler import ir
from ..compiler.abstract import Abstract, maybe_true
from ..compiler.reachability import Analysis
from ..compiler.access import action_access, reads
from ..model import Model
from .backward import backward_distances
from .position import manhattan

MAX_PATTERN_STATES = 1_000_000


@dataclass(frozen=True)
class PatternDatabase:
    indices: tuple      # state byte index of each pattern variable
    sizes: tuple        # range size of each
    table: tuple        # flattened distances (math.inf: the goal is unreachable from there)
    labels: tuple

    def index_of(self, state: bytes) -> int:
        i = 0
        for idx, n in zip(self.indices, self.sizes):
            i = i * n + state[idx]
        return i


def choose_pattern(layout, actions, position_vars: list, an: Analysis) -> list:
    pattern = [v for v in position_vars if v in layout.by_var]
    extra = set()
    for a in actions:
        lets = {loc.name: value for loc, value in a.lets}
        for e, _ in ir.set_vars(a.effects):
            if e.var in pattern:
                extra |= {v for v in reads(e.value, lets, an.vars_of) if isinstance(v, ir.StateVar)}
    candidate = pattern + sorted(extra - set(pattern), key=lambda v: layout.by_var[v].index)
    if _size(layout, candidate) <= MAX_PATTERN_STATES:
        return sorted(candidate, key=lambda v: layout.by_var[v].index)
    return pattern


def _size(layout, variables) -> int:
    n = 1
    for v in variables:
        s = layout.by_var[v]
        n *= s.hi - s.lo + 1
    return n


def build(layout, actions, candidates, goal, reach, n_values, position_vars, initial: bytes) -> PatternDatabase | None:
    an = Analysis(layout, n_values)
    pattern = choose_pattern(layout, [actions[i] for i in candidates], position_vars, an)
    if not pattern:
        return None
    slots = [layout.by_var[v] for v in pattern]
    ranges = [range(s.lo, s.hi + 1) for s in slots]
    sizes = [len(r) for r in ranges]
    movers = [i for i in candidates if any(e.var in pattern for e, _ in ir.set_vars(actions[i].effects))]
    pset = set(pattern)
    # What an action does to a pattern state depends only on the pattern variables it
    # reads (the other sets are fixed): a turn reads the facing alone, so it is evaluated
    # for 4 facings, not for every (x, z, facing).
    read_at = {i: [k for k, v in enumerate(pattern) if v in _action_reads(actions[i], an)] for i in movers}
    outcomes: dict = {}
    goal_reads = [k for k, v in enumerate(pattern) if v in reads(goal, vars_of=an.vars_of)]   # likewise the goal
    goal_at: dict = {}

    def flat(values) -> int:
        i = 0
        for v, s, n in zip(values, slots, sizes):
            i = i * n + (v - s.lo)
        return i

    n_states = math.prod(sizes)
    src, dst, cost = array.array("q"), array.array("q"), array.array("d")   # the abstract transitions
    goals = []
    base = dict(reach.values)
    cell, layer = an.cells(reach.written)
    # Only abstract states reachable from the start's are built: every real state the
    # search can meet maps to one of them (the others keep distance infinity, never read).
    start = tuple(initial[s.index] + s.lo for s in slots)
    seen = {flat(start)}
    queue = [start]
    while queue:
        values = queue.pop()
        sets = dict(base)
        sets.update({var: frozenset({v}) for var, v in zip(pattern, values)})
        here = flat(values)
        key = tuple(values[k] for k in goal_reads)
        if key not in goal_at:
            goal_at[key] = maybe_true(Abstract({}, cell, layer, sets=sets, var_at=an.var_at).eval(goal))
        if goal_at[key]:
            goals.append(here)
        for i in movers:
            a = actions[i]
            key = (i, tuple(values[k] for k in read_at[i]))
            outcome = outcomes.get(key, False)
            if outcome is False:
                ab = an.abstract(a, sets, reach.written)
                outcome = outcomes[key] = _writes(an, ab, a.effects, pattern, pset) if an.applies(a, ab) else None
            if outcome is None:
                continue
            options = _next_values(an, outcome, pattern, values)
            for nxt in itertools.product(*options):
                there = flat(nxt)
                if there != here:
                    src.append(here)
                    dst.append(there)
                    cost.append(a.cost)
                    if there not in seen:
                        seen.add(there)
                        queue.append(nxt)
    dist = backward_distances(n_states, src, dst, cost, goals)
    return PatternDatabase(tuple(s.index for s in slots), tuple(sizes),
                           tuple(int(d) if d != math.inf else math.inf for d in dist),
                           tuple(v.label for v in pattern))


def _action_reads(a, an) -> set:
    return action_access(a, an.vars_of)[0]


def _next_values(an, outcome, pattern, current) -> list:
    """Per pattern variable, the values it may have after the action (an over-approximation)."""
    options, always = outcome
    out = []
    for var, cur in zip(pattern, current):
        vals = options[var] if var in always else options[var] | {cur}
        slot = an.L.by_var[var]
        out.append(sorted(v for v in vals if slot.lo <= v <= slot.hi))
    return out


def _writes(an, ab, effects, pattern, pset) -> tuple:
    """({pattern variable: values the action may write}, the variables it always writes)."""
    options = {v: set() for v in pattern}
    always = set()

    def walk(effs, top):
        for e in effs:
            if isinstance(e, ir.When):
                c = ab.eval(e.cond)
                if maybe_true(c):
                    walk(e.then, False)
                if c is None or False in c:
                    walk(e.orelse, False)
            elif isinstance(e, ir.SetVar) and e.var in pset:
                v = ab.eval(e.value)
                options[e.var] |= an.full_range(e.var) if v is None else v
                if top:
                    always.add(e.var)

    walk(effects, True)
    return options, always


def pdb(model: Model, time_limit: float | None = None):
    """The pattern database (built by `build` above): exact distances in an abstraction
    over the agent's position and facing; falls back to manhattan."""
    db = model.data("pattern_database")
    if db is None:
        return manhattan(model)
    table = db.table
    if len(db.indices) == 3:
        (i0, i1, i2), (_, n1, n2) = db.indices, db.sizes  # the common case, without a loop
        return lambda s: table[(s[i0] * n1 + s[i1]) * n2 + s[i2]]
    return lambda s: table[db.index_of(s)]
