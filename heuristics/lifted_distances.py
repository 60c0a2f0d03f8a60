"""Distances for the landmarks of a lifted task: how far a state is from making one true.

Why: a landmark count says "3 blocks still to place", not how far the agent is from the
next one. Two generic pieces give that distance, both read off the action schemas:

- **Domain transition graphs** (as Fast Downward's causal-graph heuristics use them).
  A binary fluent predicate P(o, v) is *functional* for an object o when every schema
  that adds P(t, v') for a t that may be o also deletes P(t, v) in the same step: o
  changes value, never gains a second one. The graph's edges v -> v' are the pairs the
  schema's static atoms on v and v' allow (`(succ ?v ?v2)`: one step along a line), so a
  distance is the fewest changes of P from o's current value to the wanted one (moves
  along an axis). Other preconditions are ignored: a lower bound.
- **Achievers.** A landmark's achievers (lifted_landmarks.py) bound to it; the variables
  their static atoms determine bound too (the cell in front of a target), and one whose
  type has few objects (an agent) taken over its objects. Each such instance costs the
  sum of its functional atoms' distances plus one per other ground conjunct that is false
  ("a block below the target"); the landmark costs one more than its cheapest instance.
- **Entering a value.** A graph's distance says nothing of what the last step onto the
  wanted value needs: a one-level step up needs something to stand on. So an instance's
  wanted values of one object (its x, y and z together) are regressed once through the
  schemas that add one of them: each such schema bound so that it ends there (a value
  the schema does not change is the one wanted), its static atoms binding the rest (the
  cell it comes from). What its precondition asks of other objects there, ground, is an
  *entry*; while the object is not there yet, the instance costs one more per false
  conjunct of its cheapest entry.

The search orders states by the sum over missing landmarks (lifted_search.py).
"""
from __future__ import annotations

import itertools
from collections import deque

from ..pddl_io.lifted_types import TRUE, conjuncts
from ..pddl_io.lifted_states import LiftedTask, free_vars, substitute

SMALL_TYPE = 4          # a variable left free is taken over its type's objects if it has this many or fewer
MAX_INSTANCES = 64      # achiever instances kept per landmark
FAR = 1000              # the distance to a value the graph cannot reach


