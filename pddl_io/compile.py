"""Compile a ground PDDL task (ground.py) into bcc's IR, then into a `Model`.

Why the IR: an imported problem then is a model like any compiled dungeon: a state is
`bytes` with one byte per atom (a boolean state variable), preconditions and goal are
IR conditions (`Var`, `Not`, `BoolOp`), effects are `SetVar` (under `When` for
conditional effects), and compiler/emit.py turns them into Python. PDDL semantics:
conditions read the state before the action, deletes apply before adds.

Successors use a decision tree instead of testing every action in turn (Fast Downward's
successor generator): actions are grouped under a test of a positive precondition atom
they share, so a state only looks at actions whose first atoms hold. The generated code
holds only indices and numbers: no text from the PDDL files reaches it.
"""
from __future__ import annotations

import functools
from collections import Counter

from ..compiler import ir
from ..compiler.emit import Emitter, GroundAction
from ..compiler.layout import Layout, Slot
from .ground import GroundTask

MAX_DEPTH = 40   # nesting of the decision tree (Python's parser limits indentation depth)


def formula_ir(f, var_of):
    if isinstance(f, int):
        return ir.Var(var_of[f])
    kind = f[0]
    if kind == "true":
        return ir.TRUE
    if kind == "false":
        return ir.FALSE
    if kind == "not":
        return ir.Not(formula_ir(f[1], var_of))
    return ir.BoolOp(kind, tuple(formula_ir(s, var_of) for s in f[1]))


def formula_text(f, task: GroundTask) -> str:
    if isinstance(f, int):
        return task.atom_text(f)
    kind = f[0]
    if kind in ("true", "false"):
        return "(and)" if kind == "true" else "(or)"
    if kind == "not":
        return f"(not {formula_text(f[1], task)})"
    return f"({kind} {' '.join(formula_text(s, task) for s in f[1])})"


def _conjuncts(f) -> list:
    if isinstance(f, tuple) and f[0] == "and":
        return list(f[1])
    if f == ("true",):
        return []
    return [f]


def to_ir(task: GroundTask):
    """(layout, state variables, IR actions, IR goal)."""
    var_of = [ir.StateVar(task.atom_text(i), "atom", "holds", "bool") for i in range(len(task.atoms))]
    slots = [Slot(v, i, 0, 1) for i, v in enumerate(var_of)]
    n = len(slots)
    layout = Layout(slots, {s.var: s for s in slots}, {}, 0, 0, 0, n, (), b"", 0)
    actions = []
    for a in task.actions:
        conj = _conjuncts(a.pre)
        effects = []
        for add in (False, True):   # deletes first, then adds: an atom both deleted and added stays true
            for cond, atom, is_add in a.effects:
                if is_add != add:
                    continue
                write = ir.SetVar(var_of[atom], ir.Const(add, "bool"))
                effects.append(write if cond == ("true",) else ir.When(formula_ir(cond, var_of), (write,), ()))
        actions.append(GroundAction(a.name, a.cost, [], [formula_ir(c, var_of) for c in conj],
                                    [formula_text(c, task) for c in conj], tuple(effects)))
    return layout, var_of, actions, formula_ir(task.goal, var_of)


def successors_source(em: Emitter, actions: list, layout) -> str:
    """`successors(s)` as a decision tree (a trie) over positive precondition atoms.

    Each action's positive atoms, most frequent first, are its path in the trie; an
    action sits at the end of its path (or at MAX_DEPTH), where only its other
    conditions remain to test. Building it is linear in the size of the actions."""
    index_of = {s.var: s.index for s in layout.slots}
    keys = [[index_of[c.var] for c in a.pre if isinstance(c, ir.Var)] for a in actions]
    freq = Counter(i for k in keys for i in k)
    root: dict = {}
    for i, k in enumerate(keys):
        node = root
        for atom in sorted(set(k), key=lambda t: (-freq[t], t))[:MAX_DEPTH]:
            node = node.setdefault(atom, {})
        node.setdefault(None, []).append(i)
    lines = ["def successors(s):", "    out = []"]

    def leaf(i, used, indent):
        a = actions[i]
        rest = [em.ex(c) for c in a.pre if not (isinstance(c, ir.Var) and index_of[c.var] in used)]
        if rest:
            lines.append(f"{indent}if {' and '.join(rest)}:")
            indent += "    "
        lines.append(f"{indent}n = bytearray(s)")
        lines.extend(em.effects(a.effects, indent, a.name) or [])
        lines.append(f"{indent}out.append(({i}, bytes(n)))")

    def emit(node, used, indent):
        for i in node.get(None, ()):
            leaf(i, used, indent)
        for atom, child in node.items():
            if atom is not None:
                lines.append(f"{indent}if s[{atom}]:")
                emit(child, used | {atom}, indent + "    ")

    emit(root, frozenset(), "    ")
    lines.append("    return out")
    return "\n".join(lines)


