"""A command read as a route through the dungeon's rooms and doors, and where it ends.

"Go through the first door, then the second", "push the chair back to the room you
started in", "go to the pink room" (in a dungeon whose rooms are red, green and blue):
what such a command asks follows from the map, not from its words alone. The reader
walks the route over the world's rooms and doors (world.py), from where the agent and
the things start, and says where the agent and each thing end.

The command is cut into steps at words such as "then", "and" and commas; each step's
mentions are taken in order: a room (by a name or a text field of the dungeon's room
objects: "green"; "the next room", "the other room"; "the room you started in", "the
original room"; "back"; or a word the dungeon does not know before "room": "the pink
room", a room not named otherwise in the command, the same room each time the word comes
back), a door ("the door", "the other door", "the first door", "the green room door":
going "to" a door stands in it, going "through" one ends on its other side), or a thing
("the chair", "the object", "it"): going to it, and carrying it along when a verb of
carrying comes with it ("bring", "push", "take"). The words are in `route_words.yaml`,
no room or thing name among them. Where the words leave a choice (which of two doors;
which room "the pink room" is), the reader follows every choice with an equal share, and
its answer is a distribution over outcomes; route_model.py learns which tasks such
outcomes go with. A command that names directions ("go down four, left five, up two") is
walked on the map's cells instead (steps.py). A command with no room, door, thing, "back"
or step in it is no route: the reader abstains (None).
"""
from __future__ import annotations

import functools
import re
from dataclasses import dataclass, replace
from pathlib import Path

from . import steps as step_list
from .text import Speller
from .world import World, world_of

WORDS = Path(__file__).with_name("route_words.yaml")
BRANCHES = 64          # readings followed at once (the most likely kept)
TOKEN = re.compile(r"[a-z0-9]+|[,.;!?/]")
SPELLED = 5            # shorter words are taken as typed ("pink" is not a misspelt "pick")


@functools.lru_cache(maxsize=1)
def lexicon() -> dict:
    """{class: frozenset of words} from route_words.yaml."""
    import yaml
    data = yaml.safe_load(WORDS.read_text(encoding="utf-8"))
    return {k: frozenset(str(w) for w in v) for k, v in data.items()}


@dataclass(frozen=True)
class Scene:
    """A world and where its agent and things are at the start of a command."""
    world: World
    agent: str | None              # the agent's room at the start (None: in no room)
    things: tuple                  # ((thing, its room at the start), ...)
    cells: tuple | None = None     # (position, facing, {thing: position}) on the map (world.Cells.at)


def scene_of(space, state: bytes | None = None) -> Scene | None:
    """The scene of a TaskSpace's dungeon from `state` (default: its start), or None when
    it has no rooms."""
    return scene(world_of(space), space, space.model.initial if state is None else state)


def scene(world: World | None, space, state: bytes) -> Scene | None:
    """The scene of `world` (world.read_world(space)) from `state`: which room's atom holds."""
    if world is None:
        return None
    agent = next((r for r, a in world.room_atoms.items() if space.predicates.predicate(a)(state)), None)
    things = tuple((t, next((r for r, a in by_room.items() if space.predicates.predicate(a)(state)), None))
                   for t, (_, by_room) in sorted(world.things.items()))
    return Scene(world, agent, things, world.map.at(space.model, state) if world.map is not None else None)


@dataclass(frozen=True)
class Outcome:
    """Where a route ends: the agent's room, whether it ever left its start room; each
    thing's room, whether it was taken elsewhere; the things the agent ends with; whether
    the command gave steps (steps.py) rather than rooms and doors."""
    agent: str | None
    agent_moved: bool
    things: tuple                  # ((thing, room at the end, moved), ...)
    carried: frozenset
    walked: bool = False


@dataclass(frozen=True)
class _State:
    room: str | None               # the agent's room (when in a door: the side it stands on)
    door: int | None               # the door it stands in, or None
    history: tuple                 # rooms it has been in, in order (the start first)
    doors_used: tuple
    carrying: frozenset
    things: tuple                  # ((thing, room or None), ...)
    moved: frozenset               # things taken elsewhere
    bound: tuple                   # ((unknown word, room), ...)


@dataclass(frozen=True)
class _Mention:
    kind: str                      # "room", "door", "thing", "back"
    how: str                       # room: named/start/back/other/same/word/plain; door: named/other/first/same/plain
    value: object = None           # the room, thing, word or rooms named
    through: bool = False          # a door passed through (not stood in)
    locates: bool = False          # "the chair in the red room": where the thing is, no way to go


