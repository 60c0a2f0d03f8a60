"""`bcc batch`: run sets, generator specs, sweep files, the results file, hard limits in
the workers, resuming after a kill, and the report.

Plan costs are never copied from output: A* and BFS rows of the same dungeon must agree
(both are optimal), and the bridge's 13 steps are derived by hand in `test_rows_*`.
"""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from click.testing import CliRunner

from bcc.batch import Limits, build_runs, expand_dungeons, map_runs, read_rows, run_batch
from bcc.batch.dungeons import open_dungeon
from bcc.batch.store import ResultsFile
from bcc.cli import main
from bcc.errors import BccError
from bcc.generate import generate_maze

ROW_FIELDS = {"key", "dungeon", "size", "solver", "seed", "solved", "cost", "expanded", "seconds", "peak_mb", "error"}


def bcc(*args):
    return CliRunner().invoke(main, list(args), catch_exceptions=False)


def rows_in(path) -> list[dict]:
    return [json.loads(line) for line in Path(path).read_text().splitlines()]


# ---- dungeons and run sets ---------------------------------------------------------------

def test_generator_specs_expand_ranges_and_alternatives_to_canonical_names():
    names = expand_dungeons(["maze:seed=1..3,stones=0|2,width=7,depth=9"])
    assert names == [f"maze:width=7,depth=9,{s}seed={seed}" for s in ("", "stones=2,") for seed in (1, 2, 3)]
    # the worker regenerates exactly what `bcc generate maze` writes for those parameters
    with open_dungeon("maze:width=7,depth=9,stones=2,seed=3") as path:
        text = Path(path).read_text()
    assert text.split("\n", 1)[1] == generate_maze(7, 9, stones=2, seed=3).split("\n", 1)[1]


@pytest.mark.parametrize("spec, message", [
    ("maze:width=14", "width must be odd"),
    ("maze:widht=15", "did you mean 'width'"),
    ("maze:seed=5..1", "is empty"),
    ("maze:seed=x", "whole number"),
    ("maze:width", "expected key=value"),
    ("maze:seed=0..99999999", "at most 100,000"),              # refused before 10^8 names are built
    ("maze:width=5|7|9,seed=0..40000", "makes 120,003 runs"),  # 3 widths x 40,001 seeds
])
def test_bad_generator_specs_are_one_error_naming_the_spec(spec, message):
    with pytest.raises(BccError) as err:
        expand_dungeons([spec])
    assert message in str(err.value) and repr(spec) in str(err.value)


