"""What R-max learns: transition models built from the agent's own experience.

`Tabular` remembers each (state, action); `ObjectOriented` learns each action's effect
relative to the agent under conditions over local features, in the spirit of DOORMax
(Diuk, Cohen and Littman 2008), so knowledge from one cell carries to every cell.
Both answer `predict(s, a)` with the next state, or None when they do not know yet
(R-max is then optimistic), and learn from `observe(s, a, next_state)`.
"""
from __future__ import annotations

from ..errors import BccError
from ..model import Model
from .perception import NOTHING, Perception


class Tabular:
    """(state, action) -> observed outcome, known after m visits."""

    def __init__(self, model: Model, m: int = 1):
        self.m, self.table, self.visits = m, {}, {}

    def observe(self, s, a, outcome):
        self.visits[(s, a)] = self.visits.get((s, a), 0) + 1
        self.table[(s, a)] = outcome

    def predict(self, s, a):
        if self.visits.get((s, a), 0) >= self.m:
            return self.table[(s, a)]
        return None


class ObjectOriented:
    """DOORMax-style learner over what `Perception` sees. An action's *effect*
    (attributes stepped or set, position moved, cells changed: all relative to the agent)
    is learned as a function of *conditions* over the perceived features, so what is
    learned in one place holds wherever the surroundings look the same, whichever way the
    agent faces, and (with the same domain) in other dungeons.

    Effects: an effect's condition is a disjunction of terms that cover its examples and
    no example of another effect; each term is cut to the fewest constraints that still
    rule those out, taken first from the agent itself, what it holds and what the effect
    acts on (`_simplest`). It is trusted only where what the effect acts on, and the
    agent itself, look as they did in its examples (`_familiar`); an effect that ended an
    episode in failure is trusted wherever what it acts on looks the same, since testing
    it again would cost a whole episode. Two trusted effects are decided by the nearest.

    Nothing happening has many reasons and gets no condition of its own. It is predicted
    where it was seen, remembered by the agent, what it holds and the cells actions act
    on (`_noop_key`), or where every effect the action is known to have is ruled out: by
    a failure seen under the same conditions, or by a value seen to block the action in
    a near miss (`_all_fail`, `_blocks`). Anything else is unknown, hence optimistic for
    R-max; a wrong prediction falls back to what was seen in that very state.
    """

    def __init__(self, model: Model, m: int = 1, radius: int = 1):
        if all(p is None for p in model.position):
            raise BccError("rmax's oo model learner perceives the grid around an agent, and this model has no agent "
                           "position (e.g. an imported PDDL task): use -O model=tabular")
        self.model, self.m = model, m
        self.sense = Perception(model, radius)
        self.exact = {}          # (action, features) -> effect
        self.examples = {}       # action -> {effect: [feature tuples]}
        self.terms = {}          # (action, effect) -> [term: list of allowed value sets per feature]
        self.general = {}        # (action, effect) -> the same terms with the fewest constraints
        self.seen = {}           # (action, effect) -> [(feature of its locus, values seen in its examples)]
        self.noops = set()       # (action, what a no-op is remembered by: see _noop_key) where nothing happened
        self.noop_examples = []  # (action, features) of every no-op seen
        self.reach = set()       # features of the cells any action has changed or moved into
        self.fatal = set()       # effects seen ending the episode in failure
        self.predicted = {}      # action -> {features: effect or None}, until that action's knowledge changes
        self.failure_index = {}  # action -> {(effect, term): failure examples projected on its features}
        self.fallback = Tabular(model, m)
        self.wrong = set()       # (state, action) where a generalised prediction failed
        self.answers = {}        # action -> {state: predicted next state}, until that action's knowledge changes

    # -- terms ---------------------------------------------------------------------------
    def _is_noop(self, eff):
        return eff == NOTHING

    def _noop_key(self, f):
        """What a no-op is remembered by: the agent's own attributes but its facing (it
        sees in its own frame) and index ones (the item held counts, not the slot), what
        its index attributes point to, and the cells where actions have been seen to act
        (typically the column ahead of it). Where an action once did nothing,
        it is expected to do nothing again wherever all of these are the same."""
        if not self.reach:  # no action seen acting on a cell yet: every cell may matter
            return tuple(v for i, v in enumerate(f) if i not in self.sense.index_features)
        return tuple(f[i] for i in self.sense.own_features) + tuple(f[i] for i in sorted(self.reach))

    def _cells_of(self, eff):
        """The cell features in an effect's locus (its attributes left out)."""
        return {i for i in self.sense.locus(eff) if i >= len(self.sense.attrs)}

    def _remember_noops(self):
        """(Re)build the no-op keys; a key under which the action also did something is
        not a reason, and is left out."""
        self.noops = {(a, self._noop_key(f)) for a, f in self.noop_examples}
        self.noops -= {(a, self._noop_key(f)) for a, by_effect in self.examples.items()
                       for eff, fs in by_effect.items() if not self._is_noop(eff) for f in fs}

    @staticmethod
    def _holds(constraints, f):
        """A general term, kept as its (feature, allowed values) constraints only."""
        return all(f[i] in allowed for i, allowed in constraints)

    @staticmethod
    def _covers(term, f):
        return all(allowed is None or v in allowed for allowed, v in zip(term, f))

    def _learn_terms(self, a, eff):
        """Greedy cover of the effect's examples by terms that cover no example of another
        effect: a term allows, per feature, the values its examples had."""
        mine = self.examples[a][eff]
        others = [f for e, fs in self.examples[a].items() if e != eff for f in fs]
        terms = []
        for f in mine:
            for k, t in enumerate(terms):
                if self._covers(t, f):
                    break
                wider = [None if allowed is None else allowed | {v} for allowed, v in zip(t, f)]
                if not any(self._covers(wider, g) for g in others):
                    terms[k] = wider
                    break
            else:
                terms.append([frozenset((v,)) for v in f])
        self.terms[(a, eff)] = terms
        locus = self.sense.locus(eff)
        preferred = locus | self.sense.own
        self.general[(a, eff)] = [tuple((i, allowed) for i, allowed in enumerate(self._simplest(t, others, preferred))
                                        if allowed is not None) for t in terms]
        watched = locus if eff in self.fatal else locus | self.sense.own
        self.seen[(a, eff)] = [(i, {f[i] for f in mine}) for i in sorted(watched)]

    @staticmethod
    def _simplest(term, others, preferred=frozenset()):
        """The fewest of a term's constraints that still rule out every example of the
        other effects (greedy set cover): the most general condition the data allow, so
        that one move seen in one corridor is expected in every corridor. It
        may be too general; a wrong prediction adds the example that corrects it.
        Constraints on the `preferred` features -- the agent itself, what it holds, what
        the effect acts on -- are taken first: a coincidence elsewhere (what lay behind the
        agent the one time it placed a block) explains less than what is in front of it."""
        constraints = [(i, allowed) for i, allowed in enumerate(term) if allowed is not None]
        keep, left = {}, others
        while left and constraints:
            score = {c: sum(g[c[0]] not in c[1] for g in left) for c in constraints}
            i, allowed = max(constraints, key=lambda c: (score[c] > 0 and c[0] in preferred, score[c]))
            if not score[(i, allowed)]:
                break  # the features cannot tell these apart
            keep[i], left = allowed, [g for g in left if g[i] in allowed]
        return [keep.get(i) for i in range(len(term))]

    def observe(self, s, a, n):
        guess = self.predict(s, a)
        if guess is not None and guess != n:  # the features missed something here: remember it exactly
            self.wrong.add((s, a))
        self.fallback.observe(s, a, n)
        self.answers.get(a, {}).pop(s, None)
        f, eff = self.sense.features(s), self.sense.effect(s, n)
        if self.exact.get((a, f)) == eff:
            return
        self.exact[(a, f)] = eff
        by_effect = self.examples.setdefault(a, {})
        by_effect.setdefault(eff, []).append(f)
        if self.model.is_failure(n):
            self.fatal.add(eff)
        if self._is_noop(eff):
            self.noop_examples.append((a, f))
            self.noops.add((a, self._noop_key(f)))
        else:
            cells = self._cells_of(eff)
            if not cells <= self.reach:
                self.reach |= cells
                self.predicted.clear()  # no-ops of every action are remembered by more now
                self.answers.clear()
            self._remember_noops()
        for other in by_effect:  # effects whose terms cover this example must be split
            if self._is_noop(other):
                continue
            if other == eff or any(self._holds(t, f) for t in self.general.get((a, other), ())):
                self._learn_terms(a, other)
        self.predicted.pop(a, None)  # only this action's knowledge changed
        self.failure_index.pop(a, None)
        self.answers.pop(a, None)

    def _generalised(self, f, a):
        known = self.predicted.setdefault(a, {})
        if f in known:
            return known[f]
        hits = [eff for eff in self.examples.get(a, ())
                if not self._is_noop(eff) and any(self._holds(t, f) for t in self.general[(a, eff)])]
        trusted = [eff for eff in hits if self._familiar(f, a, eff)]
        out = None
        if len(trusted) > 1:
            out = self._nearest(f, a, trusted)
        elif trusted:
            out = trusted[0]
        elif (not hits and (a, self._noop_key(f)) in self.noops) or self._all_fail(f, a):
            out = NOTHING
        known[f] = out
        return out

    def _familiar(self, f, a, eff):
        """Whether f shows, on the features the effect is watched on, only values its own
        examples had (see `_learn_terms`)."""
        return all(f[i] in values for i, values in self.seen[(a, eff)])

    def _nearest(self, f, a, effects):
        """Two simplest conditions hold at once: at least one is too general. Keep the
        effect whose own examples' common features (its specific terms) differ least from
        `f` -- a nearest-neighbour vote between the candidates; a tie stays unknown."""
        def distance(eff):
            return min(sum(allowed is not None and v not in allowed for allowed, v in zip(t, f))
                       for t in self.terms[(a, eff)])
        scored = sorted((distance(e), k) for k, e in enumerate(effects))
        return None if scored[0][0] == scored[1][0] else effects[scored[0][1]]

    def _all_fail(self, f, a):
        """DOORMax's failure conditions, over the simplest conditions: every effect `a` is
        known to have is ruled out in `f`, because `a` once did something else in a state
        that agrees with `f` on every feature the effect's condition constrains and on
        what the effect acts on, or because a value of `f` that the condition does not
        allow is a known blocker (`_blocks`). An effect whose condition holds but which is
        not familiar here is ruled out only by a known blocker among its unfamiliar
        values. A combination never seen there leaves the effect possible (unknown, hence
        worth trying): a simplest condition may be too general, and a failure it wrongly
        predicted would never be tried again."""
        by_effect = self.examples.get(a, {})
        effects = [e for e in by_effect if not self._is_noop(e)]
        if not effects:
            return False  # never seen doing anything: nothing to rule out
        for eff in effects:
            for k, term in enumerate(self.general[(a, eff)]):
                if self._holds(term, f):  # it holds, yet is not trusted here (see _familiar)
                    if not any(f[i] not in values and self._blocks(f, a, i) for i, values in self.seen[(a, eff)]):
                        return False
                    continue
                fixed, seen = self._failures(a, eff, k, term)
                if tuple(f[i] for i in fixed) in seen:
                    continue
                if not any(f[i] not in allowed and self._blocks(f, a, i) for i, allowed in term):
                    return False
        return True

    def _blocks(self, f, a, i):
        """Whether f's value of feature i is a known blocker of `a`: a near miss (Winston)
        was seen -- `a` did something else in a state that met every constraint of one of
        its effects' conditions but the one on i, where it had this value, and that agreed
        with `f` on the cells that effect acts on. That value, not the rest of the
        surroundings, is then what stopped the effect, and it stops `a`'s effects wherever
        it is seen: looking the wrong way, or holding the wrong item, blocks a mining or
        placing action before whatever is ahead. Cells acted on must agree (a block placed
        on one kind of floor says nothing about filling another); the attributes an effect changes need
        not (where the mined block goes in the inventory does not decide whether mining
        happens)."""
        for eff in self.examples.get(a, ()):
            if self._is_noop(eff):
                continue
            for k, term in enumerate(self.general[(a, eff)]):
                rest, table = self._near_misses(a, eff, k, term)
                if (f[i],) + tuple(f[j] for j in rest) in table.get(i, ()):
                    return True
        return False

    def _near_misses(self, a, eff, k, term):
        """Per feature i, the near misses of term k of `eff`: the other effects' examples
        that met every constraint of the term but the one on i, as (their value of i, their
        cells acted on that the term does not constrain) (built once per change of
        knowledge)."""
        index = self.failure_index.setdefault(a, {})
        hit = index.get((eff, k, "near"))
        if hit is None:
            rest = tuple(sorted(self.sense.cells_acted_on(eff) - {i for i, _ in term}))
            table = {}
            for e, gs in self.examples[a].items():
                if e == eff:
                    continue
                for g in gs:
                    missed = [i for i, allowed in term if g[i] not in allowed]
                    if len(missed) == 1:
                        table.setdefault(missed[0], set()).add((g[missed[0]],) + tuple(g[j] for j in rest))
            hit = index[(eff, k, "near")] = (rest, table)
        return hit

    def _failures(self, a, eff, k, term):
        """The features term k of `eff` constrains or the effect acts on, and the other
        effects' examples projected onto them (built once per change of knowledge)."""
        index = self.failure_index.setdefault(a, {})
        hit = index.get((eff, k))
        if hit is None:
            fixed = tuple(sorted({i for i, _ in term} | self.sense.locus(eff)))
            seen = {tuple(g[i] for i in fixed)
                    for e, gs in self.examples[a].items() if e != eff for g in gs}
            hit = index[(eff, k)] = (fixed, seen)
        return hit

    def predict(self, s, a):
        answers = self.answers.get(a)
        if answers is None:
            answers = self.answers[a] = {}
        n = answers.get(s, False)
        if n is False:
            n = answers[s] = self._predict(s, a)
        return n

    def _predict(self, s, a):
        if (s, a) in self.wrong:
            return self.fallback.predict(s, a)
        f = self.sense.features(s)
        eff = self.exact.get((a, f))
        if eff is None:
            eff = self._generalised(f, a)
        if eff is None:
            return self.fallback.predict(s, a)
        if self._is_noop(eff):
            return s
        return self.sense.apply_effect(s, eff) or self.fallback.predict(s, a)


LEARNERS = {"tabular": Tabular, "oo": ObjectOriented}
