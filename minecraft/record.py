"""Demonstrations from play: poll a person's world every 100 ms, turn it into model states,
and infer the actions with the grounding layer's extractor (BurlapCraft's 'learn').

The server lets a person do things bcc's model cannot (walk diagonally, mine gold, jump):
the recorder enforces the model. A change no short sequence of model actions explains is
undone: the world and the player are put back to the last model state, with a chat
message saying why. Standing on lava is death in bcc's rules (the server applies no lava
damage): the recording stops there, as the episode does in the model.
"""
from __future__ import annotations

import time
from collections import deque
from dataclasses import dataclass, field
from typing import Callable

from ..errors import BccError
from ..model import Model
from .bridge import Bridge
from .world import WorldMap, check_supported, describe, difference

POLL_SECONDS = 0.1     # the reference recorder's period
BRIDGE_GAP = 4         # the longest run of model actions one poll may hide (a strafe is 3)
OFF_FLOOR_SECONDS = 2.0  # longer off the floor than a jump takes: put back


def explain(model: Model, before: bytes, after: bytes, depth: int = BRIDGE_GAP) -> list | None:
    """The shortest list of states (excluding `before`, ending with `after`) that model actions
    lead through from `before` to `after`, or None if none of at most `depth` actions does.
    Fast polling sees one action at a time; a quick player can fit a few into one poll."""
    if before == after:
        return []
    parents = {before: None}
    frontier = deque([(before, 0)])
    n = len(model.action_names)
    while frontier:
        s, d = frontier.popleft()
        if d == depth:
            continue
        if model.is_terminal(s):
            continue
        for i in range(n):
            t = model.apply(i, s)
            if t is None or t in parents:
                continue
            parents[t] = s
            if t == after:
                path = [t]
                while parents[path[-1]] != before:
                    path.append(parents[path[-1]])
                return path[::-1]
            frontier.append((t, d + 1))
    return None


@dataclass
class Recording:
    states: list = field(default_factory=list)     # model states, consecutive duplicates dropped
    polls: int = 0
    corrections: list = field(default_factory=list)  # what was undone, and why
    ended: str = ""                                  # why the recording stopped


class Recorder:
    """Follows one player and keeps the trajectory of model states they produce."""

    def __init__(self, model: Model, bridge: Bridge, player: str | None = None,
                 log: Callable[[str], None] = lambda line: None):
        check_supported(model)
        self.model, self.bridge, self.player, self.log = model, bridge, player, log
        self.world = WorldMap(model)
        self.recording = Recording()
        self._off_floor = 0

    def reset(self, put_back: bool = True) -> None:
        """Start a new recording at the dungeon's start (rebuilding the world)."""
        if put_back:
            self.restore(self.model.initial)
        self.recording = Recording(states=[self.model.initial])

    def restore(self, state: bytes) -> None:
        """Make the world show `state`: blocks, player pose and hotbar."""
        self.bridge.build_state(self.world, state)
        self.bridge.setup(self.player, self.world.pose(state), self.world.hotbar(state))

    def poll(self) -> bytes | None:
        """One observation; the new model state if it changed, else None."""
        rec = self.recording
        rec.polls += 1
        try:
            parsed = self.world.parse(self.bridge.observe(self.player))
        except BccError as exc:           # e.g. fell out of the dungeon's box
            return self._undo(str(exc))
        if not parsed.on_floor and self.model.decode(parsed.state)["agent.alive"]:
            # mid-jump or mid-step: not a model pose yet; but nobody jumps for 2 s (they
            # stand on a block, where bcc's agent never stands)
            self._off_floor += 1
            if self._off_floor * POLL_SECONDS < OFF_FLOOR_SECONDS:
                return None
            return self._undo("bcc's agent stays on the floor")
        self._off_floor = 0
        last = rec.states[-1] if rec.states else None
        if last is None:
            rec.states.append(parsed.state)
            return parsed.state
        if parsed.state == last:
            return None
        path = explain(self.model, last, parsed.state)
        if path is None:
            diffs = difference(self.model, last, parsed.state)
            return self._undo("no move of bcc's model does that (" + "; ".join(diffs[:3]) + ")")
        rec.states.extend(path)
        self.log(f"  {len(rec.states) - 1:3d} states  now {describe(self.model, parsed.state)}"
                 + (f"  ({len(path)} actions in one poll)" if len(path) > 1 else ""))
        return parsed.state

    def _undo(self, why: str) -> None:
        self._off_floor = 0
        last = self.recording.states[-1] if self.recording.states else self.model.initial
        self.recording.corrections.append(why)
        self.log(f"  put back: {why}")
        try:
            self.bridge.chat(f"bcc: {why}: put back", self.player)
        except BccError:
            pass
        self.restore(last)
        return None

    def demonstration(self, command: str | None):
        """The recording so far as a Demonstration (actions inferred by the extractor)."""
        from ..demonstration import extract
        demo = extract(self.model, list(self.recording.states))
        demo.command = command
        return demo


