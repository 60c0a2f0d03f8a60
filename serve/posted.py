"""Dungeons arriving over HTTP: a shipped name, or YAML text the server must not trust.

The compiler reads files, so posted text is written to a private temporary folder as
`posted.yaml`. The policy for what that text may reference: `extends:` and `domain:`
may only name *shipped* dungeons and domains (bare names, no paths), so a client can
never make the server read one of its files. The folder also holds a link to every
shipped dungeon and domain, so the compiler's "relative to this file" lookup finds the
shipped file before it would ever look in the server's working directory.

Errors go back to the client as `{"error", "line", "column", "file"}` where `file` is
`"<posted>"` for the posted text, `"goal"` for a posted goal, or the shipped file's
name; temporary paths never leak.
"""
from __future__ import annotations

import contextlib
import hashlib
import os
import re
import shutil
import tempfile
from dataclasses import dataclass
from pathlib import Path

import yaml

from ..compiler.domain import DOMAINS_DIR
from ..compiler.dungeon import DUNGEONS_DIR, shipped_dungeons
from ..compiler.source import error_at, load_yaml_text, suggest
from ..errors import CONTROL, BccError

POSTED_NAME = "posted.yaml"
POSTED_LABEL = "<posted>"


@dataclass(frozen=True)
class DungeonRef:
    """What a request's `dungeon` field means: a shipped name, or YAML text."""
    name: str | None = None
    text: str | None = None

    @property
    def key(self) -> str:
        """A cache key: the name, or a hash of the text."""
        if self.name is not None:
            return "name:" + self.name
        return "text:" + hashlib.sha256(self.text.encode("utf-8", "surrogatepass")).hexdigest()


def shipped_domains() -> list[str]:
    return sorted(p.stem for p in DOMAINS_DIR.glob("*.yaml"))


def parse_ref(value: str) -> DungeonRef:
    """A value equal to a shipped dungeon's name is that dungeon; anything with a line
    break or a colon is YAML text; anything else is a misspelt name (never a path)."""
    if value in shipped_dungeons():
        return DungeonRef(name=value)
    if "\n" in value or ":" in value:
        return DungeonRef(text=value)
    shown = repr(value) if len(value) <= 60 else repr(value[:57]) + "..."
    raise BccError(f"no shipped dungeon named {shown}{suggest(value[:100], shipped_dungeons())}; "
                   f"post a shipped name or the YAML text of a dungeon "
                   f"(shipped: {', '.join(shipped_dungeons())})")


def check_policy(text: str) -> None:
    """Reject what a posted dungeon may not do before the compiler sees it: YAML aliases
    (a few bytes of them expand exponentially) and references other than shipped names."""
    bad = CONTROL.search(text.replace("\r", ""))
    if bad is not None:  # NUL, escapes, lone surrogates (which cannot even be written to a file)
        line = text.count("\n", 0, bad.start()) + 1
        col = bad.start() - (text.rfind("\n", 0, bad.start()) + 1) + 1
        raise BccError(f"the control character {bad.group()!r} is not accepted in a dungeon", POSTED_LABEL, line, col)
    try:
        for event in yaml.parse(text, Loader=yaml.SafeLoader):
            if isinstance(event, yaml.AliasEvent):
                m = event.start_mark
                raise BccError("YAML aliases (*name) are not accepted in a posted dungeon",
                               POSTED_LABEL, m.line + 1, m.column + 1)
    except yaml.YAMLError:
        pass  # the loader below reports it with its position
    data = load_yaml_text(text, POSTED_LABEL)
    for key, allowed, kind in (("extends", shipped_dungeons(), "dungeon"), ("domain", shipped_domains(), "domain")):
        if key in data and data[key] not in allowed:
            raise error_at(data, key, f"a posted dungeon's `{key}` must name a shipped {kind} "
                                      f"({', '.join(allowed)}){suggest(str(data[key]), allowed)}")


@contextlib.contextmanager
def posted_file(text: str):
    """Yield the path of `text` written to a fresh private folder beside links to the
    shipped files; the folder is removed afterwards."""
    check_policy(text)
    folder = Path(tempfile.mkdtemp(prefix="bcc-serve-"))
    try:
        for shipped in list(DUNGEONS_DIR.glob("*.yaml")) + list(DOMAINS_DIR.glob("*.yaml")):
            for link in (folder / shipped.stem, folder / shipped.name):
                if not os.path.lexists(link):
                    link.symlink_to(shipped)
        path = folder / POSTED_NAME
        path.write_text(text, encoding="utf-8")
        yield path
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def public_error(exc: BccError) -> dict:
    """The 400 body for a BccError: positions kept, temporary folders replaced by names."""
    path = exc.path
    file = None
    if path is not None:
        p = Path(str(path))
        if str(path) == POSTED_LABEL or p.name == POSTED_NAME:
            file = POSTED_LABEL
        elif str(path) == "--goal":  # the compiler's name for a goal given beside the dungeon
            file = "goal"
        elif p.parent.name.startswith("bcc-serve-") or p.parent in (DUNGEONS_DIR, DOMAINS_DIR):
            file = p.stem  # a shipped dungeon or domain, reached through its link
        else:
            file = p.name
    return {"error": scrub(exc.message), "line": exc.line, "column": exc.col, "file": file}


def scrub(message: str) -> str:
    """Replace temporary paths in a message (e.g. in a cycle report) by what they stand for."""
    tmp = re.escape(tempfile.gettempdir().rstrip("/"))

    def name(match: re.Match) -> str:
        file = match.group(1)
        return POSTED_LABEL if file == POSTED_NAME else Path(file).stem
    return re.sub(tmp + r"/bcc-serve-[^/\s]+/([^/\s),:;'\"]+)", name, message)


def compile_ref(ref: DungeonRef, goal: str | None = None, with_rooms: bool = False):
    """Compile what a request names (and, with `with_rooms`, read its rooms for drawing)."""
    from ..compiler import compile_dungeon, load_dungeon
    from .scene import rooms_of
    if ref.name is not None:
        model = compile_dungeon(ref.name, goal=goal)
        return (model, rooms_of(load_dungeon(ref.name))) if with_rooms else model
    with posted_file(ref.text) as path:
        model = compile_dungeon(path, goal=goal)
        return (model, rooms_of(load_dungeon(path))) if with_rooms else model
