"""A small feed-forward network over a command's features: words that matter together.

The log-linear models (loglinear.py) add up one weight per (command feature, task
feature): "chair" and "green" each push towards their atoms whatever else is said, so
"take the chair out of the green room into the blue one" and "take the chair into the
green room" differ only by the weights of "out", "of" and "into". A hidden layer scores
combinations: each hidden unit fires on a weighted sum of the command's features (the
same features, loglinear.command_features), and a task's score is the hidden layer
read through the task's features:

    score(task | command) = relu(x W1 + b1) . (sum over f in F(task) of V[f])

so a task of another dungeon is scored by its atoms, as the log-linear model does, and
the softmax runs over each pair's own candidates. It is trained by Adam on minibatches
with dropout (on the command's features and on the hidden units) and a small L2
penalty, from several random starts whose log-probabilities are averaged: one start
alone is less accurate and depends on its seed. Everything is seeded, so training the
same pairs twice gives the same model. A pair whose task is latent (several weighted
explanations, from a demonstration) contributes log sum_t weight(t) P(t | command), as
in the log-linear model.

In 10-fold cross-validation over the cleanup-amt corpus (bench/corpus.py) it was the
most accurate single model on L1 commands (routes through rooms and doors, where what
is said last matters with what is said with it); as a vote of the ensemble
(ensemble.py) it raised L1 by most of a point and moved L0 and L2 by a fifth of a point
or less. Eight starts were right more often than five (their mean is steadier).
"""
from __future__ import annotations

import base64
import math

import numpy as np

from ..errors import BccError
from .loglinear import FeatureModel, command_features, index_features, task_matrix
from .model_file import expect_format
from .text import Speller

FORMAT = "bcc-network/1"
HIDDEN = 64          # hidden units
STARTS = 8           # random starts averaged
EPOCHS = 40          # passes over the pairs
BATCH = 32
RATE = 3e-3          # Adam's step size
L2 = 1e-4            # penalty per weight, on the batch's mean loss
DROP_HIDDEN = 0.5    # dropout of hidden units while training
DROP_INPUT = 0.2     # dropout of the command's features while training
SEED = 0


class Network(FeatureModel):
    """The trained network: feature indices, each start's weights, and the speller."""

    def __init__(self, command_index: dict, task_index: dict, starts: list[tuple], speller: Speller,
                 pairs: int = 0, skips: int = 0, factored: bool = True, chars: int = 0):
        super().__init__(command_index, task_index, speller, pairs, 0, skips, factored, chars)
        self.starts = starts          # [(W1 (dc x H), b1 (H), V (dt x H))]

    # ---- interpreting ------------------------------------------------------------------
    def log_posterior(self, command: str, tasks: list[str]) -> list[float]:
        """log P(task | command) for each candidate task text: the mean over the starts."""
        idx = [self.command_index[f] for f in command_features(self.tokens(command), self.skips, self.chars)
               if f in self.command_index]
        T = task_matrix(tasks, self.task_index, self.factored)
        total = np.zeros(len(tasks))
        for W1, b1, V in self.starts:
            h = np.maximum(W1[idx].sum(axis=0) + b1, 0.0)
            s = T @ (V @ h)
            s -= s.max()
            total += s - math.log(np.exp(s).sum())
        s = total / len(self.starts)
        s -= s.max()
        return list(s - math.log(np.exp(s).sum()))

    # ---- training ----------------------------------------------------------------------
    @classmethod
    def train(cls, examples: list, skips: int = 0, factored: bool = True, hidden: int = HIDDEN,
              starts: int = STARTS, epochs: int = EPOCHS, seed: int = SEED, chars: int = 0) -> Network:
        """`examples` as for LogLinear.train: (command, candidates, {task: weight})."""
        speller, feats, command_index, task_index = index_features(examples, skips, factored, chars)
        active = [np.array([command_index[f] for f in fs if f in command_index], dtype=np.int64) for fs in feats]
        groups: dict = {}
        group_of = np.empty(len(examples), dtype=np.int64)
        targets = []
        for k, (_, candidates, target) in enumerate(examples):
            key = tuple(candidates)
            if key not in groups:
                groups[key] = (len(groups), task_matrix(list(key), task_index, factored))
            group_of[k] = groups[key][0]
            pos = {t: j for j, t in enumerate(key)}
            w = np.zeros(len(key))
            for t, x in target.items():
                if t in pos and x > 0:
                    w[pos[t]] = x
            targets.append(w)
        matrices = [T for _, T in sorted(groups.values(), key=lambda g: g[0])]
        rng = np.random.default_rng(seed)
        trained = [_fit(active, group_of, matrices, targets, len(command_index), len(task_index),
                        hidden, epochs, rng) for _ in range(starts)]
        return cls(command_index, task_index, trained, speller, pairs=len(examples), skips=skips,
                   factored=factored, chars=chars)

    # ---- files -------------------------------------------------------------------------
    def to_json(self) -> dict:
        return {"format": FORMAT, "pairs": self.pairs, "skips": self.skips, "factored": self.factored,
                **({"chars": self.chars} if self.chars else {}), "hidden": int(self.starts[0][1].shape[0]),
                "command_features": sorted(self.command_index, key=self.command_index.get),
                "task_features": sorted(self.task_index, key=self.task_index.get),
                "starts": [{"W1": _encode(W1), "b1": _encode(b1), "V": _encode(V)} for W1, b1, V in self.starts],
                "word_counts": self.speller.counts}

    @classmethod
    def from_json(cls, data, path: str | None = None) -> Network:
        expect_format(data, FORMAT, path)
        try:
            command_index, task_index, speller, options = cls.read_features(data)
            hidden = int(data["hidden"])
            if hidden < 1:
                raise ValueError("\"hidden\" must be at least 1")
            starts = [(_decode(s["W1"], (len(command_index), hidden)), _decode(s["b1"], (hidden,)),
                       _decode(s["V"], (len(task_index), hidden))) for s in data["starts"]]
            if not starts:
                raise ValueError("\"starts\" must not be empty")
            return cls(command_index, task_index, starts, speller, **options)
        except (KeyError, TypeError, ValueError, AttributeError) as exc:
            raise BccError(f"malformed grounding model: {exc}", path) from None


