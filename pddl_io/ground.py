"""Ground a lifted PDDL task by relaxed reachability: only what can happen is instantiated.

Why not every combination of objects: a logistics action has millions of bindings and
almost none can ever apply. As in Fast Downward's translator (instantiate.py), the
grounder explores atoms forward from the initial state, ignoring deletes: a binding of
an action is made when the positive atoms of its precondition's top-level conjunction
are all reached (semi-naive: each new atom is joined, once, with those already reached),
and its add effects are reached in turn. Negative conditions and disjunctions are not
used to prune here (an over-approximation); they are checked when the ground action's
formula is built, with static atoms folded to constants.

Then:
- static predicates (no effect changes them) and atoms that never change are folded
  into the formulas, which are simplified; actions whose precondition folds to false go;
- backward relevance (Fast Downward's simplify step): an action matters only if it
  changes an atom the goal, or a precondition or effect condition of an action that
  matters, reads; the others, and the atoms only they touch, are dropped.

The result is a `GroundTask` over atom numbers; compile.py turns it into bcc's IR.
"""
from __future__ import annotations

import functools
import itertools
from collections import defaultdict
from dataclasses import dataclass, field

from ..errors import BccError
from .lifted_types import FALSE, TRUE, Domain, Problem, conjuncts, is_a


@dataclass
class GroundAction:
    name: str                 # "(pick ball1 rooma left)"
    pre: object               # ground formula over atom numbers: int, ("not", f), ("and", fs), ("or", fs), TRUE
    effects: list             # [(cond formula, atom, add?)]
    cost: int


@dataclass
class GroundTask:
    name: str
    atoms: list               # atom number -> (predicate, args)
    initial: set              # atom numbers true initially
    actions: list             # [GroundAction]
    goal: object              # ground formula
    uses_costs: bool
    stats: dict = field(default_factory=dict)

    def atom_text(self, i: int) -> str:
        pred, args = self.atoms[i]
        return "(" + " ".join((pred, *args)) + ")"


class _Rule:
    """A join to evaluate: variables `params`, positive atoms `pos`, and what to do on a match."""

    def __init__(self, params, pos, eqs, neqs, negs, action, effect):
        self.params = params          # ((var, types), ...)
        self.pos = pos                # ((pred, args), ...)
        self.eqs, self.neqs = eqs, neqs
        self.negs = negs              # static atoms that must be false: ((pred, args), ...)
        self.action, self.effect = action, effect


def _is_var(t: str) -> bool:
    return t[0] == "?"


class TooBig(Exception):
    """Grounding would take more than its work limit (`ground(max_work=...)`): the caller
    searches the lifted task instead (lifted_search.py)."""


