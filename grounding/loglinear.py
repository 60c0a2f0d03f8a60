"""A log-linear (maximum-entropy) model of P(task | command) over a dungeon's candidate tasks.

IBM Model 2 (translation.py) explains every word by a task token; people's commands are
mostly words that name no token ("go to the door then into the next room"), and a
generative model spends its probability on them. This model is discriminative:

    P(task | command) = exp(sum_{c in C(command), f in F(task)} W[c, f]) / Z(candidates)

C(command) are the command's features: a bias, its words and word pairs (spelling
normalised against the training vocabulary, text.py), and its words tagged by where they
stand (second half, last few words), so "bring the chair to blue then go to green" and
its mirror image differ, and words said two, or three and more, times. F(task) are the
task's features: its text, its lifted form (`agentInRoom blockInRoom`), each atom, each
function and each function with one argument (`blockInRoom:blue`). The bias crossed with the task features is the prior over
tasks; a word crossed with `blockInRoom:blue` is what IBM Model 2 calls t(word | token).
Because task features are atoms and their parts, a model trained in one dungeon scores
the tasks of another. A model trained not `factored` has only the text feature: each
task is a class of its own, as naive Bayes (bayes.py) sees it, so it cannot share what it
learned about `blockInRoom:green` between tasks; wrong on other commands than a factored
model, it is a vote of its own in the ensemble (ensemble.py), and it cannot score a task
that was never a candidate in training (`knows`).

Training maximises the conditional log-likelihood with an L2 penalty to convergence
(scipy's L-BFGS-B). A pair whose task is latent (inferred from a
demonstration: several weighted explanations) contributes log sum_{t in explanations}
weight(t) P(t | command) -- EM's objective, differentiated directly.
"""
from __future__ import annotations

import math
import re
from collections import Counter

import numpy as np
from scipy.optimize import minimize

from ..errors import BccError
from .model_file import JsonModelFile, expect_format
from .text import Speller, words

FORMAT = "bcc-loglinear/1"
L2 = 0.005         # penalty per weight (on the mean log-likelihood): tuned by cross-validation
ITERATIONS = 200  # L-BFGS iterations at most (it stops once the objective no longer falls)
MIN_COUNT = 2      # training commands a feature must occur in
TAIL = 4           # words at the end of a command tagged as such
ATOM = re.compile(r"(\w+)\(([^)]*)\)")


def task_features(task: str, agent: str = "agent", factored: bool = True) -> list[str]:
    """The task's features; not `factored`, only its text: each task a class of its own,
    as naive Bayes sees it (a task never seen in training then scores 0)."""
    if not factored:
        return ["T:" + task]
    atoms = ATOM.findall(task)
    out = ["T:" + task, "L:" + " ".join(sorted(f for f, _ in atoms)), f"N:{len(atoms)}"]
    for fn, args in atoms:
        names = [a.strip() for a in args.split(",")]
        out.append(f"A:{fn}({', '.join(names)})")
        out.append("F:" + fn)
        for a in names:
            if a != agent:
                out.append(f"FA:{fn}:{a}")
                out.append("X:" + a)
    return out


def command_features(tokens: list[str], skips: int = 0, chars: int = 0) -> list[str]:
    """The command's features; `skips` > 1 adds pairs of words up to that many apart (`s:`),
    `chars` > 1 the letter n-grams of each word, 2 to `chars` letters (`g:`)."""
    out = ["<bias>"]
    m = len(tokens)
    for j, w in enumerate(tokens):
        out.append("w:" + w)
        if j + 1 < m:
            out.append(f"b:{w}_{tokens[j + 1]}")
        out.append(("h2:" if 2 * j >= m else "h1:") + w)
        if j >= m - TAIL:
            out.append("e:" + w)
        # words a few apart: "chair ... green" across the words between them
        out += [f"s:{w}_{tokens[k]}" for k in range(j + 2, min(m, j + skips + 1))]
    # a word said again and again ("go to the door ... the door ... the door"): how many
    # rooms a route crosses, and so whether the agent comes back
    out += [f"c{min(n, 3)}:{w}" for w, n in Counter(tokens).items() if n >= 2]
    if chars > 1:
        out += letter_ngrams(tokens, chars)
    return list(dict.fromkeys(out))


def letter_ngrams(tokens: list[str], longest: int) -> list[str]:
    """Each word's letter n-grams of 2 to `longest` letters, the word padded by a space at
    either end (scikit-learn's analyzer="char_wb"): "rooom" and "room" share " ro", "roo"
    and "om ", "going" and "go" share " go"."""
    out = []
    for w in dict.fromkeys(tokens):
        padded = f" {w} "
        out += [f"g:{padded[i:i + n]}" for n in range(2, longest + 1) for i in range(len(padded) - n + 1)]
    return out


