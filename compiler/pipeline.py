"""Compile a dungeon (and its domain) into a `Model`: load -> ground -> lay out -> emit.

The package's entry points (bcc.compiler.compile_dungeon, ...) live here; compiler/__init__.py
loads this module on first use.

    model = compile_dungeon("bridge")                 # a shipped name or a path
    model = compile_dungeon("four_rooms", goal="agentInRoom(agent, red)")
"""
from __future__ import annotations

import functools
import itertools
from dataclasses import dataclass
from pathlib import Path


from ..errors import BccError
from ..model import Grid, Model, Variable
from . import ir
from .abstract import Abstract, maybe_true
from .definitions import Expr
from .domain import is_file, load_domain
from .dungeon import Dungeon, load_dungeon, resolve_dungeon_path, shipped_dungeons
from .emit import Emitter
from .ir import GroundAction
from .ground import Grounder
from .ground_effects import check_nesting
from .ground_refs import Ctx, ObjRef
from .layout import make_layout
from .reachability import Analysis, reachable
from .access import reads
from .relevance import relevant_actions
from .source import Origin
from .steps import position_steps

@dataclass(frozen=True)
class Compiled:
    """What a compile knows beyond the Model, for analyses that layers above build on
    demand (the heuristics' tables, heuristics/tables.py): `model.data("compiled")`."""
    layout: object          # the state layout (layout.py); its start cells, static grid
    actions: list           # the grounded actions (emit.GroundAction, IR)
    search: list            # the actions `successors` generates (relevance.py)
    goal: object            # the goal and the failure condition (IR)
    failure: object
    reach: object           # reachability.py's answer: values, applicable actions, written layers
    n_values: int           # values a grid cell may hold
    initial: bytes          # the start (the variables; cells at their start values)
    source: str             # the generated code: the cached tables' key
    position_vars: list     # the agent's position variables
    functions: dict         # the generated functions by name (apply_i, goal, failure, ...)


__all__ = ["compile_dungeon", "load_dungeon", "load_domain", "shipped_dungeons", "resolve_dungeon_path"]


def compile_dungeon(ref: str | Path, goal: str | None = None, prune: bool = True, task: str | None = None) -> Model:
    """Load, check, ground, analyse and emit. With `prune`, `successors` leaves out actions
    that can never apply or never matter for the goal (relevance.py); `apply` keeps all.
    `task` (a call of one of the domain's tasks) replaces the dungeon's `task:`."""
    dungeon = _load(ref)
    network = dungeon.task
    if task is not None:
        from .hierarchy import parse_task_option
        network = parse_task_option(task)
    task = _ground(dungeon, _goal(dungeon, goal, network))
    layout, initial, reach, an = _lay_out(task)
    search = (sorted(relevant_actions(task.actions, sorted(reach.applicable), task.goal, task.failure, an))
              if prune else list(range(len(task.actions))))
    enum_sizes = {n: len(e.values) for n, e in dungeon.domain.enums.items()}
    emitter = Emitter(layout, enum_sizes)
    ns, source = emitter.build(task.actions, task.goal, task.failure, search)
    _check_start(task.grounder, emitter, ns, dungeon, initial)
    hierarchy = None
    if dungeon.domain.methods or dungeon.domain.tasks or network:   # methods are checked for every dungeon of their domain
        from .hierarchy import build_hierarchy
        hierarchy = build_hierarchy(task.grounder, dungeon, layout, enum_sizes, tuple(a.name for a in task.actions),
                                    network, ns)
    return _model(task, layout, initial, reach, an, search, ns, source, enum_sizes, hierarchy)


@dataclass
class _Ground:
    """A dungeon's ground task: its actions, goal and failure condition as IR."""
    dungeon: Dungeon
    goal_src: Expr
    grounder: Grounder
    actions: list           # emit.GroundAction
    dynamic: set            # the object attributes some action writes
    layers: set | None      # the grid layers some action writes (None: a computed layer)
    goal: object
    failure: object
    n_values: int           # values a grid cell may hold


