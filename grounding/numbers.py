"""Numbers in a command as people type them: digits or cardinal number words, read apart
from the words around them.

"dig a 3x4x2 pond", "five wide and six long", "twenty-one rows", "a 10 by 10 bed":
a command is split into word and digit tokens (so `3x4x2` is 3, x, 4, x, 2 and `3by4` is
3, by, 4), and each run of number words is read as one cardinal below a thousand
("one hundred and five", "twenty one"). Number words are the one lexicon this reads: a
few hundred training commands cannot teach counting (text.py says the same). Which
parameter a number sets is learned (slots.py); this module only finds the numbers.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

TOKEN = re.compile(r"[0-9]+|[a-z]+(?:'[a-z]+)?")
UNITS = {w: i for i, w in enumerate(
    "zero one two three four five six seven eight nine ten eleven twelve thirteen fourteen fifteen "
    "sixteen seventeen eighteen nineteen".split())}
TENS = {w: 10 * i for i, w in enumerate("twenty thirty forty fifty sixty seventy eighty ninety".split(), 2)}
HUNDRED = "hundred"
NUMBER_WORDS = frozenset(UNITS) | frozenset(TENS) | {HUNDRED}
MAX_DIGITS = 6          # a longer run of digits is not a size (an id, a typo): left as a word


@dataclass(frozen=True)
class Item:
    """A word of the command, or a number read from one or more tokens."""
    text: str                # the word, or the number's tokens joined by spaces
    value: int | None = None

    @property
    def is_number(self) -> bool:
        return self.value is not None


def tokens(command: str) -> list[str]:
    """Lower-case word and digit tokens: `3x4` is three tokens, `red_tulips` two."""
    return TOKEN.findall(command.lower())


def read(words: list[str]) -> list[Item]:
    """The tokens as items, each run of number words (or digits) read as one number."""
    out, i = [], 0
    while i < len(words):
        w = words[i]
        if w.isdigit() and len(w) <= MAX_DIGITS:
            out.append(Item(w, int(w)))
            i += 1
            continue
        value, used = _cardinal(words, i)
        if used:
            out.append(Item(" ".join(words[i:i + used]), value))
            i += used
        else:
            out.append(Item(w))
            i += 1
    return out


def items(command: str) -> list[Item]:
    return read(tokens(command))


def numbers(command: str) -> list[int]:
    """The numbers a command says, in order."""
    return [x.value for x in items(command) if x.is_number]


def _cardinal(words: list[str], i: int) -> tuple[int, int]:
    """(value, tokens used) of the cardinal starting at words[i]; (0, 0) if none does.
    Grammar: [unit hundred [and]] (tens [unit] | unit), or unit hundred alone."""
    n, value, used = len(words), 0, 0
    if i < n and words[i] in UNITS and 0 < UNITS[words[i]] < 10 and i + 1 < n and words[i + 1] == HUNDRED:
        value, used = 100 * UNITS[words[i]], 2
        j = i + 2
        if j + 1 < n and words[j] == "and" and _starts_below_hundred(words, j + 1):
            j += 1
        rest, k = _below_hundred(words, j)
        if k:
            return value + rest, j + k - i
        return value, used
    return _below_hundred(words, i)


def _starts_below_hundred(words: list[str], j: int) -> bool:
    return j < len(words) and (words[j] in TENS or (words[j] in UNITS and UNITS[words[j]] > 0))


def _below_hundred(words: list[str], i: int) -> tuple[int, int]:
    if i >= len(words):
        return 0, 0
    w = words[i]
    if w in TENS:
        if i + 1 < len(words) and words[i + 1] in UNITS and 0 < UNITS[words[i + 1]] < 10:
            return TENS[w] + UNITS[words[i + 1]], 2
        return TENS[w], 1
    if w in UNITS:
        return UNITS[w], 1
    return 0, 0
