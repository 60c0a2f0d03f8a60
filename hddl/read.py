"""HDDL domain and problem files -> a checked `HtnProblem`, every refusal at its position.

Why on top of the PDDL front end: HDDL is PDDL plus :task, :method and the problem's
:htn. Its files are read with pddl_io/read.py's reader (with grammar/hddl.lark), the
PDDL sections (types, constants, predicates, actions, objects, init, goal) by
pddl_io/lifted.py, and only the hierarchy here: tasks, methods (:precondition and
:constraints, :subtasks/:tasks with :ordering, or :ordered-subtasks/:ordered-tasks) and
the initial network. Partial order is out of scope: a network whose :ordering leaves two
subtasks unordered is refused at that :ordering.
"""
from __future__ import annotations

from pathlib import Path

from ..errors import BccError
from ..pddl_io.lifted import Formulas, Reader, _define, _show, domain_from, problem_from
from ..pddl_io.lifted_types import TRUE, unsupported
from ..pddl_io.read import SList, read_sexpr
from .task import HtnProblem, Method, Task

GRAMMAR = Path(__file__).resolve().parent.parent / "grammar" / "hddl.lark"
REQUIREMENTS = frozenset({":hierarchy", ":method-preconditions", ":htn-method-pre", ":htnp", ":total-order",
                          ":htn-total-order"})
SUBTASK_KEYS = (":subtasks", ":tasks", ":ordered-subtasks", ":ordered-tasks")
ROOT = "root"   # the name the IPC plan format gives the initial network


def read_hddl(domain_path: str, problem_path: str) -> HtnProblem:
    """The HTN problem of DOMAIN and PROBLEM, or a BccError at the first thing refused."""
    d = _define(read_sexpr(domain_path, GRAMMAR, "HDDL"), "domain", domain_path)
    plain, hierarchy = _split(d, (":task", ":method"))
    dom = domain_from(plain, domain_path, REQUIREMENTS)
    r = Reader(domain_path)
    tasks: dict = {}
    for sec in hierarchy:
        if sec[0] == ":task":
            t = _task(r, sec, dom)
            if t.name in tasks or t.name in {a.name for a in dom.actions}:
                r.fail(sec, f"{t.name!r} is declared twice (as a task or an action)")
            tasks[t.name] = t
    methods = []
    for sec in hierarchy:
        if sec[0] == ":method":
            methods.append(_method(r, sec, dom, tasks))
    names = set()
    for m, sec in zip(methods, [s for s in hierarchy if s[0] == ":method"]):
        if m.name in names:
            r.fail(sec, f"method {m.name!r} is declared twice")
        names.add(m.name)
    p = _define(read_sexpr(problem_path, GRAMMAR, "HDDL"), "problem", problem_path)
    plain, htn = _split(p, (":htn",))
    prob = problem_from(plain, problem_path, dom, REQUIREMENTS, goal_needed=False, keep_order=True)
    if len(htn) > 1:
        Reader(problem_path).fail(htn[1], "a second :htn section")
    if htn:
        network = _network(Reader(problem_path), htn[0], dom, tasks, prob.objects)
    else:   # no task network: only the goal
        network = Method(ROOT, (), (ROOT, ()), TRUE, (), (p.line, p.column))
    return HtnProblem(domain=dom, problem=prob, tasks=tasks, methods=methods, network=network, name=prob.name,
                      path=problem_path,
                      report={"tasks": len(tasks), "methods": len(methods), "actions": len(dom.actions),
                              "objects": len(prob.objects), "facts": len(prob.init)})


def _split(d: SList, heads: tuple) -> tuple[SList, list]:
    """`d` without its sections headed by one of `heads`, and those sections."""
    kept, taken = SList(d[:2]), []
    kept.line, kept.column = d.line, d.column
    for sec in d[2:]:
        if isinstance(sec, SList) and sec and sec[0] in heads:
            taken.append(sec)
        else:
            kept.append(sec)
    return kept, taken


