"""Reading a task's parameter values from a command, learned from command/task-call pairs.

Numbers (numbers.py) go to integer parameters. Which number sets which parameter is a
log-linear choice per number among the task's integer parameters and "none" (a number
that sets nothing: "dig one bed"), over features of where the number stands: the
word just before and after it, the words up to three away on either side (up to the
next number), and the run of numbers it is part of ("3 by 4 by 2", "at 4, 6": its place
in the run and the word joining the run). A label is a parameter by name (`P:w`, shared by
every task with a `w`) and by task (`TP:bed.l`), so what "wide" says about `w` carries
from one task to another. The numbers are then given to parameters together: each parameter
takes at most one number, the assignment with the highest summed log-probability wins.

Enumeration parameters take a value the command names (`red_tulips` as "red
tulips", the longest name first) or a word learned to mean one: a word that, in the
training pairs, appears mostly in commands whose value is that one and that do not name
it ("scarlet" -> red_tulips). Class parameters take an object the command names.

Nothing here knows a word of the domain: parameter names, types and values come from
calls.py, words from the training pairs.
"""
from __future__ import annotations

import math
from collections import Counter, defaultdict

import numpy as np
from scipy.optimize import minimize

from .calls import Param, TaskSig
from .loglinear import _Segments
from .numbers import Item

NONE = "<none>"
L2 = 0.01                # penalty per weight on the mean log-likelihood
SYNONYM_SHARE = 0.6      # of the training commands with a word that must have its value unnamed
SYNONYM_COUNT = 2        # training commands a synonym must be seen in
WINDOW = 3               # words before and after a number read as a bag (up to the next number)
ITERATIONS = 300


def number_features(items: list[Item], k: int) -> list[str]:
    """Features of the number items[k] (see the module docstring)."""
    def word(j):
        if j < 0:
            return "^"
        if j >= len(items):
            return "$"
        return "#" if items[j].is_number else items[j].text
    nums = [j for j, x in enumerate(items) if x.is_number]
    # the run: numbers with at most one word between each and the next
    runs, cur = [], [nums[0]] if nums else []
    for a, b in zip(nums, nums[1:]):
        if b - a <= 2:
            cur.append(b)
        else:
            runs.append(cur)
            cur = [b]
    if cur:
        runs.append(cur)
    run = next(r for r in runs if k in r)
    i, size = run.index(k), len(run)
    joiners = {word(a + 1) for a, b in zip(run, run[1:]) if b - a == 2}
    joiner = "".join(sorted(joiners)) if joiners else "-"
    # fewer kinds of feature generalise better from a hundred commands: the words two away,
    # the words around a run and the number's place among all were left out by 5-fold
    # cross-validation of the training pairs (81 -> 84 % exact calls)
    out = ["b", f"p:{word(k - 1)}", f"n:{word(k + 1)}", f"r:{joiner}:{i}/{min(size, 3)}"]
    if size == 1:
        out.append("alone")
    for step, tag in ((1, "a"), (-1, "f")):     # the words after (before) it, up to a number
        j = k + step
        while 0 <= j < len(items) and abs(j - k) <= WINDOW and not items[j].is_number:
            out.append(f"{tag}:{items[j].text}")
            j += step
    return list(dict.fromkeys(out))


def label_features(task: str, label: str) -> list[str]:
    if label == NONE:
        return [NONE]
    return [f"P:{label}", f"TP:{task}.{label}"]


