"""Write files atomically: a temporary file beside the target, then os.replace.

A reader never sees half a file, and an interrupted write leaves the old file intact."""
from __future__ import annotations

import os
import tempfile
from pathlib import Path

from .errors import BccError


def _temporary(path: Path) -> tuple[int, str]:
    """A new temporary file beside `path` (fd, name); BccError if the folder cannot take one."""
    directory = path.parent if str(path.parent) else Path(".")
    try:
        return tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=directory)
    except OSError as exc:
        raise BccError(f"cannot write {path}: {exc.strerror}") from None


def check_writable(path: str | Path) -> None:
    """Fail now, with the message `write_bytes` would give, if `path` cannot be written:
    for commands that work a long time (a play session, a solve) before they write."""
    fd, tmp = _temporary(Path(path))
    os.close(fd)
    Path(tmp).unlink(missing_ok=True)


def write_text(path: str | Path, text: str) -> None:
    write_bytes(path, text.encode("utf-8"))


def write_bytes(path: str | Path, data: bytes) -> None:
    path = Path(path)
    fd, tmp = _temporary(path)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # mkstemp makes 0600; a written file gets the usual mode
        os.replace(tmp, path)
    except OSError as exc:
        Path(tmp).unlink(missing_ok=True)
        raise BccError(f"cannot write {path}: {exc.strerror}") from None
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
