"""Demonstrations: what a person (or a planner) did in a dungeon, as actions and states.

One file format is shared by the grounding layer, the web viewer's play mode and the
Minecraft recorder (`"format": "bcc-demonstration/1"`), so it lives below all three
edges, beside the replay of plans (simulate.py). Observers see states, not
actions: a recorder polls the world (the reference every 100 ms), so `extract` drops
consecutive duplicate snapshots and infers each action as the one whose model successor
is the next observed state. A snapshot names every dynamic variable and every cell of
the mutable grid layers, so it fixes the model state exactly and survives recompiling.
"""
from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

from .errors import BccError, read_input
from .model import Model

FORMAT = "bcc-demonstration/1"


def snapshot(model: Model, state: bytes) -> dict:
    """The JSON form of a state: every dynamic variable by label, every mutable cell by name."""
    g = model.grid
    names = g.value_names
    cells = [[x, y, z, names[g.cell(state, x, y, z)]]
             for y in g.layers for z in range(g.depth) for x in range(g.width)]
    return {"variables": model.decode(state), "cells": cells}


def state_from_snapshot(model: Model, snap, path: str | None = None, where: str = "snapshot") -> bytes:
    """The model state a snapshot describes; a BccError saying what is wrong otherwise."""
    if not isinstance(snap, dict) or not isinstance(snap.get("variables"), dict) \
            or not isinstance(snap.get("cells"), list):
        raise BccError(f"{where}: a snapshot is an object with \"variables\" (an object) and \"cells\" (a list)", path)
    state = bytearray(model.dense(model.initial))
    given = dict(snap["variables"])
    for v in model.variables:
        if v.label not in given:
            raise BccError(f"{where}: variable {v.label!r} is missing", path)
        value = given.pop(v.label)
        state[v.index] = _encode(v, value, path, where)
    if given:
        raise BccError(f"{where}: unknown variable {min(given)!r} (not a dynamic variable of {model.name})", path)
    g = model.grid
    area = g.width * g.depth
    seen = set()
    for cell in snap["cells"]:
        if not (isinstance(cell, list) and len(cell) == 4 and all(isinstance(c, int) and not isinstance(c, bool)
                                                                   for c in cell[:3]) and isinstance(cell[3], str)):
            raise BccError(f"{where}: a cell is [x, y, z, \"block name\"], not {json.dumps(cell)}", path)
        x, y, z, name = cell
        if name not in g.value_names:
            raise BccError(f"{where}: unknown block {name!r} at ({x}, {y}, {z})", path)
        value = g.value_names.index(name)
        if not (0 <= x < g.width and 0 <= y < g.height and 0 <= z < g.depth):
            raise BccError(f"{where}: cell ({x}, {y}, {z}) is outside the dungeon", path)
        if y not in g.layers:
            if g.cell(model.initial, x, y, z) != value:
                raise BccError(f"{where}: cell ({x}, {y}, {z}) is {name} but no action can change it "
                               f"from {g.value_names[g.cell(model.initial, x, y, z)]}", path)
            continue
        state[g.base + g.layers.index(y) * area + z * g.width + x] = value
        seen.add((x, y, z))
    missing = len(g.layers) * area - len(seen)
    if missing:
        x, y, z = next((x, y, z) for y in g.layers for z in range(g.depth) for x in range(g.width)
                       if (x, y, z) not in seen)
        raise BccError(f"{where}: {missing} cell(s) of the mutable layers {list(g.layers)} are missing, "
                       f"e.g. ({x}, {y}, {z})", path)
    return model.compact(bytes(state))


def _encode(v, value, path, where) -> int:
    if v.names:
        if value not in v.names:
            raise BccError(f"{where}: {v.label} = {value!r} is not one of {', '.join(v.names)}", path)
        return v.names.index(value) - v.lo
    if v.type == "bool":
        if not isinstance(value, bool):
            raise BccError(f"{where}: {v.label} must be true or false, not {json.dumps(value)}", path)
        return int(value) - v.lo
    if isinstance(value, bool) or not isinstance(value, int) or not v.lo <= value <= v.hi:
        raise BccError(f"{where}: {v.label} = {json.dumps(value)} is not an integer in [{v.lo}, {v.hi}]", path)
    return value - v.lo


@dataclass
class Demonstration:
    """A trajectory: `states[k + 1]` is `actions[k]` applied to `states[k]` (states are bytes)."""
    dungeon: str
    command: str | None
    actions: list
    states: list
    model: Model | None = field(default=None, repr=False, compare=False)

    def to_json(self) -> dict:
        if self.model is None:
            raise ValueError("Demonstration.to_json needs the model the states belong to")
        return {"format": FORMAT, "dungeon": self.dungeon, "command": self.command,
                "actions": list(self.actions), "states": [snapshot(self.model, s) for s in self.states]}

    def save(self, path: str | Path) -> None:
        from .atomic import write_text
        write_text(path, json.dumps(self.to_json(), separators=(",", ":")) + "\n")

    @classmethod
    def load(cls, path: str | Path, model: Model | None = None) -> Demonstration:
        """Read a demonstration file; compiles its dungeon unless `model` is given."""
        path = str(path)
        text = read_input(path, "demonstration")
        try:
            data = json.loads(text)
        except json.JSONDecodeError as exc:
            raise BccError(f"invalid JSON: {exc.msg}", path, exc.lineno, exc.colno) from None
        return from_json(data, model, path)


