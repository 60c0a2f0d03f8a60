"""The results file: JSON Lines, one row per finished run, appended atomically.

Each row is one `os.write` of a whole line on an O_APPEND descriptor, then `fsync`: a
reader sees a row entirely or not at all, and a killed sweep keeps every row it wrote.
The only damage a crash can leave is a torn last line (a write the kernel cut short,
e.g. on a full disk); `ResultsFile.open_for_append` drops it, and `read_rows` reports
it instead of failing.
"""
from __future__ import annotations

import json
import os
from dataclasses import dataclass, field

from ..errors import BccError


@dataclass
class Contents:
    rows: list = field(default_factory=list)
    bad_lines: list = field(default_factory=list)   # 1-based numbers of lines that are not rows
    torn_tail: int = 0                               # bytes of an unfinished last line

    def check_is_results(self, path: str) -> None:
        """Refuse a file with content but not one row: it is some other file (a typo in
        --out or RESULTS), which a sweep must not append to, nor cut a "torn" line from."""
        if self.rows or not (self.bad_lines or self.torn_tail):
            return
        line = self.bad_lines[0] if self.bad_lines else None
        raise BccError("not a bcc batch results file (JSON Lines, one row per run)", path, line,
                       1 if line else None)


def read_rows(path: str) -> Contents:
    """The rows of a results file (missing file: none). Unreadable lines are reported in
    `bad_lines` (a row is a JSON object with a `key` and a `solver`), an unfinished last
    line in `torn_tail`; neither is an error here (see `Contents.check_is_results`)."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except FileNotFoundError:
        return Contents()
    except OSError as exc:
        raise BccError(f"cannot read results: {exc.strerror}", path) from None
    out = Contents()
    body, _, tail = data.rpartition(b"\n")
    out.torn_tail = len(tail)
    for number, line in enumerate(body.split(b"\n") if body or data.startswith(b"\n") else [], start=1):
        if not line.strip():
            continue
        try:
            row = json.loads(line)
        except (ValueError, UnicodeDecodeError):
            out.bad_lines.append(number)
            continue
        if isinstance(row, dict) and "key" in row and "solver" in row:
            out.rows.append(row)
        else:
            out.bad_lines.append(number)
    return out


def _end_of_last_line(path: str, size: int, block: int = 65536) -> int:
    """The offset just past the file's last newline (0 if none): what stays when a torn
    last line, however long, is cut off. Reads backwards a block at a time."""
    with open(path, "rb") as f:
        end = size
        while end > 0:
            start = max(end - block, 0)
            f.seek(start)
            newline = f.read(end - start).rfind(b"\n")
            if newline >= 0:
                return start + newline + 1
            end = start
    return 0


LOCK_WAIT_SECONDS = 10.0   # a killed sweep's workers hold its lock until they exit too


def _lock(fd: int, wait: float) -> bool:
    """Take the results file's lock (released when every process holding it has ended),
    waiting up to `wait` seconds: the workers of a sweep killed a moment ago inherited it
    and are still on their way out (they die with their parent)."""
    import fcntl
    import time
    deadline = time.monotonic() + wait
    while True:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            return True
        except BlockingIOError:
            if time.monotonic() >= deadline:
                return False
            time.sleep(0.05)


class ResultsFile:
    """Appends rows to `path`; use as a context manager."""

    def __init__(self, path: str):
        self.path = path
        self.fd: int | None = None

    def __enter__(self) -> "ResultsFile":
        self.open_for_append()
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def open_for_append(self) -> int:
        """Open (creating it), lock it against a second sweep writing the same file, and cut
        off a torn last line; returns how many bytes were cut."""
        try:
            self.fd = os.open(self.path, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o666)
            if not _lock(self.fd, LOCK_WAIT_SECONDS):
                self.close()
                raise BccError("another `bcc batch` is writing this results file; wait for it, "
                               "or choose another --out", self.path) from None
            size = os.fstat(self.fd).st_size
            keep = _end_of_last_line(self.path, size)
            cut = size - keep
            if cut:
                os.truncate(self.path, keep)
            return cut
        except OSError as exc:
            raise BccError(f"cannot write results: {exc.strerror}", self.path) from None

    def append(self, row: dict) -> None:
        line = (json.dumps(row, sort_keys=False, default=str) + "\n").encode("utf-8")
        try:
            written = os.write(self.fd, line)
            while written < len(line):  # only on a full disk or a signal; the rest follows at once
                written += os.write(self.fd, line[written:])
            os.fsync(self.fd)
        except OSError as exc:
            raise BccError(f"cannot write results: {exc.strerror}", self.path) from None

    def close(self) -> None:
        if self.fd is not None:
            os.close(self.fd)
            self.fd = None