def _fit(active, group_of, matrices, targets, dc: int, dt: int, hidden: int, epochs: int, rng) -> tuple:
    """One start: Adam on minibatches of the pairs' negative log-likelihood. A batch reads
    only the rows of W1 its commands' features select, and only those rows move (with their
    share of the penalty): a command has a few dozen features of the thousands known."""
    n = len(active)
    # He-style scale for the ~30 features a command has on
    W1 = rng.standard_normal((dc, hidden)) * math.sqrt(2 / 30)
    b1 = np.zeros(hidden)
    V = rng.standard_normal((dt, hidden)) * math.sqrt(1 / hidden)
    moments = {name: (np.zeros_like(p), np.zeros_like(p)) for name, p in (("W1", W1), ("b1", b1), ("V", V))}
    steps = {"b1": 0, "V": 0}
    seen = np.zeros(dc, dtype=np.int64)          # Adam's step count per row of W1

    def adam(p, g, m1, m2, t):
        m1 *= 0.9
        m1 += 0.1 * g
        m2 *= 0.999
        m2 += 0.001 * g * g
        p -= RATE * (m1 / (1 - 0.9 ** t)) / (np.sqrt(m2 / (1 - 0.999 ** t)) + 1e-8)

    for _ in range(epochs):
        order = rng.permutation(n)
        for s in range(0, n, BATCH):
            batch = order[s:s + BATCH]
            m = len(batch)
            rows = np.concatenate([np.full(len(active[k]), r) for r, k in enumerate(batch)])
            cols = np.concatenate([active[k] for k in batch])
            used, where = np.unique(cols, return_inverse=True)
            X = np.zeros((m, len(used)))                # the batch's commands over the features they have
            X[rows, where] = (rng.random(len(cols)) > DROP_INPUT) / (1 - DROP_INPUT)
            pre = X @ W1[used] + b1
            keep = (rng.random(pre.shape) > DROP_HIDDEN) / (1 - DROP_HIDDEN)
            H = np.maximum(pre, 0.0) * keep
            gH = np.zeros_like(H)
            gV = np.zeros_like(V)
            groups = group_of[batch]
            for g in np.unique(groups):
                mine = np.nonzero(groups == g)[0]
                T = matrices[g]
                E = T @ V                                   # candidates x hidden
                S = H[mine] @ E.T
                S -= S.max(axis=1, keepdims=True)
                p = np.exp(S)
                p /= p.sum(axis=1, keepdims=True)
                q = p * np.array([targets[batch[r]] for r in mine])
                q /= np.maximum(q.sum(axis=1, keepdims=True), 1e-300)
                G = (p - q) / m                             # d loss / d scores
                gH[mine] = G @ E
                gV += T.T @ (G.T @ H[mine])
            gpre = gH * keep * (pre > 0)
            seen[used] += 1
            block = W1[used]
            m1, m2 = moments["W1"]
            b_m1, b_m2 = m1[used], m2[used]
            adam(block, X.T @ gpre + L2 * block, b_m1, b_m2, seen[used][:, None])   # a step count per row
            W1[used], m1[used], m2[used] = block, b_m1, b_m2
            for name, p, g in (("b1", b1, gpre.sum(axis=0)), ("V", V, gV + L2 * V)):
                steps[name] += 1
                adam(p, g, *moments[name], steps[name])
    return W1, b1, V


def _encode(a: np.ndarray) -> str:
    """Weights as base64 of little-endian float32: a quarter of the decimal text's size."""
    return base64.b64encode(np.ascontiguousarray(a, dtype="<f4").tobytes()).decode("ascii")


def _decode(text, shape: tuple) -> np.ndarray:
    if not isinstance(text, str):
        raise ValueError("weights must be base64 text")
    try:
        raw = base64.b64decode(text.encode("ascii"), validate=True)
    except (ValueError, UnicodeEncodeError) as exc:
        raise ValueError(f"weights are not base64: {exc}") from None
    size = int(np.prod(shape))
    if len(raw) != 4 * size:
        raise ValueError(f"weights hold {len(raw) // 4} numbers, not {size}")
    a = np.frombuffer(raw, dtype="<f4").astype(np.float64).reshape(shape)
    if not np.isfinite(a).all():
        raise ValueError("weights must be finite")
    return a


__all__ = ["Network"]
