"""Hard limits where a run executes: each item runs in a fresh forked child process.

Solvers stop themselves at their budget (cooperatively); this is the backstop for code
that does not: the child gets an address-space limit (`RLIMIT_AS`), so unbounded
allocation ends in a MemoryError, and a wall-clock deadline after which the parent
kills it. A child that dies (os._exit, a segfault, the OOM killer) is reported, never
waited for. Either way the caller gets an `Outcome`, so a sweep goes on.

Every fan-out uses this: the local pool (pool.py: batch sweeps, the grounding
cross-validation) runs many `Child`ren at once; a Ray task (batch/ray_backend.py) runs
one with `run_limited`, so a runaway run never takes a Ray worker down.
"""
from __future__ import annotations

import contextlib
import multiprocessing
import os
import signal
import threading
import time
from dataclasses import dataclass
from multiprocessing.connection import wait

KILL_GRACE = 5.0    # seconds a child has to exit after it sent its result


@dataclass(frozen=True)
class Limits:
    """Hard limits of one item: wall-clock seconds and extra memory in MB (None = none)."""
    wall_seconds: float | None = None
    memory_mb: float | None = None

    @staticmethod
    def around(time_limit: float | None, memory_mb: float | None) -> "Limits":
        """Hard limits for a run whose solver has these cooperative budgets: wide enough that
        a well-behaved solver always stops itself first (compiling is not in its budget)."""
        return Limits(None if time_limit is None else time_limit * 1.5 + 30,
                      None if memory_mb is None else memory_mb * 1.5 + 256)


@dataclass
class Outcome:
    """How one item ended. `value` is the function's return value when it returned; else
    `error` is a one-line message, and `limit` says which hard limit stopped it
    ("time_limit" or "max_memory"), or is None when it raised or its process died."""
    index: int
    value: object = None
    error: str | None = None
    limit: str | None = None
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        return self.error is None and self.limit is None


def one_line(exc: BaseException) -> str:
    text = " ".join(str(exc).split())
    from ..errors import BccError
    if isinstance(exc, BccError):
        return text
    return f"{type(exc).__name__}: {text}" if text else type(exc).__name__


def _die_with_parent() -> None:
    """Linux: the kernel kills this child when its parent dies (a killed sweep leaves no
    orphans computing runs whose results nobody will record)."""
    try:
        import ctypes
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
    except (OSError, AttributeError):
        pass


def _child_main(conn, function, item, memory_mb, orphan_kill) -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle
    signal.signal(signal.SIGALRM, signal.SIG_DFL)   # the pool forks with the parent's timer held
    if orphan_kill:
        _die_with_parent()
    if memory_mb is not None:
        from ..solvers.memory import cap_growth
        cap_growth(memory_mb)
    try:
        message = ("ok", function(item))
    except MemoryError:
        message = ("limit", "max_memory", "stopped: ran out of memory (hard limit of the worker)")
    except BaseException as exc:  # noqa: BLE001 - every failure becomes the run's error row
        message = ("error", one_line(exc))
    try:
        conn.send(message)
    except Exception as exc:  # noqa: BLE001 - e.g. a result that cannot be pickled
        conn.send(("error", f"cannot send the result back: {one_line(exc)}"))
    conn.close()


class Child:
    """One item running in its own process, with its deadline."""

    def __init__(self, index: int, function, item, limits: Limits, orphan_kill: bool = True):
        ctx = multiprocessing.get_context("fork")
        self.index, self.limits = index, limits
        self.conn, child_conn = ctx.Pipe(duplex=False)
        self.process = ctx.Process(target=_child_main, daemon=True,
                                   args=(child_conn, function, item, limits.memory_mb, orphan_kill))
        self.start = time.monotonic()
        self.process.start()
        child_conn.close()
        self.deadline = None if limits.wall_seconds is None else self.start + limits.wall_seconds

    def waitables(self) -> list:
        return [self.conn, self.process.sentinel]

    def finish(self) -> Outcome:
        """Collect the result of a child that sent it or died (call when a waitable is ready)."""
        seconds = time.monotonic() - self.start
        message = None
        try:
            if self.conn.poll():
                message = self.conn.recv()
        except (EOFError, OSError):
            message = None
        self.process.join(KILL_GRACE if message is not None else None)
        if self.process.is_alive():
            self.kill()
        self.conn.close()
        if message is None:
            return Outcome(self.index, error=_death(self.process.exitcode), seconds=seconds)
        if message[0] == "ok":
            return Outcome(self.index, value=message[1], seconds=seconds)
        if message[0] == "limit":
            return Outcome(self.index, error=message[2], limit=message[1], seconds=seconds)
        return Outcome(self.index, error=message[1], seconds=seconds)

    def expire(self) -> Outcome:
        self.kill()
        self.conn.close()
        return Outcome(self.index, limit="time_limit", seconds=time.monotonic() - self.start,
                       error=f"killed after {self.limits.wall_seconds:g} s (hard wall-clock limit of the worker)")

    def kill(self) -> None:
        if self.process.is_alive():
            try:
                os.kill(self.process.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        self.process.join()


def _death(exitcode) -> str:
    if exitcode is not None and exitcode < 0:
        try:
            name = signal.Signals(-exitcode).name
        except ValueError:
            name = f"signal {-exitcode}"
        hint = " (out of memory?)" if -exitcode == signal.SIGKILL else ""
        return f"worker died: killed by {name}{hint}"
    return f"worker died: exit status {exitcode} before returning a result"


def run_prepare(prepare, item) -> None:
    if prepare is not None:
        try:
            prepare(item)
        except Exception:  # noqa: BLE001 - the child meets the same problem and reports it as the item's
            pass


def run_limited(function, item, limits: Limits, index: int = 0, prepare=None) -> Outcome:
    """Run function(item) in a child process under `limits`; always returns an Outcome.
    `prepare(item)` runs first, in this process (see `map_runs`)."""
    run_prepare(prepare, item)
    with timer_held():
        child = Child(index, function, item, limits, orphan_kill=False)
    try:
        timeout = None if child.deadline is None else max(child.deadline - time.monotonic(), 0)
        ready = wait(child.waitables(), timeout)
        return child.finish() if ready else child.expire()
    except BaseException:
        child.kill()
        raise


@contextlib.contextmanager
def timer_held():
    """Hold back the budget's timer (solvers/limits.py: it fires again every 0.25 s once the
    time is spent) while a child is started and recorded, or children are killed and
    reaped: a raise in between would leave one running. A signal that comes meanwhile is
    noted, and its handler runs once the hold ends.

    The handler itself is swapped out, not the signal blocked: the timer's signal goes to
    the process, and blocking it in the main thread only sends it to another thread (a
    server's, a library's), after which Python still runs the handler in the main thread.
    That way a raise landed inside every slow kill of a sweep, which retried forever (CI
    hung there with its children already dead)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    fired: list = []
    old = signal.signal(signal.SIGALRM, lambda signum, frame: fired.append(signum))
    try:
        yield
    finally:
        signal.signal(signal.SIGALRM, signal.SIG_DFL if old is None else old)
        if fired and callable(old):
            old(signal.SIGALRM, None)
