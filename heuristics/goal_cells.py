"""The goal as cell atoms, and what the compiled actions say about achieving each one.

A goal that is a conjunction is read as *cell atoms* (a constant cell must hold a
constant value, `cell[3, 1, 2].kind == v`) plus the rest (any other conjunct). For
each grounded action, the cells it writes and the cells its preconditions read are taken
from the IR where they are the agent's position plus a constant offset: an *achiever*
writes value v at offset w and *needs* (offset, op, value) conditions on other cells. From
these, relative to a goal cell p:

- *standing places*: the agent must be at p - w for some achiever w to write p;
- *readiness*: some achiever's needs on the other cells (p - w + o) hold now (achievers
  that also move the agent count only where no other achiever writes the value: they
  say how to get somewhere, not what rests on what);
- *orders*: q must wait for p when every achiever of p needs q's cell to be a value other
  than q's goal value (writing q first would make p unreachable);
- an *admissible lower bound*: each unsatisfied atom needs an action that writes it,
  an action writes at most `max_writes` cells, and none costs less than `min_write_cost`;
  the agent must also walk: to a standing place of each of a set of atoms whose standing
  places are pairwise disjoint along the axes no writer moves it (`_walk`: a minimum
  spanning tree over them), or, where not every write is an achiever but writing never
  moves the agent, to the nearest standing place.

Nothing here knows what the cells or values mean; it reads only IR shapes.
"""
from __future__ import annotations

import bisect
import math
import sys
from dataclasses import dataclass, field

from ..compiler import ir

_OPS = {"==": lambda a, b: a == b, "!=": lambda a, b: a != b}


@dataclass(frozen=True)
class Achiever:
    action: int
    write: tuple            # the written cell's offset from the agent
    value: int | None       # the written value (None: not a constant)
    needs: tuple            # clauses, each some of ((dx, dy, dz) relative to the written cell, op, value)
    moves: bool             # the action also moves the agent


@dataclass
class GoalCells:
    atoms: list                       # [((x, y, z), value)] in goal order
    rest: list                        # the goal's other conjuncts (IR)
    achievers: dict                   # value -> [Achiever]
    max_writes: int                   # cells one action writes, at most
    min_write_cost: int
    step: int | None                  # the most an action moves the agent (L1), None: unknown
    min_move_cost: int
    writers_stay: bool                # no action both writes cells and moves the agent
    need_offsets: set = field(default_factory=set)   # every relative need offset
    complete: bool = False            # every cell write of every action is an achiever
    kept_axes: tuple = ()             # position axes no writing action moves the agent along
    walk_step: int = 0                # the most a move that writes nothing changes those axes (L1)
    walk_cost: int = 1                # the least such a move costs

    def standing(self, atom) -> list:
        """The agent positions from which some achiever writes this atom's value."""
        (x, y, z), v = atom
        return [(x - a.write[0], y - a.write[1], z - a.write[2]) for a in self.achievers.get(v, ())]


def _linear(node, lets: dict, axes: dict):
    """`node` as (dx, dy, dz, const) over the agent's position, or None."""
    if isinstance(node, ir.Local) and node.name in lets:
        return _linear(lets[node.name], lets, axes)
    if isinstance(node, ir.Const) and isinstance(node.value, int) and not isinstance(node.value, bool):
        return (0, 0, 0, node.value)
    if isinstance(node, ir.Var) and node.var in axes:
        out = [0, 0, 0, 0]
        out[axes[node.var]] = 1
        return tuple(out)
    if isinstance(node, ir.Arith) and node.op in "+-":
        a, b = _linear(node.left, lets, axes), _linear(node.right, lets, axes)
        if a is None or b is None:
            return None
        sign = 1 if node.op == "+" else -1
        return tuple(p + sign * q for p, q in zip(a, b))
    return None


def _offset(cell, lets, axes):
    """A cell's offset from the agent: each coordinate the agent's own axis plus a constant."""
    parts = [_linear(c, lets, axes) for c in (cell.x, cell.y, cell.z)]
    if any(p is None for p in parts):
        return None
    for axis, p in enumerate(parts):
        if tuple(p[:3]) != tuple(int(i == axis) for i in range(3)):
            return None
    return tuple(p[3] for p in parts)


def _count_writes(effects) -> int:
    n = 0
    for e in effects:
        if isinstance(e, ir.SetCell):
            n += 1
        elif isinstance(e, ir.When):
            n += max(_count_writes(e.then), _count_writes(e.orelse))
    return n


