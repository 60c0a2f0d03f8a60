"""A dungeon seen as a route-giver sees it: rooms, the doors between them, and what can be moved.

People describe a route by the map ("through the first door, then the second", "back to
the room you started in"), so the route reader (route.py) needs the map's rooms and
doors, not its cells. Everything here is read from the compiled dungeon and its
candidate tasks, never from a list of room names:

- A *room* is an object that a position-dependent atom about the agent takes as its
  other argument (`agentInRoom(agent, green)`: `green`); the positions where that atom
  holds are the room's. Its words are its name and its objects' text fields (a colour).
- The agent's positions are those it can walk to from the start: a breadth-first search
  over the actions that change only the agent's own attributes (no block mined or
  placed), projected to the agent's position.
- A *door* is a connected group of walkable positions in no room that touches two rooms
  or more (a gap in a wall); two rooms whose positions touch directly are neighbours
  without a door.
- A *thing* is an argument of an atom that also takes a room and is not the agent
  (`blockInRoom(chair, red)`: `chair`), in exactly one room at the start: something that
  can be taken from room to room. Its words are its name's parts.
- For commands given as steps (steps.py), the *cells* (`Cells`): the walkable positions
  and their rooms, and the step each of the agent's facings takes, found by setting the
  facing in a reachable state and trying the actions; a thing named by a grid value in one
  cell is where it can be pushed from.
"""
from __future__ import annotations

import re
from collections import deque
from dataclasses import dataclass, field

WALK_STATES = 50000     # states the walk search may visit (a large map's rooms are still found)
GRID_CELLS = 200000     # a larger grid is not searched for the things a command may push


@dataclass(frozen=True)
class Door:
    index: int                  # doors are numbered by their distance from the agent's start
    rooms: frozenset            # the rooms it joins
    position: tuple             # one position of it (the one nearest the start)


@dataclass(frozen=True)
class Cells:
    """The map as someone giving steps sees it: which positions the agent can stand on and
    their rooms, where it starts, the step each compass direction takes, and the positions
    of the things it can push."""
    room: dict                  # position -> its room (None: in no room, e.g. a door): where one may stand
    start: tuple                # the agent's position at the start
    compass: dict               # facing name (north, ...) -> the position step of moving while facing it
    facing: str | None          # the agent's facing at the start
    things: dict                # thing -> its position at the start (things found in one cell only)
    axes: tuple = ()            # ((state index, axis name, low), ...) of the agent's position
    turn: tuple = ()            # (state index, low, {value: facing name}) of the agent's facing

    def at(self, model, state: bytes) -> tuple:
        """(the agent's position, its facing, {thing: position}) in `state`."""
        if state == model.initial or not self.axes:
            return self.start, self.facing, self.things
        index, lo, names = self.turn
        return (tuple(state[i] for i, _, _ in self.axes), names.get(state[index] + lo),
                _thing_positions(model, state, self.things, self.axes))


@dataclass
class World:
    rooms: dict                 # room name -> frozenset of its words
    room_atoms: dict            # room name -> the atom text "the agent is in that room"
    things: dict                # thing name -> (its words, {room: atom text "the thing is in that room"})
    doors: list                 # [Door], nearest the start first
    neighbours: dict = field(default_factory=dict)   # room -> {room: [door indices] ([] : open)}
    distance: dict = field(default_factory=dict)     # room -> walk steps from the start position to it
    map: Cells | None = None    # its cells, for commands given as steps (steps.py)

    def words(self) -> frozenset:
        """Every word that names something of this world (a room or a thing)."""
        if not hasattr(self, "_words"):
            self._words = frozenset({w for ws in self.rooms.values() for w in ws} |
                                    {w for ws, _ in self.things.values() for w in ws})
        return self._words

    def doors_of(self, room: str) -> list:
        return [d for d in self.doors if room in d.rooms]


def name_words(name: str) -> set:
    return {w for w in re.split(r"[^a-z0-9]+", str(name).lower()) if w}


