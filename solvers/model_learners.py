"""What R-max learns: transition models built from the agent's own experience.

`Tabular` remembers each (state, action); `ObjectOriented` learns each action's effect
relative to the agent under conditions over local features, in the spirit of DOORMax
(Diuk, Cohen and Littman 2008), so knowledge from one cell carries to every cell.
Both answer `predict(s, a)` with the next state, or None when they do not know yet
(R-max is then optimistic), and learn from `observe(s, a, next_state)`.
"""
from __future__ import annotations

import re

from ..model import Model

# Compass names of a facing attribute's values (spec section 2): the direction ahead as
# (dx, dz) in the world's x and z.
COMPASS = {"south": (0, 1), "west": (-1, 0), "north": (0, -1), "east": (1, 0)}


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
    """DOORMax-style learner. An action's *effect* -- the agent's attributes set to new
    values, its position moved by a delta, cells changed relative to it -- is learned as a
    function of *conditions* over local features: the agent's attributes other than its
    position, what an index attribute points to (the item held, not the slot number), and
    the cells next to it (within `radius` in the plane, three layers). Nothing is keyed by
    absolute position, so what is learned in one cell holds in every cell with the same
    surroundings, and (with the same domain) in other dungeons.

    Each effect's condition is a disjunction of terms: its examples are covered greedily
    by terms that drop a feature seen with two values, as long as they cover no example
    of another effect; each term is then cut to the fewest constraints that still rule
    those out (the most general condition the data allow). A state is predicted by the
    one effect whose condition holds, or by what was seen in exactly these features.
    "Nothing happened" has many reasons and is not generalised: it is predicted where it
    was seen (up to which slot is selected), or where DOORMax's failure conditions rule out
    every effect the action is known to have (a failure seen in the same conditions, or a
    value seen to block the action in a near miss). Anything else is unknown, hence optimistic;
    a wrong prediction falls back to what was seen in that very state.
    """

    def __init__(self, model: Model, m: int = 1, radius: int = 1):
        self.model, self.m = model, m
        g = model.grid
        self.pos = [p[0] if p is not None else None for p in model.position]
        pos_idx = {i for i in self.pos if i is not None}
        self.attrs = [v.index for v in model.variables if v.index not in pos_idx]
        self.cyclic = {v.index: v.hi - v.lo + 1 for v in model.variables if v.type == "int"}
        self.pointers = self._pointers(model, pos_idx)
        self.index_features = {self.attrs.index(v) for v, _ in self.pointers}
        self.facing, self.ahead = self._frame(model)
        agent = next((model.variables[i].label.split(".")[0] for i in self.pos if i is not None), None)
        self.noop_features = [k for k, i in enumerate(self.attrs)
                              if model.variables[i].label.split(".")[0] == agent
                              and i != self.facing and k not in self.index_features]
        self.noop_features += range(len(self.attrs), len(self.attrs) + len(self.pointers))
        # The cells around the agent in its own frame: (ahead, up, right).
        self.offsets = [(da, dy, dr) for dy in (-1, 0, 1) for da in range(-radius, radius + 1)
                        for dr in range(-radius, radius + 1) if abs(da) + abs(dr) <= radius]
        self.objects = self._objects(model)
        self.plane = [(da, dr) for da, dy, dr in self.offsets if dy == 0]
        # which object stands in each cell of the plane around the agent: part of what a
        # no-op is remembered by (an action on an object happens only where it stands)
        first_object = len(self.attrs) + len(self.pointers) + len(self.offsets)
        self.noop_features += range(first_object, first_object + (len(self.plane) if self.objects else 0))
        self.own = frozenset(self.noop_features)  # the agent, what it holds, who stands next to it
        self.area = g.width * g.depth
        self.span = {v.index: v.hi - v.lo for v in model.variables}
        self.cache = {}          # state -> its feature tuple
        self.exact = {}          # (action, features) -> effect
        self.examples = {}       # action -> {effect: [feature tuples]}
        self.terms = {}          # (action, effect) -> [term: list of allowed value sets per feature]
        self.general = {}        # (action, effect) -> the same terms with the fewest constraints
        self.noops = set()       # (action, what a no-op is remembered by: see _noop_key) where nothing happened
        self.noop_examples = []  # (action, features) of every no-op seen
        self.reach = set()       # features of the cells any action has changed or moved into
        self.predicted = {}      # action -> {features: effect or None}, until that action's knowledge changes
        self.failure_index = {}  # action -> {(effect, term): failure examples projected on its features}
        self.fallback = Tabular(model, m)
        self.wrong = set()       # (state, action) where a generalised prediction failed
        self.answers = {}        # action -> {state: predicted next state}, until that action's knowledge changes
        self.seen = {}           # (action, effect) -> [(feature of its locus, values seen in its examples)]

    @staticmethod
    def _objects(model):
        """Other objects that stand in a cell (a domain's creatures, ...), each as a function of the
        state giving its (x, z): read from the state where it moves, else where the
        dungeon put it. Their cells are perceived like the grid's (`features`)."""
        by_label = {v.label: v for v in model.variables}
        out = []
        for name, x, z in (model.display or {}).get("objects", ()):
            vx, vz = by_label.get(f"{name}.x"), by_label.get(f"{name}.z")
            if vx is not None and vz is not None:
                out.append(lambda s, vx=vx, vz=vz: (s[vx.index] + vx.lo, s[vz.index] + vz.lo))
            elif x is not None and z is not None:
                out.append(lambda s, at=(x, z): at)
        return out

    @staticmethod
    def _frame(model):
        """The agent's own frame, when the domain declares which attribute is its facing and
        names that attribute's values by compass direction (spec section 2): the state index
        of the facing and, per stored value, the (dx, dz) ahead. Without it the frame is the
        world's (ahead = +x, right = +z), and what is learned facing one way is not reused
        facing another."""
        facing = (model.display or {}).get("facing")
        if not facing or facing.get("index") is None:
            return None, {}
        ahead = {value - facing["lo"]: COMPASS.get(str(name)) for value, name in facing["names"].items()}
        if not ahead or None in ahead.values():
            return None, {}
        return facing["index"], ahead

    def _axes(self, s):
        """(dx, dz) of the agent's ahead in state s."""
        return (1, 0) if self.facing is None else self.ahead.get(s[self.facing], (1, 0))

    @staticmethod
    def _to_world(axes, da, dr):
        fx, fz = axes
        return da * fx - dr * fz, da * fz + dr * fx

    @staticmethod
    def _to_frame(axes, dx, dz):
        fx, fz = axes
        return dx * fx + dz * fz, dz * fx - dx * fz

    @staticmethod
    def _pointers(model, skip):
        """Integer attributes that index a list of objects (a selected slot), each with the
        attributes of the object it points to: [(index variable, [variable per value])].
        The object pointed to is what matters (the item held), not the number."""
        lists = {}
        for v in model.variables:
            m = re.fullmatch(r"(.+)\[(\d+)\]\.(\w+)", v.label)
            if m:
                lists.setdefault((m.group(1), m.group(3)), {})[int(m.group(2))] = v.index
        out = []
        for v in model.variables:
            if v.type != "int" or v.index in skip:
                continue
            for members in lists.values():
                if sorted(members) == list(range(v.lo, v.hi + 1)):
                    out.append((v.index, [members[k] for k in range(v.lo, v.hi + 1)]))
        return out

    def features(self, s):
        f = self.cache.get(s)
        if f is None:
            x, y, z = self.model.agent_position(s)
            cell, axes, world = self.model.grid.cell, self._axes(s), self._to_world
            around = []
            for da, dy, dr in self.offsets:
                dx, dz = world(axes, da, dr)
                around.append(cell(s, x + dx, y + dy, z + dz))
            if self.objects:
                standing = {where(s): k + 1 for k, where in reversed(list(enumerate(self.objects)))}
                for da, dr in self.plane:
                    dx, dz = world(axes, da, dr)
                    around.append(standing.get((x + dx, z + dz), 0))
            f = (tuple(s[i] for i in self.attrs) + tuple(s[members[s[i]]] for i, members in self.pointers)
                 + tuple(around))
            self.cache[s] = f
        return f

    def effect(self, s, n):
        """What `n` changed in `s`, relative to the agent: integer attributes moved on by a
        (cyclic) step, other attributes set, position moved and cells changed in its frame."""
        sets = tuple((i, "add", (n[i] - s[i]) % self.cyclic[i]) if i in self.cyclic else (i, "set", n[i])
                     for i in self.attrs if s[i] != n[i])
        delta = [(n[i] - s[i]) if i is not None else 0 for i in self.pos]
        axes = self._axes(s)
        da, dr = self._to_frame(axes, delta[0], delta[2])
        x, y, z = self.model.agent_position(s)
        g = self.model.grid
        cells = []
        for i in range(g.base, len(s)):
            if s[i] != n[i]:
                layer, rest = divmod(i - g.base, self.area)
                cz, cx = divmod(rest, g.width)
                ca, cr = self._to_frame(axes, cx - x, cz - z)
                cells.append((ca, g.layers[layer] - y, cr, n[i]))
        return sets, (da, delta[1], dr), tuple(cells)

    def apply_effect(self, s, eff):
        sets, (da, dy, dr), cells = eff
        n = bytearray(s)
        for i, op, v in sets:
            n[i] = (s[i] + v) % self.cyclic[i] if op == "add" else v
        axes = self._axes(s)
        dx, dz = self._to_world(axes, da, dr)
        for i, d in zip(self.pos, (dx, dy, dz)):
            if d:
                if i is None:
                    return None  # a static axis cannot move: the caller falls back
                v = s[i] + d
                if not 0 <= v <= self.span[i]:
                    return None  # off the map: not a state; the caller falls back
                n[i] = v
        if cells:
            g = self.model.grid
            x, y, z = self.model.agent_position(s)
            for ca, cy, cr, v in cells:
                cdx, cdz = self._to_world(axes, ca, cr)
                cx, cy, cz = x + cdx, y + cy, z + cdz
                if cy not in g.layers or not (0 <= cx < g.width and 0 <= cz < g.depth):
                    return None
                n[g.base + g.layers.index(cy) * self.area + cz * g.width + cx] = v
        return bytes(n)

    # -- terms ---------------------------------------------------------------------------
    NOTHING = ((), (0, 0, 0), ())

    def _is_noop(self, eff):
        return eff == self.NOTHING

    def _noop_key(self, f):
        """What a no-op is remembered by: the agent's own attributes but its facing (it
        sees in its own frame) and index ones (the item held counts, not the slot), what
        its index attributes point to, and the cells where actions have been seen to act
        (typically the column ahead of it). Where an action once did nothing,
        it is expected to do nothing again wherever all of these are the same."""
        if not self.reach:  # no action seen acting on a cell yet: every cell may matter
            return tuple(v for i, v in enumerate(f) if i not in self.index_features)
        return tuple(f[i] for i in self.noop_features) + tuple(f[i] for i in sorted(self.reach))

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
        locus = self._locus(eff)
        preferred = locus | self.own
        self.general[(a, eff)] = [tuple((i, allowed) for i, allowed in enumerate(self._simplest(t, others, preferred))
                                        if allowed is not None) for t in terms]
        self.seen[(a, eff)] = [(i, {f[i] for f in mine}) for i in sorted(locus)]

    def _locus(self, eff):
        """The features an effect acts on: the attributes it changes, and the cells in the
        columns it changes or moves into. Its condition is trusted only where these look as
        they did in its examples (a block placed on one kind of floor is not expected to fill another),
        and they are preferred when two constraints explain the data equally well."""
        sets, (da, _, dr), cells = eff
        columns = {(ca, cr) for ca, _, cr, _ in cells} | ({(da, dr)} if (da, dr) != (0, 0) else set())
        first = len(self.attrs) + len(self.pointers)
        return ({self.attrs.index(i) for i, _, _ in sets}
                | {first + k for k, (oa, _, orr) in enumerate(self.offsets) if (oa, orr) in columns})

    def _cells_acted_on(self, eff):
        """The features of the very cells an effect changes or moves the agent into (for a
        move, its whole column): narrower than the locus, whose whole columns are there to
        guard an effect's own condition, not to tell which surroundings a failure shares."""
        _, (da, _, dr), cells = eff
        changed = {(ca, cy, cr) for ca, cy, cr, _ in cells}
        first = len(self.attrs) + len(self.pointers)
        return {first + k for k, (oa, oy, orr) in enumerate(self.offsets)
                if (oa, oy, orr) in changed or (oa, orr) == (da, dr) != (0, 0)}

    @staticmethod
    def _simplest(term, others, preferred=frozenset()):
        """The fewest of a term's constraints that still rule out every example of the
        other effects (greedy set cover): the most general condition the data allow, so
        that one turn seen facing north is expected wherever the agent faces north. It
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
        f, eff = self.features(s), self.effect(s, n)
        if self.exact.get((a, f)) == eff:
            return
        self.exact[(a, f)] = eff
        by_effect = self.examples.setdefault(a, {})
        by_effect.setdefault(eff, []).append(f)
        if self._is_noop(eff):
            self.noop_examples.append((a, f))
            self.noops.add((a, self._noop_key(f)))
        elif not self._locus(eff) - set(range(len(self.attrs))) <= self.reach:
            self.reach |= self._locus(eff) - set(range(len(self.attrs)))
            self.predicted.clear()  # no-ops of every action are remembered by more now
            self.answers.clear()
        if not self._is_noop(eff):
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
            out = self.NOTHING
        known[f] = out
        return out

    def _familiar(self, f, a, eff):
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
            rest = tuple(sorted(self._cells_acted_on(eff) - {i for i, _ in term}))
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
            fixed = tuple(sorted({i for i, _ in term} | self._locus(eff)))
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
        f = self.features(s)
        eff = self.exact.get((a, f))
        if eff is None:
            eff = self._generalised(f, a)
        if eff is None:
            return self.fallback.predict(s, a)
        if self._is_noop(eff):
            return s
        return self.apply_effect(s, eff) or self.fallback.predict(s, a)


LEARNERS = {"tabular": Tabular, "oo": ObjectOriented}
