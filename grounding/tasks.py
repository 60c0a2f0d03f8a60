"""Candidate tasks (reward functions) of a dungeon, enumerated from its compiled domain.

A task is a conjunction of lifted propositional functions, written exactly as a goal
expression: `agentInRoom(agent, blue)`, or conjuncts sorted and joined with ` and `. The
atoms come from the domain, not from a list of Minecraft words: every propositional
function whose parameters are all objects (a named object of a class, or a grid block
named by its type, "some block of that type") or enumeration values, grounded over the
dungeon's objects and the block types present in it. An atom is kept when a bounded
breadth-first exploration from the start makes it true, or when abstract interpretation
says it may hold at some agent positions and not at others (a place to go to, perhaps
far away); `blockIsType(gold, bedrock)` or `agentHasBlock(agent, bedrock)` are dropped.
An atom already true at a start is no task from there, but an atom of where the agent is
may be a conjunct of one ("bring the chair to green and come back to blue", from blue).
"""
from __future__ import annotations

import itertools
import re
from dataclasses import dataclass
from pathlib import Path

from ..model import Model
from .predicates import Predicates

MAX_CONJUNCTS = 2
EXPLORE_STATES = 5000   # states a breadth-first exploration visits to see which atoms can become true
DISTINCT_TESTS = 300    # distinct (projected) states an atom is tested on


@dataclass(frozen=True)
class Atom:
    function: str
    args: tuple          # argument names, in parameter order
    tokens: tuple        # what the translation model sees: the function and its arguments but the agent

    @property
    def text(self) -> str:
        return f"{self.function}({', '.join(self.args)})"


@dataclass(frozen=True)
class Task:
    atoms: tuple         # sorted by text

    @property
    def text(self) -> str:
        return " and ".join(a.text for a in self.atoms)

    @property
    def tokens(self) -> tuple:
        return tuple(t for a in self.atoms for t in a.tokens)

    def __len__(self) -> int:
        return len(self.atoms)


def canonical(text: str) -> str:
    """A conjunction's canonical spelling: conjuncts normalized, sorted, joined with ` and `."""
    parts = [re.sub(r"\s+", "", p).replace(",", ", ") for p in re.split(r"\s+and\s+", text.strip())]
    return " and ".join(sorted(parts))


class TaskSpace:
    """All candidate tasks of one dungeon, and their truth on its states."""

    def __init__(self, model: Model, dungeon_ref: str | Path):
        self.model = model
        self.predicates = Predicates(model, dungeon_ref)
        P = self.predicates
        seen = _explore(model, EXPLORE_STATES)
        self._distinct = {}
        self.atoms = [a for a in _atoms(P.dungeon) if self._ever_true(a.text, seen) or
                      (P.maybe_satisfiable(a.text) and P.position_dependent(a.text))]
        self._by_text = {a.text: a for a in self.atoms}
        # where the agent is, true at the start: a conjunct of a task that has the agent
        # leave and come back ("bring the chair to green and come back to blue", from blue)
        self.changeable = {a for a in self.atoms if P.position_dependent(a.text)}

    def _ever_true(self, text: str, states: list) -> bool:
        """Whether the expression holds in one of `states`, testing each distinct part of the
        state it reads once (at most DISTINCT_TESTS of them, spread over the exploration)."""
        key = self.predicates.reads(text)
        if key not in self._distinct:
            project = self.predicates.projection(key)
            distinct = {}
            for s in states:
                distinct.setdefault(project(s), s)
            reps = list(distinct.values())
            if len(reps) > DISTINCT_TESTS:
                step = len(reps) / DISTINCT_TESTS
                reps = [reps[int(k * step)] for k in range(DISTINCT_TESTS)]
            self._distinct[key] = reps
        return any(map(self.predicates.predicate(text), self._distinct[key]))

    def holds(self, atom: Atom, state: bytes) -> bool:
        return bool(self.predicates.predicate(atom.text)(state))

    def tasks(self, start: bytes, max_conjuncts: int = MAX_CONJUNCTS) -> list[Task]:
        """Candidate tasks from `start`: atoms false there, and conjunctions of atoms that may
        hold together, at least one false there (the others may hold already: they must
        still hold at the end, "and come back here")."""
        open_atoms = [a for a in self.atoms if not self.holds(a, start)]
        kept = [a for a in self.atoms if a in self.changeable and a not in open_atoms]
        out = [Task((a,)) for a in open_atoms]
        for k in range(2, max_conjuncts + 1):
            for combo in itertools.combinations(open_atoms + kept, k):
                if all(a in kept for a in combo):
                    continue
                task = Task(tuple(sorted(combo, key=lambda a: a.text)))
                if self.predicates.maybe_satisfiable(task.text):
                    out.append(task)
        return out

    def task(self, text: str) -> Task | None:
        """The candidate spelled `text` (any conjunct order), or None if it is not one."""
        atoms = []
        for part in canonical(text).split(" and "):
            atom = self._by_text.get(part)
            if atom is None:
                return None
            atoms.append(atom)
        return Task(tuple(sorted(atoms, key=lambda a: a.text)))


def _explore(model: Model, limit: int) -> list[bytes]:
    """Up to `limit` states reachable from the start, breadth first, over every action."""
    from collections import deque
    seen = {model.initial}
    order, queue = [model.initial], deque([model.initial])
    n = len(model.action_names)
    while queue and len(order) < limit:
        s = queue.popleft()
        if model.is_failure(s):
            continue
        for i in range(n):
            t = model.apply(i, s)
            if t is not None and t not in seen:
                seen.add(t)
                order.append(t)
                queue.append(t)
    return order


def _present_values(dungeon) -> frozenset:
    """Grid value names present in the dungeon: in the map, or held by keyed objects (inventory)."""
    dom = dungeon.domain
    cdef = dom.classes[dungeon.grid_class]
    attr = next(a for a in cdef.attrs if a not in cdef.key)
    enum = dom.enums[cdef.attrs[attr].type]
    names = {enum.values[v] for v in set(dungeon.grid)}
    for objects in dungeon.keyed.values():
        for values in objects.values():
            names.update(v for v in values.values() if isinstance(v, str) and v in enum.values)
    default = cdef.attrs[attr].default
    names.discard(default)
    return frozenset(names)


def _atoms(dungeon) -> list[Atom]:
    dom = dungeon.domain
    grid_enum = dom.classes[dungeon.grid_class].attrs[
        next(a for a in dom.classes[dungeon.grid_class].attrs if a not in dom.classes[dungeon.grid_class].key)].type
    present = sorted(_present_values(dungeon))
    by_class = {}
    for name, (cls, _) in dungeon.objects.items():
        by_class.setdefault(cls, []).append(name)
    out = []
    for fname, fdef in dom.functions.items():
        choices = []
        for p in fdef.params:
            if p.type == dungeon.grid_class or p.type == grid_enum:
                choices.append(present)
            elif p.type in dom.enums:
                choices.append(list(dom.enums[p.type].values))
            elif p.type in dom.classes and not dom.classes[p.type].key:
                choices.append(by_class.get(p.type, []))
            else:
                choices = None   # an integer or another keyed class: not a task-level function
                break
        if not choices:
            continue
        for args in itertools.product(*choices):
            tokens = (fname,) + tuple(a for a in args if a != dungeon.agent_name)
            out.append(Atom(fname, tuple(args), tokens))
    return out
