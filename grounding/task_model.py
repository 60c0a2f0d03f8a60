"""Commands to task calls: "dig a 3 by 4 bed of tulips" -> `bed(1, 1, 3, 4, tulips)`.

A dungeon whose domain has compound tasks (calls.py) is commanded by them. Three learned
parts, all trained on command/task-call pairs (and the tasks' descriptions):

1. which task: a log-linear classifier over the task names (loglinear.py, one class per
   task), reading the command's words with its numbers and its enumeration values put as
   placeholders (`qnumber`, `q` and the type's name), so "a 3 by 4 bed of tulips" and
   "a 9 by 2 bed of roses" are the same words to it. Each task's description, with its
   name, is one more training example, so a task no pair names still has words;
2. the integer parameters: slots.py's number model;
3. the enumeration and object parameters: value names and learned synonyms (slots.py).

A parameter the command does not set takes its default (calls.py); a task whose
parameters cannot all be given a value is not a candidate, nor is a task the model was
never trained with (its pairs' dungeons' tasks). The candidates are ranked by the
classifier's posterior, with NAMED log-odds more for a task the command names. Words are spelling-corrected first against the training
words and the domain's own (value names, task names, descriptions, number words).
"""
from __future__ import annotations

import math
import re
from collections import Counter

from ..errors import BccError
from .calls import CallSpace, TaskSig, format_call
from .interpret import TOP, Interpretation
from .loglinear import LogLinear
from .model_file import JsonModelFile, expect_format
from .numbers import NUMBER_WORDS, Item, read, tokens
from .slots import NONE, NumberModel, ValueReader, assign, expected_labels, number_features
from .text import Speller

FORMAT = "bcc-taskcalls/1"
PARAMETER = re.compile(r"`([A-Za-z_][A-Za-z0-9_]*)`")   # a parameter, in a task's description
NUMBER = "qnumber"            # a number, as the classifier sees it
TASK_L2 = 0.002        # the classifier's penalty per weight
NUMBER_L2 = 0.0003     # the number model's (both chosen by 5-fold cross-validation of the training pairs)
NAMED = 3.0            # log-odds added to a task the command names (chosen by the same cross-validation)
PLACEHOLDER = "q"             # + an enumeration's name: one of its values, as the classifier sees it


def domain_words(space: CallSpace) -> set:
    """The words a domain gives: its values' and tasks' names (split at `_`), its tasks'
    descriptions, and the number words (so a misspelt "fiev" reads as "five")."""
    out = set(NUMBER_WORDS)
    for values in space.enums.values():
        for v in values:
            out.update(str(v).lower().split("_"))
    for t in space.tasks:
        out.update(t.name.lower().split("_"))
        out.update(tokens(t.description))
    return out


