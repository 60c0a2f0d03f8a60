"""Symbolic execution of the compiler's generated functions: their exact decision trees.

Why: the PDDL export must be *exactly* the compiled model, for any domain. Rather than
re-implementing the expression semantics, we run the very functions the solvers run
(`apply_i`, `goal`, `failure`, see `bcc compile --emit-python`) on a state whose bytes are
symbolic. A read returns a `Sym` (a value per possible byte value); arithmetic and table
lookups map it; when the code branches on it, indexes with it or writes it, the run
*forks*: the byte's possible values are split by outcome and each part is explored by
re-running the function from the start with the earlier choices replayed. Every leaf is
a conjunction "byte i has one of these values" plus the function's result (a state with
concrete writes, None, or a bool) -- together the leaves partition the state space.
"""
from __future__ import annotations

import operator
import types
from dataclasses import dataclass

from ..errors import ModelError


class _Fork(Exception):
    """Raised when a run reaches a branch point it has no recorded choice for."""

    def __init__(self, options):
        self.options = options  # [(byte index, frozenset of values)]


class _Err:
    """An operation that failed for some byte values (e.g. an index out of a table)."""

    def __init__(self, exc):
        self.exc = exc


@dataclass
class Leaf:
    allowed: dict       # byte index -> tuple of values (only bytes the run narrowed)
    result: object      # None, a bool, or {byte index: value} (the writes of an action)


class _Run:
    def __init__(self, domains, choices):
        self.domains, self.choices, self.pos = domains, choices, 0
        self.allowed: dict = {}

    def values(self, i: int) -> tuple:
        return self.allowed.get(i, self.domains[i])

    def split(self, i: int, groups: list) -> frozenset:
        """Choose one of `groups` (disjoint value sets of byte i): replay or fork."""
        if len(groups) == 1:
            chosen = groups[0]
        elif self.pos < len(self.choices):
            j, chosen = self.choices[self.pos]
            assert j == i, "symbolic replay diverged"
            self.pos += 1
        else:
            raise _Fork([(i, g) for g in groups])
        self.allowed[i] = tuple(sorted(chosen))
        return chosen

    def read(self, i: int):
        vals = self.values(i)
        if len(vals) == 1:
            return vals[0]
        return Sym(self, i, {v: v for v in vals})

    def pin(self, i: int) -> int:
        vals = self.values(i)
        return next(iter(self.split(i, [frozenset([v]) for v in vals])))


def _apply(op, a, b):
    try:
        return op(a, b)
    except Exception as exc:  # noqa: BLE001 - kept per value, raised only if that value is chosen
        return _Err(exc)


class Sym:
    """The value of an expression over one state byte: a table byte value -> result."""
    __slots__ = ("run", "var", "table")

    def __init__(self, run, var, table):
        self.run, self.var, self.table = run, var, table

    def _live(self):
        vals = self.run.values(self.var)
        return {v: self.table[v] for v in vals}

    def resolve(self):
        """The concrete value, forking on the byte if the live values disagree."""
        table, groups = self.table, {}
        for v in self.run.values(self.var):
            r = table[v]
            key = ("err", id(r)) if r.__class__ is _Err else (r.__class__ is bool, r)
            group = groups.get(key)
            if group is None:
                groups[key] = (r, [v])
            else:
                group[1].append(v)
        if len(groups) == 1:
            r = next(iter(groups.values()))[0]
        else:
            chosen = self.run.split(self.var, [frozenset(vs) for _, vs in groups.values()])
            r = table[next(iter(chosen))]
        if isinstance(r, _Err):
            raise r.exc
        return r

    def _map(self, fn):
        table, out = self.table, {}
        for v in self.run.values(self.var):   # the live values (a hot loop of the export)
            r = table[v]
            out[v] = r if r.__class__ is _Err else fn(r)
        return self._folded(out)

    def _folded(self, out: dict):
        """`out` (live value -> result) as a Sym, or its one result when all agree."""
        results = iter(out.values())
        first = next(results)
        kind = first.__class__
        if kind is not _Err:
            for r in results:
                if r.__class__ is not kind or r != first:
                    break
            else:
                return first  # constant over the live values (same type, no error): fold it
        return Sym(self.run, self.var, out)

    def _bin(self, other, op, swap=False):
        if isinstance(other, Sym):
            if other.var == self.var:
                o = other._live()
                live = self._live()
                out = {v: (_apply(op, o[v], r) if swap else _apply(op, r, o[v])) for v, r in live.items()}
                return Sym(self.run, self.var, out)._map(lambda r: r)
            other = other.resolve()
        table, out = self.table, {}
        for v in self.run.values(self.var):   # _map(lambda r: _apply(op, r, other)), inlined: the hottest loop
            r = table[v]
            if r.__class__ is not _Err:
                try:
                    r = op(other, r) if swap else op(r, other)
                except Exception as exc:  # noqa: BLE001 - kept per value, raised only if that value is chosen
                    r = _Err(exc)
            out[v] = r
        return self._folded(out)

    def __add__(self, o): return self._bin(o, operator.add)
    def __radd__(self, o): return self._bin(o, operator.add, True)
    def __sub__(self, o): return self._bin(o, operator.sub)
    def __rsub__(self, o): return self._bin(o, operator.sub, True)
    def __mul__(self, o): return self._bin(o, operator.mul)
    def __rmul__(self, o): return self._bin(o, operator.mul, True)
    def __floordiv__(self, o): return self._bin(o, operator.floordiv)
    def __rfloordiv__(self, o): return self._bin(o, operator.floordiv, True)
    def __mod__(self, o): return self._bin(o, operator.mod)
    def __rmod__(self, o): return self._bin(o, operator.mod, True)
    def __eq__(self, o): return self._bin(o, operator.eq)
    def __ne__(self, o): return self._bin(o, operator.ne)
    def __lt__(self, o): return self._bin(o, operator.lt)
    def __le__(self, o): return self._bin(o, operator.le)
    def __gt__(self, o): return self._bin(o, operator.gt)
    def __ge__(self, o): return self._bin(o, operator.ge)
    def __neg__(self): return self._map(operator.neg)
    def __abs__(self): return self._map(abs)
    def __bool__(self): return bool(self.resolve())
    def __index__(self): return int(self.resolve())
    def __int__(self): return int(self.resolve())
    __hash__ = None


