"""What the web page draws: a dungeon's top view once, then one small frame per state.

Like `bcc show`, rows are z and columns x. A *column* is the list of block indices from
y = 0 up (trailing air dropped, `Model.column`); the page colours a cell by its top
block and draws it as a wall when it rises above the agent's feet. A *frame* carries
the agent's pose, the decoded variables and only the columns that differ from the
start, so a long plan stays small on the wire.
"""
from __future__ import annotations

from ..compiler.dungeon import Dungeon
from ..keys import key_map
from ..model import Model
from ..render import facing_name
from ..simulate import Replay


def rooms_of(dungeon: Dungeon) -> list[dict]:
    """The dungeon's rooms as rectangles with a colour, read through the domain's binding."""
    binding = dungeon.domain.binding.get("rooms") or {}
    cls, fields = binding.get("class"), binding.get("fields") or {}
    xs, zs, color = fields.get("x"), fields.get("z"), fields.get("color")
    if not cls or not xs or not zs:
        return []
    out = []
    for name, (c, values) in dungeon.objects.items():
        if c == cls:
            out.append({"name": name, "color": str(values.get(color, "")) if color else "",
                        "x": [values.get(xs[0]), values.get(xs[1])], "z": [values.get(zs[0]), values.get(zs[1])]})
    return out


def columns(model: Model, state: bytes) -> list[list[list[int]]]:
    g = model.grid
    return [[list(model.column(state, x, z)) for x in range(g.width)] for z in range(g.depth)]


def scene(model: Model, rooms: list[dict]) -> dict:
    """Everything static about a dungeon, plus its start as frame 0's base."""
    g = model.grid
    return {
        "dungeon": model.name, "goal": model.goal_text,
        "width": g.width, "depth": g.depth, "height": g.height,
        "blocks": list(g.value_names), "columns": columns(model, model.initial),
        "rooms": rooms,
        "objects": [{"name": n, "x": x, "z": z} for n, x, z in model.display.get("objects", [])],
        "actions": list(model.action_names),
        "keys": {key: model.action_names[i] for key, i in key_map(model.action_names).items()},
    }


def frame(model: Model, state: bytes) -> dict:
    g = model.grid
    cols = {(x, z) for x, _, z in model.view(state).changed()}
    changed = [[x, z, list(model.column(state, x, z))] for x, z in sorted(cols)]
    return {"agent": list(model.agent_position(state)), "facing": facing_name(model, state),
            "variables": model.decode(state), "changed": changed,
            "goal": bool(model.is_goal(state)), "failure": bool(model.is_failure(state))}


def replay_frames(model: Model, result: Replay) -> dict:
    """A replay as the page animates it: the outcome plus one frame per state reached."""
    return {**result.to_json(), "frames": [frame(model, s) for s in result.states]}
