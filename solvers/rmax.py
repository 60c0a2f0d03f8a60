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

MAX_IMAGINED = 200_000


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


class Local:
    """Effects relative to the agent, keyed by its surroundings (see the module docstring)."""

    def __init__(self, model: Model, m: int = 1, radius: int = 1):
        self.model, self.m = model, m
        g = model.grid
        self.pos = [p[0] if p is not None else None for p in model.position]
        pos_idx = {i for i in self.pos if i is not None}
        self.attrs = [v.index for v in model.variables if v.index not in pos_idx]
        self.n_vars = len(model.variables)
        self.offsets = [(dx, dy, dz) for dy in (-1, 0, 1) for dz in range(-radius, radius + 1)
                        for dx in range(-radius, radius + 1)]
        self.area = g.width * g.depth
        self.rules = {}                # (action, attributes) -> {effect: condition on the surroundings}
        self.bad = set()               # (action, attributes) whose effects the surroundings cannot tell apart
        self.cache = {}                # state -> its surroundings
        self.fallback = Tabular(model, m)

    def key(self, s, a):
        around = self.cache.get(s)
        if around is None:
            x, y, z = self.model.agent_position(s)
            cell = self.model.grid.cell
            around = (bytes(s[i] for i in self.attrs),
                      bytes(cell(s, x + dx, y + dy, z + dz) for dx, dy, dz in self.offsets))
            self.cache[s] = around
        return (a,) + around

    def features(self, s, a):
        """(action and the agent's other attributes, the cells around it)."""
        k = self.key(s, a)
        return k[:2], k[2]

    def effect(self, s, n):
        deltas = tuple(n[i] - s[i] for i in range(self.n_vars))
        x, y, z = self.model.agent_position(s)
        g = self.model.grid
        cells = []
        for i in range(g.base, len(s)):
            if s[i] != n[i]:
                layer, rest = divmod(i - g.base, self.area)
                cz, cx = divmod(rest, g.width)
                cells.append((cx - x, g.layers[layer] - y, cz - z, n[i]))
        return deltas, tuple(cells)

    def apply_effect(self, s, eff):
        deltas, cells = eff
        n = bytearray(s)
        for i, d in enumerate(deltas):
            v = s[i] + d
            if not 0 <= v < 256:
                return None
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

    def observe(self, s, a, n):
        """Each distinct effect keeps the conjunction of surroundings seen with it every
        time (DOORMax-style intersection: the most general condition consistent so far)."""
        self.fallback.observe(s, a, n)
        head, around = self.features(s, a)
        eff = self.effect(s, n)
        if head in self.bad:
            return
        rules = self.rules.setdefault(head, {})
        cond = rules.get(eff)
        rules[eff] = frozenset(enumerate(around)) if cond is None else cond & frozenset(enumerate(around))
        # Two effects whose conditions both hold here: the features cannot tell them apart.
        here = set(enumerate(around))
        if sum(1 for c in rules.values() if c <= here) > 1:
            self.bad.add(head)

    def predict(self, s, a):
        head, around = self.features(s, a)
        rules = self.rules.get(head)
        if head in self.bad or not rules:
            return self.fallback.predict(s, a)
        here = set(enumerate(around))
        matching = [eff for eff, cond in rules.items() if cond <= here]
        if len(matching) != 1:
            return self.fallback.predict(s, a)
        return self.apply_effect(s, matching[0]) or self.fallback.predict(s, a)


LEARNERS = {"tabular": Tabular, "oo": Local}


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

    for _ in range(10_000):
        change = 0.0
        for s in order:
            best = max(q(s, k) for k in range(len(actions)))
            change = max(change, abs(best - value[s]))
            value[s] = best
        if change < delta:
            break
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
            a = actions[rng.choice([k for k, v in enumerate(values) if v >= best - 1e-9])]
            predicted = know.predict(s, a)
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
            if predicted != n:  # new knowledge, or a wrong prediction: plan again
                q = _plan_values(model, know, s, actions, gamma, delta, dead_value)
        history.append({"episode": episode + 1, "steps": len(plan), "return": ret, "success": kind == "goal"})
        last_plan = plan if kind == "goal" else []
    converged = None
    if optimal_cost is not None:
        for i in range(len(history)):
            if all(h["success"] and h["steps"] == optimal_cost for h in history[i:]):
                converged = i + 1
                break
    solved = bool(history) and history[-1]["success"]
    result = Result("rmax", solved, "solved" if solved else "no_solution",
                    plan=[model.action_names[a] for a in last_plan], cost=len(last_plan) if solved else None,
                    expanded=steps_total, generated=steps_total,
                    message="" if solved else "the last episode did not reach the goal")
    result.episodes, result.converged_episode = history, converged
    result.heuristic = f"learner={learner}"
    return meter.finish(result)