def _keys(r: Reader, sec: SList, start: int, allowed: tuple, what: str) -> dict:
    """The `:key value` pairs of `sec` from `start`, each key once and among `allowed`."""
    parts = {}
    i = start
    while i < len(sec):
        key = sec[i]
        if isinstance(key, SList) or key.type != "KEYWORD":
            r.fail(key, f"expected one of {', '.join(allowed)} in {what}, found {_show(key)}")
        if key not in allowed:
            raise unsupported(key, f"{key} in {what}", r.path)
        if key in parts:
            r.fail(key, f"a second {key} in {what}")
        if i + 1 >= len(sec):
            r.fail(key, f"{key} needs a value")
        parts[str(key)] = (key, sec[i + 1])
        i += 2
    return parts


def _params(r: Reader, node, dom) -> tuple:
    plist = r.expect_list(node, "the parameters")
    params = tuple((str(v), t) for v, t in r.typed_list(plist, "variable", dom.parents))
    names = [v for v, _ in params]
    if len(set(names)) != len(names):
        r.fail(plist, "a parameter is named twice")
    return params


def _task(r: Reader, sec: SList, dom) -> Task:
    if len(sec) < 2:
        r.fail(sec, "a task needs a name")
    name = r.name(sec[1], "the task's name")
    parts = _keys(r, sec, 2, (":parameters",), "a task")
    params = _params(r, parts[":parameters"][1], dom) if ":parameters" in parts else ()
    return Task(name, tuple(t for _, t in params), (sec.line, sec.column))


def _call(r: Reader, f: Formulas, node, scope: dict, tasks: dict, dom, what: str) -> tuple:
    """A task or action named with arguments: (name, argument terms), arity checked."""
    node = r.expect_list(node, what)
    if not node:
        r.fail(node, f"expected {what} (name args...), found ()")
    name = r.name(node[0], "a task or action name")
    arity = len(tasks[name].params) if name in tasks else \
        next((len(a.params) for a in dom.actions if a.name == name), None)
    if arity is None:
        r.fail(node[0], f"{name!r} is neither a task nor an action of the domain")
    if len(node) - 1 != arity:
        r.fail(node, f"{name} takes {arity} arguments, found {len(node) - 1}")
    return name, tuple(f.term(a, scope) for a in node[1:])


def _method(r: Reader, sec: SList, dom, tasks: dict) -> Method:
    if len(sec) < 2:
        r.fail(sec, "a method needs a name")
    name = r.name(sec[1], "the method's name")
    parts = _keys(r, sec, 2, (":parameters", ":task", ":precondition", ":constraints", ":ordering") + SUBTASK_KEYS,
                  "a method")
    if ":task" not in parts:
        r.fail(sec, f"method {name!r} has no :task")
    params = _params(r, parts[":parameters"][1], dom) if ":parameters" in parts else ()
    scope = dict(params)
    f = Formulas(r, dom, None)
    task = _call(r, f, parts[":task"][1], scope, tasks, dom, "the method's task")
    if task[0] not in tasks:
        r.fail(parts[":task"][1], f"{task[0]!r} is an action: a method decomposes a compound task (:task)")
    pre = _condition(f, parts, scope)
    subtasks = _subtasks(r, f, parts, scope, tasks, dom, sec)
    return Method(name, params, task, pre, subtasks, (sec.line, sec.column))


def _condition(f: Formulas, parts: dict, scope: dict) -> tuple:
    """:precondition and :constraints, one conjunction (both must hold where applied)."""
    found = [f.formula(parts[k][1], scope) for k in (":precondition", ":constraints") if k in parts]
    found = [c for c in found if c != TRUE]
    return TRUE if not found else found[0] if len(found) == 1 else ("and", tuple(found))