def tokens(command: str, world: World) -> list[str]:
    """The command's words and punctuation, spelling-corrected against the route words and
    the world's names."""
    known = set().union(*lexicon().values()) | world.words()
    speller = _speller(frozenset(known))
    return [speller.correct(t) if t[0].isalpha() and len(t) >= SPELLED else t for t in TOKEN.findall(command.lower())]


@functools.lru_cache(maxsize=32)
def _speller(known: frozenset) -> Speller:
    return Speller({w: 2 for w in known})


def steps(command: str, world: World) -> list[tuple[set, list]]:
    """The route's steps: [(the step's verb classes, its mentions in order)]."""
    return _StepReader(tokens(command, world), world).read()


class _StepReader:
    """Reads a command's words left to right into steps. Each `_...` method reads the
    word at `i` as one kind of mention and returns where reading goes on (None: the word
    is not of its kind)."""

    def __init__(self, toks: list, world: World):
        self.toks, self.world, self.lex = toks, world, lexicon()
        self.room_of_word = {}
        for room, ws in world.rooms.items():
            for w in ws:
                self.room_of_word.setdefault(w, room)
        self.thing_of_word = {w: t for t, (ws, _) in world.things.items() for w in ws}
        self.out, self.verbs, self.mentions = [], set(), []
        self.earlier = []          # the last mention of the steps before
        self.named_thing = False

    def read(self) -> list[tuple[set, list]]:
        i = 0
        while i < len(self.toks):
            i = self._word(i)
        self._close()
        return self.out

    def _close(self):
        self.earlier = self.mentions[-1:] or self.earlier
        if self.verbs or self.mentions:
            self.out.append((self.verbs, self.mentions))
        self.verbs, self.mentions = set(), []

    def _near(self, i: int, span: int, *classes: str) -> bool:
        """Whether a word of one of `classes` (or a room's name, for "name") is among the
        `span` words after `i`."""
        words = self.toks[i + 1:i + 1 + span]
        return any(w in self.room_of_word if c == "name" else w in self.lex[c] for w in words for c in classes)

    def _word(self, i: int) -> int:
        toks, lex, t = self.toks, self.lex, self.toks[i]
        nxt = toks[i + 1] if i + 1 < len(toks) else ""
        if t in lex["then"] and not (t in lex["other"] and (nxt in lex["door"] or nxt in lex["room"])):
            self._close()
            return i + 1
        if t in lex["go"] and any(m.kind in ("room", "door") and not m.locates for m in self.mentions):
            self._close()
        for cls in ("carry", "release", "through", "leave", "back", "into"):
            if t in lex[cls]:
                self.verbs.add(cls)
        if t in self.room_of_word:
            return self._named_room(i)
        j = self._other(i)
        if j is not None:
            return j
        if t in lex["door"] and not (t in lex["leave"] and nxt not in ("door", "doorway")):
            return self._door(i)
        if t in lex["room"]:
            how = _modifier(toks, i, lex, door=False)
            self.mentions.append(_Mention("room", how, toks[i - 1] if how == "word" else None,
                                          locates="release" not in self.verbs and
                                          _locates(toks, i - (how == "word"), self.mentions, lex)))
        elif self._thing(i):
            self.named_thing = True
            self.mentions.append(_Mention("thing", "named", self.thing_of_word.get(t) or sorted(self.world.things)[0]))
        elif t in lex["back"] and not self._near(i, 4, "room", "door", "name"):
            self.mentions.append(_Mention("back", "back"))
        return i + 1

    def _named_room(self, i: int) -> int:
        """A room by its name ("the green room"), several before a door ("the red/green
        door"), or the colour of a thing ("the red chair": no mention here)."""
        toks, lex, n = self.toks, self.lex, len(self.toks)
        named, j = [self.room_of_word[toks[i]]], i + 1
        while j < n and (toks[j] in self.room_of_word or toks[j] in ("/", "and", "room")) and \
                any(toks[k] in lex["door"] for k in range(j, min(n, j + 3))):
            if toks[j] in self.room_of_word:
                named.append(self.room_of_word[toks[j]])
            j += 1
        if j < n and toks[j] in lex["room"]:
            j += 1
        if j < n and toks[j] in lex["door"]:
            self.mentions.append(_Mention("door", "named", frozenset(named), _through(self.verbs)))
            return j + 1
        if j < n and toks[j] in self.thing_of_word:
            return i + 1
        self.mentions.append(_Mention("room", "named", named[-1], locates="release" not in self.verbs and
                                      _locates(toks, i, self.mentions, lex)))
        return j

    def _other(self, i: int) -> int | None:
        """ "The other" with no door or room after it: another of the last mention's kind
        ("through the first door, then the second")."""
        if self.toks[i] not in self.lex["other"] or not (self.mentions or self.earlier) or \
                self._near(i, 2, "door", "room", "name", "then"):
            return None
        last = (self.mentions or self.earlier)[-1]
        if last.kind not in ("door", "room"):
            return None
        self.mentions.append(_Mention(last.kind, "other", None, last.through))
        return i + 1

    def _door(self, i: int) -> int:
        """A door: "the door to the green room" (the room is a mention too: the door leads
        there), or "the first door", "the other door", "the door"."""
        toks = self.toks
        rest = [w for w in toks[i + 1:i + 6] if w not in ("the", "a", "an", "that", "which", "leads", "leading",
                                                           "goes", "going")]
        if len(rest) >= 2 and rest[0] in ("of", "to", "into", "for") and rest[1] in self.room_of_word:
            self.mentions.append(_Mention("door", "named", frozenset({self.room_of_word[rest[1]]}),
                                          _through(self.verbs)))
            return toks.index(rest[1], i + 1)
        self.mentions.append(_Mention("door", _modifier(toks, i, self.lex, door=True), None, _through(self.verbs)))
        return i + 1

    def _thing(self, i: int) -> bool:
        """Whether the word names a thing: its name, "the object" or "it" (once a thing
        was named), or the unknown word after a verb of handling."""
        t, things = self.toks[i], self.world.things
        return t in self.thing_of_word or (t in self.lex["thing"] and bool(things) and
                                           (t != "it" or self.named_thing)) or \
            bool(things and _handled(self.toks, i, self.lex, self.world))