def parse_chat(text: str) -> tuple[str, str] | None:
    """In-game commands: 'learn <text>', 'done', 'reset'; None for ordinary chat."""
    words = text.strip().split(None, 1)
    if not words:
        return None
    head = words[0].lower()
    if head == "learn":
        return ("learn", words[1].strip() if len(words) > 1 else "")
    if head in ("done", "reset"):
        return (head, "")
    return None


def record(model: Model, bridge: Bridge, command: str | None, player: str | None = None,
           timeout: float = 600.0, interval: float = POLL_SECONDS,
           log: Callable[[str], None] = lambda line: None, stop_at_goal: bool = True):
    """Record one demonstration from `player` (default: the first person in the world).
    Ends on chat 'done' or 'learn <text>', at the dungeon's goal (if `stop_at_goal`), at
    death, or after `timeout` seconds. Returns (Demonstration, Recording)."""
    rec = Recorder(model, bridge, player, log)
    rec.reset(put_back=True)
    rec.bridge.chat(f"bcc: recording{f' {command!r}' if command else ''}: play, then type 'done' "
                    "(or 'learn <command>'); 'reset' starts over", player)
    end = time.monotonic() + timeout
    why = "timeout"
    text = command
    next_poll = time.monotonic()
    while time.monotonic() < end:
        event = bridge.next_event(max(0.0, next_poll - time.monotonic()))
        if event is not None:
            if event.get("event") == "exit":
                raise bridge.exit_error()
            if event.get("event") in ("left", "bot_left") and event.get("player") == player:
                why = f"{player} left the game"
                break
            if event.get("event") == "chat" and (player is None or event.get("player") == player):
                said = parse_chat(event.get("text", ""))
                if said and said[0] == "reset":
                    rec.reset()
                    log("  reset: recording again from the start")
                    continue
                if said and said[0] in ("done", "learn"):
                    # take the last poll first: the final move may be younger than 100 ms
                    rec.poll()
                    if said[0] == "learn" and said[1]:
                        text = said[1]
                    why = f"chat '{event['text'].strip()}'"
                    break
            continue
        next_poll += interval
        state = rec.poll()
        if state is not None and model.is_failure(state):
            why = "death (bcc's rules: lava kills)"
            bridge.chat("bcc: you walked into lava: dead in bcc's rules; recording stopped", player)
            break
        if state is not None and stop_at_goal and model.is_goal(state):
            why = "goal reached"
            break
    rec.recording.ended = why
    if not text:
        raise BccError("the demonstration has no command: give one on the command line "
                       "or type 'learn <command>' in the game")
    return rec.demonstration(text), rec.recording


class NobodyJoined(BccError):
    """The wait for a player ran out: a budget, not bad input (`bcc minecraft record` exits 1)."""


def wait_for_player(bridge: Bridge, player: str | None, timeout: float) -> str:
    """The name of the player to record: `player` once online, else the first person in."""
    end = time.monotonic() + timeout
    while True:
        people = [p["name"] for p in bridge.players() if not p["bot"]]
        if player in people or (player is None and people):
            return player or people[0]
        left = end - time.monotonic()
        if left <= 0:
            raise NobodyJoined(f"nobody joined within {timeout:g} s"
                           + (f" (waiting for {player})" if player else ""))
        event = bridge.next_event(min(left, 0.5))
        if event is not None and event.get("event") == "exit":
            raise bridge.exit_error()


