"""The Ray backend: on a local Ray with 2 CPUs (started here), a sweep gives the same
solved/cost/expanded per run as the local process pool, and hard limits and crashes in
Ray tasks become outcomes exactly as they do locally."""
from __future__ import annotations

import json
import os
import time

import pytest
from click.testing import CliRunner

from bcc.batch import Limits, build_runs, expand_dungeons, map_runs, run_batch
from bcc.cli import main

ray = pytest.importorskip("ray", reason='the ray backend needs Ray: pip install ".[ray]" in the bcc checkout')

SAME = ("key", "dungeon", "size", "solver", "seed", "options", "solved", "status", "budget", "cost",
        "plan_length", "expanded", "generated", "stored", "error")


@pytest.fixture(scope="module")
def local_ray():
    if ray.is_initialized():
        ray.shutdown()
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    yield
    ray.shutdown()


def runs():
    dungeons = expand_dungeons(["bridge", "grid", "maze:width=9,depth=9,stones=1,seed=1..2"])
    return (build_runs(dungeons, [("astar", {}, {}), ("bfs", {}, {})], [0])
            + build_runs(["grid"], [("qlearning", {"episodes": 3}, {})], [0, 1]))


def test_ray_rows_equal_local_rows(local_ray, tmp_path):
    todo = runs()
    run_batch(todo, out=str(tmp_path / "local.jsonl"), backend="local", workers=2)
    summary = run_batch(todo, out=str(tmp_path / "ray.jsonl"), backend="ray")
    assert summary["ran"] == len(todo) and summary["errors"] == 0

    def rows(name):
        found = [json.loads(l) for l in (tmp_path / name).read_text().splitlines()]
        return {r["key"]: {k: r[k] for k in SAME} for r in found}
    local, remote = rows("local.jsonl"), rows("ray.jsonl")
    assert set(local) == {r.key for r in todo}
    assert remote == local
    assert sum(r["solved"] for r in local.values()) >= 8    # A* and BFS solve all four dungeons


def test_cli_ray_backend_resumes_like_local(local_ray, tmp_path):
    out = tmp_path / "r.jsonl"
    args = ["batch", "bridge", "grid", "--backend", "ray", "--workers", "2", "--out", str(out), "--json"]
    first = CliRunner().invoke(main, args, catch_exceptions=False)
    assert first.exit_code == 0, first.stderr
    assert json.loads(first.stdout)["ran"] == 2
    again = json.loads(CliRunner().invoke(main, args, catch_exceptions=False).stdout)
    assert again["skipped"] == 2 and again["ran"] == 0 and len(out.read_text().splitlines()) == 2


def test_crashes_and_hard_limits_in_ray_tasks(local_ray):
    # builtins, so Ray workers can unpickle them: os._exit(3) crashes, time.sleep hangs,
    # bytearray(2 GB) needs more than the 200 MB the worker may add
    cases = [(os._exit, 3), (time.sleep, 3600), (bytearray, 2 * 10**9), (abs, -4)]
    found = {}
    for function, item in cases:
        [outcome] = list(map_runs(function, [item], backend="ray", limits=Limits(wall_seconds=3, memory_mb=200)))
        found[function.__name__] = outcome
    assert found["_exit"].error == "worker died: exit status 3 before returning a result"
    assert found["sleep"].limit == "time_limit"
    assert found["bytearray"].limit == "max_memory"
    assert found["abs"].ok and found["abs"].value == 4
