"""Step commands ("go down four, left five, up two") walked through the dungeon itself.

A step command names directions and counts, not a goal; where it ends is found by
walking it: from the start, each step turns the agent to face a map direction and moves
it forward that many cells (or, with no count, as far as it can go), through the
dungeon's own `move_forward` and rotation actions, walls and all. Where the walk ends --
the position atoms true there (`agentInRoom(agent, green)`) -- becomes evidence for the
classifier (loglinear.py), which learns how far to trust it.

Which words name which direction is learned, not listed (`Lexicon.learn`): each frequent
training word is given the map direction (or none) under which the most training commands
walk to where their demonstrations end, by coordinate ascent. Directions are map axes
(`x+`, `z-`), read from how `move_forward` changes the agent's position, so a lexicon
learned in one dungeon means the same in another.
"""
from __future__ import annotations

from collections import Counter

from .text import number

MAX_STEPS = 12          # cells walked by a step with no count ("go down"), and by any one step
MIN_GAIN = 3            # training commands a word's meaning must gain to be adopted
MIN_COUNT = 4           # training occurrences of a word considered as a direction
DIRECTIONS = ("x+", "x-", "z+", "z-")


class Walker:
    """Walks step sequences in one dungeon; None when it has no move/rotate actions."""

    def __init__(self, space):
        model = space.model
        self.space, self.model = space, model
        names = model.action_names
        self.ok = "move_forward" in names and "rotate_right" in names
        if not self.ok:
            return
        self.fwd, self.turn = model.action_index("move_forward"), model.action_index("rotate_right")
        self.start = model.initial
        self.position_keys: set = set()
        self.heading = self._headings()
        self.ok = len(self.heading) == 4
        self._distances: dict = {}
        agent = space.predicates.dungeon.agent_name
        self.atoms = [a for a in space.atoms if agent in a.args and space.predicates.position_dependent(a.text)]
        self._memo: dict = {}

    def _headings(self) -> dict:
        """Map direction of each number of right turns from the start's facing, found by moving."""
        model, out = self.model, {}
        frontier, seen = [(self.start, 0)], {self.start}
        while frontier and len(out) < 4 and len(seen) < 2000:
            state, turns = frontier.pop(0)
            nxt = model.apply(self.fwd, state)
            if nxt is not None and turns % 4 not in out:
                a, b = model.decode(state), model.decode(nxt)
                changed = [k for k in a if isinstance(a[k], int) and not isinstance(a[k], bool) and a[k] != b[k]]
                if len(changed) == 1:
                    k = changed[0]
                    out[turns % 4] = k.rsplit(".", 1)[-1] + ("+" if b[k] > a[k] else "-")
                    self.position_keys.add(k)
            for s, t in ((nxt, turns), (model.apply(self.turn, state), turns + 1)):
                if s is not None and s not in seen and not model.is_failure(s):
                    seen.add(s)
                    frontier.append((s, t))
        if len(out) == 4 and len(set(out.values())) == 4:
            return {v: k for k, v in out.items()}   # direction -> right turns from the start's facing
        return {}

    def walk(self, steps) -> bytes:
        """The state after the steps [(direction, count or None)] from the start."""
        state, turns = self.start, 0
        for direction, count in steps:
            key = (state, turns, direction, count)
            if key not in self._memo:
                self._memo[key] = self._step(state, turns, direction, count)
            state, turns = self._memo[key]
        return state

    def _step(self, state, turns, direction, count):
        want = self.heading[direction]
        while turns % 4 != want:
            state = self.model.apply(self.turn, state)
            turns += 1
        for _ in range(min(count or MAX_STEPS, MAX_STEPS)):
            nxt = self.model.apply(self.fwd, state)
            if nxt is None or self.model.is_failure(nxt):
                break
            state = nxt
        return state, turns % 4

    def position(self, state) -> tuple:
        d = self.model.decode(state)
        return tuple(d[k] for k in sorted(self.position_keys))

    def distance(self, state, target: frozenset) -> int:
        """Cells from the state's position to the nearest position whose signature is `target`
        (moves in any direction; MAX_STEPS * 2 when none is near)."""
        if target not in self._distances:
            self._distances[target] = self._distances_to(target)
        return self._distances[target].get(self.position(state), 2 * MAX_STEPS)

    def _distances_to(self, target: frozenset) -> dict:
        from collections import deque
        model, seen, order = self.model, {self.start}, [self.start]
        queue = deque([self.start])
        while queue and len(seen) < 20000:
            s = queue.popleft()
            for t in (model.apply(self.fwd, s), model.apply(self.turn, s)):
                if t is not None and t not in seen and not model.is_failure(t):
                    seen.add(t)
                    order.append(t)
                    queue.append(t)
        edges: dict = {}
        goal = set()
        for s in order:
            p = self.position(s)
            if self.signature(s) == target:
                goal.add(p)
            t = model.apply(self.fwd, s)
            if t is not None and t in seen:
                q = self.position(t)
                edges.setdefault(p, set()).add(q)
                edges.setdefault(q, set()).add(p)
        dist = {p: 0 for p in goal}
        queue = deque(goal)
        while queue:
            p = queue.popleft()
            for q in edges.get(p, ()):
                if q not in dist:
                    dist[q] = dist[p] + 1
                    queue.append(q)
        return dist

    def signature(self, state) -> frozenset:
        """The position atoms true in a state (`agentInRoom(agent, green)`)."""
        return frozenset(a.text for a in self.atoms if self.space.holds(a, state))


