"""Grounding model files: log-linear models voting as an ensemble, one log-linear model, or IBM
Model 2 from older files (goal models), or a task-call model (task_model.py), by their format."""
from __future__ import annotations

import json
from pathlib import Path

from ..errors import BccError, read_input
from .ensemble import FORMAT as ENSEMBLE, Ensemble
from .loglinear import FORMAT as LOGLINEAR, LogLinear
from .translation import FORMAT as IBM2, IBMModel2

GOAL_FORMATS = (ENSEMBLE, LOGLINEAR, IBM2)


def from_json(data, path: str | None = None):
    kind = data.get("format") if isinstance(data, dict) else None
    if kind == ENSEMBLE:
        return Ensemble.from_json(data, path)
    if kind == LOGLINEAR:
        return LogLinear.from_json(data, path)
    if kind == IBM2:
        return IBMModel2.from_json(data, path)
    from .task_model import FORMAT as TASKCALLS, TaskCallModel
    if kind == TASKCALLS:
        return TaskCallModel.from_json(data, path)
    raise BccError(f"not a grounding model: expected \"format\": \"{ENSEMBLE}\" (or \"{LOGLINEAR}\", \"{IBM2}\", "
                   f"\"{TASKCALLS}\")", path)


def load(path: str | Path):
    text = read_input(path, "model")
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise BccError(f"invalid JSON: {exc.msg}", str(path), exc.lineno, exc.colno) from None
    return from_json(data, str(path))