class Distances:
    def __init__(self, task: LiftedTask):
        self.task = task
        self._functional: dict = {}
        self._graphs: dict = {}
        self._to: dict = {}
        self._entries: dict = {}
        self._steppers = None

    # ---- functional predicates and their graphs -----------------------------------------
    def functional(self, pred: str, obj: str) -> bool:
        """Is every change of P(obj, .) a move from one value to another? (see the module docstring)"""
        key = (pred, self.task.objects.get(obj))
        got = self._functional.get(key)
        if got is None:
            got = self._functional[key] = self._check(pred, obj)
        return got

    def _adders(self, pred: str, obj: str):
        task = self.task
        for a in task.dom.actions:
            types = dict(a.params)
            for e in a.effects:
                if e.add and e.pred == pred:
                    t = e.args[0]
                    if t.startswith("?") and not task.fits(obj, types.get(t, frozenset({"object"}))):
                        continue
                    if not t.startswith("?") and t != obj:
                        continue
                    yield a, e

    def _check(self, pred: str, obj: str) -> bool:
        if len(self.task.dom.predicates.get(pred, ())) != 2 or pred not in self.task.fluent:
            return False
        found = False
        for a, e in self._adders(pred, obj):
            found = True
            if e.params or e.cond != TRUE or not any(
                    not d.add and d.pred == pred and d.args[0] == e.args[0] and not d.params and d.cond == TRUE
                    for d in a.effects):
                return False
        return found

    def graph(self, pred: str, obj: str) -> dict:
        """value -> the values one step of an adder of P(obj, .) leads to."""
        key = (pred, self.task.objects.get(obj))
        got = self._graphs.get(key)
        if got is not None:
            return got
        task = self.task
        edges: dict = {}
        done = set()
        for a, e in self._adders(pred, obj):
            types = dict(a.params)
            d = next(d for d in a.effects if not d.add and d.pred == pred and d.args[0] == e.args[0])
            old, new = d.args[1], e.args[1]
            statics = [c for c in conjuncts(a.pre)
                       if c[0] == "atom" and c[1] not in task.fluent and free_vars(c) and free_vars(c) <= {old, new}]
            key = (old, new, types.get(old), types.get(new), tuple(statics))
            if key in done:           # many schemas move alike (every "move and pick up" kind)
                continue
            done.add(key)
            both = old.startswith("?") and new.startswith("?") and old != new
            link = next((c for c in statics if both and len(c[2]) == 2 and set(c[2]) == {old, new}), None)
            if link is not None:
                # a static pair such as (succ ?v ?w): its facts are the candidate edges
                fit_old, fit_new = task._fit_set(types[old]), task._fit_set(types[new])
                for fact in task.static_all.get(link[1], ()):
                    env = dict(zip(link[2], fact))
                    if env[old] in fit_old and env[new] in fit_new and \
                            all((c[1], tuple(env.get(x, x) for x in c[2])) in task.static for c in statics):
                        edges.setdefault(env[old], set()).add(env[new])
                continue
            olds = task.domain(types[old]) if old.startswith("?") else [old]
            news = task.domain(types[new]) if new.startswith("?") else [new]
            for vo in olds:
                for vn in news:
                    env = {old: vo, new: vn}
                    if all((c[1], tuple(env.get(t, t) for t in c[2])) in task.static for c in statics):
                        edges.setdefault(vo, set()).add(vn)
        self._graphs[key] = edges
        return edges

    def distance(self, pred: str, obj: str, start: str, goal: str) -> int:
        if start == goal:
            return 0
        key = (pred, self.task.objects.get(obj), goal)
        table = self._to.get(key)
        if table is None:
            back: dict = {}
            for v, outs in self.graph(pred, obj).items():
                for w in outs:
                    back.setdefault(w, []).append(v)
            table = {goal: 0}
            queue = deque([goal])
            while queue:
                v = queue.popleft()
                for u in back.get(v, ()):
                    if u not in table:
                        table[u] = table[v] + 1
                        queue.append(u)
            self._to[key] = table
        return table.get(start, FAR)

    # ---- achiever instances -------------------------------------------------------------
    def instances(self, mark) -> list:
        """[(functional atoms [(pred, obj, value)], other ground conjuncts)] of the
        landmark's achievers, bound (see the module docstring)."""
        task = self.task
        if mark[0] == "exists":
            qtypes, atoms = dict(mark[1]), [c for c in conjuncts(mark[2]) if c[0] == "atom"]
        elif mark[0] == "atom":
            qtypes, atoms = {}, [mark]
        else:
            return []
        out = []
        for a in task.dom.actions:
            types = dict(a.params)
            adds = [e for e in a.effects if e.add and not e.params and e.cond == TRUE]
            env = _joint(task, adds, atoms, types, qtypes)
            if env is None:
                continue
            for full in self._complete(a, env, types):
                funcs, others = [], []
                for c in conjuncts(substitute(a.pre, full)):
                    if free_vars(c):
                        continue
                    if c[0] == "atom" and len(c[2]) == 2 and self.functional(c[1], c[2][0]):
                        funcs.append((c[1], c[2][0], c[2][1]))
                    elif not (c[0] == "atom" and c[1] not in task.fluent):
                        others.append(c)
                out.append((funcs, others))
                if len(out) >= MAX_INSTANCES:
                    return out
        return out

    def entries(self, obj: str, wanted: tuple) -> list:
        """[[ground conjuncts]] of each way to step onto `wanted` ((pred, value), ... of
        functional predicates of `obj`), fewest first, none a superset of another (see
        the module docstring); [] when no schema steps there."""
        key = (obj, wanted)
        got = self._entries.get(key)
        if got is not None:
            return got
        task = self.task
        want = dict(wanted)
        found = set()
        if self._steppers is None:      # per schema, once: its types, its adds of a binary atom, its conjuncts
            self._steppers = [(a, dict(a.params), [e for e in a.effects if e.add and len(e.args) == 2
                                                   and not e.params and e.cond == TRUE], conjuncts(a.pre))
                              for a in task.dom.actions]
        for a, types, adds, pre in self._steppers:
            if not any(e.pred in want for e in adds):
                continue
            env: dict = {}
            changed = set()
            ok = True
            for e in adds:
                if e.pred not in want:
                    continue
                t, v = e.args
                if t.startswith("?") and not task.fits(obj, types.get(t, frozenset({"object"}))) or \
                        not t.startswith("?") and t != obj:
                    continue
                for term, value in ((t, obj), (v, want[e.pred])):
                    if term.startswith("?"):
                        if env.setdefault(term, value) != value or not task.fits(value, types[term]):
                            ok = False
                    elif term != value:
                        ok = False
                changed.add(e.pred)
            if not changed or not ok:
                continue
            # a wanted value the schema does not change must hold before it too
            for c in pre:
                if c[0] == "atom" and c[1] in want and c[1] not in changed and len(c[2]) == 2 \
                        and env.get(c[2][0], c[2][0]) == obj and c[2][1].startswith("?"):
                    if env.setdefault(c[2][1], want[c[1]]) != want[c[1]]:
                        ok = False
            if not ok:
                continue
            for full in self._complete(a, env, types):
                ground = [c for c in (substitute(c, full) for c in pre) if not free_vars(c)]
                if any(c[0] == "atom" and c[1] not in task.fluent and (c[1], c[2]) not in task.static
                       for c in ground):
                    continue          # a static condition fails: this way does not exist
                if any(c[0] == "atom" and c[1] in want and c[1] not in changed and c[2] != (obj, want[c[1]])
                       for c in ground):
                    continue
                conds = frozenset(c for c in ground
                                  if not (c[0] == "atom" and (c[1] not in task.fluent or
                                          len(c[2]) == 2 and c[2][0] == obj and self.functional(c[1], obj))))
                found.add(conds)
        kept = sorted(found, key=lambda c: (len(c), sorted(map(repr, c))))
        out = []
        for c in kept:
            if not any(k <= c for k in out):
                out.append(c)
        got = self._entries[key] = [sorted(c, key=repr) for c in out]
        return got

    def _complete(self, a, env: dict, types: dict) -> list:
        """`env` extended through the precondition's static atoms, then over small types."""
        task = self.task
        envs = [env]
        statics = [c for c in conjuncts(a.pre) if c[0] == "atom" and c[1] not in task.fluent]
        changed = True
        while changed:
            changed = False
            for c in statics:
                out = []
                for e in envs:
                    args = tuple(e.get(t, t) for t in c[2])
                    unbound = [t for t in args if t.startswith("?")]
                    if not unbound:
                        if (c[1], args) in task.static:
                            out.append(e)
                        continue
                    if len(unbound) == len(args):
                        out.append(e)          # nothing to join on
                        continue
                    changed = True
                    k = next(i for i, t in enumerate(args) if not t.startswith("?"))
                    for fact in task.static_index.get((c[1], k, args[k]), ()):    # the facts with that object there
                        e2 = dict(e)
                        if all(e2.setdefault(t, o) == o if t.startswith("?") else t == o
                               for t, o in zip(args, fact)):
                            if all(task.fits(e2[t], types[t]) for t in unbound):
                                out.append(e2)
                envs = out[:MAX_INSTANCES]
        free = [v for v, _ in a.params if v not in envs[0]] if envs else []
        small = [v for v in free if len(task.domain(types[v])) <= SMALL_TYPE]
        if small:
            envs = [dict(e, **dict(zip(small, combo))) for e in envs
                    for combo in itertools.product(*(task.domain(types[v]) for v in small))]
        return envs[:MAX_INSTANCES]


def _joint(task: LiftedTask, adds: list, atoms: list, types: dict, qtypes: dict) -> dict | None:
    """A binding of the schema's variables under which its add effects make every atom of
    the landmark true (the landmark's quantified variables match any object of a shared
    type), or None."""
    env: dict = {}
    qmap: dict = {}
    for atom in atoms:
        for e in adds:
            if e.pred != atom[1]:
                continue
            trial, tq = dict(env), dict(qmap)
            ok = True
            for te, ta in zip(e.args, atom[2]):
                if ta in qtypes:
                    if not te.startswith("?") or tq.setdefault(ta, te) != te or \
                            not any(task.fits(o, types[te]) for o in task.domain(qtypes[ta])):
                        ok = False
                        break
                    continue
                if te.startswith("?"):
                    if trial.setdefault(te, ta) != ta or not task.fits(ta, types[te]):
                        ok = False
                        break
                elif te != ta:
                    ok = False
                    break
            if ok:
                env, qmap = trial, tq
                break
        else:
            return None
    return env
