"""A domain's methods, type-checked and compiled for one dungeon: each method becomes a
generated function from a state and its task's arguments to every way it decomposes
the task there.

Why generated, like actions: an HTN search applies "place the next block of a row"
thousands of times; a Python function per method, reading the compact state directly,
costs a few microseconds a call. Why not grounded ahead: a task's parameters are
numbers (coordinates, lengths) whose values only the decomposition makes, so they stay
arguments. What is grounded is what actions ground: parameters and variables of a class
of named objects (one function per combination of objects, as for actions).

A method's own variables (`vars:`) are bound by its precondition: a conjunct `v == E`
whose E is known assigns v; otherwise v ranges over its type (an enumeration's values,
an int's `range`, a class's objects) and the conjuncts are tested as soon as their
variables are bound. An int variable that neither binds is an error at its name.

Subtasks come out as (name, args): a task as its name and argument values (ints; an
enumeration's value index; an object's name), an action as its index in the model's
actions and (). Text from the file reaches the generated code only through constant
tables (the task names, the object names), never as code.
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass, field

from ..errors import BccError
from . import ir
from .definitions import Expr
from .emit import Emitter
from .ground_refs import Ctx, KeyRef, ObjRef
from .source import Origin

ROOT = "root"   # the name the decomposition tree gives the dungeon's own network
SHARED_HELPERS = ("_cell", "_set_cell", "_index", "_range", "_divide", "_cells", "_merge", "_S0", "_expand", "_CC", "SG")


@dataclass(frozen=True)
class Variant:
    """One method, grounded for one choice of its objects."""
    method: str
    task: str
    objects: tuple          # ((task parameter position, object name), ...) the task's arguments must match
    values: tuple           # the task parameter positions passed to `fn` (ints, enumerations, bools)
    fn: object              # (state, *values) -> [subtasks, ...], each subtasks a tuple of (name, args)
    shape: tuple            # ((subtask name or action index, ()), ...): what the estimate reads

    @property
    def name(self) -> str:
        return self.method


@dataclass
class Hierarchy:
    """What the `htn` solver plans with on a compiled dungeon."""
    tasks: dict                        # name -> [parameter type, ...]
    variants: dict                     # task name -> [Variant] in the file's order of methods
    root: Variant | None               # the dungeon's task network (None: the dungeon gives no task)
    network_text: list = field(default_factory=list)
    value_names: dict = field(default_factory=dict)   # enumeration -> its value names
    derive: object = None              # (state, its successor): the successor's cells cached for the methods' reads

    def task_text(self, name: str, args: tuple) -> str:
        """`row(2, 1, 3, east)`: enumeration values by name, objects by name, bools as words."""
        types = self.tasks.get(name, ())
        shown = []
        for t, v in zip(types, args):
            if t in self.value_names:
                shown.append(self.value_names[t][v])
            elif t == "bool":
                shown.append("true" if v else "false")
            else:
                shown.append(str(v))
        return f"{name}({', '.join(shown)})"


def build_hierarchy(g, dungeon, layout, enum_sizes: dict, action_names: tuple, network: list | None,
                    model_ns: dict) -> Hierarchy:
    """Check and compile every method of the dungeon's domain, and its task network
    (`network`: the dungeon's `task:` or --task, a list of Exprs of calls, or None).
    `model_ns`: the actions' generated namespace, whose helpers the methods share (one
    cache of expanded cells for both: the actions just expanded the states the methods read)."""
    dom = dungeon.domain
    emitter = Emitter(layout, enum_sizes)
    emitter.ns.update({k: model_ns[k] for k in SHARED_HELPERS if k in model_ns})
    emitter.ns["_T"] = tuple(dom.tasks)          # task names: data, read by index
    objects = tuple(dungeon.objects)
    emitter.ns["_O"] = objects
    compiler = _MethodCompiler(g, dom, emitter, {n: i for i, n in enumerate(action_names)}, objects)
    variants: dict = {t: [] for t in dom.tasks}
    for m in dom.methods.values():
        variants[m.task].extend(compiler.method(m))
    root = None
    if network:
        root = compiler.compile(ROOT, ROOT, [], [], [], network, {}, (), ())
    source = "\n\n".join(compiler.sources) + "\n"
    ns = dict(emitter.ns)
    exec(compile(source, "<bcc methods>", "exec"), ns)
    bind = lambda v: Variant(v.method, v.task, v.objects, v.values, ns[v.fn], v.shape)  # noqa: E731
    return Hierarchy(
        tasks={t.name: [p.type for p in t.params] for t in dom.tasks.values()},
        variants={t: [bind(v) for v in vs] for t, vs in variants.items()},
        root=bind(root) if root is not None else None,
        network_text=[" ".join(e.text.split()) for e in network or ()],
        value_names={n: tuple(e.values) for n, e in dom.enums.items()},
        derive=model_ns.get("_derive"))


def parse_task_option(text: str) -> list:
    """`--task TEXT`: one call, parsed as a dungeon's `task:` would be."""
    from . import ast
    from .parse import parse_expression
    where = Origin("--task", 1, 1)
    node = parse_expression(text, where)
    if not isinstance(node, ast.Call):
        raise where.error("--task is a call of a task of the domain, e.g. row(2, 1, 2, 10)")
    return [Expr(node, where, text)]


