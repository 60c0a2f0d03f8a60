"""Bernoulli naive Bayes over a command's features: a second opinion for the log-linear models.

The log-linear models (loglinear.py) are discriminative and share their features, so
they tend to be wrong on the same commands. Naive Bayes is generative: each task is a
class, and P(command | task) is the product over every command feature (the same
features as the log-linear model's) of the probability that a command of this task has
it, or lacks it. It is a poor judge alone (about 80 % in 10-fold cross-validation on the
cleanup-amt corpus against 85 %) but errs differently, and a small share of its vote
made the ensemble (ensemble.py) right more often over several shuffles.

Classes are task texts. A candidate task never seen in training has no counts of its
own: it is scored as the language at large (every training command pooled), with the
smallest prior, so the naive Bayes vote neither favours nor rules out tasks of another
dungeon. Demonstrations whose task is latent ({task: weight}) count fractionally.
"""
from __future__ import annotations

import math
from collections import Counter

import numpy as np

from ..errors import BccError
from .loglinear import MIN_COUNT, command_features
from .model_file import JsonModelFile, expect_format
from .text import Speller

FORMAT = "bcc-naive-bayes/1"
ALPHA = 0.5        # add-alpha smoothing of each feature's presence probability
PRIOR = 0.5        # pseudo-count of every candidate task in the prior


class NaiveBayes(JsonModelFile):
    def __init__(self, features: list[str], task_counts: dict, feature_counts: dict, speller: Speller):
        """`task_counts` {task: (soft) number of training commands}; `feature_counts` {task:
        {feature index: (soft) number of those commands having it}}."""
        self.features = features
        self.index = {f: i for i, f in enumerate(features)}
        self.task_counts = dict(task_counts)
        self.feature_counts = {t: dict(c) for t, c in feature_counts.items()}
        self.speller = speller
        self.vocabulary = {f[2:] for f in features if f.startswith("w:")}
        self.pairs = int(round(sum(self.task_counts.values())))
        self.iterations = 0
        self._classes = {t: self._class(self.task_counts[t], self.feature_counts.get(t, {})) for t in self.task_counts}
        pooled = Counter()
        for c in self.feature_counts.values():
            pooled.update(c)
        self._background = self._class(sum(self.task_counts.values()), pooled)

    def _class(self, n: float, counts: dict) -> tuple[float, np.ndarray]:
        """(sum over all features of log P(absent), log P(present) - log P(absent) per feature)."""
        seen = np.zeros(len(self.features))
        for i, c in counts.items():
            seen[int(i)] = c
        p = (seen + ALPHA) / (n + 2 * ALPHA)
        absent = np.log1p(-p)
        return float(absent.sum()), np.log(p) - absent

    # ---- the interface interpret.rank uses (shared with LogLinear) ---------------------
    def tokens(self, command: str) -> list[str]:
        return self.speller.normalise(command)

    def known(self, command_words: list[str]) -> list[str]:
        return [w for w in command_words if w in self.vocabulary]

    def log_posterior(self, command: str, tasks: list[str]) -> list[float]:
        idx = [self.index[f] for f in command_features(self.tokens(command)) if f in self.index]
        s = np.empty(len(tasks))
        for k, t in enumerate(tasks):
            base, delta = self._classes.get(t, self._background)
            s[k] = math.log(self.task_counts.get(t, 0.0) + PRIOR) + base + delta[idx].sum()
        s -= s.max()
        return list(s - math.log(np.exp(s).sum()))

    # ---- training ----------------------------------------------------------------------
    @classmethod
    def train(cls, examples: list) -> NaiveBayes:
        """`examples` as for LogLinear.train: (command, candidates, {task: weight})."""
        speller = Speller.learn(c for c, _, _ in examples)
        prepared = [(command_features(speller.normalise(c)), target) for c, _, target in examples]
        counts = Counter(f for feats, _ in prepared for f in feats)
        least = MIN_COUNT if len(prepared) >= 50 else 1
        features = sorted(f for f, c in counts.items() if c >= least and f != "<bias>")
        index = {f: i for i, f in enumerate(features)}
        task_counts: Counter = Counter()
        feature_counts: dict = {}
        for feats, target in prepared:
            total = sum(w for w in target.values() if w > 0)
            for t, w in target.items():
                if w <= 0:
                    continue
                share = w / total
                task_counts[t] += share
                mine = feature_counts.setdefault(t, Counter())
                for f in feats:
                    if f in index:
                        mine[index[f]] += share
        return cls(features, task_counts, feature_counts, speller)

    # ---- files -------------------------------------------------------------------------
    def to_json(self) -> dict:
        return {"format": FORMAT, "features": self.features,
                "task_counts": {t: round(c, 6) for t, c in self.task_counts.items()},
                "feature_counts": {t: {str(i): round(c, 6) for i, c in sorted(cs.items())}
                                   for t, cs in self.feature_counts.items()},
                "word_counts": self.speller.counts}

    @classmethod
    def from_json(cls, data, path: str | None = None) -> NaiveBayes:
        expect_format(data, FORMAT, path)
        try:
            features = [str(f) for f in data["features"]]
            task_counts = {str(t): float(c) for t, c in data["task_counts"].items()}
            feature_counts = {}
            for t, cs in data["feature_counts"].items():
                row = {int(i): float(c) for i, c in cs.items()}
                if any(not 0 <= i < len(features) or c < 0 for i, c in row.items()):
                    raise ValueError(f"feature index out of range for task {t!r}")
                feature_counts[str(t)] = row
            if any(c < 0 for c in task_counts.values()) or set(feature_counts) - set(task_counts):
                raise ValueError("task counts must be non-negative and cover every task with feature counts")
            counts = {str(w): int(c) for w, c in data["word_counts"].items()}
            return cls(features, task_counts, feature_counts, Speller(counts))
        except (KeyError, TypeError, ValueError, AttributeError) as exc:
            raise BccError(f"malformed grounding model: {exc}", path) from None