def _ground(dungeon: Dungeon, goal_src: Expr) -> _Ground:
    """Ground in two passes: the first finds which attributes and grid layers actions
    change, the second folds every other read into a constant."""
    Grounder(dungeon, None).check_domain()
    discovery = Grounder(dungeon, None)
    _ground_actions(discovery, dungeon, symbolic_values=True)
    dynamic = {w for w in discovery.writes if w[0] != "<grid>"}
    g = Grounder(dungeon, dynamic)
    _check_keyed_objects(g, dungeon)
    actions = _ground_actions(g, dungeon)
    grid_ys = [y for kind, y in g.writes if kind == "<grid>"]
    layers = None if any(not isinstance(y, ir.Const) for y in grid_ys) else \
        {int(y.value) for y in grid_ys if 0 <= y.value < dungeon.height}
    dom = dungeon.domain
    failure = g.bool_expr(dom.failure.node, Ctx(dom.failure)) if dom.failure else ir.FALSE
    venum = dom.enums[dom.classes[dungeon.grid_class].attrs[_grid_value_attr(dungeon)].type]
    return _Ground(dungeon, goal_src, g, actions, dynamic, layers,
                   g.bool_expr(goal_src.node, Ctx(goal_src)), failure, len(venum.values))


def _lay_out(task: _Ground):
    """The state layout, laid out twice: relaxed reachability from the first start refines
    which layers really change (and which actions can apply), and the second layout
    stores only those."""
    g, dungeon = task.grounder, task.dungeon
    layout = make_layout(g, dungeon, task.dynamic, task.layers)
    initial = layout.initial(g, dungeon)
    reach = reachable(layout, task.actions, {s.var: initial[s.index] + s.lo for s in layout.slots}, task.n_values)
    layout = make_layout(g, dungeon, task.dynamic, {y for y, vals in reach.written.items() if vals})
    return layout, layout.initial(g, dungeon), reach, Analysis(layout, task.n_values)


def _model(task: _Ground, layout, initial: bytes, reach, an: Analysis, search: list, ns: dict, source: str,
           enum_sizes: dict, hierarchy=None) -> Model:
    """The Model: the generated functions, the state's variables and grid, the agent's
    position, and what layers above build on demand (`lazy`; `hierarchy`: the methods
    and task network the htn solver plans with, compiler/hierarchy.py)."""
    dungeon, actions, dom = task.dungeon, task.actions, task.dungeon.domain

    @functools.lru_cache(maxsize=1)
    def dense_functions():
        """The same functions over the dense layout (`Model.dense`), for the PDDL export."""
        dense_ns, _ = Emitter(layout, enum_sizes, compact=False).build(actions, task.goal, task.failure, search)
        return dense_ns

    venum = dom.enums[dom.classes[dungeon.grid_class].attrs[_grid_value_attr(dungeon)].type]
    grid = Grid(dungeon.width, dungeon.depth, dungeon.height, layout.grid_base, layout.layers,
                layout.static_grid, tuple(venum.values), layout.grid_default)
    variables = tuple(Variable(s.var.label, s.index, s.lo, s.hi, s.var.type,
                               tuple(dom.enums[s.var.type].values) if s.var.type in dom.enums else ())
                      for s in layout.slots)
    position, static_pos, position_vars = _position(dungeon, layout)
    goal_positions = _goal_positions(an, reach, task.goal, position, static_pos, position_vars, layout)
    steps = position_steps(actions, search, position_vars, position)

    layer_expanders = functools.lru_cache(maxsize=1)(ns["_build_layers"])

    def layer_skips() -> dict:
        """What a layered search skips (compiler/inverses.py), by action name:
        {"undone_by": {a: [b]}, "skipped_after": {a: [b]}}."""
        layer_expanders()
        names = lambda d: {actions[a].name: [actions[b].name for b in bs] for a, bs in d.items()}
        return {"undone_by": names(ns["_undo"]), "skipped_after": names(ns["_skips"])}

    compiled = Compiled(layout, actions, search, task.goal, task.failure, reach, task.n_values, initial, source,
                        position_vars, ns)
    return Model(
        name=dungeon.name, path=dungeon.path, goal_text=task.goal_src.text,
        action_names=tuple(a.name for a in actions), action_costs=tuple(a.cost for a in actions),
        initial=initial, successors=ns["successors"], live_successors=ns["live"],
        fresh_successors=ns["fresh"],
        apply_fns=tuple(ns[f"apply_{i}"] for i in range(len(actions))),
        why_fns=tuple(ns[f"why_{i}"] for i in range(len(actions))),
        pre_texts=tuple(tuple(a.pre_text) for a in actions),
        is_goal=ns["goal"], is_failure=ns["failure"], variables=variables, grid=grid,
        position=position, position_static=static_pos, goal_positions=goal_positions, position_steps=steps,
        report={**_report(task, layout, initial, reach, search, goal_positions), **_hierarchy_report(dom, hierarchy)},
        source=source,
        display=_display(dungeon, layout),
        search_actions=tuple(search), lazy={"compiled": lambda: compiled,
                                                    "layer_expanders": layer_expanders,
                                                    "layer_skips": layer_skips,
                                                    "dense_functions": dense_functions,
                                                    "hierarchy": lambda: hierarchy})