class _MethodCompiler:
    def __init__(self, g, dom, emitter: Emitter, action_index: dict, objects: tuple):
        self.g, self.dom, self.em = g, dom, emitter
        self.action_index = action_index
        self.object_index = {n: i for i, n in enumerate(objects)}
        self.task_index = {n: i for i, n in enumerate(dom.tasks)}
        self.sources: list = []
        self.count = itertools.count()

    def is_class(self, t: str) -> bool:
        return t in self.dom.classes

    def method(self, m) -> list:
        """The method's variants: one per choice of objects for its parameters and
        variables of a class (every choice; none when a class has no objects)."""
        task = self.dom.tasks[m.task]
        for v in m.vars:
            if self.is_class(v.type) and self.dom.classes[v.type].key:
                raise _at(v.where, f"variable {v.name!r} is of the keyed class {v.type!r}: name its key "
                                   f"attributes as int variables instead")
        slots = [(p.name, p.type, i) for i, p in enumerate(task.params) if self.is_class(p.type)] + \
                [(v.name, v.type, None) for v in m.vars if self.is_class(v.type)]
        for name, cls, _ in slots:
            if self.dom.classes[cls].key:
                raise _at(m.where, f"method {m.name!r}: {name!r} is of the keyed class {cls!r}; "
                                            f"a task's parameters are ints, bools, enumerations or named objects")
        choices = [[(name, obj, pos, cls) for obj in self.g.by_class[cls]] for name, cls, pos in slots]
        out = []
        for combo in itertools.product(*choices):
            env = {name: ObjRef(obj, cls) for name, obj, _, cls in combo}
            fixed = tuple((pos, obj) for _, obj, pos, _ in combo if pos is not None)
            values = tuple(i for i, p in enumerate(task.params) if not self.is_class(p.type))
            out.append(self.compile(m.name, m.task, task.params, [v for v in m.vars if not self.is_class(v.type)],
                                    m.pre, m.subtasks, env, fixed, values))
        return out

    def compile(self, name, task, params, free_vars, pres, calls, env, fixed, values) -> Variant:
        """One generated function: the precondition's tests and bindings as nested `if`s
        and `for`s (each test as early as its variables are bound), the subtasks at the
        innermost level."""
        k = next(self.count)
        env = dict(env)
        for i in values:
            p = params[i]
            env[p.name] = ir.Local(f"{k}:{p.name}", p.type)
        for v in free_vars:
            env[v.name] = ir.Local(f"{k}:{v.name}", v.type)
        conjuncts = []
        for e in pres:
            value = self.g.bool_expr(e.node, Ctx(e, env))
            conjuncts += ir.conjuncts(value)
        lines, indent = [], "    "
        bound = {env[params[i].name].name for i in values}
        pending = [c for c in conjuncts if not (isinstance(c, ir.Const) and c.value)]
        if any(isinstance(c, ir.Const) and not c.value for c in pending):
            pending = [ir.FALSE]

        def flush():
            nonlocal indent
            ready = [c for c in pending if _free_locals(c) <= bound]
            if ready:
                lines.append(f"{indent}if {' and '.join(self.em.ex(c) for c in ready)}:")
                indent += "    "
                for c in ready:
                    pending.remove(c)

        flush()
        unbound = list(free_vars)
        while unbound:
            found = None
            for c in pending:
                pair = _equality(c, {env[v.name].name for v in unbound}, bound)
                if pair is not None:
                    found = (c, *pair)
                    break
            if found is not None:
                c, var, value = found
                pending.remove(c)
                lines.append(f"{indent}{self.em.local(var)} = {self.em.ex(value)}")
                v = next(v for v in unbound if env[v.name].name == var)
            else:
                v = unbound[0]
                lines.append(f"{indent}for {self.em.local(env[v.name].name)} in {self.domain_of(v, name)}:")
                indent += "    "
            unbound.remove(v)
            bound.add(env[v.name].name)
            flush()
        subtasks, shape = [], []
        for e in calls:
            text, sh = self.call(e, env)
            subtasks.append(text)
            shape.append(sh)
        lines.append(f"{indent}out.append(({''.join(s + ', ' for s in subtasks)}))")
        header = f"def _m{k}(s{''.join(', ' + self.em.local(env[params[i].name].name) for i in values)}):"
        self.sources.append(self.em._function(header, ["    out = []"] + lines + ["    return out"]))
        return Variant(name, task, fixed, values, f"_m{k}", tuple(shape))

    def domain_of(self, v, method: str) -> str:
        """The values an unbound variable ranges over, as generated code."""
        if v.type in self.dom.enums:
            return f"range({len(self.dom.enums[v.type].values)})"
        if v.type == "bool":
            return "(False, True)"
        if v.range is None:
            raise _at(v.where, f"variable {v.name!r} of method {method!r} is not bound: give it a `range` "
                               f"or a precondition `{v.name} == ...`")
        lo, hi = (self.g.const_int(e) for e in v.range)
        return f"range({lo}, {hi + 1})"

    def call(self, e: Expr, env: dict) -> tuple:
        """A subtask's generated value `(name, (args...))` and its shape for the estimate."""
        call = e.node
        ctx = Ctx(e, env)
        from .source import suggest
        known = self.dom.tasks if call.func in self.dom.tasks else self.dom.actions.get(call.func)
        if known is None:
            raise e.error(f"unknown task or action {call.func!r}"
                          f"{suggest(call.func, list(self.dom.tasks) + list(self.dom.actions))}", call)
        want = len(self.dom.tasks[call.func].params) if call.func in self.dom.tasks else len(known.params)
        if len(call.args) != want:
            raise e.error(f"{call.func} takes {want} argument(s), found {len(call.args)}", call)
        if call.func in self.dom.tasks:
            args = []
            for p, a in zip(self.dom.tasks[call.func].params, call.args):
                value = self.g.expr(a, ctx, p.type)
                got = self.g.type_of(value)
                if got != p.type:
                    raise e.error(f"type error: argument {p.name!r} of {call.func} is {p.type}, found {got}", a)
                if isinstance(value, ObjRef):
                    args.append(f"_O[{self.object_index[value.name]}]")
                elif isinstance(value, KeyRef) or not hasattr(value, "type"):
                    raise e.error(f"argument {p.name!r} of {call.func} must be a value", a)
                else:
                    args.append(self.em.ex(value))
            tuple_text = "(" + "".join(a + ", " for a in args) + ")"
            return f"(_T[{self.task_index[call.func]}], {tuple_text})", (call.func, ())
        schema = self.dom.actions[call.func]
        objs = []
        for p, a in zip(schema.params, call.args):
            value = self.g.expr(a, ctx, p.type)
            if not isinstance(value, ObjRef) or value.cls != p.type:
                raise e.error(f"argument {p.name!r} of the action {call.func} must be an object of the class "
                              f"{p.type!r} (a name, or a variable of that class)", a)
            objs.append(value.name)
        multi = any(len(self.g.by_class[p.type]) > 1 for p in schema.params)
        ground = f"{schema.name}({', '.join(objs)})" if multi else schema.name
        index = self.action_index.get(ground)
        if index is None:
            raise e.error(f"the action {ground} does not exist in this dungeon", call)
        return f"({index}, ())", (index, ())


def _free_locals(node) -> set:
    """The Locals an expression reads, less those a grid quantifier binds inside it."""
    if isinstance(node, ir.CellLoop):
        return _free_locals(node.body) - set(node.names)
    out = {node.name} if isinstance(node, ir.Local) else set()
    for child in ir.children(node):
        out |= _free_locals(child)
    return out


def _equality(c, unbound: set, bound: set):
    """(variable, value) when conjunct `c` is `v == E` (either way round) with v unbound
    and E's variables all bound; else None."""
    if not (isinstance(c, ir.Cmp) and c.ops == ("==",)):
        return None
    a, b = c.operands
    for var, value in ((a, b), (b, a)):
        if isinstance(var, ir.Local) and var.name in unbound and _free_locals(value) <= bound:
            return var.name, value
    return None


def _at(where: tuple, message: str) -> BccError:
    path, line, col = where
    return BccError(message, path, line, col)

