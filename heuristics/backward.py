"""The one backward search of the abstraction heuristics (the pattern database,
patterns.py, and the counting abstraction, counting_explore.py): the cheapest cost from
every abstract state to a goal state, over a list of transitions."""
from __future__ import annotations

import array
import heapq
import math


def backward_distances(n: int, src, dst, cost, goals) -> list:
    """Cheapest cost from each abstract state to a goal state (math.inf: none), over the
    transitions src[k] -> dst[k] of cost[k]: Dijkstra backward from the goals. Given as
    numpy arrays (the counting abstraction's millions), the transitions are indexed in
    numpy, and searched breadth-first in numpy when they all cost the same; given as
    Python sequences (the pattern database's), all is done in Python, without importing
    numpy (which would cost a cold `bcc solve` of a maze 0.2 s of CPU)."""
    if not len(goals):
        return [math.inf] * n
    if isinstance(src, (list, tuple, array.array)):
        out = [math.inf] * n
        for g in goals:
            out[g] = 0.0
        return _dijkstra(out, *_by_target(n, src, dst, cost), goals)
    import numpy as np
    dist = np.full(n, np.inf)
    s = np.asarray(src, dtype=np.int32)
    d = np.asarray(dst, dtype=np.int32)
    c = np.asarray(cost, dtype=np.float64)
    order = np.argsort(d, kind="stable")
    s, d, c = s[order], d[order], c[order]
    starts = np.searchsorted(d, np.arange(n + 1))
    g = np.asarray(goals, dtype=np.int64)
    dist[g] = 0
    if len(c) and np.all(c == c[0]) and c[0] > 0:
        # Equal costs: breadth-first, one frontier at a time, in numpy.
        step = c[0]
        frontier = unique(g)
        level = 0.0
        while len(frontier):
            level += step
            lo, hi = starts[frontier], starts[frontier + 1]
            if not len(lo):
                break
            idx, _ = ranges(lo, hi)
            preds = unique(s[idx])
            preds = preds[dist[preds] == np.inf]
            dist[preds] = level
            frontier = preds
        return dist.tolist()
    return _dijkstra(dist.tolist(), s.tolist(), c.tolist(), starts.tolist(), goals)


def _by_target(n: int, src, dst, cost) -> tuple:
    """The transitions grouped by their target (a counting sort): sources, costs, and
    where each target's group starts."""
    starts = [0] * (n + 1)
    for d in dst:
        starts[d + 1] += 1
    for k in range(n):
        starts[k + 1] += starts[k]
    at = starts[:-1]
    sl, cl = [0] * len(dst), [0.0] * len(dst)
    for s, d, c in zip(src, dst, cost):
        k = at[d]
        sl[k], cl[k] = s, c
        at[d] = k + 1
    return sl, cl, starts


def _dijkstra(out: list, sl: list, cl: list, st: list, goals) -> list:
    """`out` (0 at the goals) lowered to each state's cheapest cost to a goal."""
    heap = [(0.0, int(x)) for x in set(goals)]
    heapq.heapify(heap)
    pop, push = heapq.heappop, heapq.heappush
    while heap:
        du, u = pop(heap)
        if du > out[u]:
            continue
        for j in range(st[u], st[u + 1]):
            v, nd = sl[j], du + cl[j]
            if nd < out[v]:
                out[v] = nd
                push(heap, (nd, v))
    return out


def ranges(lo, hi):
    """The indices lo[k] .. hi[k] - 1 of every k, concatenated, and each range's length:
    the rows of a compressed adjacency table for several nodes at once."""
    import numpy as np
    total = hi - lo
    return np.repeat(lo - np.concatenate(([0], np.cumsum(total)[:-1])), total) + np.arange(total.sum()), total


def unique(a):
    """The sorted distinct values of an integer array (np.unique by a sort: its hash-based
    path was 20x slower on these arrays)."""
    import numpy as np
    a = np.sort(a)
    return a[np.concatenate(([True], a[1:] != a[:-1]))] if len(a) else a


