"""From pairs to a trained translation model: task spaces per dungeon, explanations, EM.

The glue between the dataset (rows), task inference and IBM Model 2; the CLI and the
corpus generator both go through here, so a pair is explained the same way everywhere.
"""
from __future__ import annotations

import functools
import re
import time

from ..errors import BccError
from .demonstration import Demonstration
from .infer import explanations
from .loglinear import LogLinear
from .tasks import TaskSpace
from .translation import IBMModel2, words


@functools.lru_cache(maxsize=64)
def space_for(ref: str) -> TaskSpace:
    """The candidate tasks of a dungeon (compiled once per process)."""
    from ..compiler import compile_dungeon
    return TaskSpace(compile_dungeon(ref), ref)


def explain(demo: Demonstration, ref: str, optimality: bool = True) -> list[dict]:
    """The demonstration's explanations as stored rows: [{task, tokens, weight}], most likely first."""
    found = explanations(space_for(ref), demo.states, optimality=optimality)
    return [{"task": e.task.text, "tokens": list(e.task.tokens), "weight": e.weight} for e in found]


def template(task_text: str) -> str:
    """A task's lifted form: its functions, sorted (`agentHasBlock agentInRoom`)."""
    return " ".join(sorted(re.findall(r"(\w+)\(", task_text)))


def training_pairs(rows) -> list:
    """Rows with `command` and `explanations` -> (words, [(tokens, weight, lifted form)]) for EM."""
    out = []
    for r in rows:
        tasks = [(tuple(x["tokens"]), float(x["weight"]), template(x["task"]))
                 for x in r["explanations"] if x["weight"] > 0]
        e = words(r["command"])
        if tasks and e:
            out.append((e, tasks))
    return out


def train_ibm2(rows) -> tuple[IBMModel2, float]:
    """IBM Model 2 trained on the rows (the seed's model, kept as a baseline)."""
    t0 = time.perf_counter()
    model = IBMModel2.train(training_pairs(rows))
    return model, time.perf_counter() - t0


def train(rows, candidates_of=None) -> tuple[LogLinear, float]:
    """The log-linear model trained on rows with `command`, `dungeon` and `explanations`
    ([{task, weight}]), and the training time in seconds. A row's negatives are its
    dungeon's candidate tasks from the start, or `candidates_of(row)`."""
    from .pairs import candidates
    t0 = time.perf_counter()
    examples = []
    for r in rows:
        target = {x["task"]: float(x["weight"]) for x in r["explanations"] if float(x["weight"]) > 0}
        if not target or not r["command"].strip():
            continue
        cands = candidates_of(r) if candidates_of else candidates(r["dungeon"])
        examples.append((r["command"], cands + [t for t in target if t not in cands], target))
    if not examples:
        raise BccError("no pair to train on")
    model = LogLinear.train(examples)
    return model, time.perf_counter() - t0
