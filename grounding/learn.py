"""From pairs to a trained translation model: task spaces per dungeon, explanations, EM.

The glue between the dataset (rows), task inference and IBM Model 2; the CLI and the
corpus generator both go through here, so a pair is explained the same way everywhere.
"""
from __future__ import annotations

import functools
import re
import time

from ..errors import BccError
from ..demonstration import Demonstration
from .infer import explanations
from .ensemble import Ensemble
from .tasks import TaskSpace
from .translation import IBMModel2, words


@functools.lru_cache(maxsize=64)
def space_for(ref: str) -> TaskSpace:
    """The candidate tasks of a dungeon (compiled once per process)."""
    from ..compiler import compile_dungeon
    return TaskSpace(compile_dungeon(ref), ref)


@functools.lru_cache(maxsize=64)
def candidates(ref: str) -> list[str]:
    """Candidate task texts of a dungeon from its start (computed once per process)."""
    space = space_for(ref)
    return [t.text for t in space.tasks(space.model.initial)]


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


def train(rows, candidates_of=None, scene_of_row=None) -> tuple[Ensemble, float]:
    """The grounding model (log-linear models voting, ensemble.py) trained on rows with `command`, `dungeon` and `explanations`
    ([{task, weight}]), and the training time in seconds. A row's negatives are its
    dungeon's candidate tasks from the start, or `candidates_of(row)`; its scene (the rooms
    and where things are, for the member that reads routes) is its dungeon's from the
    start, or `scene_of_row(row)`."""
    from .route import scene_of
    t0 = time.perf_counter()
    examples, scenes = [], []
    for r in rows:
        target = {x["task"]: float(x["weight"]) for x in r["explanations"] if float(x["weight"]) > 0}
        if not target or not r["command"].strip():
            continue
        cands = candidates_of(r) if candidates_of else candidates(r["dungeon"])
        examples.append((r["command"], cands + [t for t in target if t not in cands], target))
        scenes.append(scene_of_row(r) if scene_of_row else scene_of(space_for(r["dungeon"])))
    if not examples:
        raise BccError("no pair to train on")
    model = Ensemble.train(examples, scenes=scenes)
    return model, time.perf_counter() - t0


def add_pair(dungeon: str, command_text: str, demo_path, db=None) -> dict:
    """`bcc learn`: add the pair (command, the demonstration in `demo_path`) to the dataset
    `db` (None: the default one) with the tasks it explains; returns what was stored.
    BccError when the command is empty, the demonstration was recorded elsewhere, or it
    explains no task."""
    from ..compiler import compile_dungeon
    from ..errors import BccError
    from .dataset import Dataset
    if not command_text.strip():
        raise BccError("the command is empty")
    model = compile_dungeon(dungeon)
    _same_dungeon(dungeon, demo_path)
    demo = Demonstration.load(demo_path, model)
    explained = explain(demo, dungeon)
    if not explained:
        raise BccError("the demonstration explains no task: its last state must achieve something no earlier "
                       "state did", demo_path)
    data = Dataset(db)
    try:
        row = data.add_pair(command_text, dungeon, demo.to_json() | {"command": command_text}, explained)
        total = data.count()
    finally:
        data.close()
    return {"id": row, "command": command_text, "dungeon": dungeon, "task": explained[0]["task"],
            "explanations": [{"task": e["task"], "weight": e["weight"]} for e in explained],
            "pairs": total, "db": str(data.path)}


def _same_dungeon(dungeon: str, demo_path: str) -> None:
    """The demonstration must have been recorded in the dungeon it is learned for."""
    import json
    from pathlib import Path

    from ..compiler import resolve_dungeon_path
    from ..errors import BccError
    try:
        recorded = json.loads(Path(demo_path).read_text(encoding="utf-8")).get("dungeon")
    except (OSError, ValueError, AttributeError):
        return   # unreadable or not an object: Demonstration.load says what is wrong
    if not isinstance(recorded, str):
        return

    def where(ref, base=None):
        if base is not None and not Path(ref).is_absolute() and (Path(base) / ref).is_file():
            ref = str(Path(base) / ref)
        try:
            return resolve_dungeon_path(ref).resolve()
        except BccError:
            return None
    if where(recorded, Path(demo_path).parent) != where(dungeon):
        raise BccError(f"the demonstration was recorded in {recorded!r}, not in {dungeon!r}", demo_path)
