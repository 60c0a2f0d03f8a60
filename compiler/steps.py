"""How far one action can move the agent along each axis of its position.

Why: the distance heuristic (heuristics/position.py) divides a distance by the most an
action can change it. Counting every axis as one step is right when each action moves
along one axis; an action that moves along two at once (a step up onto a block changes x
and y) would make the plain L1 distance overestimate. So each grounded action's writes
to the position variables are read from the IR: `v = v + k` (through `let`s, in every
branch of a conditional effect) moves v by at most |k|; any other write (a teleport)
makes the steps unknown.
"""
from __future__ import annotations

from . import ir


def _offset(node, var, lets: dict):
    """|k| when `node` is `var + k` (k a constant, possibly 0), else None."""
    if isinstance(node, ir.Local) and node.name in lets:
        return _offset(lets[node.name], var, lets)
    if isinstance(node, ir.Var):
        return 0 if node.var == var else None
    if isinstance(node, ir.Arith) and node.op in ("+", "-"):
        if isinstance(node.right, ir.Const):
            d = _offset(node.left, var, lets)
            return None if d is None else d + abs(int(node.right.value))
        if isinstance(node.left, ir.Const) and node.op == "+":
            d = _offset(node.right, var, lets)
            return None if d is None else d + abs(int(node.left.value))
    return None


def _moves(effects, var, lets: dict):
    """The largest move of `var` over the effects (0 when unwritten); None if unbounded."""
    most = 0
    for e in effects:
        if isinstance(e, ir.When):
            parts = [_moves(e.then, var, lets), _moves(e.orelse, var, lets)]
        elif isinstance(e, ir.SetVar) and e.var == var:
            parts = [_offset(e.value, var, lets)]
        else:
            continue
        if None in parts:
            return None
        most = max(most, *parts)
    return most


def position_steps(actions, search, position_vars: list, position: tuple):
    """The distinct vectors (one entry per dynamic axis) of the most each searched action
    moves the agent, or None when some action moves it by an amount not known here."""
    dynamic = [var for var, p in zip(position_vars, position) if p is not None]
    out = set()
    for i in search:
        a = actions[i]
        lets = {loc.name: value for loc, value in a.lets}
        vector = tuple(_moves(a.effects, var, lets) for var in dynamic)
        if None in vector:
            return None
        out.add(vector)
    return tuple(sorted(out))