class NumberModel:
    """P(parameter | a number's features) among one task's int parameters and none."""

    def __init__(self, command_index: dict, label_index: dict, weights: np.ndarray):
        self.command_index, self.label_index, self.W = command_index, label_index, weights

    def log_probs(self, feats: list[str], task: str, labels: list[str]) -> list[float]:
        rows = [self.command_index[f] for f in feats if f in self.command_index]
        v = self.W[rows].sum(axis=0) if rows else np.zeros(len(self.label_index))
        s = np.array([sum(v[self.label_index[g]] for g in label_features(task, lab) if g in self.label_index)
                      for lab in labels])
        s -= s.max()
        return list(s - math.log(np.exp(s).sum()))

    @classmethod
    def train(cls, examples: list, l2: float = L2) -> NumberModel:
        """`examples`: (features, task, labels, expected labels) for each number of each pair."""
        counts = Counter(f for fs, _, _, _ in examples for f in set(fs))
        command_index = {f: i for i, f in enumerate(sorted(counts))}
        label_index: dict = {}
        for _, task, labels, _ in examples:
            for lab in labels:
                for g in label_features(task, lab):
                    label_index.setdefault(g, len(label_index))
        dc, dl = len(command_index), len(label_index)
        rows, cols, groups = [], [], {}
        for k, (fs, task, labels, expected) in enumerate(examples):
            for f in set(fs):
                rows.append(k)
                cols.append(command_index[f])
            groups.setdefault((task, tuple(labels)), []).append(k)
        n = max(len(examples), 1)
        rows_a, cols_a = np.array(rows, dtype=np.int64), np.array(cols, dtype=np.int64)
        by_row = _Segments(rows_a, cols_a, len(examples))     # X W: W's rows summed per number
        by_col = _Segments(cols_a, rows_a, dc)                # X^T G
        blocks = []
        for (task, labels), members in groups.items():
            L = np.zeros((len(labels), dl))
            for r, lab in enumerate(labels):
                for g in label_features(task, lab):
                    L[r, label_index[g]] = 1.0
            mask = np.array([[lab in examples[k][3] for lab in labels] for k in members])
            blocks.append((np.array(members), L, mask))

        def value_and_gradient(x):
            W = x.reshape(dc, dl)
            S = by_row.sum(W)
            G = np.zeros((len(examples), dl))
            loss = 0.0
            for members, L, mask in blocks:
                s = S[members] @ L.T
                s -= s.max(axis=1, keepdims=True)
                e = np.exp(s)
                z = e.sum(axis=1, keepdims=True)
                q = np.where(mask, e, 0.0)
                zq = q.sum(axis=1, keepdims=True)
                loss += float((np.log(z) - np.log(zq)).sum())
                G[members] = (e / z - q / zq) @ L
            grad = by_col.sum(G) / n + l2 * W
            return loss / n + 0.5 * l2 * float((W * W).sum()), grad.ravel()
        fit = minimize(value_and_gradient, np.zeros(dc * dl), jac=True, method="L-BFGS-B",
                       options={"maxiter": ITERATIONS, "gtol": 1e-6})
        return cls(command_index, label_index, fit.x.reshape(dc, dl))

    def to_json(self) -> dict:
        return {"command_features": sorted(self.command_index, key=self.command_index.get),
                "label_features": sorted(self.label_index, key=self.label_index.get),
                "weights": [[round(float(x), 4) for x in row] for row in self.W]}

    @classmethod
    def from_json(cls, data: dict) -> NumberModel:
        cf = [str(f) for f in data["command_features"]]
        lf = [str(f) for f in data["label_features"]]
        W = np.array(data["weights"], dtype=np.float64).reshape(len(cf), len(lf))
        return cls({f: i for i, f in enumerate(cf)}, {f: i for i, f in enumerate(lf)}, W)


def expected_labels(task: TaskSig, values: tuple, value: int) -> set:
    """The int parameters the expected call gives this number's value (none if no one does)."""
    hit = {p.name for p, v in zip(task.params, values) if p.kind == "int" and v == value}
    return hit or {NONE}


def assign(model: NumberModel, items: list[Item], task: TaskSig) -> tuple[dict, float]:
    """({parameter: number}, summed log-probability) of the best assignment of the command's
    numbers to the task's int parameters, each parameter taking at most one number."""
    ints = [p.name for p in task.params if p.kind == "int"]
    nums = [k for k, x in enumerate(items) if x.is_number]
    if not nums:
        return {}, 0.0
    labels = ints + [NONE]
    scores = [model.log_probs(number_features(items, k), task.name, labels) for k in nums]
    # best assignment: dynamic programming over numbers, with the set of parameters used
    best = {frozenset(): (0.0, ())}
    for row in scores:
        nxt: dict = {}
        for used, (total, choice) in best.items():
            for j, lab in enumerate(labels):
                if lab != NONE and lab in used:
                    continue
                key = used | {lab} if lab != NONE else used
                cand = (total + row[j], choice + (lab,))
                if key not in nxt or cand[0] > nxt[key][0]:
                    nxt[key] = cand
        best = nxt
    total, choice = max(best.values(), key=lambda tc: tc[0])
    return {lab: items[k].value for k, lab in zip(nums, choice) if lab != NONE}, total


class ValueReader:
    """Enumeration values and objects a command names, by name or by a learned word."""

    def __init__(self, synonyms: dict):
        self.synonyms = synonyms            # word -> value name (any enumeration)

    @classmethod
    def learn(cls, pairs: list) -> ValueReader:
        """`pairs`: (words, task, values). A word is a synonym of v when most training commands
        holding it have v as a value, unnamed and not the default (which needs no word)."""
        holding, unnamed = Counter(), defaultdict(Counter)
        for words, task, values in pairs:
            seen = set(words)
            holding.update(seen)
            for p, v in zip(task.params, values):
                if p.kind not in ("enum", "object") or v == task.defaults.get(p.name):
                    continue
                if mentions(words, p, {}):
                    continue
                for w in seen:
                    unnamed[w][v] += 1
        synonyms = {}
        for w, by_value in unnamed.items():
            v, c = by_value.most_common(1)[0]
            if c >= max(SYNONYM_COUNT, SYNONYM_SHARE * holding[w]) and \
                    not any(w == part for part in str(v).split("_")):
                synonyms[w] = v
        return cls(synonyms)

    def read(self, words: list[str], p: Param) -> list:
        return mentions(words, p, self.synonyms)


def mentions(words: list[str], p: Param, synonyms: dict) -> list:
    """The values of parameter p that `words` name, in order: by their names (split at `_`,
    the longest first) if any is named, else by words learned to mean one."""
    names = sorted(((tuple(str(v).lower().split("_")), v) for v in p.values), key=lambda nv: -len(nv[0]))
    named, learned, i = [], [], 0
    while i < len(words):
        for parts, v in names:
            if tuple(words[i:i + len(parts)]) == parts:
                named.append(v)
                i += len(parts)
                break
        else:
            v = synonyms.get(words[i])
            if v is not None and v in p.values:
                learned.append(v)
            i += 1
    return named or learned
