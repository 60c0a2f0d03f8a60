#!/usr/bin/env python3
"""Whole-process `bcc solve` beside Fast Downward, in the same run: prints a table, writes
bench/engine.json (and bench/engine.png with matplotlib).

    python bench/engine.py             # reference dungeons + generated mazes 11-65 wide, 0-12 stones
    python bench/engine.py --quick     # a few cases
    python bench/engine.py --time-limit 60

For each dungeon: `bcc solve` (A*, `auto`) as a whole process with a cold cache (a fresh
cache folder) and a warm one (the second run), `bcc solve --heuristic blind`, and Fast
Downward's `astar(blind())` and `astar(lmcut())` on bcc's own PDDL export (translator
included: the driver's whole process). Each row: wall seconds, peak memory of the
process (ru_maxrss of the child), the plan cost (equal costs are checked), bcc's bytes
per state (`bcc compile --json`), and the ratio bcc / Fast Downward's best configuration.
Fast Downward comes from `pip install "bcc[pddl]"` (up-fast-downward); without it the
Fast Downward columns are empty. Generated dungeons and PDDL files go to a temporary
folder, never into the repository. Machine noise: run on a quiet machine; expansions
and bytes are exact, seconds are not.
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))   # also when a test loads this file by its path
from timed_env import timed_env  # noqa: E402
REFERENCE = ["bridge", "easy_maze", "tough_maze", "four_rooms"]
# (width, stones, seed): 11-65 wide, 0-12 stones
GENERATED = [(11, 0, 1), (11, 4, 2), (15, 2, 3), (21, 0, 4), (21, 6, 1), (31, 2, 5), (41, 4, 6), (51, 12, 1),
             (65, 0, 7), (65, 10, 1)]
QUICK_GENERATED = [(11, 4, 2), (21, 6, 1), (65, 10, 1)]


# Fast Downward's --overall-time-limit counts CPU seconds; our wall-clock kill only backs
# it up, generously: on a loaded machine a 120 s wall limit stopped it after 8 s of CPU,
# rows that said nothing about its speed.
FD_WALL_FACTOR = 4


def run(cmd: list, env: dict | None = None, timeout: float = 600) -> dict:
    """One whole process: wall seconds, peak RSS (MB), exit code, stdout."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, text=True,
                            start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        kill_group(proc)
        out, err = proc.communicate()
    wall = time.perf_counter() - start
    return {"wall": round(wall, 3), "code": proc.returncode, "stdout": out, "stderr": err}


def kill_group(proc) -> None:
    """Stop a timed process and its children (Fast Downward's driver runs the search as a
    child, which would outlive the driver and keep a core busy through the next rows)."""
    import signal
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass


def peak_of(cmd: list, env: dict | None = None, timeout: float = 600, cwd: Path | None = None) -> dict:
    """`run`, with wait4's peak of the child (ru_maxrss: an upper bound, since it starts
    from this process's size at fork; the rows use the peak the child reports itself)."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, start_new_session=True,
                            cwd=cwd)
    out_chunks = []
    deadline = start + timeout
    import selectors
    sel = selectors.DefaultSelector()
    sel.register(proc.stdout, selectors.EVENT_READ)
    sel.register(proc.stderr, selectors.EVENT_READ)
    err_chunks = []
    open_streams = 2
    while open_streams:
        if time.perf_counter() > deadline:
            kill_group(proc)
            break
        for key, _ in sel.select(timeout=0.5):
            data = os.read(key.fd, 65536)
            if not data:
                sel.unregister(key.fileobj)
                open_streams -= 1
            elif key.fileobj is proc.stdout:
                out_chunks.append(data)
            else:
                err_chunks.append(data)
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    wall = time.perf_counter() - start
    return {"wall": round(wall, 3), "cpu": round(usage.ru_utime + usage.ru_stime, 3),
            "code": proc.returncode, "peak_mb": round(usage.ru_maxrss / 1024, 1),
            "stdout": b"".join(out_chunks).decode(errors="replace"),
            "stderr": b"".join(err_chunks).decode(errors="replace")}


def fd_driver() -> Path | None:
    try:
        from bcc.solvers.fast_downward import driver
        return driver()
    except Exception:  # noqa: BLE001 - not installed: the FD columns stay empty
        return None


def fd_cost(stdout: str) -> int | None:
    for line in stdout.splitlines():
        if "Plan cost:" in line:
            return int(line.rsplit(":", 1)[1].strip())
    return None


def fd_peak_mb(stdout: str) -> float | None:
    """The search's `Peak memory: N KB` (Fast Downward's own report; the translator's is lower)."""
    peaks = [int(line.split(":", 1)[1].split()[0]) for line in stdout.splitlines() if "Peak memory:" in line]
    return round(max(peaks) / 1024, 1) if peaks else None