def save_only(demo, path) -> dict:
    """`host`'s default keeper: write the demonstration file, nothing more."""
    demo.save(path)
    return {"stored": False, "message": "saved"}


def host(model: Model, bridge: Bridge, out_dir, log: Callable[[str], None] = print,
         duration: float | None = None, interval: float = POLL_SECONDS, stop=None,
         keep: Callable[..., dict] = save_only, written: list | None = None) -> list:
    """`bcc minecraft serve`: follow the first person in the world; 'learn <command>' in the
    chat stores what they did since the start (or the last 'learn'/'reset') and starts over.
    `keep(demo, path)` writes each demonstration and says where else it went (`bcc
    minecraft serve` also adds it to the grounding dataset: the command line puts the two
    edges together); its dict's "message" is logged.
    Runs for `duration` seconds (None: until interrupted) or until the `stop` event is set.
    Returns the demonstration files written, also appended to `written` as they are, so a
    caller interrupted by Ctrl-C still knows them."""
    from pathlib import Path
    out_dir = Path(out_dir)
    rec: Recorder | None = None
    written = [] if written is None else written
    announced_goal = False
    end = None if duration is None else time.monotonic() + duration
    next_poll = time.monotonic()
    while (end is None or time.monotonic() < end) and not (stop is not None and stop.is_set()):
        event = bridge.next_event(max(0.0, next_poll - time.monotonic()))
        if event is not None:
            kind, who = event.get("event"), event.get("player")
            if kind == "exit":
                raise bridge.exit_error()
            people = {p["name"] for p in bridge.players() if not p["bot"]} if kind == "joined" else set()
            if kind == "joined" and who in people:
                if rec is None:
                    rec = Recorder(model, bridge, who, log)
                    rec.reset()
                    announced_goal = False
                    log(f"{who} joined: placed at the start; recording")
                    bridge.chat(f"bcc: welcome to {model.name} ({model.goal_text}). Play, then type "
                                "'learn <command>' to store a demonstration; 'reset' starts over", who)
                else:
                    bridge.chat(f"bcc: {rec.player} is playing this dungeon; you can watch", who)
            elif kind == "left" and rec is not None and who == rec.player:
                log(f"{who} left")
                rec = None
            elif kind == "chat" and rec is not None and who == rec.player:
                said = parse_chat(event.get("text", ""))
                if said and said[0] == "reset":
                    rec.reset()
                    announced_goal = False
                elif said and said[0] == "learn":
                    if not said[1]:
                        bridge.chat("bcc: say what you showed, e.g. 'learn go to the gold block'", who)
                        continue
                    rec.poll()
                    try:
                        demo = rec.demonstration(said[1])
                    except BccError as exc:
                        bridge.chat(f"bcc: could not make a demonstration: {exc}", who)
                        continue
                    out_dir.mkdir(parents=True, exist_ok=True)
                    path = out_dir / f"{model.name}-{len(written) + 1}-{time.strftime('%Y%m%d-%H%M%S')}.json"
                    info = keep(demo, path)
                    written.append(path)
                    log(f"learned {said[1]!r}: {len(demo.actions)} actions -> {path}; {info['message']}")
                    bridge.chat(f"bcc: learned '{said[1]}' from {len(demo.actions)} actions; back to the start", who)
                    rec.reset()
                    announced_goal = False
            continue
        next_poll += interval
        if rec is None:
            continue
        state = rec.poll()
        if state is None:
            continue
        if model.is_failure(state):
            bridge.chat("bcc: you walked into lava: dead in bcc's rules; back to the start", rec.player)
            log(f"{rec.player} died (lava): back to the start")
            rec.reset()
            announced_goal = False
        elif model.is_goal(state) and not announced_goal:
            announced_goal = True
            bridge.chat("bcc: goal reached! type 'learn <command>' to store this demonstration", rec.player)
    return written
