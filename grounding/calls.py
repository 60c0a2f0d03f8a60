"""The tasks of a dungeon's domain as candidates for a command: their parameters, types and
defaults, and task calls written the way `bcc solve --task` reads them.

Every compound task of the domain (`tasks:`, compiler/tasks.py) is a candidate: the
classifier (task_model.py) learns which ones people ask for, and a task whose parameters
cannot all be given a value is not a candidate of that command. A parameter the command
does not set takes its default:

- the one the domain states (`w: {type: int, default: 5}`; `x: {type: int, default:
  agent.x}` reads the attribute of a named object where the dungeon starts it: "here");
- else, for an enumeration, the first value of that type the dungeon's objects hold, in
  the order the dungeon lists them (a dungeon lists its main supply first);
- else, for a class, its only object in the dungeon.

Nothing here knows a task's name or a parameter's: all of it is read from the loaded
domain and dungeon (the front end only: nothing is compiled).
"""
from __future__ import annotations

import functools
import re
from dataclasses import dataclass, field

from ..errors import BccError

CALL = re.compile(r"\s*([A-Za-z_][A-Za-z0-9_]*)\s*\((.*)\)\s*")
INT = re.compile(r"-?[0-9]+")


@dataclass(frozen=True)
class Param:
    name: str
    type: str
    kind: str                      # "int", "bool", "enum" or "object"
    values: tuple = ()             # an enumeration's values, a class's objects in the dungeon


@dataclass(frozen=True)
class TaskSig:
    name: str
    params: tuple                  # (Param, ...) in order
    description: str = ""
    defaults: dict = field(default_factory=dict, hash=False, compare=False)   # name -> value, or absent

    def text(self, values) -> str:
        return format_call(self.name, values)


def format_call(name: str, values) -> str:
    """`bed(1, 1, 3, 4, tulips)`: a call as --task takes it."""
    return f"{name}({', '.join(_spell(v) for v in values)})"


def _spell(v) -> str:
    return ("true" if v else "false") if isinstance(v, bool) else str(v)


class CallSpace:
    """The candidate tasks of one dungeon, with their parameters' types and defaults."""

    def __init__(self, dungeon_ref: str):
        from ..compiler.pipeline import load_dungeon
        d = load_dungeon(dungeon_ref)
        self.dungeon_ref = dungeon_ref
        self.name = d.name
        dom = d.domain
        self.enums = {n: tuple(e.values) for n, e in dom.enums.items()}
        by_class: dict = {}
        for obj, (cls, _) in d.objects.items():
            by_class.setdefault(cls, []).append(obj)
        self.tasks = []
        for t in dom.tasks.values():
            params = tuple(_param(p, self.enums, by_class) for p in t.params)
            defaults = {}
            for p in params:
                value = _default(t, p, d, by_class)
                if value is not None:
                    defaults[p.name] = value
            self.tasks.append(TaskSig(t.name, params, t.description, defaults))
        self.by_name = {t.name: t for t in self.tasks}

    def __bool__(self) -> bool:
        return bool(self.tasks)

    def parse(self, text: str, where: tuple = (None, None, None)) -> tuple[str, tuple]:
        """(task name, argument values) of a call such as `bed(1, 1, 3, 4, tulips)`; BccError
        (at `where`: path, line, col) unless it names a task of the domain with one value of
        the right type for each parameter."""
        m = CALL.fullmatch(text)
        if not m:
            raise BccError(f"{text!r} is not a task call such as name(1, 2, value)", *where)
        name, inner = m.group(1), m.group(2).strip()
        task = self.by_name.get(name)
        if task is None:
            raise BccError(f"{name!r} is not a task of dungeon {self.name!r} (its tasks: "
                           f"{', '.join(t.name for t in self.tasks) or 'none'})", *where)
        args = [a.strip() for a in inner.split(",")] if inner else []
        if len(args) != len(task.params):
            raise BccError(f"{name} takes {len(task.params)} argument(s), found {len(args)}", *where)
        return name, tuple(_value(p, a, name, where) for p, a in zip(task.params, args))

    def canonical(self, text: str, where: tuple = (None, None, None)) -> str:
        name, values = self.parse(text, where)
        return format_call(name, values)


@functools.lru_cache(maxsize=64)
def space_for(ref: str) -> CallSpace:
    """The candidate tasks of a dungeon (loaded once per process)."""
    return CallSpace(ref)


def _param(p, enums: dict, by_class: dict) -> Param:
    if p.type in ("int", "bool"):
        return Param(p.name, p.type, p.type)
    if p.type in enums:
        return Param(p.name, p.type, "enum", enums[p.type])
    return Param(p.name, p.type, "object", tuple(by_class.get(p.type, ())))


def _default(task, p: Param, dungeon, by_class: dict):
    """The parameter's default in this dungeon (see the module's docstring), or None."""
    stated = task.defaults.get(p.name)
    if stated is not None:
        value, where = stated
        if p.kind == "int" and isinstance(value, str):
            obj, attr = value.split(".")
            found = dungeon.objects.get(obj)
            if found is None or not isinstance(found[1].get(attr), int) or isinstance(found[1].get(attr), bool):
                raise BccError(f"the default {value} of {task.name}'s {p.name}: dungeon {dungeon.name!r} has no "
                               f"object {obj!r} with an int attribute {attr!r}", *where)
            return found[1][attr]
        return value
    if p.kind == "enum":
        for _, (_, values) in dungeon.objects.items():
            for v in values.values():
                if isinstance(v, str) and v in p.values:
                    return v
        return None
    if p.kind == "object" and len(p.values) == 1:
        return p.values[0]
    return None


def _value(p: Param, arg: str, task: str, where: tuple):
    if p.kind == "int":
        if INT.fullmatch(arg):
            return int(arg)
    elif p.kind == "bool":
        if arg in ("true", "false"):
            return arg == "true"
    elif arg in p.values:
        return arg
    what = {"int": "a whole number", "bool": "true or false"}.get(p.kind) or \
        f"one of {', '.join(p.values) or '(none in this dungeon)'}"
    raise BccError(f"{task}'s {p.name} ({p.type}) is {what}, found {arg!r}", *where)
