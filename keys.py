"""The keys that play a dungeon: one table for the terminal (`bcc play`) and the web page.

The page receives the same bindings in its scene (`serve/scene.py`), so a key does the
same thing wherever you play; the page adds only the arrow keys as aliases. Actions the
table does not name get the digits 1-9 in the model's order.
"""
from __future__ import annotations

KEYS = {"move_forward": "w", "rotate_left": "a", "rotate_right": "d", "look_down": "s", "look_ahead": "e",
        "change_item": "c", "destroy_block": "x", "place_block": "p"}
QUIT = "q"


def key_map(action_names) -> dict[str, int]:
    """key -> action index: the usual actions by their letters, any other action by a digit."""
    out, spare = {}, iter("123456789")
    for i, name in enumerate(action_names):
        key = KEYS.get(name.split("(")[0])
        if key is None or key in out:
            key = next(spare, None)
            if key is None:
                continue  # more than nine unnamed actions: the rest have buttons only
        out[key] = i
    return out
