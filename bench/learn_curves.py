#!/usr/bin/env python3
"""Learning curves of R-max (tabular and object-oriented models) and Q-learning on grid and bridge.

    python bench/learn_curves.py                    # grid 10 episodes, bridge 600; 3 seeds each
    python bench/learn_curves.py --only grid        # one dungeon
    python bench/learn_curves.py --workers 2        # runs at once (same numbers, less wall time)
    python bench/learn_curves.py --time-limit 600   # seconds per run (default 180)

Every (learner, seed) runs through the batch API (`bcc.learning_curves`, the code of
`bcc learn-curve`). Writes bench/learn_curves_<dungeon>.png (mean steps per episode over
the seeds, band min to max, the optimal cost dashed) and bench/learn_curves.json (per
dungeon and learner: steps per episode per seed, converged_episode per seed, seconds),
and prints a table: per learner, the mean steps of the first and last episode, how many
seeds converged to the optimal cost and when, the solver seconds, and how many runs
stopped at the time limit (`--time-limit`, a run's curve then ends early) or failed.
"""
from __future__ import annotations

import argparse
import json
import platform
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
EPISODES = {"grid": 10, "bridge": 600}   # tabular R-max needs about 500 episodes of bridge
TIME_LIMIT = 180.0   # per run


def row(name: str, run: dict) -> str:
    from bcc.learning_curves import mean_curve
    mean = mean_curve(run["steps"])[0]
    converged = [c for c in run["converged_episode"] if c is not None]
    when = f"{min(converged)}..{max(converged)}" if converged else "-"
    seconds = [s for s in run["seconds"] if s is not None]
    first, last = (f"{mean[0]:.1f}", f"{mean[-1]:.1f}") if mean else ("-", "-")
    return (f"{name:<14} {first:>10} {last:>10} {len(converged):>3}/{len(run['steps']):<3} {when:>10} "
            f"{sum(seconds) / max(len(seconds), 1):>9.2f} {run['status'].count('budget'):>7} "
            f"{sum(e is not None for e in run['errors']):>6}")


def show(run, outcome) -> None:
    """One line on stderr per finished run: a long benchmark shows where it is."""
    what = f"{outcome.seconds:.1f} s" if outcome.ok else outcome.error
    print(f"  {run.dungeon} {run.learner} seed {run.seed}: {what}", file=sys.stderr, flush=True)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", choices=sorted(EPISODES), help="only this dungeon")
    ap.add_argument("--seeds", type=int, default=3, help="seeds 0..N-1 per learner (default 3)")
    ap.add_argument("--workers", type=int, default=1, help="runs at once (default 1)")
    ap.add_argument("--episodes", type=int, default=None,
                    help="episodes for every dungeon (default: grid 10, bridge 600)")
    ap.add_argument("--time-limit", type=float, default=TIME_LIMIT,
                    help=f"seconds per run; a run stopped there keeps its episodes (default {TIME_LIMIT:g})")
    args = ap.parse_args()
    from bcc.learning_curves import plot_curves
    from bcc.learning_curves import learning_curves

    out_json = HERE / "learn_curves.json"
    report = json.loads(out_json.read_text()) if out_json.exists() and args.only else {}
    report.setdefault("dungeons", {})
    report.update(machine=platform.platform(), python=platform.python_version())
    for dungeon in [args.only] if args.only else list(EPISODES):
        episodes = args.episodes or EPISODES[dungeon]
        start = time.perf_counter()
        data = learning_curves(dungeon, episodes=episodes, seeds=list(range(args.seeds)), workers=args.workers,
                               time_limit=args.time_limit, progress=show)
        data.update(wall_seconds=round(time.perf_counter() - start, 2), time_limit=args.time_limit)
        png = HERE / f"learn_curves_{dungeon}.png"
        plot_curves(data["runs"], data["optimal_cost"],
                     f"{dungeon}: steps per episode ({args.seeds} seeds)", str(png))
        report["dungeons"][dungeon] = data
        print(f"\n{dungeon}: optimal cost {data['optimal_cost']}, {episodes} episodes, {args.seeds} seeds, "
              f"{args.workers} worker(s), {data['wall_seconds']} s wall -> {png.name}")
        print(f"{'learner':<14} {'ep 1 mean':>10} {'last mean':>10} {'conv':>7} {'at episode':>10} "
              f"{'mean s':>9} {'stopped':>7} {'errors':>6}")
        print("-" * 80)
        for name, run in data["runs"].items():
            print(row(name, run))
    from bcc.atomic import write_text
    write_text(out_json, json.dumps(report, indent=1) + "\n")
    print(f"\nwrote {out_json}")
    failed = any(e for d in report["dungeons"].values() for r in d["runs"].values() for e in r["errors"])
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