class _Segments:
    """Sums of gathered rows per key, for a sparse 0/1 matrix given as (key, other) pairs."""

    def __init__(self, keys: np.ndarray, others: np.ndarray, size: int):
        order = np.argsort(keys, kind="stable")
        self.others = others[order]
        keys = keys[order]
        self.present, self.starts = np.unique(keys, return_index=True)
        self.size = size

    def sum(self, M: np.ndarray) -> np.ndarray:
        out = np.zeros((self.size, M.shape[1]))
        out[self.present] = np.add.reduceat(M[self.others], self.starts, axis=0)
        return out


def task_matrix(tasks: list[str], task_index: dict, factored: bool = True) -> np.ndarray:
    """Candidates x task features, 1 where a task has a feature (features never trained on are left out)."""
    T = np.zeros((len(tasks), len(task_index)), dtype=np.float64)
    for k, t in enumerate(tasks):
        for f in task_features(t, factored=factored):
            i = task_index.get(f)
            if i is not None:
                T[k, i] = 1.0
    return T


def index_features(examples: list, skips: int = 0, factored: bool = True, chars: int = 0) -> tuple:
    """(speller, each example's command features, command feature -> index, task feature ->
    index) for training examples (command, candidates, target): the speller learns the
    examples' words; a command feature must occur in MIN_COUNT commands (on 50 examples or
    more: a feature of a single command says more about that command than about the
    language); task features are those of every candidate."""
    speller = Speller.learn(c for c, _, _ in examples)
    feats = [command_features(speller.normalise(c), skips, chars) for c, _, _ in examples]
    counts = Counter(f for fs in feats for f in fs)
    least = MIN_COUNT if len(examples) >= 50 else 1
    command_index = {f: i for i, f in enumerate(sorted(f for f, c in counts.items() if c >= least))}
    task_index: dict = {}
    for _, candidates, _ in examples:
        for t in candidates:
            for f in task_features(t, factored=factored):
                task_index.setdefault(f, len(task_index))
    return speller, feats, command_index, task_index


class FeatureModel(JsonModelFile):
    """What every model over command and task features shares (this one and network.py's):
    feature indices, the speller and training options; spelling-corrected tokens, the
    words it knows, and whether it can score given tasks; and reading those from a file."""

    def __init__(self, command_index: dict, task_index: dict, speller: Speller, pairs: int = 0,
                 iterations: int = 0, skips: int = 0, factored: bool = True, chars: int = 0):
        self.command_index, self.task_index = command_index, task_index
        self.speller = speller
        self.pairs, self.iterations = pairs, iterations
        self.skips, self.factored, self.chars = skips, factored, chars
        self.vocabulary = {f[2:] for f in command_index if f.startswith("w:")}

    @staticmethod
    def read_features(data) -> tuple[dict, dict, Speller, dict]:
        """The fields every feature model's file holds: (command feature -> index, task
        feature -> index, the speller, {pairs, skips, factored, chars}). Raises KeyError, TypeError,
        ValueError or AttributeError on malformed fields (from_json turns them into one line)."""
        cf, tf = [str(x) for x in data["command_features"]], [str(x) for x in data["task_features"]]
        counts = {str(w): int(c) for w, c in data["word_counts"].items()}
        return ({f: i for i, f in enumerate(cf)}, {f: i for i, f in enumerate(tf)}, Speller(counts),
                {"pairs": int(data.get("pairs", 0)), "skips": int(data.get("skips", 0)),
                 "factored": _flag(data.get("factored", True)), "chars": int(data.get("chars", 0))})

    def tokens(self, command: str) -> list[str]:
        return self.speller.normalise(command)

    def known(self, command_words: list[str]) -> list[str]:
        return [w for w in command_words if w in self.vocabulary]

    def knows(self, tasks: list[str]) -> bool:
        """Whether every task has a feature the model was trained on (a factored model
        scores any task by its atoms; one that is not, only the tasks it was trained with)."""
        return self.factored or all("T:" + t in self.task_index for t in tasks)


