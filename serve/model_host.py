"""A sandboxed process that compiles posted dungeons and steps them, keeping the models.

Posted text is never compiled in the server's own process: a dungeon's names, sizes and
expressions are input, and compiling runs generated code. Drawing and stepping a posted
dungeon (/replay, /demonstration) need the model many times in a row, so instead of a
throwaway job per request, one long-lived process forked from the fork server holds
them (least recently used out). It runs under the same address-space cap as a job; a
request that runs past its wall clock, or a process that dies (out of memory), is
killed and the next request starts a fresh one. Requests take turns.
"""
from __future__ import annotations

import threading
import time

from .sandbox import _CTX, Outcome


class ModelHost:
    def __init__(self, memory_mb: float, wall_seconds: float, cache_size: int = 8):
        self.memory_mb, self.wall_seconds, self.cache_size = memory_mb, wall_seconds, cache_size
        self._lock = threading.Lock()
        self._process = None
        self._conn = None

    def _start(self) -> None:
        from . import worker
        parent, child = _CTX.Pipe(duplex=True)
        self._process = _CTX.Process(target=worker.host_main, args=(child, self.memory_mb, self.cache_size),
                                     daemon=True)
        self._process.start()
        child.close()
        self._conn = parent

    def _stop(self) -> None:
        if self._process is not None and self._process.is_alive():
            self._process.kill()
        if self._process is not None:
            self._process.join(5)
        if self._conn is not None:
            self._conn.close()
        self._process = self._conn = None

    def call(self, task: str, spec: dict) -> Outcome:
        """Run `task` ("replay" | "demonstration" | "compile") on the posted dungeon in `spec`."""
        with self._lock:
            if self._process is None or not self._process.is_alive():
                self._stop()
                self._start()
            try:
                self._conn.send((task, spec))
                deadline = time.monotonic() + self.wall_seconds
                while not self._conn.poll(0.2):
                    if time.monotonic() > deadline:
                        self._stop()
                        return Outcome("timeout", f"stepping the posted dungeon ran past {self.wall_seconds:g} s "
                                                  "and was stopped")
                    if not self._process.is_alive():
                        break
                return Outcome(*self._conn.recv())
            except (EOFError, OSError):
                self._stop()
                return Outcome("failed", "the process holding posted dungeons stopped (out of memory?)")

    def shutdown(self) -> None:
        with self._lock:
            self._stop()