def _moves(effects, axes) -> bool:
    """Whether the effects may write one of the agent's position `axes`."""
    return any(e.var in axes for e, _ in ir.set_vars(effects))


def _displacement(action, lets, axes) -> tuple | None:
    """The agent's move as a constant change per axis, when every moved axis is itself plus
    a constant; else None."""
    out = [0, 0, 0]
    for e in action.effects:
        if isinstance(e, ir.When) and _moves((e,), axes):
            return None
        if isinstance(e, ir.SetVar) and e.var in axes:
            lin = _linear(e.value, lets, axes)
            axis = axes[e.var]
            if lin is None or tuple(lin[:3]) != tuple(int(i == axis) for i in range(3)):
                return None
            out[axis] += lin[3]
    return tuple(out)


def goal_cells(model, allow_empty: bool = False) -> GoalCells | None:
    """The analysis for a compiled dungeon, or None when the model has no IR (an imported
    task) or its goal has no cell atom (unless `allow_empty`)."""
    c = model.data("compiled")
    if c is None:
        return None
    memo = model.memo.get("goal_cells")
    if memo is not None:
        return memo if memo.atoms or allow_empty else None
    items = c.goal.items if isinstance(c.goal, ir.BoolOp) and c.goal.op == "and" else (c.goal,)
    atoms, rest = [], []
    for g in items:
        cell = _const_cell_atom(g)
        (atoms if cell else rest).append(cell or g)
    if not atoms and not allow_empty:
        return None
    axes = {v: i for i, v in enumerate(c.position_vars)} if len(c.position_vars) == 3 else {}
    achievers, max_writes, write_costs, move_costs, steps, stay = {}, 0, [], [], [], True
    complete = True
    writer_axes, walks = set(), []          # axes some writer moves the agent along; (cost, shift) of other moves
    for index in c.search:
        act = c.actions[index]
        lets = {loc.name: expr for loc, expr in act.lets}
        writes = _count_writes(act.effects)
        moves = _moves(act.effects, axes)
        if moves:
            move_costs.append(act.cost)
            shift = _displacement(act, lets, axes)
            steps.append(None if shift is None else sum(map(abs, shift)))
            if writes:
                writer_axes |= {0, 1, 2} if shift is None else {i for i in range(3) if shift[i]}
            else:
                walks.append((act.cost, shift))
        if not writes:
            continue
        max_writes = max(max_writes, writes)
        write_costs.append(act.cost)
        stay = stay and not moves
        complete = complete and not any(isinstance(e, ir.When) and _count_writes((e,)) for e in act.effects)
        needs = []          # clauses: some literal (offset, op, value) of each holds
        for p in ir.conjuncts(act.pre):
            alternatives = p.items if isinstance(p, ir.BoolOp) and p.op == "or" else (p,)
            clause = [_literal(q, lets, axes) for q in alternatives]
            if clause and None not in clause:
                needs.append(tuple(clause))
        for e in act.effects:
            if isinstance(e, ir.SetCell):
                w = _offset(e, lets, axes)
                if w is None:
                    stay = complete = False   # a write the standing places cannot describe: no walking bound
                    continue
                value = int(e.value.value) if isinstance(e.value, ir.Const) else None
                rel = tuple(tuple(((o[0] - w[0], o[1] - w[1], o[2] - w[2]), op, v) for o, op, v in clause)
                            for clause in needs)
                achievers.setdefault(value, []).append(Achiever(index, w, value, rel, moves))
    if None in achievers:   # a write of a run-time value may write anything
        for v, lst in achievers.items():
            if v is not None:
                lst.extend(achievers[None])
    step = None if not steps or None in steps else max(steps)
    out = GoalCells(atoms, rest, achievers, max(max_writes, 1), min(write_costs, default=1), step,
                    min(move_costs, default=1), stay and bool(axes))
    out.need_offsets = {n[0] for lst in achievers.values() for a in lst for c in a.needs for n in c}
    out.complete = complete
    if axes and walks and all(shift is not None for _, shift in walks):
        out.kept_axes = tuple(i for i in range(3) if i not in writer_axes)
        out.walk_step = max(sum(abs(shift[i]) for i in out.kept_axes) for _, shift in walks)
        out.walk_cost = min(cost for cost, _ in walks)
    model.memo["goal_cells"] = out
    return out


