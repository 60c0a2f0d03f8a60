"""The one backward search of the abstraction heuristics (the pattern database,
patterns.py, and the counting abstraction, counting_build.py): the cheapest cost from
every abstract state to a goal state, over a list of transitions."""
from __future__ import annotations


def backward_distances(n: int, src, dst, cost, goals) -> list:
    """Cheapest cost from each abstract state to a goal state (math.inf: none)."""
    import numpy as np
    dist = np.full(n, np.inf)
    if not len(goals):
        return dist.tolist()
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
    import heapq
    sl, cl, st = s.tolist(), c.tolist(), starts.tolist()
    out = dist.tolist()
    heap = [(0.0, int(x)) for x in set(goals)]
    heapq.heapify(heap)
    while heap:
        du, u = heapq.heappop(heap)
        if du > out[u]:
            continue
        for j in range(st[u], st[u + 1]):
            v, nd = sl[j], du + cl[j]
            if nd < out[v]:
                out[v] = nd
                heapq.heappush(heap, (nd, v))
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