def _handled(toks: list, i: int, lex: dict, world: World) -> bool:
    """Whether the word at `i` is the first word the dungeon does not know after a verb of
    handling ("push the bag": the thing, by another name)."""
    t = toks[i]
    if not t.isalpha() or any(t in v for v in lex.values()) or t in world.words():
        return False
    for k in range(i - 1, max(-1, i - 4), -1):
        if toks[k] in lex["handle"]:
            return True
        if toks[k] not in ("the", "a", "an", "up", "that", "this") and (any(toks[k] in v for v in lex.values()) or
                                                                     toks[k] in world.words() or not toks[k].isalpha()):
            return False
    return False


def _locates(toks: list, i: int, mentions: list, lex: dict) -> bool:
    """Whether the room word at `i` says where the thing just named is ("the chair in the
    pink room", "the object from the red room")."""
    before = [t for t in toks[max(0, i - 3):i] if t not in ("the", "a", "an")]
    return bool(mentions) and mentions[-1].kind == "thing" and bool(before) and before[-1] in ("in", "from", "of")


def _through(verbs: set) -> bool:
    return "through" in verbs or "leave" in verbs


def _modifier(toks: list, i: int, lex: dict, door: bool) -> str:
    """What the words just before a door or room word say about which one it is."""
    before = [t for t in toks[max(0, i - 3):i] if t not in ("the", "a", "an")]
    last = before[-1] if before else ""
    for t in reversed(before):
        if t in lex["then"]:
            break
        if (t in lex["start"] and not (door and t == "first")) or (not door and t == "this"):
            return "start"
        if door and t == "first":
            return "first"
        if t in lex["other"]:
            return "other"
        if t in lex["same"]:
            return "same"
        if t in lex["back"]:
            return "back"
    if not door and last and last.isalpha() and not any(last in v for v in lex.values()):
        return "word"
    for t in toks[i + 1:i + 5]:      # "the room you started in", "the door you came through"
        if t in lex["then"] or t in lex["door"] or t in lex["room"]:
            break
        if t in lex["start"] and t != "first":
            return "start"
        if t in lex["back"] or t in ("came", "come"):
            return "same" if door else "back"
    return "plain"