class Grounder:
    def __init__(self, dom: Domain, prob: Problem, max_actions: int | None = None, max_work: int | None = None):
        self.dom, self.prob = dom, prob
        self.max_actions = max_actions
        self.max_work = max_work
        self.work = 0
        self.fluent_preds = {e.pred for a in dom.actions for e in a.effects}
        self._typed: dict = {}
        self.object_types = prob.objects

    def objects_of(self, types: frozenset) -> list:
        got = self._typed.get(types)
        if got is None:
            fits = {t: any(is_a(t, w, self.dom.parents) for w in types) for t in set(self.object_types.values())}
            got = [o for o, t in self.object_types.items() if fits[t]]
            self._typed[types] = got
        return got

    # ---- rules --------------------------------------------------------------------
    def _rule(self, params, conds, action, effect):
        pos, eqs, neqs, negs = [], [], [], []
        for c in conds:
            if c[0] == "atom":
                pos.append((c[1], c[2]))
            elif c[0] == "=":
                eqs.append((c[1], c[2]))
            elif c[0] == "not" and c[1][0] == "=":
                neqs.append((c[1][1], c[1][2]))
            elif c[0] == "not" and c[1][0] == "atom" and c[1][1] not in self.fluent_preds:
                negs.append((c[1][1], c[1][2]))
        return _Rule(params, tuple(pos), eqs, neqs, negs, action, effect)

    def rules(self) -> list:
        out = []
        for ai, a in enumerate(self.dom.actions):
            conds = conjuncts(a.pre)
            out.append(self._rule(a.params, conds, ai, None))
            for e in a.effects:
                if e.add and (e.params or e.cond != TRUE):
                    out.append(self._rule(a.params + e.params, conds + conjuncts(e.cond), ai, e))
        return out

    # ---- exploration -------------------------------------------------------------
    def explore(self):
        """Reached atoms (a set of (pred, args)) and action bindings {action: set of arg tuples}."""
        rules = self.rules()
        by_pred = defaultdict(list)
        for r in rules:
            for k, (pred, _) in enumerate(r.pos):
                by_pred[pred].append((r, k))
        reached: set = set()
        index: dict = defaultdict(list)          # (pred, position, object) -> [args]
        of_pred: dict = defaultdict(list)
        bindings: dict = defaultdict(set)
        queue = list(self.prob.init)
        fire = self._firing(bindings, queue)
        complete, unify = self._joining(fire, index, of_pred)
        for r in rules:
            if not r.pos:
                complete(r, {}, frozenset())
        while queue:
            atom = queue.pop()
            reached.add(atom)
            pred, args = atom
            of_pred[pred].append(args)
            for p, o in enumerate(args):
                index[(pred, p, o)].append(args)
            for rule, k in by_pred.get(pred, ()):
                env = unify(rule, rule.pos[k][1], args, {})
                if env is not None:
                    complete(rule, env, frozenset({k}))
        return reached, bindings

    def _firing(self, bindings: dict, queue: list):
        """`fire(rule, env)`: a rule's match, its equalities and static negative atoms
        checked; a new binding of an action is recorded in `bindings` and its plain add
        effects pushed on `queue`, a conditional effect's atom pushed. The closures of
        explore's inner loop (called per match: no extra calls)."""
        pending = set(queue)
        init = self.prob.init
        count = 0

        def fire(rule, env):
            nonlocal count
            for v, _ in rule.params:
                if v not in env:
                    raise AssertionError("unbound")
            for a, b in rule.eqs:
                if env.get(a, a) != env.get(b, b):
                    return
            for a, b in rule.neqs:
                if env.get(a, a) == env.get(b, b):
                    return
            for pred, args in rule.negs:
                if (pred, tuple(env.get(t, t) for t in args)) in init:
                    return
            act = self.dom.actions[rule.action]
            if rule.effect is None:
                key = tuple(env[v] for v, _ in act.params)
                got = bindings[rule.action]
                if key in got:
                    return
                got.add(key)
                count += 1
                if self.max_actions is not None and count > self.max_actions:
                    raise BccError(f"grounding makes more than {self.max_actions:,} actions "
                                   "(raise the limit with --max-states)", self.prob.path)
                for e in act.effects:
                    if e.add and not e.params and e.cond == TRUE:
                        push((e.pred, tuple(env.get(t, t) for t in e.args)))
            else:
                e = rule.effect
                push((e.pred, tuple(env.get(t, t) for t in e.args)))

        def push(atom):
            if atom not in pending:
                pending.add(atom)
                queue.append(atom)
        return fire

    def _joining(self, fire, index: dict, of_pred: dict):
        """`complete(rule, env, done)`: bind a rule's remaining positive atoms against the
        atoms reached so far (`of_pred`, `index`), then its free parameters, and `fire`
        each match; `unify(rule, args, fact_args, env)`: env extended by one atom, or None.
        The closures of explore's inner loop (called per candidate: no extra calls)."""
        def complete(rule, env, done):
            """Bind the remaining positive atoms, then the free parameters, then fire."""
            best, best_bound = None, -1
            for k, (pred, args) in enumerate(rule.pos):
                if k in done:
                    continue
                bound = sum(1 for t in args if not _is_var(t) or t in env)
                if bound > best_bound:
                    best, best_bound = k, bound
            if best is None:
                free = [(v, t) for v, t in rule.params if v not in env]
                if not free:
                    fire(rule, env)
                    return
                for combo in itertools.product(*(self.objects_of(t) for _, t in free)):
                    env2 = dict(env)
                    env2.update(zip((v for v, _ in free), combo))
                    fire(rule, env2)
                return
            pred, args = rule.pos[best]
            cands = of_pred[pred]
            for p, t in enumerate(args):
                val = env.get(t, t) if _is_var(t) else t
                if not _is_var(val):
                    got = index.get((pred, p, val), ())
                    if len(got) < len(cands):
                        cands = got
            self.spend(len(cands))
            done2 = done | {best}
            for fact_args in list(cands):
                env2 = unify(rule, args, fact_args, env)
                if env2 is not None:
                    complete(rule, env2, done2)

        ptypes_cache: dict = {}

        def unify(rule, args, fact_args, env):
            env2 = dict(env)
            types = ptypes_cache.get(id(rule))
            if types is None:
                types = ptypes_cache[id(rule)] = dict(rule.params)
            for t, o in zip(args, fact_args):
                if _is_var(t):
                    have = env2.get(t)
                    if have is None:
                        if o not in self.object_types or not self._fits(o, types[t]):
                            return None
                        env2[t] = o
                    elif have != o:
                        return None
                elif t != o:
                    return None
            return env2
        return complete, unify

    def spend(self, work: int) -> None:
        """Count `work` (candidate atoms joined, bindings of quantified variables) against max_work."""
        self.work += work
        if self.max_work is not None and self.work > self.max_work:
            raise TooBig(f"grounding needs more than {self.max_work:,} steps")

    def _fits(self, obj: str, types: frozenset) -> bool:
        return obj in self._fit_set(types)

    def _fit_set(self, types: frozenset) -> set:
        key = ("set", types)
        got = self._typed.get(key)
        if got is None:
            got = self._typed[key] = set(self.objects_of(types))
        return got


