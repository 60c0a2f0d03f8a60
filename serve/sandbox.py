"""One job, one process: started from a fork server, watched by a wall clock, killable.

A runaway solve (memory, time, a crash in generated code) can only end its own process.
Processes come from multiprocessing's *forkserver*: forking the server itself would copy
its threads' locks mid-flight, and spawning a fresh interpreter per job costs a second
of imports; the fork server is a clean process that imports bcc and compiles the shipped
dungeons once (`worker.py`, `preload.py`), and every job is a fork of it.
"""
from __future__ import annotations

import multiprocessing
import threading
import time
from dataclasses import dataclass

_CTX = multiprocessing.get_context("forkserver")
_CTX.set_forkserver_preload(["bcc.serve.worker", "bcc.serve.preload"])


@dataclass
class Outcome:
    kind: str            # "ok" | "bad_input" | "memory" | "failed" | "timeout" | "killed"
    payload: object      # the result, the 400 body, or a message


class JobProcess:
    """A child running `worker.main(task, spec)`; `wait` returns its Outcome."""

    def __init__(self, task: str, spec: dict, memory_mb: float, wall_seconds: float):
        from . import worker
        self.wall_seconds, self.memory_mb = wall_seconds, memory_mb
        self._recv, send = _CTX.Pipe(duplex=False)
        self._killed = threading.Event()
        self._process = _CTX.Process(target=worker.main, args=(send, task, spec, memory_mb), daemon=True)
        self._process.start()
        send.close()  # the child holds the only writer: its death is our EOF

    def kill(self) -> None:
        """Stop the job now (DELETE, or the wall clock); `wait` then reports "killed"."""
        self._killed.set()
        if self._process.is_alive():
            self._process.kill()

    def wait(self) -> Outcome:
        deadline = time.monotonic() + self.wall_seconds
        message = None
        try:
            while True:
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    self._process.kill()
                    self._process.join(5)
                    return Outcome("timeout", f"the job ran past its wall-clock limit of {self.wall_seconds:g} s "
                                              "and was stopped")
                if self._recv.poll(min(remaining, 0.5)):
                    try:
                        message = self._recv.recv()
                    except (EOFError, OSError):
                        message = None
                    break
                if self._killed.is_set():
                    break
        finally:
            self._recv.close()
        self._process.join(5)
        if self._process.is_alive():
            self._process.kill()
            self._process.join(5)
        if message is None and self._killed.is_set():
            return Outcome("killed", "the job was cancelled")
        if message is None:
            code = self._process.exitcode
            how = f"was killed by signal {-code}" if code is not None and code < 0 else f"exited with code {code}"
            # Under its address-space cap, an allocation that fails in C (not as a Python
            # MemoryError) ends the process by a signal: the likely cause, said as such.
            return Outcome("failed", f"the job's process {how} before it reported, most likely at its memory limit "
                                     f"of {self.memory_mb:g} MB")
        return Outcome(*message)


def run(task: str, spec: dict, memory_mb: float, wall_seconds: float) -> Outcome:
    """Run one task to the end in its own process (used for compile checks)."""
    return JobProcess(task, spec, memory_mb, wall_seconds).wait()


def warm_up() -> None:
    """Start the fork server now, so the first request does not wait for its imports."""
    run("compile", {"ref": {"name": "grid"}}, 512, 60)
