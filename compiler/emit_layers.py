"""The layer expanders of the generated successor code: a whole layer of states expanded
in one loop, for breadth-first and blind searches with equal costs.

Why a module of its own: the expanders are a second, optional product of the emitter
(compiled on first use, `Model.data("layer_expanders")`), with their own bookkeeping:
groups of states by the action that made them, so the next layer skips the actions that
undo it or commute with it (inverses.py). The emitter (emit.py) takes this mixin and
lends it its expression and action code.
"""
from __future__ import annotations

from . import ir
from .access import fixed_reads, var_reads, writes_any

MAX_GROUPS = 8        # layer expanders per model past the plain one, at most (`layer_functions`)
MAX_INLINED = 2000    # inlined action bodies over all layer expanders, at most


class LayerExpanders:
    """`layer_source` and `layer_functions` of `emit.Emitter`."""

    def layer_source(self, name: str, actions: list, search: list[int], goal, failure,
                     group_of: dict, skip=frozenset()) -> str:
        """`name(states, seen, outs)`: `fresh` over a run of states in one loop, for a
        layered search (breadth-first, blind with equal costs). A next state not yet in
        `seen` is stored there (its parent as value) and appended to `outs[g]`, g the
        group of the action that made it (`group_of`, else 0), so the next layer knows
        which actions undid it (`skip`: this function's states were all made by an action
        those undo; their next states are certain duplicates, never built). It returns
        how many next states there were; when one is a goal, at once, the count's
        complement (negative), that goal being the last of its group's list. The goal
        is tested only after actions that may change it (every state handed in is not a
        goal), inline where it reads only variables and fixed cells."""
        self.uses_cells = False
        failure_false = isinstance(failure, ir.Const) and not failure.value
        goal_reads, goal_complex = fixed_reads(goal, self.L)
        goal_test = self._test_on_t(goal, "goal")
        groups = sorted({group_of.get(i, 0) for i in search if i not in skip} | {0})
        body = []
        if not failure_false:
            body += [f"        if {self.ex(failure)}:",
                     "            _r = _layer_slow(s, seen, outs)",
                     "            if _r < 0: return ~(_k + ~_r)",
                     "            _k += _r",
                     "            continue"]
        counted = [0]   # next states every expansion makes: counted once per state

        def keep(i: int, state: str, indent: str) -> list[str]:
            out = [] if state == "t" else [f"{indent}t = {state}"]
            if indent == "        ":
                counted[0] += 1
            else:
                out.append(f"{indent}_k += 1")
            out += [f"{indent}if t not in seen:",
                    f"{indent}    seen[t] = s",
                    f"{indent}    _a{group_of.get(i, 0)}(t)"]
            if goal_complex or writes_any(actions[i].effects, goal_reads):
                out.append(f"{indent}    if {goal_test}: return ~_k")
            return out

        body += self._search_body(actions, search, failure, "        ", keep, skip)
        if counted[0]:
            body.insert(5 if not failure_false else 0, f"        _k += {counted[0]}")
        nv = self.L.grid_base
        prologue = []
        if self.uses_cells:
            prologue.append(f"        c = _S0 if len(s) == {nv} else _CC.get(s[{nv}:]) or _expand(s[{nv}:])")
        if self.uses_int:
            prologue.append("        _I = _from_bytes(s, 'little'); _L = len(s)")
        self.uses_cells = self.uses_int = False
        head = [f"def {name}(states, seen, outs):"]
        head += [f"    _a{g} = outs[{g}].append" for g in groups]
        head += ["    _k = 0", "    for s in states:"]
        loop = prologue + body or ["        pass"]   # no actions: nothing to expand
        return "\n".join(head + loop + ["    return _k"])

    def layer_functions(self, actions: list, goal, failure, search: list[int], ns: dict) -> tuple:
        """The layer expanders (`layer_source`), compiled into `ns`: group 0 for the start
        and states made by actions after which nothing is skipped, then one per action
        after which some are (inverses.py: its inverses, and the earlier actions it
        commutes with), at most MAX_GROUPS. Their source is kept in `ns["_layers_source"]`,
        the inverses and the skips by action index in `ns["_undo"]` and `ns["_skips"]`."""
        from .inverses import find_inverses, find_skips
        apply_fns = [ns[f"apply_{i}"] for i in range(len(actions))]
        reads, complex_failure = var_reads(failure)
        failure_reads = None if complex_failure else {self.L.by_var[v].index for v in reads}
        undo = find_inverses(actions, search, self.L, apply_fns)
        reads, complex_goal = fixed_reads(goal, self.L)
        goal_reads = None if complex_goal else {self.L.by_var[v].index for v in reads}
        skips = find_skips(actions, search, self.L, apply_fns, failure_reads, undo, goal_reads)
        ns["_undo"] = {a: tuple(sorted(b)) for a, b in undo.items()}
        ns["_skips"] = {a: tuple(sorted(b)) for a, b in skips.items()}
        # each group is a copy of every action's code: a few, and not for thousands of actions
        most = min(MAX_GROUPS, max(0, MAX_INLINED // max(1, len(search)) - 1))
        makers = [i for i in search if i in skips][:most]
        group_of = {a: g for g, a in enumerate(makers, 1)}
        parts = [self.layer_source(f"layer_{g}", actions, search, goal, failure, group_of,
                                   skips[makers[g - 1]] if g else frozenset())
                 for g in range(len(makers) + 1)]
        source = "\n\n".join(parts)
        for name, value in self.ns.items():   # tables the new code made
            ns.setdefault(name, value)
        exec(compile(source, "<bcc model layers>", "exec"), ns)
        ns["_layers_source"] = source
        live_slow, is_goal, groups = ns["_live_slow"], ns["goal"], tuple(group_of.get(i, 0) for i in range(len(actions)))

        def layer_slow(s, seen, outs):
            """A state that already fails: `live`'s filter, then the same bookkeeping."""
            k = 0
            for a, n in live_slow(s):
                k += 1
                if n not in seen:
                    seen[n] = s
                    outs[groups[a]].append(n)
                    if is_goal(n):
                        return ~k
            return k

        ns["_layer_slow"] = layer_slow
        return tuple(ns[f"layer_{g}"] for g in range(len(makers) + 1))

