"""Fast Downward on an export: the `fd` solver (a plugin, entry point `bcc.solvers`).

Why a subprocess: Fast Downward is a C++ planner; the PyPI package `up-fast-downward`
ships its driver `fast-downward.py` and a release build. We export the model (task.py),
run the driver on the two files, and map the plan's operators back to canonical bcc
actions, so the result is an ordinary bcc `Result` (and `bcc validate` replays it).

The search configuration is the `search` option, else the environment variable
`BCC_FD_SEARCH`, else `astar(lmcut())` (optimal).
"""
from __future__ import annotations

import contextlib
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, replace
from pathlib import Path

from ..errors import BccError
from ..extras import install_hint
from .options import Option, declare

DEFAULT_SEARCH = "astar(lmcut())"
# Fast Downward's LM-cut does not take axioms (PDDL's derived predicates); its blind A* does,
# and stays optimal: the default search falls back to it on such a task.
AXIOMS_SEARCH = "astar(blind())"
# The driver's exit codes for "ran out of time or memory": translate (20, 21), search
# (22-24), and a component killed by the CPU-time limit (SIGXCPU; the driver exits with
# its negative return code, 256 - 24 = 232).
OUT_OF_BUDGET = (20, 21, 22, 23, 24, 256 - 24)
INSTALL_HINT = f"Fast Downward is not installed: {install_hint('pddl')} (the PyPI package up-fast-downward)"


def driver() -> Path:
    """The path of fast-downward.py, or BccError with the install hint."""
    try:
        import importlib.resources
        import up_fast_downward  # noqa: F401
        path = Path(str(importlib.resources.files("up_fast_downward").joinpath("downward/fast-downward.py")))
    except ImportError:
        raise BccError(INSTALL_HINT) from None
    if not path.exists():
        raise BccError(INSTALL_HINT + f" ({path} is missing)")
    return path


def available() -> bool:
    try:
        driver()
        return True
    except BccError:
        return False


@dataclass
class FdRun:
    solved: bool
    plan: list          # operator names as Fast Downward printed them
    cost: int | None
    seconds: float
    status: str         # "solved" | "no_solution" | "budget" | "error"
    message: str
    expanded: int = 0   # Fast Downward's own counters (its last report), 0 where it printed none
    generated: int = 0
    search: str = DEFAULT_SEARCH   # the configuration that ran


def _counter(out: str, what: str) -> int:
    """The last 'Expanded N state(s).' (or Generated) Fast Downward printed."""
    found = re.findall(rf"\b{what} (\d+) state", out)
    return int(found[-1]) if found else 0


def run(domain_file: str, problem_file: str, search: str | None = None, time_limit: float | None = None,
        memory_mb: float | None = None, full_names: bool = False) -> FdRun:
    """Run Fast Downward (translate + search) on two PDDL files; the default search, on a
    task with axioms it does not take, again with AXIOMS_SEARCH."""
    search = search or os.environ.get("BCC_FD_SEARCH") or DEFAULT_SEARCH
    fd = _run(domain_file, problem_file, search, time_limit, memory_mb, full_names)
    if fd.status == "error" and search == DEFAULT_SEARCH and "support axioms" in fd.message:
        left = None if time_limit is None else max(1.0, time_limit - fd.seconds)
        fd = _run(domain_file, problem_file, AXIOMS_SEARCH, left, memory_mb, full_names)
    return fd


GRACE = 2.0   # seconds Fast Downward may overrun its own limit before bcc stops it


def _bounded(cmd: list, cwd: str, time_limit: float | None):
    """Run `cmd`; None if it outlived `time_limit` + GRACE of wall-clock time. Fast
    Downward's own --overall-time-limit counts CPU time, which a loaded machine stretches
    (19 s of wall time on a 1 s limit in CI): the process group is killed here."""
    proc = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True)
    try:
        out, err = proc.communicate(timeout=None if time_limit is None else max(1.0, time_limit) + GRACE)
    except subprocess.TimeoutExpired:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return None
    except BaseException:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()
        raise
    return subprocess.CompletedProcess(cmd, proc.returncode, out, err)


def _run(domain_file: str, problem_file: str, search: str, time_limit: float | None, memory_mb: float | None,
         full_names: bool) -> FdRun:
    with tempfile.TemporaryDirectory(prefix="bcc-fd-") as tmp:
        plan_file = os.path.join(tmp, "plan")
        cmd = [sys.executable, str(driver()), "--plan-file", plan_file]
        if time_limit is not None:
            cmd += ["--overall-time-limit", f"{max(1, int(time_limit))}s"]
        if memory_mb is not None:
            cmd += ["--overall-memory-limit", f"{int(memory_mb)}M"]
        cmd += [os.path.abspath(domain_file), os.path.abspath(problem_file), "--search", search]
        start = time.perf_counter()
        proc = _bounded(cmd, tmp, time_limit)
        seconds = time.perf_counter() - start
        if proc is None:
            return FdRun(False, [], None, seconds, "budget", "stopped: Fast Downward ran out of time (stopped by bcc)",
                         search=search)
        counts = {"expanded": _counter(proc.stdout, "Expanded"), "generated": _counter(proc.stdout, "Generated"),
                  "search": search}
        if proc.returncode == 0 and os.path.exists(plan_file):
            plan, cost = _read_plan(plan_file, full_names)
            return FdRun(True, plan, cost, seconds, "solved", "", **counts)
        if proc.returncode in (11, 12):
            return FdRun(False, [], None, seconds, "no_solution", "no plan exists (Fast Downward proved it)", **counts)
        if proc.returncode in OUT_OF_BUDGET:
            return FdRun(False, [], None, seconds, "budget", "stopped: Fast Downward ran out of time or memory",
                         **counts)
        said = [line.strip() for line in (proc.stderr.strip() or proc.stdout.strip()).splitlines()]
        tail = [line for line in said if line.strip("^~ ")][-3:]   # a caret line says nothing here
        return FdRun(False, [], None, seconds, "error",
                     f"Fast Downward failed (exit {proc.returncode}): {' | '.join(tail)}", **counts)


