"""Compound tasks and methods in a domain file: the `tasks:` and `methods:` sections.

A task is a name with typed parameters; a method decomposes one task into an ordered
list of subtasks (tasks or actions, called with expressions as arguments) where its
precondition holds, with variables of its own (`vars:`) that the precondition binds.
Recursion is allowed: that is how a row of any length is one task.

This is the "load and check the shape" step, as domain.py is for actions: keys and
names are checked, every precondition and every call is parsed with its position, and
each call must name a task or an action of the domain with the right number of
arguments. Types and unbound variables are checked when a dungeon gives the domain its
objects (compiler/hierarchy.py), like every other expression.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

from ..errors import BccError
from . import ast
from .limits import MAX_METHOD_VARS
from .names import check_text
from .source import YList, YMap, check_keys, error_at, node_pos, suggest, value_node

TASK_KEYS = {"params", "description", "override"}
METHOD_KEYS = {"task", "vars", "pre", "subtasks", "description", "override"}


@dataclass
class TaskDef:
    name: str
    params: list            # [Param], in order
    description: str = ""
    # parameter name -> (default, (path, line, col)): an int, a bool, an enumeration value's
    # name, or "object.attribute" (that attribute of a named object at the dungeon's start).
    # Only `bcc command` reads them (grounding/calls.py): a call always gives every argument.
    defaults: dict = field(default_factory=dict)


@dataclass
class VarDef:
    """A method's own variable: its type, for an int its range (two Exprs) or None."""
    name: str
    type: str
    range: tuple | None
    where: tuple            # (path, line, col) of its name, for errors


@dataclass
class MethodDef:
    name: str
    task: str
    vars: list              # [VarDef]
    pre: list               # [Expr], all must hold
    subtasks: list          # [Expr] whose node is an ast.Call
    where: tuple            # (path, line, col) of the method's name
    task_where: tuple = ()  # and of its `task:` value


def load_tasks(data: YMap, base, names_in_use: set, read) -> dict:
    """The domain's tasks: the base's, then this file's. `read` holds domain.py's readers
    (merge: its rule for `override`; params, expr, ident), handed in so that this module
    does not import the one that imports it."""
    def load(section, name):
        tdef = section[name]
        if tdef is None:
            tdef = YMap()
        if not isinstance(tdef, YMap):
            raise error_at(section, name, "a task is a mapping, e.g. {params: {x: int, n: int}}")
        check_keys(tdef, TASK_KEYS, set(), f"task {name!r}")
        params, defaults = _task_params(tdef, names_in_use, read)
        description = tdef.get("description")
        if description is not None:
            check_text(tdef, "description", description, "the description")
        return TaskDef(name, params, " ".join(str(description or "").split()), defaults)
    return read.merge("task", data, "tasks", base.tasks if base else {}, load, base)


def _task_params(tdef: YMap, names_in_use: set, read) -> tuple[list, dict]:
    """A task's `params`: `name: type`, or `name: {type: T, default: V}` (see TaskDef.defaults)."""
    section = tdef.get("params")
    if not isinstance(section, YMap) or not any(isinstance(v, YMap) for v in section.values()):
        return read.params(tdef, names_in_use), {}
    params, defaults = [], {}
    for pname, ptype in section.items():
        container, key = section, pname
        if isinstance(ptype, YMap):
            check_keys(ptype, {"type", "default"}, {"type"}, f"parameter {pname!r}")
            container, key, spec, ptype = ptype, "type", ptype, ptype["type"]
        else:
            spec = None
        if not isinstance(ptype, str) or ptype not in names_in_use:
            raise error_at(container, key, f"unknown type or class {ptype!r}{suggest(str(ptype), names_in_use)}")
        name = read.ident(section, pname, pname, "a parameter")
        if spec is not None and "default" in spec:
            defaults[name] = (_default(spec, read.enums), _where(spec, "default"))
        params.append(read.param(name, ptype))
    return params, defaults


