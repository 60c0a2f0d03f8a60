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

import numpy as np
from scipy.optimize import minimize

from .bayes import NaiveBayes
from .ensemble import Ensemble, member_scores, train_member, vote
from .loglinear import LogLinear
from .network import Network
from .route_model import RouteModel

INNER = 3
# the members a configuration may vote with: (name, model class, training options); the
# route reader's member twice, once voting on routes of rooms and doors, once on steps, so
# that a stacked vote can weigh the two readings apart
POOL = (("words", LogLinear, {"skips": 0}),
        ("skips", LogLinear, {"skips": 4}),
        ("whole", LogLinear, {"skips": 0, "factored": False}),
        ("bayes", NaiveBayes, {}),
        ("network", Network, {}),
        ("letters", LogLinear, {"skips": 0, "factored": False, "chars": 4}),
        ("route", RouteModel, {"reads": "routes"}),
        ("steps", RouteModel, {"reads": "steps"}))
STACKED = "stacked"
# (name, one vote per POOL member): at most about a dozen, so that luck on the inner folds
# has few tries; first the votes shipped until the step reader ("shipped", naive Bayes
# 0.2); ensemble.MEMBERS ships the one an inner cross-validation over the whole corpus
# chose ("no-bayes": bench/corpus.py --choose). STACKED has no fixed votes:
# they are fitted to the inner held-out scores (stack_votes).
CONFIGS = (("shipped", (1, 1, 1, 0.2, 1.5, 0, 1, 1)),
           ("no-route", (1, 1, 1, 0.2, 1.5, 0, 0, 0)),
           ("no-bayes", (1, 1, 1, 0, 1.5, 0, 1, 1)),
           ("network-3", (1, 1, 1, 0.2, 3, 0, 1, 1)),
           ("route-0.5", (1, 1, 1, 0.2, 1.5, 0, 0.5, 0.5)),
           ("route-2", (1, 1, 1, 0.2, 1.5, 0, 2, 2)),
           ("whole-2", (1, 1, 2, 0.2, 1.5, 0, 1, 1)),
           ("factored", (1, 1, 0, 0.2, 1.5, 0, 1, 1)),
           ("bayes-0.5", (1, 1, 1, 0.5, 1.5, 0, 1, 1)),
           ("letters", (1, 1, 1, 0.2, 1.5, 1, 1, 1)),
           ("network-3-no-route", (1, 1, 1, 0.2, 3, 0, 0, 0)),
           (STACKED, None))
RIDGE = 1e-3       # penalty on the squared stacked votes: keeps them finite when members agree


def choose(examples: list, rows_of, splits, scenes: list | None = None) -> tuple[str, dict, tuple]:
    """(the name of the configuration right most often over the inner `splits`, {name:
    inner accuracy}, its votes). `examples[k]` is training pair k as (command, candidates,
    {task: weight}); `splits` are (training indices, held-out indices); `rows_of(k)` is
    pair k's correct task text, the one a prediction is checked against. The stacked
    votes are judged by cross-fitting: on each split's held-out commands, the votes
    fitted to the other splits' held-out commands; chosen, they are fitted to all.
    `scenes[k]` is pair k's scene for the member that reads routes (route.Scene, or None)."""
    held = []                 # per split: [(scores per member, knows per member, index of the truth)]
    for train_ix, test_ix in splits:
        members = [train_member(kind, [examples[k] for k in train_ix], options,
                                [scenes[k] for k in train_ix] if scenes else None) for _, kind, options in POOL]
        part = []
        for k in test_ix:
            command, candidates, _ = examples[k]
            scores, knows = member_scores(members, (1,) * len(POOL), command, candidates,
                                          scenes[k] if scenes else None)
            truth = rows_of(k)
            part.append((scores, knows, candidates.index(truth) if truth in candidates else -1))
        held.append(part)
    votes = {name: weights for name, weights in CONFIGS if weights is not None}
    right = {name: 0 for name, _ in CONFIGS}
    for j, part in enumerate(held):
        fitted = {name: w for name, w in votes.items()}
        if any(name == STACKED for name, _ in CONFIGS):
            others = [r for i, p in enumerate(held) if i != j for r in p] or part
            fitted[STACKED] = stack_votes(others)
        for scores, knows, truth in part:
            for name, weights in fitted.items():
                right[name] += int(vote(weights, scores, knows).argmax()) == truth
    total = sum(len(p) for p in held)
    accuracy = {name: right[name] / max(total, 1) for name, _ in CONFIGS}
    best = max(CONFIGS, key=lambda c: (accuracy[c[0]], -CONFIGS.index(c)))[0]
    return best, accuracy, votes[best] if best in votes else stack_votes([r for p in held for r in p])


def stack_votes(records: list) -> tuple:
    """Votes (one per POOL member, non-negative) that maximise the log-probability of the
    right task under the vote of held-out scores `records` [(scores per member, knows per
    member, index of the truth)], with a small ridge; a member that does not know a
    record's tasks adds nothing to it. All zero for the members that read words (no
    member helps, or only the route reader, which abstains on most commands): equal votes."""
    records = [r for r in records if r[2] >= 0]
    m = len(POOL)
    if not records:
        return (1.0,) * m
    by_size: dict = {}
    for scores, knows, truth in records:
        size = len(next(s for s in scores if s is not None))
        stack = np.array([s if k and s is not None else np.zeros(size) for s, k in zip(scores, knows)])
        by_size.setdefault(stack.shape[1], []).append((stack, truth))
    blocks = [(np.array([s for s, _ in group]), np.array([t for _, t in group])) for group in by_size.values()]

    def value_and_gradient(w):
        loss, grad = 0.0, np.zeros(m)
        for S, truth in blocks:                # S: records x members x candidates
            z = np.einsum("m,rmc->rc", w, S)
            z -= z.max(axis=1, keepdims=True)
            p = np.exp(z)
            p /= p.sum(axis=1, keepdims=True)
            rows = np.arange(len(truth))
            loss -= float(np.log(np.maximum(p[rows, truth], 1e-300)).sum())
            grad -= np.einsum("rmc,rc->m", S, np.eye(S.shape[2])[truth] - p)
        n = len(records)
        return loss / n + RIDGE * float(w @ w), grad / n + 2 * RIDGE * w
    fit = minimize(value_and_gradient, np.ones(m), jac=True, method="L-BFGS-B", bounds=[(0, None)] * m)
    w = np.round(np.maximum(fit.x, 0.0), 4)
    reads_words = [k for k, (_, kind, _) in enumerate(POOL) if not getattr(kind, "reads_world", False)]
    if not any(w[k] > 0 for k in reads_words):     # an ensemble needs a member that reads words
        return (1.0,) * m
    return tuple(float(x) for x in w)


def train(examples: list, weights, scenes: list | None = None) -> Ensemble:
    """The ensemble voting with `weights` (one per POOL member, e.g. a configuration's or
    the stacked ones): the members it gives a vote, trained on `examples` (and their
    `scenes`, for the member that reads routes)."""
    members = [(kind, options, w) for (_, kind, options), w in zip(POOL, weights) if w > 0]
    return Ensemble.train(examples, members, scenes)