class TaskCallModel(JsonModelFile):
    def __init__(self, classifier: LogLinear, numbers: NumberModel, values: ValueReader, speller: Speller,
                 pairs: int = 0):
        self.classifier, self.numbers, self.values, self.speller = classifier, numbers, values, speller
        self.pairs = pairs
        self.vocabulary = classifier.vocabulary

    # ---- reading a command -------------------------------------------------------------
    def words(self, command: str) -> list[str]:
        return spelt(self.speller, command)

    def placeholders(self, items: list[Item], space: CallSpace) -> str:
        return classifier_text(items, space, self.values.synonyms)

    def fill(self, task: TaskSig, items: list[Item], words: list[str]) -> tuple | None:
        """The task's argument values read from the command, defaults for the rest; None
        when a parameter gets no value."""
        ints, _ = assign(self.numbers, items, task)
        named: dict = {}
        for p in task.params:
            if p.kind in ("enum", "object"):
                named.setdefault(p.type, self.values.read(words, p))
        taken: Counter = Counter()
        out = []
        for p in task.params:
            value = None
            if p.kind == "int":
                value = ints.get(p.name)
            elif p.kind in ("enum", "object"):
                said = named[p.type]
                if taken[p.type] < len(said):
                    value = said[taken[p.type]]
                    taken[p.type] += 1
            if value is None:
                value = task.defaults.get(p.name)
            if value is None:
                return None
            out.append(value)
        return tuple(out)

    def interpret(self, command: str, space: CallSpace) -> Interpretation:
        words = self.words(command)
        items = read(words)
        text = self.placeholders(items, space)
        marks = {NUMBER} | {PLACEHOLDER + e for e in space.enums}
        plain = [w for w in text.split() if w not in marks]
        unknown = sorted({w for w in plain if w not in self.speller.counts})
        tasks = [t for t in space.tasks if self.classifier.knows([t.name])]
        if not tasks:
            return Interpretation(command, None, [], unknown,
                                  f"the model was never trained with the tasks of {space.name!r}'s domain: train it on "
                                  "commands for it (bcc train --pairs FILE)")
        names = [t.name for t in tasks]
        scores = _named(self.classifier.log_posterior(text, names), tasks, set(words))
        known = [w for w in plain if w in self.speller.counts]
        if not known:
            return Interpretation(command, None, [], unknown, "no word of the command was seen in training")
        if len(known) < len(plain) - len(known):
            return Interpretation(command, None, [], unknown, "most words of the command were never seen in training")
        chance = -math.log(len(names))
        ranked = []
        for t, s in sorted(zip(tasks, scores), key=lambda ts: (-ts[1], ts[0].name)):
            if s <= chance + 1e-9 and len(names) > 1:
                continue
            values = self.fill(t, items, words)
            if values is not None:
                ranked.append((format_call(t.name, values), math.exp(s)))
        if not ranked:
            return Interpretation(command, None, [], unknown, "no task explains the command better than chance "
                                  "with a value for each of its parameters")
        return Interpretation(command, ranked[0][0], ranked[:TOP], unknown)

    # ---- training ----------------------------------------------------------------------
    @classmethod
    def train(cls, rows: list, space_of, task_l2: float = TASK_L2, number_l2: float = NUMBER_L2) -> TaskCallModel:
        """`rows`: {command, task (a call), dungeon, and optionally path, line}; `space_of(ref)`:
        the dungeon's CallSpace. BccError (at the row's line) for a call that is not one of
        its dungeon's tasks with values of the right types."""
        spaces, parsed = {}, []
        for r in rows:
            space = spaces.get(r["dungeon"]) or spaces.setdefault(r["dungeon"], space_of(r["dungeon"]))
            name, values = space.parse(r["task"], (r.get("path"), r.get("line"), 1 if r.get("line") else None))
            parsed.append((r["command"], space, space.by_name[name], values))
        if not parsed:
            raise BccError("no pair to train on")
        counts = Counter(w for c, _, _, _ in parsed for w in tokens(c))
        for space in spaces.values():
            for w in domain_words(space):
                counts[w] = max(counts[w], 2)      # a speller target, as a word seen twice
        speller = Speller(counts)
        spelt_ = [(spelt(speller, c), space, task, values) for c, space, task, values in parsed]
        values_reader = ValueReader.learn([(w, task, values) for w, _, task, values in spelt_])
        numbers = []
        for w, _, task, values in spelt_:
            items = read(w)
            labels = [p.name for p in task.params if p.kind == "int"] + [NONE]
            for k, x in enumerate(items):
                if x.is_number:
                    numbers.append((number_features(items, k), task.name, labels,
                                    expected_labels(task, values, x.value)))
        for space in spaces.values():
            for t in space.tasks:
                items = description_items(t)
                labels = [p.name for p in t.params if p.kind == "int"] + [NONE]
                numbers += [(number_features(items, k), t.name, labels, {x.text}) for k, x in enumerate(items)
                            if x.is_number]
        number_model = NumberModel.train(numbers, number_l2)
        synonyms = values_reader.synonyms
        examples = []
        for w, space, task, _ in spelt_:
            names = [t.name for t in space.tasks]
            examples.append((classifier_text(read(w), space, synonyms), names, {task.name: 1.0}))
        for space in spaces.values():
            names = [t.name for t in space.tasks]
            for t in space.tasks:
                items = [Item(w) for w in t.name.lower().split("_")] + description_items(t)
                examples.append((classifier_text(items, space, synonyms), names, {t.name: 1.0}))
        classifier = LogLinear.train(examples, l2=task_l2, factored=False)
        return cls(classifier, number_model, values_reader, speller, pairs=len(parsed))

    # ---- files -------------------------------------------------------------------------
    def to_json(self) -> dict:
        return {"format": FORMAT, "pairs": self.pairs, "classifier": self.classifier.to_json(),
                "numbers": self.numbers.to_json(), "synonyms": dict(sorted(self.values.synonyms.items())),
                "word_counts": self.speller.counts}

    @classmethod
    def from_json(cls, data, path: str | None = None) -> TaskCallModel:
        expect_format(data, FORMAT, path)
        try:
            classifier = LogLinear.from_json(data["classifier"], path)
            numbers = NumberModel.from_json(data["numbers"])
            synonyms = {str(w): str(v) for w, v in data["synonyms"].items()}
            counts = {str(w): int(c) for w, c in data["word_counts"].items()}
            return cls(classifier, numbers, ValueReader(synonyms), Speller(counts), pairs=int(data.get("pairs", 0)))
        except (KeyError, TypeError, ValueError, AttributeError) as exc:
            raise BccError(f"malformed task-call model: {exc}", path) from None


