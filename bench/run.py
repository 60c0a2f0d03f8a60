#!/usr/bin/env python3
"""bcc benchmarks, one command: prints tables, writes bench/results.json (and a PNG plot
when matplotlib is installed: `pip install ".[bench]"`).

    python bench/run.py            # everything (about 10-20 minutes on 2 cores)
    python bench/run.py --quick    # smaller sizes, fewer solvers (about 2 minutes)
    python bench/run.py --workers 2  # solves two at a time (faster; timings less clean)

Three parts:
1. reference dungeons x solvers/heuristics;
2. generated mazes of growing size (15 -> 65 cells wide, 0 -> 10 stones) x solvers;
3. simulator throughput: steps/s through the compiled model, against a literal Python
   reading of the spec (tests/spec_reference.py) as the peer, in the same run.
Solves go through the batch API (`bcc.batch.solve_runs`): every solve runs in its own
process (peak memory is its own) with its time limit, and hard limits behind it; one at
a time by default, so timings are not disturbed by each other. `wall_seconds` is compile
plus solve. Speed is compared as ratios against peers in the same run, never as absolute
targets in tests.
"""
from __future__ import annotations

import argparse
import json
import platform
import random
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
REFERENCE = ["grid", "bridge", "easy_maze", "tough_maze", "four_rooms", "four_rooms_red",
             "four_rooms_orange", "four_rooms_green"]
SOLVERS = [("bfs", None), ("astar", "auto"), ("astar", "manhattan"), ("astar", "pdb"), ("astar", "blind"),
           ("idastar", "pdb"), ("wastar", "auto"), ("gbfs", "pdb")]
QUICK_SOLVERS = [("bfs", None), ("astar", "auto"), ("astar", "manhattan"), ("astar", "pdb")]


def solve_all(jobs: list, time_limit: float, workers: int) -> list[dict]:
    """jobs: (label, dungeon, solver, heuristic) -> one row each, through the batch API."""
    from bcc.batch import Run, solve_runs
    runs = [Run(dungeon, solver, None, (("heuristic", heuristic),) if heuristic else (),
                (("time_limit", time_limit),)) for _, dungeon, solver, heuristic in jobs]
    rows = []
    for (label, *_), data in zip(jobs, solve_runs(runs, workers=workers)):
        data["states_per_second"] = round(data["expanded"] / data["seconds"]) if data["seconds"] else None
        rows.append(row_of(label, data))
    return rows


def row_of(label: dict, data: dict) -> dict:
    keep = ("solved", "status", "budget", "cost", "expanded", "generated", "stored", "seconds", "wall_seconds",
            "states_per_second", "peak_mb", "heuristic", "error")
    return {**label, **{k: data.get(k) for k in keep}}


def print_table(rows: list, title: str) -> None:
    print(f"\n## {title}")
    head = f"{'dungeon':<28} {'solver':<18} {'cost':>6} {'expanded':>10} {'seconds':>9} {'x best':>7} {'states/s':>9} {'MB':>7}"
    print(head)
    print("-" * len(head))
    by_dungeon: dict = {}
    for r in rows:
        by_dungeon.setdefault(r["dungeon"], []).append(r)
    for name, group in by_dungeon.items():
        times = [r["seconds"] for r in group if r.get("solved") and r.get("seconds")]
        best = min(times) if times else None
        for r in group:
            solver = r["solver"] + (f"/{r['heuristic_asked']}" if r.get("heuristic_asked") else "")
            if not r.get("solved"):
                why = r.get("error") or r.get("budget") or r.get("status")
                print(f"{name:<28} {solver:<18} {'-':>6} {r.get('expanded') or 0:>10,} {'-':>9} {'':>7} {'':>9} "
                      f"{r.get('peak_mb') or 0:>7.1f}  ({why})")
                continue
            ratio = f"{r['seconds'] / best:.1f}" if best else "-"
            print(f"{name:<28} {solver:<18} {r['cost']:>6} {r['expanded']:>10,} {r['seconds']:>9.3f} {ratio:>7} "
                  f"{r['states_per_second'] or 0:>9,} {r['peak_mb']:>7.1f}")


def reference(solvers, time_limit, workers) -> list:
    jobs = [({"dungeon": name, "solver": solver, "heuristic_asked": heuristic}, name, solver, heuristic)
            for name in REFERENCE for solver, heuristic in solvers]
    return solve_all(jobs, time_limit, workers)


def generated(sizes, stone_counts, solvers, time_limit, workers, seed=1) -> list:
    """Generated mazes, named by generator spec: each worker regenerates its maze."""
    jobs = []
    for size in sizes:
        for stones in stone_counts:
            spec = f"maze:width={size},depth={size},stones={stones},seed={seed}"
            for solver, heuristic in solvers:
                jobs.append(({"dungeon": f"maze {size}x{size} stones={stones}", "size": size, "stones": stones,
                              "solver": solver, "heuristic_asked": heuristic}, spec, solver, heuristic))
    return solve_all(jobs, time_limit, workers)