def _hierarchy_report(dom, hierarchy) -> dict:
    """`bcc compile --json`'s tasks and methods (only for a domain that has some) and the
    dungeon's task network (None without one)."""
    if hierarchy is None:
        return {}
    from .tasks import describe
    tasks, methods = describe(dom.tasks, dom.methods)
    return {"tasks": tasks, "methods": methods, "task": hierarchy.network_text or None}


def _report(task: _Ground, layout, initial: bytes, reach, search: list, goal_positions) -> dict:
    """What `bcc compile --json` says about the compile (Model.report)."""
    dungeon, actions, dom, g = task.dungeon, task.actions, task.dungeon.domain, task.grounder
    return {
        "dungeon": dungeon.name, "domain": dom.name, "size": dungeon.sizes,
        "classes": {c: {"attributes": {a: ad.type for a, ad in cd.attrs.items()}, "key": cd.key}
                    for c, cd in dom.classes.items()},
        "objects": {c: (g.by_class[c] if not cd.key else
                        (f"{dungeon.width * dungeon.height * dungeon.depth} cells" if c == dungeon.grid_class
                         else f"{len(g.keys_of(c))} keyed objects"))
                    for c, cd in dom.classes.items()},
        "functions": {f: [f"{p.name}: {p.type}" for p in fd.params] for f, fd in dom.functions.items()},
        "action_schemas": {a: [f"{p.name}: {p.type}" for p in ad.params] for a, ad in dom.actions.items()},
        "grounded_actions": len(actions),
        "never_applicable": [actions[i].name for i in range(len(actions)) if i not in reach.applicable],
        "pruned_from_search": [actions[i].name for i in range(len(actions)) if i not in search],
        "state_variables": len(layout.slots),
        "mutable_cells": len(layout.layers) * dungeon.width * dungeon.depth,
        "mutable_layers": list(layout.layers),
        # a state: the variables, then 4 bytes per cell that differs from the start
        "state_bytes": {"start": len(initial), "per_changed_cell": 4,
                        "worst": len(initial) + 4 * layout.mutable_cells, "dense": layout.size},
        "goal": task.goal_src.text,
        "goal_positions": None if goal_positions is None else len(goal_positions),
        "structure": dungeon.structure.summary() if dungeon.structure is not None else None,
        "warnings": [str(w) for w in dungeon.warnings],
    }


def _check_start(g: Grounder, emitter: Emitter, ns: dict, dungeon: Dungeon, initial: bytes) -> None:
    """The domain's `dungeon.start` condition (e.g. "the agent's cells are free") must hold
    in the dungeon's start, or the agent would begin stuck inside a wall with no hint why."""
    from .source import error_at
    src = dungeon.domain.start
    if src is None:
        return
    source = emitter.predicate_source("start_ok", g.bool_expr(src.node, Ctx(src)))
    # the check may need a constants table no action's code made (a domain with no actions)
    space = {**emitter.ns, **ns}
    exec(compile(source, "<bcc start>", "exec"), space)
    if space["start_ok"](initial):
        return
    text = " ".join(src.text.split())
    message = f"the dungeon's start breaks its domain's start condition `{text}`"
    where = dungeon.where.get((dungeon.agent_name, "x"))
    raise error_at(*where, message + " (is the agent inside a block?)") if where else BccError(message, dungeon.path)


def _load(ref) -> Dungeon:
    """load_dungeon, through the on-disk cache (compiler/cache.py) when `ref` names a file."""
    from .cache import load_cached
    path = resolve_dungeon_path(ref)
    return load_cached(path, load_dungeon)


def _goal(dungeon: Dungeon, goal: str | None, network=None) -> Expr:
    if goal is not None and goal.endswith((".yaml", ".yml")) and is_file(Path(goal)):
        return _structure_file(dungeon, goal)
    if goal is not None:
        dungeon.structure = None
        from .parse import parse_expression   # lark: imported only when text is parsed
        where = Origin("--goal", 1, 1)
        return Expr(parse_expression(goal, where), where, goal)
    if dungeon.goal is None and network:   # a task alone: done when the task is
        from . import ast
        return Expr(ast.Bool(True, (1, 1)), Origin(dungeon.path, 1, 1), "true")
    if dungeon.goal is None:
        raise BccError("the dungeon has no `goal`; add one or pass --goal EXPRESSION", dungeon.path)
    return dungeon.goal


