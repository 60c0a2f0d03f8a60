"""The lifted PDDL task: its formulas, actions, domain and problem, as lifted.py reads them.

Formulas are tuples: ("atom", pred, args), ("=", a, b), ("not", f), ("and", fs),
("or", fs), ("exists", params, f), ("forall", params, f), ("true",), ("false",). A term
is a variable "?x" or an object name; `params` is a tuple of (variable, types). Every
reader of a lifted task (the grounder, the lifted search, the HTN planner) works on these.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from ..errors import BccError

TRUE, FALSE = ("true",), ("false",)


def conjuncts(f) -> list:
    """The conjuncts of a formula (lifted, or ground: an atom is its number), nested `and`s
    flattened, `true` dropped."""
    if isinstance(f, tuple) and f[0] == "and":
        return [g for sub in f[1] for g in conjuncts(sub)]
    return [] if f == TRUE else [f]


def is_a(t: str, want: str, parents: dict) -> bool:
    """Is type `t` (or one of its ancestors) `want`?"""
    if want == "object" or t == want:
        return True
    return any(is_a(p, want, parents) for p in parents.get(t, ()))


@dataclass(frozen=True)
class Effect:
    """`(forall params (when cond (not? (pred args))))`, flattened."""
    params: tuple
    cond: tuple
    add: bool
    pred: str
    args: tuple


@dataclass
class Action:
    name: str
    params: tuple            # ((variable, frozenset of types), ...)
    pre: tuple               # formula
    effects: list            # [Effect]
    cost: object             # None, an int, or (function, args) read from the problem's :init
    where: tuple             # (line, column) of the action


@dataclass
class Domain:
    name: str
    path: str
    parents: dict            # type -> its parent types (`either` gives several); "object" has none
    constants: dict          # name -> type
    predicates: dict         # name -> tuple of parameter types (frozensets)
    functions: dict          # name -> tuple of parameter types (only static cost functions)
    actions: list
    uses_costs: bool = False
    loose_names: dict = field(default_factory=dict)  # names actions use without declaring them: name -> token
    derived: dict = field(default_factory=dict)      # derived predicate -> [(params, formula), ...] (its rules)


@dataclass
class Problem:
    name: str
    path: str
    objects: dict            # name -> type (the domain's constants included)
    init: set                # ground atoms (pred, args)
    function_values: dict    # (function, args) -> int
    goal: tuple
    metric: bool             # (:metric minimize (total-cost))
    where: dict = field(default_factory=dict)
    init_order: list | None = None   # the :init atoms in file order, when asked for (HDDL's planner)


def err(node, message: str, path: str) -> BccError:
    return BccError(message, path, getattr(node, "line", None), getattr(node, "column", None))


def unsupported(node, what: str, path: str) -> BccError:
    return err(node, f"{what} is not supported", path)
