"""The grounded STRIPS task of a compiled model: facts, operators, initial state, goal.

Why grounded STRIPS: every PDDL planner and validator reads it, and Fast Downward's
optimal heuristics (lmcut) need it (no conditional effects, no axioms). Each operator is
one leaf of a bcc action's decision tree (symbolic.py), preceded by the failure test:
its precondition pins every state byte the action (or the failure test) reads, its
effect sets every byte it writes. Failure states therefore have no successors, as in
bcc's solvers.

A fact is (byte index, value); in PDDL it is `(agent-x n3)` for a variable or
`(cell x1 y0 z3 lava)` for a mutable grid cell. An operator `move_forward__17` maps back
to the bcc action `move_forward` (`Task.action_of`).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

from ..errors import InternalError, ModelError
from .domains import Domains, domains_for
from .symbolic import explore, symbolic_functions


@dataclass(frozen=True)
class Operator:
    name: str                 # PDDL name, e.g. "move_forward__17"
    action: int               # index into model.action_names
    cost: int
    pre: tuple                # ((byte, value), ...)
    add: tuple                # ((byte, value), ...)
    delete: tuple             # ((byte, value), ...)


@dataclass
class Task:
    name: str                 # PDDL domain/problem name
    model_name: str
    domain_name: str
    goal_text: str
    predicates: dict          # byte -> (predicate name, argument prefix tuple)
    value_names: dict         # byte -> tuple of constant names, one per raw value
    operators: list
    init: tuple               # facts true initially
    goal_terms: list          # disjunction of conjunctions of facts
    domains: Domains
    action_names: tuple       # the model's canonical action names
    use_costs: bool
    stats: dict = field(default_factory=dict)
    layout: tuple = (None, None)   # the model's (dense, compact): a fact's byte is a dense-layout byte

    def facts_of(self, state: bytes) -> frozenset:
        dense = self.layout[0]
        return frozenset(enumerate(dense(state) if dense else state))

    def state_of(self, facts) -> bytes:
        out = bytearray(len(self.predicates))
        for i, v in facts:
            out[i] = v
        compact = self.layout[1]
        return compact(bytes(out)) if compact else bytes(out)

    def atom(self, fact, flat: bool = False) -> str:
        """`(cell x1 y0 z3 lava)`, or with `flat` the 0-ary `(cell_x1_y0_z3_lava)`."""
        i, v = fact
        pred, args = self.predicates[i]
        return "(" + ("_" if flat else " ").join((pred, *args, self.value_names[i][v])) + ")"

    def action_of(self, op_name: str) -> str | None:
        """The canonical bcc action of a PDDL operator name (None for the goal operators)."""
        op = self._by_name.get(op_name.lower().strip("()").split()[0]) if op_name.strip() else None
        return None if op is None or op.action < 0 else self.action_names[op.action]

    @property
    def _by_name(self) -> dict:
        if not hasattr(self, "_names"):
            self._names = {op.name: op for op in self.operators}
        return self._names

    def successors(self, facts: frozenset) -> list:
        """(operator, next facts) for every applicable operator: a STRIPS reference semantics."""
        out = []
        for op in self.operators:
            if op.action >= 0 and all(f in facts for f in op.pre):
                out.append((op, (facts - set(op.delete)) | set(op.add)))
        return out

    def is_goal(self, facts) -> bool:
        return any(all(f in facts for f in term) for term in self.goal_terms)


GOAL_ACTION = "reach_goal"


def _sanitize(text: str) -> str:
    s = re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-")
    return s if s and s[0].isalpha() else f"v-{s}"


def _unique(names: list) -> tuple:
    seen: dict = {}
    out = []
    for n in names:
        k = seen.get(n, 0)
        seen[n] = k + 1
        out.append(n if k == 0 else f"{n}-{k}")
    return tuple(out)


def _naming(model, n_bytes: int):
    predicates, value_names = {}, {}
    used = {"cell"}
    for v in model.variables:
        name = _sanitize(v.label)
        while name in used:
            name += "-v"
        used.add(name)
        predicates[v.index] = (name, ())
        if v.names:
            values = [_sanitize(x) for x in v.names]
        elif v.type == "bool":
            values = ["false", "true"]
        else:
            values = [f"n{v.lo + k}" for k in range(v.hi - v.lo + 1)]
        value_names[v.index] = _unique(values)
    g = model.grid
    area = g.width * g.depth
    cells = _unique([_sanitize(x) for x in g.value_names])
    for k, y in enumerate(g.layers):
        for z in range(g.depth):
            for x in range(g.width):
                i = g.base + k * area + z * g.width + x
                predicates[i] = ("cell", (f"x{x}", f"y{y}", f"z{z}"))
                value_names[i] = cells
    for i in range(n_bytes):
        if i not in predicates:
            raise InternalError(f"state byte {i} of {model.name} belongs to no variable or cell")
    return predicates, value_names


def build_task(model, max_states: int | None = None) -> Task:
    """Ground `model` into STRIPS (see the module docstring)."""
    from .domains import DEFAULT_MAX_STATES
    domains = domains_for(model, DEFAULT_MAX_STATES if max_states is None else max_states)
    dom = domains.values
    fns = symbolic_functions(model)
    initial = model.dense(model.initial)   # symbolic_functions read the dense layout
    predicates, value_names = _naming(model, len(initial))
    ops, errors, unreachable = [], 0, 0
    for a, leaves in enumerate(domains.leaves):
        stem = re.sub(r"[^a-z0-9_]+", "_", model.action_names[a].lower())
        k = 0
        for leaf in leaves:
            if leaf.result is None:
                continue
            if not isinstance(leaf.result, dict):
                errors += 1      # the action raises a domain error here: no transition
                continue
            pre = tuple(sorted((i, vs[0]) for i, vs in leaf.allowed.items()))
            old = dict(pre)
            if any(v not in dom[i] for i, v in leaf.result.items()):
                unreachable += 1  # writes a value outside the fixpoint's domains: never fires
                continue
            changes = sorted((i, v) for i, v in leaf.result.items() if v != old[i])
            ops.append(Operator(f"{stem}__{k}", a, model.action_costs[a], pre,
                                tuple(changes), tuple((i, old[i]) for i, _ in changes)))
            k += 1
    goal_terms = []
    for leaf in explore(fns["goal"], dom):
        if leaf.result is not ModelError and leaf.result:
            goal_terms.append(tuple(sorted((i, vs[0]) for i, vs in leaf.allowed.items())))
    use_costs = len(goal_terms) != 1 or any(c != 1 for c in model.action_costs)
    if len(goal_terms) != 1:
        for k, term in enumerate(goal_terms):
            ops.append(Operator(f"{GOAL_ACTION}__{k}", -1, 0, term, (), ()))
    name = _sanitize(model.name)
    n_facts = sum(len(d) for d in dom)
    return Task(name=name, model_name=model.name, domain_name=model.report.get("domain", ""),
                goal_text=model.goal_text, predicates=predicates, value_names=value_names, operators=ops,
                init=tuple(enumerate(initial)), goal_terms=goal_terms, domains=domains,
                action_names=tuple(model.action_names), use_costs=use_costs, layout=(model.dense, model.compact),
                stats={"operators": len(ops), "facts": n_facts, "goal_terms": len(goal_terms),
                       "domains": domains.source, "abstract_states": domains.states, "rounds": domains.rounds,
                       "error_leaves": errors, "unreachable_leaves": unreachable})

