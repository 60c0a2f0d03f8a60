"""The state of a lifted progression search: ground facts with the indices its joins read,
changed in place and undone on backtracking, with an incremental hash.

Why in place: a depth-first progression over a plan of tens of thousands of actions
cannot copy a state of a hundred thousand facts at each step. Each change is logged, so
backtracking to a choice point undoes exactly what happened since. The hash is the XOR
of the facts' hashes (Zobrist), kept up to date in O(1) per change, so a (state,
network) pair is recognised again in O(1) for loop detection.

Facts are (predicate, args), kept in insertion order (the problem's :init first). An index (pred, positions) maps the values at `positions`
to the arguments of every fact of `pred` with those values, in insertion order (dicts,
not sets: the search's choices must not depend on string hashing).
"""
from __future__ import annotations


class Facts:
    def __init__(self, init, patterns=()):
        """The state `init`, with an index for each (pred, positions) of `patterns` (the
        joins' lookups), built in the same one pass; any other is built when first asked."""
        self.facts: dict = {}               # fact -> None: a set in insertion order
        self.hash = 0
        self.indices: dict = {}             # (pred, positions) -> {key: {args: None}}
        self.by_pred: dict = {}             # pred -> [(positions, index), ...] (maintained indices)
        self.log: list = []                 # (fact, added) since the start, undone by `undo`
        for pred, positions in sorted(patterns):
            index = self.indices[(pred, positions)] = {}
            self.by_pred.setdefault(pred, []).append((positions, index))
        for fact in init:
            self._add(fact)
        self.log.clear()

    def index(self, pred: str, positions: tuple) -> dict:
        """The index of `pred` by `positions`, built on first use and kept up to date."""
        key = (pred, positions)
        found = self.indices.get(key)
        if found is None:
            found = {}
            for fact in self.facts:
                if fact[0] == pred:
                    args = fact[1]
                    found.setdefault(tuple(args[p] for p in positions), {})[args] = None
            self.indices[key] = found
            self.by_pred.setdefault(pred, []).append((positions, found))
        return found

    def _add(self, fact) -> bool:
        if fact in self.facts:
            return False
        self.facts[fact] = None
        self.hash ^= hash(fact)
        args = fact[1]
        for positions, index in self.by_pred.get(fact[0], ()):
            index.setdefault(tuple(args[p] for p in positions), {})[args] = None
        return True

    def _remove(self, fact) -> bool:
        if fact not in self.facts:
            return False
        del self.facts[fact]
        self.hash ^= hash(fact)
        args = fact[1]
        for positions, index in self.by_pred.get(fact[0], ()):
            bucket = index.get(tuple(args[p] for p in positions))
            if bucket is not None:
                bucket.pop(args, None)
        return True

    def add(self, fact) -> None:
        if self._add(fact):
            self.log.append((fact, True))

    def remove(self, fact) -> None:
        if self._remove(fact):
            self.log.append((fact, False))

    def mark(self) -> int:
        return len(self.log)

    def undo(self, mark: int) -> None:
        log = self.log
        while len(log) > mark:
            fact, added = log.pop()
            if added:
                self._remove(fact)
            else:
                self._add(fact)