def world_of(space) -> World | None:
    """The world of a TaskSpace, read once per space."""
    if not hasattr(space, "_world"):
        space._world = read_world(space)
    return space._world


def read_world(space) -> World | None:
    """The world of a TaskSpace (its compiled model and atoms), or None when the dungeon
    has no rooms for a route to cross."""
    dungeon = space.predicates.dungeon
    agent = dungeon.agent_name
    objects = dungeon.objects
    room_atoms = {}
    for atom in space.atoms:
        if atom not in space.changeable or agent not in atom.args or len(atom.args) != 2:
            continue
        other = atom.args[1] if atom.args[0] == agent else atom.args[0]
        if other in objects and other != agent:
            room_atoms.setdefault(other, atom)
    if len(room_atoms) < 2:
        return None
    rooms = {}
    for name in room_atoms:
        words = name_words(name)
        for value in objects[name][1].values():
            if isinstance(value, str):
                words |= name_words(value)
        rooms[name] = frozenset(words)
    start = space.model.initial
    things = {}
    for atom in space.atoms:
        if len(atom.args) != 2 or agent in atom.args:
            continue
        room = next((a for a in atom.args if a in room_atoms), None)
        thing = next((a for a in atom.args if a not in room_atoms), None)
        if room is None or thing is None:
            continue
        things.setdefault(thing, {})[room] = atom
    things = {t: by_room for t, by_room in things.items() if sum(space.holds(a, start) for a in by_room.values()) == 1}
    thing_rooms = {t: next(r for r, a in by_room.items() if space.holds(a, start)) for t, by_room in things.items()}
    things = {t: (frozenset(name_words(t)), {r: a.text for r, a in by_room.items()}) for t, by_room in things.items()}
    walk = _walk(space)
    room_of = {p: next((r for r, a in room_atoms.items() if space.holds(a, s)), None) for p, s in walk.states.items()}
    doors, neighbours = _doors(walk, room_of, set(room_atoms))
    distance = {}
    for p, d in walk.steps.items():
        r = room_of.get(p)
        if r is not None and d < distance.get(r, 1 << 30):
            distance[r] = d
    return World({r: rooms[r] for r in room_atoms}, {r: a.text for r, a in room_atoms.items()}, things,
                 doors, neighbours, distance, _cells(space, walk, room_of, thing_rooms))


def _cells(space, walk: _Walk, room_of: dict, thing_rooms: dict) -> Cells | None:
    """The map's cells (Cells), or None when moving does not follow a facing with names.
    A thing's cell counts as one the agent may stand on (once the thing is pushed on), in
    the thing's room."""
    from ..compiler import pipeline as c
    dungeon = space.predicates.dungeon
    layout = space.predicates._layout
    model = space.model
    _, adef, slot = c.facing_slot(dungeon, layout) or (None, None, None)
    if slot is None or not adef.names:
        return None
    position, _, variables = c._position(dungeon, layout)
    axes = [(var.attr, dyn) for var, dyn in zip(variables, position) if dyn is not None]
    compass = {}
    for name, value in adef.names.items():
        for s in list(walk.states.values())[:64]:
            t = _moved(model, s[:slot.index] + bytes([value - slot.lo]) + s[slot.index + 1:], [i for _, (i, _) in axes])
            if t is not None:
                compass[name] = t
                break
    if len(compass) < 2:
        return None
    start = model.initial
    facing = next((n for n, v in adef.names.items() if v - slot.lo == start[slot.index]), None)
    axes = tuple((i, name, lo) for name, (i, lo) in axes)
    things = _thing_positions(model, start, thing_rooms, axes)
    rooms = dict(room_of)
    rooms.update({p: thing_rooms[t] for t, p in things.items()})
    return Cells(rooms, tuple(start[i] for i, _, _ in axes), compass, facing, things, axes,
                 (slot.index, slot.lo, {v: n for n, v in adef.names.items()}))