def _structure_file(dungeon: Dungeon, path: str) -> Expr:
    """`--goal FILE.yaml`: a file holding a blueprint (`structure:`, compiler/structure.py)."""
    from .source import error_on, load_yaml
    from .structure import is_structure, read_blueprint, structure_expr
    data = load_yaml(path)
    if not is_structure(data):
        raise error_on(data, "a goal file holds a blueprint: a mapping with `structure:`")
    cdef = dungeon.domain.classes[dungeon.grid_class]
    attr = _grid_value_attr(dungeon)
    values = tuple(dungeon.domain.enums[cdef.attrs[attr].type].values)
    dungeon.structure = read_blueprint(data, values, (dungeon.width, dungeon.height, dungeon.depth))
    return structure_expr(dungeon.structure, data, dungeon.grid_class, attr)


def _check_keyed_objects(g: Grounder, d: Dungeon) -> None:
    """Objects a dungeon gives by key (inventory slots) must exist in their class's key range,
    and every integer a dungeon gives a named object must lie in its attribute's range."""
    from .source import error_at
    for name, (cls, values) in d.objects.items():
        cdef = d.domain.classes[cls]
        for attr, value in values.items():
            rng = g.attr_range(cdef, attr) if cdef.attrs[attr].type == "int" else None
            if rng is not None and not rng[0] <= value <= rng[1]:
                where = d.where.get((name, attr))
                message = f"{name}.{attr} = {value} is outside its range [{rng[0]}, {rng[1]}]"
                raise error_at(*where, message) if where else BccError(message, d.path)
    for cls, objects in d.keyed.items():
        valid = set(g.keys_of(cls))
        for key in objects:
            if key not in valid:
                where = d.where.get(((cls, key), "key"))
                message = f"{cls}[{', '.join(map(str, key))}] does not exist: keys range over {g.key_ranges[cls]}"
                raise error_at(*where, message) if where else BccError(message, d.path)


def _grid_value_attr(d: Dungeon) -> str:
    cdef = d.domain.classes[d.grid_class]
    return next(a for a in cdef.attrs if a not in cdef.key)


def _ground_actions(g: Grounder, d: Dungeon, symbolic_values: bool = False) -> list[GroundAction]:
    """Each schema once per combination of its parameters' choices: the named objects of a
    class, or the values of an enumeration (`params: {r: recipe}`). A schema with an
    enumeration parameter is grounded only for the values its preconditions allow in some
    state: a combination whose preconditions are false whatever the state is left out
    (`m.tool_needed > 0` keeps the values of m that need one). With `symbolic_values` (the
    pass that only finds which attributes actions write), an enumeration parameter is one
    run-time stand-in instead of each value: the same attributes, grounded once."""
    out = []
    enums = d.domain.enums
    for schema in d.domain.actions.values():
        choices = []
        for p in schema.params:
            if p.type in enums:
                choices.append([(p.name, p.name, ir.Local(f"__{p.name}", p.type))] if symbolic_values else
                               [(p.name, v, ir.Const(i, p.type)) for i, v in enumerate(enums[p.type].values)])
                continue
            if p.type not in g.by_class or d.domain.classes[p.type].key:
                raise schema.effects.where.error(
                    f"action {schema.name}: parameter {p.name!r} must be of a class of named objects "
                    f"or an enumeration, not {p.type!r}")
            choices.append([(p.name, obj, ObjRef(obj, p.type)) for obj in g.by_class[p.type]])
        multi = any(len(c) > 1 for c in choices)
        by_value = any(p.type in enums for p in schema.params)
        for combo in itertools.product(*choices):
            name = f"{schema.name}({', '.join(o for _, o, _ in combo)})" if multi else schema.name
            action = _ground_one(g, schema, name, combo, len(out), skip_false=by_value)
            if action is not None:
                out.append(action)
    return out


def _ground_one(g: Grounder, schema, name: str, combo, number: int, skip_false: bool = False) -> GroundAction | None:
    """The action for one combination; with `skip_false`, None when a precondition is false
    whatever the state is."""
    env = {pname: value for pname, _, value in combo}
    lets = []
    for let_name, src in schema.lets:
        value = g.expr(src.node, Ctx(src, env))
        if isinstance(value, (ir.Const, ir.Local)) or not hasattr(value, "type") or not isinstance(value.type, str) \
                or value.type in g.dom.classes:
            env[let_name] = value  # constants and object references are substituted, not stored
            continue
        loc = ir.Local(f"a{number}_{let_name}", value.type)
        lets.append((loc, value))
        env[let_name] = loc
    pre, texts = [], []
    for src in schema.pre:
        cond = g.bool_expr(src.node, Ctx(src, env))
        if isinstance(cond, ir.Const) and cond.value:
            continue
        if skip_false and isinstance(cond, ir.Const):
            return None
        pre.append(cond)
        texts.append(" ".join(src.text.split()))
    effects = g.effects(schema.effects.node, Ctx(schema.effects, env))
    check_nesting(name, pre, effects, schema.effects)
    return GroundAction(name, schema.cost, lets, pre, texts, effects)