def _literal(node, lets, axes):
    """A precondition `cell == value` / `cell != value` at an offset from the agent, or None."""
    if isinstance(node, ir.Cmp) and len(node.ops) == 1 and node.ops[0] in _OPS:
        a, b = node.operands
        if isinstance(a, ir.Cell) and isinstance(b, ir.Const):
            off = _offset(a, lets, axes)
            if off is not None:
                return off, node.ops[0], int(b.value)
    return None


def _const_cell_atom(node):
    if isinstance(node, ir.Cmp) and node.ops == ("==",):
        a, b = node.operands
        if isinstance(b, ir.Cell):
            a, b = b, a
        if isinstance(a, ir.Cell) and isinstance(b, ir.Const) and all(
                isinstance(k, ir.Const) for k in (a.x, a.y, a.z)):
            return (int(a.x.value), int(a.y.value), int(a.z.value)), int(b.value)
    return None


class CellReader:
    """Reads cells of a state in O(log n) (the changed cells are sorted by index)."""

    def __init__(self, model):
        g = model.grid
        self.grid, self.base = g, g.base
        self.little = sys.byteorder == "little"

    def __call__(self, state: bytes, x: int, y: int, z: int) -> int:
        g = self.grid
        if not (0 <= x < g.width and 0 <= z < g.depth and 0 <= y < g.height):
            return g.default
        start = g.static[(y * g.depth + z) * g.width + x]
        k = g.mutable_index(x, y, z)
        if k is None or len(state) == self.base:
            return start
        entries = memoryview(state)[self.base:].cast("I") if self.little else \
            __import__("bcc.model", fromlist=["cell_entries"]).cell_entries(state[self.base:])
        i = bisect.bisect_left(entries, k << 8)
        if i < len(entries) and entries[i] >> 8 == k:
            return entries[i] & 255
        return start


def ready(cells: GoalCells, read, state, atom) -> bool:
    """Some achiever of the atom's value has its needs on the other cells met in `state`."""
    (x, y, z), v = atom
    achs = cells.achievers.get(v, ())
    if any(not a.moves for a in achs):   # one that also moves the agent is a way up, not an order
        achs = [a for a in achs if not a.moves]
    for a in achs:
        if all(any(rel == (0, 0, 0) or _OPS[op](read(state, x + rel[0], y + rel[1], z + rel[2]), val)
                   for rel, op, val in clause) for clause in a.needs):
            return True
    return False


def orders(cells: GoalCells) -> dict:
    """{q: [p, ...]}: goal atom q waits for the atoms p, because every achiever of p needs
    q's cell to hold a value other than q's goal value."""
    where = {pos: v for pos, v in cells.atoms}
    out = {}
    for (p, vp) in cells.atoms:
        achs = cells.achievers.get(vp, ())
        if not achs:
            continue
        units = [[c[0] for c in a.needs if len(c) == 1] for a in achs]
        offsets = set.intersection(*({n[0] for n in u if n[0] != (0, 0, 0)} for u in units))
        for rel in offsets:
            q = (p[0] + rel[0], p[1] + rel[1], p[2] + rel[2])
            vq = where.get(q)
            if vq is None:
                continue
            if all(any(n[0] == rel and not _OPS[n[1]](vq, n[2]) for n in u) for u in units):
                out.setdefault(q, []).append(p)
    return out


def lower_bound(cells: GoalCells, model, state, read=None) -> int:
    """An admissible lower bound on the cost of reaching the goal from `state` (see the
    module docstring); it ignores the goal's other conjuncts."""
    read = read or CellReader(model)
    todo = [a for a in cells.atoms if read(state, *a[0]) != a[1]]
    if not todo:
        return 0
    bound = math.ceil(len(todo) / cells.max_writes) * cells.min_write_cost
    if not all(cells.achievers.get(a[1]) for a in todo):
        return bound
    here = model.agent_position(state)
    if cells.complete and cells.kept_axes and cells.walk_step:
        return bound + _walk(cells, todo, here) * cells.walk_cost
    if cells.writers_stay and cells.step:
        places = [p for a in todo for p in cells.standing(a)]
        if places:
            far = min(sum(abs(i - j) for i, j in zip(here, p)) for p in places)
            bound += math.ceil(far / cells.step) * cells.min_move_cost
    return bound


