"""An on-disk cache of loaded dungeons (their YAML read and their domain's expressions
parsed), so a warm `bcc solve` skips YAML, lark and the grammar; of loaded domains, so a
new dungeon on a known domain (a generated structure) parses only itself; and of costly
analyses of a compiled model (`cached_analysis`: the pattern database).

Like `.pyc` files: safe to delete, rebuilt when stale, never trusted across versions.
An entry is found by the hash of bcc's version (a fingerprint of its code), Python's
version, the dungeon's path and its bytes; it lists every file the load read (dungeon, `extends` chain, domains) with its
SHA-256, and is used only if all of them still hash the same. Entries live in the user's
own cache folder (`$XDG_CACHE_HOME/bcc`, else `~/.cache/bcc`; `BCC_CACHE_DIR` overrides,
`BCC_NO_CACHE=1` turns the cache off), which is kept under 1 GB (`BCC_CACHE_MAX_MB`) by
deleting the least recently used entries; they are written atomically, and are read with an
unpickler that builds only bcc's own data classes and plain containers: a tampered
entry can fail to load (then it is ignored and rebuilt), but it cannot run code.
"""
from __future__ import annotations

import dataclasses
import functools
import hashlib
import io
import os
import pickle
import re
import sys
from pathlib import Path

FORMAT = 1
MAX_MB = 1024          # the cache folder's size at most (BCC_CACHE_MAX_MB): least recently used entries go first
_TRIM_TO = 0.8         # a trim leaves this share of the limit, so the next writes do not trim again at once
_STALE_TMP_SECONDS = 3600   # a temporary file this old was left by a writer that was killed
_ENTRY_NAME = re.compile(r"[0-9a-f]{40}\.pickle")
_TMP_NAME = re.compile(r"\.[0-9a-f]{40}\.pickle\.[0-9]+\.tmp")
_RECORDING: list | None = None   # while a load runs: the files it read


def note_read(path, data: bytes) -> None:
    """Called by the loader for every file it reads (source.py)."""
    if _RECORDING is not None:
        try:
            name = str(Path(path).resolve())
        except (OSError, ValueError):
            name = None
        _RECORDING.append((name, None if data is None else hashlib.sha256(data).hexdigest()))


def cache_dir() -> Path | None:
    if os.environ.get("BCC_NO_CACHE"):
        return None
    if os.environ.get("BCC_CACHE_DIR"):
        return Path(os.environ["BCC_CACHE_DIR"])
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "bcc"


@functools.lru_cache(maxsize=1)
def _version() -> str:
    """Which bcc wrote an entry: Python's version and a fingerprint (name, size, mtime) of
    the code that makes and reads what is cached (compiler/, heuristics/, model.py,
    errors.py, the grammar). Any other version or edit of that code gives other keys, so an entry is
    never read by a bcc other than the one that wrote it. (Cheaper than asking
    importlib.metadata for the version number, which scans every installed package.)"""
    root = Path(__file__).resolve().parent.parent
    parts = [f"{FORMAT}|{sys.version_info[:3]}"]
    for folder, pattern in (("compiler", "*.py"), ("heuristics", "*.py"), ("grammar", "*.lark"), (".", "model.py"),
                            (".", "errors.py")):
        for f in sorted((root / folder).glob(pattern)):
            st = f.stat()
            parts.append(f"{f.name}|{st.st_size}|{st.st_mtime_ns}")
    return hashlib.sha256("\n".join(parts).encode()).hexdigest()


def _entry(path: Path, data: bytes, kind: str = "dungeons") -> Path | None:
    folder = cache_dir()
    if folder is None:
        return None
    key = hashlib.sha256(b"\0".join([_version().encode(), str(path.resolve()).encode(), data])).hexdigest()
    return folder / kind / f"{key[:40]}.pickle"


def _fresh(files) -> bool:
    for name, digest in files:
        try:
            with open(name, "rb") as f:
                if hashlib.sha256(f.read()).hexdigest() != digest:
                    return False
        except OSError:
            return False
    return True


def load_cached(path: Path, load, kind: str = "dungeons"):
    """`load(path)`, or the cached result of an earlier load of the same files. Loads nest
    (a dungeon's load reads its domain through a cached load of its own, kind "domains":
    a new dungeon on a shipped domain skips the domain's YAML and lark): the files an
    inner load read, found or loaded, are the outer entry's files too."""
    global _RECORDING
    try:
        with open(path, "rb") as f:
            data = f.read()
        entry = _entry(path, data, kind)
    except (OSError, ValueError):
        entry = None
    if entry is not None:
        found = _read(entry, want_record=True)
        if found is not None:
            if _RECORDING is not None:
                _RECORDING.extend(found.get("files", ()))
            return found["value"]
    outer, _RECORDING = _RECORDING, []
    try:
        value = load(path)
        files = _RECORDING
    finally:
        _RECORDING = outer
    if outer is not None:
        outer.extend(files)
    if entry is not None and files and all(name and digest for name, digest in files):
        _write(entry, {"version": _version(), "files": files, "value": value})
    return value


