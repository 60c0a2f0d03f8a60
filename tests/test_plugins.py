"""Solver plugins, end to end: a real package (tests/plugin_demo) registering entry points
in the `bcc.solvers` group is pip-installed into a temporary folder, and `bcc` runs in
subprocesses with that folder on PYTHONPATH. The surrounding environment is never touched.
"""
from __future__ import annotations

import importlib.metadata
import importlib.util
import json
import re
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

PLUGIN_SRC = Path(__file__).parent / "plugin_demo"
BUILTINS = {"bfs", "astar", "wastar", "gbfs", "idastar"}


@pytest.fixture(scope="module")
def plugin_env(tmp_path_factory):
    """An environment for subprocesses in which bcc-plugin-demo is installed (pip runs once)."""
    if importlib.util.find_spec("pip") is None:
        pytest.skip("pip is not available: cannot install the demo plugin package")
    if importlib.util.find_spec("setuptools") is None:
        pytest.skip("setuptools is not available: cannot build the demo plugin package offline")
    reason = _cannot_build_wheels()
    if reason:
        pytest.skip(reason)
    root = tmp_path_factory.mktemp("plugins")
    src = root / "src"  # build from a copy: pip builds in-tree and would leave build/ and *.egg-info here
    shutil.copytree(PLUGIN_SRC, src, ignore=shutil.ignore_patterns("build", "*.egg-info", "__pycache__"))
    target = root / "site"
    proc = subprocess.run(
        [sys.executable, "-m", "pip", "install", "--no-deps", "--no-build-isolation", "--no-index",
         "--disable-pip-version-check", "--no-input", "--quiet", "--target", str(target), str(src)],
        capture_output=True, text=True, timeout=120)
    if proc.returncode != 0:
        pytest.fail(f"pip could not install the demo plugin:\n{proc.stdout}\n{proc.stderr}")
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(target), env.get("PYTHONPATH")) if p)
    env.pop("BCC_DEBUG", None)  # internal errors must stay one line, as users see them
    return env


def _cannot_build_wheels() -> str | None:
    """Why setuptools cannot build a wheel here without downloading anything, or None.

    setuptools >= 70.1 has `bdist_wheel` built in; older ones borrow it from the `wheel` package,
    and `--no-build-isolation` means pip will not fetch it."""
    try:
        version = importlib.metadata.version("setuptools")
    except importlib.metadata.PackageNotFoundError:
        return "setuptools is not available: cannot build the demo plugin package offline"
    parts = tuple(int(n) for n in re.findall(r"\d+", version)[:2])
    if parts >= (70, 1) or importlib.util.find_spec("wheel") is not None:
        return None
    return (f"setuptools {version} cannot build wheels without the `wheel` package, which is not installed "
            "(install `wheel`, or setuptools>=70.1, to run the plugin tests)")


def bcc(env, *args, stdin=None):
    exe = shutil.which("bcc", path=env.get("PATH"))
    cmd = [exe] if exe else [sys.executable, "-m", "bcc"]
    return subprocess.run([*cmd, *args], input=stdin, capture_output=True, text=True, env=env, timeout=60)


SOLVE_DOC = "Depth-first search, a demonstration plugin (not optimal)"   # bcc_plugin_demo.solve's docstring


def test_solvers_lists_plugins_besides_builtins(plugin_env):
    proc = bcc(plugin_env, "solvers", "--json")
    assert proc.returncode == 0, proc.stderr
    solvers = json.loads(proc.stdout)["solvers"]
    assert BUILTINS <= set(solvers)
    assert {"dfs", "broken"} <= set(solvers)
    assert "bcc_plugin_demo:solve" in solvers["dfs"]["description"]
    # described by the first line of the plugin's docstring; a plugin that cannot load says so
    assert solvers["dfs"]["description"].startswith(SOLVE_DOC)
    assert solvers["dfs"]["unavailable"] is None and solvers["dfs"]["options"] == []
    assert "fails to load" in solvers["broken"]["description"] and solvers["broken"]["unavailable"]


def test_dfs_plugin_solves_and_its_plan_validates(plugin_env):
    proc = bcc(plugin_env, "solve", "bridge", "--solver", "dfs", "--json")
    assert proc.returncode == 0, proc.stderr
    result = json.loads(proc.stdout)
    assert result["solved"] is True and result["status"] == "solved"
    assert result["solver"] == "dfs"
    assert result["plan"] and result["cost"] is not None
    check = bcc(plugin_env, "validate", "bridge", "-", stdin=proc.stdout)
    assert check.returncode == 0, check.stdout + check.stderr
    assert check.stdout.startswith("valid:")


def test_dfs_plugin_honours_the_state_budget(plugin_env):
    proc = bcc(plugin_env, "solve", "bridge", "--solver", "dfs", "--max-states", "1", "--json")
    assert proc.returncode == 1, proc.stderr
    result = json.loads(proc.stdout)
    assert result["solved"] is False and result["status"] == "budget" and result["budget"] == "max_states"


def test_broken_plugin_is_reported_by_name_in_one_line(plugin_env):
    proc = bcc(plugin_env, "solve", "bridge", "--solver", "broken")
    assert proc.returncode == 2, proc.stdout + proc.stderr
    lines = proc.stderr.splitlines()
    assert len(lines) == 1, proc.stderr
    assert "broken" in lines[0] and "failed to load" in lines[0]
    assert "Traceback" not in proc.stderr
    assert proc.stdout == ""


def test_builtins_still_work_with_a_broken_plugin_installed(plugin_env):
    proc = bcc(plugin_env, "solve", "bridge", "--solver", "bfs", "--json")
    assert proc.returncode == 0, proc.stderr
    result = json.loads(proc.stdout)
    assert result["solved"] is True and result["solver"] == "bfs"
