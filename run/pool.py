"""The local backend: up to `workers` items at once, each in its own child process.

A fresh process per item (forked, so bcc is already imported: a few milliseconds) is
what makes the hard limits of `children.py` possible: a killed or crashed run takes no
pool down with it, unlike `concurrent.futures`, whose pool breaks for good when one
worker dies. Outcomes come back in completion order.
"""
from __future__ import annotations

import time
from multiprocessing.connection import wait
from typing import Callable, Iterable, Iterator

from .children import Child, Limits, Outcome, run_prepare


def map_local(function, items: Iterable, workers: int, limits_of: Callable[[object], Limits],
              prepare: Callable | None = None) -> Iterator[Outcome]:
    pending = iter(enumerate(items))
    running: dict[int, Child] = {}
    exhausted = False
    try:
        while True:
            while not exhausted and len(running) < workers:
                nxt = next(pending, None)
                if nxt is None:
                    exhausted = True
                    break
                index, item = nxt
                run_prepare(prepare, item)
                running[index] = Child(index, function, item, limits_of(item))
            if not running:
                return
            deadlines = [c.deadline for c in running.values() if c.deadline is not None]
            timeout = max(min(deadlines) - time.monotonic(), 0) if deadlines else None
            waitables = [(w, c) for c in running.values() for w in c.waitables()]
            ready = wait([w for w, _ in waitables], timeout)
            finished = {c.index: c for w, c in waitables if any(w is r for r in ready)}
            for index, child in finished.items():
                del running[index]
                yield child.finish()
            now = time.monotonic()
            for index, child in list(running.items()):
                if child.deadline is not None and now >= child.deadline:
                    del running[index]
                    yield child.expire()
    finally:  # Ctrl-C, or the consumer stopped early: no child outlives the sweep
        for child in running.values():
            child.kill()
