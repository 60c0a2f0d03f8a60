"""Compiled models kept in the server process, for drawing and stepping (not for solving).

Shipped dungeons are trusted and compiled here directly. Posted text (a dungeon, or a
goal replacing a shipped dungeon's) is compiled only in a job process under the memory
and time limits (`sandbox.run("compile")`), which answers its report; drawing and
stepping it happen in the model host (`model_host.py`), never here, so a hostile
dungeon can exhaust a throwaway process but never the server. Reports and models are
cached by the dungeon (name or text hash) and goal, least recently used first out.
"""
from __future__ import annotations

import threading
from collections import OrderedDict

from ..errors import BccError
from . import sandbox
from .posted import DungeonRef, compile_ref


def trusted(ref: DungeonRef, goal: str | None) -> bool:
    """A shipped dungeon with its own goal is safe to compile in the server. A posted goal
    is text too (nested quantifiers can ground into millions of terms), so it is checked."""
    return ref.name is not None and goal is None


class CompileRejected(Exception):
    """Posted text that did not compile: `body` is the 400 body, `status` the HTTP code."""

    def __init__(self, body: dict, status: int = 400):
        super().__init__(body.get("error"))
        self.body, self.status = body, status


class _LRU:
    def __init__(self, size: int):
        self.size, self._items, self._lock = size, OrderedDict(), threading.Lock()

    def get_fresh(self, key):
        with self._lock:
            if key in self._items:
                self._items.move_to_end(key)
                return self._items[key]
            return None

    def put(self, key, value):
        with self._lock:
            self._items[key] = value
            self._items.move_to_end(key)
            while len(self._items) > self.size:
                self._items.popitem(last=False)


class CompiledCache:
    def __init__(self, memory_mb: float, wall_seconds: float, checks: int = 2, size: int = 32):
        self.memory_mb, self.wall_seconds = memory_mb, wall_seconds
        self._reports = _LRU(256)
        self._models = _LRU(size)
        self._lock = threading.Lock()            # one in-process compile at a time (the GIL allows no more)
        self._checks = threading.BoundedSemaphore(checks)  # processes spent on checks at once

    def report(self, ref: DungeonRef, goal: str | None) -> dict:
        """The compile report (`bcc compile --json`), or CompileRejected."""
        key = (ref.key, goal)
        cached = self._reports.get_fresh(key)
        if cached is None:
            if trusted(ref, goal):
                model = self.model(ref, goal)[0]
                cached = ("ok", model.compile_report())
            else:
                with self._checks:
                    outcome = sandbox.run("compile", {"ref": {"name": ref.name, "text": ref.text}, "goal": goal},
                                          self.memory_mb, self.wall_seconds)
                if outcome.kind == "ok":
                    cached = ("ok", outcome.payload)
                elif outcome.kind == "bad_input":
                    cached = ("bad_input", outcome.payload)
                else:  # over its memory or time: the same text would fail again
                    cached = ("limits", {"error": f"compiling the dungeon failed: {outcome.payload}",
                                         "line": None, "column": None, "file": None})
            self._reports.put(key, cached)
        kind, body = cached
        if kind == "ok":
            return body
        raise CompileRejected(body, 400 if kind == "bad_input" else 422)

    def model(self, ref: DungeonRef, goal: str | None):
        """(Model, rooms) of a shipped dungeon, for drawing. Posted text is never compiled
        in the server's process (`model_host.py` holds those models)."""
        if not trusted(ref, goal):
            raise RuntimeError("posted text is compiled only in the model host")
        key = (ref.key, goal)
        with self._lock:
            cached = self._models.get_fresh(key)
            if cached is None:
                try:
                    cached = compile_ref(ref, goal, with_rooms=True)
                except BccError as exc:
                    from .posted import public_error
                    raise CompileRejected(public_error(exc)) from None
                self._models.put(key, cached)
            return cached
