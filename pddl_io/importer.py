"""Import a STRIPS PDDL problem (typed, negative preconditions) as a bcc model.

Why: so bcc's own solvers run on the field's benchmarks (gripper, blocksworld,
logistics, ...) and can be checked against Fast Downward there. Parsing and grounding
are unified-planning's (its PDDL reader; the grounder it picks, Fast Downward's
reachability grounder when `up-fast-downward` is installed); we only turn the grounded
actions into a `Model`: one state byte per atom that some action or the goal mentions,
each action's precondition and effects as a closure. The model has no grid (width,
depth and height 0, no position), so heuristics fall back to blind search.
"""
from __future__ import annotations

from pathlib import Path

from ..errors import BccError

HINT = 'importing PDDL needs unified-planning: pip install "bcc[pddl]"'


def _reader():
    try:
        import unified_planning.shortcuts as ups
        from unified_planning.io import PDDLReader
    except ImportError:
        raise BccError(HINT) from None
    ups.get_environment().credits_stream = None
    return PDDLReader()


def _parse(domain: str, problem: str):
    reader = _reader()
    for path in (domain, problem):
        if not Path(path).is_file():
            raise BccError("no such PDDL file", path)
    for files, blame in (((domain,), domain), ((domain, problem), problem)):
        try:
            parsed = reader.parse_problem(*files)
        except Exception as exc:  # noqa: BLE001 - pyparsing and unified-planning errors alike
            raise _read_error(exc, blame) from None
    return parsed


def _read_error(exc: Exception, path: str) -> BccError:
    """One BccError from pyparsing's (lineno, col) or unified-planning's message, which
    names the place in words ("... line: 5, col 19 to ...") or, for a name the domain
    does not declare, is a bare KeyError."""
    import re
    if isinstance(exc, KeyError):
        return BccError(f"cannot read PDDL: unknown name {exc.args[0]!r} (a type, predicate or object "
                        "the domain does not declare)", path)
    msg = str(getattr(exc, "msg", None) or exc).splitlines()[0]
    line, col = getattr(exc, "lineno", None), getattr(exc, "col", None)
    where = re.search(r"line:? (\d+),? col:? (\d+)", msg)
    if line is None and where:
        line, col = int(where[1]), int(where[2])
        msg = msg[:where.start()].rstrip(" ,.").removesuffix(" From").removesuffix(" found at").rstrip(" ,.")
    return BccError(f"cannot read PDDL: {msg}", path, line, col)


def _literals(expr, where: str) -> list | None:
    """A conjunction of (fluent, polarity); None if the expression is constant false."""
    if expr.is_and():
        out = []
        for arg in expr.args:
            sub = _literals(arg, where)
            if sub is None:
                return None
            out += sub
        return out
    if expr.is_fluent_exp():
        return [(expr, True)]
    if expr.is_not() and expr.arg(0).is_fluent_exp():
        return [(expr.arg(0), False)]
    if expr.is_bool_constant():
        return [] if expr.bool_constant_value() else None
    raise BccError(f"unsupported PDDL in {where}: {expr} (bcc imports STRIPS: conjunctions of literals)")


def _name(grounded, back) -> str:
    lifted = back.get(grounded)
    if lifted is None:
        return f"({grounded.name})"
    action, params = lifted
    return "(" + " ".join([action.name, *(str(p) for p in params)]) + ")"


def import_pddl(domain: str, problem: str):
    """Parse, ground and compile DOMAIN + PROBLEM into a `bcc.model.Model`."""
    from ..model import Grid, Model, Variable
    parsed = _parse(domain, problem)           # first: it says how to install unified-planning
    from unified_planning.shortcuts import CompilationKind, Compiler
    kind = parsed.kind
    if kind.has_numeric_fluents() or kind.has_continuous_time() or kind.has_conditional_effects():
        raise BccError("bcc imports STRIPS PDDL (with typing, negative preconditions, equality); "
                       f"this problem has {', '.join(sorted(f.lower() for f in kind.features))}", problem)
    try:
        with Compiler(problem_kind=kind, compilation_kind=CompilationKind.GROUNDING) as grounder:
            res = grounder.compile(parsed, CompilationKind.GROUNDING)
    except Exception as exc:  # noqa: BLE001
        raise BccError(f"cannot ground the PDDL problem: {exc}", problem) from None
    task = res.problem
    back = getattr(res.map_back_action_instance, "keywords", {}).get("map", {})
    atoms: dict = {}

    def index(f):
        return atoms.setdefault(f, len(atoms))

    actions = []
    for a in task.actions:
        pre = []
        ok = True
        for p in a.preconditions:
            lits = _literals(p, f"the precondition of {a.name}")
            if lits is None:
                ok = False
                break
            pre += lits
        if not ok:
            continue
        adds, dels = [], []
        for e in a.effects:
            if e.is_conditional() or not e.is_assignment() or not e.value.is_bool_constant():
                raise BccError(f"unsupported effect in {a.name}: {e} (bcc imports STRIPS)", domain)
            (adds if e.value.bool_constant_value() else dels).append(index(e.fluent))
        cost = 1
        actions.append((_name(a, back), [(index(f), v) for f, v in pre], dels, adds, cost))
    goal = []
    for g in task.goals:
        lits = _literals(g, "the goal")
        if lits is None:
            goal = None
            break
        goal += [(index(f), v) for f, v in lits]
    init_values = task.initial_values
    initial = bytes(1 if init_values[f].bool_constant_value() else 0 for f in atoms)
    return _model(Path(problem).stem, problem, actions, goal, initial, list(atoms), Grid, Model, Variable)


def _model(name, path, actions, goal, initial, atoms, Grid, Model, Variable):
    def make_apply(pre, dels, adds):
        def apply(s):
            for i, v in pre:
                if s[i] != v:
                    return None
            n = bytearray(s)
            for i in dels:
                n[i] = 0
            for i in adds:  # PDDL: deletes first, then adds
                n[i] = 1
            return bytes(n)
        return apply

    apply_fns = tuple(make_apply(p, d, a) for _, p, d, a, _ in actions)

    def successors(s):
        out = []
        for k, fn in enumerate(apply_fns):
            t = fn(s)
            if t is not None:
                out.append((k, t))
        return out

    def is_goal(s):
        return goal is not None and all(s[i] == v for i, v in goal)

    names = tuple(a[0] for a in actions)
    n = len(initial)
    return Model(
        name=name, path=path, goal_text="the PDDL goal", action_names=names,
        action_costs=tuple(a[4] for a in actions), initial=initial, successors=successors,
        apply_fns=apply_fns, why_fns=tuple((lambda s: None) for _ in actions), pre_texts=tuple(() for _ in actions),
        is_goal=is_goal, is_failure=lambda s: False,
        variables=tuple(Variable(str(f), i, 0, 1, "bool") for i, f in enumerate(atoms)),
        grid=Grid(0, 0, 0, n, (), b"", (), 0), position=(None, None, None), position_static=(0, 0, 0),
        goal_positions=None,
        report={"dungeon": name, "domain": "pddl", "atoms": n, "grounded_actions": len(actions)},
        search_actions=tuple(range(len(actions))))
