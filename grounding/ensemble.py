"""Several models that vote: the weighted mean of their log P(task | command).

Models trained on the same pairs with different command features (words and adjacent
pairs; also pairs of words a few apart) are about as accurate alone and wrong on
different commands; averaging their log-probabilities was right more often than either
in 10-fold cross-validation on the cleanup-amt corpus with two different shuffles
(bench/corpus.py reports the figures). A third log-linear model sees each task whole
(not `factored`: one class per task, no shared atoms), discriminatively; it cannot score
tasks it was never trained with (another dungeon's): there it abstains, and the other
members vote. A small feed-forward network (network.py) scores words together rather
than one by one. The route reader's member (route_model.py) votes twice, on commands
read as routes of rooms and doors and on commands given as steps; it abstains on the
others. Naive Bayes (bayes.py) and a model of letters are members a configuration may
give a vote (nested.py). Which members vote, and how much, is chosen by cross-validation
(`MEMBERS`); the members are ordinary `LogLinear`, `NaiveBayes`, `Network` and
`RouteModel` models.
"""
from __future__ import annotations

import numpy as np

from ..errors import BccError
from .bayes import FORMAT as BAYES, NaiveBayes
from .loglinear import FORMAT as LOGLINEAR, LogLinear
from .model_file import JsonModelFile, expect_format
from .network import FORMAT as NETWORK, Network
from .route_model import FORMAT as ROUTE, RouteModel

FORMAT = "bcc-ensemble/1"
# (model class, its training options, its vote): the configuration of nested.CONFIGS that
# a 3-fold cross-validation over the whole cleanup-amt corpus chose (`python
# bench/corpus.py --choose`, bench/corpus_votes.json: "no-bayes"), the procedure whose
# figures on commands it has not seen the nested cross-validation reports
MEMBERS = ((LogLinear, {"skips": 0}, 1.0), (LogLinear, {"skips": 4}, 1.0),
           (LogLinear, {"skips": 0, "factored": False}, 1.0), (Network, {}, 1.5),
           (RouteModel, {"reads": "routes"}, 1.0), (RouteModel, {"reads": "steps"}, 1.0))
KINDS = {LOGLINEAR: LogLinear, BAYES: NaiveBayes, NETWORK: Network, ROUTE: RouteModel}


class Ensemble(JsonModelFile):
    reads_scenes = True        # log_posterior takes the command's scene (route.Scene)
    def __init__(self, members: list, weights: list[float] | None = None):
        if not members:
            raise BccError("an ensemble needs at least one model")
        self.members = members
        self.weights = np.array(weights if weights is not None else [1.0] * len(members), dtype=np.float64)
        if len(self.weights) != len(members) or not (self.weights >= 0).all() or self.weights.sum() <= 0:
            raise BccError("an ensemble needs one non-negative weight per model, not all zero")
        first = next((m for m in members if not getattr(m, "reads_world", False)), None)
        if first is None:
            raise BccError("an ensemble needs a member that reads words, not only routes")
        self.speller, self.vocabulary = first.speller, first.vocabulary
        self.pairs = first.pairs
        self.iterations = max(m.iterations for m in members)
        self.first = first

    @classmethod
    def train(cls, examples: list, members=MEMBERS, scenes: list | None = None) -> Ensemble:
        """One model per (class, options, weight) in `members`, each trained on all `examples`;
        a member that reads routes (route_model.py) also gets each example's scene
        (`scenes`, parallel to `examples`; None: it learns nothing and abstains)."""
        return cls([train_member(kind, examples, options, scenes) for kind, options, _ in members],
                   [w for _, _, w in members])

    # ---- the interface interpret.rank uses (shared with LogLinear) ---------------------
    def tokens(self, command: str) -> list[str]:
        return self.first.tokens(command)

    def known(self, command_words: list[str]) -> list[str]:
        return self.first.known(command_words)

    def log_posterior(self, command: str, tasks: list[str], scene=None) -> list[float]:
        """The vote over `tasks`; `scene` (route.Scene: the dungeon's rooms and where things
        start) lets a member that reads routes vote too."""
        scores, knows = member_scores(self.members, self.weights, command, tasks, scene)
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


def train_member(kind, examples: list, options: dict, scenes: list | None = None):
    """One member trained on `examples`; one that reads routes also gets their scenes."""
    if getattr(kind, "reads_world", False):
        return kind.train(examples, scenes=scenes, **options)
    return kind.train(examples, **options)


def member_scores(members: list, weights, command: str, tasks: list[str], scene=None) -> tuple[list, list]:
    """(each member's log-probabilities of `tasks`, None when it has no vote; whether it
    knows them): a member abstains when it cannot score tasks it was never trained with
    (`knows`), or, reading routes, when the command is no route in `scene`. The one rule,
    used by Ensemble.log_posterior and by the nested cross-validation (nested.py)."""
    knows, scores = [], []
    for m, w in zip(members, weights):
        if getattr(m, "reads_world", False):
            s = m.log_posterior(command, tasks, scene) if w > 0 else None
            knows.append(s is not None)
            scores.append(None if s is None else np.asarray(s))
            continue
        k = getattr(m, "knows", lambda _: True)(tasks)
        knows.append(k)
        scores.append(np.asarray(m.log_posterior(command, tasks)) if w > 0 and k else None)
    words = [k for k, m in enumerate(members) if not getattr(m, "reads_world", False)]
    if all(scores[k] is None for k in words):
        # only members that cannot score these tasks have a vote: they all vote
        for k in words:
            scores[k] = np.asarray(members[k].log_posterior(command, tasks))
            knows[k] = knows[k] or weights[k] > 0
    return scores, knows


def vote(weights, scores: list, knows: list[bool]) -> np.ndarray:
    """The weighted mean of the members' log-probabilities over the same tasks, normalised:
    `scores[k]` is member k's (None when it has no vote), and a member that does not `know`
    the tasks abstains, unless only such members have a vote. The one rule, used by
    Ensemble.log_posterior and by the nested cross-validation's choice of votes (nested.py)."""
    weights = np.asarray(weights, dtype=np.float64)
    voting = [k for k, w in enumerate(weights) if w > 0 and knows[k]]
    if not voting:
        voting = [k for k, w in enumerate(weights) if w > 0 and scores[k] is not None]
    w = weights[voting]
    s = w @ np.array([scores[k] for k in voting]) / w.sum()
    s = s - s.max()
    return s - np.log(np.exp(s).sum())