def _position(d: Dungeon, layout):
    """Per axis of the agent's `position`: (state index, low) if it changes, else its value."""
    cls_name, values = d.objects[d.agent_name]
    cdef = d.domain.classes[cls_name]
    dyn, static, variables = [], [], []
    for axis in cdef.position:
        var = ir.StateVar(d.agent_name, cls_name, axis, cdef.attrs[axis].type)
        slot = layout.by_var.get(var)
        dyn.append((slot.index, slot.lo) if slot else None)
        static.append(None if slot else values.get(axis, cdef.attrs[axis].default))
        variables.append(var)
    return tuple(dyn), tuple(static), variables


def _goal_positions(an: Analysis, reach, goal_ir, position, static_pos, position_vars, layout):
    """Agent positions at which the goal may hold (an over-approximation), for Manhattan.

    The box of positions is split in halves, an axis at a time, and a part where the goal
    cannot hold is dropped whole: a goal "stand here" costs a few dozen evaluations, not
    one per position of a large world. A goal that reads no position holds anywhere."""
    if not position:
        return None
    cell, layer = an.cells(reach.written)
    axes = [(value, value) if dyn is None else (layout.slots[dyn[0]].lo, layout.slots[dyn[0]].hi)
            for dyn, value in zip(position, static_pos)]
    dynamic = [var for var, dyn in zip(position_vars, position) if dyn is not None]
    read = reads(goal_ir, vars_of=an.vars_of)
    if not read & set(dynamic):
        if maybe_true(Abstract({}, cell, layer, sets=dict(reach.values), var_at=an.var_at).eval(goal_ir)):
            return tuple(itertools.product(*(range(lo, hi + 1) for lo, hi in axes)))
        return ()
    found = []

    def maybe(box) -> bool:
        sets = dict(reach.values)
        sets.update({var: frozenset(range(lo, hi + 1))
                     for var, dyn, (lo, hi) in zip(position_vars, position, box) if dyn is not None})
        return maybe_true(Abstract({}, cell, layer, sets=sets, var_at=an.var_at).eval(goal_ir))

    def split(box) -> None:
        if not maybe(box):
            return
        wide = max(range(len(box)), key=lambda i: box[i][1] - box[i][0])
        lo, hi = box[wide]
        if lo == hi:
            found.append(tuple(lo for lo, _ in box))
            return
        mid = (lo + hi) // 2
        split(box[:wide] + [(lo, mid)] + box[wide + 1:])
        split(box[:wide] + [(mid + 1, hi)] + box[wide + 1:])

    split(axes)
    return tuple(sorted(found))


def facing_slot(d: Dungeon, layout) -> tuple | None:
    """(the agent's facing attribute: its name, its definition, its state slot or None
    when the layout keeps no slot for it), or None when the domain binds no facing."""
    attr = (d.domain.binding.get("agent_fields") or {}).get("facing")
    cls_name = d.objects[d.agent_name][0]
    adef = d.domain.classes[cls_name].attrs.get(attr) if attr else None
    if adef is None:
        return None
    return attr, adef, layout.by_var.get(ir.StateVar(d.agent_name, cls_name, attr, adef.type))


def _display(d: Dungeon, layout) -> dict:
    """What `bcc show` needs to draw a state: legend glyphs and the agent's facing."""
    legend_src = d.legend_columns
    start_char = d.start_char
    glyphs = {}
    for ch, column in legend_src.items():
        key = tuple(column)
        if key not in glyphs or glyphs[key] == start_char:
            glyphs[key] = ch
    facing = None
    found = facing_slot(d, layout)
    if found:
        attr, adef, slot = found
        by_value = {v: k for k, v in adef.names.items()}
        facing = {"index": slot.index if slot else None, "lo": slot.lo if slot else 0,
                  "value": d.objects[d.agent_name][1].get(attr), "names": by_value}
    # Other named objects with a position are drawn by the initial of their name.
    objects = []
    for name, (cls, values) in d.objects.items():
        pos = d.domain.classes[cls].position
        if name != d.agent_name and len(pos) == 3:
            objects.append((name, values.get(pos[0]), values.get(pos[2])))
    chars = dict(d.structure.chars) if d.structure is not None else {}   # a blueprint's own legend
    return {"glyphs": glyphs, "facing": facing, "default": layout.grid_default, "objects": objects,
            "value_chars": chars}
