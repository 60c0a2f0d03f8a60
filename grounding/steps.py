"""A command given as steps on the map -- "go down four, left five, up two" -- and where it ends.

People who give steps count cells and name directions on the map as they see it; where
the steps end (the agent's room, and the room of a thing it pushed on the way) says what
they ask. The reader walks the steps over the dungeon's cells (world.Cells: the positions
the agent can stand on, their rooms, the step each compass direction takes), pushing a
thing one cell on when the agent walks into it, as a robot pushes a chair.

People miscount ("give or take one"), some read the picture mirrored (left for right, or
the robot's south as north), and some give no count ("go down, then left"): the reader
follows every reading -- each count one more or one less, each mirrored frame, a
direction without a count as far as it goes -- and weighs each by exp(-beta x its
faults): a count off by one, a step into a wall, a mirrored axis. What it answers is a
distribution over where the steps end; route_model.py learns which tasks such ends go
with, and fits beta among `BETAS` to its training pairs.

Direction words are in route_words.yaml ("up" is north: the map drawn with north up); the
compass names are the domain's names of the agent's facing.
"""
from __future__ import annotations

import functools
import itertools
import math
import re
from dataclasses import dataclass
from pathlib import Path

from .numbers import UNITS as NUMBER

WORDS = Path(__file__).with_name("route_words.yaml")
BETAS = (1.0, 2.0, 4.0)    # the weights of one fault route_model.py chooses among
BEAM = 64                  # readings followed at once (the heaviest kept)
NEAR = 3                   # a count stands at most this many words from its direction
TOKEN = re.compile(r"[a-z]+|[0-9]+|[,.;!?]")


@functools.lru_cache(maxsize=1)
def words() -> dict:
    """The step words of route_words.yaml, tables as dicts and lists as frozensets."""
    import yaml
    data = yaml.safe_load(WORDS.read_text(encoding="utf-8"))
    keys = ("directions", "sideways", "ahead", "turn", "turns", "clockwise", "mirrors", "counts", "units",
            "count_typos", "then")
    return {k: dict(data[k]) if isinstance(data[k], dict) else
            (list(data[k]) if k in ("clockwise", "mirrors") else frozenset(data[k])) for k in keys}


@dataclass(frozen=True)
class Move:
    """One step of the command: `way` a compass name, "sideways", "ahead", or "turn-left" /
    "turn-right" (the facing turns, no move); `count` None when none was said."""
    way: str
    count: int | None = None


def moves(command: str, compass: dict) -> list[Move]:
    """The command's moves, in order (empty: it names no direction). A count goes with the
    direction it follows ("down four"), or, in a command whose first count comes before its
    first direction, with the one it comes before ("four steps down , two over"); never
    across a word that ends a step ("then", "and", a comma). A count of steps with no
    direction ("turn right, go one step") goes ahead."""
    w = words()
    toks = TOKEN.findall(command.lower())
    names = {n: n for n in compass}
    names.update({k: v for k, v in w["directions"].items() if v in compass})
    events = []                # (token index, way or None for a count, count)
    for i, t in enumerate(toks):
        if t in names:
            turning = any(toks[k] in w["turn"] for k in range(max(0, i - 2), i)) or \
                (i + 1 < len(toks) and toks[i + 1] in w["turn"])
            if turning and t in w["turns"]:
                events.append((i, w["turns"][t], None))
            else:
                events.append((i, names[t], None))
        elif t in w["sideways"] or t in w["ahead"]:
            events.append((i, "sideways" if t in w["sideways"] else "ahead", None))
        else:
            n = _count(toks, i)
            if n is not None:
                events.append((i, None, n))
    out, used = [], set()
    ways = [k for k, e in enumerate(events) if e[1] is not None]
    counts = [k for k, e in enumerate(events) if e[1] is None]
    counts_first = bool(ways and counts) and counts[0] < ways[0]
    for pos, k in enumerate(ways):
        way = events[k][1]
        count = None
        if not way.startswith("turn-"):
            nxt = ways[pos + 1] if pos + 1 < len(ways) else len(events)
            prev = ways[pos - 1] if pos else -1
            after = [j for j in range(k + 1, nxt) if j not in used and events[j][0] - events[k][0] <= NEAR
                     and not w["then"] & set(toks[events[k][0]:events[j][0]])]
            before = [j for j in range(k - 1, prev, -1) if j not in used and events[k][0] - events[j][0] <= NEAR
                      and not w["then"] & set(toks[events[j][0]:events[k][0]])]
            near = (before or after) if counts_first else (after or before)
            if near:
                used.add(near[0])
                count = events[near[0]][2]
        out.append((events[k][0], Move(way, count)))
    for j, (i, way, n) in enumerate(events):
        if way is None and j not in used and i + 1 < len(toks) and toks[i + 1] in w["units"]:
            out.append((i, Move("ahead", n)))
    return [m for _, m in sorted(out, key=lambda x: x[0])]


