"""Play a dungeon in the terminal, one key per action, and record a demonstration.

On a terminal keys are read raw (no Enter needed); from a pipe or a test, each line is a
string of keys. The map is redrawn after every key with `bcc.render`. `q` (or the end of
input) stops; death stops too. Inapplicable keys are reported and change nothing.
"""
from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterator

from ..model import Model
from ..render import facing_name, render

KEYS = {"move_forward": "w", "rotate_left": "a", "rotate_right": "d", "look_down": "j", "look_ahead": "k",
        "change_item": "c", "destroy_block": "x", "place_block": "p"}
QUIT = "q"


def key_map(model: Model) -> dict[str, int]:
    """key -> action index: the canonical actions by their usual keys, any other action by a digit."""
    out, spare = {}, iter("123456789")
    for i, name in enumerate(model.action_names):
        key = KEYS.get(name.split("(")[0])
        if key is None or key in out:
            key = next(spare)
        out[key] = i
    return out


def tty_keys() -> Iterator[str]:
    """Single key presses from a terminal in raw mode (restored on exit)."""
    import termios
    import tty
    fd = sys.stdin.fileno()
    old = termios.tcgetattr(fd)
    try:
        tty.setcbreak(fd)
        while True:
            ch = os.read(fd, 1).decode(errors="ignore")
            if not ch:
                return
            yield ch
    finally:
        termios.tcsetattr(fd, termios.TCSADRAIN, old)


def line_keys(stream) -> Iterator[str]:
    """Keys from a non-terminal input: every non-blank character of every line."""
    for line in stream:
        for ch in line:
            if not ch.isspace():
                yield ch


def status(model: Model, state: bytes) -> str:
    v = model.decode(state)
    x, y, z = model.agent_position(state)
    held = [f"{v[k]} x{v[k.replace('blockType', 'count')]}" for k in v
            if k.endswith(".blockType") and k.replace("blockType", "count") in v and v[k.replace('blockType', 'count')]]
    look = {0: "ahead", 1: "down"}.get(v.get("agent.verticalDirection"), "")
    parts = [f"at ({x}, {y}, {z})", f"facing {facing_name(model, state) or '?'}"]
    if look:
        parts.append(f"looking {look}")
    if "agent.selectedItem" in v:
        parts.append(f"slot {v['agent.selectedItem']}")
    return ", ".join(parts) + (f"; holding {', '.join(held)}" if held else "")


def play(model: Model, keys: Iterator[str], out: Callable[[str], None], clear: bool = False,
         start: bytes | None = None) -> list[bytes]:
    """Run a session; return the visited states (the start first)."""
    bindings = key_map(model)
    legend = "  ".join(f"{k}={model.action_names[i]}" for k, i in bindings.items()) + f"  {QUIT}=quit"
    state = model.initial if start is None else start
    states = [state]
    note = f"goal: {model.goal_text}"

    def draw():
        out(("\x1b[2J\x1b[H" if clear else "") + render(model, state) + "\n" + status(model, state) +
            "\n" + note + "\n" + legend)

    draw()
    for key in keys:
        if key == QUIT:
            break
        if key not in bindings:
            note = f"key {key!r} does nothing ({QUIT} quits)"
            draw()
            continue
        i = bindings[key]
        nxt = model.apply(i, state)
        if nxt is None:
            note = f"{model.action_names[i]} does not apply: {model.why_not(i, state)}"
        else:
            state = nxt
            states.append(state)
            note = model.action_names[i] + (" -- goal reached" if model.is_goal(state) else "")
        if model.is_failure(state):
            note = f"{model.action_names[i]} -- you died"
            draw()
            break
        draw()
    return states
