"""The one exploration of a relaxed task's facts, behind hmax, hadd, hff and LM-cut.

From a state's facts (cost 0), facts are reached in order of cost (Dijkstra, as Knuth
generalised it to AND/OR graphs): an operator fires when the last of its preconditions
is reached, at the sum (hadd) or the maximum (hmax) of their costs plus its own, and
offers that to the facts it adds. Each fact keeps its supporter (the operator that
reached it most cheaply: hff's relaxed plan) and each fired operator the precondition
that fired it (the costliest one under max: LM-cut's justification graph). It stops
once the goal's facts are reached, or runs to the end (LM-cut).

Its cost is the number of times a reached fact touches an operator that needs it. For
an exploration run once per expanded state (hadd, hff, hmax) three things cut that
number, none changing a fact's cost:

- **Shared preconditions are evaluated once** (`share`). Preconditions sorted by how many
  operators share them form a trie (many operators need the same facing, the same looking
  direction, the same selected slot and what it holds, and differ only in a position and
  a cell). Each trie node shared by MIN_SHARE or more operators becomes a conjunction fact,
  reached by a zero-cost node operator from its parent node and its last fact; an
  operator then needs its deepest shared node and the facts after it. A conjunction's
  cost is the sum (or the maximum) of its facts', so every original fact's cost is unchanged.
- **The state's facts are not explored** (`incremental`). The counters of unmet
  preconditions are kept from the last evaluated state and moved by the facts that changed
  (a child differs from its parent in a few facts); node facts whose parts all hold count
  as state facts. The operators that the state alone enables fire at once.
- **The queue holds each distinct cost once**, with the facts of that cost in a list
  (first in, first out).

LM-cut uses it with neither (`Exploration(..., share=False, incremental=False)`): its cuts
follow which precondition fired each operator, so there facts of equal cost are taken
in the order of their numbers (the queue's lists kept as heaps), the state's facts
included; after a cut `lower` carries the costs down from the cheaper operators.

Operators 0..n_ops-1 and facts 0..n_facts-1 are the task's own; node operators and
facts are numbered after them (`is_node(i)`), so a supporter chain read off `sup` may
pass through node operators, which cost 0 and stand for no action.
"""
from __future__ import annotations

import heapq
import math

INF = math.inf
MIN_SHARE = 8   # a trie node becomes a conjunction fact when this many operators share it (2: 7 % slower)


