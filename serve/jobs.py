"""Solve jobs: a queue, N runner threads (so at most N solves run at once), an expiry.

Each runner thread takes the next queued job, runs it in its own process
(`sandbox.JobProcess`) and records how it ended. A job is `queued`, `running`, then
exactly one of `done` (the solver returned a result, solved or not), `failed` (bad
input, the memory cap, the wall clock, a crash) or `cancelled` (DELETE). Finished jobs
are kept in memory for `keep_seconds`, then forgotten.
"""
from __future__ import annotations

import itertools
import queue
import secrets
import threading
import time
from dataclasses import dataclass, field

from .sandbox import JobProcess

FINISHED = ("done", "failed", "cancelled")


@dataclass
class Job:
    id: str
    spec: dict
    memory_mb: float
    wall_seconds: float
    status: str = "queued"
    result: dict | None = None
    error: str | None = None
    submitted: float = field(default_factory=time.time)
    started: float | None = None
    finished: float | None = None
    process: JobProcess | None = None

    def to_json(self) -> dict:
        return {"id": self.id, "status": self.status, "result": self.result, "error": self.error,
                "dungeon": self.spec.get("dungeon_name"), "solver": self.spec.get("solver"),
                "submitted": self.submitted, "started": self.started, "finished": self.finished}


class QueueFull(Exception):
    pass


class JobManager:
    def __init__(self, workers: int = 2, keep_seconds: float = 3600, max_queued: int = 1000):
        self.workers, self.keep_seconds, self.max_queued = workers, keep_seconds, max_queued
        self._jobs: dict[str, Job] = {}
        self._queue: queue.Queue = queue.Queue()
        self._lock = threading.Lock()
        self._counter = itertools.count(1)
        self._stopping = False
        self._threads = [threading.Thread(target=self._run, name=f"bcc-job-runner-{i}", daemon=True)
                         for i in range(workers)]
        for t in self._threads:
            t.start()

    # ---- the API's verbs ----------------------------------------------------------
    def submit(self, spec: dict, memory_mb: float, wall_seconds: float) -> Job:
        with self._lock:
            self._expire()
            if sum(1 for j in self._jobs.values() if j.status == "queued") >= self.max_queued:
                raise QueueFull(f"{self.max_queued} jobs are already queued; try again later")
            job = Job(f"{next(self._counter)}-{secrets.token_hex(4)}", spec, memory_mb, wall_seconds)
            self._jobs[job.id] = job
        self._queue.put(job)
        return job

    def get(self, job_id: str) -> Job | None:
        with self._lock:
            self._expire()
            return self._jobs.get(job_id)

    def cancel(self, job_id: str) -> Job | None:
        """Cancel a queued or running job (killing its process); a finished job is left as it is."""
        with self._lock:
            job = self._jobs.get(job_id)
            if job is None or job.status in FINISHED:
                return job
            job.status, job.finished, job.error = "cancelled", time.time(), "cancelled by request"
            process = job.process
        if process is not None:
            process.kill()
        return job

    def counts(self) -> dict:
        with self._lock:
            out = {s: 0 for s in ("queued", "running") + FINISHED}
            for j in self._jobs.values():
                out[j.status] += 1
            return out

    def shutdown(self) -> None:
        """Cancel everything still queued or running (the server is stopping)."""
        self._stopping = True
        with self._lock:
            ids = [j.id for j in self._jobs.values() if j.status not in FINISHED]
        for job_id in ids:
            self.cancel(job_id)
        for _ in self._threads:
            self._queue.put(None)

    # ---- the runner threads -------------------------------------------------------
    def _run(self) -> None:
        while True:
            job = self._queue.get()
            if job is None:
                return
            with self._lock:
                if job.status != "queued":  # cancelled while it waited
                    continue
                job.status, job.started = "running", time.time()
            try:
                process = JobProcess("solve", job.spec, job.memory_mb, job.wall_seconds)
            except Exception as exc:  # noqa: BLE001 - e.g. no more processes: the job fails, the runner lives
                self._finish(job, "failed", error=f"could not start the job's process: {exc}")
                continue
            with self._lock:
                job.process = process
                cancelled = job.status == "cancelled"
            if cancelled:  # DELETE arrived between the two locks
                process.kill()
            outcome = process.wait()
            if outcome.kind == "ok":
                self._finish(job, "done", result=outcome.payload)
            elif outcome.kind == "bad_input":
                self._finish(job, "failed", error=outcome.payload.get("error"), result=None)
            else:
                self._finish(job, "failed", error=str(outcome.payload))

    def _finish(self, job: Job, status: str, result: dict | None = None, error: str | None = None) -> None:
        with self._lock:
            job.process = None
            if job.status == "cancelled":
                return
            job.status, job.result, job.error, job.finished = status, result, error, time.time()

    def _expire(self) -> None:
        """Forget finished jobs older than keep_seconds (called with the lock held)."""
        cutoff = time.time() - self.keep_seconds
        for job_id in [j.id for j in self._jobs.values() if j.status in FINISHED and (j.finished or 0) < cutoff]:
            del self._jobs[job_id]
