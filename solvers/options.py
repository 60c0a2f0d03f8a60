"""Solver options: each solver declares what it takes beside its `solve`, and one function
checks a request against that declaration for every caller (`bcc solve`, `POST /solve`,
`bcc batch` sweeps and every other edge).

    @declare(Option("weight", float, 2.0, "f = g + W h", low=1))
    def solve(model, budget, progress=None, weight=2.0, **options): ...

An option is named as users spell it: `--known-after` on the command line, `known_after`
in JSON and sweep files; `keyword` is the `solve` argument when it differs. A solver that
declares nothing (a plugin written before declarations) takes no options.

An `internal` option is a keyword bcc itself (or a Python caller) passes, never a user:
it is declared so that the declaration lists every keyword a solver takes, but requests
cannot set it and `bcc solvers` does not list it. `optimal_cost` is one: the run path
(bcc/run) gives A*'s cost to every solver that declares it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

from ..errors import BccError


@dataclass(frozen=True)
class Option:
    """One option of a solver: its type, range or choices, default, and help."""
    name: str
    type: type                     # int, float, str or bool
    default: object
    help: str
    low: float | None = None       # the range, inclusive unless low_open / high_open
    high: float | None = None
    low_open: bool = False
    high_open: bool = False
    choices: tuple | Callable[[], tuple] | None = None   # a callable: choices known only at run time
    keyword: str | None = None     # the solve() keyword, when it is not `name`
    internal: bool = False         # passed by bcc or a Python caller, never by a user (see above)

    @property
    def argument(self) -> str:
        return self.keyword or self.name

    def allowed(self) -> tuple | None:
        return tuple(self.choices()) if callable(self.choices) else self.choices

    def what(self) -> str:
        """What a value must be, e.g. `a number > 0 and < 1`, `one of tabular, oo`."""
        choices = self.allowed()
        if choices is not None:
            return f"one of {', '.join(map(str, choices))}"
        kind = {int: "a whole number", float: "a number", str: "text", bool: "true or false"}[self.type]
        bounds = []
        if self.low is not None:
            bounds.append(f"{'>' if self.low_open else '>='} {self.low:g}")
        if self.high is not None:
            bounds.append(f"{'<' if self.high_open else '<='} {self.high:g}")
        return kind + (" " + " and ".join(bounds) if bounds else "")

    def check(self, value, spelled: str):
        """`value` (typed from JSON or YAML, or text from the command line) as this option's
        type, or BccError naming the option as the user spelled it."""
        parsed = self._parse(value)
        if parsed is None:
            raise BccError(f"{spelled} must be {self.what()}, got {value!r}{near(value, self.allowed() or ())}")
        return parsed

    def _parse(self, value):
        if self.type is bool:
            if isinstance(value, str):
                value = {"true": True, "yes": True, "on": True, "1": True,
                         "false": False, "no": False, "off": False, "0": False}.get(value.strip().lower(), value)
            return value if isinstance(value, bool) else None
        if isinstance(value, bool):
            return None
        if isinstance(value, str) and self.type is not str:
            try:
                value = self.type(value.strip())
            except ValueError:
                return None
        if self.type is float and isinstance(value, int):
            value = float(value)
        if not isinstance(value, self.type):
            return None
        if self.type is float and not math.isfinite(value):
            return None
        choices = self.allowed()
        if choices is not None and value not in choices:
            return None
        if self.low is not None and (value < self.low or self.low_open and value == self.low):
            return None
        if self.high is not None and (value > self.high or self.high_open and value == self.high):
            return None
        return value

    def to_json(self) -> dict:
        return {"name": self.name, "type": self.type.__name__, "default": self.default, "help": self.help,
                "accepts": self.what(),
                "choices": list(self.allowed()) if self.choices is not None else None,
                "low": self.low, "high": self.high, "low_open": self.low_open, "high_open": self.high_open}


def heuristic_option(default: str) -> Option:
    """The option of every informed solver: a name in heuristics.registry.HEURISTICS, or auto
    (the solver's own choice); the names are read when a request is checked."""
    def names():
        from ..heuristics.registry import HEURISTICS
        return ("auto", *HEURISTICS)
    return Option("heuristic", str, default, "the heuristic (auto: the solver's choice)", choices=names)


def near(name, names) -> str:
    """` (did you mean 'x'?)` for a near name among `names`, else ``."""
    import difflib
    close = difflib.get_close_matches(str(name), [str(n) for n in names], n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


def declare(*options: Option, optimal: bool = False, unavailable: Callable[[], str | None] | None = None):
    """Attach to a solve function the options it takes (read by `options_of`); `optimal`:
    with its default options its plans are optimal (tests/test_solver_contract.py holds it
    to BFS's cost); `unavailable()`, for a solver that needs something not installed: why
    it cannot run now and how to get it, or None when it can."""
    def mark(solve):
        solve.options = tuple(options)
        solve.optimal = optimal
        solve.unavailable = unavailable or (lambda: None)
        return solve
    return mark


def unavailable(solve) -> str | None:
    """Why `solve` cannot run here, or None."""
    check = getattr(solve, "unavailable", None)
    return check() if callable(check) else None


def options_of(solve) -> tuple[Option, ...]:
    """The options users may set (internal ones left out)."""
    return tuple(o for o in getattr(solve, "options", ()) if not o.internal)


def keywords_of(solve) -> tuple[str, ...]:
    """Every keyword `solve` declares it takes, internal ones included."""
    return tuple(o.argument for o in getattr(solve, "options", ()))


def check_options(solver: str, given: dict, spell: Callable[[str], str] = lambda name: f"`{name}`") -> dict:
    """The keyword arguments for `solver` from `given` (option name -> value; None means
    not given), each checked against the solver's declaration. BccError for an unknown
    solver (with a near name), an option the solver does not take, or a bad value;
    `spell(name)` names an option as the caller's users write it (`--known-after`)."""
    from . import get_solver
    declared = {o.name: o for o in options_of(get_solver(solver))}
    out = {}
    for name, value in given.items():
        if value is None:
            continue
        option = declared.get(name)
        if option is None:
            raise not_taken(solver, name, declared, spell)
        out[option.argument] = option.check(value, spell(name))
    return out


def check_arguments(solve, arguments: dict) -> None:
    """For a solver's own use, when called from Python without `check_options`: each
    declared option among its keyword `arguments` (`locals()` at the top of `solve`) is
    checked against the declaration; None stands for not given."""
    for option in getattr(solve, "options", ()):
        if arguments.get(option.argument) is not None:
            option.check(arguments[option.argument], f"{option.name} ({solve.__module__})")


def not_taken(solver: str, name: str, declared, spell=lambda name: f"`{name}`") -> BccError:
    takes = ", ".join(spell(n) for n in declared) or "none"
    return BccError(f"{spell(name)} does not apply to {solver}{near(name, declared)} (its options: {takes})")
