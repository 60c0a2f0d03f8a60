"""The values each state byte can take, which bounds the size of the grounded export.

Why: a grounded encoding needs one fact per (byte, value), and its operators are the
leaves of each action's decision tree over those values. The declared ranges are exact
but large (an inventory count has 65 values, and a mined block can land in any of 9
slots), and enumerating the reachable states to keep only the values that occur does not
scale (the tough maze's six stones give millions of states). So, as Fast Downward's
translator does, we compute a *reachability fixpoint over value domains*: start from the
initial value of every byte, ground every action over the current domains (symbolic.py),
add every value an applicable operator writes, and repeat until nothing is added.

A plain relaxed fixpoint (any combination of known values may co-occur) lets a counter
grow without bound: mining "a stone" stays possible forever, so every count reaches 64
and every slot fills. The fixpoint therefore tracks a coarser but still exact-enough
abstraction jointly: an abstract state is (every byte that is neither a grid cell nor the
agent's position, exactly; the *histogram* of grid cell values). An operator applies to
an abstract state when its precondition on the exact bytes matches and the histogram has
the cell values it requires; its effect moves cell values between histogram bins. Mining
a stone then consumes one from the histogram, so the counts stay within the stones that
exist. This over-approximates the reachable states (the position and which cell holds
which value are forgotten), so every reachable state's values are kept: a transition from
a state whose values are all in the domains is one of the grounded leaves, and it writes
values the fixpoint added. The export's reachable graph is therefore the model's.
"""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

DEFAULT_MAX_STATES = 300_000


@dataclass
class Domains:
    values: tuple         # per state byte: the tuple of values kept
    source: str           # how they were found: "fixpoint"
    states: int           # abstract states of the last round
    rounds: int = 0       # grounding rounds until the fixpoint
    leaves: list = field(default_factory=list)  # per action: its leaves over `values` (reused by task.py)


def _cell_bytes(model) -> range:
    g = model.grid
    return range(g.base, g.base + len(g.layers) * g.width * g.depth)


def _guarded(apply, failure):
    def guarded(s):
        return None if failure is not None and failure(s) else apply(s)
    return guarded


def _abstract_ops(leaves, exact, cells, n_values):
    """Group transition leaves by their effect on abstract states.

    Key: (precondition on exact bytes, cell values required, writes of exact bytes,
    histogram change); value: the (byte, value) pairs its leaves write elsewhere."""
    groups: dict = {}
    for action_leaves in leaves:
        for leaf in action_leaves:
            if not isinstance(leaf.result, dict):
                continue
            pre = {i: vs[0] for i, vs in leaf.allowed.items()}
            pre_e = tuple(sorted((i, v) for i, v in pre.items() if i in exact))
            need = tuple(sorted(Counter(v for i, v in pre.items() if i in cells).items()))
            w_e = tuple(sorted((i, v) for i, v in leaf.result.items() if i in exact))
            delta = [0] * n_values
            other = set()
            for i, v in leaf.result.items():
                if i in cells:
                    delta[pre[i]] -= 1
                    delta[v] += 1
                if i not in exact:
                    other.add((i, v))
            groups.setdefault((pre_e, need, w_e, tuple(delta)), set()).update(other)
    return groups


def _abstract_reach(initial, exact_idx, cells, n_values, groups, max_states):
    """Abstract states reachable from `initial`; the values written; None past max_states."""
    start = (tuple(initial[i] for i in exact_idx), tuple(Counter(initial[i] for i in cells).get(v, 0)
                                                         for v in range(n_values)))
    pos = {i: k for k, i in enumerate(exact_idx)}
    ops = [(tuple((pos[i], v) for i, v in pre_e), need, tuple((pos[i], v) for i, v in w_e), delta, other)
           for (pre_e, need, w_e, delta), other in groups.items()]
    seen = {start}
    stack = [start]
    written: set = set()
    fired = [False] * len(ops)
    while stack:
        ex, hist = stack.pop()
        for k, (pre_e, need, w_e, delta, other) in enumerate(ops):
            if any(ex[p] != v for p, v in pre_e) or any(hist[v] < c for v, c in need):
                continue
            if not fired[k]:
                fired[k] = True
                written |= other
            if w_e:
                e2 = list(ex)
                for p, v in w_e:
                    e2[p] = v
                e2 = tuple(e2)
            else:
                e2 = ex
            h2 = tuple(h + d for h, d in zip(hist, delta)) if any(delta) else hist
            nxt = (e2, h2)
            if nxt not in seen:
                if len(seen) >= max_states:
                    return None
                seen.add(nxt)
                stack.append(nxt)
    return seen, written