def read(command: str, scene_: Scene | None, beta: float = step_list.BETAS[1]) -> list[tuple[float, Outcome]] | None:
    """The outcomes of the route the command describes, with their shares (summing to 1),
    or None when the command names no room, door, thing, way back or step. A command that
    names two directions or more, or one with a count ("go down four, left five"), or a
    step and no room, is walked on the map (steps.py; `beta` weighs its faults)."""
    if scene_ is None:
        return None
    world = scene_.world
    route = steps(command, world)
    said = step_list.moves(command, world.map.compass) if world.map is not None else []
    walks = [m for m in said if not m.way.startswith("turn-")]
    directed = [m for m in walks if m.way != "ahead"]      # a direction said, not only a count of steps
    if walks and (len(directed) >= 2 or any(m.count is not None for m in directed) or not any(m for _, m in route)):
        return _walked(said, scene_, beta)
    if not any(m for _, m in route):
        return None
    named = {m.value for _, ms in route for m in ms if m.kind == "room" and m.how == "named"}
    start = _State(scene_.agent, None, (scene_.agent,), (), frozenset(), scene_.things, frozenset(), ())
    branches = {start: 1.0}
    for verbs, mentions in route:
        for m in mentions:
            branches = _spread(branches, lambda s: _apply(s, m, verbs, world, named))
        if "leave" in verbs and not any(m.kind in ("room", "door") for m in mentions):
            branches = _spread(branches, lambda s: _door(s, _Mention("door", "plain", None, True), world))
        if "release" in verbs and any(m.kind == "thing" for m in mentions):
            branches = {replace(s, carrying=frozenset()): w for s, w in branches.items()}
        # a thing carried into another room is left there once the step ends: people rarely
        # say "drop it" ("get the chair, go to the blue room, go to the green room")
        branches = _merge((_delivered(s), w) for s, w in branches.items())
    ends: dict = {}
    for s, w in branches.items():
        for t, share in _settle(s, world):
            o = _outcome(t, scene_)
            ends[o] = ends.get(o, 0.0) + w * share
    total = sum(ends.values())
    return sorted(((w / total, o) for o, w in ends.items()), key=lambda x: -x[0])


def _walked(said: list, scene_: Scene, beta: float) -> list[tuple[float, Outcome]] | None:
    """The outcomes of a command's moves (steps.moves) walked on the map (steps.py)."""
    ends = step_list.read(said, scene_.world.map, scene_.cells, beta)
    if ends is None:
        return None
    out = []
    for share, e in ends:
        pushed = dict(e.things)
        things = tuple((t, pushed.get(t, r), pushed.get(t, r) != r) for t, r in scene_.things)
        out.append((share, Outcome(e.agent, e.agent_moved, things, frozenset(), walked=True)))
    return out


def _merge(pairs) -> dict:
    out: dict = {}
    for s, w in pairs:
        out[s] = out.get(s, 0.0) + w
    return out


def _delivered(s: _State) -> _State:
    if not s.carrying or s.door is not None or not (s.carrying & s.moved):
        return s
    return replace(s, carrying=frozenset())


def _spread(branches: dict, step) -> dict:
    out: dict = {}
    for s, w in branches.items():
        options = step(s)
        for t, share in options:
            out[t] = out.get(t, 0.0) + w * share
    if len(out) > BRANCHES:
        out = dict(sorted(out.items(), key=lambda x: -x[1])[:BRANCHES])
    return out


def _apply(s: _State, m: _Mention, verbs: set, world: World, named: set) -> list:
    if m.kind == "thing":
        here = dict(s.things).get(m.value)
        s = _go(s, here, world) if here is not None and m.value not in s.carrying else s
        if "carry" in verbs:
            s = replace(s, carrying=s.carrying | {m.value})
        return [(s, 1.0)]
    if m.kind == "back":
        return [(_go(s, _previous(s), world), 1.0)]
    if m.kind == "door":
        return _door(s, m, world)
    if m.locates:
        where = next((r for t, r in s.things if t in s.carrying), None)
        if m.how == "word" and where is not None and m.value not in dict(s.bound):
            return [(replace(s, bound=s.bound + ((m.value, where),)), 1.0)]
        return [(s, 1.0)]
    return _room(s, m, world, named)


def _previous(s: _State) -> str | None:
    """The room before the one the agent is in (standing in a door: the side it came from)."""
    if s.door is not None:
        return s.room
    earlier = [r for r in s.history[:-1] if r != s.room]
    return earlier[-1] if earlier else s.room


def _room(s: _State, m: _Mention, world: World, named: set) -> list:
    rooms = sorted(world.rooms)
    if m.how == "named":
        options = [m.value]
    elif m.how == "start":
        options = [s.history[0]]
    elif m.how == "back":
        options = [_previous(s)]
    elif m.how == "same":
        options = [s.room]
    elif m.how == "word":
        bound = dict(s.bound)
        if m.value in bound:
            options = [bound[m.value]]
        else:
            taken = set(bound.values()) | named
            options = [r for r in rooms if r not in taken and r != s.room] or \
                [r for r in rooms if r != s.room] or rooms
            return [(replace(_go(s, r, world), bound=s.bound + ((m.value, r),)), 1 / len(options)) for r in options]
    else:   # other, next, plain: a room across a door from here, one not yet been in first
        here = _across(s, world) if s.door is not None else _neighbours(s.room, world)
        fresh = [r for r in here if r not in s.history]
        options = fresh or here or [r for r in rooms if r != s.room] or rooms
    return [(_go(s, r, world), 1 / len(options)) for r in options]