def steps(tokens: list[str], lexicon: dict, default: int | None) -> list:
    """[(direction, count)] of a command under a lexicon (word -> direction): a count is the
    number next to a direction word (after it, or before it when the next one is nearer);
    a direction with no count walks `default` cells (None: as far as it goes)."""
    marks = [(i, lexicon[w]) for i, w in enumerate(tokens) if lexicon.get(w)]
    if not marks:
        return []
    counts: list = [None] * len(marks)
    for i, w in enumerate(tokens):
        n = number(w)
        if n is None or n == 0:
            continue
        before = [k for k, (j, _) in enumerate(marks) if j < i and i - j <= 3 and counts[k] is None]
        after = [k for k, (j, _) in enumerate(marks) if j > i and j - i <= 3 and counts[k] is None]
        if before and (not after or i - marks[before[-1]][0] <= marks[after[0]][0] - i):
            counts[before[-1]] = n
        elif after:
            counts[after[0]] = n
    return [(d, c if c is not None else default) for (_, d), c in zip(marks, counts)]


class Lexicon:
    """Learned meanings of direction words: word -> map direction."""

    def __init__(self, meanings: dict | None = None):
        self.meanings = dict(meanings or {})

    def to_json(self) -> dict:
        return dict(sorted(self.meanings.items()))

    @classmethod
    def learn(cls, examples, rounds: int = 2) -> Lexicon:
        """`examples`: (walker, tokens, target signature). Coordinate ascent over frequent words:
        each takes the meaning (a direction, or none) under which most commands walk to their
        target, counting both ways of reading a count-less step."""
        examples = [(w, t, sig) for w, t, sig in examples
                    if w is not None and w.ok and any(number(x) for x in t)   # counted steps only
                    and sig and sig != w.signature(w.start)]   # nowhere named, or staying put, teaches nothing
        freq = Counter(x for _, t, _ in examples for x in set(t))
        candidates = [x for x, c in freq.most_common() if c >= MIN_COUNT and number(x) is None]
        having = {x: [k for k, (_, t, _) in enumerate(examples) if x in t] for x in candidates}
        lexicon: dict = {}

        def hits(k):   # minus the cells between where the walk ends and where it should
            walker, tokens, target = examples[k]
            return -walker.distance(walker.walk(steps(tokens, lexicon, 1)), target)

        score = {k: hits(k) for k in range(len(examples))}
        for _ in range(rounds * len(candidates)):   # best single change first, until none gains
            best = (MIN_GAIN - 1, None, None, None)
            for x in candidates:
                current = lexicon.get(x)
                for meaning in (None,) + DIRECTIONS:
                    if meaning == current:
                        continue
                    lexicon[x] = meaning
                    new = {k: hits(k) for k in having[x]}
                    gain = sum(new.values()) - sum(score[k] for k in having[x])
                    if gain > best[0]:
                        best = (gain, x, meaning, new)
                lexicon[x] = current
            gain, x, meaning, new = best
            if x is None:
                break
            lexicon[x] = meaning
            score.update(new)
        return cls({x: d for x, d in lexicon.items() if d is not None})
