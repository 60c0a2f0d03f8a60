"""The fd solver's two time bounds, without Fast Downward: the export's timer fires again
when a raise of it is swallowed, and a child process that outlives its limit is killed."""
import sys
import time

import pytest

from bcc.solvers import Budget
from bcc.solvers import fast_downward as fd


def test_the_export_timer_fires_again_after_a_swallowed_raise():
    swallowed, start = 0, time.perf_counter()
    with pytest.raises(fd._Expired):
        with fd._export_limit(Budget(time_limit=0.05)):
            while time.perf_counter() - start < 5:
                try:                      # what a garbage-collector callback does with it
                    time.sleep(0.01)
                except fd._Expired:
                    if swallowed:
                        raise
                    swallowed += 1
    assert swallowed == 1 and time.perf_counter() - start < 2


def test_a_child_past_its_limit_is_killed_with_its_group():
    start = time.perf_counter()
    code = "import subprocess, sys, time; subprocess.Popen([sys.executable, '-c', 'import time; time.sleep(60)']); time.sleep(60)"
    assert fd._bounded([sys.executable, "-c", code], ".", 0.1) is None
    assert time.perf_counter() - start < 1.0 + fd.GRACE + 2


def test_a_child_within_its_limit_returns_its_output():
    done = fd._bounded([sys.executable, "-c", "print('ok')"], ".", 30)
    assert done.returncode == 0 and done.stdout.strip() == "ok"