def _neighbours(room: str | None, world: World) -> list:
    return sorted(world.neighbours.get(room, {})) if room is not None else sorted(world.rooms)


def _across(s: _State, world: World) -> list:
    """The rooms on the other side of the door the agent stands in."""
    return sorted(world.doors[s.door].rooms - {s.room}) or [s.room]


def _door(s: _State, m: _Mention, world: World) -> list:
    doors = world.doors
    if not doors:
        return [(s, 1.0)]
    mine = [d.index for d in world.doors_of(s.room)] if s.room is not None else []
    last = s.doors_used[-1] if s.doors_used else None
    if s.door is not None and m.through and m.how in ("other", "plain"):
        options = [s.door]      # "walk to the next doorway, walk through the next doorway"
    elif m.how == "named":
        options = [d.index for d in doors if m.value <= d.rooms] or \
            [d.index for d in doors if m.value & d.rooms and (s.room in d.rooms or s.room is None)] or \
            [d.index for d in doors if m.value & d.rooms]
    elif m.how == "other":
        options = [d for d in mine if d != last] or [d.index for d in doors if d.index != last] or [last]
    elif m.how == "first":
        options = [s.doors_used[0]] if s.doors_used else mine[:1] or [0]
    elif m.how in ("same", "back"):
        options = [last] if last is not None else mine or [0]
    elif s.door is not None:
        options = [s.door]
    else:
        options = mine or [d.index for d in doors]
    out = []
    for k in options:
        share = 1 / len(options)
        t = _to_door(s, doors[k], world)
        if m.through:
            for room in sorted(doors[k].rooms - {t.room}) or [t.room]:
                out.append((_go(t, room, world), share / max(1, len(doors[k].rooms - {t.room}))))
        else:
            out.append((t, share))
    return out


def _to_door(s: _State, door, world: World) -> _State:
    """The agent walks to `door`, standing on the side it reaches first."""
    if s.door == door.index:
        return s
    side = s.room if s.room in door.rooms else None
    if side is None:
        side = min(door.rooms, key=lambda r: (_hops(s.room, r, world), r))
        s = _go(s, side, world)
    used = s.doors_used + (door.index,) if not s.doors_used or s.doors_used[-1] != door.index else s.doors_used
    return replace(s, door=door.index, doors_used=used,
                   things=tuple((t, None if t in s.carrying else r) for t, r in s.things))


def _hops(a: str | None, b: str, world: World) -> int:
    """Doors between two rooms (1 << 20 when no way leads from one to the other)."""
    if a is None or a == b:
        return 0
    path = _path(a, b, world)
    return len(path) if path and path[-1] == b else 1 << 20


def _path(a: str | None, b: str, world: World) -> list:
    """The rooms after `a` on a shortest way to `b` (breadth first over neighbours, in name
    order on a tie); just [b] when no way is known."""
    if a is None or a == b:
        return [b]
    before, frontier = {a: None}, [a]
    while frontier and b not in before:
        nxt = []
        for r in frontier:
            for q in sorted(world.neighbours.get(r, {})):
                if q not in before:
                    before[q] = r
                    nxt.append(q)
        frontier = nxt
    if b not in before:
        return [b]
    out = [b]
    while before[out[-1]] != a:
        out.append(before[out[-1]])
    return out[::-1]


def _go(s: _State, room: str | None, world: World) -> _State:
    """The agent (and what it carries) goes into `room`."""
    if room is None:
        return s
    if s.history[-1] == room and s.door is None:
        history = s.history
    else:   # the rooms passed on the way count as rooms been in ("back to the room you came from")
        history = s.history + tuple(r for r in _path(s.room, room, world) if r != s.history[-1] or s.door is not None)
    things = tuple((t, room if t in s.carrying else r) for t, r in s.things)
    moved = s.moved | {t for t, r in s.things if t in s.carrying and r != room}
    return replace(s, room=room, door=None, history=history, things=things, moved=moved)


def _settle(s: _State, world: World) -> list:
    """A route that ends in a door ends on one of its sides, either equally likely."""
    if s.door is None:
        return [(s, 1.0)]
    sides = [s.room] + _across(s, world)
    sides = list(dict.fromkeys(sides))
    return [(_go(replace(s, door=None), r, world), 1 / len(sides)) for r in sides]


def _outcome(s: _State, scene_: Scene) -> Outcome:
    start = dict(scene_.things)
    things = tuple((t, r, t in s.moved and r != start.get(t)) for t, r in s.things)
    return Outcome(s.room, any(r != s.history[0] for r in s.history), things, s.carrying)