def ground(dom: Domain, prob: Problem, max_actions: int | None = None, relevance: bool = True,
           max_work: int | None = None) -> GroundTask:
    """The ground task; with `max_work`, TooBig when grounding would take more steps than that."""
    g = Grounder(dom, prob, max_actions, max_work)
    reached, bindings = g.explore()
    raw = [(a, key, dict(zip((v for v, _ in a.params), key)))
           for ai, a in enumerate(dom.actions) for key in sorted(bindings.get(ai, ()))]
    changing, inst_effects = _instantiated_effects(g, raw, reached, prob.init)
    atom_ids: dict = {}
    atoms: list = []

    def atom_id(atom) -> int:
        i = atom_ids.get(atom)
        if i is None:
            i = atom_ids[atom] = len(atoms)
            atoms.append(atom)
        return i

    fold = _folder(g, changing, prob.init, atom_id)
    actions = []
    for (a, key, env), effs in zip(raw, inst_effects):
        action = _ground_action(a, key, env, effs, changing, fold, atom_id, prob, dom)
        if action is not None:
            actions.append(action)
    goal = fold(prob.goal, {})
    initial = {atom_ids[a] for a in prob.init if a in atom_ids}
    task = GroundTask(prob.name, atoms, initial, actions, goal, prob.metric,
                      stats={"reached_atoms": len(reached), "instantiated_actions": len(actions)})
    task = fold_unchanging(task)
    if relevance:
        task = relevant(task)
    task.stats.update({"atoms": len(task.atoms), "actions": len(task.actions)})
    return task


def _instantiated_effects(g: Grounder, raw: list, reached, init) -> tuple[set, list]:
    """The effects of every reached binding, and which reached atoms can change at all
    (an add of an atom false at the start, a delete of one true)."""
    changing: set = set()
    inst_effects = []
    for a, key, env in raw:
        effs = []
        for e in a.effects:
            for combo in itertools.product(*(g.objects_of(t) for _, t in e.params)):
                env2 = dict(env)
                env2.update(zip((v for v, _ in e.params), combo))
                atom = (e.pred, tuple(env2.get(t, t) for t in e.args))
                if e.add and atom not in reached:
                    continue    # its condition can never hold (a rule would have reached it)
                if not e.add and atom not in reached:
                    continue    # deleting what is never true changes nothing
                effs.append((e.cond, env2, atom, e.add))
                if e.add != (atom in init):
                    changing.add(atom)
        inst_effects.append(effs)
    return changing, inst_effects


