"""P(task | command, world): which task a route's outcome asks for, learned from pairs.

The route reader (route.py) says where a command's route ends -- the agent's room, each
thing's room, whether each was moved, what the agent ends with -- as a distribution over
outcomes. Which task that is, is a convention of the people who speak: "bring the chair
to the blue room" ends with the agent in blue too, yet asks only for the chair there;
"go to the red room, bring the chair to green and come back" asks for both. So a
conditional logit learns it: a task's features relate each of its atoms to the outcome
(the agent's or a thing's room atom naming where it ends, where it started, or another
room; a thing's atom when the thing was moved or not; no atom about the agent when it
ends with a thing it carried, ...), averaged over the outcomes by their shares. The
features name no room, thing or dungeon, so what is learned in one dungeon reads routes
in another. The member abstains on commands the reader does not read as routes and in
dungeons without rooms (ensemble.py: `reads`).
"""
from __future__ import annotations

import re

import numpy as np
from scipy.optimize import minimize

from ..errors import BccError
from .model_file import JsonModelFile, expect_format
from .route import Scene, read
from .steps import BETAS

FORMAT = "bcc-route/1"
ROUTES, STEPS, BOTH = "routes", "steps", "both"
READS = (ROUTES, STEPS, BOTH)     # which commands a member votes on: routes of rooms and doors, steps, or both
L2 = 0.01                  # penalty per weight on the mean log-likelihood
ATOM = re.compile(r"(\w+)\(([^)]*)\)")


def features(task: str, outcomes: list, scene: Scene) -> dict:
    """{feature: value} of a candidate task against the outcomes [(share, Outcome)]."""
    world = scene.world
    agent_atoms = {a: r for r, a in world.room_atoms.items()}
    thing_atoms = {a: (t, r) for t, (_, by_room) in world.things.items() for r, a in by_room.items()}
    start = dict(scene.things)
    atoms = [f"{fn}({args})" for fn, args in ATOM.findall(task)]
    out: dict = {}
    for share, o in outcomes:
        ends = {t: (r, moved) for t, r, moved in o.things}
        f = [f"atoms:{len(atoms)}"]
        about_agent = [agent_atoms[a] for a in atoms if a in agent_atoms]
        about = {}
        for a in atoms:
            if a in thing_atoms:
                t, r = thing_atoms[a]
                about.setdefault(t, []).append(r)
        others = [a for a in atoms if a not in agent_atoms and a not in thing_atoms]
        f += [f"other:{ATOM.match(a).group(1)}" for a in others]
        carried_moved = any(moved and r == o.agent for r, moved in ends.values())
        if about_agent:
            for r in about_agent:
                f.append("agent:" + ("end" if r == o.agent else "start" if r == scene.agent else "elsewhere") +
                         (":moved" if o.agent_moved else ":still"))
        else:
            f.append("agent:none:" + ("with-moved-thing" if carried_moved else "moved" if o.agent_moved else "still"))
        for t, (end, moved) in ends.items():
            rooms = about.get(t, [])
            state = "moved" if moved else "still"
            if not rooms:
                f.append(f"thing:none:{state}")
            for r in rooms:
                f.append("thing:" + ("end" if r == end else "start" if r == start.get(t) else "elsewhere") + ":" + state)
            if len(rooms) > 1:
                f.append("thing:twice")
        if o.walked:      # people who give steps speak by other conventions: weights of their own
            f = ["steps:" + name for name in f]
        for name in f:
            out[name] = out.get(name, 0.0) + share
    return out


