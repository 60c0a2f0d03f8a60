#!/usr/bin/env python3
"""How `bcc batch` scales: one sweep of generated mazes with 1 worker, then 2, in one run.

    python bench/batch_scaling.py                  # 200 mazes 21x21 with 2 stones, A*
    python bench/batch_scaling.py --count 40       # a quicker look
    python bench/batch_scaling.py --ray            # also the ray backend (local Ray, 2 CPUs)

The local configurations take turns on slices of the runs (`--rounds`), so a change in
the machine's other load during the measurement falls on each of them alike; Ray runs
afterwards (its daemons would otherwise take CPU from the local measurement).

Prints a table (wall time, runs/s, speed-up against 1 worker, mean seconds per run,
how busy the workers were, their CPU time) and writes bench/batch_scaling.json. Every configuration must give the same solved/cost/expanded
per run; the script fails otherwise. The speed-up is only meaningful on a quiet machine:
the JSON records the load average before and after, to judge that.
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent

COMPARED = ("solved", "status", "cost", "expanded", "error")


def children_cpu() -> float:
    import resource
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def sweep(runs, backend: str, workers: int, out: Path) -> tuple[float, float]:
    """Wall seconds and CPU seconds of the worker processes (local only: Ray's are not
    our children) of one run_batch call appending to `out`."""
    from bcc.batch import run_batch
    cpu = children_cpu()
    start = time.perf_counter()
    run_batch(runs, out=str(out), backend=backend, workers=workers)
    return time.perf_counter() - start, children_cpu() - cpu


def measure(runs, configs, rounds: int, tmp: Path) -> dict:
    """Interleaved: the runs are cut into `rounds` slices, and every slice is run by each
    configuration in turn (order reversed every other round), so a change in the machine's
    other load falls on all configurations alike. Ray is started once, outside the timing."""
    totals = {c: [0.0, 0.0] for c in configs}
    slices = [runs[i::rounds] for i in range(rounds)]
    ray = None
    if any(backend == "ray" for backend, _ in configs):
        import ray
        ray.init(num_cpus=max(w for b, w in configs if b == "ray"), include_dashboard=False, log_to_driver=False)
    try:
        for k, part in enumerate(slices):
            for backend, workers in (configs if k % 2 == 0 else configs[::-1]):
                wall, cpu = sweep(part, backend, workers, tmp / f"{backend}-{workers}.jsonl")
                totals[backend, workers][0] += wall
                totals[backend, workers][1] += cpu
    finally:
        if ray is not None:
            ray.shutdown()
    return totals


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--count", type=int, default=200, help="generated mazes (seeds 1..COUNT)")
    ap.add_argument("--width", type=int, default=21)
    ap.add_argument("--stones", type=int, default=2)
    ap.add_argument("--solver", default="astar")
    ap.add_argument("--ray", action="store_true", help="also run the ray backend (local Ray, 2 CPUs)")
    ap.add_argument("--rounds", type=int, default=4, help="interleaved slices of the runs (see measure)")
    ap.add_argument("--out", default=str(HERE / "batch_scaling.json"))
    args = ap.parse_args()
    from bcc.batch import build_runs, expand_dungeons, read_rows
    spec = f"maze:width={args.width},depth={args.width},stones={args.stones},seed=1..{args.count}"
    runs = build_runs(expand_dungeons([spec]), [(args.solver, {}, {})], [0])
    configs = [("local", 1), ("local", 2)] + ([("ray", 2)] if args.ray else [])
    load_before = os.getloadavg()
    results = []
    with tempfile.TemporaryDirectory() as tmp:
        totals = measure(runs, configs[:2], args.rounds, Path(tmp))   # the local pool, Ray not running
        if args.ray:
            totals.update(measure(runs, configs[2:], 1, Path(tmp)))
        reference = None
        for backend, workers in configs:
            wall, cpu = totals[backend, workers]
            rows = {r["key"]: r for r in read_rows(str(Path(tmp) / f"{backend}-{workers}.jsonl")).rows}
            if len(rows) != len(runs):
                raise SystemExit(f"{backend} x{workers}: {len(rows)} rows for {len(runs)} runs")
            same = {k: {f: r[f] for f in COMPARED} for k, r in rows.items()}
            if reference is None:
                reference = same
            elif same != reference:
                bad = [k for k in reference if reference[k] != same.get(k)]
                raise SystemExit(f"{backend} x{workers}: rows differ from local x1 for {len(bad)} runs, e.g. {bad[0]}")
            run_seconds = sum(r["wall_seconds"] for r in rows.values())
            results.append({"backend": backend, "workers": workers, "wall_seconds": round(wall, 3),
                            "runs_per_second": round(len(runs) / wall, 3),
                            "mean_run_seconds": round(run_seconds / len(runs), 4),
                            # the workers' share of the time spent inside runs: below 100% is the
                            # pool's own overhead (forks, result passing, writing rows)
                            "busy": round(run_seconds / (workers * wall), 3),
                            "worker_cpu_seconds": round(cpu, 2) if backend == "local" else None,
                            "solved": sum(r["solved"] for r in rows.values())})
    base = results[0]["wall_seconds"]
    for r in results:
        r["speedup"] = round(base / r["wall_seconds"], 3)
    print(f"\n## bcc batch: {len(runs)} runs ({spec}, {args.solver}) on {os.cpu_count()} CPUs")
    head = (f"{'backend':<8} {'workers':>7} {'wall s':>8} {'runs/s':>7} {'speed-up':>8} {'s/run':>7} "
            f"{'busy':>6} {'cpu s':>7} {'solved':>7}")
    print(head)
    print("-" * len(head))
    for r in results:
        cpu = f"{r['worker_cpu_seconds']:>7.1f}" if r["worker_cpu_seconds"] is not None else f"{'-':>7}"
        print(f"{r['backend']:<8} {r['workers']:>7} {r['wall_seconds']:>8.2f} {r['runs_per_second']:>7.2f} "
              f"{r['speedup']:>7.2f}x {r['mean_run_seconds']:>7.3f} {r['busy']:>6.0%} {cpu} {r['solved']:>7}")
    print("s/run: mean wall time of one run inside its worker; busy: share of workers x wall spent in runs;\n"
          "cpu s: CPU time of the worker processes. s/run growing with workers while cpu s stays is a\n"
          "machine short of free cores (other load), not pool overhead.")
    print("rows identical across configurations (solved, status, cost, expanded, error)")
    payload = {"when": time.strftime("%Y-%m-%d %H:%M:%S"), "python": sys.version.split()[0],
               "machine": platform.machine(), "cpus": os.cpu_count(), "spec": spec, "solver": args.solver,
               "runs": len(runs), "rounds": args.rounds, "load_average_before": [round(x, 2) for x in load_before],
               "load_average_after": [round(x, 2) for x in os.getloadavg()], "results": results}
    out = Path(args.out)
    tmp_out = out.with_suffix(".tmp")
    tmp_out.write_text(json.dumps(payload, indent=2) + "\n")
    tmp_out.replace(out)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
