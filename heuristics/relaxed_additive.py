"""The additive exploration behind hadd and hff, made cheap enough to run once per expanded
state (relaxed.py asks it).

Its cost is the number of times a reached fact touches an operator that needs it. Three
things cut that number, none changing a fact's cost:

- **Shared preconditions are evaluated once.** Preconditions sorted by how many operators
  share them form a trie (many operators need the same facing, the same looking
  direction, the same selected slot and what it holds, and differ only in a position and
  a cell). Each trie node shared by MIN_SHARE or more operators becomes a conjunction fact,
  reached by a zero-cost node operator from its parent node and its last fact; an
  operator then needs its deepest shared node and the facts after it. A conjunction's
  additive cost is the sum of its facts', so every original fact's cost is unchanged.
- **The state's facts are not explored.** The counters of unmet preconditions are kept
  from the last evaluated state and moved by the facts that changed (a child differs
  from its parent in a few facts); node facts whose parts all hold count as state facts.
  The operators that the state alone enables fire at once.
- **The queue holds each distinct cost once**, with the facts of that cost in a list.

Operators 0..n_ops-1 and facts 0..n_facts-1 are the view's own; node operators and
facts are numbered after them (`is_node(i)`), so a supporter chain read off `sup` may
pass through node operators, which cost 0 and stand for no action.
"""
from __future__ import annotations

import heapq
import math

INF = math.inf
MIN_SHARE = 8   # a trie node becomes a conjunction fact when this many operators share it (2: 7 % slower)


class Additive:
    def __init__(self, n_facts: int, pre: list, add: list, goal_set):
        self.n_ops = len(pre)
        self.n_facts = n_facts
        freq = [0] * n_facts
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
        self.node_pre: list = []         # node operator k (index n_ops + k): its two preconditions
        self.node_add: list = []
        n = n_facts

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
        self.n_all = n
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

    def explore(self, facts, costs):
        """Fact costs (hadd) and each fact's supporter, stopping once the goal's facts are
        reached; `costs` are the view's operator costs (node operators cost 0)."""
        self.rebase(facts)
        cost = [INF] * self.n_all
        sup = [-1] * self.n_all
        for f in facts:
            cost[f] = 0
        for f in self.base_nodes:
            cost[f] = 0
        is_goal = self.is_goal
        goals_left = sum(1 for g in self.goal_set if cost[g] != 0)   # each counted once, when popped
        if not goals_left:
            return cost, sup
        add = self.add
        buckets: dict = {}
        for i in self.ready:
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
        unsat = self.unsat[:]
        opv = [0] * len(unsat)
        pre_of, n_ops = self.pre_of, self.n_ops
        pop, push, get = heapq.heappop, heapq.heappush, buckets.get
        while keys:
            c = pop(keys)
            for f in buckets.pop(c):   # facts added to this bucket meanwhile are visited too
                if c > cost[f]:
                    continue
                if is_goal[f]:
                    goals_left -= 1
                    if goals_left == 0:
                        return cost, sup
                for i in pre_of[f]:
                    v = opv[i] + c
                    opv[i] = v
                    u = unsat[i] - 1
                    unsat[i] = u
                    if u == 0:
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
                                    b.append(g)
        return cost, sup