def _reachable_positions(domains: tuple, leaves: list, position: list, initial: bytes) -> tuple:
    """The domains and leaves cut down to the positions the agent can reach: a flood over
    the position bytes alone, from the start, through every leaf that writes one (its
    other conditions assumed to hold, so every reachable position is kept). Leaves that
    pin a position byte to a value no reachable position has never apply."""
    if not position:
        return domains, leaves
    moves = []   # ({k: allowed values} of the position bytes a leaf tests, {k: written value})
    for action_leaves in leaves:
        for leaf in action_leaves:
            if isinstance(leaf.result, dict) and any(i in leaf.result for i in position):
                moves.append(({k: leaf.allowed[i] for k, i in enumerate(position) if i in leaf.allowed},
                              {k: leaf.result[i] for k, i in enumerate(position) if i in leaf.result}))
    by_place: dict = {}   # a leaf pinning every position byte, under its one position
    anywhere = []
    for pre, writes in moves:
        if len(pre) == len(position) and all(len(vs) == 1 for vs in pre.values()):
            by_place.setdefault(tuple(pre[k][0] for k in range(len(position))), []).append(writes)
        else:
            anywhere.append((pre, writes))
    start = tuple(initial[i] for i in position)
    seen, stack = {start}, [start]
    while stack:
        here = stack.pop()
        nexts = list(by_place.get(here, ()))
        nexts += [w for pre, w in anywhere if all(here[k] in vs for k, vs in pre.items())]
        for writes in nexts:
            there = tuple(writes.get(k, v) for k, v in enumerate(here))
            if there not in seen:
                seen.add(there)
                stack.append(there)
    kept = {i: {p[k] for p in seen} for k, i in enumerate(position)}
    domains = tuple(tuple(v for v in d if v in kept[i]) if i in kept else d for i, d in enumerate(domains))
    leaves = [[leaf for leaf in action_leaves
               if all(any(v in kept[i] for v in leaf.allowed[i]) for i in position if i in leaf.allowed)]
              for action_leaves in leaves]
    return domains, leaves


def domains_for(model, max_states: int = DEFAULT_MAX_STATES) -> Domains:
    """The fixpoint domains (see the module docstring); BccError past `max_states` abstract states."""
    from ..errors import BccError
    from .symbolic import explore, symbolic_functions
    fns = symbolic_functions(model)
    initial = model.dense(model.initial)   # the symbolic functions read the dense layout
    n = len(initial)
    cells = set(_cell_bytes(model))
    position = {p[0] for p in model.position if p is not None}
    exact_idx = tuple(i for i in range(n) if i not in cells and i not in position)
    exact = set(exact_idx)
    n_values = len(model.grid.value_names)
    dom = [{v} for v in initial]
    # The agent's position starts with its whole declared range: grown from the start, it
    # gains one value per round (one move), and every round re-grounds the actions over
    # the larger domains -- rounds times leaves, 41 s on a 21x21 maze. The positions the
    # agent can reach are cut back out of the final leaves (`_reachable_positions`).
    for v in model.variables:
        if v.index in position:
            dom[v.index] = set(range(v.hi - v.lo + 1))
    # Chaotic iteration: an action whose grounding is slow (destroy, place: they read the
    # inventory) is re-grounded only when the cheap ones (moves, turns) add nothing more.
    # Leaves grounded over older domains may lack cases (new values) or test less (a byte
    # with one value then is not tested), so they can only delay or add values; the loop
    # ends after a round that grounds every action over the current domains and adds
    # nothing: a fixpoint of exact leaves, whose leaves task.py turns into operators.
    n_actions = len(fns["apply"])
    leaves, grounded_over, cost = [[]] * n_actions, [None] * n_actions, [0] * n_actions
    rounds, full = 0, True
    while True:
        rounds += 1
        frozen = tuple(tuple(sorted(d)) for d in dom)
        slow = (sorted(cost)[n_actions // 2] if cost else 0) * 4 + 50  # in leaves, so the rounds are deterministic
        for a, apply in enumerate(fns["apply"]):
            if grounded_over[a] != frozen and (full or cost[a] <= slow):
                leaves[a] = list(explore(_guarded(apply, fns["failure"]), frozen))
                cost[a], grounded_over[a] = len(leaves[a]), frozen
        groups = _abstract_ops(leaves, exact, cells, n_values)
        found = _abstract_reach(initial, exact_idx, sorted(cells), n_values, groups, max_states)
        if found is None:
            raise BccError(f"{model.name}: more than {max_states:,} abstract states (inventory and counts of "
                           "cell values) are reachable; the grounded PDDL export explores them to bound each "
                           "variable's values (raise the limit with --max-states)", model.path)
        seen, written = found
        changed = False
        for ex, _ in seen:
            for i, v in zip(exact_idx, ex):
                if v not in dom[i]:
                    dom[i].add(v)
                    changed = True
        for i, v in written:
            if v not in dom[i]:
                dom[i].add(v)
                changed = True
        if not changed:
            if all(g == frozen for g in grounded_over):
                frozen, leaves = _reachable_positions(frozen, leaves, sorted(position), initial)
                return Domains(frozen, "fixpoint", len(seen), rounds, leaves)
            full = True
        else:
            full = False
