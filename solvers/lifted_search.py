"""Search on a lifted PDDL task (lifted_states.py): successors by joins, a greedy search with novelty.

Why this search: a relaxed-plan heuristic needs the grounding that the task is too big
for. Here the heuristic is read off the action schemas without grounding: the missing
landmarks (lifted_landmarks.py: the goal's conjuncts, the precondition of a goal atom's
only achiever, and what every achiever of a landmark needs), each with the false
conditions of its cheapest achiever, and once, the movers' distance to the nearest
place where work can be done (lifted_distances.py: along domain transition graphs to
where an achiever can act, plus what the last step onto that place needs: a block to
stand on). Moves are counted once, not once per landmark: summed, a step away from a
cluster of five goals cost five, and fetching a block from two cells away looked worse
than any detour. A counter that every achiever of several landmarks steps down ("holds
one T") costs the steps it lacks (lifted_landmarks.supply); while it is short, or a
need is unmet, the way to the nearest place to step it up (break a block of T, pick one
up) that undoes no landmark met, and on from there to an achiever's place, is a way to
work too (lifted_supplies.py): without the way on, fetching the last block looked worse
than staying beside the goal, and putting a block down to take it back looked like
progress. A goal that is any of several values of a counter ("holds 5 or more T", an
`or`) costs the counter's distance to the nearest of them, and its nearest refill is a
place to go too (`_direct`). (The block-building benchmark's plus shape of five blocks: stuck at 13 with
the sum; at 3 with the moves shared, its last block wanting a count spent on a support;
solved with supplies too.)

States wait in two queues, taken from in turn (as LAMA alternates its queues): one by
that estimate first, then by *novelty* (Lipovetzky and Geffner's best-first width
search), the other by novelty first, then the estimate. Novelty: w = 1 when a state
makes true an atom no earlier state with the same number of missing landmarks did, 2
when it makes a new pair of atoms of one object (an agent's x and z), else 3. By the
estimate alone the search sank into plateaus of blocks put anywhere (each new, none
closer): the plus shape gathered from the world (Collect_Build_Shape) and the cross
(Build_Cross) were not solved in 60 s; by turns in 1,854 and 2,185 expansions. Every
state is queued, so the search is complete; it is not optimal.

Novelty is judged on the atoms an action makes true (not all of a state's atoms: a
state can hold tens of thousands of atoms, and its parent's were judged already).
"""
from __future__ import annotations

import heapq
import itertools

from .base import Budget, Meter, Result, budget_result
from ..heuristics.lifted_estimate import LandmarkEstimate
from ..pddl_io.lifted_states import LiftedTask
from ..pddl_io.lifted_successors import Successors  # noqa: F401 - where tests and tools take it from
from ..pddl_io.lifted_types import Domain, Problem


WIDTH = 2     # novelty judged on single atoms (1) or also on pairs of atoms of one object (2)


def solve(dom: Domain, prob: Problem, budget: Budget, progress=None, optimal: bool = False,
          solver: str = "gbfs") -> Result:
    """BFWS (see the module docstring), or with `optimal` a search by cost (uniform cost,
    first in first out among equals: breadth-first when every action costs 1), whose
    first plan is a cheapest one. Both use the symmetry rule, which keeps costs."""
    task = LiftedTask(dom, prob)
    estimate = LandmarkEstimate(task, prob, optimal)
    succ, h, count = estimate.succ, estimate.h, estimate.count
    heuristic = "blind" if optimal else "bfws-landmarks"
    goal_test = succ.tests[0]
    meter = Meter(budget, progress)
    start = frozenset()
    h0 = h(start)
    seen: set = set()             # (landmark count, atom) pairs some state made true
    c0 = count(start)
    for i in task.true_atoms(start):
        seen.add((c0, i))
    novelty = _novelty(task, seen)
    parents = {start: None}
    best_g = {start: 0}           # (optimal) the cheapest known cost of each state
    tie = itertools.count()
    queue = [(0 if optimal else h0, 1, next(tie), start)]
    expanded = generated = 0
    mask = meter.mask

    def finish(**kw) -> Result:
        return meter.finish(Result(solver=solver, stored=len(parents), heuristic=heuristic,
                                   initial_h=h0, expanded=expanded, generated=generated, **kw))

    closed: set = set()
    other: list = [] if optimal else [(1, h0, next(tie), start)]      # the same states by (novelty, h)
    turn = 0
    while queue or other:
        turn += 1
        if other and (not queue or turn & 1):
            w, key, _, s = heapq.heappop(other)
        else:
            if not queue:
                break
            key, _, _, s = heapq.heappop(queue)
        if s in closed or optimal and key > best_g[s]:
            continue
        closed.add(s)
        succ.begin(s)
        if goal_test(s):
            plan, cost = _plan_to(s, parents)
            return finish(solved=True, status="solved", plan=plan, cost=cost)
        expanded += 1
        if not expanded & mask or budget.max_states is not None and len(parents) > budget.max_states:
            which = meter.check(expanded, generated, len(parents))
            mask = meter.mask
            if which:
                return budget_result(solver, which, meter, expanded, generated, len(parents),
                                     heuristic=heuristic, initial_h=h0)
        gs = best_g[s] if optimal else 0
        for name, c, t in succ(s):
            generated += 1
            if optimal:
                if t in closed or best_g.get(t, gs + c + 1) <= gs + c:
                    continue
                best_g[t] = gs + c
                parents[t] = (s, name, c)
                heapq.heappush(queue, (gs + c, 0, next(tie), t))
                continue
            if t in parents:
                continue
            parents[t] = (s, name, c)
            ht = h(t)
            w = novelty(s, t, count(t))
            heapq.heappush(queue, (ht, w, next(tie), t))
            heapq.heappush(other, (w, ht, next(tie), t))
    return finish(solved=False, status="no_solution", message="no plan exists: every reachable state was explored")


def _novelty(task: LiftedTask, seen: set):
    """`novelty(s, t, ht)`, judged against and recorded in `seen`."""
    atoms, of_object, width, n_init = task.atoms, task.of_object, WIDTH, task.n_init

    def novelty(s, t, ht) -> int:
        """1: t makes true an atom no state of landmark count ht did; 2: a pair of atoms
        of one object (its first argument: an agent's x and z, a block's place) that no
        such state had together; else 3."""
        w = 3
        for i in t ^ s:
            if (i < n_init) == (i in t):
                continue          # made false
            if (ht, i) not in seen:
                seen.add((ht, i))
                w = 1
            if width < 2:
                continue
            args = atoms[i][1]
            if not args:
                continue
            for j in of_object[args[0]]:
                if j != i and (j < n_init) != (j in t) and atoms[j][1][:1] == args[:1]:
                    key = (ht, i, j) if i < j else (ht, j, i)
                    if key not in seen:
                        seen.add(key)
                        w = min(w, 2)
        return w if width >= 2 else min(w, 2)
    return novelty


def _plan_to(s, parents: dict) -> tuple[list, int]:
    """The actions from the start to `s` along `parents`, and their cost."""
    plan, cost = [], 0
    while parents[s] is not None:
        s, name, c = parents[s]
        plan.append(name)
        cost += c
    plan.reverse()
    return plan, cost
