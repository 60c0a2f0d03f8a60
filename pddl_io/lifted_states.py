"""States of a lifted PDDL task and the joins that find an action's bindings in one.

Why lifted: some tasks cannot be grounded. A world of blocks where any block may be
placed on any cell, with an inventory count of 0..64, has blocks x cells x counts
ground actions (hundreds of millions on a 17 x 17 x 17 world), and each "is some block
on this cell" condition grounds to a disjunction over every block. Fast Downward's
translator and bcc's grounder both spend their whole budget there. Here nothing is
grounded ahead: an action schema's bindings are found in the current state by a join
(as Powerlifted does), so a state costs what its own atoms cost.

A state is a frozenset of atom numbers: the fluent atoms whose truth differs from the
initial state (so a state stores only what changed, and a successor is `s ^ flips`).
Atoms are numbered as they are met; the initial state's fluent atoms come first, so
"atom i holds in s" is `(i < n_init) != (i in s)`. Static atoms (of predicates no
effect changes) are looked up in the problem's :init.

Joins (`Plan`): a conjunction's parts are ordered once per set of variables bound on
entry, cheapest first: tests whose variables are all bound, then the positive atom
whose bound arguments select the fewest atoms of the initial state (an index per
predicate, argument position and object), then `=`, then a type's objects for a
variable nothing else binds. `not`, `or`, `exists` and `forall` run as tests once their
free variables are bound (`forall` as `not exists not`).

Interchangeable objects (`Symmetry`): two objects of the same type that no constant of
the domain, no goal and no static atom tells apart (equal static atoms with each put in
place of the other, none naming both), and on which no fluent atom holds in state s,
are swapped by a permutation of objects that maps s, the goal, the static atoms and
every action schema to themselves. Such a permutation maps a binding to a binding and
a successor to a successor with the same distance to the goal. So where a join takes a
type's objects for a variable, it takes every object with some atom in s, the free
objects the binding already uses, and only the first other free object of each class:
sound (every kept binding is a binding) and complete (every pruned successor is the
image of a kept one, with the same plans to the goal up to renaming). A world with 297
spare blocks of one type places the first spare one, not each of them.
"""
from __future__ import annotations

from collections import defaultdict

from .lifted_types import Domain, Problem, is_a


def _is_var(t: str) -> bool:
    return t[:1] == "?"


def free_vars(f, acc: set | None = None) -> set:
    """The variables a formula reads that it does not quantify."""
    acc = set() if acc is None else acc
    kind = f[0]
    if kind == "atom":
        acc.update(t for t in f[2] if _is_var(t))
    elif kind == "=":
        acc.update(t for t in f[1:3] if _is_var(t))
    elif kind == "not":
        free_vars(f[1], acc)
    elif kind in ("and", "or"):
        for g in f[1]:
            free_vars(g, acc)
    elif kind in ("exists", "forall"):
        inner = free_vars(f[2], set())
        acc.update(inner - {v for v, _ in f[1]})
    return acc


def substitute(f, env: dict):
    """`f` with the variables of `env` replaced by objects (quantified ones are left alone)."""
    kind = f[0]
    if kind == "atom":
        return ("atom", f[1], tuple(env.get(t, t) for t in f[2]))
    if kind == "=":
        return ("=", env.get(f[1], f[1]), env.get(f[2], f[2]))
    if kind == "not":
        return ("not", substitute(f[1], env))
    if kind in ("and", "or"):
        return (kind, tuple(substitute(g, env) for g in f[1]))
    if kind in ("exists", "forall"):
        inner = {k: v for k, v in env.items() if k not in {v for v, _ in f[1]}}
        return (kind, f[1], substitute(f[2], inner))
    return f