def _count(toks: list, i: int) -> int | None:
    """The count the word at `i` says, or None."""
    w = words()
    t = toks[i]
    if t.isdigit() and len(t) <= 2:
        return int(t)
    if t in NUMBER or t in w["counts"]:
        return NUMBER.get(t, w["counts"].get(t))
    if t in w["count_typos"] and i + 1 < len(toks) and toks[i + 1] in w["units"] and i > 0 and \
            not toks[i - 1].isdigit() and toks[i - 1] not in NUMBER:
        return w["count_typos"][t]
    return None


def gives_steps(said: list[Move]) -> bool:
    """Whether the moves walk at all (not only turn)."""
    return any(not m.way.startswith("turn-") for m in said)


@dataclass(frozen=True)
class End:
    """Where the steps end: the agent's room, whether it ever left its start room, and each
    thing's room (None: not in a room of the map)."""
    agent: str | None
    agent_moved: bool
    things: tuple          # ((thing, room), ...)


def read(said: list[Move], cells, at: tuple | None, beta: float) -> list[tuple[float, End]] | None:
    """The ends of the moves a command gives (`moves`) from `at` (the agent's position, its
    facing, {thing: position}; world.Cells.at) on the map `cells` (world.Cells), with their
    shares (summing to 1), or None when they walk nowhere or there is no map."""
    if cells is None or at is None or not gives_steps(said):
        return None
    position, facing, pushable = at
    start_room = cells.room.get(position)
    things = tuple(sorted(pushable.items()))
    states: dict = {}
    pairs = [p for p in words()["mirrors"] if set(p) <= set(cells.compass)]
    for flips in itertools.product((False, True), repeat=len(pairs)):
        frame = _frame(cells.compass, [p for p, flip in zip(pairs, flips) if flip])
        s = (position, facing, things, False)
        states[(frame, s)] = states.get((frame, s), 0.0) + math.exp(-beta * sum(flips))
    walks = [m for m in said if not m.way.startswith("turn-")]
    if any(a.count is None and a == b for a, b in zip(walks, walks[1:])):
        # "down , down , left": a word a step
        said = [Move(m.way, 1) if m.count is None and not m.way.startswith("turn-") else m for m in said]
    for k, move in enumerate(said):
        following = next((m.way for m in said[k + 1:] if not m.way.startswith("turn-")), None)
        nxt: dict = {}
        for (frame, s), weight in states.items():
            for t, share, faults in _step(s, move, frame, cells, start_room, following):
                key = (frame, t)
                nxt[key] = nxt.get(key, 0.0) + weight * share * math.exp(-beta * faults)
        states = dict(sorted(nxt.items(), key=lambda kv: -kv[1])[:BEAM])
    ends: dict = {}
    for (_, (position, _, things_at, left)), weight in states.items():
        rooms = tuple((t, cells.room.get(p)) for t, p in things_at)
        end = End(cells.room.get(position), left or cells.room.get(position) != start_room, rooms)
        ends[end] = ends.get(end, 0.0) + weight
    total = sum(ends.values())
    if total <= 0:
        return None
    return sorted(((w / total, e) for e, w in ends.items()), key=lambda x: -x[0])


