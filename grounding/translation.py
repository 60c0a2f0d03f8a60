"""IBM Model 2 (Brown et al. 1993): how command words align with a task's tokens.

P(task | words) is proportional to P(task) P(words | task). The prior is over the task's
lifted form (its functions: `agentInRoom`, `agentHasBlock agentInRoom`), learned from the
pairs' latent tasks, so conjunctions nobody asked for stay unlikely; the likelihood is
P(words | task) = prod_j sum_i a(i | j, l, m) t(word_j | token_i), where the task's tokens
(`agentInRoom red`, plus a NULL token at position 0) are the "source language" and the
command the "target". Trained with EM as in MacGlashan et al. (2015): a pair's task is
latent, a distribution over the explanations of its demonstration (infer.py), and each EM
step re-weights those by how well they explain the words. Model 1 iterations (uniform
alignment) initialize the lexical table; Model 2 iterations then learn the distortion.

Smoothing: t(e | f) = (c(e, f) + delta) / (c(f) + delta (|V| + 1)); a token never seen in
training gives every word 1 / (|V| + 1), "chance". A word never seen in training carries
no evidence for any task and is left out of the score (`unknown` lists it). Distortion is
interpolated with the uniform alignment 1 / (l + 1).
"""
from __future__ import annotations

import math
import re
from collections import defaultdict

from ..errors import BccError
from .model_file import JsonModelFile

NULL = "<null>"
FORMAT = "bcc-ibm2/1"
DELTA = 0.01          # lexical smoothing
LAMBDA = 1.0          # distortion smoothing: pseudo-counts of the uniform alignment
ALPHA = 0.5           # pseudo-count of every lifted task in the prior
WORD = re.compile(r"[a-z0-9]+(?:'[a-z]+)?")


def words(command: str) -> list[str]:
    """Lower-case word tokens of a command."""
    return WORD.findall(command.lower())


