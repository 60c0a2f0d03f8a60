"""The one exploration behind hmax, hadd, hff and LM-cut (heuristics/relaxed_explore.py):
shared preconditions folded into conjunction facts, counters kept from the last state,
costs queued in buckets. None of that may change a fact's cost. The reference here is
hadd (and hmax) computed the plainest way: a Bellman-Ford fixpoint over the operators,
from nothing, for every state."""
from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from bcc.heuristics.relaxed_explore import MIN_SHARE, Exploration

INF = math.inf


def fixpoint(n_facts, pre, add, costs, state, additive=True):
    cost = [INF] * n_facts
    for f in state:
        cost[f] = 0
    changed = True
    while changed:
        changed = False
        for p, a, c in zip(pre, add, costs):
            v = (sum if additive else lambda xs: max(xs, default=0))([cost[f] for f in p]) + c
            for g in a:
                if v < cost[g]:
                    cost[g] = v
                    changed = True
    return cost


@st.composite
def tasks(draw):
    n = draw(st.integers(3, 12))
    fact = st.integers(0, n - 1)
    n_ops = draw(st.integers(1, 40))
    # Preconditions drawn from a few shared prefixes, so that the trie has nodes to fold.
    shared = draw(st.lists(st.lists(fact, min_size=2, max_size=4, unique=True), min_size=1, max_size=3))
    pre, add = [], []
    for _ in range(n_ops):
        p = set(draw(st.sampled_from(shared))) if draw(st.booleans()) else set()
        p |= set(draw(st.lists(fact, max_size=3)))
        pre.append(sorted(p))
        add.append(sorted(set(draw(st.lists(fact, min_size=1, max_size=3)))))
    costs = draw(st.lists(st.integers(0, 3), min_size=n_ops, max_size=n_ops))
    goal = sorted(set(draw(st.lists(fact, min_size=1, max_size=3))))
    states = draw(st.lists(st.lists(fact, max_size=n, unique=True), min_size=1, max_size=6))
    return n, pre, add, costs, goal, states


@settings(max_examples=150, deadline=None)
@given(tasks(), st.booleans())
def test_costs_equal_a_plain_fixpoint(task, additive):
    """On every state of a sequence (the counters carried from one to the next), each goal
    fact's cost (hadd, or hmax), and each fact's below the costliest goal fact (the
    exploration stops once all goal facts are reached), equals the fixpoint's, in the
    fast form (shared preconditions, kept counters) and in the plain one; run to the end,
    the plain form gives every fact's."""
    n, pre, add, costs, goal, states = task
    fast = Exploration(n, pre, add, goal)
    plain = Exploration(n, pre, add, goal, share=False, incremental=False)
    for state in states:
        ref = fixpoint(n, pre, add, costs, state, additive)
        top = max(ref[g] for g in goal)
        for a in (fast, plain):
            cost, sup, pcf = a.explore(state, costs, additive)
            assert [cost[g] for g in goal] == [ref[g] for g in goal]
            assert all(cost[f] == ref[f] for f in range(n) if ref[f] < top)
            # A supporter chain ends in the state; a fact's supporter adds it.
            for f in range(n):
                if cost[f] not in (0, INF):
                    assert f in a.add[sup[f]]
        cost, _, pcf = plain.explore(state, costs, additive, stop_at_goal=False)
        assert cost[:n] == ref
        if not additive:   # each fired operator's pcf is a costliest precondition of it
            for i, p in enumerate(pre):
                if p and all(cost[f] < INF for f in p):
                    assert pcf[i] in p and cost[pcf[i]] == max(cost[f] for f in p)


def test_shared_preconditions_become_one_fact():
    """MIN_SHARE operators needing a, b, c and one fact of their own each: a, b, c are
    folded into conjunction nodes (a∧b, then (a∧b)∧c), so a fact reached touches only
    the node that needs it. hadd of an operator's fact is unchanged: here b costs 2 (via
    the operator from a), so each x_i costs a + b + c + its own d_i + 1 = 0 + 2 + 0 + 0 + 1."""
    a_, b_, c_ = 0, 1, 2
    k = MIN_SHARE
    d = list(range(3, 3 + k))
    x = list(range(3 + k, 3 + 2 * k))
    n = 3 + 2 * k
    pre = [[a_]] + [[a_, b_, c_, d[i]] for i in range(k)]
    add = [[b_]] + [[x[i]] for i in range(k)]
    costs = [2] + [1] * k
    ad = Exploration(n, pre, add, x)
    assert ad.n_all == n + 2                       # a∧b, (a∧b)∧c
    assert all(len(p) == 2 for p in ad.pre[1:k + 1])   # the node and d_i
    cost, _, _ = ad.explore([a_, c_] + d, costs)
    assert [cost[f] for f in x] == [3] * k
    cost, _, _ = ad.explore([a_, b_, c_] + d[:1], costs)   # b now holds: the nodes count as held
    assert cost[x[0]] == 1 and cost[x[1]] == INF
