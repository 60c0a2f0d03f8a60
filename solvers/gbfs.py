"""Greedy best-first search: always expand the state with the lowest h. Fast, not optimal.

With a heuristic that names *preferred actions* (`hff`: the first steps of its relaxed
plan), successors reached by them also go to a second open list, and the search
alternates between the two, giving the preferred list BOOST extra turns each time h
improves (Fast Downward's dual queue with boosting; its 1,000 turns sent the search down
long plateaus of preferred states on the manipulation dungeons: 6,615 expansions on the
largest against 917 with 10, and the same on the reference dungeons). Preferred actions only change the
order of expansion, never which states can be reached, so completeness is kept.

Evaluation is *lazy* (deferred, as in Fast Downward's lazy search) for the heuristics of
the relaxed view, whose one evaluation costs far more than generating a state: a state
is queued under its parent's h and its own h is computed only when it is expanded, so
one evaluation per expansion instead of one per generated state. `--evaluation eager`
computes h on generation (the default for table heuristics such as pdb).
"""
from __future__ import annotations

import heapq
import math

from ..model import Model
from .base import Budget, Meter, Result, extract_plan
from ..heuristics.registry import HEURISTICS, make, serves
from .options import Option, declare, heuristic_option

BOOST = 10


class _OpenLists:
    """The two open lists: every state, and states reached by a preferred action. They
    are taken in turn, and each new best h gives the preferred list BOOST extra turns."""

    def __init__(self, h0, start):
        self.queues = [[(h0, 0, start)], []]
        self.turn = self.boost = self.tie = 0
        self.best = h0

    def __bool__(self) -> bool:
        return bool(self.queues[0] or self.queues[1])

    def pop(self):
        if self.boost > 0 and self.queues[1]:
            q, self.boost = 1, self.boost - 1
        else:
            q = self.turn if self.queues[self.turn] else 1 - self.turn
            self.turn = 1 - self.turn
        return heapq.heappop(self.queues[q])[2]

    def push(self, h, state, preferred: bool) -> None:
        self.tie += 1
        heapq.heappush(self.queues[0], (h, self.tie, state))
        if preferred:
            heapq.heappush(self.queues[1], (h, self.tie, state))

    def progress(self, h) -> None:
        if h < self.best:
            self.best, self.boost = h, BOOST
def auto_heuristic(model: Model) -> str:
    """gbfs's own choice: the pattern database where it sees the goal (a goal about the
    agent's position), hff where it is blind at the start (h = 0 although the goal does
    not hold: carrying things, or a model without a position) and serves the model, else
    the pattern database (which falls back to manhattan)."""
    if not serves("hff", model):
        return "pdb"
    if model.data("pattern_database") is None and model.goal_positions is None:
        return "hff"
    h0 = make("pdb", model)(model.initial)
    return "hff" if h0 == 0 and not model.is_goal(model.initial) else "pdb"


@declare(heuristic_option("auto"),
         Option("preferred", bool, True, "with hff: also expand states reached by its preferred actions "
                "(a second queue, boosted on progress)"),
         Option("evaluation", str, "auto", "when h is computed: eager (on generation), lazy (on expansion, "
                "successors queued under the parent's h), auto (lazy for the relaxed-view heuristics)",
                choices=("auto", "eager", "lazy")))
def solve(model: Model, budget: Budget, progress=None, heuristic: str = "auto", preferred: bool = True,
          evaluation: str = "auto", **options) -> Result:
    meter = Meter(budget, progress, "gbfs")
    if heuristic == "auto":
        heuristic = auto_heuristic(model)
    h = make(heuristic, model)
    # h.preferred(): the preferred actions of the state h last rated (not on a blind fallback)
    helpful = getattr(h, "preferred", None) if preferred and HEURISTICS[heuristic].preferred else None
    if evaluation == "lazy" or evaluation == "auto" and HEURISTICS[heuristic].costly:
        return _lazy(model, budget, meter, h, helpful, heuristic)
    start = model.initial
    parents = {start: None}
    h0 = h(start)
    if h0 == math.inf:
        return meter.finish(Result(solver="gbfs", solved=False, status="no_solution", stored=1,
                                   heuristic=heuristic, initial_h=h0,
                                   message="no plan exists: the goal cannot hold at any reachable position"))
    pref_of = {start: helpful()} if helpful else None
    open_lists = _OpenLists(h0, start)
    closed = set()
    expanded = generated = 0
    mask, max_states = meter.mask, budget.max_states
    while open_lists:
        state = open_lists.pop()
        if state in closed:
            continue
        closed.add(state)
        if model.is_goal(state):
            plan, cost = extract_plan(model, parents, state)
            return meter.finish(Result(solver="gbfs", solved=True, status="solved", plan=plan, cost=cost,
                                       expanded=expanded, generated=generated, stored=len(parents),
                                       heuristic=heuristic, initial_h=h0))
        expanded += 1
        if not expanded & mask or max_states is not None and len(parents) > max_states:
            stopped = meter.stop(expanded, generated, len(parents))
            if stopped:
                return stopped
            mask = meter.mask
        prefer = pref_of.pop(state, frozenset()) if pref_of is not None else frozenset()
        for action, nxt in model.successors(state):
            generated += 1
            if nxt in parents or model.is_failure(nxt):
                continue
            hn = h(nxt)
            if hn == math.inf:
                continue
            parents[nxt] = (state, action)
            open_lists.push(hn, nxt, action in prefer)
            if pref_of is not None:
                pref_of[nxt] = helpful()
            open_lists.progress(hn)
    return meter.finish(Result(solver="gbfs", solved=False, status="no_solution", expanded=expanded,
                               generated=generated,
                               stored=len(parents), heuristic=heuristic, initial_h=h0,
                               message="no plan exists: every reachable state was explored"))


def _lazy(model: Model, budget: Budget, meter: Meter, h, helpful, heuristic: str) -> Result:
    """Greedy best-first search with deferred evaluation (see the module docstring)."""
    start = model.initial
    parents = {start: None}
    h0 = h(start)

    def finish(**kw) -> Result:
        return meter.finish(Result(solver="gbfs", stored=len(parents), heuristic=heuristic, initial_h=h0, **kw))

    if h0 == math.inf:
        return finish(solved=False, status="no_solution",
                      message="no plan exists: the goal cannot hold at any reachable position")
    known = {start: (h0, helpful() if helpful else frozenset())}
    open_lists = _OpenLists(h0, start)
    closed = set()
    expanded = generated = 0
    mask, max_states = meter.mask, budget.max_states
    while open_lists:
        state = open_lists.pop()
        if state in closed:
            continue
        closed.add(state)
        if model.is_goal(state):
            plan, cost = extract_plan(model, parents, state)
            return finish(solved=True, status="solved", plan=plan, cost=cost, expanded=expanded,
                          generated=generated)
        if state in known:
            hs, prefer = known.pop(state)
        else:
            hs = h(state)
            prefer = helpful() if helpful else frozenset()
        if hs == math.inf:
            continue
        open_lists.progress(hs)
        expanded += 1
        if not expanded & mask or max_states is not None and len(parents) > max_states:
            stopped = meter.stop(expanded, generated, len(parents))
            if stopped:
                return stopped
            mask = meter.mask
        for action, nxt in model.successors(state):
            generated += 1
            if nxt in parents or model.is_failure(nxt):
                continue
            parents[nxt] = (state, action)
            open_lists.push(hs, nxt, action in prefer)
    return finish(solved=False, status="no_solution", expanded=expanded, generated=generated,
                  message="no plan exists: every reachable state was explored")