def _time_left(budget, start: float) -> float | None:
    """What remains of the time limit for Fast Downward's own (at least 1 s)."""
    return None if budget.time_limit is None else max(1.0, budget.time_limit - (time.perf_counter() - start))


def _unsolved(fd, seconds: float):
    """The Result of a run that found no plan; a BccError when Fast Downward failed."""
    from .base import Result
    if fd.status == "error":
        raise BccError(fd.message)
    return Result(solver="fd", solved=False, status=fd.status, seconds=seconds, message=fd.message,
                  budget="time_limit" if fd.status == "budget" else None, expanded=fd.expanded,
                  generated=fd.generated)


def _solve_files(model, budget, files, search, start):
    """A model imported from PDDL: Fast Downward reads the very files bcc read, and its
    plan's steps are the model's action names (`(pick ball1 rooma left)`)."""
    from .base import Result
    left = _time_left(budget, start)
    fd = run(files[0], files[1], search, left, budget.max_memory_mb, full_names=True)
    seconds = round(time.perf_counter() - start, 6)
    if not fd.solved:
        return _unsolved(fd, seconds)
    costs = dict(zip(model.action_names, model.action_costs))
    known = all(a in costs for a in fd.plan)
    cost = sum(costs[a] for a in fd.plan) if known else fd.cost
    return Result(solver="fd", solved=True, status="solved", plan=fd.plan, cost=cost, seconds=seconds,
                  expanded=fd.expanded, generated=fd.generated,
                  message=f"Fast Downward on the PDDL files, search {fd.search}")


def _read_plan(path: str, full_names: bool = False):
    ops, cost = [], None
    for line in Path(path).read_text().splitlines():
        line = line.strip()
        if line.startswith(";"):
            if "cost =" in line:
                cost = int(line.split("cost =")[1].split()[0])
        elif line:
            ops.append("(" + " ".join(line.strip("()").lower().split()) + ")" if full_names else line.strip("()").split()[0])
    return ops, cost


def _unavailable() -> str | None:
    return None if available() else INSTALL_HINT


class _Expired(BaseException):
    """The export's timer ran out. A BaseException: raised wherever the export is, it must
    pass the symbolic engine's `except Exception` (which keeps a per-value error); as an
    Exception it was swallowed there, the export ran on and `fd` took 7.7 s on a 0.02 s
    budget in CI."""


def _export_limit(budget):
    """The export (task.py) has no budget checks of its own: bound it by a timer, unless
    the command already runs under one (solvers/limits.py's hard_limits), which it
    would cancel."""
    import threading
    if budget.time_limit is None or threading.current_thread() is not threading.main_thread() \
            or signal.getitimer(signal.ITIMER_REAL)[0] > 0:
        return contextlib.nullcontext()

    @contextlib.contextmanager
    def limit():
        def expire(signum, frame):
            raise _Expired()
        old = signal.signal(signal.SIGALRM, expire)
        # and again every 50 ms: a raise inside a garbage-collector callback (hypothesis
        # installs one) is printed and dropped, and the export ran on for 19 s in CI
        signal.setitimer(signal.ITIMER_REAL, budget.time_limit, 0.05)
        try:
            yield
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, old)
    return limit()


@declare(Option("fd_search", str, DEFAULT_SEARCH, "the Fast Downward search configuration", keyword="search"),
         optimal=True, unavailable=_unavailable)
def solve(model, budget, progress=None, search: str | None = None, **_):
    """Fast Downward on the exact PDDL export (--fd-search CONFIG, default astar(lmcut()))

    The `fd` solver: export `model`, run Fast Downward, return a bcc Result."""
    from ..atomic import write_text
    from .base import Result
    from ..pddl_export.task import build_task
    from ..pddl_export.writer import domain_text, problem_text
    driver()  # fail early, with the install hint
    start = time.perf_counter()
    files = model.data("pddl_files")
    if files is not None:
        return _solve_files(model, budget, files, search, start)
    spent = Result(solver="fd", solved=False, status="budget", budget="time_limit",
                   message="stopped: the time limit (--time-limit) ran out while exporting the model to PDDL")
    try:
        with _export_limit(budget):
            task = build_task(model)
    except _Expired:
        return replace(spent, seconds=round(time.perf_counter() - start, 6))
    if budget.time_limit is not None and time.perf_counter() - start >= budget.time_limit:
        return replace(spent, seconds=round(time.perf_counter() - start, 6))
    with tempfile.TemporaryDirectory(prefix="bcc-pddl-") as tmp:
        dom, prob = os.path.join(tmp, "domain.pddl"), os.path.join(tmp, "problem.pddl")
        write_text(dom, domain_text(task))
        write_text(prob, problem_text(task))
        left = _time_left(budget, start)
        fd = run(dom, prob, search, left, budget.max_memory_mb)
    seconds = round(time.perf_counter() - start, 6)
    if not fd.solved:
        return _unsolved(fd, seconds)
    plan = [a for a in (task.action_of(op) for op in fd.plan) if a is not None]
    cost = sum(model.action_costs[model.action_index(a)] for a in plan)
    return Result(solver="fd", solved=True, status="solved", plan=plan, cost=cost, seconds=seconds,
                  expanded=fd.expanded, generated=fd.generated,
                  message=f"Fast Downward, search {fd.search}")