def dungeon_ref(model: Model) -> str:
    """How a demonstration names its dungeon: the shipped name, else the file's path."""
    from .compiler import shipped_dungeons
    return model.name if model.name in shipped_dungeons() and Path(model.path).stem == model.name else model.path


def from_json(data, model: Model | None = None, path: str | None = None) -> Demonstration:
    """A demonstration from its parsed JSON (see the module docstring for the format)."""
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        raise BccError(f"not a demonstration: expected an object with \"format\": \"{FORMAT}\"", path)
    dungeon = data.get("dungeon")
    if not isinstance(dungeon, str) or not dungeon:
        raise BccError("a demonstration names its \"dungeon\" (a shipped name or a path)", path)
    command = data.get("command")
    if command is not None and not isinstance(command, str):
        raise BccError("\"command\" is a string or null", path)
    actions, states = data.get("actions"), data.get("states")
    if actions is not None and (not isinstance(actions, list) or not all(isinstance(a, str) for a in actions)):
        raise BccError("\"actions\" is a list of action names", path)
    if states is not None and not isinstance(states, list):
        raise BccError("\"states\" is a list of snapshots", path)
    if actions is None and states is None:
        raise BccError("a demonstration has \"actions\", \"states\" or both", path)
    if model is None:
        from .compiler import compile_dungeon
        ref = dungeon
        if path is not None and not Path(ref).is_absolute() and (Path(path).parent / ref).is_file():
            ref = str(Path(path).parent / ref)   # a path relative to the demonstration file
        model = compile_dungeon(ref)
    if states:
        demo = extract(model, states, path)
        if actions is not None and list(actions) != demo.actions:
            k = next((i for i, (a, b) in enumerate(zip(actions, demo.actions)) if a != b),
                     min(len(actions), len(demo.actions)))
            raise BccError(f"\"actions\" and \"states\" disagree at step {k + 1}: the states show "
                           f"{demo.actions[k] if k < len(demo.actions) else 'no further action'}, the actions say "
                           f"{actions[k] if k < len(actions) else 'nothing'}", path)
    else:
        start = None
        if data.get("start") is not None:
            start = state_from_snapshot(model, data["start"], path, "start")
        demo = from_actions(model, actions or [], start=start, path=path)
    demo.dungeon, demo.command = dungeon, command
    return demo


def from_actions(model: Model, actions, start: bytes | None = None, command: str | None = None,
                 path: str | None = None) -> Demonstration:
    """Replay action names from `start` (default: the dungeon's start); each must apply."""
    state = model.initial if start is None else start
    states = [state]
    for k, name in enumerate(actions, 1):
        if name not in model.action_names:
            import difflib
            close = difflib.get_close_matches(str(name), model.action_names, n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            raise BccError(f"step {k}: unknown action {name!r}{hint}", path)
        i = model.action_index(name)
        nxt = model.apply(i, state)
        if nxt is None:
            raise BccError(f"step {k}: {name} does not apply: {model.why_not(i, state)} is false", path)
        states.append(nxt)
        state = nxt
    return Demonstration(dungeon_ref(model), command, list(actions), states, model)


def extract(model: Model, snapshots, path: str | None = None) -> Demonstration:
    """Actions from observed states: consecutive duplicates dropped, each transition explained
    by the first action (canonical order) whose successor is the next observed state."""
    states = []
    for k, snap in enumerate(snapshots):
        s = snap if isinstance(snap, bytes) else state_from_snapshot(model, snap, path, f"snapshot {k}")
        if not states or states[-1] != s:
            states.append(s)
    if not states:
        raise BccError("a demonstration needs at least one state", path)
    actions = []
    for k in range(len(states) - 1):
        s, nxt = states[k], states[k + 1]
        found = next((i for i in range(len(model.action_names)) if model.apply(i, s) == nxt), None)
        if found is None:
            raise BccError(f"step {k + 1}: no action explains the transition from observed state {k} to {k + 1} "
                           f"({_difference(model, s, nxt)})", path)
        actions.append(model.action_names[found])
    return Demonstration(dungeon_ref(model), None, actions, states, model)


def changes(model: Model, a: bytes, b: bytes) -> list[tuple[str, object, object]]:
    """(what, value in a, value in b) for every variable and grid cell that differs,
    variables first; shared by the error messages here and the Minecraft bridge's
    prediction-vs-world report."""
    da, db = model.decode(a), model.decode(b)
    out = [(k, da[k], db[k]) for k in da if da[k] != db[k]]
    g = model.grid
    va, vb = model.view(a), model.view(b)
    for x, y, z in sorted(set(va.changed()) | set(vb.changed()), key=lambda c: (c[1], c[2], c[0])):
        ca, cb = va.cell(x, y, z), vb.cell(x, y, z)
        if ca != cb:
            out.append((f"block ({x}, {y}, {z})", g.value_names[ca], g.value_names[cb]))
    return out


def _difference(model: Model, a: bytes, b: bytes) -> str:
    """What changed between two states, for error messages."""
    found = [f"{what}: {before} -> {after}" for what, before, after in changes(model, a, b)]
    shown = found[:4] + ([f"... {len(found) - 4} more"] if len(found) > 4 else [])
    return "; ".join(shown)