def _folder(g: Grounder, changing: set, init, atom_id):
    """`fold(f, env)`: a lifted formula grounded and simplified; atoms that cannot change
    become constants."""
    def fold(f, env):
        kind = f[0]
        if kind == "atom":
            atom = (f[1], tuple(env.get(t, t) for t in f[2]))
            if atom in changing:
                return atom_id(atom)
            return TRUE if atom in init else FALSE
        if kind == "=":
            return TRUE if env.get(f[1], f[1]) == env.get(f[2], f[2]) else FALSE
        if kind == "not":
            sub = fold(f[1], env)
            return FALSE if sub == TRUE else TRUE if sub == FALSE else ("not", sub)
        if kind in ("and", "or"):
            return _junction(kind, [fold(s, env) for s in f[1]])
        if kind in ("exists", "forall"):
            parts = []
            sizes = [len(g.objects_of(t)) for _, t in f[1]]
            g.spend(functools.reduce(lambda x, y: x * y, sizes, 1))
            for combo in itertools.product(*(g.objects_of(t) for _, t in f[1])):
                env2 = dict(env)
                env2.update(zip((v for v, _ in f[1]), combo))
                parts.append(fold(f[2], env2))
            return _junction("or" if kind == "exists" else "and", parts)
        return f  # TRUE / FALSE
    return fold


def _ground_action(a, key, env, effs: list, changing: set, fold, atom_id, prob: Problem, dom: Domain):
    """The ground action of one binding, or None when its precondition folds to false or
    it changes nothing (a self-loop, never part of a shortest plan)."""
    pre = fold(a.pre, env)
    if pre == FALSE:
        return None
    effects = []
    for cond, env2, atom, add in effs:
        if atom not in changing:
            continue
        c = fold(cond, env2) if cond != TRUE else TRUE
        if c != FALSE:
            effects.append((c, atom_id(atom), add))
    effects = effective_effects(pre, effects)
    if not effects:
        return None
    cost = _cost(a, env, prob, dom) if prob.metric else 1
    return GroundAction("(" + " ".join((a.name, *key)) + ")", pre, effects, cost)


def effective_effects(pre, effects: list) -> list:
    """The effects that can change the state, as Fast Downward's translator keeps them.

    An unconditional add beats any delete of the same atom (PDDL: deletes apply first);
    an add of an atom the precondition requires (and no effect deletes), or a delete of
    one it forbids, changes nothing. Without this, `(not (channel-free ?l)) (channel-free ?l)`
    would count as writing `channel-free`, and backward relevance would keep every action
    doing it."""
    conj = [pre] if not (isinstance(pre, tuple) and pre[0] == "and") else list(pre[1])
    true = {c for c in conj if isinstance(c, int)}
    false = {c[1] for c in conj if isinstance(c, tuple) and c[0] == "not" and isinstance(c[1], int)}
    added = {atom for cond, atom, add in effects if add and cond == TRUE}
    effects = [(cond, atom, add) for cond, atom, add in effects if add or not (atom in false or atom in added)]
    deleted = {atom for cond, atom, add in effects if not add}
    # an add of a required atom that a (conditional) delete may clear restores it: it stays
    out = [(cond, atom, add) for cond, atom, add in effects if not (add and atom in true and atom not in deleted)]
    return list(dict.fromkeys(out))


def _cost(a, env, prob: Problem, dom: Domain) -> int:
    if a.cost is None:
        return 0                      # Fast Downward's rule under a total-cost metric
    if isinstance(a.cost, int):
        return a.cost
    fname, args = a.cost
    key = (fname, tuple(env.get(t, t) for t in args))
    value = prob.function_values.get(key)
    if value is None:
        raise BccError(f"the cost of action {a.name} reads ({' '.join((key[0], *key[1]))}), "
                       "which the problem's :init does not give", dom.path, *a.where)
    return value


