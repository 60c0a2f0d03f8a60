"""Write files atomically: a temporary file beside the target, then os.replace.

A reader never sees half a file, and an interrupted write leaves the old file intact.
Where Linux offers it, the data is first written to an unnamed file (O_TMPFILE) that gets
its temporary name only once complete, so even a SIGKILL leaves no empty or half-written
temporary file behind; checking that a folder is writable creates no file at all.
"""
from __future__ import annotations

import errno
import os
from pathlib import Path

from .errors import BccError

# Errors that mean "no unnamed files here" (old kernels, some file systems, no /proc):
# fall back to a named temporary file.
_NO_TMPFILE = {errno.EOPNOTSUPP, errno.EISDIR, errno.EINVAL, errno.ENOENT, errno.EPERM, errno.EXDEV}


def _folder(path: Path) -> Path:
    return path.parent if str(path.parent) else Path(".")


def _cannot(path: Path, exc: OSError) -> BccError:
    return BccError(f"cannot write {path}: {exc.strerror}")


def _temporary(path: Path) -> tuple[int, str]:
    """A new named temporary file beside `path` (fd, name); BccError if the folder cannot take one."""
    import tempfile    # only where unnamed files are not offered: 3 ms of every command's start-up
    try:
        return tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=_folder(path))
    except OSError as exc:
        raise _cannot(path, exc) from None


def _unnamed(path: Path) -> int | None:
    """An unnamed file in `path`'s folder (it vanishes unless linked), or None where the
    system cannot make one; BccError when the folder refuses files."""
    flag = getattr(os, "O_TMPFILE", None)
    if flag is None:
        return None
    try:
        return os.open(_folder(path), flag | os.O_WRONLY, 0o600)
    except OSError as exc:
        if exc.errno in _NO_TMPFILE and _folder(path).is_dir():
            return None
        raise _cannot(path, exc) from None


def check_writable(path: str | Path) -> None:
    """Fail now, with the message `write_bytes` would give, if `path` cannot be written:
    for commands that work a long time (a play session, a solve) before they write."""
    path = Path(path)
    fd = _unnamed(path)
    if fd is None:
        fd, tmp = _temporary(path)
        Path(tmp).unlink(missing_ok=True)
    os.close(fd)


def write_text(path: str | Path, text: str) -> None:
    write_bytes(path, text.encode("utf-8"))


def _fill(fd: int, data: bytes, mode: int) -> None:
    os.fchmod(fd, mode)  # temporary files start 0600; the written file gets the usual mode
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view):]
    os.fsync(fd)


def write_bytes(path: str | Path, data: bytes) -> None:
    path = Path(path)
    umask = os.umask(0)
    os.umask(umask)
    mode = 0o666 & ~umask
    fd = _unnamed(path)
    if fd is not None:
        tmp = _folder(path) / f".{path.name}.{os.getpid()}.{os.urandom(4).hex()}.tmp"
        try:
            _fill(fd, data, mode)
            os.link(f"/proc/self/fd/{fd}", tmp)  # named only now, complete
        except OSError as exc:
            if exc.errno not in _NO_TMPFILE:
                raise _cannot(path, exc) from None
            tmp = None  # no /proc: write a named temporary file instead
        finally:
            os.close(fd)
        if tmp is not None:
            try:
                os.replace(tmp, path)
            except BaseException as exc:
                tmp.unlink(missing_ok=True)
                if isinstance(exc, OSError):
                    raise _cannot(path, exc) from None
                raise
            return
    fd, name = _temporary(path)
    try:
        _fill(fd, data, mode)
        os.close(fd)
        fd = None
        os.replace(name, path)
    except BaseException as exc:
        if fd is not None:
            os.close(fd)
        Path(name).unlink(missing_ok=True)
        if isinstance(exc, OSError):
            raise _cannot(path, exc) from None
        raise
