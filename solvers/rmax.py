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
iteration (gamma, stop at delta) over the states its model imagines from here, as far as
the nearest goal or unknown (`_plan_values`); it plans again after any surprise.

Learners:
- `tabular`: one entry per (state, action), known after m visits.
- `oo`: DOORMax-style (Diuk et al. 2008): an action's effect relative to the agent is
  learned as a function of conditions over local features, so what it learns in one
  cell applies in every cell where the same conditions hold (see `model_learners.py`).

Dying is terminal and is valued like never reaching the goal (-1 / (1 - gamma)).
"""
from __future__ import annotations

import random

import numpy as np

from ..model import Model
from .base import Budget, Meter, Result, without_actions
from .model_learners import LEARNERS
from .options import Option, check_arguments, declare

MAX_IMAGINED = 20_000


class Kinds(dict):
    """state -> "goal", "dead" or None, by the given terminal function, each computed once
    and remembered across plans."""

    def __init__(self, model: Model):
        super().__init__()
        self.model = model

    def __missing__(self, s):
        k = self[s] = "goal" if self.model.is_goal(s) else ("dead" if self.model.is_failure(s) else None)
        return k


def _plan_values(model: Model, learner, start, actions, gamma, delta, dead_value, kinds, toward_goal=None):
    """Value iteration over the states the learned model imagines from `start`; the given
    terminal function says which imagined states end the episode (`kinds`, a `Kinds`).

    The imagined states are visited breadth first, and only as deep as the nearest
    *target* -- a goal, or a state with an action the model cannot predict (worth R_max).
    With -1 a step and a deterministic learned model, a state farther away than the
    nearest target cannot be on a better path, so value iteration over this ball chooses
    what it would choose over everything the model can imagine, at a fraction of the
    cost; states on the ball's edge are valued as dead ends. Without a target in reach the
    whole imagined graph is kept, up to MAX_IMAGINED states. A graph larger than that
    cannot be valued state by state: then `toward_goal(start)` may give a plan that follows
    the shortest imagined path to the goal (unknowns beyond the cap are not explored);
    without one, the states beyond the cap are optimistic."""
    kind = kinds.__getitem__

    index, order, frontier, succ, edge = {start: 0}, [start], [start], {}, None
    while frontier and len(order) < MAX_IMAGINED:
        nxt, found = [], False
        for s in frontier:
            row = [learner.predict(s, a) for a in actions]
            for n in row:
                if n is None or kind(n) == "goal":
                    found = True
                elif n not in index and kind(n) is None:
                    index[n] = len(order)
                    order.append(n)
                    nxt.append(n)
            succ[s] = row
        frontier = nxt
        if found:
            edge = nxt  # known states beyond the nearest target
            break
    if frontier and edge is None and toward_goal is not None:
        path = toward_goal(start)
        if path:
            return _follow(path)
    # Value iteration, vectorised: per imagined state and action, the immediate value and
    # (for a step that goes on) the index of the next state.
    n_states, n_actions = len(order), len(actions)
    now = np.zeros((n_states, n_actions))            # unknown: optimistic, R_max / (1 - gamma) = 0
    after = np.full((n_states, n_actions), -1)
    for i, s in enumerate(order):
        for k, n in enumerate(succ.get(s, ())):
            if n is None:
                continue
            now[i, k] = -1.0 + (gamma * dead_value if kind(n) == "dead" else 0.0)
            if kind(n) is None:
                after[i, k] = index.get(n, -1)   # beyond the imagined graph: optimistic 0
    for s in edge or ():
        now[index[s], :] = dead_value
    goes_on = after >= 0
    target = np.where(goes_on, after, 0)
    # From below: a state's value is exact once the nearest target's value has reached it,
    # so the sweeps needed are about the depth of the ball, not log(delta) / log(gamma).
    value = np.full(n_states, dead_value)
    for _ in range(100_000):
        qs = now + gamma * np.where(goes_on, value[target], 0.0)
        new = qs.max(axis=1)
        change = float(np.abs(new - value).max()) if n_states else 0.0
        value = new
        if change < delta:
            break
    qs = now + gamma * np.where(goes_on, value[target], 0.0)

    def q(s, k):
        i = index.get(s)
        return 0.0 if i is None or s not in succ else float(qs[i, k])

    q.covers = succ.__contains__
    q.next = lambda s, k: succ[s][k] if s in succ else None
    return q


def _shortest_to_goal(model: Model, learner, start, actions, kinds, h, limit: int = 5 * MAX_IMAGINED):
    """A* over the learned model, known transitions only, from `start` to a goal state:
    [(state, action position, next state)] or None. `h` must not overestimate the steps
    left in the learned model (see `_steps_left`)."""
    import heapq
    from itertools import count
    tie = count()
    g, parent, heap, closed = {start: 0}, {start: None}, [(h(start), 0, next(tie), start)], set()
    while heap and len(closed) < limit:
        _, gs, _, s = heapq.heappop(heap)
        if s in closed:
            continue
        if kinds[s] == "goal":
            path = []
            while parent[s] is not None:
                prev, k = parent[s]
                path.append((prev, k, s))
                s = prev
            return path[::-1]
        closed.add(s)
        for k, a in enumerate(actions):
            n = learner.predict(s, a)
            if n is None or n == s or n in closed:
                continue
            if kinds[n] == "dead" or gs + 1 >= g.get(n, gs + 2):
                continue
            g[n], parent[n] = gs + 1, (s, k)
            heapq.heappush(heap, (gs + 1 + h(n), gs + 1, next(tie), n))
    return None


def _follow(path):
    """A plan that takes the path's actions (value 0) and nothing else (-inf), covering
    only the path's states: any surprise or step off it plans again."""
    step = {s: (k, n) for s, k, n in path}

    def q(s, k):
        return 0.0 if step.get(s, (None,))[0] == k else -float("inf")

    q.covers = step.__contains__
    q.next = lambda s, k: step[s][1] if step.get(s, (None,))[0] == k else None
    return q


