"""R-max: model-based reinforcement learning in a dungeon, with a tabular or an object-
oriented (local, relational) model learner.

The agent is not handed the transition function: it acts in the world (the compiled
model used only as the environment, spec section 3 RL semantics: an inapplicable action is
a no-op that costs a step), records what it sees, and plans on what it has learned. As in
the reference system, the task -- reward (-1 a step) and terminal function (goal, death) -- is given;
the dynamics are learned. By default it acts with the actions the compiler found
relevant to the goal (`model.search_actions`: knowledge of the YAML domain, not of the
dynamics); `all_actions=True` uses all of them.
Unknown state-action pairs are optimistic (R_max = 0, the best possible return with -1
per step), so the agent goes for the nearest unknown or the goal. Planning is value
iteration (gamma, stop at delta) over the states its model can imagine from here.

Learners:
- `tabular`: one entry per (state, action), known after m visits.
- `oo`: in the spirit of DOORMax, an action's effect is learned as a change of the
  agent's attributes plus changes of cells *relative to the agent*; for each effect the
  condition is the conjunction of surrounding cells (within `radius`, three layers) seen
  seen every time it happened, for the same values of the agent's other attributes. What it
  learns in one cell applies wherever the condition holds. Where two effects' conditions
  both hold (the features cannot tell them apart), that case falls back to tabular.

Dying is terminal and is valued like never reaching the goal (-1 / (1 - gamma)).
"""
from __future__ import annotations

import math
import random

from ..model import Model
from .base import Budget, Meter, Result

MAX_IMAGINED = 50_000


class Tabular:
    """(state, action) -> observed outcome, known after m visits."""

    def __init__(self, model: Model, m: int = 1):
        self.m, self.table, self.visits = m, {}, {}

    def observe(self, s, a, outcome):
        self.visits[(s, a)] = self.visits.get((s, a), 0) + 1
        self.table[(s, a)] = outcome

    def predict(self, s, a):
        if self.visits.get((s, a), 0) >= self.m:
            return self.table[(s, a)]
        return None