def _network(r: Reader, sec: SList, dom, tasks: dict, objects: dict) -> Method:
    parts = _keys(r, sec, 1, (":parameters", ":constraints", ":ordering") + SUBTASK_KEYS, "the :htn")
    params = _params(r, parts[":parameters"][1], dom) if ":parameters" in parts else ()
    scope = dict(params)
    f = Formulas(r, dom, objects)
    pre = _condition(f, parts, scope)
    subtasks = _subtasks(r, f, parts, scope, tasks, dom, sec)
    return Method(ROOT, params, (ROOT, ()), pre, subtasks, (sec.line, sec.column))


def _subtasks(r: Reader, f: Formulas, parts: dict, scope: dict, tasks: dict, dom, sec: SList) -> tuple:
    """The subtasks in their total order: as listed for :ordered-subtasks, else as the
    :ordering's `(< a b)` pairs chain them (refused where they leave two unordered)."""
    given = [k for k in SUBTASK_KEYS if k in parts]
    if len(given) > 1:
        r.fail(parts[given[1]][0], f"{given[1]} beside {given[0]}: give the subtasks once")
    if not given:
        if ":ordering" in parts:
            r.fail(parts[":ordering"][0], ":ordering without subtasks")
        return ()
    key, node = parts[given[0]]
    node = r.expect_list(node, "the subtasks")
    items = list(node[1:]) if node and node[0] == "and" else ([node] if node else [])
    ids, calls = [], []
    for item in items:
        item = r.expect_list(item, "a subtask")
        if len(item) == 2 and not isinstance(item[0], SList) and item[0].type == "NAME" and isinstance(item[1], SList):
            label, call = str(item[0]), item[1]     # (id (task args))
        else:
            label, call = None, item
        if label is not None and label in ids:
            r.fail(item[0], f"subtask id {label!r} is used twice")
        ids.append(label)
        calls.append(_call(r, f, call, scope, tasks, dom, "a subtask"))
    if ":ordering" not in parts:
        if key.startswith(":ordered") or len(calls) <= 1:
            return tuple(calls)
        raise BccError(f"{key} has {len(calls)} subtasks and no :ordering: only totally ordered networks are "
                       f"supported (use :ordered-subtasks)", r.path, key.line, key.column)
    order = _total_order(r, parts[":ordering"], ids, key.startswith(":ordered"))
    return tuple(calls[i] for i in order)


def _total_order(r: Reader, ordering, ids: list, listed: bool) -> list:
    """The subtasks' indices in the one order the `(< a b)` pairs allow (with the listed
    order too for :ordered-subtasks), or a BccError at the :ordering."""
    key, node = ordering
    node = r.expect_list(node, "the ordering")
    pairs = list(node[1:]) if node and node[0] == "and" else ([node] if node else [])
    index = {label: i for i, label in enumerate(ids) if label is not None}
    after: dict = {i: set() for i in range(len(ids))}
    if listed:
        for i in range(len(ids) - 1):
            after[i].add(i + 1)
    for pair in pairs:
        pair = r.expect_list(pair, "an ordering constraint (< a b)")
        if len(pair) != 3 or pair[0] not in ("<", ">"):
            raise unsupported(pair, "an ordering constraint other than (< a b)", r.path)
        for label in pair[1:]:
            if isinstance(label, SList) or str(label) not in index:
                r.fail(label, f"{_show(label)} is not the id of a subtask of this network")
        a, b = index[str(pair[1])], index[str(pair[2])]
        after[a if pair[0] == "<" else b].add(b if pair[0] == "<" else a)
    indegree = {i: 0 for i in after}
    for i in after:
        for j in after[i]:
            indegree[j] += 1
    order, ready = [], [i for i in after if indegree[i] == 0]
    while ready:
        if len(ready) > 1:
            a, b = (ids[i] or f"#{i + 1}" for i in ready[:2])
            raise BccError(f"the ordering leaves subtasks {a} and {b} unordered: only totally ordered networks are "
                           f"supported", r.path, node.line, node.column)
        i = ready.pop()
        order.append(i)
        for j in after[i]:
            indegree[j] -= 1
            if indegree[j] == 0:
                ready.append(j)
    if len(order) < len(ids):
        raise BccError("the ordering has a cycle", r.path, node.line, node.column)
    return order