def _steps_left(distance, longest_move: int):
    """Steps at least needed to the goal in the learned model: the Manhattan `distance` to
    where the goal may hold (the task is given) over the longest move ever observed (the
    learned model can only repeat observed moves); 0 before any move is seen."""
    if longest_move <= 0:
        return lambda s: 0
    return lambda s: -(-distance(s) // longest_move)


@declare(
    Option("model", str, "tabular", "the model learner", choices=lambda: tuple(LEARNERS), keyword="learner"),
    Option("episodes", int, 10, "episodes to learn for", low=1),
    Option("seed", int, 0, "random seed"),
    Option("gamma", float, 0.99, "discount", low=0, high=1, low_open=True, high_open=True),
    Option("delta", float, 0.01, "value iteration stops when no value changes more", low=0, low_open=True),
    Option("known_after", int, 1, "visits before a (state, action) is known (1: the world is deterministic)",
           low=1, keyword="m"),
    Option("max_steps", int, 1000, "steps before an episode is cut", low=1),
    Option("optimal_cost", int, None, "A*'s cost: converged_episode is the first episode from which all are this "
           "long", low=0, internal=True),
    Option("all_actions", bool, False, "learn over every action, not only those that can matter for the goal",
           internal=True),
)
def solve(model: Model, budget: Budget, progress=None, learner: str = "tabular", episodes: int = 10,
          seed: int = 0, gamma: float = 0.99, delta: float = 0.01, m: int = 1, max_steps: int = 1000,
          optimal_cost: int | None = None, all_actions: bool = False, **options) -> Result:
    check_arguments(solve, locals())
    meter = Meter(budget, progress, "rmax")
    rng = random.Random(seed)
    know = LEARNERS[learner](model, m)
    actions = list(range(len(model.action_names))) if all_actions or not model.search_actions \
        else list(model.search_actions)
    if not actions:
        return without_actions(model, meter, "rmax", heuristic=f"learner={learner}")
    dead_value = -1.0 / (1.0 - gamma)
    kinds = Kinds(model)
    from ..heuristics.position import manhattan
    distance, where, longest = manhattan(model), model.agent_position, [0]

    def toward_goal(start):
        return _shortest_to_goal(model, know, start, actions, kinds, _steps_left(distance, longest[0]))

    def plan_from(s):
        return _plan_values(model, know, s, actions, gamma, delta, dead_value, kinds, toward_goal)

    history, steps_total, last_plan, replanned = [], 0, [], False
    for episode in range(episodes):
        s, plan, ret, kind = model.initial, [], 0.0, None
        q = plan_from(s)
        for _ in range(max_steps):
            values = [q(s, k) for k in range(len(actions))]
            best = max(values)
            k = rng.choice([k for k, v in enumerate(values) if v >= best - 1e-9])
            a, planned = actions[k], q.next(s, k)
            n, reward, outcome = model.step(s, a)
            know.observe(s, a, n)
            longest[0] = max(longest[0], sum(abs(u - v) for u, v in zip(where(s), where(n))))
            plan.append(a)
            ret += reward
            steps_total += 1
            if steps_total % 256 == 0 or replanned:  # planning can be slow: check after it too
                replanned = False
                stopped = meter.stop(steps_total, steps_total, 0, episodes=history)
                if stopped:
                    return stopped
            s, kind = n, outcome
            if kind is not None:
                break
            if planned != n or not q.covers(s):  # a surprise, or beyond what was planned: plan again
                q = plan_from(s)
                replanned = True
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
    result = Result(solver="rmax", solved=solved, status="solved" if solved else "no_solution",
                    plan=[model.action_names[a] for a in last_plan], cost=len(last_plan) if solved else None,
                    expanded=steps_total, generated=steps_total,
                    message="" if solved else "the last episode did not reach the goal")
    result.episodes, result.converged_episode = history, converged
    result.heuristic = f"learner={learner}"
    return meter.finish(result)