class Exploration:
    """The exploration over one relaxed task's facts (see the module docstring)."""

    def __init__(self, n_facts: int, pre: list, add: list, goal_set, share: bool = True, incremental: bool = True):
        self.n_ops = len(pre)
        self.n_facts = n_facts
        self.incremental = incremental
        self.node_pre: list = []         # node operator k (index n_ops + k): its two preconditions
        self.node_add: list = []
        fpre = self._fold(pre) if share else [list(p) for p in pre]
        n = self.n_all = n_facts + len(self.node_add)
        self.pre = fpre + [list(x) for x in self.node_pre]
        self.add = list(add) + self.node_add
        self.pre_of = [[] for _ in range(n)]
        for i, p in enumerate(self.pre):
            for f in p:
                self.pre_of[f].append(i)
        self.n_pre = [len(p) for p in self.pre]
        self.node_of_op = [-1] * self.n_ops + [a[0] for a in self.node_add]
        self.is_goal = bytearray(n)
        self.goal_set = set(goal_set)
        for g in self.goal_set:
            self.is_goal[g] = 1
        # Kept between evaluations (see rebase).
        self.base: set = set()
        self.unsat = self.n_pre[:]
        self.ready = {i for i in range(self.n_ops) if not self.pre[i]}
        self.base_nodes: set = set()

    def _fold(self, pre: list) -> list:
        """The operators' preconditions with shared prefixes folded into conjunction facts
        (node_pre, node_add: the node operators that reach them)."""
        freq = [0] * self.n_facts
        for p in pre:
            for f in p:
                freq[f] += 1
        order = [sorted(set(p), key=lambda f: (-freq[f], f)) for p in pre]
        # Trie over the sorted preconditions (node 0 is the root): how many operators pass
        # each node, each node's parent and last fact. Memory is linear in the preconditions.
        child: dict = {}
        passing, parent, last = [0], [-1], [-1]
        paths = []
        for p in order:
            path, node = [0], 0
            for f in p[:-1]:   # a node leaves at least one fact after it
                nxt = child.get((node, f))
                if nxt is None:
                    nxt = child[node, f] = len(passing)
                    passing.append(0)
                    parent.append(node)
                    last.append(f)
                passing[nxt] += 1
                path.append(nxt)
                node = nxt
            paths.append(path)
        fact_of: dict = {}               # trie node -> its conjunction fact
        n = self.n_facts

        def conjunction(node, depth):
            nonlocal n
            f = fact_of.get(node)
            if f is None:
                head = last[parent[node]] if depth == 2 else conjunction(parent[node], depth - 1)
                f = fact_of[node] = n
                n += 1
                self.node_pre.append((head, last[node]))
                self.node_add.append((f,))
            return f

        fpre = []
        for p, path in zip(order, paths):
            k = 1
            while k + 1 < len(path) and passing[path[k + 1]] >= MIN_SHARE:
                k += 1     # passing only falls with depth: the deepest shared node
            fpre.append([conjunction(path[k], k)] + p[k:] if k >= 2 else p)
        return fpre

    def is_node(self, i: int) -> bool:
        return i >= self.n_ops

    def rebase(self, facts) -> None:
        """Move the kept counters from the last evaluated state to `facts`. A node fact
        holds in the state when its node operator's preconditions do; it then counts as
        a state fact (its operators' counters move with it)."""
        new = set(facts)
        old = self.base
        gone, came = old - new, new - old
        self.base = new
        unsat, ready, pre_of, node_of_op = self.unsat, self.ready, self.pre_of, self.node_of_op
        base_nodes = self.base_nodes
        n_ops = self.n_ops
        while gone or came:
            lost, won = [], []
            for f in gone:
                for i in pre_of[f]:
                    u = unsat[i]
                    if u == 0:
                        if i >= n_ops:
                            base_nodes.discard(node_of_op[i])
                            lost.append(node_of_op[i])
                        else:
                            ready.discard(i)
                    unsat[i] = u + 1
            for f in came:
                for i in pre_of[f]:
                    u = unsat[i] - 1
                    unsat[i] = u
                    if u == 0:
                        if i >= n_ops:
                            base_nodes.add(node_of_op[i])
                            won.append(node_of_op[i])
                        else:
                            ready.add(i)
            gone, came = lost, won

    def explore(self, facts, costs, additive: bool = True, stop_at_goal: bool = True):
        """(cost, sup, pcf) from the state `facts`: each fact's cost (hadd with `additive`,
        else hmax) and supporter, and under max each fired operator's costliest
        precondition (pcf; None under sum). `costs` are the task's operator costs (node
        operators cost 0). With `stop_at_goal` it stops once the goal's facts are reached:
        then only they and the facts cheaper than the costliest of them are final."""
        cost = [INF] * self.n_all
        sup = [-1] * self.n_all
        opv = [0 if additive else -1] * len(self.pre)   # under sum: the costs reached so far; under max: pcf
        buckets: dict = {}
        add = self.add
        if self.incremental:
            self.rebase(facts)
            for f in facts:
                cost[f] = 0
            for f in self.base_nodes:
                cost[f] = 0
            goals_left = sum(1 for g in self.goal_set if cost[g] != 0)   # each counted once, when popped
            if stop_at_goal and not goals_left:
                return cost, sup, None if additive else opv
            unsat = self.unsat[:]
            fired = self.ready
        else:
            zero = buckets[0] = []
            for f in facts:
                if cost[f] != 0:
                    cost[f] = 0
                    zero.append(f)
            goals_left = len(self.goal_set)
            unsat = self.n_pre[:]
            fired = [i for i in range(self.n_ops) if not self.pre[i]]
        for i in fired:
            c = costs[i]
            for g in add[i]:
                if c < cost[g]:
                    cost[g] = c
                    sup[g] = i
                    b = buckets.get(c)
                    if b is None:
                        buckets[c] = [g]
                    else:
                        b.append(g)
        keys = sorted(buckets)
        ordered = not self.incremental
        if ordered:   # facts of equal cost by their numbers
            for b in buckets.values():
                heapq.heapify(b)
        put = heapq.heappush if ordered else list.append
        is_goal, pre_of, n_ops = self.is_goal, self.pre_of, self.n_ops
        pop, push, get = heapq.heappop, heapq.heappush, buckets.get
        while keys:
            c = pop(keys)
            bucket = buckets[c]   # facts added to it meanwhile are taken too
            for f in _in_order(bucket) if ordered else bucket:
                if c > cost[f]:
                    continue
                if stop_at_goal and is_goal[f]:
                    goals_left -= 1
                    if goals_left == 0:
                        return cost, sup, None if additive else opv
                for i in pre_of[f]:
                    u = unsat[i] - 1
                    unsat[i] = u
                    if additive:
                        v = opv[i] + c
                        opv[i] = v
                    else:
                        v = c     # facts come in order of cost: the last one is the costliest
                    if u == 0:
                        if not additive:
                            opv[i] = f
                        if i < n_ops:
                            v += costs[i]
                        for g in add[i]:
                            if v < cost[g]:
                                cost[g] = v
                                sup[g] = i
                                b = get(v)
                                if b is None:
                                    buckets[v] = [g]
                                    push(keys, v)
                                else:
                                    put(b, g)
            del buckets[c]
        return cost, sup, None if additive else opv

    def lower(self, cut, costs, cost, pcf) -> None:
        """hmax after the operators `cut` got cheaper (`costs`), from `explore`'s `cost` and
        `pcf` (Fast Downward's incremental exploration, for LM-cut): fact costs only fall,
        so facts are taken again from those the cut adds, in order of cost, and an operator
        whose costliest precondition fell re-chooses it; this gives the hmax a fresh
        exploration would (up to ties)."""
        pre, add, pre_of = self.pre, self.add, self.pre_of
        heap = []
        for i in cut:
            v = (cost[pcf[i]] if pcf[i] >= 0 else 0) + costs[i]
            for g in add[i]:
                if v < cost[g]:
                    cost[g] = v
                    heap.append((v, g))
        heapq.heapify(heap)
        pop, push = heapq.heappop, heapq.heappush
        while heap:
            c, f = pop(heap)
            if c > cost[f]:
                continue
            for i in pre_of[f]:
                if pcf[i] != f:
                    continue   # not the costliest precondition (or never applicable): unchanged
                p = max(pre[i], key=cost.__getitem__)
                pcf[i] = p
                v = cost[p] + costs[i]
                for g in add[i]:
                    if v < cost[g]:
                        cost[g] = v
                        push(heap, (v, g))


def _in_order(heap: list):
    """The facts of a bucket kept as a heap, smallest number first, while it grows."""
    pop = heapq.heappop
    while heap:
        yield pop(heap)