class ObjectOriented:
    """DOORMax-style learner. An action's *effect* -- the agent's attributes set to new
    values, its position moved by a delta, cells changed relative to it -- is learned as a
    function of *conditions* over local features: the agent's attributes other than its
    position, and the cells next to it (within `radius` in the plane, three layers).
    Nothing is keyed by absolute position, so what is learned in one cell holds in every
    cell with the same surroundings, and (with the same domain) in other dungeons.

    Each effect's condition is a disjunction of terms; a term allows, per feature, the
    values seen with it (an attribute seen with two values stops mattering). A new example
    of an effect widens the first term that can take it without covering any example of
    another effect (DOORMax's failure conditions), else starts a term of its own; an
    example that a term of another effect covered splits that effect's terms again.
    A state is predicted when exactly one effect covers it (or it was seen exactly);
    otherwise it is unknown, hence optimistic. A feature seen with two values stops
    mattering to a term, except that "nothing happened" (a disjunction of many reasons)
    keeps the values it was seen with: a block never met next to the agent, or an item
    never held, is worth trying.
    """

    ANY = None

    def __init__(self, model: Model, m: int = 1, radius: int = 1):
        self.model, self.m = model, m
        g = model.grid
        self.pos = [p[0] if p is not None else None for p in model.position]
        pos_idx = {i for i in self.pos if i is not None}
        self.attrs = [v.index for v in model.variables if v.index not in pos_idx]
        self.pointers = self._pointers(model, pos_idx)
        self.n_attrs = len(self.attrs) + len(self.pointers)
        self.index_features = {self.attrs.index(v) for v, _ in self.pointers}
        self.offsets = [(dx, dy, dz) for dy in (-1, 0, 1) for dz in range(-radius, radius + 1)
                        for dx in range(-radius, radius + 1) if abs(dx) + abs(dz) <= radius]
        self.area = g.width * g.depth
        self.span = {v.index: v.hi - v.lo for v in model.variables}
        self.cache = {}          # state -> its feature tuple
        self.exact = {}          # (action, features) -> effect
        self.examples = {}       # action -> {effect: [feature tuples]}
        self.terms = {}          # (action, effect) -> [term: list of allowed value sets per feature]
        self.general = {}        # (action, effect) -> the same terms with the fewest constraints
        self.noops = set()       # (action, features but index attributes) where nothing happened
        self.predicted = {}      # (action, features) -> effect or None, until knowledge changes
        self.fallback = Tabular(model, m)
        self.wrong = set()       # (state, action) where a generalised prediction failed

    @staticmethod
    def _pointers(model, skip):
        """Integer attributes that index a list of objects (a selected slot), each with the
        attributes of the object it points to: [(index variable, [variable per value])].
        The object pointed to is what matters (the item held), not the number."""
        import re
        lists = {}
        for v in model.variables:
            m = re.fullmatch(r"(.+)\[(\d+)\]\.(\w+)", v.label)
            if m:
                lists.setdefault((m.group(1), m.group(3)), {})[int(m.group(2))] = v.index
        out = []
        for v in model.variables:
            if v.type != "int" or v.index in skip:
                continue
            for members in lists.values():
                if sorted(members) == list(range(v.lo, v.hi + 1)):
                    out.append((v.index, [members[k] for k in range(v.lo, v.hi + 1)]))
        return out

    def features(self, s):
        f = self.cache.get(s)
        if f is None:
            x, y, z = self.model.agent_position(s)
            cell = self.model.grid.cell
            f = (tuple(s[i] for i in self.attrs) + tuple(s[members[s[i]]] for i, members in self.pointers)
                 + tuple(cell(s, x + dx, y + dy, z + dz) for dx, dy, dz in self.offsets))
            self.cache[s] = f
        return f

    def effect(self, s, n):
        """What `n` changed in `s`: attributes set, position moved, cells changed (relative)."""
        sets = tuple((i, n[i]) for i in self.attrs if s[i] != n[i])
        moved = tuple((n[i] - s[i]) if i is not None else 0 for i in self.pos)
        x, y, z = self.model.agent_position(s)
        g = self.model.grid
        cells = []
        for i in range(g.base, len(s)):
            if s[i] != n[i]:
                layer, rest = divmod(i - g.base, self.area)
                cz, cx = divmod(rest, g.width)
                cells.append((cx - x, g.layers[layer] - y, cz - z, n[i]))
        return sets, moved, tuple(cells)

    def apply_effect(self, s, eff):
        sets, moved, cells = eff
        n = bytearray(s)
        for i, v in sets:
            n[i] = v
        for i, d in zip(self.pos, moved):
            if d:
                v = s[i] + d
                if not 0 <= v <= self.span[i]:
                    return None  # off the map: not a state; the caller falls back
                n[i] = v
        if cells:
            g = self.model.grid
            x, y, z = self.model.agent_position(s)
            for dx, dy, dz, v in cells:
                cx, cy, cz = x + dx, y + dy, z + dz
                if cy not in g.layers or not (0 <= cx < g.width and 0 <= cz < g.depth):
                    return None
                n[g.base + g.layers.index(cy) * self.area + cz * g.width + cx] = v
        return bytes(n)

    # -- terms ---------------------------------------------------------------------------
    NOTHING = ((), None, ())

    def _is_noop(self, eff):
        return not eff[0] and not any(eff[1]) and not eff[2]

    def _pointed(self, f):
        """The features with index attributes left out: what a no-op is remembered by."""
        return tuple(v for i, v in enumerate(f) if i not in self.index_features)

    @staticmethod
    def _covers(term, f):
        return all(allowed is None or v in allowed for allowed, v in zip(term, f))

    def _learn_terms(self, a, eff):
        """Greedy cover of the effect's examples by terms that cover no example of another
        effect: a feature that differs between two examples is dropped from their term."""
        mine = self.examples[a][eff]
        others = [f for e, fs in self.examples[a].items() if e != eff for f in fs]
        terms = []
        for f in mine:
            for k, t in enumerate(terms):
                if self._covers(t, f):
                    break
                wider = [allowed if allowed is None or v in allowed else None for allowed, v in zip(t, f)]
                if not any(self._covers(wider, g) for g in others):
                    terms[k] = wider
                    break
            else:
                terms.append([frozenset((v,)) for v in f])
        self.terms[(a, eff)] = terms
        self.general[(a, eff)] = [self._simplest(t, others) for t in terms]

    @staticmethod
    def _simplest(term, others):
        """The fewest of a term's constraints that still rule out every example of the
        other effects (greedy set cover): the most general condition the data allow, so
        that one turn seen facing north is expected wherever the agent faces north. It
        may be too general; a wrong prediction adds the example that corrects it."""
        constraints = [(i, allowed) for i, allowed in enumerate(term) if allowed is not None]
        keep, left = {}, others
        while left and constraints:
            i, allowed = max(constraints, key=lambda c: sum(g[c[0]] not in c[1] for g in left))
            rest = [g for g in left if g[i] in allowed]
            if len(rest) == len(left):
                break  # the features cannot tell these apart
            keep[i], left = allowed, rest
        return [keep.get(i) for i in range(len(term))]

    def observe(self, s, a, n):
        guess = self.predict(s, a)
        if guess is not None and guess != n:  # the features missed something here: remember it exactly
            self.wrong.add((s, a))
        self.fallback.observe(s, a, n)
        f, eff = self.features(s), self.effect(s, n)
        if self.exact.get((a, f)) == eff:
            return
        self.exact[(a, f)] = eff
        if self._is_noop(eff):
            self.noops.add((a, self._pointed(f)))
        by_effect = self.examples.setdefault(a, {})
        by_effect.setdefault(eff, []).append(f)
        for other in by_effect:  # effects whose terms cover this example must be split
            if self._is_noop(other):
                continue
            if other == eff or any(self._covers(t, f) for t in self.general.get((a, other), ())):
                self._learn_terms(a, other)
        self.predicted.clear()

    def _generalised(self, f, a):
        key = (a, f)
        if key in self.predicted:
            return self.predicted[key]
        hits = [eff for eff in self.examples.get(a, ())
                if not self._is_noop(eff) and any(self._covers(t, f) for t in self.general[(a, eff)])]
        out = None
        if len(hits) == 1:
            out = hits[0]
        elif not hits and ((a, self._pointed(f)) in self.noops or self._all_fail(f, a)):
            out = self.NOTHING
        self.predicted[key] = out
        return out

    def _all_fail(self, f, a):
        """DOORMax's failure conditions: every effect `a` is known to have is sure to fail in
        `f` -- for each of its terms, `a` once did something else in a state that agrees with
        `f` on all the features the term constrains (the true condition is among them)."""
        by_effect = self.examples.get(a, {})
        effects = [e for e in by_effect if not self._is_noop(e)]
        if not effects:
            return False  # never seen doing anything: nothing to rule out
        for eff in effects:
            others = [g for e, gs in by_effect.items() if e != eff for g in gs]
            for t in self.terms[(a, eff)]:
                fixed = [(i, f[i]) for i, allowed in enumerate(t) if allowed is not None]
                if not any(all(g[i] == v for i, v in fixed) for g in others):
                    return False
        return True

    def predict(self, s, a):
        if (s, a) in self.wrong:
            return self.fallback.predict(s, a)
        f = self.features(s)
        eff = self.exact.get((a, f))
        if eff is None:
            eff = self._generalised(f, a)
        if eff is None:
            return self.fallback.predict(s, a)
        if eff is self.NOTHING:
            return s
        return self.apply_effect(s, eff) or self.fallback.predict(s, a)