def _named(scores: list, tasks: list, words: set) -> list:
    """Log-posteriors with NAMED added to each task whose name (its words) the command says,
    renormalised: "dig a pond" is a pond even where "dig" mostly meant a bed."""
    s = [x + (NAMED if set(t.name.lower().split("_")) <= words else 0.0) for x, t in zip(scores, tasks)]
    top = max(s)
    z = top + math.log(sum(math.exp(x - top) for x in s))
    return [x - z for x in s]


def description_items(task: TaskSig) -> list[Item]:
    """A task's description as items: an int parameter written in backquotes (`w`) stands
    for a number that sets it, so "a bed `w` x `l`, `h` deep" teaches the number model
    "x" between w and l and "high" after h before any pair does."""
    ints = {p.name for p in task.params if p.kind == "int"}
    out = []
    for j, part in enumerate(PARAMETER.split(task.description)):
        if j % 2 and part in ints:
            out.append(Item(part, 0))
        else:
            out += [Item(w) for w in tokens(part)]
    return out


def spelt(speller: Speller, command: str) -> list[str]:
    """The command's tokens, spelling corrected; never a word into a number ("right" is not
    a misspelt "eight": a wrong number is worse than an unknown word)."""
    out = []
    for w in tokens(command):
        c = speller.correct(w)
        out.append(w if c in NUMBER_WORDS and w not in NUMBER_WORDS else c)
    return out


def classifier_text(items: list[Item], space: CallSpace, synonyms: dict) -> str:
    """The command as the classifier reads it: numbers and values put as placeholders."""
    words = [x.text if not x.is_number else NUMBER for x in items]
    for enum, values in space.enums.items():
        words = _replace_mentions(words, _enum_param(enum, values), synonyms, PLACEHOLDER + enum)
    return " ".join(words)


def _enum_param(enum: str, values: tuple):
    from .calls import Param
    return Param(enum, enum, "enum", values)


def _replace_mentions(words: list[str], p, synonyms: dict, placeholder: str) -> list[str]:
    """`words` with each value of p it names (by name or synonym) put as `placeholder`."""
    from .slots import mentions
    out, i = [], 0
    while i < len(words):
        for size in (3, 2, 1):
            span = words[i:i + size]
            if len(span) == size and NUMBER not in span and mentions(span, p, synonyms) and \
                    len(mentions(span, p, synonyms)) == 1 and _whole(span, p, synonyms):
                out.append(placeholder)
                i += size
                break
        else:
            out.append(words[i])
            i += 1
    return out


def _whole(span: list[str], p, synonyms: dict) -> bool:
    """Whether the span is exactly one value's name or one synonym (not a name and more)."""
    if len(span) == 1:
        return span[0] in synonyms and synonyms[span[0]] in p.values or span[0] in p.values
    return tuple(span) in {tuple(str(v).lower().split("_")) for v in p.values}
