"""From pairs to a trained translation model: task spaces per dungeon, explanations, EM.

The glue between the dataset (rows), task inference and IBM Model 2; the CLI and the
corpus generator both go through here, so a pair is explained the same way everywhere.
"""
from __future__ import annotations

import functools
import re
import time

from .demonstration import Demonstration
from .infer import explanations
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


def train(rows) -> tuple[IBMModel2, float]:
    """A model trained on the rows, and the training time in seconds."""
    t0 = time.perf_counter()
    model = IBMModel2.train(training_pairs(rows))
    return model, time.perf_counter() - t0
