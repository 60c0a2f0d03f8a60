"""Command/task pairs from a JSON Lines file, and evaluating a fresh model on them.

A line is an object with at least `command` and `task` (a goal expression, or a task call
in a dungeon whose domain has tasks: task_pairs.py) and optionally `dungeon`, `level`,
`kind` (what sort of command it is, reported apart by task-call evaluations) and `id` --
the shape of the cleanup-amt corpus. `evaluate` trains a
model on training pairs only (given tasks, or tasks inferred from demonstrations planned
in the dungeon, as the crowd workers saw one) and scores it on held-out pairs: a
prediction is right when it is the same goal, conjunctions compared as sets.
"""
from __future__ import annotations

import contextlib

import json
import random
import time
from collections import Counter
from pathlib import Path

from ..errors import BccError, read_input
from .tasks import canonical

MODES = ("tasks", "demonstrations")


def load(path: str | Path, dungeon: str | None = None, levels=None) -> list[dict]:
    """The pairs of a file, each with `id`, `command`, `task` (canonical), `dungeon` and `level`;
    every line checked (bad lines are bad input: file:line:col). A line with no `dungeon`
    is in `dungeon`, or else in the one shipped dungeon that has all such lines' tasks
    (`inferred` is then set)."""
    text = read_input(path, "pairs")
    out = []
    for n, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        try:
            row = json.loads(line)
        except json.JSONDecodeError as exc:
            raise BccError(f"invalid JSON line: {exc.msg}", str(path), n, exc.colno) from None
        if not isinstance(row, dict):
            raise BccError("a line must be a JSON object with \"command\" and \"task\"", str(path), n, 1)
        for key in ("command", "task"):
            if not isinstance(row.get(key), str) or not row[key].strip():
                raise BccError(f"\"{key}\" must be a non-empty string", str(path), n, 1)
        ref = row.get("dungeon", dungeon)
        if ref is not None and not isinstance(ref, str):
            raise BccError("\"dungeon\" must be a string", str(path), n, 1)
        level = row.get("level")
        if level is not None and not isinstance(level, (str, int)) or isinstance(level, bool):
            raise BccError("\"level\" must be a string such as \"L2\"", str(path), n, 1)
        if levels and level not in levels:
            continue
        out.append({"id": row.get("id", n), "command": row["command"], "task": canonical(row["task"]),
                    "dungeon": ref, "level": str(level) if level is not None else "all", "line": n,
                    "path": str(path), "kind": row["kind"] if isinstance(row.get("kind"), str) else None})
    if not out:
        raise BccError("no pairs" + (f" at level {', '.join(levels)}" if levels else ""), str(path))
    missing = [r for r in out if r["dungeon"] is None]
    if missing:
        fits = dungeons_with({r["task"] for r in missing})
        if len(fits) != 1:
            which = f"several shipped dungeons have all the file's tasks ({', '.join(fits)})" if fits \
                else "no shipped dungeon has all the file's tasks"
            raise BccError(f"the pair names no dungeon and {which}: give one with --dungeon",
                           str(path), missing[0]["line"], 1)
        for r in missing:
            r["dungeon"], r["inferred"] = fits[0], True
    return out


def dungeons_with(tasks: set) -> list[str]:
    """The shipped dungeons whose candidate tasks include all of `tasks`: pairs that name
    no dungeon, such as the cleanup-amt corpus's, are read in the one their tasks are about."""
    from ..compiler.dungeon import shipped_dungeons
    from .learn import candidates
    from .calls import space_for
    fits = []
    for ref in shipped_dungeons():
        try:
            if space_for(ref):      # commanded by its tasks, not by goals (task_pairs.py)
                continue
            known = set(candidates(ref))
        except BccError:
            continue
        if tasks <= known:
            fits.append(ref)
    return fits


def check_tasks(rows: list[dict]) -> None:
    """Every pair's task must be a candidate task of its dungeon from the start."""
    from .learn import candidates, space_for
    for row in rows:
        try:
            space = space_for(row["dungeon"])
        except BccError as exc:  # e.g. no such dungeon: the pair that names it is the bad input
            raise exc.at(row["path"], row["line"], 1) from None
        if space.task(row["task"]) is None or row["task"] not in candidates(row["dungeon"]):
            raise BccError(f"{row['task']!r} is not a task of dungeon {row['dungeon']!r} from its start "
                           f"(its atoms: {', '.join(a.text for a in space.atoms)})", row["path"], row["line"], 1)


def demonstrated(ref: str, task: str, time_limit: float = 60.0) -> dict:
    """{task: weight} the seed's pipeline infers from an optimal demonstration of `task`."""
    key = (ref, task)
    if key not in _explained:
        from ..solvers import Budget
        from ..demonstration import from_actions
        from .interpret import plan
        from .learn import explain, space_for
        result = plan(ref, task, None, Budget(time_limit=time_limit, max_memory_mb=Budget.default().max_memory_mb))
        if not result.solved:
            raise BccError(f"no demonstration of {task!r} in {ref!r}: {result.message}")
        demo = from_actions(space_for(ref).model, result.plan)
        _explained[key] = {e["task"]: e["weight"] for e in explain(demo, ref)}
    return _explained[key]


_explained: dict = {}


def examples(rows: list[dict], mode: str) -> list:
    """Training examples of the log-linear model: (command, candidates, {task: weight})."""
    from .learn import candidates
    out = []
    for r in rows:
        target = {r["task"]: 1.0} if mode == "tasks" else demonstrated(r["dungeon"], r["task"])
        cands = candidates(r["dungeon"])
        extra = [t for t in target if t not in cands]
        out.append((r["command"], cands + extra, target))
    return out