def build_functions(layout, actions: list, goal) -> tuple[dict, str]:
    """Generated `successors`, `goal` and `failure` (and their source). One action at a
    time (`apply_fns`, `why_fns`: replaying and explaining plans) reads the ground task
    instead (`action_functions`): compiling a function per action would cost more than
    the search on most IPC problems."""
    from ..errors import ModelError
    em = Emitter(layout, {})
    parts = [successors_source(em, actions, layout)]
    parts.append(em.predicate_source("goal", goal))
    parts.append(em.predicate_source("failure", ir.FALSE))
    source = "\n\n".join(parts) + "\n"
    ns = dict(em.ns)
    ns.setdefault("ModelError", ModelError)
    exec(compile(source, "<bcc pddl model>", "exec"), ns)
    return ns, source


def holds(f, s) -> bool:
    """A ground formula (ground.py) in state `s`."""
    if isinstance(f, int):
        return s[f] == 1
    kind = f[0]
    if kind == "not":
        return not holds(f[1], s)
    if kind == "and":
        return all(holds(g, s) for g in f[1])
    if kind == "or":
        return any(holds(g, s) for g in f[1])
    return kind == "true"


def action_functions(a) -> tuple:
    """(apply, why) of one ground action: PDDL semantics, conditions read the old state."""
    conj = _conjuncts(a.pre)

    def apply(s):
        if not all(holds(c, s) for c in conj):
            return None
        fire = [(atom, add) for cond, atom, add in a.effects if cond == ("true",) or holds(cond, s)]
        n = bytearray(s)
        for atom, add in fire:
            if not add:
                n[atom] = 0
        for atom, add in fire:
            if add:
                n[atom] = 1
        return bytes(n)

    def why(s):
        return next((k for k, c in enumerate(conj) if not holds(c, s)), None)

    return apply, why


def to_model(task: GroundTask, path: str, report: dict, files: tuple = ()):
    from ..model import Grid, Model, Variable
    layout, var_of, actions, goal = to_ir(task)
    ns, source = build_functions(layout, actions, goal)
    fns = [action_functions(a) for a in task.actions]
    n = len(var_of)
    initial = bytes(1 if i in task.initial else 0 for i in range(n))
    return Model(
        name=task.name, path=path, goal_text=formula_text(task.goal, task),
        action_names=tuple(a.name for a in actions), action_costs=tuple(a.cost for a in actions),
        initial=initial, successors=ns["successors"], live_successors=ns["successors"],  # no failure states
        apply_fns=tuple(f[0] for f in fns), why_fns=tuple(f[1] for f in fns),
        pre_texts=tuple(tuple(a.pre_text) for a in actions),
        is_goal=ns["goal"], is_failure=ns["failure"],
        variables=tuple(Variable(v.owner, i, 0, 1, "bool") for i, v in enumerate(var_of)),
        grid=Grid(0, 0, 0, n, (), b"", (), 0), position=(None, None, None), position_static=(0, 0, 0),
        goal_positions=None, report=report, source=source, search_actions=tuple(range(len(actions))),
        lazy={"ground_task": lambda: task, "ir": lambda: (actions, goal), "pddl_files": lambda: files,
              "relaxed_task": functools.partial(_relaxed_once, task, {})})


def _relaxed_once(task, cache: dict, time_limit: float | None = None):
    """The delete-relaxed view (relaxed.py), built on first use."""
    if "view" not in cache:
        from .relaxed import relaxed_task
        cache["view"] = relaxed_task(task)
    return cache["view"]