LEARNERS = {"tabular": Tabular, "oo": ObjectOriented}


def _world(model: Model, s: bytes, a: int) -> bytes:
    """The world: RL semantics of spec section 3 (an inapplicable action is a no-op)."""
    n = model.apply(a, s)
    return s if n is None else n


def _plan_values(model: Model, learner, start, actions, gamma, delta, dead_value):
    """Value iteration over the states the learned model imagines from `start`; the given
    terminal function says which imagined states end the episode."""
    states, frontier, succ = {start}, [start], {}
    order = [start]
    is_goal, is_failure = model.is_goal, model.is_failure
    while frontier and len(states) < MAX_IMAGINED:
        nxt = []
        for s in frontier:
            row = []
            for a in actions:
                n = learner.predict(s, a)
                row.append(n)
                if n is not None and n not in states and not is_goal(n) and not is_failure(n):
                    states.add(n)
                    order.append(n)
                    nxt.append(n)
            succ[s] = row
        frontier = nxt
    value = {s: 0.0 for s in order}
    terminal = {}

    def q(s, k):
        n = succ[s][k] if s in succ else None
        if n is None:
            return 0.0  # unknown: optimistic, R_max / (1 - gamma) with R_max = 0
        if n not in terminal:
            terminal[n] = "goal" if is_goal(n) else ("dead" if is_failure(n) else None)
        kind = terminal[n]
        if kind == "goal":
            return -1.0
        if kind == "dead":
            return -1.0 + gamma * dead_value
        return -1.0 + gamma * value.get(n, 0.0)

    backwards = order[::-1]  # values flow back from where the imagined graph ends: fewer sweeps
    for _ in range(10_000):
        change = 0.0
        for s in backwards:
            best = max(q(s, k) for k in range(len(actions)))
            change = max(change, abs(best - value[s]))
            value[s] = best
        if change < delta:
            break
    q.covers = succ.__contains__
    q.next = lambda s, k: succ[s][k] if s in succ else None
    return q


