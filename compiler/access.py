"""What a ground expression reads and what ground effects write: the one such analysis.

Why one place: relevance (which actions matter), the emitter (which actions may break
the failure test or a layer's goal), the relaxed view (which variables pick a cell) and
the abstractions (what an action's outcome depends on) all ask "which state variables
does this read or write". Each answer is a set of:

- a `StateVar` (an object's attribute; a `let` is followed to its value when `lets` is given),
- `CELLS` when a grid cell is read or written (the grid counts as one variable),
- a keyed attribute chosen at run time (`inventory[selected].count`): the variables
  `vars_of(cls, attr)` names when the caller can list them (analysis: every key), else
  the marker `("keyed", cls, attr)`.

The emitter's questions close the module: reads as (variables, reads anything else),
and the state indices an action writes, as a sum or as constant stores.
"""
from __future__ import annotations

from typing import Callable

from . import ir

CELLS = "cells"


def keyed(cls: str, attr: str) -> tuple:
    return ("keyed", cls, attr)


def reads(node, lets: dict | None = None, vars_of: Callable | None = None, acc: set | None = None,
          fixed_layer: Callable[[int], bool] | None = None) -> set:
    """What `node` reads. With `fixed_layer(y)`, a cell of a layer no action changes reads
    only its x and z (a goal "stand on a cell of this kind" reads the position only)."""
    acc = set() if acc is None else acc
    if isinstance(node, ir.Var):
        acc.add(node.var)
    elif isinstance(node, ir.VarAt):
        if vars_of is None:
            acc.add(keyed(node.cls, node.attr))
        else:
            acc.update(vars_of(node.cls, node.attr))
    elif isinstance(node, ir.Cell):
        if fixed_layer is not None and isinstance(node.y, ir.Const) and fixed_layer(node.y.value):
            reads(node.x, lets, vars_of, acc, fixed_layer)
            reads(node.z, lets, vars_of, acc, fixed_layer)
            return acc
        acc.add(CELLS)
    elif isinstance(node, ir.CellLoop):
        acc.add(CELLS)
    elif isinstance(node, ir.Local) and lets and node.name in lets:
        reads(lets[node.name], lets, vars_of, acc, fixed_layer)
    for child in ir.children(node):
        reads(child, lets, vars_of, acc, fixed_layer)
    return acc


def state_vars(found: set) -> set:
    """The plain variables among what `reads` or `writes` found."""
    return {v for v in found if isinstance(v, ir.StateVar)}


def effect_access(effects, lets: dict | None = None, vars_of: Callable | None = None,
                  r: set | None = None, w: set | None = None) -> tuple[set, set]:
    """(what the effects read: conditions, keys, values, cell places; what they write)."""
    r = set() if r is None else r
    w = set() if w is None else w
    for e in effects:
        if isinstance(e, ir.When):
            reads(e.cond, lets, vars_of, r)
            effect_access(e.then, lets, vars_of, r, w)
            effect_access(e.orelse, lets, vars_of, r, w)
        elif isinstance(e, ir.SetVar):
            w.add(e.var)
            reads(e.value, lets, vars_of, r)
        elif isinstance(e, ir.SetVarAt):
            if vars_of is None:
                w.add(keyed(e.cls, e.attr))
            else:
                w.update(vars_of(e.cls, e.attr))
            reads(e.key, lets, vars_of, r)
            reads(e.value, lets, vars_of, r)
        elif isinstance(e, ir.SetCell):
            w.add(CELLS)
            for part in (e.x, e.y, e.z, e.value):
                reads(part, lets, vars_of, r)
    return r, w


def writes(effects) -> set:
    """What the effects may write (keyed writes as markers)."""
    return effect_access(effects)[1]


def action_access(action, vars_of: Callable | None = None) -> tuple[set, set]:
    """(reads, writes) of a ground action: its preconditions, lets and effects."""
    lets = {loc.name: value for loc, value in action.lets}
    r: set = set()
    for c in action.pre:
        reads(c, lets, vars_of, r)
    return effect_access(action.effects, lets, vars_of, r)


def effect_locals(effects, acc: set | None = None) -> set:
    """Names of the `let` locals the effects read."""
    acc = set() if acc is None else acc
    for e in effects:
        if isinstance(e, ir.When):
            acc |= ir.locals_of(e.cond)
            effect_locals(e.then, acc)
            effect_locals(e.orelse, acc)
        else:
            for part in vars(e).values():
                if not isinstance(part, (ir.StateVar, str)):
                    acc |= ir.locals_of(part)
    return acc


def var_reads(node) -> tuple[set, bool]:
    """The variables an expression reads, and whether it reads anything else (a cell, a
    keyed attribute chosen at run time), which makes it depend on any write."""
    found = reads(node)
    plain = state_vars(found)
    return plain, len(plain) < len(found)


def fixed_reads(node, layout) -> tuple[set, bool]:
    """`var_reads`, where a cell of a layer no action changes (its x and z aside) reads
    nothing that can change: a goal "stand on a cell of this kind" reads the position only."""
    found = reads(node, fixed_layer=lambda y: layout.layer_index(y) is None)
    plain = state_vars(found)
    return plain, len(plain) < len(found)


def writes_any(effects, variables: set) -> bool:
    """May the effects change one of `variables` (a keyed write may change any)?"""
    return any(isinstance(w, tuple) or w in variables for w in writes(effects))


def delta_slots(effects, layout) -> set | None:
    """The state indices the effects may write, when each is written at most once on any
    path and all are fixed variables (no cell, no keyed write); else None. Such an action
    can build its next state as one integer sum (`_new_state`)."""
    out: set = set()
    for e in effects:
        if isinstance(e, ir.When):
            then, orelse = delta_slots(e.then, layout), delta_slots(e.orelse, layout)
            if then is None or orelse is None:
                return None
            these = then | orelse
        elif isinstance(e, ir.SetVar):
            these = {layout.by_var[e.var].index}
        else:
            return None
        if out & these:
            return None
        out |= these
    return out


def constant_stores(effects, layout) -> list:
    """[(state index, stored byte)] when every effect sets a variable to a constant
    unconditionally (the action changes nothing where all already hold), else []."""
    out = []
    for e in effects:
        if not (isinstance(e, ir.SetVar) and isinstance(e.value, ir.Const)):
            return []
        slot = layout.by_var[e.var]
        out.append((slot.index, int(e.value.value) - slot.lo))
    return out
