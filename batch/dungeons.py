"""What a sweep's dungeons are: files, shipped names, globs and generator specs.

`expand_dungeons` turns what the user wrote into a list of dungeon names, each one run
of the sweep's dungeon axis. A generator spec such as

    maze:width=21,depth=21,stones=2,seed=1..200

expands its ranges (`lo..hi`, inclusive) and alternatives (`a|b|c`) into one canonical
spec per combination (`maze:width=21,depth=21,stones=2,seed=7`). Only that short text
travels to a worker, which regenerates the dungeon (the generator is deterministic by
seed) in `open_dungeon`; so a generated sweep needs no shared file system, on a cluster
either.
"""
from __future__ import annotations

import contextlib
import glob
import itertools
import os
import tempfile
from pathlib import Path

from ..errors import BccError
from .runs import check_size

GENERATORS = ("maze",)
# generate_maze's parameters, in canonical order, with their defaults (as `bcc generate maze`)
MAZE_PARAMS = {"width": 15, "depth": 15, "stones": 0, "lava": 0, "loops": 0.0, "seed": 0}
ALWAYS_SHOWN = ("width", "depth", "seed")   # the rest appear in a name only when not 0
GLOB_CHARS = set("*?[")


def is_generator_spec(text: str) -> bool:
    head, sep, _ = text.partition(":")
    return bool(sep) and head in GENERATORS


def expand_dungeons(texts, base: Path | None = None, where=None) -> list[str]:
    """One name per dungeon, in the order given (globs sorted), duplicates dropped.

    `base` is the folder relative paths are read from (a sweep file's folder); `where(i)`
    gives the BccError position of entry i (a sweep file's line), else errors have none."""
    out: dict[str, None] = {}
    for i, text in enumerate(texts):
        try:
            names = _expand_one(text, base)
            out.update(dict.fromkeys(names))
            check_size(len(out), "the dungeons")
        except BccError as exc:
            if where is not None:
                raise where(i, exc.message) from None
            raise
    return list(out)


def _expand_one(text, base: Path | None) -> list[str]:
    if not isinstance(text, str) or not text.strip():
        raise BccError(f"a dungeon is a file, a shipped name, a glob or a generator spec, got {text!r}")
    text = text.strip()
    if is_generator_spec(text):
        return expand_spec(text)
    if GLOB_CHARS & set(text):
        pattern = text if base is None or os.path.isabs(text) else str(base / text)
        found = sorted(p for p in glob.glob(pattern) if os.path.isfile(p))
        if not found:
            raise BccError(f"no dungeon files match {text!r}")
        return [_display_path(p) for p in found]
    if base is not None and not os.path.isabs(text) and (base / text).is_file():
        return [_display_path(str(base / text))]
    from ..compiler import resolve_dungeon_path
    resolve_dungeon_path(text)  # a missing file or unknown name: an error now, not 200 error rows later
    return [text]


def _display_path(path: str) -> str:
    rel = os.path.relpath(path)
    return path if rel.startswith("..") else rel


def expand_spec(text: str) -> list[str]:
    """`maze:k=v,...` with ranges and alternatives -> canonical specs, one per combination.

    Each distinct maze shape is generated once here, so a bad parameter is one error now
    (generate_maze's own message) rather than an error row per seed."""
    kind, _, body = text.partition(":")
    values: dict[str, list] = {}
    for part in filter(None, (p.strip() for p in body.split(","))):
        key, eq, raw = part.partition("=")
        key = key.strip()
        if not eq:
            raise BccError(f"{text!r}: expected key=value, got {part!r}")
        if key not in MAZE_PARAMS:
            from ..compiler.source import suggest
            raise BccError(f"{text!r}: unknown {kind} parameter {key!r}{suggest(key, MAZE_PARAMS)}; "
                           f"known: {', '.join(MAZE_PARAMS)}")
        if key in values:
            raise BccError(f"{text!r}: {key} is given twice")
        values[key] = _values(text, key, raw.strip())
    keys = list(MAZE_PARAMS)
    axes = [values.get(k, [MAZE_PARAMS[k]]) for k in keys]
    count = 1
    for axis in axes:
        count *= len(axis)
    check_size(count, repr(text))
    specs, shapes = [], set()
    for combo in itertools.product(*axes):
        params = dict(zip(keys, combo))
        shape = tuple(v for k, v in params.items() if k != "seed")
        if shape not in shapes:
            shapes.add(shape)
            _check_maze(text, params)
        specs.append(canonical_spec(kind, params))
    return specs


def _values(text: str, key: str, raw: str) -> list:
    out = []
    for alt in raw.split("|"):
        alt = alt.strip()
        lo, dots, hi = alt.partition("..")
        try:
            if dots:
                lo_i, hi_i = int(lo), int(hi)
                if hi_i < lo_i:
                    raise BccError(f"{text!r}: the range {alt!r} of {key} is empty")
                check_size(hi_i - lo_i + 1 + len(out), f"{text!r}: {key}")
                out.extend(range(lo_i, hi_i + 1))
            elif key == "loops":
                out.append(float(alt))
            else:
                out.append(int(alt))
        except ValueError:
            what = "a number" if key == "loops" else "a whole number or a range lo..hi"
            raise BccError(f"{text!r}: {key} must be {what}, got {alt!r}") from None
    return out


def _check_maze(text: str, params: dict) -> None:
    from ..generate import generate_maze
    try:
        generate_maze(**params)
    except BccError as exc:
        raise BccError(f"{text!r}: {exc.message}") from None


def canonical_spec(kind: str, params: dict) -> str:
    shown = [f"{k}={params[k]:g}" if isinstance(params[k], float) else f"{k}={params[k]}"
             for k in MAZE_PARAMS if k in ALWAYS_SHOWN or params[k]]
    return f"{kind}:{','.join(shown)}"


def parse_spec(name: str) -> dict:
    """The generator parameters of one canonical spec (no ranges), defaults filled in."""
    kind, _, body = name.partition(":")
    params = dict(MAZE_PARAMS)
    for part in filter(None, body.split(",")):
        key, _, raw = part.partition("=")
        params[key] = float(raw) if key == "loops" else int(raw)
    return params


@contextlib.contextmanager
def open_dungeon(name: str):
    """A path or shipped name to compile; generator specs are generated into a temp file."""
    if not is_generator_spec(name):
        yield name
        return
    from ..generate import generate_maze
    text = generate_maze(**parse_spec(name))  # named maze_WxD_...: a spec is not a valid dungeon name
    with tempfile.TemporaryDirectory(prefix="bcc-batch-") as tmp:
        path = Path(tmp) / "generated.yaml"
        path.write_text(text, encoding="utf-8")
        yield str(path)
