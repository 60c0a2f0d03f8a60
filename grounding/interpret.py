"""A command in a dungeon -> the most probable task, and a plan that carries it out.

The grounding model gives P(task | command) over the dungeon's candidate tasks from the
start (loglinear.py; IBM Model 2 for older model files). A task is *plausible* when its
posterior beats chance (one over the number of candidates); if none does, or if at least
half of the words (spelling corrected) were never seen in training, the command is not
understood.
"""
from __future__ import annotations

import dataclasses
import functools
import math
import re
from dataclasses import dataclass, field

from ..model import Model
from .tasks import TaskSpace
from .text import words

TOP = 5              # candidates reported


@dataclass
class Interpretation:
    command: str
    task: str | None                   # canonical text of the chosen task, None if no task is plausible
    candidates: list                   # [(task text, posterior score)], best first, plausible ones only
    unknown_words: list
    message: str = ""
    result: object = None              # the solver's Result for the chosen task
    all_scores: list = field(default_factory=list, repr=False)

    def to_json(self) -> dict:
        r = self.result
        return {"command": self.command, "task": self.task,
                "candidates": [{"task": t, "score": round(s, 6)} for t, s in self.candidates],
                "unknown_words": self.unknown_words,
                "solved": bool(r is not None and r.solved), "plan": list(r.plan) if r is not None and r.solved else [],
                "cost": r.cost if r is not None and r.solved else None, "message": self.message}


def rank(translation, space: TaskSpace, start: bytes, command: str, unseen_names_refused: bool = False) -> Interpretation:
    """Score every candidate task of the dungeon from `start` against the command.

    `translation` is a grounding model: the log-linear model (loglinear.py) or, from an
    older model file, IBM Model 2 (translation.py). With `unseen_names_refused`, a command
    that names one of the tasks' things (an object, a room, a block type) with a word the
    model never saw is not understood: the model was not trained for this dungeon, and its
    best guess ignores the very word that says what to do (`bcc command` acts on it)."""
    e = translation.tokens(command)
    unknown = sorted({w for w, n in zip(words(command), e) if n not in translation.vocabulary})
    tasks = [t.text for t in space.tasks(start)]
    if not tasks:
        return Interpretation(command, None, [], unknown, "the dungeon offers no task from this start")
    unseen = sorted(set(unknown) & _task_names(tasks)) if unseen_names_refused else []
    if unseen:
        return Interpretation(command, None, [], unknown,
                              f"the model never saw {', '.join(map(repr, unseen))}, which this dungeon's tasks name: "
                              "train it on commands for this dungeon (bcc train --pairs FILE)")
    if getattr(translation, "reads_scenes", False):
        from .route import scene_of
        scores = translation.log_posterior(command, tasks, scene_of(space, start))
    else:
        scores = translation.log_posterior(command, tasks)
    chance = -math.log(len(tasks))
    posterior = sorted(((t, math.exp(s), s > chance + 1e-9 or len(tasks) == 1) for t, s in zip(tasks, scores)),
                       key=lambda x: (-x[1], x[0]))
    plausible = [(t, p) for t, p, ok in posterior if ok]
    known = translation.known(e)
    if not known:
        return Interpretation(command, None, [], unknown, "no word of the command was seen in training",
                              all_scores=posterior)
    if len(known) <= len(e) - len(known):
        return Interpretation(command, None, [], unknown, "most words of the command were never seen in training",
                              all_scores=posterior)
    if not plausible:
        return Interpretation(command, None, [], unknown, "no task explains the command better than chance",
                              all_scores=posterior)
    return Interpretation(command, plausible[0][0], plausible[:TOP], unknown, all_scores=posterior)


def _task_names(tasks: list) -> set:
    """The lowercase names the tasks pass to their functions (agent, red, chair, ...)."""
    return {name.lower() for t in tasks for args in re.findall(r"\(([^()]*)\)", t)
            for name in re.findall(r"[A-Za-z_][A-Za-z0-9_]*", args)}


@functools.lru_cache(maxsize=64)
def goal_model(model_ref: str, task: str) -> Model:
    from ..compiler import compile_dungeon
    return compile_dungeon(model_ref, goal=task)


def plan(model_ref: str, task: str, start: bytes | None, budget):
    """Solve the chosen task with A* from `start` (default: the dungeon's start), on the
    one run path every edge takes (run/solve.py); the caller bounds the process."""
    from ..run.solve import Request, run
    goal_model_: Model = goal_model(model_ref, task)
    options = {}
    if start is not None and start != goal_model_.initial:
        # the pattern database is built for the compiled start; Manhattan holds from anywhere
        goal_model_ = dataclasses.replace(goal_model_, initial=start)
        options["heuristic"] = "manhattan"
    return run(Request(load=lambda: goal_model_, solver="astar", options=options, budget=budget, hard=False)).result
