"""The one run path (bcc/run): what every edge gets from it, whoever calls it."""
from __future__ import annotations

import signal
import time

import pytest

from bcc.errors import BccError
from bcc.run import Request, run
from bcc.solvers import Budget, get_solver
from bcc.solvers.base import Meter
from bcc.solvers.limits import hard_limits

from conftest import compiled


def test_bad_options_are_refused_before_the_model_is_loaded():
    loaded = []
    with pytest.raises(BccError, match="--weight must be a number >= 1"):
        run(Request(lambda: loaded.append(1), "astar", {"weight": "0.5"}, spell=lambda name: f"--{name}"))
    with pytest.raises(BccError, match="does not apply to bfs"):
        run(Request(lambda: loaded.append(1), "bfs", {"weight": "2"}))
    assert not loaded


def test_internal_keywords_cannot_be_requested():
    # optimal_cost is declared (internal): the run path sets it, a request cannot
    with pytest.raises(BccError, match="does not apply to rmax"):
        run(Request(lambda: compiled("grid"), "rmax", {"optimal_cost": 3}))


def test_a_learner_gets_the_reference_cost_and_a_search_does_not():
    model = compiled("grid")
    astar = get_solver("astar")(model, Budget(time_limit=30))
    ran = run(Request(lambda: model, "rmax", {"model": "oo", "episodes": "6", "seed": "0"}, Budget(time_limit=60)))
    assert ran.model is model and ran.result.solved
    # converged_episode is measured against A*'s cost: the first episode from which all are that long
    steps = [e["steps"] for e in ran.result.episodes]
    assert ran.result.converged_episode is not None
    assert all(s == astar.cost for s in steps[ran.result.converged_episode:])
    assert run(Request(lambda: model, "astar")).result.converged_episode is None


def test_the_memory_budget_defaults_to_half_the_machine():
    seen = {}

    def spy(model, budget, progress=None, **options):
        seen["budget"] = budget
        return get_solver("bfs")(model, budget)
    run(Request(lambda: compiled("grid"), "bfs", solve=spy))
    assert seen["budget"].max_memory_mb == pytest.approx(Budget.default().max_memory_mb)


def test_a_budget_spent_while_loading_is_a_result():
    def slow():
        deadline = time.perf_counter() + 5
        while time.perf_counter() < deadline:   # a compile that outlives the time limit
            pass
    ran = run(Request(slow, "astar", budget=Budget(time_limit=0.2)))
    assert ran.model is None
    assert ran.result.status == "budget" and ran.result.budget == "time_limit" and not ran.result.solved


def test_the_meter_stops_with_the_solvers_result():
    meter = Meter(Budget(max_states=10), solver="mine")
    assert meter.stop(1, 5, 10) is None
    stopped = meter.stop(2, 9, 11, heuristic="h")
    assert stopped.solver == "mine" and stopped.status == "budget" and stopped.budget == "max_states"
    assert (stopped.expanded, stopped.generated, stopped.stored, stopped.heuristic) == (2, 9, 11, "h")
    assert "--max-states" in stopped.message


def test_a_spent_budget_stops_every_child_even_when_reaping_is_slow(monkeypatch):
    """The budget's timer fires again every 0.25 s once the time is spent; the pool's sweep
    holds it back, so a raise cannot land between two children's kills and leave one
    running (seen under load: `bcc corpus evaluate --workers 2 --time-limit 1` left one)."""
    import multiprocessing

    from bcc.run import children, pool
    from bcc.solvers.limits import BudgetExceeded
    kill = children.Child.kill

    def slow_kill(self):
        time.sleep(0.4)         # longer than the timer's repeat: a raise would land here
        kill(self)
    monkeypatch.setattr(children.Child, "kill", slow_kill)
    with pytest.raises(BudgetExceeded):
        with hard_limits(Budget(time_limit=0.3), grace=0.0):
            for _ in pool.map_local(time.sleep, [30, 30, 30], 2, lambda item: children.Limits()):
                pass
    assert not multiprocessing.active_children()


_SWEEP_WITH_A_THREAD = """
import multiprocessing, threading, time
from bcc.run import children, pool
from bcc.solvers import Budget
from bcc.solvers.limits import BudgetExceeded, hard_limits
threading.Thread(target=time.sleep, args=(60,), daemon=True).start()   # a thread the timer's signal may go to
kill = children.Child.kill
def slow_kill(self):
    time.sleep(0.4)          # longer than the timer's repeat
    kill(self)
children.Child.kill = slow_kill
try:
    with hard_limits(Budget(time_limit=0.3), grace=0.0):
        for _ in pool.map_local(time.sleep, [30, 30, 30], 2, lambda item: children.Limits()):
            pass
except BudgetExceeded:
    print("budget", len(multiprocessing.active_children()))
"""


def test_a_sweep_ends_while_another_thread_takes_the_timers_signal():
    """With another thread alive (a server's, a library's: the whole suite has some), the
    timer's signal went to that thread while the main thread blocked it, and Python ran the
    handler in the main thread anyway: a raise landed in every slow kill and the sweep
    retried forever (CI timed out there). In a child process, so a hang is a failure."""
    import subprocess
    import sys
    proc = subprocess.run([sys.executable, "-c", _SWEEP_WITH_A_THREAD], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert proc.stdout.split() == ["budget", "0"], (proc.stdout, proc.stderr[-2000:])


def test_a_raise_that_lands_inside_the_sweep_still_leaves_no_child(monkeypatch):
    """A signal that came just before the hold runs its handler inside it (seen in CI: a long
    garbage collection on a loaded machine, then both children left running); here the
    first kill raises as that handler would, and the sweep still reaps every child."""
    import multiprocessing

    from bcc.run import children, pool
    from bcc.solvers.limits import BudgetExceeded
    kill, raised = children.Child.kill, []

    def kill_raising_once(self):
        if not raised:
            raised.append(self.index)
            raise BudgetExceeded("time_limit")
        kill(self)
    monkeypatch.setattr(children.Child, "kill", kill_raising_once)
    sweep = pool.map_local(time.sleep, [30, 30, 30], 2, lambda item: children.Limits())
    with pytest.raises(BudgetExceeded):
        with hard_limits(Budget(time_limit=0.3), grace=0.0):
            for _ in sweep:
                pass
    assert raised and not multiprocessing.active_children()


def _held_signals(_item):
    return signal.pthread_sigmask(signal.SIG_BLOCK, [])


def test_children_start_with_the_budget_timer_unblocked():
    """The pool forks with SIGALRM held (so no raise separates a fork from its record); a
    child's own budget timer must still fire."""
    from bcc.run import children, pool
    outcomes = list(pool.map_local(_held_signals, [0, 1], 2, lambda item: children.Limits()))
    assert all(o.ok and signal.SIGALRM not in o.value for o in outcomes)
