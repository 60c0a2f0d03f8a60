"""The HTTP service: the JSON API (FastAPI, so /openapi.json is real) and the web page.

Handlers are plain `def`s, so FastAPI runs them in its thread pool: a compile for
drawing never blocks the event loop. Solves never run here: they are jobs
(`jobs.py`), each in its own process. Posted text is never compiled here either: it is
checked in a throwaway process and drawn or stepped in the model host (`model_host.py`).
"""
from __future__ import annotations

import asyncio
import contextlib
from dataclasses import dataclass
from pathlib import Path

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import FileResponse, JSONResponse
from fastapi.staticfiles import StaticFiles

from .. import __version__
from ..errors import BccError, ModelError, printable
from .body_limit import BodyLimit
from .compiled import CompileRejected, CompiledCache, trusted
from .model_host import ModelHost
from .jobs import JobManager, QueueFull
from .posted import parse_ref, public_error
from .stepping import demonstration_body, replay_body
from .schemas import (DemonstrationRequest, DungeonFile, DungeonList, DungeonRequest, ErrorBody, JobCreated,
                      JobStatus, ReplayRequest, ReplayResponse, SolveRequest)

STATIC = Path(__file__).resolve().parent / "static"
ERRORS = {400: {"model": ErrorBody, "description": "Bad input, with its position when known"},
          413: {"model": ErrorBody, "description": "The request body is over the size limit"}}


@dataclass(frozen=True)
class Settings:
    workers: int = 2                 # solves running at once
    max_body_bytes: int = 1_000_000  # larger request bodies get 413
    job_memory_mb: float = 1024      # default and cap of a job's max_memory_mb
    max_time_limit: float = 300      # cap of a solve's time_limit
    compile_seconds: float = 60      # wall-clock allowance for compiling, on top of time_limit
    keep_seconds: float = 3600       # finished jobs are kept this long


def error(status: int, body: dict) -> JSONResponse:
    return JSONResponse(body, status_code=status)


def create_app(settings: Settings = Settings()) -> FastAPI:
    """The service: its error answers, the page, the dungeon listing, compiling and
    stepping (shipped dungeons here, posted text in the model host), and solve jobs."""
    jobs = JobManager(settings.workers, settings.keep_seconds)
    compiled = CompiledCache(settings.job_memory_mb, settings.compile_seconds, checks=max(2, settings.workers))
    host = ModelHost(settings.job_memory_mb, settings.compile_seconds)

    @contextlib.asynccontextmanager
    async def lifespan(app):
        from . import sandbox
        await asyncio.to_thread(sandbox.warm_up)  # start the fork server before the first job
        yield
        jobs.shutdown()
        host.shutdown()

    # No /docs or /redoc: FastAPI's pages for them load scripts from a CDN, and the
    # viewer must work offline. The description itself is at /openapi.json.
    app = FastAPI(title="bcc", version=__version__, lifespan=lifespan, docs_url=None, redoc_url=None,
                  description="Compile and solve bcc dungeons over HTTP; a viewer at `/`.")
    app.state.jobs, app.state.settings = jobs, settings
    app.add_middleware(BodyLimit, max_bytes=settings.max_body_bytes)
    _answer_errors(app)
    _page_and_dungeons(app)
    _compile_and_step(app, compiled, host)
    _jobs(app, jobs, compiled, settings)
    return app


def _answer_errors(app: FastAPI) -> None:
    """Bad input of every kind answers with one body: {error, line, column, file}."""
    @app.exception_handler(RequestValidationError)
    def invalid_request(request: Request, exc: RequestValidationError):
        """422 with the first problem in one line; the offending input is never echoed
        (it may be huge, NaN or not encodable)."""
        problems = exc.errors()
        first = problems[0] if problems else {"loc": (), "msg": "invalid request"}
        where = ".".join(str(p) for p in first.get("loc", ()) if p != "body")
        message = printable(str(first.get("msg", "invalid request")))[:300]
        return error(422, {"error": f"{where}: {message}" if where else message,
                           "line": None, "column": None, "file": None})

    @app.exception_handler(BccError)
    def bad_input(request: Request, exc: BccError):
        return error(400, public_error(exc))

    @app.exception_handler(CompileRejected)
    def rejected(request: Request, exc: CompileRejected):
        return error(exc.status, exc.body)

    @app.exception_handler(ModelError)
    def domain_error(request: Request, exc: ModelError):
        return error(400, {"error": f"domain error: {exc}", "line": None, "column": None, "file": None})