class RouteModel(JsonModelFile):
    reads_world = True

    def __init__(self, weights: dict, beta: float = BETAS[1], reads: str = BOTH):
        self.weights = dict(weights)
        self.beta = float(beta)       # the weight of one fault of a command given as steps (steps.py)
        self.reads = reads            # READS: the commands it votes on (routes, steps or both)
        self.iterations = 0

    def log_posterior(self, command: str, tasks: list[str], scene: Scene | None = None) -> list[float] | None:
        """log P(task | command) over `tasks`, or None when the command is no route there."""
        outcomes = _read(command, scene, self.beta, self.reads)
        if outcomes is None:
            return None
        s = np.array([sum(self.weights.get(k, 0.0) * v for k, v in features(t, outcomes, scene).items())
                      for t in tasks])
        s -= s.max()
        return list(s - np.log(np.exp(s).sum()))

    @classmethod
    def train(cls, examples: list, scenes: list | None = None, l2: float = L2, reads: str = BOTH) -> RouteModel:
        """Fit the weights to `examples` [(command, candidates, {task: weight})] whose command
        reads as a route in its scene (`scenes[k]`, parallel to the examples; `reads`: only
        routes of rooms and doors, only steps, or both), and the weight of a fault in
        commands given as steps: the one of `BETAS` whose fit is the most likely (a
        parameter like the others, fitted to the training pairs alone)."""
        if reads not in READS:
            raise BccError(f"a route member reads one of {', '.join(READS)}, not {reads!r}")
        fits = [_fit(examples, scenes, l2, beta, reads) for beta in (BETAS if reads != ROUTES else BETAS[1:2])]
        loss, model = min(fits, key=lambda f: f[0])
        return model

    def to_json(self) -> dict:
        return {"format": FORMAT, "weights": self.weights, "beta": self.beta, "reads": self.reads}

    @classmethod
    def from_json(cls, data, path: str | None = None) -> RouteModel:
        expect_format(data, FORMAT, path)
        weights = data.get("weights")
        if not isinstance(weights, dict) or any(isinstance(v, bool) or not isinstance(v, (int, float))
                                                for v in weights.values()):
            raise BccError("malformed grounding model: \"weights\" must map features to numbers", path)
        beta = data.get("beta", BETAS[1])
        if isinstance(beta, bool) or not isinstance(beta, (int, float)) or not 0 < beta < 1e6:
            raise BccError("malformed grounding model: \"beta\" must be a positive number", path)
        reads = data.get("reads", BOTH)
        if reads not in READS:
            raise BccError(f"malformed grounding model: \"reads\" must be one of {', '.join(READS)}", path)
        return cls(weights, beta, reads)


def _read(command: str, scene, beta: float, reads: str):
    """The reader's outcomes, or None when the command is not of the kind `reads` names."""
    outcomes = read(command, scene, beta)
    if outcomes is None or reads == BOTH or (reads == STEPS) == outcomes[0][1].walked:
        return outcomes
    return None


def _fit(examples: list, scenes: list | None, l2: float, beta: float, reads: str = BOTH) -> tuple[float, RouteModel]:
    """(the penalised mean negative log-likelihood, the model) of the weights fitted with
    steps read at `beta`."""
    rows = []
    for k, (command, candidates, target) in enumerate(examples):
        scene = scenes[k] if scenes else None
        outcomes = _read(command, scene, beta, reads)
        if outcomes is None:
            continue
        rows.append(([features(t, outcomes, scene) for t in candidates],
                     np.array([float(target.get(t, 0.0)) for t in candidates])))
    index = {f: i for i, f in enumerate(sorted({f for fs, _ in rows for d in fs for f in d}))}
    if not rows or not index:
        return 0.0, RouteModel({}, beta, reads)
    blocks = []
    for fs, y in rows:
        X = np.zeros((len(fs), len(index)))
        for j, d in enumerate(fs):
            for f, v in d.items():
                X[j, index[f]] = v
        blocks.append((X, y / y.sum() if y.sum() > 0 else y))
    n = len(blocks)

    def value_and_gradient(w):
        loss, grad = 0.0, np.zeros(len(index))
        for X, y in blocks:
            z = X @ w
            z -= z.max()
            p = np.exp(z)
            p /= p.sum()
            loss -= float(y @ np.log(np.maximum(p, 1e-300)))
            grad -= X.T @ (y - p * y.sum())
        return loss / n + l2 * float(w @ w), grad / n + 2 * l2 * w
    fit = minimize(value_and_gradient, np.zeros(len(index)), jac=True, method="L-BFGS-B")
    model = RouteModel({f: round(float(fit.x[i]), 6) for f, i in index.items() if abs(fit.x[i]) > 1e-9}, beta, reads)
    model.iterations = int(fit.nit)
    return float(fit.fun), model