def _moved(model, state: bytes, index: list) -> tuple | None:
    """The position step of the first action that moves the agent one cell and changes
    nothing else but its position, or None."""
    for i in range(len(model.action_names)):
        t = model.apply(i, state)
        if t is None or model.is_failure(t):
            continue
        step = tuple(t[k] - state[k] for k in index)
        if sum(map(abs, step)) == 1 and all(t[k] == state[k] for k in range(len(state)) if k not in index):
            return step
    return None


def _thing_positions(model, state: bytes, things, axes: tuple) -> dict:
    """{thing: position} in `state` for each of `things` named by a grid value found in
    exactly one cell, in the agent's position coordinates (the same axis names)."""
    grid = model.grid
    if grid.width * grid.depth * grid.height > GRID_CELLS:
        return {}
    names = {n: v for v, n in enumerate(grid.value_names)}
    out = {}
    for thing in things:
        if thing not in names:
            continue
        cells = [(x, y, z) for y in range(grid.height) for z in range(grid.depth) for x in range(grid.width)
                 if grid.cell(state, x, y, z) == names[thing]]
        if len(cells) != 1:
            continue
        where = dict(zip("xyz", cells[0]))
        if all(a in where for _, a, _ in axes):
            out[thing] = tuple(where[a] - lo for _, a, lo in axes)
    return out


@dataclass
class _Walk:
    states: dict      # position -> one state with the agent there
    edges: dict       # position -> set of positions one step away
    steps: dict       # position -> fewest steps from the start


def _walk(space) -> _Walk:
    model = space.model
    from ..compiler import pipeline as c
    position, _, _ = c._position(space.predicates.dungeon, space.predicates._layout)
    index = [dyn[0] for dyn in position if dyn is not None]
    agent_prefix = space.predicates.dungeon.agent_name + "."
    fixed = [v.index for v in model.variables if not v.label.startswith(agent_prefix)]
    base = model.grid.base

    def where(s: bytes) -> tuple:
        return tuple(s[i] for i in index)

    start = model.initial
    seen = {start}
    queue = deque([start])
    walk = _Walk({where(start): start}, {}, {where(start): 0})
    n = len(model.action_names)
    while queue and len(seen) < WALK_STATES:
        s = queue.popleft()
        here = where(s)
        for i in range(n):
            t = model.apply(i, s)
            if t is None or t in seen or t[base:] != s[base:] or any(t[k] != s[k] for k in fixed) \
                    or model.is_failure(t):
                continue
            seen.add(t)
            queue.append(t)
            there = where(t)
            if there != here:
                walk.edges.setdefault(here, set()).add(there)
                walk.edges.setdefault(there, set()).add(here)
                if there not in walk.states:
                    walk.states[there] = t
                    walk.steps[there] = walk.steps[here] + 1
    return walk


def _doors(walk: _Walk, room_of: dict, rooms: set) -> tuple[list, dict]:
    """The doors (groups of walkable positions in no room joining two rooms or more), nearest
    the start first, and which rooms neighbour which through which doors."""
    neighbours = {r: {} for r in rooms}
    for p, qs in walk.edges.items():
        for q in qs:
            a, b = room_of.get(p), room_of.get(q)
            if a is not None and b is not None and a != b:
                neighbours[a].setdefault(b, [])
    seen, groups = set(), []
    for p in sorted(walk.states, key=lambda p: (walk.steps[p], p)):
        if room_of.get(p) is not None or p in seen:
            continue
        group, touches, queue = [], set(), deque([p])
        seen.add(p)
        while queue:
            q = queue.popleft()
            group.append(q)
            for r in walk.edges.get(q, ()):
                if room_of.get(r) is not None:
                    touches.add(room_of[r])
                elif r not in seen:
                    seen.add(r)
                    queue.append(r)
        if len(touches) >= 2:
            groups.append((min(walk.steps[q] for q in group), min(group, key=lambda q: (walk.steps[q], q)),
                           frozenset(touches)))
    doors = []
    for k, (_, position, touches) in enumerate(sorted(groups, key=lambda g: (g[0], g[1]))):
        doors.append(Door(k, touches, position))
        for a in touches:
            for b in touches:
                if a != b:
                    neighbours[a].setdefault(b, []).append(k)
    return doors, neighbours
