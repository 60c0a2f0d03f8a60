"""Compile a ground PDDL task (ground.py) into a `Model`.

An imported problem is a model like any compiled dungeon, with one boolean state
variable per atom; bits.py turns the ground formulas and effects into Python over int
states (bit i is atom i), which is faster than compiler/emit.py's byte-per-variable
states for tasks made only of booleans. PDDL semantics: conditions read the state before
the action, deletes apply before adds. The generated code holds only numbers: no text
from the PDDL files reaches it.
"""
from __future__ import annotations

import functools

from .bits import BitEmitter, atom_shares
from .ground import GroundTask
from .lifted_types import conjuncts


def formula_text(f, task: GroundTask) -> str:
    if isinstance(f, int):
        return task.atom_text(f)
    kind = f[0]
    if kind in ("true", "false"):
        return "(and)" if kind == "true" else "(or)"
    if kind == "not":
        return f"(not {formula_text(f[1], task)})"
    return f"({kind} {' '.join(formula_text(s, task) for s in f[1])})"


SAMPLED_TREE_ACTIONS = 400   # tasks with this many actions get blind search's tree from a sample
SAMPLE_STATES = 2000          # of the first states blind search expands
PRUNED_TREE_AFTER = 50_000    # expansions before blind search's sampled tree is built
INTERPRETED_CALLS = 64        # `successors` calls answered by the ground task before it is compiled
MAX_COST_LEVELS = 256         # distinct action costs a search by cost keeps apart (one local each)


def build_functions(actions: list, goal) -> tuple[dict, str]:
    """Generated `goal` and the layer expander `expand` (Model.search_layers, for
    breadth-first and blind search) over int states (bits.py), and their source; and,
    compiled only when first needed, `successors` and `cost_expander()` (the expander of
    a blind search by cost, solvers/uniform_cost.py; None when every action costs the
    same). One action at a time (`apply_fns`, `why_fns`: replaying and explaining plans)
    reads the ground task instead (`action_functions`).

    Why so lazy: Python compiles a tree of thousands of actions in 0.1-0.3 s, more than
    the whole search on most IPC problems blind search solves (grid p01: 0.40 s to build
    the model with two trees compiled, the search 0.1 s). So `successors` answers its
    first INTERPRETED_CALLS calls (a plan's steps, LM-cut's first states) from the ground
    task, in the tree's order, and is compiled on the next one; and on tasks with
    SAMPLED_TREE_ACTIONS actions or more, blind search starts on the tree by frequency and
    after PRUNED_TREE_AFTER expansions moves to one whose tests prune most in the first
    SAMPLE_STATES states it expanded (bits._tree_by_pruning: freecell p3 23 % faster a
    state, barman 5 %)."""
    em = BitEmitter()
    parts = [em.predicate_source("goal", goal), em.successors_source(actions, goal=goal)]
    ns: dict = {}
    exec(compile("\n\n".join(parts) + "\n", "<bcc pddl model>", "exec"), ns)
    ns["failure"] = _never
    ns["expand"] = _sampling_expander(em, actions, goal, ns["expand"]) if len(actions) >= SAMPLED_TREE_ACTIONS \
        else ns["expand"]
    ns["successors"] = _lazy_successors(em, actions)
    costs = [a.cost for a in actions]

    @functools.lru_cache(maxsize=1)
    def cost_expander():
        if len(set(costs)) <= 1 or len(set(costs)) > MAX_COST_LEVELS \
                or not all(type(c) is int and c >= 0 for c in costs):
            return None
        made: dict = {}
        exec(compile(em.successors_source(actions, costs=costs), "<bcc pddl model>", "exec"), made)
        return made["expand_costs"], tuple(sorted(set(costs)))
    ns["cost_expander"] = cost_expander
    return ns, "\n\n".join(parts) + "\n"


def _lazy_successors(em: BitEmitter, actions: list):
    """`successors(s)` (see build_functions): interpreted, then compiled."""
    order = em.tree_order(actions)
    checks = [(a, em.positive_mask(actions[a]), action_functions(actions[a])[0]) for a in order]
    compiled: list = []
    calls = [0]

    def successors(s):
        if compiled:
            return compiled[0](s)
        calls[0] += 1
        if calls[0] <= INTERPRETED_CALLS:
            return [(a, n) for a, m, apply in checks if s & m == m and (n := apply(s)) is not None]
        made: dict = {}
        exec(compile(em.successors_source(actions), "<bcc pddl model>", "exec"), made)
        compiled.append(made["successors"])
        return compiled[0](s)
    return successors


def _sampling_expander(em: BitEmitter, actions: list, goal, first):
    """`expand` (Model.search_layers) that runs `first` and keeps the first SAMPLE_STATES
    states it is handed; after PRUNED_TREE_AFTER of them, it compiles the tree chosen by
    what prunes in that sample and runs that one."""
    current = [first]
    sample: list = []
    count = [0]

    def expand(states, seen, outs):
        if current[0] is first:
            if len(sample) < SAMPLE_STATES:
                sample.extend(states[:SAMPLE_STATES - len(sample)])
            count[0] += len(states)
            if count[0] >= PRUNED_TREE_AFTER:
                made: dict = {}
                source = em.successors_source(actions, prob=atom_shares(sample), goal=goal)
                exec(compile(source, "<bcc pddl model>", "exec"), made)
                current[0] = made["expand"]
        return current[0](states, seen, outs)
    return expand


def _never(s) -> bool:
    """An imported task has no failure states."""
    return False


def holds(f, s) -> bool:
    """A ground formula (ground.py) in state `s` (an int: bit i is atom i)."""
    if isinstance(f, int):
        return s >> f & 1 == 1
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
    conj = conjuncts(a.pre)

    def apply(s):
        if not all(holds(c, s) for c in conj):
            return None
        fire = [(atom, add) for cond, atom, add in a.effects if cond == ("true",) or holds(cond, s)]
        dels = adds = 0
        for atom, add in fire:
            if add:
                adds |= 1 << atom
            else:
                dels |= 1 << atom
        return s & ~dels | adds

    def why(s):
        return next((k for k, c in enumerate(conj) if not holds(c, s)), None)

    return apply, why


def to_model(task: GroundTask, path: str, report: dict, files: tuple = ()):
    from ..model import Grid, Model, Variable
    actions = task.actions
    initial = sum(1 << i for i in task.initial)   # an int: bit i is atom i (bits.py)
    ns, source = build_functions(actions, task.goal)
    fns = [action_functions(a) for a in actions]
    n = len(task.atoms)
    return Model(
        name=task.name, path=path, goal_text=formula_text(task.goal, task),
        action_names=tuple(a.name for a in actions), action_costs=tuple(a.cost for a in actions),
        initial=initial, successors=ns["successors"], live_successors=ns["successors"],  # no failure states
        apply_fns=tuple(f[0] for f in fns), why_fns=tuple(f[1] for f in fns),
        pre_texts=tuple(tuple(formula_text(c, task) for c in conjuncts(a.pre)) for a in actions),
        is_goal=ns["goal"], is_failure=ns["failure"],
        variables=tuple(Variable(task.atom_text(i), i, 0, 1, "bool") for i in range(n)),
        grid=Grid(0, 0, 0, n, (), b"", (), 0), position=(None, None, None), position_static=(0, 0, 0),
        goal_positions=None, report=report, source=source, search_actions=tuple(range(len(actions))),
        lazy={"ground_task": lambda: task, "layer_expanders": lambda: (ns["expand"],),
              "cost_expander": ns["cost_expander"], "pddl_files": lambda: files})
