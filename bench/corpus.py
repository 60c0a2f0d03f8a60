#!/usr/bin/env python3
"""Grounding accuracy on people's commands: 10-fold cross-validation over the cleanup-amt corpus.

    python bench/corpus.py                                  # ../shared/corpora/cleanup-amt/commands.jsonl
    python bench/corpus.py --pairs FILE --folds 10 --seed 0
    python bench/corpus.py --quick                          # 3 folds, pooled levels only

The corpus is read from where it lies (never copied into the repository). For each mode
(`--from tasks`, `--from demonstrations`) a fresh model is trained per fold on the other
folds only (the code of `bcc corpus evaluate`), once on all levels pooled and once per
level (trained and tested on one level, as the published figures were). Prints accuracy
per level beside the published figures (Arumugam et al., RSS 2017) and writes
bench/corpus.json with the figures, training seconds per model, and the machine.
"""
from __future__ import annotations

import argparse
import json
import platform
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
DEFAULT = HERE.parent.parent / "shared" / "corpora" / "cleanup-amt" / "commands.jsonl"
PUBLISHED = {"IBM Model 2": {"L0": 21.6, "L1": 10.2, "L2": 31.5},
             "Single-RNN": {"L0": 77.7, "L1": 83.0, "L2": 87.9}}
TARGET = {"L0": 80.0, "L1": 85.0, "L2": 90.0}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pairs", default=str(DEFAULT), help="JSON Lines with command, task, level")
    ap.add_argument("--dungeon", default="cleanup")
    ap.add_argument("--folds", type=int, default=10)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--quick", action="store_true", help="3 folds, pooled levels only")
    ap.add_argument("-o", "--output", default=str(HERE / "corpus.json"))
    args = ap.parse_args(argv)
    from bcc.grounding import pairs
    folds = 3 if args.quick else args.folds
    rows = pairs.load(args.pairs, args.dungeon)
    pairs.check_tasks(rows)
    levels = sorted({r["level"] for r in rows})
    results = {}
    for mode in pairs.MODES:
        t0 = time.perf_counter()
        pooled = pairs.evaluate(pairs.folds(rows, folds, args.seed), mode)
        entry = {"pooled": {lv: 100 * v["accuracy"] for lv, v in pooled["by_level"].items()},
                 "overall": 100 * pooled["accuracy"], "train_seconds": pooled["train_seconds"]}
        if not args.quick:
            entry["per_level"] = {}
            for lv in levels:
                mine = [r for r in rows if r["level"] == lv]
                entry["per_level"][lv] = 100 * pairs.evaluate(pairs.folds(mine, folds, args.seed), mode)["accuracy"]
        entry["seconds"] = round(time.perf_counter() - t0, 1)
        results[mode] = entry
        print(f"[{mode}] done in {entry['seconds']} s", file=sys.stderr)
    head = f"{'model':<40}" + "".join(f"{lv:>8}" for lv in levels) + f"{'all':>8}"
    print(f"{len(rows)} pairs, {folds}-fold cross-validation (seed {args.seed}), accuracy %")
    print(head)
    for name, figs in PUBLISHED.items():
        print(f"{name + ' (published, per level)':<40}" + "".join(f"{figs.get(lv, float('nan')):8.1f}" for lv in levels))
    print(f"{'target':<40}" + "".join(f"{TARGET.get(lv, float('nan')):8.1f}" for lv in levels))
    for mode, e in results.items():
        print(f"{'bcc --from ' + mode + ' (pooled levels)':<40}" + "".join(f"{e['pooled'][lv]:8.1f}" for lv in levels)
              + f"{e['overall']:8.1f}")
        if "per_level" in e:
            print(f"{'bcc --from ' + mode + ' (per level)':<40}" + "".join(f"{e['per_level'][lv]:8.1f}" for lv in levels))
    out = {"pairs": args.pairs, "count": len(rows), "folds": folds, "seed": args.seed, "published": PUBLISHED,
           "target": TARGET, "results": results, "python": sys.version.split()[0], "machine": platform.machine()}
    from bcc.atomic import write_text
    write_text(args.output, json.dumps(out, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
