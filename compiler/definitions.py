"""A loaded domain as data: expressions with their place in the file, enumerations,
classes, functions, action schemas and the domain that holds them.

Apart from the loader (domain.py) because every later step -- grounding, the dungeon
loader, the hierarchy compiler, the on-disk cache -- reads these and none needs the loader.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from ..errors import BccError
from . import ast
from .source import YMap, Origin

BUILTIN_TYPES = ("int", "bool")


@dataclass(frozen=True)
class Expr:
    """A parsed expression (or effect list) and where its text lives."""
    node: object
    where: Origin
    text: str

    def error(self, message: str, node: ast.Node | None = None) -> BccError:
        line, col = (node or self.node).pos if hasattr(node or self.node, "pos") else (1, 1)
        return self.where.error(message, line, col)


@dataclass
class EnumType:
    name: str
    values: list[str]                     # dense index -> name
    ids: list[int]                        # dense index -> external id
    properties: dict[str, list]           # property -> value per dense index
    prop_types: dict = field(default_factory=dict)  # property -> "bool" | "int" | an enumeration name
    prop_defaults: dict = field(default_factory=dict)  # property -> its declared default
    # table properties (`per: E`): property -> E; each value's entry is then a dict from E's
    # value names to values (entries left out take the default), read as `v.prop[e]`
    prop_per: dict = field(default_factory=dict)

    def index(self, name: str) -> int:
        return self.values.index(name)


@dataclass
class AttrDef:
    name: str
    type: str
    range: tuple[Expr, Expr] | None = None
    names: dict[str, int] = field(default_factory=dict)
    default: object = None


@dataclass
class ClassDef:
    name: str
    attrs: dict[str, AttrDef]
    key: list[str] = field(default_factory=list)
    position: list[str] = field(default_factory=list)


@dataclass
class Param:
    name: str
    type: str


@dataclass
class FunctionDef:
    name: str
    params: list[Param]
    body: Expr


@dataclass
class ActionDef:
    name: str
    params: list[Param]
    lets: list[tuple[str, Expr]]
    pre: list[Expr]
    effects: Expr
    cost: int = 1


@dataclass
class Domain:
    name: str
    path: str
    description: str
    enums: dict[str, EnumType]
    constants: dict[str, tuple[int, ...]]
    classes: dict[str, ClassDef]
    functions: dict[str, FunctionDef]
    actions: dict[str, ActionDef]
    failure: Expr | None
    binding: YMap                         # the `dungeon:` section, read by dungeon.py
    source: YMap
    start: Expr | None = None             # `dungeon.start`, parsed here (a cached domain needs no parser)
    tasks: dict = field(default_factory=dict)     # compound tasks (tasks.py): name -> TaskDef
    methods: dict = field(default_factory=dict)   # their methods, in the file's order: name -> MethodDef



def table_row(enums: dict, enum: EnumType, p: str, index: int) -> tuple:
    """Entry `index` of the table property `p`, as a tuple over the values of its `per`
    enumeration in order (values a table leaves out, or added by a later domain, take the
    property's default)."""
    row, default = enum.properties[p][index], enum.prop_defaults[p]
    return tuple(row.get(name, default) for name in enums[enum.prop_per[p]].values)