class LogLinear(FeatureModel):
    """The trained model: feature indices, the weight matrix and the speller."""

    def __init__(self, command_index: dict, task_index: dict, weights: np.ndarray, speller: Speller,
                 pairs: int = 0, iterations: int = 0, skips: int = 0, factored: bool = True, chars: int = 0):
        super().__init__(command_index, task_index, speller, pairs, iterations, skips, factored, chars)
        self.W = weights

    # ---- interpreting ------------------------------------------------------------------
    def _command_vector(self, tokens: list[str]) -> np.ndarray:
        idx = [self.command_index[f] for f in command_features(tokens, self.skips, self.chars)
               if f in self.command_index]
        return self.W[idx].sum(axis=0)

    def log_posterior(self, command: str, tasks: list[str]) -> list[float]:
        """log P(task | command) for each candidate task text."""
        s = task_matrix(tasks, self.task_index, self.factored) @ self._command_vector(self.tokens(command))
        s -= s.max()
        return list(s - math.log(np.exp(s).sum()))

    # ---- training ----------------------------------------------------------------------
    @classmethod
    def train(cls, examples: list, iterations: int = ITERATIONS, l2: float = L2, skips: int = 0,
              factored: bool = True, chars: int = 0) -> LogLinear:
        """`examples`: (command text, candidate task texts, {task text: weight}) -- the weights of
        the pair's task (one task weighted 1 when known, a demonstration's explanations when not);
        every weighted task must be among the candidates."""
        speller, feats, command_index, task_index = index_features(examples, skips, factored, chars)
        prepared = [(fs, list(candidates), target) for fs, (_, candidates, target) in zip(feats, examples)]
        n, dc, dt = len(prepared), len(command_index), len(task_index)
        rows, cols = [], []
        groups: dict = {}          # candidate list -> (example indices, task matrix, target matrix rows)
        for k, (feats, candidates, target) in enumerate(prepared):
            for f in feats:
                if f not in command_index:
                    continue
                rows.append(k)
                cols.append(command_index[f])
            groups.setdefault(tuple(candidates), []).append(k)
        rows_a, cols_a = np.array(rows, dtype=np.int64), np.array(cols, dtype=np.int64)
        by_row = _Segments(rows_a, cols_a, n)       # S = X W: sum of W's rows per example
        by_col = _Segments(cols_a, rows_a, dc)      # X^T G: sum of G's rows per feature
        blocks = []
        for candidates, members in groups.items():
            T = task_matrix(list(candidates), task_index, factored)
            pos = {t: j for j, t in enumerate(candidates)}
            prior = np.zeros((len(members), len(candidates)))
            for r, k in enumerate(members):
                for t, w in prepared[k][2].items():
                    if t in pos and w > 0:
                        prior[r, pos[t]] = w
            blocks.append((np.array(members), T, np.log(np.maximum(prior, 1e-300)), prior > 0))

        def value_and_gradient(x):
            W = x.reshape(dc, dt)
            S = by_row.sum(W)
            G = np.zeros((n, dt))
            loss = 0.0
            for members, T, log_prior, mask in blocks:
                scores = S[members] @ T.T
                scores -= scores.max(axis=1, keepdims=True)
                e = np.exp(scores)
                z = e.sum(axis=1, keepdims=True)
                q = np.where(mask, np.exp(np.minimum(scores + log_prior, 700)), 0.0)
                zq = np.maximum(q.sum(axis=1, keepdims=True), 1e-300)
                loss += float((np.log(z) - np.log(zq)).sum())
                G[members] = (e / z - q / zq) @ T
            grad = by_col.sum(G) / n + l2 * W
            return loss / n + 0.5 * l2 * float((W * W).sum()), grad.ravel()
        fit = minimize(value_and_gradient, np.zeros(dc * dt), jac=True, method="L-BFGS-B",
                       options={"maxiter": iterations, "maxcor": 10, "gtol": 1e-6, "ftol": 1e-10})
        return cls(command_index, task_index, fit.x.reshape(dc, dt), speller, pairs=n, iterations=int(fit.nit),
                   skips=skips, factored=factored, chars=chars)

    # ---- files -------------------------------------------------------------------------
    def to_json(self) -> dict:
        return {"format": FORMAT, "pairs": self.pairs, "iterations": self.iterations, "skips": self.skips,
                "factored": self.factored, **({"chars": self.chars} if self.chars else {}),
                "command_features": sorted(self.command_index, key=self.command_index.get),
                "task_features": sorted(self.task_index, key=self.task_index.get),
                "weights": [[round(float(x), 4) for x in row] for row in self.W],
                "word_counts": self.speller.counts}

    @classmethod
    def from_json(cls, data, path: str | None = None) -> LogLinear:
        expect_format(data, FORMAT, path)
        try:
            command_index, task_index, speller, options = cls.read_features(data)
            W = np.array(data["weights"], dtype=np.float64).reshape(len(command_index), len(task_index))
            return cls(command_index, task_index, W, speller, iterations=int(data.get("iterations", 0)), **options)
        except (KeyError, TypeError, ValueError, AttributeError) as exc:
            raise BccError(f"malformed grounding model: {exc}", path) from None


def _flag(value) -> bool:
    if not isinstance(value, bool):
        raise ValueError("\"factored\" must be true or false")
    return value


__all__ = ["FeatureModel", "LogLinear", "words", "task_features", "command_features", "task_matrix"]
