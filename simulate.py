"""Replay a plan in a compiled model and say where and why it fails (for `bcc validate`)."""
from __future__ import annotations

import json
from dataclasses import dataclass, field

from .errors import BccError
from .model import Model


@dataclass
class Replay:
    valid: bool
    steps: int                       # actions run
    cost: int
    reached_goal: bool
    message: str
    failed_step: int | None = None   # 1-based
    states: list = field(default_factory=list)

    def to_json(self) -> dict:
        return {"valid": self.valid, "steps": self.steps, "cost": self.cost, "reached_goal": self.reached_goal,
                "failed_step": self.failed_step, "message": self.message}


def read_plan(text: str, path: str) -> list[tuple[str, int, int]]:
    """Action names with their (line, col): one per line (`#` comments and blanks skipped),
    or JSON: a list of names, an object with a `plan` list (the output of `bcc solve --json`),
    or one with an `actions` list (a demonstration, as `bcc play --record` writes)."""
    stripped = text.strip()
    if stripped.startswith(("[", "{")):
        try:
            data = json.loads(stripped)
        except json.JSONDecodeError as exc:
            raise BccError(f"invalid JSON plan: {exc.msg}", path, exc.lineno, exc.colno) from None
        plan = (data.get("plan", data.get("actions")) if isinstance(data, dict) else data)
        if not isinstance(plan, list) or not all(isinstance(a, str) for a in plan):
            raise BccError("a JSON plan is a list of action names, or an object with a \"plan\" list "
                           "(bcc solve --json) or an \"actions\" list (bcc play --record)", path, 1, 1)
        return [(a, 1, 1) for a in plan]
    out = []
    for lineno, line in enumerate(text.splitlines(), 1):
        content = line.split("#", 1)[0]
        name = content.strip()
        if name:
            out.append((name, lineno, len(content) - len(content.lstrip()) + 1))
    return out


def replay(model: Model, plan: list[tuple[str, int, int]], path: str = "<plan>") -> Replay:
    import difflib
    indices = []
    for name, line, col in plan:
        if name not in model.action_names:
            close = difflib.get_close_matches(name, model.action_names, n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            raise BccError(f"unknown action {name!r}{hint}", path, line, col)
        indices.append(model.action_index(name))
    state = model.initial
    states, cost = [state], 0
    # a task is done when its plan is: the goal is checked after the last step, not the first it holds at
    to_the_end = bool(model.report.get("task"))
    if model.is_goal(state) and not indices:
        return Replay(True, 0, 0, True, "the goal holds in the initial state", states=states)
    for step, a in enumerate(indices, 1):
        nxt = model.apply(a, state)
        if nxt is None:
            why = model.why_not(a, state)
            return Replay(False, step - 1, cost, False,
                          f"step {step} ({model.action_names[a]}) is not applicable: `{why}` is false",
                          failed_step=step, states=states)
        state = nxt
        cost += model.action_costs[a]
        states.append(state)
        if model.is_goal(state) and not to_the_end:
            extra = len(indices) - step
            note = f"; the {extra} step(s) after it were not run" if extra else ""
            return Replay(True, step, cost, True, f"the goal holds after step {step}{note}", states=states)
        if model.is_failure(state):
            return Replay(False, step, cost, False,
                          f"step {step} ({model.action_names[a]}) ends the episode in failure", failed_step=step,
                          states=states)
    if to_the_end and model.is_goal(state):
        return Replay(True, len(indices), cost, True, f"all {len(indices)} step(s) apply and the goal holds after "
                                                      f"the last", states=states)
    return Replay(False, len(indices), cost, False,
                  f"the plan ends after {len(indices)} step(s) but the goal `{model.goal_text}` does not hold",
                  states=states)