class LiftedTask:
    """The problem's objects, static atoms and atom numbering (see the module docstring)."""

    def __init__(self, dom: Domain, prob: Problem):
        self.dom, self.prob = dom, prob
        self.fluent = {e.pred for a in dom.actions for e in a.effects}
        self.static = {a for a in prob.init if a[0] not in self.fluent}
        # Orders follow the files (predicates and objects as declared), never names:
        # a task with every name changed is searched in the same order.
        self.rank = {o: k for k, o in enumerate(prob.objects)}
        pred_rank = {p: k for k, p in enumerate(dom.predicates)}
        self.order_key = lambda atom: (pred_rank.get(atom[0], -1), [self.rank.get(o, -1) for o in atom[1]])
        self.static_index: dict = defaultdict(list)      # (pred, position, object) -> [args]
        self.static_all: dict = defaultdict(list)        # pred -> [args]
        for pred, args in sorted(self.static, key=self.order_key):
            self.static_all[pred].append(args)
            for k, o in enumerate(args):
                self.static_index[(pred, k, o)].append(args)
        self.typed: dict = {}                            # see typed_candidates
        self._live: dict = defaultdict(list)             # (pred, pos, obj) -> [(tkey, typed list)]
        self.ids: dict = {}                              # fluent atom -> number
        self.atoms: list = []                            # number -> (pred, args)
        self.index: dict = defaultdict(list)             # (pred, position, object) -> [(number, args)]
        self.of_pred: dict = defaultdict(list)           # pred -> [(number, args)]
        self.of_object: dict = defaultdict(list)         # object -> [number]
        for atom in sorted((a for a in prob.init if a[0] in self.fluent), key=self.order_key):
            self.intern(atom)
        self.n_init = len(self.atoms)
        self.objects = prob.objects
        self._domains: dict = {}
        self._fits: dict = {}
        self.stats = self._selectivity()
        self.symmetry = Symmetry(self)

    def intern(self, atom) -> int:
        i = self.ids.get(atom)
        if i is None:
            i = self.ids[atom] = len(self.atoms)
            self.atoms.append(atom)
            pred, args = atom
            entry = (i, args)
            self.of_pred[pred].append(entry)
            for k, o in enumerate(args):
                self.index[(pred, k, o)].append(entry)
            for o in set(args):
                self.of_object[o].append(i)
            for key in [(pred, None, None), *((pred, k, o) for k, o in enumerate(args))]:
                for tkey, lst in self._live.get(key, ()):
                    if self._typed_ok(args, tkey):
                        lst.append(entry)
        return i

    def _selectivity(self) -> dict:
        """(pred, position) -> the mean number of initial atoms sharing an object there;
        pred -> the number of its initial atoms: the join order's cost estimates."""
        count: dict = defaultdict(int)
        keys: dict = defaultdict(set)
        for pred, args in self.prob.init:
            count[pred] += 1
            for k, o in enumerate(args):
                keys[(pred, k)].add(o)
        out = dict(count)
        for (pred, k), objs in keys.items():
            out[(pred, k)] = count[pred] / max(1, len(objs))
        return out

    def holds_atom(self, s, pred: str, args: tuple) -> bool:
        if pred not in self.fluent:
            return (pred, args) in self.static
        i = self.ids.get((pred, args))
        return i is not None and (i < self.n_init) != (i in s)

    def true_atoms(self, s) -> list:
        """The fluent atoms (numbers) that hold in s."""
        return [i for i in range(self.n_init) if i not in s] + [i for i in s if i >= self.n_init]

    def domain(self, types: frozenset) -> list:
        got = self._domains.get(types)
        if got is None:
            # whether each object's type is one of `types` is asked once per distinct type:
            # a world of 11,000 blocks has a few dozen types
            fits = {t: any(is_a(t, w, self.dom.parents) for w in types) for t in set(self.objects.values())}
            got = self._domains[types] = [o for o, t in self.objects.items() if fits[t]]
            self._fits[types] = set(got)
        return got

    def _fit_set(self, types: frozenset) -> set:
        self.domain(types)
        return self._fits[types]

    def fits(self, obj: str, types: frozenset) -> bool:
        got = self._fits.get(types)
        if got is None:
            self.domain(types)
            got = self._fits[types]
        return obj in got

    def typed_candidates(self, pred: str, pos, obj, tkey: tuple) -> list:
        """The atoms of `pred` (with `obj` at position `pos`, unless pos is None) whose
        arguments at the positions of `tkey` ((position, types), ...) are of those types:
        (number, args) for a fluent predicate, args for a static one. Kept in `typed`
        (the generated joins read it directly) and grown by `intern` as atoms are met."""
        key = (pred, pos, obj, tkey)
        got = self.typed.get(key)
        if got is None:
            fluent = pred in self.fluent
            if fluent:
                src = self.of_pred.get(pred, ()) if pos is None else self.index.get((pred, pos, obj), ())
            else:
                src = self.static_all.get(pred, ()) if pos is None else self.static_index.get((pred, pos, obj), ())
            got = self.typed[key] = [c for c in src if self._typed_ok(c[1] if fluent else c, tkey)]
            if fluent:
                self._live[(pred, pos, obj)].append((tkey, got))
        return got

    def _typed_ok(self, args: tuple, tkey: tuple) -> bool:
        return all(self.fits(args[k], types) for k, types in tkey)

    def free(self, s, obj: str) -> bool:
        """No fluent atom naming `obj` holds in s."""
        n = self.n_init
        return not any((i < n) != (i in s) for i in self.of_object.get(obj, ()))


class Symmetry:
    """Classes of interchangeable objects (see the module docstring)."""

    def __init__(self, task: LiftedTask):
        dom, prob = task.dom, task.prob
        fixed = set(dom.constants) | set(dom.loose_names) | _objects_in(prob.goal)
        sig: dict = defaultdict(list)
        mentions: dict = defaultdict(set)
        for pred, args in task.static:
            for o in set(args):
                sig[o].append((pred, tuple("*" if a == o else a for a in args)))
                mentions[o].update(args)
        for (fname, args), value in prob.function_values.items():
            for o in set(args):
                sig[o].append((fname, tuple("*" if a == o else a for a in args), value))
                mentions[o].update(args)
        groups: dict = defaultdict(list)
        for o, t in prob.objects.items():
            if o not in fixed:
                groups[(t, tuple(sorted(sig.get(o, ()))))].append(o)
        self.cls: dict = {}           # object -> its class (a list of objects, in order)
        for members in groups.values():
            # two members named by one static atom cannot be swapped on their own: split them off
            members = [o for o in members if not (mentions.get(o, set()) - {o}) & set(members)]
            if len(members) > 1:
                for o in members:
                    self.cls[o] = members
        self.task = task

    def allowed(self, obj: str, s, used) -> bool:
        """May a join take `obj` for a variable, given the objects `used` by the binding so far?"""
        members = self.cls.get(obj)
        if members is None or obj in used:
            return True
        task = self.task
        if not task.free(s, obj):
            return True
        for o in members:               # the first free member the binding does not use
            if o not in used and task.free(s, o):
                return o == obj
        return True


def _objects_in(f) -> set:
    kind = f[0]
    if kind == "atom":
        return {t for t in f[2] if not _is_var(t)}
    if kind == "=":
        return {t for t in f[1:3] if not _is_var(t)}
    if kind == "not":
        return _objects_in(f[1])
    if kind in ("and", "or"):
        return set().union(*(_objects_in(g) for g in f[1])) if f[1] else set()
    if kind in ("exists", "forall"):
        return _objects_in(f[2])
    return set()