def cached_analysis(kind: str, key: bytes, build):
    """`build()`, or what an earlier build under the same key left in the cache: for
    analyses of a compiled model that cost more than compiling it (the pattern database
    of a big maze). `key` must hash everything the analysis is computed from; bcc's own
    code is in every key already."""
    folder = cache_dir()
    if folder is None:
        return build()
    digest = hashlib.sha256(b"\0".join([_version().encode(), kind.encode(), key])).hexdigest()
    entry = folder / kind / f"{digest[:40]}.pickle"
    found = _read(entry)
    if found is not None:
        return found
    value = build()
    if value is not None:
        _write(entry, {"version": _version(), "files": [], "value": value})
    return value


def _read(entry: Path, want_record: bool = False):
    """The value of a fresh entry (with `want_record`, the whole record: value and files), or None."""
    try:
        with open(entry, "rb") as f:
            record = _SafeUnpickler(f).load()
    except FileNotFoundError:
        return None
    except Exception:  # noqa: BLE001 - a damaged or foreign entry is a miss, rebuilt below
        return None
    if not isinstance(record, dict) or record.get("version") != _version() or not _fresh(record.get("files", ())):
        return None
    try:
        os.utime(entry)   # used now: the trim keeps recently used entries
    except OSError:
        pass
    return record if want_record else record.get("value")


def _write(entry: Path, record: dict) -> None:
    try:
        blob = pickle.dumps(record, protocol=pickle.HIGHEST_PROTOCOL)
        entry.parent.mkdir(parents=True, exist_ok=True)
        tmp = entry.with_name(f".{entry.name}.{os.getpid()}.tmp")
        with open(tmp, "wb") as f:
            f.write(blob)
        os.replace(tmp, entry)   # atomic: readers see the old entry or the whole new one
    except Exception:  # noqa: BLE001 - no cache (read-only home, full disk, an unpicklable value): just slower
        try:
            tmp.unlink()
        except Exception:  # noqa: BLE001
            pass
        return
    trim(entry.parent.parent, keep=entry)


def max_bytes() -> int:
    try:
        mb = float(os.environ.get("BCC_CACHE_MAX_MB", MAX_MB))
    except ValueError:
        mb = MAX_MB
    return int(max(mb, 0) * 1024 * 1024)


def trim(folder: Path, keep: Path | None = None) -> None:
    """Keep the cache folder under `max_bytes()`: entries of other bcc versions are never
    read again and a batch of big mazes writes many, so after a write the least recently
    used entries (by modification time, which a read refreshes) are deleted until the
    folder is at most 80 % of the limit; `keep` (the entry just written) stays. Temporary
    files of killed writers go once they are an hour old. Races with other processes are
    harmless: a deleted entry is a miss and is rebuilt."""
    import time
    limit = max_bytes()
    entries, total, now = [], 0, time.time()
    try:
        for path in folder.glob("*/*"):   # only bcc's own names: BCC_CACHE_DIR may hold other files
            entry, tmp = _ENTRY_NAME.fullmatch(path.name), _TMP_NAME.fullmatch(path.name)
            if not (entry or tmp):
                continue
            try:
                st = path.lstat()
            except OSError:
                continue
            if tmp:
                if now - st.st_mtime > _STALE_TMP_SECONDS:
                    path.unlink(missing_ok=True)
                continue
            entries.append((st.st_mtime, st.st_size, path))
            total += st.st_size
    except OSError:
        return
    if total <= limit:
        return
    for _, size, path in sorted(entries, key=lambda e: e[0]):
        if total <= limit * _TRIM_TO:
            break
        if keep is not None and path == keep:
            continue
        try:
            path.unlink()
            total -= size
        except OSError:
            pass


_SAFE_BUILTINS = {"dict", "list", "tuple", "set", "frozenset", "str", "bytes", "bytearray", "int", "float",
                  "bool", "complex", "NoneType", "slice", "range"}
_SAFE_GLOBALS = {("copyreg", "_reconstructor"), ("copyreg", "__newobj__"), ("builtins", "object"),
                 ("numpy", "ndarray"), ("numpy", "dtype"), ("numpy.core.multiarray", "_reconstruct"),
                 ("numpy._core.multiarray", "_reconstruct"), ("numpy.core.multiarray", "scalar"),
                 ("numpy._core.numeric", "_frombuffer"), ("numpy.core.numeric", "_frombuffer"),
                 ("numpy._core.multiarray", "scalar"), ("pathlib", "PosixPath"), ("pathlib", "WindowsPath"),
                 ("pathlib", "Path")}
_DATA_MODULES = ("bcc.compiler.", "bcc.heuristics.", "bcc.errors", "yaml.nodes", "yaml.error")


class _SafeUnpickler(pickle.Unpickler):
    """Builds plain containers, numpy arrays and data classes of bcc's compiler and
    heuristics (and the YAML nodes they keep for positions); any other global -- a function, os.system -- is
    refused, so an entry cannot run code."""

    def find_class(self, module: str, name: str):
        if module == "builtins" and name in _SAFE_BUILTINS or (module, name) in _SAFE_GLOBALS:
            return super().find_class(module, name)
        if module.startswith(_DATA_MODULES):
            found = super().find_class(module, name)
            if isinstance(found, type) and (dataclasses.is_dataclass(found)
                                            or issubclass(found, (dict, list, str, BaseException))
                                            or module.startswith("yaml.")):
                return found
        raise pickle.UnpicklingError(f"the cache may not build {module}.{name}")


def load_bytes(blob: bytes):
    """Unpickle `blob` as a cache entry is read (for tests)."""
    return _SafeUnpickler(io.BytesIO(blob)).load()
