#!/usr/bin/env python3
"""Benchmark: every reference dungeon x solver; prints a table, writes bench/results/*.json.

Speed is reported as ratios against BFS in the same run (shared machines make absolute
seconds noisy). Each (dungeon, solver) runs in its own process so peak memory is its own.

    python bench/solve_reference.py [--repeat 3] [--time-limit 300] [--only tough_maze]
"""
from __future__ import annotations

import argparse
import json
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

DUNGEONS = [("grid", None), ("bridge", None), ("easy_maze", None), ("tough_maze", None),
            ("four_rooms", None), ("four_rooms_red", None), ("four_rooms_orange", None), ("four_rooms_green", None)]
SOLVERS = [("bfs", None), ("astar", "blind"), ("astar", "manhattan")]


def run_one(dungeon: str, solver: str, heuristic: str | None, time_limit: float) -> dict:
    cmd = [sys.executable, "-m", "bcc", "solve", dungeon, "--solver", solver, "--json", "--time-limit", str(time_limit)]
    if heuristic:
        cmd += ["--heuristic", heuristic]
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if proc.returncode not in (0, 1):
        return {"error": proc.stderr.strip(), "wall": wall}
    data = json.loads(proc.stdout)
    data["wall"] = wall
    return data


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--time-limit", type=float, default=300)
    ap.add_argument("--only", action="append", help="run only these dungeons")
    ap.add_argument("--out", default=str(Path(__file__).resolve().parent / "results"))
    args = ap.parse_args()
    rows = []
    for dungeon, goal in DUNGEONS:
        if args.only and dungeon not in args.only:
            continue
        base_seconds = None
        for solver, heuristic in SOLVERS:
            runs = [run_one(dungeon, solver, heuristic, args.time_limit) for _ in range(args.repeat)]
            ok = [r for r in runs if "error" not in r]
            if not ok:
                rows.append({"dungeon": dungeon, "solver": solver, "heuristic": heuristic, "error": runs[0]["error"]})
                continue
            r = ok[0]
            seconds = statistics.median(x["seconds"] for x in ok)
            if solver == "bfs":
                base_seconds = seconds
            rows.append({
                "dungeon": dungeon, "solver": solver, "heuristic": heuristic, "solved": r["solved"],
                "cost": r["cost"], "expanded": r["expanded"], "generated": r["generated"], "stored": r["stored"],
                "seconds": seconds, "peak_mb": max(x["peak_mb"] for x in ok),
                "speedup_vs_bfs": round(base_seconds / seconds, 2) if base_seconds and seconds else None,
            })
    header = f"{'dungeon':<18} {'solver':<16} {'cost':>5} {'expanded':>10} {'stored':>10} {'seconds':>9} {'x bfs':>6} {'peak MB':>8}"
    print(header)
    print("-" * len(header))
    for row in rows:
        name = row["solver"] + (f"/{row['heuristic']}" if row["heuristic"] else "")
        if "error" in row:
            print(f"{row['dungeon']:<18} {name:<16} error: {row['error']}")
            continue
        print(f"{row['dungeon']:<18} {name:<16} {row['cost'] if row['cost'] is not None else '-':>5} "
              f"{row['expanded']:>10,} {row['stored']:>10,} {row['seconds']:>9.3f} "
              f"{row['speedup_vs_bfs'] or '-':>6} {row['peak_mb']:>8.1f}")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    stamp = time.strftime("%Y%m%d-%H%M%S")
    payload = {"when": stamp, "python": sys.version.split()[0], "machine": platform.machine(),
               "repeat": args.repeat, "rows": rows}
    target = out / f"solve_reference-{stamp}.json"
    tmp = target.with_suffix(".tmp")
    tmp.write_text(json.dumps(payload, indent=2) + "\n")
    tmp.replace(target)
    print(f"\nwrote {target}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
