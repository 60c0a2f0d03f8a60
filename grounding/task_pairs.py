"""Command/task-call pairs: which pairs are about tasks, the shipped ones, training and
measuring a task-call model (task_model.py) on them.

A pairs file line (pairs.py's format) is about a task when its dungeon's domain has
compound tasks: its `task` is then a call, `wall(1, 1, 3, 4, stone)`, checked against
the dungeon's tasks (calls.py). `grounding/corpus/task_commands.jsonl` holds the shipped
training pairs on `mason_yard`; the model `bcc command` uses on a dungeon with tasks
until you train your own is trained on them (about a second, once per process). A
prediction is right when it is the same call: the task and every argument.
"""
from __future__ import annotations

import functools
import random
import time
from collections import Counter, defaultdict
from pathlib import Path

from ..errors import BccError
from .calls import space_for

SHIPPED = Path(__file__).parent / "corpus" / "task_commands.jsonl"


def is_task_row(row: dict) -> bool:
    """Whether a pair is about a task of its dungeon (its domain has tasks)."""
    try:
        return bool(space_for(row["dungeon"]))
    except BccError as exc:
        raise (exc.at(row.get("path"), row["line"], 1) if row.get("line") else exc) from None


def check(rows: list[dict]) -> None:
    """Every task pair's call must be a task of its dungeon with values of the right types;
    its `task` is rewritten in canonical spelling."""
    for r in rows:
        r["task"] = space_for(r["dungeon"]).canonical(r["task"], (r.get("path"), r.get("line"), 1))


def shipped_rows() -> list[dict]:
    from .pairs import load
    rows = load(SHIPPED)
    check(rows)
    return rows


@functools.lru_cache(maxsize=1)
def shipped_model():
    """The task-call model trained on the shipped pairs."""
    return train(shipped_rows())[0]


def train(rows: list[dict]):
    """(model, seconds): a task-call model trained on the rows."""
    from .task_model import TaskCallModel
    t0 = time.perf_counter()
    model = TaskCallModel.train(rows, space_for)
    return model, time.perf_counter() - t0


def evaluate(model, rows: list[dict]) -> dict:
    """Exact-call accuracy of the model on the rows, overall and per `kind` (or `level`)."""
    out, by_kind = [], defaultdict(Counter)
    for r in rows:
        found = model.interpret(r["command"], space_for(r["dungeon"]))
        ok = found.task == r["task"]
        same_task = found.task is not None and found.task.split("(")[0] == r["task"].split("(")[0]
        kind = str(r.get("kind") or r.get("level") or "all")
        by_kind[kind].update(total=1, correct=int(ok), task_correct=int(same_task))
        out.append({"id": r.get("id"), "kind": kind, "command": r["command"], "task": r["task"],
                    "predicted": found.task, "correct": ok, "message": found.message})
    correct = sum(p["correct"] for p in out)
    return {"correct": correct, "total": len(out), "accuracy": correct / len(out) if out else 0.0,
            "task_accuracy": sum(c["task_correct"] for c in by_kind.values()) / len(out) if out else 0.0,
            "by_kind": {k: {"correct": c["correct"], "total": c["total"], "accuracy": c["correct"] / c["total"],
                            "task_accuracy": c["task_correct"] / c["total"]} for k, c in sorted(by_kind.items())},
            "pairs": out}


def cross_validate(rows: list[dict], folds: int = 5, seed: int = 0) -> dict:
    """K-fold cross-validation over the rows (shuffled with `seed`): every row tested once by
    a model trained on the others."""
    if folds > len(rows):
        raise BccError(f"{folds} folds need at least {folds} pairs, found {len(rows)}")
    order = list(rows)
    random.Random(seed).shuffle(order)
    results = []
    seconds = 0.0
    for k in range(folds):
        test = order[k::folds]
        model, s = train([r for i, r in enumerate(order) if i % folds != k])
        seconds += s
        results += evaluate(model, test)["pairs"]
    return _summary(results) | {"folds": folds, "seed": seed, "train_seconds": round(seconds / folds, 3)}


def _summary(pairs: list[dict]) -> dict:
    by_kind = defaultdict(Counter)
    for p in pairs:
        by_kind[p["kind"]].update(total=1, correct=int(p["correct"]))
    correct = sum(p["correct"] for p in pairs)
    return {"correct": correct, "total": len(pairs), "accuracy": correct / len(pairs) if pairs else 0.0,
            "by_kind": {k: {"correct": c["correct"], "total": c["total"], "accuracy": c["correct"] / c["total"]}
                        for k, c in sorted(by_kind.items())}, "pairs": pairs}
