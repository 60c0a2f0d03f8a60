#!/usr/bin/env python3
"""Heuristics benchmark: expansions and time per heuristic, on the manipulation dungeons
(three rooms, N stones to carry into the blue room) and the reference dungeons.

    python bench/heuristics.py                  # stones 1 2 4, 60 s per run
    python bench/heuristics.py --stones 1 2 4 8 --time-limit 120
    python bench/heuristics.py --quick          # stones 1 2, reference grid/bridge, 20 s
    python bench/heuristics.py --stones 1 2 4 6 8 --reference --configs gbfs:hff --merge
                                                # re-run some rows, keep the others in the json
    python bench/heuristics.py --stones 1 2 4 6 8 --reference --configs astar:auto --no-cache --merge
                                                # cold starts: every run builds what it needs

Prints a table and writes bench/heuristics.json. Every run is a subprocess of the
installed `bcc solve --json` (its own memory, its own budget); `relaxed_build_seconds`
is the time to build the relaxed view once per dungeon, `counting_build_cpu_seconds` the
counting abstraction's (measured apart; that build also leaves them in bcc's on-disk cache,
so the runs read them, unless --no-cache: rows say `cache: warm` or `off`). Expansions are
the figure to compare; timings on a shared machine are noisy: `cpu_seconds` (the whole
`bcc` process's user + system time) suffers less from other load than `seconds` (wall,
as `bcc` reports it).
"""
from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))   # also when a test loads this file by its path
from timed_env import timed_env  # noqa: E402
CONFIGS = [("astar", "blind"), ("astar", "auto"), ("astar", "counting"), ("astar", "hmax"), ("astar", "lmcut"),
           ("gbfs", "hff"), ("gbfs", "hadd"), ("gbfs", "pdb"), ("wastar", "hff")]
REFERENCE = ["grid", "bridge", "easy_maze", "tough_maze", "four_rooms"]


def run(dungeon: str, solver: str, heuristic: str, time_limit: float, cache: bool = True) -> dict:
    cmd = ["bcc", "solve", dungeon, "--solver", solver, "--heuristic", heuristic, "--json",
           "--time-limit", str(time_limit)]
    start = time.perf_counter()
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    env = timed_env() if cache else timed_env(BCC_NO_CACHE="1")
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=time_limit + 60, env=env)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    wall = time.perf_counter() - start
    cpu = after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime
    try:
        data = json.loads(proc.stdout)
    except json.JSONDecodeError:
        data = {"solved": False, "status": f"exit {proc.returncode}", "message": proc.stderr.strip()[-200:]}
    return {"solved": data.get("solved"), "status": data.get("status"), "cost": data.get("cost"),
            "expanded": data.get("expanded"), "seconds": data.get("seconds"), "wall_seconds": round(wall, 3),
            "cpu_seconds": round(cpu, 3),
            "initial_h": data.get("initial_h"), "budget": data.get("budget"),
            "cache": "warm" if cache else "off"}


def build_seconds(dungeon: str, counting: bool) -> dict:
    """Build times of the relaxed view and (with `counting`) the counting abstraction, in
    this process: CPU seconds, with the cache off so they are really built; both are then
    written to the cache for the warm runs."""
    import os
    import bcc.heuristics  # noqa: F401 - the heuristics' tables as model data
    from bcc.compiler import compile_dungeon
    model = compile_dungeon(dungeon)
    start = time.perf_counter()
    task = model.data("relaxed_task")
    out = {"relaxed_build_seconds": round(time.perf_counter() - start, 3),
           "relaxed": None if task is None else {k: v for k, v in task.stats.items() if k != "groups"}}
    if counting:
        os.environ["BCC_NO_CACHE"] = "1"
        try:
            start = time.process_time()
            db = compile_dungeon(dungeon).data("counting_database")
            out["counting_build_cpu_seconds"] = round(time.process_time() - start, 3)
        finally:
            del os.environ["BCC_NO_CACHE"]
        names = [v.label for v in model.variables]
        out["counting"] = None if db is None else {
            "abstract_states": db.states, "exact_cells": len(db.exact),
            "projected": [names[j] for j, _ in db.projected]}
        model.data("counting_database")   # into the cache, for the warm runs
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--stones", type=int, nargs="*", default=[1, 2, 4])
    ap.add_argument("--time-limit", type=float, default=60)
    ap.add_argument("--reference", nargs="*", default=REFERENCE)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--configs", nargs="*", metavar="SOLVER:HEURISTIC",
                    help="run only these configurations (default: all of CONFIGS)")
    ap.add_argument("--no-cache", action="store_true",
                    help="run bcc with BCC_NO_CACHE=1: every run builds the relaxed view (a cold start); "
                         "by default the view built for relaxed_build_seconds is read from the on-disk cache")
    ap.add_argument("--merge", action="store_true",
                    help="replace the rows run in the existing json and keep its other rows")
    ap.add_argument("-o", "--output", default=str(HERE / "heuristics.json"))
    args = ap.parse_args()
    if args.quick:
        args.stones, args.time_limit, args.reference = [1, 2], 20, ["grid", "bridge"]
    configs = CONFIGS if not args.configs else [tuple(c.split(":", 1)) for c in args.configs]
    from bcc.atomic import write_text
    from bcc.generate_rooms import generate_manipulation
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        dungeons = []
        for n in args.stones:
            path = Path(tmp) / f"manipulation_{n}.yaml"
            path.write_text(generate_manipulation(n))
            dungeons.append((f"manipulation_{n}", str(path)))
        dungeons += [(name, name) for name in args.reference]
        print(f"{'dungeon':<16} {'solver':<7} {'heuristic':<9} {'solved':<6} {'cost':>5} {'expanded':>9} {'seconds':>8} {'cpu':>6}")
        for label, ref in dungeons:
            info = build_seconds(ref, any(h in ("auto", "counting") for s, h in configs if s == "astar"))
            for solver, heuristic in configs:
                r = run(ref, solver, heuristic, args.time_limit, cache=not args.no_cache)
                r.update({"dungeon": label, "solver": solver, "heuristic": heuristic, **info})
                rows.append(r)
                print(f"{label:<16} {solver:<7} {heuristic:<9} {str(r['solved']):<6} {str(r['cost']):>5} "
                      f"{str(r['expanded']):>9} {str(r['seconds']):>8} {r['cpu_seconds']:>6}", flush=True)
    out = {"time_limit": args.time_limit, "rows": rows}
    if args.merge and Path(args.output).exists():
        old = json.loads(Path(args.output).read_text())
        def key(r):
            return r["dungeon"], r["solver"], r["heuristic"], r.get("cache", "warm")
        ran = {key(r) for r in rows}
        kept = [dict(r, time_limit=r.get("time_limit", old.get("time_limit"))) for r in old.get("rows", [])
                if key(r) not in ran]
        out = {"time_limit": args.time_limit,
               "rows": kept + [dict(r, time_limit=args.time_limit) for r in rows]}
    write_text(args.output, json.dumps(out, indent=1) + "\n")
    print(f"wrote {args.output}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