def throughput(steps: int = 200_000) -> list:
    """Random actions, RL style (an inapplicable action is a no-op), through the compiled
    model and through the literal spec reading, on the same dungeons and the same seed."""
    from bcc.compiler import compile_dungeon
    sys.path.insert(0, str(HERE.parent / "tests"))
    import spec_reference as ref
    rows = []
    for name in ["bridge", "tough_maze"]:
        model = compile_dungeon(name, prune=False)
        rng = random.Random(0)
        actions = [rng.randrange(len(model.action_names)) for _ in range(steps)]
        apply, s = model.apply, model.initial
        t0 = time.perf_counter()
        for a in actions:
            n = apply(a, s)
            if n is not None:
                s = n
                if model.is_failure(s):
                    s = model.initial
        bcc_rate = steps / (time.perf_counter() - t0)
        walk, s = [], model.initial  # states from a random walk, to time whole successor sets on
        for a in actions[: steps // 8]:
            n = apply(a, s)
            s = n if n is not None and not model.is_failure(n) else s
            walk.append(s)
        t0 = time.perf_counter()
        for s in walk:
            model.successors(s)
        succ_rate = len(walk) / (time.perf_counter() - t0)
        names = model.action_names
        w = w0 = ref.spec_world(name)
        t0 = time.perf_counter()
        for a in actions[: steps // 4]:
            n = ref.apply(w, names[a])
            if n is not None:
                w = n
                if ref.is_failure(w):
                    w = w0
        ref_rate = (steps // 4) / (time.perf_counter() - t0)
        rows.append({"dungeon": name, "bcc_steps_per_second": round(bcc_rate),
                     "reference_steps_per_second": round(ref_rate), "ratio": round(bcc_rate / ref_rate, 1),
                     "bcc_successor_sets_per_second": round(succ_rate)})
    print("\n## simulator throughput (random actions; no-op when inapplicable)")
    for r in rows:
        print(f"{r['dungeon']:<12} bcc {r['bcc_steps_per_second']:>10,} steps/s   literal reference "
              f"{r['reference_steps_per_second']:>9,} steps/s   x{r['ratio']}   successor sets/s "
              f"{r['bcc_successor_sets_per_second']:>8,}")
    return rows


def plot(rows: list, target: Path) -> bool:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("(matplotlib not installed: no plot; pip install '.[bench]')")
        return False
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    series: dict = {}
    for r in rows:
        if r.get("solved") and r.get("stones") == max(x.get("stones", 0) for x in rows):
            key = r["solver"] + (f"/{r['heuristic_asked']}" if r.get("heuristic_asked") else "")
            series.setdefault(key, []).append((r["size"], r["seconds"], r["expanded"]))
    for key, pts in series.items():
        pts.sort()
        axes[0].plot([p[0] for p in pts], [p[1] for p in pts], marker="o", label=key)
        axes[1].plot([p[0] for p in pts], [max(p[2], 1) for p in pts], marker="o", label=key)
    for ax, what in zip(axes, ("seconds", "expanded states")):
        ax.set_xlabel("maze width = depth (cells)")
        ax.set_ylabel(what)
        ax.set_yscale("log")
        ax.grid(True, alpha=0.3)
    axes[0].set_title("time to an optimal (or first) plan")
    axes[1].set_title("states expanded")
    axes[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(target, dpi=100)
    return True


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--time-limit", type=float, default=60)
    ap.add_argument("--workers", type=int, default=1, help="solves at once (default 1: clean timings)")
    ap.add_argument("--out", default=str(HERE / "results.json"))
    args = ap.parse_args()
    solvers = QUICK_SOLVERS if args.quick else SOLVERS
    sizes = [15, 25, 35] if args.quick else [15, 25, 35, 45, 55, 65]
    stones = [0, 10] if args.quick else [0, 5, 10]
    ref_rows = reference(solvers, args.time_limit, args.workers)
    print_table(ref_rows, "reference dungeons")
    gen_rows = generated(sizes, stones, solvers, args.time_limit, args.workers)
    print_table(gen_rows, "generated mazes")
    tp = throughput(50_000 if args.quick else 200_000)
    out = Path(args.out)
    payload = {"when": time.strftime("%Y-%m-%d %H:%M:%S"), "python": sys.version.split()[0],
               "machine": platform.machine(), "quick": args.quick, "time_limit": args.time_limit,
               "workers": args.workers,
               "reference": ref_rows, "generated": gen_rows, "throughput": tp}
    tmp = out.with_suffix(".tmp")
    tmp.write_text(json.dumps(payload, indent=2) + "\n")
    tmp.replace(out)
    png = out.with_suffix(".png")
    if plot(gen_rows, png):
        print(f"wrote {png}")
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