def scenes(rows: list[dict]) -> list:
    """Each pair's scene (its dungeon's rooms and where things start: route.py), or None
    for a dungeon without rooms."""
    from .learn import space_for
    from .route import scene_of
    return [scene_of(space_for(r["dungeon"])) for r in rows]


def train(rows: list[dict], mode: str = "tasks"):
    from .ensemble import Ensemble
    return Ensemble.train(examples(rows, mode), scenes=scenes(rows))


def train_nested(rows: list[dict], mode: str = "tasks", seed: int = 0):
    """(the ensemble whose votes an inner cross-validation over `rows` alone chose, the
    chosen configuration's name, {configuration: inner accuracy}, its votes, one per
    member of nested.POOL): nested.py."""
    from . import nested
    train_examples = examples(rows, mode)
    inner = folds(list(range(len(rows))), nested.INNER, seed)
    where = scenes(rows)
    name, accuracy, weights = nested.choose(train_examples, lambda k: rows[k]["task"], inner, where)
    return nested.train(train_examples, weights, where), name, accuracy, list(weights)


def predict(model, rows: list[dict]) -> list[str]:
    from .learn import candidates
    out = []
    for r, where in zip(rows, scenes(rows)):
        cands = candidates(r["dungeon"])
        scores = model.log_posterior(r["command"], cands, where) if getattr(model, "reads_scenes", False) \
            else model.log_posterior(r["command"], cands)
        out.append(cands[max(range(len(cands)), key=scores.__getitem__)])
    return out


def folds(rows: list[dict], k: int, seed: int = 0) -> list[tuple[list, list]]:
    """k (train, test) splits: a seeded shuffle, every k-th pair held out once."""
    order = list(range(len(rows)))
    random.Random(seed).shuffle(order)
    splits = []
    for f in range(k):
        held = set(order[f::k])
        splits.append(([r for i, r in enumerate(rows) if i not in held], [r for i, r in enumerate(rows) if i in held]))
    return splits


def _prepare_fold(item) -> None:
    """In the parent, before forking a fold's child: what every fold needs, computed once
    (the dungeon's candidate tasks; in demonstrations mode, each task's explanations)."""
    from .learn import candidates
    train_rows, test_rows, mode, _ = item
    for ref in {r["dungeon"] for r in train_rows + test_rows}:
        candidates(ref)
    if mode == "demonstrations":
        for ref, task in {(r["dungeon"], r["task"]) for r in train_rows}:
            demonstrated(ref, task)


def _fold(item) -> tuple[list[dict], float, dict | None]:
    """One split (training pairs, held-out pairs, mode, nested seed or None): a fresh model
    (with a seed, its votes chosen by an inner cross-validation of the training pairs),
    its predictions, its training seconds (the inner cross-validation included), and
    what the inner cross-validation chose."""
    train_rows, test_rows, mode, nested_seed = item
    t0 = time.perf_counter()
    chosen = None
    if nested_seed is None:
        model = train(train_rows, mode)
    else:
        model, name, inner, votes = train_nested(train_rows, mode, nested_seed)
        chosen = {"config": name, "inner_accuracy": inner, "votes": votes}
    seconds = time.perf_counter() - t0
    return [{"id": r["id"], "level": r["level"], "command": r["command"], "task": r["task"],
             "predicted": got, "correct": got == r["task"]}
            for r, got in zip(test_rows, predict(model, test_rows))], seconds, chosen


def evaluate(splits: list[tuple[list, list]], mode: str = "tasks", progress=None, workers: int = 1,
             memory_mb: float | None = None, nested_seed: int | None = None) -> dict:
    """Train a fresh model on each split's training pairs; score its held-out pairs. With
    `nested_seed`, each split's votes are chosen by an inner cross-validation of its
    training pairs (shuffled with that seed; nested.py), reported under "chosen". With
    `workers` > 1 the splits run in that many child processes at once (bcc.run.pool.map_local),
    each under an equal share of `memory_mb`; the report is the same for any number of
    workers (the models are seeded, and pairs come back in the splits' order)."""
    done = [None] * len(splits)
    if workers <= 1 or len(splits) == 1:
        for k, split in enumerate(splits):
            done[k] = _fold((*split, mode, nested_seed))
            if progress:
                progress(k + 1, len(splits))
    else:
        from ..run.children import Limits
        from ..run.pool import map_local
        from ..solvers.limits import BudgetExceeded
        limits = Limits(memory_mb=None if memory_mb is None else memory_mb / workers)
        outcomes = map_local(_fold, [(*split, mode, nested_seed) for split in splits], workers, lambda item: limits,
                             _prepare_fold)
        with contextlib.closing(outcomes):    # a raise here (a spent budget) stops the children now
            for finished, outcome in enumerate(outcomes, 1):
                if outcome.limit:
                    raise BudgetExceeded(outcome.limit)
                if outcome.error:
                    raise BccError(outcome.error)
                done[outcome.index] = outcome.value
                if progress:
                    progress(finished, len(splits))
    pairs = [p for fold_pairs, _, _ in done for p in fold_pairs]
    seconds = sum(s for _, s, _ in done)
    by_level = {}
    for level in sorted({p["level"] for p in pairs}):
        mine = [p for p in pairs if p["level"] == level]
        right = sum(p["correct"] for p in mine)
        by_level[level] = {"correct": right, "total": len(mine), "accuracy": right / len(mine)}
    confusion = Counter((p["task"], p["predicted"]) for p in pairs)
    return {"mode": mode, "accuracy": sum(p["correct"] for p in pairs) / len(pairs), "by_level": by_level,
            "confusion": [{"task": t, "predicted": g, "count": c} for (t, g), c in sorted(confusion.items())],
            "train_seconds": round(seconds / len(splits), 3), "pairs": pairs} | \
        ({"chosen": [c for _, _, c in done]} if nested_seed is not None else {})
