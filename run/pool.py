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

from .children import Child, Limits, Outcome, run_prepare, timer_held


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
                limits = limits_of(item)
                with timer_held():  # no raise between the fork and the child's entry in `running`
                    running[index] = Child(index, function, item, limits)
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
    finally:  # Ctrl-C, a spent budget, or the consumer stopped early: no child outlives the sweep
        _kill_all(running)


def _kill_all(running: dict[int, Child]) -> None:
    """Kill and reap every child in `running`, with the budget's timer held back. A raise can
    still land inside the hold when its signal came just before it (its handler runs at the
    next step, e.g. after a long garbage collection on a loaded machine): the sweep then goes
    on with the children left, and the first such error is raised once all are reaped."""
    error: BaseException | None = None
    while running:
        try:
            with timer_held():
                while running:
                    index, child = next(iter(running.items()))
                    child.kill()        # idempotent: a retry after a raise inside it is safe
                    del running[index]
        except BaseException as exc:  # noqa: BLE001 - kept and raised after the sweep
            error = error or exc
    if error is not None:
        raise error