def solve(model: Model, budget: Budget, progress=None, learner: str = "tabular", episodes: int = 10,
          seed: int = 0, gamma: float = 0.99, delta: float = 0.01, m: int = 1, max_steps: int = 1000,
          optimal_cost: int | None = None, all_actions: bool = False, **options) -> Result:
    if learner not in LEARNERS:
        from ..errors import BccError
        raise BccError(f"unknown model learner {learner!r}; available: {', '.join(LEARNERS)}")
    meter = Meter(budget, progress)
    rng = random.Random(seed)
    know = LEARNERS[learner](model, m)
    actions = list(range(len(model.action_names))) if all_actions or not model.search_actions \
        else list(model.search_actions)
    dead_value = -1.0 / (1.0 - gamma)
    history, steps_total, last_plan = [], 0, []
    for episode in range(episodes):
        s, plan, ret, kind = model.initial, [], 0.0, None
        q = _plan_values(model, know, s, actions, gamma, delta, dead_value)
        for _ in range(max_steps):
            values = [q(s, k) for k in range(len(actions))]
            best = max(values)
            k = rng.choice([k for k, v in enumerate(values) if v >= best - 1e-9])
            a, planned = actions[k], q.next(s, k)
            n = _world(model, s, a)
            know.observe(s, a, n)
            plan.append(a)
            ret -= 1
            steps_total += 1
            if steps_total % 256 == 0:
                which = meter.check(steps_total, steps_total, 0)
                if which:
                    from .base import budget_result
                    r = budget_result("rmax", which, meter, steps_total, steps_total, 0)
                    r.episodes = history
                    return r
            s = n
            kind = "goal" if model.is_goal(s) else ("dead" if model.is_failure(s) else None)
            if kind is not None:
                break
            if planned != n or not q.covers(s):  # a surprise, or beyond what was planned: plan again
                q = _plan_values(model, know, s, actions, gamma, delta, dead_value)
        history.append({"episode": episode + 1, "steps": len(plan), "return": ret, "success": kind == "goal"})
        last_plan = plan if kind == "goal" else []
    # converged_episode: the first episode after which every episode's plan has the optimal
    # length -- the number of episodes spent learning (as for Q-learning, whose greedy plan
    # after episode k is the plan of episode k + 1); 0 if even the first was optimal.
    converged = None
    if optimal_cost is not None:
        for i in range(len(history)):
            if all(h["success"] and h["steps"] == optimal_cost for h in history[i:]):
                converged = i
                break
    solved = bool(history) and history[-1]["success"]
    result = Result("rmax", solved, "solved" if solved else "no_solution",
                    plan=[model.action_names[a] for a in last_plan], cost=len(last_plan) if solved else None,
                    expanded=steps_total, generated=steps_total,
                    message="" if solved else "the last episode did not reach the goal")
    result.episodes, result.converged_episode = history, converged
    result.heuristic = f"learner={learner}"
    return meter.finish(result)