def bench_case(label: str, dungeon: str, work: Path, time_limit: float, fd: Path | None) -> dict:
    bcc = [sys.executable, "-m", "bcc"]
    env = dict(timed_env(), BCC_CACHE_DIR=str(work / f"cache-{label}"))
    row = {"case": label}
    report = json.loads(run(bcc + ["compile", dungeon, "--json"], env=dict(env, BCC_NO_CACHE="1"))["stdout"])
    row["state_bytes"] = report["state_bytes"]
    row["size"] = report["size"]
    for name, extra in (("bcc_cold", []), ("bcc_warm", []), ("bcc_blind", ["--heuristic", "blind"])):
        r = peak_of(bcc + ["solve", dungeon, "--json", "--time-limit", str(time_limit)] + extra, env=env,
                    timeout=time_limit + 60)
        try:
            data = json.loads(r["stdout"])
        except ValueError:
            data = {}
        # the process's own peak (ru_maxrss of a child also counts the parent's at fork)
        row[name] = {"wall": r["wall"], "cpu": r["cpu"], "peak_mb": data.get("peak_mb"), "cost": data.get("cost"),
                     "expanded": data.get("expanded"), "stored": data.get("stored"),
                     "search_seconds": data.get("seconds"), "status": data.get("status", f"exit {r['code']}")}
    if fd is not None:
        pddl = work / f"pddl-{label}"
        exported = run(bcc + ["export", "pddl", dungeon, "-o", str(pddl)], env=env, timeout=time_limit + 60)
        if exported["code"] == 0:
            for name, search in (("fd_blind", "astar(blind())"), ("fd_lmcut", "astar(lmcut())")):
                plan = work / f"plan-{label}-{name}"
                r = peak_of([sys.executable, str(fd), "--plan-file", str(plan), "--overall-time-limit",
                             f"{int(time_limit)}s", str(pddl / "domain.pddl"), str(pddl / "problem.pddl"),
                             "--search", search], env=timed_env(), timeout=FD_WALL_FACTOR * time_limit + 60,
                            cwd=work)   # the translator writes output.sas into its working folder
                row[name] = {"wall": r["wall"], "cpu": r["cpu"], "peak_mb": fd_peak_mb(r["stdout"]),
                             "cost": fd_cost(r["stdout"]),
                             "status": "solved" if r["code"] == 0 else f"exit {r['code']}"}
        else:
            row["fd_error"] = exported["stderr"].strip().splitlines()[-1:] or ["export failed"]
    solved = [k for k in ("fd_blind", "fd_lmcut") if k in row and row[k]["status"] == "solved"]
    if solved:
        # Fast Downward's best configuration: the faster one, by wall and by CPU seconds
        # (CPU is steadier on a shared machine; wall includes waiting for a core)
        row["fd_best_wall"] = min(row[k]["wall"] for k in solved)
        row["fd_best_cpu"] = min(row[k]["cpu"] for k in solved)
        for k in ("bcc_cold", "bcc_warm"):
            row[f"ratio_{k}"] = round(row[k]["wall"] / row["fd_best_wall"], 2)
            row[f"ratio_{k}_cpu"] = round(row[k]["cpu"] / row["fd_best_cpu"], 2)
    costs = {row[k]["cost"] for k in ("bcc_cold", "bcc_warm", "bcc_blind", "fd_blind", "fd_lmcut")
             if k in row and row[k].get("cost") is not None}
    row["costs_agree"] = len(costs) <= 1
    return row


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--time-limit", type=float, default=60)
    ap.add_argument("--output", default=str(HERE / "engine.json"))
    args = ap.parse_args()
    from bcc.generate import generate_maze
    fd = fd_driver()
    load_before = os.getloadavg()
    rows = []
    with tempfile.TemporaryDirectory(prefix="bcc-bench-") as tmp:
        work = Path(tmp)
        cases = [(name, name) for name in (REFERENCE[2:3] if args.quick else REFERENCE)]
        for width, stones, seed in (QUICK_GENERATED if args.quick else GENERATED):
            path = work / f"maze_{width}_s{stones}_seed{seed}.yaml"
            path.write_text(generate_maze(width, width, stones=stones, seed=seed))
            cases.append((path.stem, str(path)))
        print(f"{'case':<24}{'bytes/state':>12}{'bcc cold':>10}{'warm':>8}{'blind':>8}{'FD blind':>10}"
              f"{'FD lmcut':>10}{'ratio':>7}{'cpu ratio':>10}{'search s':>9}{'bcc MB':>8}{'FD MB':>7}{'cost':>6}")
        nan = float("nan")
        for label, dungeon in cases:
            row = bench_case(label, dungeon, work, args.time_limit, fd)
            rows.append(row)
            sb = row["state_bytes"]
            fdb, fdl = row.get("fd_blind", {}), row.get("fd_lmcut", {})
            fd_mb = min([r["peak_mb"] for r in (fdb, fdl) if r and r["peak_mb"] is not None], default=None)
            warm = row["bcc_warm"]
            print(f"{label:<24}{sb['typical']:>12}{row['bcc_cold']['wall']:>10.2f}{warm['wall']:>8.2f}"
                  f"{row['bcc_blind']['wall']:>8.2f}{fdb.get('wall', nan):>10.2f}"
                  f"{fdl.get('wall', nan):>10.2f}{row.get('ratio_bcc_warm', nan):>7.2f}"
                  f"{row.get('ratio_bcc_warm_cpu', nan):>10.2f}{warm['search_seconds'] or nan:>9.3f}"
                  f"{warm['peak_mb'] or nan:>8.0f}{fd_mb if fd_mb is not None else nan:>7.0f}"
                  f"{str(warm['cost']):>6}{'' if row['costs_agree'] else '  COSTS DIFFER'}", flush=True)
    print("seconds: whole processes, wall; ratio: bcc warm / Fast Downward's best configuration (wall, then CPU); "
          "search s: bcc warm's own search time")
    data = {"machine": {"python": platform.python_version(), "platform": platform.platform(),
                        "cpus": os.cpu_count(), "load_before": load_before, "load_after": os.getloadavg()},
            "fast_downward": str(fd) if fd else None, "time_limit": args.time_limit, "rows": rows}
    from bcc.atomic import write_text
    write_text(args.output, json.dumps(data, indent=2) + "\n")
    print(f"wrote {args.output}")
    plot(rows, Path(args.output).with_suffix(".png"))


def plot(rows: list, path: Path) -> None:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no plot: pip install matplotlib")
        return
    labels = [r["case"] for r in rows]
    fig, ax = plt.subplots(figsize=(10, 4))
    x = range(len(rows))
    for k, (key, name) in enumerate((("bcc_cold", "bcc cold"), ("bcc_warm", "bcc warm"), ("fd_blind", "FD blind"),
                                     ("fd_lmcut", "FD lmcut"))):
        ax.bar([i + k * 0.2 for i in x], [r.get(key, {}).get("wall", 0) for r in rows], width=0.2, label=name)
    ax.set_xticks([i + 0.3 for i in x])
    ax.set_xticklabels(labels, rotation=45, ha="right", fontsize="small")
    ax.set_ylabel("whole-process seconds")
    ax.set_yscale("log")
    ax.legend(fontsize="small")
    fig.tight_layout()
    import io
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100)
    plt.close(fig)
    from bcc.atomic import write_bytes
    write_bytes(str(path), buf.getvalue())
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