def _walk(cells: GoalCells, todo: list, here: tuple) -> int:
    """Moves that write nothing the agent must make, at least, to stand where the atoms of
    `todo` are written. Seen along the axes no writer moves the agent (`kept_axes`), atoms
    whose standing places are pairwise disjoint there (picked greedily, fewest places
    first: any such set gives a bound) are written from as many distinct places, which only
    such moves reach, each changing those axes by `walk_step` at most. The agent visits
    the groups in some order from where it is, and each leg takes at least the groups'
    nearest distance over `walk_step` moves: the legs span the groups, so they weigh at
    least a minimum spanning tree over the groups and the start (Prim's, with numpy)."""
    import numpy as np
    keep = cells.kept_axes
    standing = sorted((sorted({tuple(p[i] for i in keep) for p in cells.standing(a)}) for a in todo),
                      key=lambda r: (len(r), r))
    used, groups = set(), []
    for places in standing:
        if used.isdisjoint(places):
            used.update(places)
            groups.append(places)
    if not groups:
        return 0
    points = np.array([p for g in groups for p in g], dtype=np.int64)
    owner = np.repeat(np.arange(len(groups)), [len(g) for g in groups])
    nearest = np.abs(points - np.array([here[i] for i in keep])).sum(axis=1)     # distance to the tree
    joined = np.zeros(len(groups), dtype=bool)
    total = 0
    for _ in range(len(groups)):
        key = np.full(len(groups), np.iinfo(np.int64).max)
        np.minimum.at(key, owner, nearest)
        key[joined] = np.iinfo(np.int64).max
        g = int(key.argmin())
        total += -(-int(key[g]) // cells.walk_step)
        joined[g] = True
        for q in points[owner == g]:
            np.minimum(nearest, np.abs(points - q).sum(axis=1), out=nearest)
    return total


def support_levels(cells: GoalCells, read, state) -> dict:
    """{atom position: level}: level 0 is ready in `state`, level k becomes ready once the
    atoms of the levels below hold (readiness read over `state` with them written in).
    Atoms that never become ready are left out. This is the order the achievers' needs
    impose on the goal (what rests on what), found without knowing what anything is."""
    where = dict(cells.atoms)
    placed = {}

    def overlay(s, x, y, z):
        v = placed.get((x, y, z))
        return read(s, x, y, z) if v is None else v
    todo = {p for p, v in cells.atoms if read(state, *p) != v}
    level, frontier = {}, [p for p in todo if ready(cells, overlay, state, (p, where[p]))]
    k = 0
    offsets = {(-o[0], -o[1], -o[2]) for o in cells.need_offsets if o != (0, 0, 0)}
    while frontier:
        for p in frontier:
            level[p] = k
            todo.discard(p)
        for p in frontier:
            placed[p] = where[p]
        k += 1
        near = {(p[0] + o[0], p[1] + o[1], p[2] + o[2]) for p in frontier for o in offsets}
        frontier = [q for q in near & todo if ready(cells, overlay, state, (q, where[q]))]
    return level


def footing(model) -> tuple:
    """(solid, free): offsets from the agent's cell that must hold something wherever the
    agent arrives (what it stands on, e.g. {(0, -1, 0)}) and that must be free (its body,
    e.g. {(0, 0, 0), (0, 1, 0)}): the cell conditions every moving action that writes no
    cell puts on its destination. Empty sets when not known."""
    c = model.data("compiled")
    if c is None or len(c.position_vars) != 3:
        return set(), set()
    axes = {v: i for i, v in enumerate(c.position_vars)}
    default, common, body = model.grid.default, None, None
    for index in c.search:
        act = c.actions[index]
        if _count_writes(act.effects) or not _moves(act.effects, axes):
            continue
        lets = {loc.name: expr for loc, expr in act.lets}
        dest = [0, 0, 0]
        for e in act.effects:
            if isinstance(e, ir.SetVar) and e.var in axes:
                lin = _linear(e.value, lets, axes)
                if lin is None or tuple(lin[:3]) != tuple(int(i == axes[e.var]) for i in range(3)):
                    return set(), set()
                dest[axes[e.var]] = lin[3]
        solid, free = set(), set()
        for p in ir.conjuncts(act.pre):
            lit = _literal(p, lets, axes)
            if lit is not None and lit[2] == default:
                rel = (lit[0][0] - dest[0], lit[0][1] - dest[1], lit[0][2] - dest[2])
                (solid if lit[1] == "!=" else free).add(rel)
        common = solid if common is None else common & solid
        body = free if body is None else body & free
    return common or set(), body or set()
