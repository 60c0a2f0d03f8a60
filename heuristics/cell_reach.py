"""Goal cell atoms that can never hold: a relaxed reachability over cells.

A cell can come to hold value v if it holds it now, or some achiever of v
(goal_cells.Achiever) has each of its need clauses satisfiable: some literal's cell can
come to hold a value the literal accepts. Everything else an action needs is ignored (the
agent's position, amounts, properties of what is in a cell), so "never" is sound: the
answer of a relaxation, as h^max is infinite only where no plan exists. Cells outside the
grid or in a layer no action changes keep their value.

It answers only when every cell write of every action is an achiever
(GoalCells.complete); the graph is built backwards from the goal's atoms, so a column
under a block costs its height, not the size of the world, and a graph over `limit`
questions gives no answer. Nothing here knows what the cells or values mean.
"""
from __future__ import annotations

from .goal_cells import _OPS, CellReader, GoalCells, goal_cells

LIMIT = 200_000   # questions (cell, op, value) the backward graph may hold


def _writers(cells: GoalCells, op: str, value: int) -> list:
    """The achievers that may make `cell op value` hold (a write of a run-time value may
    write anything: goal_cells lists those under every value, and under None)."""
    if op == "==":
        return cells.achievers.get(value) or cells.achievers.get(None, [])
    seen, out = set(), []
    for v, lst in cells.achievers.items():
        if v is None or v != value:
            for a in lst:
                if id(a) not in seen:
                    seen.add(id(a))
                    out.append(a)
    return out


def never_hold(cells: GoalCells, model, state, read, limit: int = LIMIT) -> list | None:
    """The goal atoms ((x, y, z), value) that no sequence of actions from `state` can make
    hold (module docstring), in goal order; None when the analysis cannot tell."""
    if not cells.complete:
        return None
    grid = model.grid
    graph, order = {}, []   # question -> alternatives (each: clauses, each: questions); discovery order
    stack = [(p, "==", v) for p, v in cells.atoms if read(state, *p) != v]
    while stack:
        q = stack.pop()
        if q in graph:
            continue
        (x, y, z), op, value = q
        alternatives = []
        if grid.mutable_index(x, y, z) is not None:
            for a in _writers(cells, op, value):
                clauses = []
                for clause in a.needs:
                    lits = []
                    for rel, o, v in clause:
                        c = (x + rel[0], y + rel[1], z + rel[2])
                        if _OPS[o](read(state, *c), v):
                            lits = None   # holds now
                            break
                        lits.append((c, o, v))
                    if lits is not None:
                        clauses.append(lits)
                        stack.extend(lits)
                alternatives.append(clauses)
        graph[q] = alternatives
        order.append(q)
        if len(graph) > limit:
            return None
    held = _fixpoint(graph, order)
    return [(p, v) for p, v in cells.atoms if read(state, *p) != v and (p, "==", v) not in held]


def _fixpoint(graph: dict, order: list) -> set:
    """The questions that can come to hold: the least fixpoint, swept deepest first."""
    held, changed = set(), True
    while changed:
        changed = False
        for q in reversed(order):
            if q not in held and any(all(any(lit in held for lit in clause) for clause in alt)
                                     for alt in graph[q]):
                held.add(q)
                changed = True
    return held


def never_message(model, never: list) -> str:
    """What `never_hold` found, for a user: the first atoms, by value name."""
    names = model.grid.value_names
    shown = ", ".join(f"{names[v] if 0 <= v < len(names) else v} at {p}" for p, v in never[:3])
    more = f" and {len(never) - 3} more" if len(never) > 3 else ""
    return (f"no plan exists: no sequence of actions can put {shown}{more} (even ignoring where the agent "
            "must stand and what it carries, what each write needs beneath or beside it never holds)")


def goal_never_holds(model) -> str | None:
    """What a user is told when some goal cell atom can never hold from the model's start
    (`never_message`), else None: also when the goal has no cell atom, the model is not a
    compiled dungeon, or the analysis cannot tell. Kept in the model's memo by start state
    (a model copied with another start shares the memo): the run path asks it, and so does
    the build solver for a library caller."""
    known = model.memo.setdefault("goal_never_holds", {})
    if model.initial not in known:
        cells = goal_cells(model)
        never = never_hold(cells, model, model.initial, CellReader(model)) if cells is not None else None
        known[model.initial] = never_message(model, never) if never else None
    return known[model.initial]