def _default(spec: YMap, enums: dict):
    """A parameter's default, checked against its type: an int, a bool, a value of its
    enumeration, or `object.attribute` for an int (read from the dungeon's start)."""
    ptype, value = spec["type"], spec["default"]
    if ptype == "int":
        if isinstance(value, int) and not isinstance(value, bool):
            return value
        if isinstance(value, str) and _OBJECT_ATTR.fullmatch(value):
            return value
        raise error_at(spec, "default", "the default of an int parameter is a whole number or object.attribute "
                                        "(e.g. agent.x: where the agent starts)")
    if ptype == "bool":
        if isinstance(value, bool):
            return value
        raise error_at(spec, "default", "the default of a bool parameter is true or false")
    if ptype in enums:
        if isinstance(value, str) and value in enums[ptype].values:
            return value
        raise error_at(spec, "default", f"{value!r} is not a value of {ptype!r}{suggest(str(value), enums[ptype].values)}")
    raise error_at(spec, "default", f"a parameter of class {ptype!r} has no default")


_OBJECT_ATTR = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\.[A-Za-z_][A-Za-z0-9_]*")


def load_methods(data: YMap, base, names_in_use: set, read) -> dict:
    def load(section, name):
        return _load_method(section, name, names_in_use, read)
    return read.merge("method", data, "methods", base.methods if base else {}, load, base)


def _where(container, key) -> tuple:
    if isinstance(container, YMap) and key in container.nodes:
        return (container.src_of(key).path, *node_pos(container.nodes[key][0]))
    return (container.src.path, *node_pos(value_node(container, key)))


def _load_method(section, name, names_in_use, read) -> MethodDef:
    _expr = read.expr
    mdef = section[name]
    if not isinstance(mdef, YMap):
        raise error_at(section, name, "a method needs `task` and `subtasks`")
    check_keys(mdef, METHOD_KEYS, {"task", "subtasks"}, f"method {name!r}")
    task = mdef["task"]
    if not isinstance(task, str):
        raise error_at(mdef, "task", "`task` names the one task this method decomposes")
    vars_ = []
    section_vars = mdef.get("vars") or YMap()
    if not isinstance(section_vars, YMap):
        raise error_at(mdef, "vars", "`vars` maps variable names to types, e.g. {s: stock, d: {type: int, range: [0, 3]}}")
    if len(section_vars) > MAX_METHOD_VARS:
        raise error_at(mdef, "vars", f"method {name!r} has {len(section_vars)} variables; at most {MAX_METHOD_VARS}")
    for vname, vtype in section_vars.items():
        read.ident(section_vars, vname, vname, "a variable name")
        rng = None
        if isinstance(vtype, YMap):
            check_keys(vtype, {"type", "range"}, {"type"}, f"variable {vname!r}")
            if "range" in vtype:
                r = vtype["range"]
                if vtype["type"] != "int" or not isinstance(r, YList) or len(r) != 2:
                    raise error_at(vtype, "range", "`range` is [low, high] and only for int variables")
                rng = (_expr(r, 0), _expr(r, 1))
            container, key, vtype = vtype, "type", vtype["type"]
        else:
            container, key = section_vars, vname
        if not isinstance(vtype, str) or vtype not in names_in_use:
            raise error_at(container, key, f"unknown type or class {vtype!r}{suggest(str(vtype), names_in_use)}")
        vars_.append(VarDef(str(vname), vtype, rng, _where(section_vars, vname)))
    pre = mdef.get("pre")
    if pre is None:
        pres = []
    elif isinstance(pre, YList):
        pres = [_flow_hinted(_expr, pre, i) for i in range(len(pre))]
    else:
        pres = [_expr(mdef, "pre")]
    subs = mdef["subtasks"]
    if subs is None:
        subs = YList()
    if not isinstance(subs, YList):
        raise error_at(mdef, "subtasks", "`subtasks` is a list of calls, e.g. [move_east(agent), row(n - 1)]; "
                                         "[] for none")
    calls = []
    for i in range(len(subs)):
        e = _flow_hinted(_expr, subs, i)
        if not isinstance(e.node, ast.Call):
            raise e.error("a subtask is a call of a task or an action, e.g. row(x + 1, n - 1) or move_east(agent)")
        calls.append(e)
    task_where = (mdef.src_of("task").path, *node_pos(value_node(mdef, "task")))
    return MethodDef(name, task, vars_, pres, calls, _where(section, name), task_where)


