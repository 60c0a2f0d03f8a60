"""Play a dungeon in the terminal, one key per action, and record a demonstration.

On a terminal keys are read raw (no Enter needed); from a pipe or a test, each line is a
string of keys. The map is redrawn after every key with `bcc.render`. `q` (or the end of
input) stops; after a death the session waits for `q`. Inapplicable keys are reported
and change nothing. The keys are `keys.py`'s, the same as the web page's.
"""
from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterator

from ..keys import QUIT, key_map
from ..model import Model
from ..render import facing_name, render

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
    """Where the agent is and what it holds: the item in its hand (the selected slot),
    then the rest of the inventory."""
    v = model.decode(state)
    x, y, z = model.agent_position(state)
    look = {0: "ahead", 1: "down"}.get(v.get("agent.verticalDirection"), "")
    parts = [f"at ({x}, {y}, {z})", f"facing {facing_name(model, state) or '?'}"]
    if look:
        parts.append(f"looking {look}")
    slots = {k[:-len(".blockType")]: (v[k], v[k[:-len("blockType")] + "count"]) for k in v
             if k.endswith(".blockType") and k[:-len("blockType")] + "count" in v}
    text = ", ".join(parts)
    if "agent.selectedItem" in v:
        hand = next((item for key, item in slots.items() if key.endswith(f"[{v['agent.selectedItem']}]")), None)
        held = f"{hand[0]} x{hand[1]}" if hand and hand[1] else "nothing"
        text += f"; slot {v['agent.selectedItem']} in hand: {held}"
        rest = [f"{item} x{count}" for key, (item, count) in slots.items()
                if count and not key.endswith(f"[{v['agent.selectedItem']}]")]
        if rest:
            text += f"; also carrying {', '.join(rest)}"
    return text


def play(model: Model, keys: Iterator[str], out: Callable[[str], None], clear: bool = False,
         start: bytes | None = None) -> list[bytes]:
    """Run a session; return the visited states (the start first)."""
    bindings = key_map(model.action_names)
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
            # The episode is over, but the session waits for `q`: on a terminal, keys
            # typed after a sudden exit would go to the shell.
            note = f"{model.action_names[i]} -- you died. Press {QUIT} to quit."
            draw()
            for key in keys:
                if key == QUIT:
                    break
                note = f"you died; no more moves. Press {QUIT} to quit."
                draw()
            break
        draw()
    return states