def _frame(compass: dict, swapped: list) -> tuple:
    """((compass name, step), ...) with each pair of names in `swapped` trading steps."""
    swap = {a: b for p in swapped for a, b in (p, p[::-1])}
    return tuple(sorted((n, compass[swap.get(n, n)]) for n in compass))


def _step(s: tuple, move: Move, frame: tuple, cells, start_room, following: str | None) \
        -> list[tuple[tuple, float, int]]:
    """The states one move may lead to: [(state, share, faults)]; `following` is the way of
    the next move that walks."""
    position, facing, things, left = s
    order = [d for d in words()["clockwise"] if d in dict(frame)]
    if move.way.startswith("turn-"):
        if facing not in order:
            return [(s, 1.0, 0)]
        k = order.index(facing) + (1 if move.way == "turn-right" else -1)
        return [((position, order[k % len(order)], things, left), 1.0, 0)]
    across = words()["mirrors"][0]
    if move.way == "sideways":
        ways = [d for d in across if d in dict(frame)]
    elif move.way == "ahead":
        ways = [facing] if facing in dict(frame) else []
    else:
        ways = [move.way]
    then = [dict(frame)[d] for d in (across if following == "sideways" else (following,)) if d in dict(frame)]
    out = []
    for way in ways:
        for t, share, faults in _walk(s, dict(frame)[way], move.count, cells, start_room, then):
            out.append(((t[0], way, t[1], t[2]), share / len(ways), faults))
    return out or [(s, 1.0, 1)]


def _walk(s: tuple, step: tuple, count: int | None, cells, start_room, then: list) \
        -> list[tuple[tuple, float, int]]:
    """[((position, things, left), share, faults)] after walking `count` steps along `step`
    (one fewer or one more: a fault each). A step into a wall, or into a thing that cannot
    be pushed on, is a fault and leaves the agent where it was. Without a count the walk
    stops, each with an equal share, where people stop: on entering a room, where the next
    move's way (`then`: its steps) opens into a door or another room, before walking into
    a thing, or as far as it goes; not a step at all is a fault."""
    position, _, things, left = s
    path = [(position, things, left, 0)]          # after k steps: (position, things, left, faults)
    blocked = 0
    for _ in range(count + 1 if count is not None else len(cells.room)):
        position, things, ok = _one(position, things, step, cells)
        if not ok and count is None:
            break
        blocked += not ok
        left = left or (ok and cells.room.get(position) != start_room)
        path.append((position, things, left, blocked))
    if count is not None:
        return [((p, t, lf), 1.0, faults + abs(k - count)) for k, (p, t, lf, faults) in enumerate(path)
                if k >= 1 and abs(k - count) <= 1]
    if len(path) == 1:
        return [((position, things, left), 1.0, 1)]
    stops = [k for k in range(1, len(path)) if k == len(path) - 1 or _stops(path, k, step, then, cells)]
    return [((path[k][0], path[k][1], path[k][2]), 1.0 / len(stops), 0) for k in stops]


def _stops(path: list, k: int, step: tuple, then: list, cells) -> bool:
    """Whether a walk without a count may stop after its k-th step (see _walk)."""
    room = cells.room
    here, things = path[k][0], path[k][1]
    if room.get(here) is not None and room.get(here) != room.get(path[k - 1][0]):
        return True
    ahead = tuple(a + b for a, b in zip(here, step))
    if ahead in {p for _, p in things}:
        return True
    for turn in then:
        side = tuple(a + b for a, b in zip(here, turn))
        if side in room and room.get(side) != room.get(here):
            return True
    return False


def _one(position: tuple, things: tuple, step: tuple, cells) -> tuple[tuple, tuple, bool]:
    """One step: (position, things, whether it moved)."""
    there = tuple(a + b for a, b in zip(position, step))
    at = {p: t for t, p in things}
    if there in at:
        beyond = tuple(a + b for a, b in zip(there, step))
        if not _free(beyond, cells) or beyond in at:
            return position, things, False
        things = tuple(sorted((t, beyond if t == at[there] else p) for t, p in things))
        return there, things, True
    if not _free(there, cells):
        return position, things, False
    return there, things, True


def _free(position: tuple, cells) -> bool:
    """Whether a thing or the agent may stand there."""
    return position in cells.room