class IBMModel2(JsonModelFile):
    def __init__(self, t: dict | None = None, a: dict | None = None, vocabulary=None, f_counts=None,
                 a_counts=None, pairs: int = 0, iterations: int = 0, templates: dict | None = None):
        self.t = t or {}                       # token -> {word: count}  (expected counts)
        self.f_counts = f_counts or {}         # token -> total expected count
        self.a = a or {}                       # "l,m,j" -> {i: count}
        self.a_counts = a_counts or {}         # "l,m,j" -> total
        self.vocabulary = set(vocabulary or ())
        self.pairs = pairs
        self.iterations = iterations
        self.templates = templates or {}       # lifted task (its functions) -> expected count

    def log_prior(self, template: str) -> float:
        """log P(task's lifted form), up to a constant: (expected count + ALPHA), learned by EM."""
        return math.log(self.templates.get(template, 0.0) + ALPHA)

    # ---- probabilities -----------------------------------------------------------------
    def lexical(self, word: str, token: str) -> float:
        v = len(self.vocabulary) + 1
        counts = self.t.get(token)
        if counts is None:
            return 1.0 / v
        return (counts.get(word, 0.0) + DELTA) / (self.f_counts[token] + DELTA * v)

    def distortion(self, i: int, j: int, l: int, m: int) -> float:
        key = f"{l},{m},{j}"
        counts = self.a.get(key, {})
        total = self.a_counts.get(key, 0.0)
        return (counts.get(str(i), 0.0) + LAMBDA / (l + 1)) / (total + LAMBDA)

    def known(self, command_words: list[str]) -> list[str]:
        return [w for w in command_words if w in self.vocabulary]

    def log_likelihood(self, command_words: list[str], tokens) -> float:
        """log P(known words | tokens); unknown words are left out (they favour no task)."""
        e = self.known(command_words)
        f = [NULL] + list(tokens)
        l, m = len(f) - 1, len(e)
        total = 0.0
        for j, word in enumerate(e, 1):
            p = sum(self.distortion(i, j, l, m) * self.lexical(word, fi) for i, fi in enumerate(f))
            total += math.log(p)
        return total

    def chance(self, command_words: list[str]) -> float:
        """log-likelihood of the known words under a task of unseen tokens (the baseline)."""
        return len(self.known(command_words)) * -math.log(len(self.vocabulary) + 1)

    # ---- the interface interpret.rank uses (shared with loglinear.LogLinear) -------------
    def tokens(self, command: str) -> list[str]:
        return words(command)

    def log_posterior(self, command: str, tasks: list[str]) -> list[float]:
        """log P(task | command) over candidate task texts: prior x likelihood, normalised."""
        e = words(command)
        scores = []
        for text in tasks:
            tokens = tuple(t for fn, args in re.findall(r"(\w+)\(([^)]*)\)", text)
                           for t in [fn] + [a.strip() for a in args.split(",") if a.strip() != "agent"])
            fns = " ".join(sorted(re.findall(r"(\w+)\(", text)))
            scores.append(self.log_likelihood(e, tokens) + self.log_prior(fns))
        top = max(scores)
        z = top + math.log(sum(math.exp(s - top) for s in scores))
        return [s - z for s in scores]

    # ---- training ----------------------------------------------------------------------
    @classmethod
    def train(cls, pairs: list, iterations: int = 10, model1_iterations: int = 5) -> IBMModel2:
        """`pairs`: (command words, [(tokens, weight, template), ...]) with at least one task each;
        `weight` is the task's likelihood from the demonstration, `template` its lifted form."""
        vocabulary = {w for e, _ in pairs for w in e}
        model = cls(vocabulary=vocabulary, pairs=len(pairs))
        for it in range(model1_iterations + iterations):
            ibm1 = it < model1_iterations
            t = defaultdict(lambda: defaultdict(float))
            a = defaultdict(lambda: defaultdict(float))
            templates = defaultdict(float)
            for e, tasks in pairs:
                m = len(e)
                # E-step over the latent task: weight x prior x P(words | task), normalized
                scores = [math.log(w) + (model.log_prior(tp) + model.log_likelihood(e, tok) if it else 0.0)
                          for tok, w, tp in tasks]
                top = max(scores)
                post = [math.exp(s - top) for s in scores]
                z = sum(post)
                for (tokens, _, template), r in zip(tasks, post):
                    r /= z
                    templates[template] += r
                    if r < 1e-6:
                        continue
                    f = [NULL] + list(tokens)
                    l = len(f) - 1
                    for j, word in enumerate(e, 1):
                        probs = [(1.0 if ibm1 else model.distortion(i, j, l, m)) *
                                 (model.lexical(word, fi) if it else 1.0) for i, fi in enumerate(f)]
                        s = sum(probs)
                        for i, (fi, p) in enumerate(zip(f, probs)):
                            c = r * p / s
                            t[fi][word] += c
                            if not ibm1:
                                a[f"{l},{m},{j}"][str(i)] += c
            model.templates = dict(templates)
            model.t = {f: dict(ws) for f, ws in t.items()}
            model.f_counts = {f: sum(ws.values()) for f, ws in t.items()}
            if not ibm1:
                model.a = {k: dict(v) for k, v in a.items()}
                model.a_counts = {k: sum(v.values()) for k, v in a.items()}
            model.iterations = it + 1
        return model

    # ---- files -------------------------------------------------------------------------
    def to_json(self) -> dict:
        return {"format": FORMAT, "pairs": self.pairs, "iterations": self.iterations,
                "vocabulary": sorted(self.vocabulary), "templates": self.templates, "t": self.t, "a": self.a}

    @classmethod
    def from_json(cls, data, path: str | None = None) -> IBMModel2:
        if not isinstance(data, dict) or data.get("format") != FORMAT:
            raise BccError(f"not a translation model: expected \"format\": \"{FORMAT}\"", path)
        try:
            t = {f: {w: float(c) for w, c in ws.items()} for f, ws in data["t"].items()}
            a = {k: {i: float(c) for i, c in v.items()} for k, v in data["a"].items()}
            return cls(t=t, a=a, vocabulary=data["vocabulary"], f_counts={f: sum(ws.values()) for f, ws in t.items()},
                       a_counts={k: sum(v.values()) for k, v in a.items()}, pairs=int(data.get("pairs", 0)),
                       iterations=int(data.get("iterations", 0)),
                       templates={k: float(v) for k, v in data.get("templates", {}).items()})
        except (KeyError, TypeError, ValueError, AttributeError) as exc:
            raise BccError(f"malformed translation model: {exc}", path) from None

