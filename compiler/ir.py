"""The grounded, typed intermediate form: what `ground.py` produces and `emit.py` compiles.

Names are resolved, functions inlined, quantifiers over finite classes expanded, static
attributes folded to constants. What remains reads the state: `Var` (a state variable),
`VarAt` (an attribute of a keyed object chosen at run time), `Cell` (a grid cell).
Nodes are frozen and hashable, so equal expressions can be recognised (abstract.py).
"""
from __future__ import annotations

from dataclasses import dataclass, fields, replace

# A state variable is an attribute of an object; the owner is an object name, or
# (class, key) for an object of a keyed class such as inventoryBlock[3].
Owner = str | tuple


@dataclass(frozen=True)
class StateVar:
    owner: Owner
    cls: str
    attr: str
    type: str

    @property
    def label(self) -> str:
        if isinstance(self.owner, tuple):
            cls, key = self.owner
            return f"{cls}[{', '.join(map(str, key))}].{self.attr}"
        return f"{self.owner}.{self.attr}"


@dataclass(frozen=True)
class Const:
    value: int | bool
    type: str


@dataclass(frozen=True)
class Local:
    name: str
    type: str


@dataclass(frozen=True)
class Var:
    var: StateVar

    @property
    def type(self) -> str:
        return self.var.type


@dataclass(frozen=True)
class VarAt:
    cls: str
    key: object
    attr: str
    type: str


@dataclass(frozen=True)
class Cell:
    x: object
    y: object
    z: object
    type: str


@dataclass(frozen=True)
class Lookup:
    """A constant table indexed by a value: `dx[d]`, or a property `t.solid` of an enum."""
    table: tuple
    index: object
    type: str
    label: str


@dataclass(frozen=True)
class Arith:
    op: str
    left: object
    right: object
    type: str = "int"
    label: str = ""     # `//` and `%` by a value: where the text is, for a division by zero at run time


@dataclass(frozen=True)
class Neg:
    operand: object
    type: str = "int"


@dataclass(frozen=True)
class Cmp:
    ops: tuple
    operands: tuple
    type: str = "bool"


@dataclass(frozen=True)
class BoolOp:
    op: str  # "and" | "or"
    items: tuple
    type: str = "bool"


@dataclass(frozen=True)
class Not:
    operand: object
    type: str = "bool"


@dataclass(frozen=True)
class CellLoop:
    """exists/forall over every cell of the grid (a quantifier whose cell was not pinned)."""
    kind: str
    names: tuple  # local names bound to x, y, z
    body: object
    type: str = "bool"


# ---- effects -----------------------------------------------------------------------
@dataclass(frozen=True)
class SetVar:
    var: StateVar
    value: object


@dataclass(frozen=True)
class SetVarAt:
    cls: str
    key: object
    attr: str
    value: object


@dataclass(frozen=True)
class SetCell:
    x: object
    y: object
    z: object
    value: object


@dataclass(frozen=True)
class When:
    cond: object
    then: tuple
    orelse: tuple


@dataclass
class GroundAction:
    """One action of the ground task, its parameters bound (compiler/ground.py builds it)."""
    name: str
    cost: int
    lets: list          # [(Local, IR)] in order
    pre: list           # [IR] conjuncts (constant-true ones dropped)
    pre_text: list      # source text of each conjunct, for explanations
    effects: tuple      # IR effects


TRUE = Const(True, "bool")
FALSE = Const(False, "bool")


def children(node) -> tuple:
    """Sub-expressions of an IR expression (for walks)."""
    if isinstance(node, VarAt):
        return (node.key,)
    if isinstance(node, Cell):
        return (node.x, node.y, node.z)
    if isinstance(node, Lookup):
        return (node.index,)
    if isinstance(node, Arith):
        return (node.left, node.right)
    if isinstance(node, (Neg, Not)):
        return (node.operand,)
    if isinstance(node, (Cmp,)):
        return node.operands
    if isinstance(node, BoolOp):
        return node.items
    if isinstance(node, CellLoop):
        return (node.body,)
    return ()


def leaf_effects(effects, conditional: bool = False):
    """Every effect that is not a `When`, those inside conditional ones too, in order:
    (effect, whether it is conditional)."""
    for e in effects:
        if isinstance(e, When):
            yield from leaf_effects(e.then, True)
            yield from leaf_effects(e.orelse, True)
        else:
            yield e, conditional


def set_vars(effects) -> list:
    """The `SetVar` effects among `leaf_effects`: (SetVar, whether it is unconditional)."""
    return [(e, not conditional) for e, conditional in leaf_effects(effects) if isinstance(e, SetVar)]


def conjuncts(conditions, de_morgan: bool = False) -> list:
    """The conjuncts of a condition (a list or tuple of conditions is their conjunction),
    `and` flattened. With `de_morgan`, `True` is dropped, `not (a or b)` is read as `not a`,
    `not b` and `not not a` as `a`: the relaxed view splits a condition as far as it goes."""
    out: list = []
    for c in conditions if isinstance(conditions, (list, tuple)) else (conditions,):
        if isinstance(c, BoolOp) and c.op == "and":
            out.extend(conjuncts(c.items, de_morgan))
        elif not de_morgan:
            out.append(c)
        elif isinstance(c, Const) and c.value is True:
            continue
        elif isinstance(c, Not) and isinstance(c.operand, BoolOp) and c.operand.op == "or":
            out.extend(conjuncts(tuple(negate(item) for item in c.operand.items), True))
        elif isinstance(c, Not) and isinstance(c.operand, Not):
            out.extend(conjuncts(c.operand.operand, True))
        else:
            out.append(c)
    return out


def negate(node):
    """`not node`, a double negation or a constant folded."""
    if isinstance(node, Not):
        return node.operand
    if isinstance(node, Const):
        return Const(not node.value, "bool")
    return Not(node)


def locals_of(node) -> set:
    """Names of the Local variables an expression reads."""
    out = {node.name} if isinstance(node, Local) else set()
    for child in children(node):
        out |= locals_of(child)
    return out


def substitute(node, mapping: dict):
    """Replace Locals named in `mapping` (name -> expression) throughout an expression."""
    if isinstance(node, Local):
        return mapping.get(node.name, node)
    if not children(node):
        return node
    changes = {}
    for f in fields(node):
        value = getattr(node, f.name)
        if isinstance(value, tuple):
            changes[f.name] = tuple(substitute(v, mapping) if _is_expr(v) else v for v in value)
        elif _is_expr(value):
            changes[f.name] = substitute(value, mapping)
    return replace(node, **changes)


def _is_expr(value) -> bool:
    return isinstance(value, (Const, Local, Var, VarAt, Cell, Lookup, Arith, Neg, Cmp, BoolOp, Not, CellLoop))
