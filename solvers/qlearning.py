"""Tabular Q-learning: a model-free reinforcement-learning baseline.

The compiled model is used only as a simulator, the way an RL agent meets the world
(spec section 3, RL semantics): in every state all actions are offered, an inapplicable
one is a no-op that still costs a step, the reward is minus the action's cost (-1), and
an episode ends at the goal, at death, or after `max_steps` steps. Unlike the planners,
the learner never enumerates successors; unlike R-max, it learns no model of the world,
only Q-values, kept in a dict keyed by (state bytes, action index).

- Exploration: epsilon-greedy with random tie-breaking. Unvisited pairs start at
  `q_init` (default 0: optimistic, the best return possible with -1 per step), so even
  a small epsilon explores systematically.
- Update: Q(s, a) += alpha (r + gamma max_a' Q(s', a') - Q(s, a)), with no bootstrap
  from the goal. Dying is terminal and valued like never reaching the goal
  (-1 / (1 - gamma)), otherwise an early death would look better than a long walk.
  An episode cut at `max_steps` still bootstraps (the time limit is not part of the
  world).
- The answer is a final greedy rollout (ties broken by the lowest action index) from
  the initial state: solved, plan and cost come from it. `expanded` (and `generated`)
  count the environment steps taken while learning; `stored` the distinct states seen.
- `result.episodes` has one record per episode: {"episode", "steps", "return",
  "success", "greedy_steps"}, where greedy_steps is the length of the greedy plan after
  that episode's updates (None if the greedy policy does not reach the goal).
  `result.converged_episode` is the first episode from which the greedy plan reaches the
  goal at the optimal cost (`optimal_cost` if given, else the final plan's cost) in
  every later episode too; None if it never does.

Q-learning is not complete: a result that is not solved says nothing about whether a
plan exists (status "no_solution" with a message saying so; more episodes may help).
"""
from __future__ import annotations

import random

from ..model import Model
from .base import Budget, Meter, Result, without_actions
from .options import Option, check_arguments, declare

CHECK_STEPS = 1024   # environment steps between budget checks


def greedy_rollout(model: Model, q: dict, max_steps: int, q_init: float = 0.0) -> tuple[list[int], bool]:
    """Follow argmax_a Q(s, a) (lowest index on ties) from the initial state: (actions, reached goal).
    Stops at the goal, at death, at `max_steps`, or when a state repeats (the greedy
    policy is deterministic, so a repeat is a loop that never ends)."""
    n_actions = len(model.action_names)
    s, plan, seen = model.initial, [], {model.initial}
    if model.is_goal(s):
        return [], True
    for _ in range(max_steps):
        a = max(range(n_actions), key=lambda i: (q.get((s, i), q_init), -i))
        s, _, kind = model.step(s, a)
        plan.append(a)
        if kind is not None:
            return plan, kind == "goal"
        if s in seen:
            return plan, False
        seen.add(s)
    return plan, False


@declare(
    Option("episodes", int, 200, "episodes to learn for", low=1),
    Option("seed", int, 0, "random seed"),
    Option("gamma", float, 0.99, "discount", low=0, high=1),
    Option("alpha", float, 0.5, "learning rate", low=0, high=1, low_open=True),
    Option("epsilon", float, 0.1, "exploration rate (epsilon-greedy)", low=0, high=1),
    Option("max_steps", int, 200, "steps before an episode is cut", low=1),
    Option("q_init", float, 0.0, "the value of a (state, action) never tried (0: optimistic)", internal=True),
    Option("optimal_cost", int, None, "A*'s cost: converged_episode is the first episode from which the greedy "
           "plan is this long", low=0, internal=True),
)
def solve(model: Model, budget: Budget, progress=None, episodes: int = 200, seed: int = 0, alpha: float = 0.5,
          gamma: float = 0.99, epsilon: float = 0.1, max_steps: int = 200, q_init: float = 0.0,
          optimal_cost: int | None = None, **options) -> Result:
    check_arguments(solve, locals())
    meter = Meter(budget, progress, "qlearning")
    rng = random.Random(seed)
    n_actions = len(model.action_names)
    actions = range(n_actions)
    if not n_actions:
        return without_actions(model, meter, "qlearning",
                               heuristic=f"alpha={alpha} gamma={gamma} epsilon={epsilon} episodes={episodes}")
    dead_value = -1.0 / (1.0 - gamma) if gamma < 1 else -float(max_steps)
    q: dict = {}
    seen = {model.initial}
    history: list[dict] = []
    steps_total = 0
    greedy_costs: list[int | None] = []

    def values(s):
        return [q.get((s, a), q_init) for a in actions]

    for episode in range(episodes):
        s, ret, kind, steps = model.initial, 0.0, None, 0
        if model.is_goal(s):
            kind = "goal"
        while kind is None and steps < max_steps:
            if rng.random() < epsilon:
                a = rng.randrange(n_actions)
            else:
                vs = values(s)
                best = max(vs)
                a = rng.choice([i for i, v in enumerate(vs) if v >= best - 1e-12])
            n, r, kind = model.step(s, a)
            if kind == "goal":
                target = r
            elif kind == "dead":
                target = r + gamma * dead_value
            else:
                target = r + gamma * max(values(n))
            old = q.get((s, a), q_init)
            q[(s, a)] = old + alpha * (target - old)
            seen.add(n)
            ret += r
            steps += 1
            steps_total += 1
            s = n
            if steps_total % CHECK_STEPS == 0:
                stopped = meter.stop(steps_total, steps_total, len(seen), episodes=history)
                if stopped:
                    return stopped
        plan, ok = greedy_rollout(model, q, max_steps, q_init)
        greedy_costs.append(sum(model.action_costs[a] for a in plan) if ok else None)
        history.append({"episode": episode + 1, "steps": steps, "return": ret, "success": kind == "goal",
                        "greedy_steps": len(plan) if ok else None})

    plan, ok = greedy_rollout(model, q, max_steps, q_init)
    cost = sum(model.action_costs[a] for a in plan) if ok else None
    reference = optimal_cost if optimal_cost is not None else cost
    converged = None
    if reference is not None:
        for i in range(len(greedy_costs) - 1, -1, -1):
            if greedy_costs[i] != reference:
                break
            converged = i + 1
    message = "" if ok else (f"after {episodes} episode(s) the greedy policy does not reach the goal; Q-learning is "
                             f"not complete, so a plan may still exist (try more --episodes)")
    result = Result(solver="qlearning", solved=ok, status="solved" if ok else "no_solution",
                    plan=[model.action_names[a] for a in plan] if ok else [], cost=cost,
                    expanded=steps_total, generated=steps_total, stored=len(seen), message=message,
                    heuristic=f"alpha={alpha} gamma={gamma} epsilon={epsilon} episodes={episodes}")
    result.episodes, result.converged_episode = history, converged
    return meter.finish(result)
