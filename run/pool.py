"""The local backend: up to `workers` items at once, each in its own child process.

A fresh process per item (forked, so bcc is already imported: a few milliseconds) is
what makes the hard limits of `children.py` possible: a killed or crashed run takes no
pool down with it, unlike `concurrent.futures`, whose pool breaks for good when one
worker dies. Outcomes come back in completion order.
"""
from __future__ import annotations

import contextlib
import signal
import threading
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
    finally:  # Ctrl-C, a spent budget, or the consumer stopped early: no child outlives the sweep
        with _timer_held():
            for child in running.values():
                child.kill()


@contextlib.contextmanager
def _timer_held():
    """Hold back the budget's timer (solvers/limits.py: it fires again every 0.25 s once the
    time is spent) while children are killed and reaped: a raise in the middle of the sweep
    would leave the rest running. A signal that came meanwhile is delivered after."""
    held = threading.current_thread() is threading.main_thread()
    if held:
        signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGALRM})
    try:
        yield
    finally:
        if held:
            signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGALRM})
