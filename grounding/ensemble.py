"""Several models that vote: the weighted mean of their log P(task | command).

Models trained on the same pairs with different command features (words and adjacent
pairs; also pairs of words a few apart) are about as accurate alone and wrong on
different commands; averaging their log-probabilities was right more often than either
in 10-fold cross-validation on the cleanup-amt corpus with two different shuffles
(bench/corpus.py reports the figures). A naive Bayes model (bayes.py), a different
family that is worse alone, adds a small vote: it breaks the log-linear models' ties
the other way often enough to be right more often over three shuffles. A third
log-linear model sees each task whole (not `factored`: one class per task, no shared
atoms), as naive Bayes does but discriminatively; an equal vote of it made the ensemble
right as often or more often on every level over three shuffles (bench/corpus.py). It
cannot score tasks it was never trained with (another dungeon's): there it abstains,
and the other members vote. A small feed-forward network (network.py) scores words
together rather than one by one; a vote of 1.5 for it raised L1 past its target on each
of three shuffles and kept L0 and L2 above theirs (bench/corpus.py). The members are
ordinary `LogLinear`, `NaiveBayes` and `Network` models.
"""
from __future__ import annotations

import numpy as np

from ..errors import BccError
from .bayes import FORMAT as BAYES, NaiveBayes
from .loglinear import FORMAT as LOGLINEAR, LogLinear
from .model_file import JsonModelFile, expect_format
from .network import FORMAT as NETWORK, Network

FORMAT = "bcc-ensemble/1"
# (model class, its training options, its vote): tuned by 10-fold cross-validation over
# three shuffles of the cleanup-amt corpus
MEMBERS = ((LogLinear, {"skips": 0}, 1.0), (LogLinear, {"skips": 4}, 1.0),
           (LogLinear, {"skips": 0, "factored": False}, 1.0), (NaiveBayes, {}, 0.2), (Network, {}, 1.5))
KINDS = {LOGLINEAR: LogLinear, BAYES: NaiveBayes, NETWORK: Network}


class Ensemble(JsonModelFile):
    def __init__(self, members: list, weights: list[float] | None = None):
        if not members:
            raise BccError("an ensemble needs at least one model")
        self.members = members
        self.weights = np.array(weights if weights is not None else [1.0] * len(members), dtype=np.float64)
        if len(self.weights) != len(members) or not (self.weights >= 0).all() or self.weights.sum() <= 0:
            raise BccError("an ensemble needs one non-negative weight per model, not all zero")
        first = members[0]
        self.speller, self.vocabulary = first.speller, first.vocabulary
        self.pairs = first.pairs
        self.iterations = max(m.iterations for m in members)

    @classmethod
    def train(cls, examples: list, members=MEMBERS) -> Ensemble:
        """One model per (class, options, weight) in `members`, each trained on all `examples`."""
        return cls([kind.train(examples, **options) for kind, options, _ in members], [w for _, _, w in members])

    # ---- the interface interpret.rank uses (shared with LogLinear) ---------------------
    def tokens(self, command: str) -> list[str]:
        return self.members[0].tokens(command)

    def known(self, command_words: list[str]) -> list[str]:
        return self.members[0].known(command_words)

    def log_posterior(self, command: str, tasks: list[str]) -> list[float]:
        knows = [getattr(m, "knows", lambda _: True)(tasks) for m in self.members]
        scores = [m.log_posterior(command, tasks) if w > 0 and k else None
                  for m, w, k in zip(self.members, self.weights, knows)]
        if all(s is None for s in scores):     # only members that cannot score these tasks have a vote
            scores = [m.log_posterior(command, tasks) for m in self.members]
        return list(vote(self.weights, scores, knows))

    # ---- files -------------------------------------------------------------------------
    def to_json(self) -> dict:
        return {"format": FORMAT, "pairs": self.pairs, "weights": [float(w) for w in self.weights],
                "members": [m.to_json() for m in self.members]}

    @classmethod
    def from_json(cls, data, path: str | None = None) -> Ensemble:
        expect_format(data, FORMAT, path)
        members = data.get("members")
        if not isinstance(members, list) or not members or \
                any(not isinstance(m, dict) or m.get("format") not in KINDS for m in members):
            raise BccError(f"malformed grounding model: \"members\" must be a non-empty list of "
                           f"{' or '.join(repr(k) for k in KINDS)} models", path)
        weights = data.get("weights")     # older files: equal votes
        if weights is not None and (not isinstance(weights, list) or
                                    len(weights) != len(members) or
                                    any(isinstance(w, bool) or not isinstance(w, (int, float)) or w < 0 for w in weights)
                                    or sum(weights) <= 0):
            raise BccError("malformed grounding model: \"weights\" must be one non-negative number per member, "
                           "not all zero", path)
        return cls([KINDS[m["format"]].from_json(m, path) for m in members], weights)


def vote(weights, scores: list, knows: list[bool]) -> np.ndarray:
    """The weighted mean of the members' log-probabilities over the same tasks, normalised:
    `scores[k]` is member k's (None when it has no vote), and a member that does not `know`
    the tasks abstains, unless only such members have a vote. The one rule, used by
    Ensemble.log_posterior and by the nested cross-validation's choice of votes (nested.py)."""
    weights = np.asarray(weights, dtype=np.float64)
    voting = [k for k, w in enumerate(weights) if w > 0 and knows[k]]
    if not voting:
        voting = [k for k, w in enumerate(weights) if w > 0]
    w = weights[voting]
    s = w @ np.array([scores[k] for k in voting]) / w.sum()
    s = s - s.max()
    return s - np.log(np.exp(s).sum())
