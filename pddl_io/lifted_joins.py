"""Joins over a lifted state, as generated Python: an action schema's bindings, a formula's truth.

Why generated code: a join run by an interpreter of formulas (a generator per conjunct)
cost about 50 ms a state on a world of 200 blocks and 113 action schemas; nested loops
written once per schema cost a tenth of that. The order of a conjunction's parts is
chosen once (`order`), cheapest first: a test whose variables are all bound, then the
positive atom whose bound arguments select the fewest atoms of the initial state
(LiftedTask.stats: mean atoms per predicate, position and object), then `=`, then a
type's objects for a variable nothing else binds (with the symmetry rule of
lifted_states.py). `not`, `or`, `exists` and `forall` run as tests once their free
variables are bound; an `exists` is a function of its own, its answer kept for the
state (the question "is some block on this cell" comes from many schemas).

Only numbers and repr() of names reach the generated source; the objects' names are
the problem's, lowercased by the reader.
"""
from __future__ import annotations

from .lifted_types import conjuncts
from .lifted_states import LiftedTask, free_vars


def _is_var(t: str) -> bool:
    return t[:1] == "?"


class JoinCompiler:
    """Writes the functions; `compile()` runs the source once and returns its namespace."""

    def __init__(self, task: LiftedTask):
        self.task = task
        self.lines: list = []
        self.n_exists = 0
        self.n_tables = 0
        self.tables: dict = {}        # name -> object put in the namespace
        self.memo: dict = {}          # answers for the current state (the caller clears it)

    # ---- ordering ------------------------------------------------------------------
    def _cost(self, f, bound: set) -> float | None:
        unbound = free_vars(f) - bound
        if not unbound:
            return 0.0
        if f[0] == "atom":
            st = self.task.stats
            best = float(st.get(f[1], 0))
            for k, t in enumerate(f[2]):
                if not _is_var(t) or t in bound:
                    best = min(best, st.get((f[1], k), 0))
            return 1.0 + best
        if f[0] == "=" and len(unbound) == 1:
            return 1.0
        return None

    def order(self, parts: list, bound: set, types: dict, must: tuple = ()) -> list:
        """Steps ("part", f) or ("enum", var), in join order; `must` are bound at the end."""
        parts, bound, steps = list(parts), set(bound), []
        while parts:
            best, best_cost = None, None
            for k, f in enumerate(parts):
                c = self._cost(f, bound)
                if c is not None and (best_cost is None or c < best_cost):
                    best, best_cost = k, c
            if best is None:      # a test waits for a variable nothing binds: a type's objects
                need = sorted({v for f in parts for v in free_vars(f) - bound},
                              key=lambda v: (len(self.task.domain(types[v])), v))
                steps.append(("enum", need[0]))
                bound.add(need[0])
                continue
            f = parts.pop(best)
            steps.append(("part", f))
            bound |= free_vars(f)
        steps += [("enum", v) for v in must if v not in bound]
        return steps

    # ---- code ----------------------------------------------------------------------
    def table(self, value) -> str:
        name = f"T{self.n_tables}"
        self.n_tables += 1
        self.tables[name] = value
        return name

    def term(self, t: str, names: dict) -> str:
        return names[t] if _is_var(t) else repr(t)

    def args_tuple(self, args, names: dict) -> str:
        inner = ", ".join(self.term(t, names) for t in args)
        return f"({inner},)" if len(args) == 1 else f"({inner})"

    def expr(self, f, names: dict, types: dict) -> str:
        """A Python expression for formula f, its free variables bound to locals `names`."""
        kind = f[0]
        if kind == "atom":
            atom = f"({f[1]!r}, {self.args_tuple(f[2], names)})"
            if f[1] not in self.task.fluent:
                return f"({atom} in STATIC)"
            return f"(((i := IDS({atom}, -1)) >= 0) and ((i < N) != (i in s)))"
        if kind == "=":
            return f"({self.term(f[1], names)} == {self.term(f[2], names)})"
        if kind == "not":
            return f"(not {self.expr(f[1], names, types)})"
        if kind in ("and", "or"):
            if not f[1]:
                return "True" if kind == "and" else "False"
            return "(" + f" {kind} ".join(self.expr(g, names, types) for g in f[1]) + ")"
        if kind in ("exists", "forall"):
            outer = sorted(free_vars(f))
            inner_types = dict(types)
            inner_types.update(f[1])
            body = f[2] if kind == "exists" else ("not", f[2])
            fn = self.exists_function(body, outer, inner_types)
            call = f"{fn}(s{''.join(', ' + names[v] for v in outer)})"
            return call if kind == "exists" else f"(not {call})"
        return "True" if kind == "true" else "False"

    def exists_function(self, body, outer: list, types: dict) -> str:
        """def E<k>(s, <outer>): is there a binding of body's other variables? (memoized per state)"""
        k = self.n_exists
        self.n_exists += 1
        name = f"E{k}"
        names = {v: f"o{j}" for j, v in enumerate(outer)}
        key = f"({k}{''.join(', ' + names[v] for v in outer)})"
        lines = [f"def {name}(s{''.join(', ' + names[v] for v in outer)}):",
                 f"    got = MEMO.get({key})",
                 "    if got is not None:",
                 "        return got"]
        steps = self.order(conjuncts(body), set(outer), types)
        self.join(steps, dict(names), types, lines, "    ", [f"MEMO[{key}] = True", "return True"])
        lines += [f"    MEMO[{key}] = False", "    return False"]
        self.lines += lines
        return name

    def schema_function(self, name: str, pre, params: tuple, types: dict) -> None:
        """def <name>(s, out): out.append(parameter tuple) for each binding where pre holds."""
        lines = [f"def {name}(s, out):"]
        steps = self.order(conjuncts(pre), set(), types, params)
        names: dict = {}
        result = "(" + "".join(f"{{{v}}}, " for v in params) + ")"
        self.join(steps, names, types, lines, "    ", [f"out.append({result})"], params)
        lines.append("    return out")
        self.lines += lines

    def join(self, steps, names: dict, types: dict, lines: list, indent: str, success: list, params=()):
        """Nested loops and tests for `steps`; `success` lines run at the innermost level
        (`{var}` in them is replaced by the variable's local). Inside a loop a failed test
        is `continue`; before the first loop, consecutive tests make one `if` (a goal of a
        hundred conjuncts would otherwise nest past Python's limit of 100 blocks)."""
        depth = indent
        loops = 0
        pending: list = []

        def flush():
            nonlocal depth
            if pending:
                lines.append(f"{depth}if {' and '.join(pending)}:")
                depth += "    "
                pending.clear()

        for step in steps:
            if step[0] == "enum":
                flush()
                v = step[1]
                names[v] = local = f"v{len(names)}_{len(lines)}"
                dom = self.table(self.task.domain(types[v]))
                used = [names[u] for u in names if u != v]
                lines.append(f"{depth}for {local} in {dom}:")
                depth += "    "
                loops += 1
                if not self.symmetric(types[v]):
                    continue
                lines.append(f"{depth}if not ALLOWED({local}, s, ({''.join(u + ', ' for u in used)})):")
                lines.append(f"{depth}    continue")
                continue
            f = step[1]
            unbound = sorted(free_vars(f) - set(names))
            if not unbound:
                test = f"({self.expr(f, names, types)})"
                if loops:
                    lines.append(f"{depth}if not {test}:")
                    lines.append(f"{depth}    continue")
                else:
                    pending.append(test)
                continue
            flush()
            if f[0] == "=":
                v = unbound[0]
                other = f[2] if f[1] == v else f[1]
                names[v] = local = f"v{len(names)}_{len(lines)}"
                fits = self.table(self.task._fit_set(types[v]))
                lines.append(f"{depth}{local} = {self.term(other, names)}")
                lines.append(f"{depth}if {local} in {fits}:")
                depth += "    "
                continue
            depth = self.atom_loop(f, names, types, lines, depth)
            loops += 1
        flush()
        for line in success:
            for v in params:
                line = line.replace("{" + v + "}", names[v])
            lines.append(depth + line)

    def atom_loop(self, f, names: dict, types: dict, lines: list, depth: str) -> str:
        task = self.task
        pred, args = f[1], f[2]
        st = task.stats
        keypos, best = None, float(st.get(pred, 0)) + 1
        for k, t in enumerate(args):
            if (not _is_var(t) or t in names) and st.get((pred, k), 0) < best:
                keypos, best = k, st.get((pred, k), 0)
        fresh = [t for t in dict.fromkeys(args) if _is_var(t) and t not in names]
        tkey = tuple(sorted((k, types[t]) for k, t in enumerate(args) if t in fresh))
        tk = self.table(tkey)
        value = "None" if keypos is None else self.term(args[keypos], names)
        fluent = pred in task.fluent
        c = f"c{len(lines)}"
        key = f"({pred!r}, {keypos!r}, {value}, {tk})"
        if fluent:      # the atoms that hold in s, found once per state (MEMO)
            lines.append(f"{depth}{c} = MEMO.get({key})")
            lines.append(f"{depth}if {c} is None:")
            lines.append(f"{depth}    {c} = HOLDING(s, {key})")
        else:
            lines.append(f"{depth}{c} = TG({key})")
            lines.append(f"{depth}if {c} is None:")
            lines.append(f"{depth}    {c} = CANDS(*{key})")
        c, cl = f"d{len(lines)}", c
        lines.append(f"{depth}for {c} in {cl}:")
        depth += "    "
        a = c
        tests = []
        bound_here: dict = {}
        for k, t in enumerate(args):
            if k == keypos:
                continue
            if not _is_var(t):
                tests.append(f"{a}[{k}] == {t!r}")
            elif t in names:
                tests.append(f"{a}[{k}] == {names[t]}")
            elif t in bound_here:
                tests.append(f"{a}[{k}] == {a}[{bound_here[t]}]")
            else:
                bound_here[t] = k
        if tests:
            lines.append(f"{depth}if not ({' and '.join(tests)}):")
            lines.append(f"{depth}    continue")
        for t, k in bound_here.items():
            names[t] = local = f"v{len(names)}_{len(lines)}"
            lines.append(f"{depth}{local} = {a}[{k}]")
        if not fluent and bound_here:     # a static atom leaves its objects free: the symmetry rule
            for t in bound_here:
                if not self.symmetric(types[t]):
                    continue
                used = [names[u] for u in names if u != t]
                lines.append(f"{depth}if not ALLOWED({names[t]}, s, ({''.join(u + ', ' for u in used)})):")
                lines.append(f"{depth}    continue")
        return depth

    def test_function(self, f, types: dict) -> tuple[str, list]:
        """def F<k>(s, <free variables>): does f hold? -> (name, the variables in order)."""
        free = sorted(free_vars(f))
        names = {v: f"o{j}" for j, v in enumerate(free)}
        name = f"F{self.n_exists}"
        self.n_exists += 1
        body = self.expr(f, names, types)
        self.lines += [f"def {name}(s{''.join(', ' + names[v] for v in free)}):", f"    return bool({body})"]
        return name, free

    def symmetric(self, types: frozenset) -> bool:
        """Does a type hold objects of a symmetry class (so a join must apply the rule)?"""
        cls = self.task.symmetry.cls
        return any(o in cls for o in self.task.domain(types))

    def holding(self, s, key: tuple) -> list:
        """The args of the atoms of typed_candidates(*key) that hold in s (kept in MEMO)."""
        n = self.task.n_init
        cands = self.task.typed.get(key)
        if cands is None:
            cands = self.task.typed_candidates(*key)
        got = self.memo[key] = [args for i, args in cands if (i < n) != (i in s)]
        return got

    def compile(self) -> dict:
        task = self.task
        ns = {"STATIC": task.static, "IDS": task.ids.get, "N": task.n_init, "MEMO": self.memo,
              "HOLDING": self.holding,
              "CANDS": task.typed_candidates, "TG": task.typed.get, "ALLOWED": task.symmetry.allowed, **self.tables}
        self.source = "\n".join(self.lines) + "\n"
        exec(compile(self.source, "<bcc lifted joins>", "exec"), ns)
        self.ns, self.compiled = ns, len(self.lines)
        return ns

    def compile_more(self) -> dict:
        """The functions written since the last compile, run into the same namespace (a
        heuristic that asks for tests only when it first needs them)."""
        new = "\n".join(self.lines[self.compiled:]) + "\n"
        self.ns.update(self.tables)
        exec(compile(new, "<bcc lifted joins>", "exec"), self.ns)
        self.source += new
        self.compiled = len(self.lines)
        return self.ns
