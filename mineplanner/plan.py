"""A native plan (builder actions) as the MinePlanner task's own PDDL actions, fully
parameterised, ending with `checkgoal`.

Why replay here rather than trust names: a PDDL action names every object it touches
(which block object is broken, which spare block object is placed, which item is picked
up, the count before and after, and each position), so the plan is replayed on the
task's objects: the same moves as domains/builder.yaml, read from MinePlanner's domain.
A step that does not apply is an error naming it; the result is then checked by a PDDL
validator that knows nothing of the builder domain (bench/mineplanner_native.py).
"""
from __future__ import annotations

import re

from ..errors import BccError
from ..pddl_io.read import read_sexpr
from .task import Task
from .world import STEPS, Frame

_STEP = re.compile(r"^(move|jump|drop|break|place)_(north|south|east|west)(?:\(agent, (\w+)\))?$")


def action_parameters(domain_path: str) -> dict:
    """PDDL action name -> its parameter variables, in order."""
    out = {}
    for part in read_sexpr(domain_path)[0][2:]:
        if isinstance(part, list) and part[:1] == [":action"]:
            keys = {part[i]: part[i + 1] for i in range(2, len(part) - 1, 2)}
            out[str(part[1])] = [v for v in keys.get(":parameters", []) if str(v).startswith("?")]
    return out


class Replay:
    """The task's state as its objects: where the agent is, which block object is in each
    cell, the spare block objects, the items lying, the counts."""

    def __init__(self, task: Task, fr: Frame, item_names: list, check: bool = True):
        self.task, self.fr, self.check = task, fr, check
        self.at = list(task.agent_at)
        self.cells = {at: name for at, (name, _) in task.blocks.items()}
        self.kind = {name: material for name, material in task.blocks.values()}
        self.spare = {m: list(objs) for m, objs in task.spare.items()}
        self.items = [[name, material, at, True] for name, material, at in task.items]
        self.counts = dict(task.counts)
        self.params = action_parameters(task.paths[0])
        self.top = len(task.positions) - 1
        self.item_names = item_names

    def solid(self, x, y, z) -> bool:
        return (x, y, z) in self.cells

    def item_at(self, at):
        return next((i for i in self.items if i[3] and i[2] == at), None)

    def takeable(self, at):
        """The first lying item at `at` the agent has room for (the builder domain's choice)."""
        return next((i for i in self.items if i[3] and i[2] == at and self.counts[i[1]] < len(self.task.count_objects) - 1),
                    None)

    def emit(self, action: str, binding: dict) -> str:
        if action not in self.params:
            raise BccError(f"the task's domain has no action {action}", self.task.paths[0])
        P, C = self.task.positions, self.task.count_objects
        names = []
        for var in self.params[action]:
            value = binding[str(var)]
            names.append(value if isinstance(value, str) else (C[value[1]] if value[0] == "n" else P[value[1]]))
        return f"({action} {' '.join(names)})"

    def step(self, number: int, name: str) -> str:
        m = _STEP.match(name)
        if m is None:
            raise BccError(f"step {number}: {name!r} is not an action of the builder domain")
        kind, direction, stock = m[1], m[2], m[3]
        dx, dz = STEPS[direction]
        x, y, z = self.at
        fx, fz = x + dx, z + dz
        error = BccError(f"step {number}: {name} does not apply in the task")

        def fail():
            if self.check:
                raise error
        p = lambda v: ("p", v)                             # a position
        along = {"x": p(x)} if dx == 0 else {"z": p(z)}
        if dx == 0:
            ends = {"z_start": p(z), "z_end": p(fz), "z_front": p(fz)}
        else:
            ends = {"x_start": p(x), "x_end": p(fx), "x_front": p(fx)}
        b = {"?ag": self.task.agent, **{f"?{k}": v for k, v in {**along, **ends}.items()}}
        if kind in ("move", "jump", "drop"):
            ny = {"move": y, "jump": y + 1, "drop": y - 1}[kind]
            if ny < 0 or ny + 1 > self.top or (kind == "jump" and y + 2 > self.top) or (kind == "drop" and y < 2):
                raise error
            S = self.solid
            if not {"move": S(fx, y - 1, fz) and not S(fx, y, fz) and not S(fx, y + 1, fz),
                    "jump": S(fx, y, fz) and not (S(x, y + 2, z) or S(fx, y + 1, fz) or S(fx, y + 2, fz)),
                    "drop": S(fx, y - 2, fz) and not (S(fx, y - 1, fz) or S(fx, y, fz) or S(fx, y + 1, fz))}[kind]:
                fail()
            item = self.item_at((fx, ny, fz))
            take = self.takeable((fx, ny, fz)) if item else None
            if item and not take:
                fail()
            b.update({"?y_down": p(y), "?y_up": p(y + 1), "?y_up_up": p(y + 2), "?y_2_down": p(y - 1),
                      "?y_3_down": p(y - 2)})
            base = {"move": "move", "jump": "jumpup", "drop": "jumpdown"}[kind]
            if take:
                b.update({"?i": take[0], "?n_start": ("n", self.counts[take[1]]),
                          "?n_end": ("n", self.counts[take[1]] + 1)})
                action = f"{base}_and_pickup-{take[1]}-{direction}"
                take[3] = False
                self.counts[take[1]] += 1
            else:
                action = f"{base}-{direction}"
            self.at = [fx, ny, fz]
            return self.emit(action, b)
        if kind == "break":
            obj = self.cells.get((fx, y, fz))
            material = self.kind.get(obj)
            if obj is None or material not in self.counts:
                raise error
            if self.item_at((fx, y + 1, fz)):
                fail()
            b.update({"?b": obj, "?y": p(y), "?y_up": p(y + 1), "?z": p(z), "?x": p(x),
                      "?n_start": ("n", self.counts[material]), "?n_end": ("n", self.counts[material] + 1)})
            del self.cells[(fx, y, fz)]
            self.spare[material].append(obj)
            self.counts[material] += 1
            return self.emit(f"break-{material}-{direction}", b)
        material = stock
        if material not in self.counts or self.counts[material] < 1 or not self.spare.get(material):
            raise error
        if self.solid(fx, y, fz) or not self.solid(fx, y - 1, fz) or self.item_at((fx, y, fz)):
            fail()
        obj = self.spare[material].pop(0)
        b.update({"?b": obj, "?y": p(y), "?y_down": p(y - 1), "?z": p(z), "?x": p(x),
                  "?n_start": ("n", self.counts[material]), "?n_end": ("n", self.counts[material] - 1)})
        self.cells[(fx, y, fz)] = obj
        self.kind[obj] = material
        self.counts[material] -= 1
        return self.emit(f"place-{material}-{direction}", b)


def pddl_plan(task: Task, fr: Frame, item_names: list, plan: list, check: bool = True) -> list:
    """The PDDL actions of a native plan, `(checkgoal AGENT)` last. With `check=False`, a step
    whose conditions fail is still written (for a PDDL validator to judge, e.g. of a plan
    from elsewhere), as long as its objects can be named."""
    replay = Replay(task, fr, item_names, check)
    out = [replay.step(i, name.strip()) for i, name in enumerate(plan, 1) if name.strip()]
    return out + [f"(checkgoal {task.agent})"]
