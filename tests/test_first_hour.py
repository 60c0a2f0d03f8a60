"""A newcomer's first hour, through the installed `bcc` executable as a shell runs it:
the plan alone on stdout (so `> plan.txt` makes a file `bcc validate` reads), a
demonstration from `bcc play --record` validates, and a machine that never ran bcc (HOME
an empty folder) works the same.
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys

import pytest

from bcc.keys import KEYS


def bcc(*args, cwd, home=None, stdin=None):
    exe = shutil.which("bcc")
    cmd = [exe] if exe else [sys.executable, "-m", "bcc"]
    env = dict(os.environ)
    if home is not None:
        env["HOME"] = str(home)
        for name in ("XDG_DATA_HOME", "XDG_CACHE_HOME", "XDG_CONFIG_HOME", "BCC_HOME", "MPLCONFIGDIR"):
            env.pop(name, None)
    return subprocess.run([*cmd, *args], cwd=cwd, env=env, input=stdin, capture_output=True, text=True, timeout=120)


def test_solve_to_a_file_then_validate_it(tmp_path):
    """The README's `bcc solve bridge > plan.txt && bcc validate bridge plan.txt`."""
    solved = bcc("solve", "bridge", cwd=tmp_path)
    assert solved.returncode == 0, solved.stderr
    (tmp_path / "plan.txt").write_text(solved.stdout)
    assert solved.stderr.startswith("solved bridge with astar: cost 13, 13 steps")
    # 13 actions and nothing else: the summary is on stderr
    assert len(solved.stdout.split()) == 13 and "solved" not in solved.stdout
    checked = bcc("validate", "bridge", "plan.txt", cwd=tmp_path)
    assert checked.returncode == 0 and checked.stdout.startswith("valid:"), checked.stdout + checked.stderr


def test_no_plan_is_said_on_stderr_and_stdout_stays_empty(tmp_path):
    failed = bcc("solve", "bridge", "--goal", "agentInRoom(agent, nowhere)", cwd=tmp_path)
    assert failed.returncode == 2   # an unknown room is bad input, not "no plan"
    unreachable = bcc("solve", "bridge", "--max-states", "5", cwd=tmp_path)
    assert unreachable.returncode == 1 and unreachable.stdout == ""
    assert "not solved: stopped: the state budget (--max-states) ran out" in unreachable.stderr


def test_a_recorded_demonstration_validates(tmp_path):
    """`bcc play --record demo.json`, then `bcc validate bridge demo.json`."""
    solved = bcc("solve", "bridge", cwd=tmp_path)
    keys = "".join(KEYS[a] for a in solved.stdout.split()) + "q\n"
    played = bcc("play", "bridge", "--record", "demo.json", cwd=tmp_path, stdin=keys)
    assert played.returncode == 0, played.stderr
    assert json.loads((tmp_path / "demo.json").read_text())["actions"] == solved.stdout.split()
    checked = bcc("validate", "bridge", "demo.json", cwd=tmp_path)
    assert checked.returncode == 0 and checked.stdout.startswith("valid: the goal holds after step 13"), \
        checked.stdout + checked.stderr


def test_a_machine_that_never_ran_bcc(tmp_path):
    """HOME empty: no data folders exist; the first commands and the listing still work."""
    home = tmp_path / "home"
    home.mkdir()
    solved = bcc("solve", "bridge", cwd=tmp_path, home=home)
    assert solved.returncode == 0, solved.stderr
    listed = bcc("solvers", "--json", cwd=tmp_path, home=home)
    assert listed.returncode == 0, listed.stderr
    solvers = json.loads(listed.stdout)["solvers"]
    assert solvers["astar"]["options"] and solvers["bfs"]["options"] == []
    if solvers.get("fd", {}).get("unavailable"):
        assert 'pip install ".[pddl]"' in solvers["fd"]["unavailable"]


def test_bcc_solvers_says_what_is_unavailable(tmp_path):
    listed = bcc("solvers", cwd=tmp_path)
    assert listed.returncode == 0
    assert "--heuristic" in listed.stdout and "--known-after" in listed.stdout
    try:
        import up_fast_downward  # noqa: F401
    except ImportError:
        assert "unavailable: Fast Downward is not installed" in listed.stdout


def test_sizes_are_worded_one_way(tmp_path):
    """`bcc compile` and the errors both say `W wide x D deep x H high`."""
    (tmp_path / "out.yaml").write_text("dungeon: outside\nextends: bridge\nagent:\n  start: [20, 1, 1]\n")
    refused = bcc("solve", "out.yaml", cwd=tmp_path)
    assert refused.returncode == 2
    assert refused.stderr.strip() == "out.yaml:4:10: the start [20, 1, 1] is outside the dungeon (7 wide x 7 deep x 4 high)"
    compiled = bcc("compile", "bridge", cwd=tmp_path)
    assert compiled.stdout.splitlines()[0].endswith(": 7 wide x 7 deep x 4 high")


def test_one_unknown_solver_message_everywhere(tmp_path):
    """bcc solve, bcc batch and bcc import pddl name an unknown solver the same way."""
    want = "unknown solver 'astr' (did you mean 'astar'?); available: bfs, astar,"
    solve = bcc("solve", "bridge", "--solver", "astr", cwd=tmp_path)
    batch = bcc("batch", "bridge", "--solver", "astr", "--out", "r.jsonl", cwd=tmp_path)
    for proc in (solve, batch):
        assert proc.returncode == 2 and proc.stderr.startswith(want), proc.stderr
    rmax = bcc("solve", "bridge", "--solver", "rmax", "--heuristic", "pdb", cwd=tmp_path)
    assert rmax.returncode == 2 and rmax.stderr.startswith("--heuristic does not apply to rmax (its options: --model")