def _concrete(v):
    return v.resolve() if isinstance(v, Sym) else v


class _Table:
    """A constant table of the generated code; a symbolic index maps through it."""

    def __init__(self, values):
        self.values = values

    def __getitem__(self, i):
        if isinstance(i, Sym):
            return i._map(lambda r: self.values[r])
        return self.values[i]

    def __len__(self):
        return len(self.values)


class _State:
    """The old state `s`: reads are symbolic."""

    def __init__(self, run):
        self.run = run

    def __getitem__(self, i):
        return self.run.read(_concrete(i))


class _Next:
    """The new state `n` = bytearray(s): records writes, pins each written byte's old value."""

    def __init__(self, state):
        self.state, self.writes = state, {}

    def __getitem__(self, i):
        i = _concrete(i)
        return self.writes[i] if i in self.writes else self.state[i]

    def __setitem__(self, i, v):
        self.writes[_concrete(i)] = int(_concrete(v))


def _bytearray(s):
    return _Next(s)


def _bytes(n):
    return n


def symbolic_functions(model) -> dict:
    """Copies of the model's generated functions whose globals make them symbolic: the
    dense-layout variants (`Model.dense`: every mutable cell one byte), so a leaf's bytes
    are the variables and cells themselves."""
    dense = model.data("dense_functions")
    if dense is not None:
        apply_fns = [dense[f"apply_{i}"] for i in range(len(model.apply_fns))]
        g = dense
    else:
        apply_fns = list(model.apply_fns)
        g = apply_fns[0].__globals__ if apply_fns else {}
    ns = dict(g)
    for k, v in g.items():
        if isinstance(v, tuple) and k.startswith("T"):
            ns[k] = _Table(v)
    ns["bytearray"], ns["bytes"] = _bytearray, _bytes

    def rebind(fn):
        return types.FunctionType(fn.__code__, ns, fn.__name__, fn.__defaults__, fn.__closure__)
    out = {"apply": [rebind(f) for f in apply_fns]}
    for name in ("goal", "failure"):
        out[name] = rebind(g[name]) if name in g else None
    return out


def explore(fn, domains, pin_all: bool = True, max_leaves: int = 2_000_000):
    """All leaves of `fn(state)` over byte domains (tuple of value tuples per byte).

    With `pin_all`, every byte the run narrowed (and, for actions, every byte written)
    is split into single values, so each leaf is a conjunction of positive facts.
    Yields Leaf; runs that raise ModelError (a write out of range) are yielded with
    result `ModelError` so callers can count them.
    """
    stack = [[]]
    count = 0
    while stack:
        choices = stack.pop()
        run = _Run(domains, choices)
        try:
            result = fn(_State(run))
            if isinstance(result, _Next):
                for i in sorted(result.writes):
                    run.pin(i)
                result = dict(result.writes)
            elif isinstance(result, Sym):
                result = result.resolve()
            if pin_all:
                for i in sorted(run.allowed):
                    run.pin(i)
        except _Fork as fork:
            for option in reversed(fork.options):
                stack.append(choices + [option])
            continue
        except ModelError:
            result = ModelError
        count += 1
        if count > max_leaves:
            raise OverflowError(f"more than {max_leaves} leaves")
        yield Leaf(dict(run.allowed), result)
