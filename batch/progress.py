"""A one-line progress bar on stderr: done, failed, rate, ETA. Only on a terminal."""
from __future__ import annotations

import sys
import time


class ProgressBar:
    WIDTH = 24

    def __init__(self, total: int, stream=None, enabled: bool | None = None):
        self.stream = stream or sys.stderr
        self.enabled = self.stream.isatty() if enabled is None else enabled
        self.total, self.done, self.failed = total, 0, 0
        self.start = time.monotonic()
        self.last = 0.0

    def update(self, solved: bool) -> None:
        self.done += 1
        self.failed += not solved
        now = time.monotonic()
        if self.enabled and (now - self.last >= 0.2 or self.done == self.total):
            self.last = now
            self.stream.write("\r" + self.line(now - self.start))
            self.stream.flush()

    def line(self, elapsed: float) -> str:
        fill = int(self.WIDTH * self.done / self.total) if self.total else self.WIDTH
        rate = self.done / elapsed if elapsed > 0 else 0.0
        eta = (self.total - self.done) / rate if rate > 0 else None
        return (f"[{'#' * fill}{'.' * (self.WIDTH - fill)}] {self.done}/{self.total} done, "
                f"{self.failed} failed, {rate:.2f} runs/s, ETA {_clock(eta)}   ")

    def close(self) -> None:
        if self.enabled and self.done:
            self.stream.write("\n")
            self.stream.flush()


def _clock(seconds: float | None) -> str:
    if seconds is None:
        return "--:--"
    seconds = int(seconds + 0.5)
    h, rest = divmod(seconds, 3600)
    m, s = divmod(rest, 60)
    return f"{h}:{m:02d}:{s:02d}" if h else f"{m:02d}:{s:02d}"
