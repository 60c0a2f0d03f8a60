"""What runs inside a job's own process: compile or solve under a memory limit.

The parent (`sandbox.py`) forks this from a clean fork server that has already imported
the compiler and the solvers, so a job starts in milliseconds. The process caps its own
address space (`RLIMIT_AS`) at what it uses now plus the job's memory limit, and passes
the same allowance to the solver's `Budget`: whichever trips first ends the job cleanly
(a solver's budget stop is a result; an allocation past the cap is a MemoryError,
reported as a failure). Either way the server's process is never touched.
"""
from __future__ import annotations

import os

from ..errors import BccError, ModelError
from ..run import Request, run
from ..solvers import Budget
from ..solvers.memory import cap_growth, current_rss_mb
from .posted import DungeonRef, compile_ref, public_error
# Imported here so the fork server preloads them: a job never pays for these imports.
from ..solvers import astar, bfs  # noqa: F401


def limit_memory(memory_mb: float) -> float:
    """Cap this process's address space; return the RSS ceiling (MB) for the solver's Budget."""
    cap_growth(memory_mb, lock=True)   # without /proc or rlimits the Budget alone still limits
    return current_rss_mb() + memory_mb


# Shipped dungeons compiled once in the fork server (`preload.py`); every job inherits them.
PRECOMPILED: dict = {}


def load_model(spec: dict):
    ref = DungeonRef(**spec["ref"])
    if ref.name is not None and spec.get("goal") is None and ref.name in PRECOMPILED:
        return PRECOMPILED[ref.name]
    return compile_ref(ref, spec.get("goal"))


def compile_task(spec: dict, rss_ceiling: float) -> dict:
    model = load_model(spec)
    return model.compile_report()


def solve_task(spec: dict, rss_ceiling: float) -> dict:
    """A solve, the one way every edge runs one (bcc/run); this process already caps its
    own memory (`limit_memory`), so the run adds no hard limits of its own."""
    model = load_model(spec)
    ran = run(Request(lambda: model, spec.get("solver", "astar"), dict(spec.get("options") or {}),
                      Budget(spec.get("max_states"), spec.get("time_limit"), rss_ceiling), hard=False))
    return {"dungeon": model.name, "goal": model.goal_text, **ran.result.to_json()}


TASKS = {"compile": compile_task, "solve": solve_task}


def host_main(conn, memory_mb: float, cache_size: int) -> None:
    """Entry point of the model host (`model_host.py`): answer `(task, spec)` requests on
    `conn` with `(kind, payload)`, keeping up to `cache_size` compiled models. A
    MemoryError ends the process after its answer (its heap may be half-built)."""
    from collections import OrderedDict
    from .scene import rooms_of
    from .stepping import demonstration_body, replay_body
    try:
        os.nice(5)
    except OSError:
        pass
    limit_memory(memory_mb)
    models: OrderedDict = OrderedDict()

    def model_of(spec):
        ref = DungeonRef(**spec["ref"])
        key = (ref.key, spec.get("goal"))
        if key not in models:
            models[key] = compile_ref(ref, spec.get("goal"), with_rooms=True)
            while len(models) > cache_size:
                models.popitem(last=False)
        models.move_to_end(key)
        return models[key]

    while True:
        try:
            task, spec = conn.recv()
        except (EOFError, OSError):
            return
        fatal = False
        try:
            model, rooms = model_of(spec)
            if task == "replay":
                payload = replay_body(model, rooms, spec["actions"], spec.get("include_scene", True))
            elif task == "demonstration":
                payload = demonstration_body(model, spec["ref"].get("name") is None, spec["actions"],
                                             spec.get("command"))
            else:
                payload = model.compile_report()
            message = ("ok", payload)
        except MemoryError:
            models.clear()
            message, fatal = ("memory", f"the posted dungeon exceeded the memory limit of {memory_mb:g} MB"), True
        except BccError as exc:
            message = ("bad_input", public_error(exc))
        except ModelError as exc:
            message = ("bad_input", {"error": f"domain error: {exc}", "line": None, "column": None, "file": None})
        except Exception as exc:  # noqa: BLE001 - a bug in bcc: this request fails, the server does not
            message = ("failed", f"internal error: {type(exc).__name__}: {exc}")
        try:
            conn.send(message)
        except (MemoryError, OSError):
            return
        if fatal:
            return


def main(conn, task: str, spec: dict, memory_mb: float) -> None:
    """Entry point of a job process: one message on `conn`, `(kind, payload)`.

    kind is "ok" (payload: the result), "bad_input" (the 400 body), "memory" or
    "failed" (payload: a one-line message)."""
    try:
        os.nice(5)  # the server's own requests come first
    except OSError:
        pass
    try:
        rss_ceiling = limit_memory(memory_mb)
        message = ("ok", TASKS[task](spec, rss_ceiling))
    except MemoryError:
        message = ("memory", f"the job exceeded its memory limit of {memory_mb:g} MB")
    except BccError as exc:
        message = ("bad_input", public_error(exc))
    except ModelError as exc:
        message = ("failed", f"domain error: {exc}")
    except Exception as exc:  # noqa: BLE001 - a bug in bcc: the job fails, the server does not
        message = ("failed", f"internal error: {type(exc).__name__}: {exc}")
    try:
        conn.send(message)
    except MemoryError:
        conn.send(("memory", "the job exceeded its memory limit"))
    finally:
        conn.close()
