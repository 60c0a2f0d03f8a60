"""Which task does a demonstration carry out? (the latent reward function of a pair)

A task *explains* a demonstration when its last state satisfies the task and no earlier
state does: the person stopped as soon as the job was done. Every such task is a
candidate: single atoms and conjunctions of atoms that hold at the end (the most specific
explanation conjoins everything the demonstration achieved). Side effects make this
ambiguous -- walking to the gold may also enter the blue room -- so each explanation gets
a weight: a prior that prefers fewer conjuncts, times, when there is more than one, a
Boltzmann likelihood of the demonstration's length against the optimal plan length for
that task from the same start, exp(-beta (steps - optimal)), as an IRL-style observer
would (a person heading for "the gold in the red room" walks past nearer gold). The
translation model resolves the rest against the words: EM over the latent task, as in
MacGlashan et al. (2015).
"""
from __future__ import annotations

import itertools
import math
from collections import deque
from dataclasses import dataclass

from .tasks import MAX_CONJUNCTS, Task, TaskSpace

BETA = 1.0
CONJUNCT_PRIOR = 0.3     # prior weight of each conjunct beyond the first
SEARCH_LIMIT = 20000     # states a breadth-first search may store when measuring optimality


@dataclass(frozen=True)
class Explanation:
    task: Task
    weight: float        # unnormalized likelihood of the demonstration under the task
    optimal: int | None  # optimal steps from the demonstration's start (None: not measured)


def explanations(space: TaskSpace, states: list, optimality: bool = True) -> list[Explanation]:
    """The tasks the trajectory `states` explains, most likely first."""
    start = states[0]
    open_atoms = [a for a in space.atoms if not space.holds(a, start)]
    truth = {a: [space.holds(a, s) for s in states] for a in space.atoms}
    at_end = [a for a in open_atoms if truth[a][-1]]
    # where the agent was at the start, left on the way and is again at the end: a conjunct
    # ("and come back"), as in TaskSpace.tasks
    back = [a for a in space.changeable if a not in open_atoms and truth[a][-1] and not all(truth[a])]
    found = []
    for k in range(1, MAX_CONJUNCTS + 1):
        for combo in itertools.combinations(at_end + back, k):
            if all(a in back for a in combo):
                continue
            if not any(all(truth[a][step] for a in combo) for step in range(len(states) - 1)):
                found.append(Task(tuple(sorted(combo, key=lambda a: a.text))))
    steps = len(states) - 1
    out = []
    for task in found:
        best = optimal_steps(space, task, start, steps) if optimality and len(found) > 1 else None
        weight = CONJUNCT_PRIOR ** (len(task) - 1)
        if best is not None:
            weight *= math.exp(-BETA * (steps - best))
        out.append(Explanation(task, weight, best))
    out.sort(key=lambda e: (-e.weight, len(e.task), e.task.text))
    return out


def optimal_steps(space: TaskSpace, task: Task, start: bytes, bound: int) -> int | None:
    """Fewest actions from `start` to a state satisfying `task` (at most `bound`), by
    breadth-first search over every action; None when the search grew too large."""
    model = space.model
    tests = [space.predicates.predicate(a.text) for a in task.atoms]
    n = len(model.action_names)
    seen = {start}
    frontier = deque([(start, 0)])
    while frontier:
        s, d = frontier.popleft()
        if all(t(s) for t in tests):
            return d
        if d >= bound or model.is_failure(s):
            continue
        for i in range(n):
            t = model.apply(i, s)
            if t is not None and t not in seen:
                if len(seen) >= SEARCH_LIMIT:
                    return None
                seen.add(t)
                frontier.append((t, d + 1))
    return bound