def _page_and_dungeons(app: FastAPI) -> None:
    """The web page, the shipped dungeons and the solvers."""
    @app.get("/", include_in_schema=False)
    def index():
        return FileResponse(STATIC / "index.html")

    app.mount("/static", StaticFiles(directory=STATIC), name="static")

    @app.get("/dungeons", response_model=DungeonList, summary="The shipped dungeons and domains")
    def list_dungeons():
        from .listing import listing
        return listing()

    @app.get("/dungeons/{name}", response_model=DungeonFile, responses={404: {"model": ErrorBody}},
             summary="One shipped dungeon, with its YAML text")
    def get_dungeon(name: str):
        from .listing import dungeon_file
        found = dungeon_file(name)
        if found is None:
            return error(404, {"error": f"no shipped dungeon named {name!r}"})
        return found

    @app.get("/solvers", summary="The available solvers")
    def solvers():
        from ..solvers import describe_solvers
        return {"solvers": describe_solvers()}


def _compile_and_step(app: FastAPI, compiled: CompiledCache, host: ModelHost) -> None:
    """Compile, replay and record: a shipped dungeon in this process, posted text only in
    a throwaway process (checking) and the model host (stepping)."""
    def stepped(req: DungeonRequest, task: str, extra: dict):
        ref = parse_ref(req.dungeon)
        if trusted(ref, req.goal):
            model, rooms = compiled.model(ref, req.goal)
            if task == "replay":
                return replay_body(model, rooms, extra["actions"], extra["include_scene"])
            return demonstration_body(model, False, extra["actions"], extra["command"])
        compiled.report(ref, req.goal)  # checked (and rejected) once, in a throwaway process
        outcome = host.call(task, {"ref": {"name": ref.name, "text": ref.text}, "goal": req.goal, **extra})
        if outcome.kind == "ok":
            return outcome.payload
        if outcome.kind == "bad_input":
            return error(400, outcome.payload)
        return error(422, {"error": f"stepping the dungeon failed: {outcome.payload}",
                           "line": None, "column": None, "file": None})

    @app.post("/compile", responses={**ERRORS, 422: {"model": ErrorBody}},
              summary="Check and compile a dungeon: the report of `bcc compile --json`")
    def compile_(req: DungeonRequest):
        return compiled.report(parse_ref(req.dungeon), req.goal)

    @app.post("/replay", response_model=ReplayResponse, responses=ERRORS,
              summary="Run actions from the start: one frame per state, stopping where an action does not apply")
    def replay(req: ReplayRequest):
        return stepped(req, "replay", {"actions": list(req.actions), "include_scene": req.include_scene})

    @app.post("/demonstration", responses=ERRORS,
              summary="A demonstration file (bcc-demonstration/1) of actions played from the start")
    def demonstration(req: DemonstrationRequest):
        return stepped(req, "demonstration", {"actions": list(req.actions), "command": req.command})


def _jobs(app: FastAPI, jobs: JobManager, compiled: CompiledCache, settings: Settings) -> None:
    """Solves, each a job in a process of its own: queue, poll, cancel; and /health."""
    @app.post("/solve", status_code=202, response_model=JobCreated, responses={**ERRORS, 503: {"model": ErrorBody}},
              summary="Queue a solve; poll GET /jobs/{id}")
    def solve(req: SolveRequest):
        from .options import given_options, solver_options
        ref = parse_ref(req.dungeon)
        report = compiled.report(ref, req.goal)   # a malformed dungeon is a 400 now, not a failed job
        solver_options(req)                       # so are bad options; the job's run checks them again
        options = {name: value for name, value in given_options(req).items() if value is not None}
        memory = min(req.max_memory_mb or settings.job_memory_mb, settings.job_memory_mb)
        time_limit = min(req.time_limit, settings.max_time_limit)
        spec = {"ref": {"name": ref.name, "text": ref.text}, "goal": req.goal, "solver": req.solver,
                "options": options, "time_limit": time_limit, "max_states": req.max_states,
                "dungeon_name": report["dungeon"]}
        try:
            job = jobs.submit(spec, memory, time_limit + settings.compile_seconds)
        except QueueFull as exc:
            return error(503, {"error": str(exc)})
        return {"id": job.id, "status": "queued"}

    @app.get("/jobs/{job_id}", response_model=JobStatus, responses={404: {"model": ErrorBody}},
             summary="A job's status, and its result when done")
    def get_job(job_id: str):
        job = jobs.get(job_id)
        if job is None:
            return error(404, {"error": f"no job {job_id!r} (finished jobs are forgotten after "
                                        f"{settings.keep_seconds:g} s)"})
        return job.to_json()

    @app.delete("/jobs/{job_id}", response_model=JobStatus, responses={404: {"model": ErrorBody},
                                                                       409: {"model": ErrorBody}},
                summary="Cancel a queued or running job (its process is killed)")
    def cancel_job(job_id: str):
        job = jobs.get(job_id)
        if job is None:
            return error(404, {"error": f"no job {job_id!r}"})
        if job.status in ("done", "failed"):
            return error(409, {"error": f"job {job_id} has already finished ({job.status})"})
        return jobs.cancel(job_id).to_json()

    @app.get("/health", summary="Liveness, and how many jobs are in each state")
    def health():
        return {"ok": True, "version": __version__, "workers": settings.workers, "jobs": jobs.counts()}

