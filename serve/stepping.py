"""What /replay and /demonstration answer for a compiled model, wherever it was compiled.

A shipped dungeon is stepped in the server; posted text only inside the sandboxed model
host (`model_host.py`). Both call these functions, so the answers are the same.
"""
from __future__ import annotations


def replay_body(model, rooms: list[dict], actions: list[str], include_scene: bool) -> dict:
    from ..simulate import replay as run
    from .scene import replay_frames, scene
    result = run(model, [(a, 1, k) for k, a in enumerate(actions, 1)], "actions")
    out = replay_frames(model, result)
    out["scene"] = scene(model, rooms) if include_scene else None
    return out


def demonstration_body(model, posted: bool, actions: list[str], command: str | None) -> dict:
    from ..demonstration import from_actions
    demo = from_actions(model, actions, command=command, path="actions")
    if posted:  # posted text has no path the file could name: save it as NAME.yaml beside it
        demo.dungeon = f"{model.name}.yaml"
    return demo.to_json()
