"""The shipped dungeons, as `bcc list --json` shows them, and one dungeon's file."""
from __future__ import annotations

from ..compiler.domain import DOMAINS_DIR
from ..compiler.dungeon import DUNGEONS_DIR, shipped_dungeons
from ..compiler.source import load_yaml
from ..compiler.structure import listed_goal


def _info(name: str, data) -> dict:
    return {"name": name, "goal": listed_goal(data.get("goal")), "extends": data.get("extends"),
            "description": " ".join(str(data.get("description", "")).split())}


def listing() -> dict:
    dungeons = [_info(name, load_yaml(DUNGEONS_DIR / f"{name}.yaml")) for name in shipped_dungeons()]
    return {"dungeons": dungeons, "domains": sorted(p.stem for p in DOMAINS_DIR.glob("*.yaml"))}


def dungeon_file(name: str) -> dict | None:
    """A shipped dungeon's listing entry plus its text; None for any other name (never a path)."""
    if name not in shipped_dungeons():
        return None
    path = DUNGEONS_DIR / f"{name}.yaml"
    data = load_yaml(path)
    return {**_info(name, data), "domain": data.get("domain"), "yaml": path.read_text(encoding="utf-8")}
