"""Settings chosen by cross-validation inside the training pairs only (nested cross-validation).

Choosing the ensemble's votes by reading the very folds that are then reported flatters
the figure: with about 650 commands a level, a point is six commands, and a dozen tries
will find a setting that is a point better on those folds by luck. Here every choice is
made by an inner `INNER`-fold cross-validation over the training pairs alone: each member
of the pool (`POOL`) is trained once per inner split, its log-probabilities for the inner
held-out commands are kept, and every configuration in `CONFIGS` (one vote per pool
member; a vote of 0 leaves the member out) is scored on them by the ensemble's own rule
(ensemble.vote). The configuration right most often (the first on a tie: they are listed
from the shipped one on) is trained on all the training pairs. An outer fold's
held-out commands are never seen before its configuration is fixed, so the outer figure
is an honest estimate of what the choice procedure does on new commands.

Cost: per outer fold, `INNER` trainings of the pool on two thirds of its training pairs,
and one of the chosen members on all of them -- about three times plain cross-validation.
"""
from __future__ import annotations

from .bayes import NaiveBayes
from .ensemble import Ensemble, vote
from .loglinear import LogLinear
from .network import Network

INNER = 3
# the members a configuration may vote with: (name, model class, training options)
POOL = (("words", LogLinear, {"skips": 0}),
        ("skips", LogLinear, {"skips": 4}),
        ("whole", LogLinear, {"skips": 0, "factored": False}),
        ("bayes", NaiveBayes, {}),
        ("network", Network, {}))
# (name, one vote per POOL member): at most about a dozen, so that luck on the inner folds
# has few tries; the shipped votes first (ensemble.MEMBERS)
CONFIGS = (("shipped", (1, 1, 1, 0.2, 1.5)),
           ("equal", (1, 1, 1, 1, 1)),
           ("no-bayes", (1, 1, 1, 0, 1.5)),
           ("network-3", (1, 1, 1, 0.2, 3)),
           ("network-0.75", (1, 1, 1, 0.2, 0.75)),
           ("log-linear", (1, 1, 1, 0.2, 0)),
           ("network-alone", (0, 0, 0, 0, 1)),
           ("whole-2", (1, 1, 2, 0.2, 1.5)),
           ("factored", (1, 1, 0, 0.2, 1.5)),
           ("bayes-0.5", (1, 1, 1, 0.5, 1.5)),
           ("no-skips", (1, 0, 1, 0.2, 1.5)))


def choose(examples: list, rows_of, splits) -> tuple[str, dict]:
    """(the name of the configuration right most often over the inner `splits`, {name:
    inner accuracy}). `examples[k]` is training pair k as (command, candidates, {task:
    weight}); `splits` are (training indices, held-out indices); `rows_of(k)` is pair k's
    correct task text, the one a prediction is checked against."""
    right = {name: 0 for name, _ in CONFIGS}
    total = 0
    for train_ix, test_ix in splits:
        members = [kind.train([examples[k] for k in train_ix], **options) for _, kind, options in POOL]
        for k in test_ix:
            command, candidates, _ = examples[k]
            knows = [getattr(m, "knows", lambda _: True)(candidates) for m in members]
            scores = [m.log_posterior(command, candidates) for m in members]
            truth = rows_of(k)
            for name, weights in CONFIGS:
                s = vote(weights, scores, knows)
                right[name] += candidates[int(s.argmax())] == truth
            total += 1
    accuracy = {name: right[name] / max(total, 1) for name, _ in CONFIGS}
    best = max(CONFIGS, key=lambda c: (accuracy[c[0]], -CONFIGS.index(c)))[0]
    return best, accuracy


def train(examples: list, config: str) -> Ensemble:
    """The ensemble of `config` (a name in CONFIGS): the members it gives a vote, trained on `examples`."""
    weights = dict(CONFIGS)[config]
    members = [(kind, options, w) for (_, kind, options), w in zip(POOL, weights) if w > 0]
    return Ensemble.train(examples, members)
