"""Words of a command as people type them: tokens, spelling normalised against the training vocabulary.

Nothing here knows a word of English: a word never seen in training is replaced by the
training word closest to it in edit distance (one edit for short words, two for words of
seven letters or more), the most frequent one on a tie, so "chiar" reads as "chair" when
"chair" was seen and "chiar" was not. Numbers are digits or number words (`NUMBERS`, the
one generic lexicon the grounding layer carries: counting is not learned from a few
hundred commands).
"""
from __future__ import annotations

import re
from collections import Counter

WORD = re.compile(r"[a-z0-9]+(?:'[a-z]+)?")
NUMBERS = {w: i for i, w in enumerate(
    "zero one two three four five six seven eight nine ten eleven twelve".split())}
NUMBERS.update({"once": 1, "twice": 2, "single": 1})


def words(command: str) -> list[str]:
    """Lower-case word tokens of a command."""
    return WORD.findall(command.lower())


def number(word: str) -> int | None:
    """The count a word names (digits, or an English number word), else None."""
    if word.isdigit():
        return int(word) if len(word) <= 3 else None
    return NUMBERS.get(word)


def edit_distance(a: str, b: str, cap: int) -> int:
    """Damerau-Levenshtein distance (adjacent swaps cost one), or cap + 1 once it exceeds cap."""
    if abs(len(a) - len(b)) > cap:
        return cap + 1
    prev2, prev = None, list(range(len(b) + 1))
    for i, ca in enumerate(a, 1):
        cur = [i] + [0] * len(b)
        for j, cb in enumerate(b, 1):
            cur[j] = min(prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (ca != cb))
            if i > 1 and j > 1 and ca == b[j - 2] and a[i - 2] == cb:
                cur[j] = min(cur[j], prev2[j - 2] + 1)
        if min(cur) > cap:
            return cap + 1
        prev2, prev = prev, cur
    return prev[-1]


class Speller:
    """Maps words unseen in training to the nearest training word, learned from word counts."""

    def __init__(self, counts: Counter | dict, min_count: int = 2):
        self.counts = dict(counts)
        self.targets = sorted((w for w, c in self.counts.items() if c >= min_count and not w.isdigit()),
                              key=lambda w: (-self.counts[w], w))
        self._cache: dict = {}

    @classmethod
    def learn(cls, commands) -> Speller:
        return cls(Counter(w for c in commands for w in words(c)))

    def correct(self, word: str) -> str:
        if word in self.counts or number(word) is not None or len(word) < 4:
            return word
        if word not in self._cache:
            cap = 2 if len(word) >= 7 else 1
            best, best_d = word, cap + 1
            for target in self.targets:      # most frequent first: ties keep the frequent word
                if abs(len(target) - len(word)) > cap or len(target) < 3:
                    continue
                d = edit_distance(word, target, cap)
                if d < best_d:
                    best, best_d = target, d
                    if d == 1:
                        break
            self._cache[word] = best
        return self._cache[word]

    def normalise(self, command: str) -> list[str]:
        return [self.correct(w) for w in words(command)]
