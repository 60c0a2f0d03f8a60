"""Several log-linear models that vote: the mean of their log P(task | command).

Models trained on the same pairs with different command features (words and adjacent
pairs; also pairs of words a few apart) are about as accurate alone and wrong on
different commands; averaging their log-probabilities was right more often than either
in 10-fold cross-validation on the cleanup-amt corpus with two different shuffles
(bench/corpus.py reports the figures). The members are ordinary `LogLinear` models.
"""
from __future__ import annotations

import numpy as np

from ..errors import BccError
from .loglinear import FORMAT as MEMBER_FORMAT, LogLinear
from .model_file import JsonModelFile

FORMAT = "bcc-ensemble/1"
MEMBERS = ({"skips": 0}, {"skips": 4})   # the training options of each member


class Ensemble(JsonModelFile):
    def __init__(self, members: list[LogLinear]):
        if not members:
            raise BccError("an ensemble needs at least one model")
        self.members = members
        first = members[0]
        self.speller, self.vocabulary = first.speller, first.vocabulary
        self.pairs = first.pairs
        self.iterations = max(m.iterations for m in members)

    @classmethod
    def train(cls, examples: list, members=MEMBERS) -> Ensemble:
        """One `LogLinear` per options dict in `members`, each trained on all `examples`."""
        return cls([LogLinear.train(examples, **options) for options in members])

    # ---- the interface interpret.rank uses (shared with LogLinear) ---------------------
    def tokens(self, command: str) -> list[str]:
        return self.members[0].tokens(command)

    def known(self, command_words: list[str]) -> list[str]:
        return self.members[0].known(command_words)

    def log_posterior(self, command: str, tasks: list[str]) -> list[float]:
        s = np.mean([m.log_posterior(command, tasks) for m in self.members], axis=0)
        s -= s.max()
        return list(s - np.log(np.exp(s).sum()))

    # ---- files -------------------------------------------------------------------------
    def to_json(self) -> dict:
        return {"format": FORMAT, "pairs": self.pairs, "members": [m.to_json() for m in self.members]}

    @classmethod
    def from_json(cls, data, path: str | None = None) -> Ensemble:
        if not isinstance(data, dict) or data.get("format") != FORMAT:
            raise BccError(f"not a grounding model: expected \"format\": \"{FORMAT}\"", path)
        members = data.get("members")
        if not isinstance(members, list) or not members or \
                any(not isinstance(m, dict) or m.get("format") != MEMBER_FORMAT for m in members):
            raise BccError(f"malformed grounding model: \"members\" must be a non-empty list of "
                           f"\"{MEMBER_FORMAT}\" models", path)
        return cls([LogLinear.from_json(m, path) for m in members])