def _junction(kind: str, parts: list):
    unit, zero = (TRUE, FALSE) if kind == "and" else (FALSE, TRUE)
    out = []
    for p in parts:
        if p == zero:
            return zero
        if p == unit:
            continue
        if isinstance(p, tuple) and p[0] == kind:
            out.extend(p[1])
        else:
            out.append(p)
    if not out:
        return unit
    if len(out) == 1:
        return out[0]
    return (kind, tuple(dict.fromkeys(out)))


def atoms_of(f, acc: set) -> set:
    if isinstance(f, int):
        acc.add(f)
    elif f[0] == "not":
        atoms_of(f[1], acc)
    elif f[0] in ("and", "or"):
        for s in f[1]:
            atoms_of(s, acc)
    return acc


def _substitute(f, value: dict):
    """Ground formula `f` with the atoms of `value` replaced by TRUE/FALSE, simplified."""
    if isinstance(f, int):
        v = value.get(f)
        return f if v is None else (TRUE if v else FALSE)
    kind = f[0]
    if kind == "not":
        sub = _substitute(f[1], value)
        return FALSE if sub == TRUE else TRUE if sub == FALSE else ("not", sub)
    if kind in ("and", "or"):
        return _junction(kind, [_substitute(g, value) for g in f[1]])
    return f


def fold_unchanging(task: GroundTask) -> GroundTask:
    """Atoms that no effective effect (effective_effects) changes keep their initial
    value: fold them into the formulas, as grounding did for the atoms no effect writes.
    Repeated until nothing changes (an action whose precondition folds to false goes,
    and with it its effects)."""
    actions = task.actions
    while True:
        changing = {atom for a in actions for _, atom, add in a.effects if add != (atom in task.initial)}
        value = {i: i in task.initial for i in range(len(task.atoms)) if i not in changing}
        if not value:
            break
        out = []
        for a in actions:
            pre = _substitute(a.pre, value)
            if pre == FALSE:
                continue
            effects = []
            for c, atom, add in a.effects:
                if atom in value:
                    continue
                c = _substitute(c, value)
                if c != FALSE:
                    effects.append((c, atom, add))
            effects = effective_effects(pre, effects)
            if effects:
                out.append(GroundAction(a.name, pre, effects, a.cost))
        if len(out) == len(actions) and all(x.pre == y.pre and x.effects == y.effects for x, y in zip(out, actions)):
            break
        actions = out
    goal = _substitute(task.goal, value) if value else task.goal
    return GroundTask(task.name, task.atoms, task.initial, actions, goal, task.uses_costs, dict(task.stats))


def relevant(task: GroundTask) -> GroundTask:
    """Drop actions that change no atom the goal (transitively) depends on, and atoms
    nothing relevant reads; renumber the rest."""
    need = atoms_of(task.goal, set())
    keep: set = set()
    changed = True
    info = []
    for a in task.actions:
        reads = atoms_of(a.pre, set())
        for c, _, _ in a.effects:
            atoms_of(c, reads)
        info.append((reads, {atom for _, atom, _ in a.effects}))
    while changed:
        changed = False
        for k, (reads, writes) in enumerate(info):
            if k not in keep and writes & need:
                keep.add(k)
                new = reads - need
                if new:
                    need |= new
                changed = True
    new_id = {old: i for i, old in enumerate(sorted(need))}

    def renum(f):
        if isinstance(f, int):
            return new_id[f]
        if f[0] == "not":
            return ("not", renum(f[1]))
        if f[0] in ("and", "or"):
            return (f[0], tuple(renum(s) for s in f[1]))
        return f

    actions = []
    for k in sorted(keep):
        a = task.actions[k]
        effects = [(renum(c), new_id[atom], add) for c, atom, add in a.effects if atom in need]
        actions.append(GroundAction(a.name, renum(a.pre), effects, a.cost))
    stats = dict(task.stats, irrelevant_actions=len(task.actions) - len(actions))
    return GroundTask(task.name, [task.atoms[i] for i in sorted(need)], {new_id[i] for i in task.initial if i in need},
                      actions, renum(task.goal), task.uses_costs, stats)