def _flow_hinted(_expr, items: YList, i: int):
    """items[i] parsed; a syntax error in a `[flow, list]` says why it may be one: YAML splits
    `[row(a, b)]` at its comma before bcc sees it."""
    try:
        return _expr(items, i)
    except BccError as exc:
        if getattr(getattr(items, "node", None), "flow_style", False):
            exc.message += "; in a [flow, list] YAML splits calls at their commas: write one `- item` a line"
        raise


def check_hierarchy(tasks: dict, methods: dict, actions: dict, functions: dict, data: YMap) -> None:
    """What can be checked without a dungeon: names are not shared between tasks and
    actions, each method's task exists, its variables do not shadow the task's parameters,
    and each call names a task or an action with the right number of arguments."""
    for name in tasks:
        if name in actions:
            raise _key_error(data, "tasks", name, f"{name!r} is both a task and an action")
        if name in functions:
            raise _key_error(data, "tasks", name, f"{name!r} is both a task and a function")
    for m in methods.values():
        if m.task not in tasks:
            hint = " (it is an action: a method decomposes a task)" if m.task in actions else \
                suggest(m.task, tasks)
            raise _error_at_where(m.task_where or m.where, f"method {m.name!r}: unknown task {m.task!r}{hint}")
        params = {p.name for p in tasks[m.task].params}
        seen = set()
        for v in m.vars:
            if v.name in params:
                raise _error_at_where(v.where, f"variable {v.name!r} is already a parameter of the task {m.task!r}")
            seen.add(v.name)
        for e in m.subtasks:
            call = e.node
            if call.func in tasks:
                want = len(tasks[call.func].params)
            elif call.func in actions:
                want = len(actions[call.func].params)
            else:
                raise e.error(f"unknown task or action {call.func!r}{suggest(call.func, list(tasks) + list(actions))}",
                              call)
            if len(call.args) != want:
                raise e.error(f"{call.func} takes {want} argument(s), found {len(call.args)}", call)


def _key_error(data, section: str, name: str, message: str):
    return error_at(data[section], name, message, on_key=True)


def _error_at_where(where: tuple, message: str):
    path, line, col = where
    return BccError(message, path, line, col)


def describe(tasks: dict, methods: dict) -> tuple[dict, dict]:
    """For `bcc compile --json`: {task: [param: type]}, {method: {task, vars, subtasks}}."""
    return ({t.name: [f"{p.name}: {p.type}" for p in t.params] for t in tasks.values()},
            {m.name: {"task": m.task, "vars": [f"{v.name}: {v.type}" for v in m.vars],
                      "pre": [" ".join(p.text.split()) for p in m.pre],
                      "subtasks": [" ".join(e.text.split()) for e in m.subtasks]} for m in methods.values()})


def task_calls(container, key, _expr) -> list:
    """A dungeon's `task:`: one call (`row(2, 1, 2, 10)`) or a list of
    them, done in order; each parsed with its position (checked when compiled). `_expr`
    is domain.py's expression reader."""
    value = container[key]
    if isinstance(value, YList):
        if not value:
            raise error_at(container, key, "`task` is an empty list: leave the key out instead")
        items = [_expr(value, i) for i in range(len(value))]
    else:
        items = [_expr(container, key)]
    for e in items:
        if not isinstance(e.node, ast.Call):
            raise e.error("a task is a call of a task of the domain, e.g. row(2, 1, 2, 10)")
    return items