def test_globs_files_and_shipped_names(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    for seed in (2, 1):
        (tmp_path / f"m{seed}.yaml").write_text(generate_maze(5, 5, seed=seed))
    assert expand_dungeons(["m*.yaml", "bridge", "m1.yaml"]) == ["m1.yaml", "m2.yaml", "bridge"]
    with pytest.raises(BccError, match="no dungeon files match"):
        expand_dungeons(["nothing*.yaml"])
    with pytest.raises(BccError, match="did you mean 'bridge'"):
        expand_dungeons(["bridg"])


def test_a_sweep_past_the_run_limit_is_one_error_before_anything_is_built():
    import resource
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    r = bcc("batch", "run", "grid", "--solver", "rmax", "--seeds", "999999999", "--out", "unused.jsonl")
    assert r.exit_code == 2 and "at most 100,000" in r.stderr
    # 10^9 seeds as a list would take tens of GB; refused, the process barely grew (KB)
    assert resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before < 100_000
    with pytest.raises(BccError, match="dungeons x solvers x seeds"):
        build_runs([f"d{i}" for i in range(400)], [("rmax", {}, {})], list(range(300)))


def test_run_set_is_the_product_and_seeds_multiply_only_seeded_solvers():
    runs = build_runs(["grid", "bridge"], [("astar", {}, {}), ("rmax", {"episodes": 2}, {})], [0, 1, 2])
    assert len(runs) == 2 * (1 + 3)
    assert {r.seed for r in runs if r.solver == "astar"} == {None}
    assert len({r.key for r in runs}) == len(runs)
    # the key ignores everything but what determines the result
    again = build_runs(["grid", "bridge"], [("astar", {}, {}), ("rmax", {"episodes": 2}, {})], [0, 1, 2])
    assert [r.key for r in runs] == [r.key for r in again]
    limited = build_runs(["grid"], [("astar", {}, {"time_limit": 5})], [0])
    assert limited[0].key != runs[0].key


# ---- sweep files -------------------------------------------------------------------------

SWEEP = """\
dungeons:
  - bridge
  - "maze:width=7,depth=7,stones=1,seed=1..2"
solvers:
  - bfs
  - {solver: astar, heuristic: [manhattan, pdb]}
  - {solver: qlearning, episodes: 5}
seeds: 2
budget: {time_limit: 60}
"""


def test_sweep_file_expands_to_its_product(tmp_path):
    from bcc.batch import load_sweep
    path = tmp_path / "sweep.yaml"
    path.write_text(SWEEP)
    sweep = load_sweep(str(path))
    assert sweep.dungeons == ["bridge", "maze:width=7,depth=7,stones=1,seed=1", "maze:width=7,depth=7,stones=1,seed=2"]
    assert [(s, o) for s, o, _ in sweep.settings] == [
        ("bfs", {}), ("astar", {"heuristic": "manhattan"}), ("astar", {"heuristic": "pdb"}),
        ("qlearning", {"episodes": 5})]
    assert sweep.seeds == [0, 1] and sweep.budget == {"time_limit": 60}


@pytest.mark.parametrize("bad, token, message", [
    ("  - {solver: astar, heuristic: [manhattan, pbd]}", "pbd",
     "`heuristic` must be one of auto, pdb, manhattan, blind, "),   # then every other heuristic
    ("  - {solver: astar, heuristic: [manhattan, pbd]}", "pbd", "got 'pbd' (did you mean 'pdb'?)"),
    ("  - {solver: bfs, weight: 2}", "weight", "`weight` does not apply to bfs (its options: none)"),
    ("  - {solver: rmax, heuristic: pdb}", "heuristic", "`heuristic` does not apply to rmax"),
    ("  - {solver: qlearning, gamma: 1.5}", "1.5", "`gamma` must be a number >= 0 and <= 1, got 1.5"),
    ("  - {solver: qlearning, seed: 1}", "seed", "seeds are swept with `seeds:`"),
    ("  - {solver: astr}", "astr", "did you mean 'astar'"),
    ("  - {solver: astar, heurstic: pdb}", "heurstic", "`heurstic` does not apply to astar (did you mean 'heuristic'?)"),
])
def test_sweep_errors_point_into_the_file(tmp_path, bad, token, message):
    path = tmp_path / "sweep.yaml"
    path.write_text(SWEEP.replace("  - {solver: astar, heuristic: [manhattan, pdb]}", bad))
    result = bcc("batch", "--sweep", str(path), "--out", str(tmp_path / "r.jsonl"))
    assert result.exit_code == 2
    col = bad.index(token) + 1      # line 6 of SWEEP is the replaced solver entry
    assert result.stderr.startswith(f"{path}:6:{col}: ") and message in result.stderr, result.stderr
    assert not (tmp_path / "r.jsonl").exists()


def test_sweep_error_in_a_dungeon_spec_points_at_its_line(tmp_path):
    path = tmp_path / "sweep.yaml"
    path.write_text(SWEEP.replace("width=7,depth=7", "width=8,depth=7"))
    result = bcc("batch", "--sweep", str(path), "--out", str(tmp_path / "r.jsonl"))
    assert result.exit_code == 2 and result.stderr.startswith(f"{path}:3:5: ") and "width must be odd" in result.stderr


# ---- running a sweep ---------------------------------------------------------------------

def test_rows_have_the_promised_fields_and_optimal_solvers_agree(tmp_path):
    out = tmp_path / "r.jsonl"
    result = bcc("batch", "bridge", "maze:width=9,depth=9,stones=1,seed=1..3", "--solver", "astar",
                 "--solver", "bfs", "--workers", "2", "--out", str(out), "--json")
    assert result.exit_code == 0, result.stderr
    summary = json.loads(result.stdout)
    assert summary["runs"] == summary["ran"] == summary["solved"] == 8 and summary["errors"] == 0
    assert result.stderr == ""      # not a terminal: no progress bar
    rows = rows_in(out)
    assert len(rows) == 8 and all(ROW_FIELDS <= set(r) for r in rows)
    cost = {(r["dungeon"], r["solver"]): r["cost"] for r in rows}
    for dungeon in {d for d, _ in cost}:
        assert cost[dungeon, "astar"] == cost[dungeon, "bfs"]   # two optimal solvers, one optimum
    # bridge by hand: turn round (2), look down, mine, pick up... see tests/test_solvers.py: 13
    assert cost["bridge", "astar"] == 13
    assert {r["size"] for r in rows if r["dungeon"].startswith("maze")} == {81}
    assert all(r["error"] is None and r["peak_mb"] > 0 for r in rows)
    # the same command again runs nothing and reports the same totals
    again = json.loads(bcc("batch", "bridge", "maze:width=9,depth=9,stones=1,seed=1..3", "--solver", "astar",
                           "--solver", "bfs", "--out", str(out), "--json").stdout)
    assert again["skipped"] == 8 and again["ran"] == 0 and again["solved"] == 8
    assert len(rows_in(out)) == 8


def test_budget_exhausted_and_bad_dungeons_are_rows_not_failures(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    Path("bad.yaml").write_text("dungeon: bad\ndomain: minecraft\nheight: 4\n")
    out = tmp_path / "r.jsonl"
    result = bcc("batch", "tough_maze", "bad.yaml", "--solver", "bfs", "--max-states", "50", "--out", str(out))
    assert result.exit_code == 0, result.stderr
    rows = {r["dungeon"]: r for r in rows_in(out)}
    assert rows["tough_maze"]["status"] == "budget" and rows["tough_maze"]["budget"] == "max_states"
    assert rows["tough_maze"]["error"] is None and not rows["tough_maze"]["solved"]
    assert rows["bad.yaml"]["error"].startswith("bad.yaml:1:1: ") and "\n" not in rows["bad.yaml"]["error"]
    assert rows["bad.yaml"]["status"] == "error" and rows["bad.yaml"]["cost"] is None


# ---- hard limits in the workers ----------------------------------------------------------

def _exit_hard(item):
    if item == "crash":
        os._exit(3)
    if item == "signal":
        os.kill(os.getpid(), signal.SIGTERM)
    if item == "hog":
        hoard = []
        while True:
            hoard.append(bytearray(16 * 2**20))
    if item == "hang":
        time.sleep(3600)
    if item == "raise":
        raise ValueError("bad\nitem")
    return item.upper()


def test_crashes_hogs_and_hangs_become_outcomes_and_the_rest_go_on():
    items = ["a", "crash", "hog", "b", "hang", "signal", "raise", "c"]
    outcomes = {o.index: o for o in map_runs(_exit_hard, items, workers=2,
                                             limits=Limits(wall_seconds=3, memory_mb=200))}
    assert sorted(outcomes) == list(range(len(items)))
    by_item = {items[i]: o for i, o in outcomes.items()}
    assert [by_item[x].value for x in "abc"] == ["A", "B", "C"] and all(by_item[x].ok for x in "abc")
    assert by_item["crash"].error == "worker died: exit status 3 before returning a result"
    assert by_item["crash"].limit is None
    assert by_item["signal"].error == "worker died: killed by SIGTERM"
    assert by_item["hog"].limit == "max_memory"
    assert by_item["hang"].limit == "time_limit" and "killed after 3 s" in by_item["hang"].error
    assert by_item["raise"].error == "ValueError: bad item" and by_item["raise"].limit is None


PLUGIN = '''
import os
from bcc.solvers.base import Result

def crash(model, budget, progress=None, **options):
    os._exit(9)

def hog(model, budget, progress=None, **options):
    hoard = []                      # ignores its memory budget on purpose
    while True:
        hoard.append(bytearray(16 * 2**20))
'''


def test_plugin_solvers_that_crash_or_ignore_their_budget_give_rows(tmp_path):
    """A crashing plugin is an error row, a runaway one a budget row; the sweep goes on."""
    site = tmp_path / "site"
    (site / "bcc_rogue-0.1.dist-info").mkdir(parents=True)
    (site / "bcc_rogue.py").write_text(PLUGIN)
    (site / "bcc_rogue-0.1.dist-info" / "METADATA").write_text("Metadata-Version: 2.1\nName: bcc-rogue\nVersion: 0.1\n")
    (site / "bcc_rogue-0.1.dist-info" / "entry_points.txt").write_text(
        "[bcc.solvers]\ncrash = bcc_rogue:crash\nhog = bcc_rogue:hog\n")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(filter(None, [str(site), os.environ.get("PYTHONPATH")])))
    out = tmp_path / "r.jsonl"
    proc = subprocess.run([sys.executable, "-m", "bcc", "batch", "bridge", "grid", "--solver", "crash",
                           "--solver", "hog", "--solver", "astar", "--max-memory", "150", "--workers", "2",
                           "--out", str(out), "--json"], capture_output=True, text=True, env=env, timeout=120)
    assert proc.returncode == 0, proc.stderr
    rows = {(r["dungeon"], r["solver"]): r for r in rows_in(out)}
    assert len(rows) == 6
    for dungeon in ("bridge", "grid"):
        assert rows[dungeon, "crash"]["error"] == "worker died: exit status 9 before returning a result"
        assert rows[dungeon, "hog"]["status"] == "budget" and rows[dungeon, "hog"]["budget"] == "max_memory"
        assert rows[dungeon, "astar"]["solved"]
    assert json.loads(proc.stdout)["errors"] == 2


# ---- loss-free and resumable -------------------------------------------------------------

def test_a_torn_last_line_is_dropped_and_its_run_redone(tmp_path):
    runs = build_runs(["bridge", "grid"], [("astar", {}, {})], [0])
    out = tmp_path / "r.jsonl"
    run_batch(runs[:1], out=str(out), workers=1)
    whole = out.read_bytes()
    out.write_bytes(whole + b'{"key": "' + runs[1].key.encode() + b'", "dungeon": "gr')  # a write cut short
    contents = read_rows(str(out))
    assert len(contents.rows) == 1 and contents.torn_tail > 0
    summary = run_batch(runs, out=str(out), workers=1)
    assert summary["skipped"] == 1 and summary["ran"] == 1 and summary["torn_bytes_dropped"] > 0
    rows = rows_in(out)
    assert [r["key"] for r in rows] == [r.key for r in runs]


def test_a_torn_last_line_longer_than_a_read_block_is_dropped_too(tmp_path):
    runs = build_runs(["bridge", "grid"], [("astar", {}, {})], [0])
    out = tmp_path / "r.jsonl"
    run_batch(runs[:1], out=str(out), workers=1)
    whole = out.read_bytes()
    torn = b'{"key": "' + runs[1].key.encode() + b'", "message": "' + b"x" * 200_000  # cut short, 200 KB long
    out.write_bytes(whole + torn)
    summary = run_batch(runs, out=str(out), workers=1)
    assert summary["torn_bytes_dropped"] == len(torn)
    rows = rows_in(out)  # every line parses: the torn line is gone, not kept as a bad line
    assert [r["key"] for r in rows] == [r.key for r in runs]


def test_appends_are_whole_lines(tmp_path, monkeypatch):
    from bcc.batch import store
    monkeypatch.setattr(store, "LOCK_WAIT_SECONDS", 0.3)   # how long a second sweep waits for the lock
    out = tmp_path / "r.jsonl"
    with ResultsFile(str(out)) as f:
        f.append({"key": "a", "text": "x" * 200_000})
        f.append({"key": "b"})
        with pytest.raises(BccError, match="another `bcc batch` is writing this results file"):
            ResultsFile(str(out)).open_for_append()     # a second sweep on the same file
    assert [r["key"] for r in rows_in(out)] == ["a", "b"] and out.read_bytes().endswith(b"\n")


def test_a_killed_sweep_resumes_with_exactly_one_row_per_run(tmp_path):
    """Rerun at once after a SIGKILL: the dying workers still hold the results file's lock
    for a moment (under load it made the rerun fail as 'another bcc batch is writing'); the
    rerun waits for them."""
    spec = "maze:width=15,depth=15,stones=1,seed=1..12"
    out = tmp_path / "r.jsonl"
    cmd = [sys.executable, "-m", "bcc", "batch", spec, "--workers", "2", "--out", str(out)]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None:
        if out.exists() and out.read_bytes().count(b"\n") >= 3:
            break
        time.sleep(0.05)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    first = rows_in(out)
    assert 3 <= len(first) < 12, "the sweep should have been killed half-way"
    proc = subprocess.run(cmd + ["--json"], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    summary = json.loads(proc.stdout)
    assert summary["skipped"] == len(first) and summary["ran"] == 12 - len(first)
    data = out.read_bytes()
    assert data.endswith(b"\n")
    rows = rows_in(out)          # every line parses: nothing torn
    expected = {r.key for r in build_runs(expand_dungeons([spec]), [("astar", {}, {})], [0])}
    assert sorted(r["key"] for r in rows) == sorted(expected)   # exactly one row per run
    assert rows[:len(first)] == first                           # what was written stays as it was


# ---- CLI edges and the report --------------------------------------------------------------

def test_ray_backend_without_ray_says_how_to_install_it(tmp_path):
    fake = tmp_path / "noray"
    fake.mkdir()
    (fake / "ray.py").write_text("raise ImportError('No module named ray')\n")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(filter(None, [str(fake), os.environ.get("PYTHONPATH")])))
    proc = subprocess.run([sys.executable, "-m", "bcc", "batch", "bridge", "--backend", "ray", "--out",
                           str(tmp_path / "r.jsonl")], capture_output=True, text=True, env=env, timeout=60)
    assert proc.returncode == 2
    assert proc.stderr.strip() == 'the ray backend needs Ray: pip install ".[ray]" in the bcc checkout'


def test_usage_errors_exit_2(tmp_path):
    out = str(tmp_path / "r.jsonl")
    assert bcc("batch", "--out", out).exit_code == 2                              # no dungeons
    result = bcc("batch", "bridge", "--address", "auto", "--out", out)
    assert result.exit_code == 2 and "--backend ray" in result.stderr
    result = bcc("batch", "bridge", "--solver", "bfz", "--out", out)
    assert result.exit_code == 2 and "did you mean 'bfs'" in result.stderr
    assert not Path(out).exists()


def test_report_table_json_and_plot(tmp_path):
    out = tmp_path / "r.jsonl"
    assert bcc("batch", "bridge", "grid", "tough_maze", "--solver", "bfs", "--solver", "astar",
               "--max-states", "2000", "--out", str(out)).exit_code == 0
    rows = rows_in(out)
    result = bcc("batch", "report", str(out), "--json")
    assert result.exit_code == 0
    report = json.loads(result.stdout)
    by_solver = {s["solver"]: s for s in report["solvers"]}
    for solver in ("bfs", "astar"):
        mine = [r for r in rows if r["solver"] == solver]
        assert by_solver[solver]["runs"] == 3
        assert by_solver[solver]["solved"] == sum(r["solved"] for r in mine)
        assert by_solver[solver]["max_expanded"] == max(r["expanded"] for r in mine if r["solved"])
    text = bcc("batch", "report", str(out)).stdout
    assert text.splitlines()[0].split()[:3] == ["solver", "runs", "solved"] and "astar" in text
    pytest.importorskip("matplotlib")
    png = tmp_path / "sizes.png"
    result = bcc("batch", "report", str(out), "--plot", str(png))
    assert result.exit_code == 0 and png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert bcc("batch", "report", str(tmp_path / "none.jsonl")).exit_code == 2
    empty = tmp_path / "empty.jsonl"
    empty.write_text("")
    nothing = bcc("batch", "report", str(empty), "--json")
    assert nothing.exit_code == 1 and json.loads(nothing.stdout)["rows"] == 0
    assert "no runs recorded yet" in bcc("batch", "report", str(empty)).output


def test_progress_bar_counts_done_failed_rate_and_eta():
    import io
    from bcc.batch.progress import ProgressBar
    stream = io.StringIO()
    bar = ProgressBar(4, stream=stream, enabled=True)
    for solved in (True, False, True, True):
        bar.last = 0.0                  # draw every update
        bar.update(solved)
    bar.close()
    frames = stream.getvalue().split("\r")[1:]
    assert len(frames) == 4
    assert "1/4 done, 0 failed" in frames[0] and "2/4 done, 1 failed" in frames[1]
    assert frames[-1].startswith("[" + "#" * ProgressBar.WIDTH + "] 4/4 done, 1 failed")
    assert "runs/s, ETA 00:00" in frames[-1] and stream.getvalue().endswith("\n")
    half = ProgressBar(4, stream=io.StringIO(), enabled=False)
    half.done = 2                       # 2 runs in 30 s: 2 more take 30 s
    assert "2/4 done, 0 failed, 0.07 runs/s, ETA 00:30" in half.line(30.0)


def test_command_line_solver_options_apply_to_every_solver_and_are_checked(tmp_path):
    out = tmp_path / "r.jsonl"
    result = bcc("batch", "grid", "--solver", "astar", "--solver", "gbfs", "--heuristic", "manhattan",
                 "--out", str(out))
    assert result.exit_code == 0, result.output
    rows = rows_in(out)
    assert sorted(r["solver"] for r in rows) == ["astar", "gbfs"]
    assert all(r["options"] == {"heuristic": "manhattan"} and r["heuristic"] == "manhattan" for r in rows)
    # an option one of the solvers does not take is bad input, before anything runs
    refused = bcc("batch", "grid", "--solver", "astar", "--solver", "bfs", "--heuristic", "manhattan",
                  "--out", str(tmp_path / "none.jsonl"))
    assert refused.exit_code == 2 and "--heuristic does not apply to bfs" in refused.output
    assert not (tmp_path / "none.jsonl").exists()
