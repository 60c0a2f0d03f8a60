#!/usr/bin/env python3
"""Grounding accuracy on people's commands: 10-fold cross-validation over the cleanup-amt corpus.

    python bench/corpus.py                                  # ../shared/corpora/cleanup-amt/commands.jsonl
    python bench/corpus.py --pairs FILE --folds 10 --seeds 0,1,2
    python bench/corpus.py --seeds 0                        # one shuffle
    python bench/corpus.py --quick                          # 3 folds, one shuffle, pooled levels only
    python bench/corpus.py --pooled-only                    # without the per-level models
    python bench/corpus.py --nested                         # votes chosen inside each fold: bench/corpus_nested.json
    python bench/corpus.py --choose                         # the shipped votes: bench/corpus_votes.json

The corpus is read from where it lies (never copied into the repository). For each mode
(`--from tasks`, `--from demonstrations`) a fresh model is trained per fold on the other
folds only (the code of `bcc corpus evaluate`), once on all levels pooled and once per
level (trained and tested on one level, as the published figures were). A level holds
about 650 commands and the shuffle alone moves its figure by up to a point and a half,
so the pooled figures are run on several shuffles (`--seeds`, the folds of `bcc corpus
evaluate --seed N`) and their mean is the figure reported; the per-level models run on
the first shuffle. Prints accuracy per level beside the published figures (Arumugam et
al., RSS 2017) and writes bench/corpus.json with the figures (per shuffle and their
mean), training seconds per model, and the machine.

`--nested` measures what the choice of settings does on new commands instead: each outer
fold's votes are chosen by an inner 3-fold cross-validation of its training pairs
(grounding/nested.py), `--from tasks`, pooled levels; it reports each shuffle, the mean,
the spread and a 95 % Wilson interval per level (grounding/shuffles.py), which
configuration the inner cross-validations chose, and the CPU seconds of the whole run,
in bench/corpus_nested.json.

`--choose` makes the same choice once over the whole file (the 3-fold inner
cross-validation of grounding/nested.py, seed 0) and writes the chosen configuration and
its votes to bench/corpus_votes.json: the shipped votes (ensemble.MEMBERS) are these, so
what `bcc train` ships is what the nested figures measure the choice of.
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

# One BLAS thread, as the `bcc` command runs (cli/core.py): this script imports bcc directly,
# and a thread per core made training 4x slower on a busy machine. Set before numpy loads.
for _blas_threads in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_blas_threads, "1")

HERE = Path(__file__).resolve().parent
DEFAULT = HERE.parent.parent / "shared" / "corpora" / "cleanup-amt" / "commands.jsonl"
PUBLISHED = {"IBM Model 2": {"L0": 21.6, "L1": 10.2, "L2": 31.5},
             "Single-RNN": {"L0": 77.7, "L1": 83.0, "L2": 87.9}}
TARGET = {"L0": 80.0, "L1": 85.0, "L2": 90.0}               # issue 20; issue 32: every nested shuffle above these
NESTED_MEAN_TARGET = {"L0": 86.0, "L1": 87.0, "L2": 92.0, "all": 88.0}   # issue 32: the nested mean
MODEL = ("three log-linear models (words and adjacent pairs; also pairs up to four apart; each task whole, L-BFGS), "
         "a feed-forward network (64 hidden units, eight starts) and the route reader's member for routes and for "
         "steps voting 1 : 1 : 1 : 1.5 : 1 : 1 (ensemble.MEMBERS)")


def _mode(rows, levels, mode, folds, seeds, pooled_only) -> dict:
    """Accuracy in one mode: pooled levels on each shuffle and their mean, then each level
    on its own (first shuffle)."""
    from bcc.grounding import pairs
    t0 = time.perf_counter()
    by_seed = {}
    for seed in seeds:
        pooled = pairs.evaluate(pairs.folds(rows, folds, seed), mode)
        by_seed[str(seed)] = {"pooled": {lv: 100 * v["accuracy"] for lv, v in pooled["by_level"].items()},
                              "overall": 100 * pooled["accuracy"], "train_seconds": pooled["train_seconds"]}
    entry = mean_of_shuffles(by_seed)
    if not pooled_only:
        entry["per_level"] = {}
        for lv in levels:
            mine = [r for r in rows if r["level"] == lv]
            entry["per_level"][lv] = 100 * pairs.evaluate(pairs.folds(mine, folds, seeds[0]), mode)["accuracy"]
    entry["seconds"] = round(time.perf_counter() - t0, 1)
    return entry


def _nested(rows, folds, seeds, workers, save=None, done=None) -> dict:
    """Nested cross-validation (--from tasks, pooled levels) on each shuffle, its folds on
    `workers` processes: each shuffle's figures and choices, and the summary over them.
    `done` (--resume): shuffles a previous run of the same settings finished, kept as they are."""
    from collections import Counter

    from bcc.grounding import pairs
    wall, cpu = time.perf_counter(), _cpu()
    done = {seed: entry for seed, entry in (done or {}).items() if int(seed) in seeds}
    reports = [_saved_report(entry, rows) for entry in done.values()]
    by_seed = dict(done)
    for seed in seeds:
        if str(seed) in by_seed:
            print(f"[nested] seed {seed}: kept from the previous run ({by_seed[str(seed)]['overall']:.1f} %)",
                  file=sys.stderr)
            continue
        t0 = time.perf_counter()
        r = pairs.evaluate(pairs.folds(rows, folds, seed), "tasks", workers=workers, nested_seed=seed)
        reports.append(r)
        by_seed[str(seed)] = {"pooled": {lv: 100 * v["accuracy"] for lv, v in r["by_level"].items()},
                              "overall": 100 * r["accuracy"], "train_seconds": r["train_seconds"],
                              "chosen": dict(Counter(c["config"] for c in r["chosen"])),
                              "inner_accuracy": [c["inner_accuracy"] for c in r["chosen"]],
                              "votes": [c["votes"] for c in r["chosen"]]}
        print(f"[nested] seed {seed}: {100 * r['accuracy']:.1f} % in {time.perf_counter() - t0:.0f} s "
              f"({', '.join(f'{lv} {v:.1f}' for lv, v in by_seed[str(seed)]['pooled'].items())})", file=sys.stderr)
        if save:       # each shuffle as it ends: a run cut short still leaves its finished shuffles
            save(_nested_result(reports, by_seed, wall, cpu))
    return _nested_result(reports, by_seed, wall, cpu)


def _saved_report(entry: dict, rows: list) -> dict:
    """A finished shuffle read back from the output file, in the shape `summarise` reads
    (accuracies and each level's count: the count is the corpus's, the same every shuffle)."""
    totals = {}
    for r in rows:
        totals[r["level"]] = totals.get(r["level"], 0) + 1
    return {"accuracy": entry["overall"] / 100, "pairs": rows,
            "by_level": {lv: {"accuracy": v / 100, "total": totals[lv]} for lv, v in entry["pooled"].items()}}


def _nested_result(reports, by_seed, wall, cpu) -> dict:
    from bcc.grounding.shuffles import summarise
    summary = {lv: {"mean": 100 * v["mean"], "low": 100 * v["low"], "high": 100 * v["high"],
                    "ci95": [100 * x for x in v["ci95"]], "total": v["total"]} for lv, v in summarise(reports).items()}
    return {"by_seed": by_seed, "summary": summary, "seconds": round(time.perf_counter() - wall, 1),
            "cpu_seconds": round(_cpu() - cpu, 1)}


def _cpu() -> float:
    """CPU seconds of this process and its finished children (the folds' workers)."""
    t = os.times()
    return t.user + t.system + t.children_user + t.children_system


def mean_of_shuffles(by_seed: dict) -> dict:
    """The reported entry: per-level and overall accuracy averaged over the shuffles, with
    each shuffle's own figures under `by_seed`."""
    n = len(by_seed)
    levels = sorted({lv for e in by_seed.values() for lv in e["pooled"]})
    return {"pooled": {lv: sum(e["pooled"][lv] for e in by_seed.values()) / n for lv in levels},
            "overall": sum(e["overall"] for e in by_seed.values()) / n,
            "train_seconds": round(sum(e["train_seconds"] for e in by_seed.values()) / n, 3),
            "by_seed": by_seed}


def _seeds(text: str) -> list[int]:
    try:
        seeds = [int(x) for x in text.split(",") if x.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected seeds separated by commas, got {text!r}") from None
    if not seeds or len(set(seeds)) != len(seeds):
        raise argparse.ArgumentTypeError(f"expected distinct seeds separated by commas, got {text!r}")
    return seeds


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pairs", default=str(DEFAULT), help="JSON Lines with command, task, level")
    ap.add_argument("--dungeon", default="cleanup")
    ap.add_argument("--folds", type=int, default=10)
    ap.add_argument("--seeds", type=_seeds, default=[0, 1, 2],
                    help="shuffles, separated by commas (default 0,1,2): the reported figure is their mean")
    ap.add_argument("--quick", action="store_true", help="3 folds, the first shuffle, pooled levels only")
    ap.add_argument("--pooled-only", action="store_true",
                    help="only the models trained on all levels (the targets); skip the per-level ones")
    ap.add_argument("--workers", type=int, default=2, help="processes (one per mode; with --nested, per fold)")
    ap.add_argument("--nested", action="store_true",
                    help="nested cross-validation (votes chosen inside each fold), --from tasks: bench/corpus_nested.json")
    ap.add_argument("-o", "--output", default=None, help="[default: bench/corpus.json, or corpus_nested.json]")
    ap.add_argument("--resume", action="store_true",
                    help="with --nested: keep the shuffles the output file already holds (same pairs, folds and "
                         "configurations) and run only the others")
    ap.add_argument("--choose", action="store_true",
                    help="choose the votes by the inner cross-validation over the whole file: bench/corpus_votes.json")
    args = ap.parse_args(argv)
    from bcc.grounding import pairs
    folds = 3 if args.quick else args.folds
    seeds = args.seeds[:1] if args.quick else args.seeds
    rows = pairs.load(args.pairs, args.dungeon)
    pairs.check_tasks(rows)
    levels = sorted({r["level"] for r in rows})
    if args.nested:
        return _report_nested(args, rows, levels, folds, seeds)
    if args.choose:
        return _choose(args, rows)
    # the two modes are independent: one process each (the machine's other core)
    with ProcessPoolExecutor(max_workers=min(args.workers, len(pairs.MODES))) as pool:
        jobs = {mode: pool.submit(_mode, rows, levels, mode, folds, seeds,
                                   args.quick or args.pooled_only) for mode in pairs.MODES}
        results = {mode: job.result() for mode, job in jobs.items()}
    for mode, entry in results.items():
        print(f"[{mode}] done in {entry['seconds']} s", file=sys.stderr)
    train_cpu, command_ms = _limits(rows)
    print(f"training on all {len(rows)} pairs: {train_cpu:.1f} s CPU; one command: {command_ms:.2f} ms CPU",
          file=sys.stderr)
    head = f"{'model':<50}" + "".join(f"{lv:>8}" for lv in levels) + f"{'all':>8}"
    shuffles = f"mean of {len(seeds)} shuffles (seeds {', '.join(map(str, seeds))})" if len(seeds) > 1 \
        else f"seed {seeds[0]}"
    print(f"{len(rows)} pairs, {folds}-fold cross-validation, {shuffles}, accuracy %")
    print(head)
    for name, figs in PUBLISHED.items():
        print(f"{name + ' (published, per level)':<50}" + "".join(f"{figs.get(lv, float('nan')):8.1f}" for lv in levels))
    print(f"{'target':<50}" + "".join(f"{TARGET.get(lv, float('nan')):8.1f}" for lv in levels))
    for mode, e in results.items():
        if len(seeds) > 1:
            for seed, one in e["by_seed"].items():
                print(f"{'bcc --from ' + mode + ' (pooled, seed ' + seed + ')':<50}"
                      + "".join(f"{one['pooled'][lv]:8.1f}" for lv in levels) + f"{one['overall']:8.1f}")
        print(f"{'bcc --from ' + mode + ' (pooled levels' + (', mean)' if len(seeds) > 1 else ')'):<50}"
              + "".join(f"{e['pooled'][lv]:8.1f}" for lv in levels) + f"{e['overall']:8.1f}")
        if "per_level" in e:
            print(f"{'bcc --from ' + mode + f' (per level, seed {seeds[0]})':<50}" + "".join(f"{e['per_level'][lv]:8.1f}" for lv in levels))
    out = {"pairs": args.pairs, "count": len(rows), "model": MODEL, "folds": folds, "seeds": seeds, "published": PUBLISHED,
           "target": TARGET, "results": results,
           "train_all_cpu_seconds": round(train_cpu, 2), "command_cpu_ms": round(command_ms, 3),
           "python": sys.version.split()[0], "machine": platform.machine()}
    from bcc.atomic import write_text
    write_text(args.output or str(HERE / "corpus.json"), json.dumps(out, indent=2) + "\n")
    return 0


def _choose(args, rows) -> int:
    """The configuration an inner cross-validation over all `rows` chooses, and its votes."""
    from bcc.grounding import nested, pairs
    t0 = time.process_time()
    examples = pairs.examples(rows, "tasks")
    inner = pairs.folds(list(range(len(rows))), nested.INNER, 0)
    name, accuracy, votes = nested.choose(examples, lambda k: rows[k]["task"], inner, pairs.scenes(rows))
    cpu = time.process_time() - t0
    print(f"{'configuration':<22}{'inner accuracy %':>18}")
    for n, a in sorted(accuracy.items(), key=lambda x: -x[1]):
        print(f"{n:<22}{100 * a:18.2f}" + ("   <- chosen" if n == name else ""))
    print(f"votes ({', '.join(m for m, _, _ in nested.POOL)}): {', '.join(f'{v:g}' for v in votes)}")
    out = {"pairs": args.pairs, "count": len(rows), "inner_folds": nested.INNER, "seed": 0,
           "pool": [m for m, _, _ in nested.POOL], "chosen": name, "votes": [float(v) for v in votes],
           "inner_accuracy": accuracy, "cpu_seconds": round(cpu, 1),
           "python": sys.version.split()[0], "machine": platform.machine()}
    from bcc.atomic import write_text
    write_text(args.output or str(HERE / "corpus_votes.json"), json.dumps(out, indent=2) + "\n")
    return 0


def _limits(rows) -> tuple[float, float]:
    """The issue's limits: CPU seconds to train on the whole file (one core), and CPU
    milliseconds to interpret one command."""
    from bcc.grounding import pairs
    t0 = time.process_time()
    model = pairs.train(rows, "tasks")
    train_cpu = time.process_time() - t0
    sample = rows[:200]
    t0 = time.process_time()
    pairs.predict(model, sample)
    return train_cpu, 1000 * (time.process_time() - t0) / len(sample)


def _resumable(args, output: str, rows, folds) -> dict:
    """The finished shuffles of `output`, if it was written with the same pairs, folds and
    configurations (else none: a changed setting runs every shuffle again)."""
    from bcc.grounding import nested
    try:
        old = json.loads(Path(output).read_text())
    except (OSError, ValueError):
        return {}
    same = (old.get("count") == len(rows) and old.get("folds") == folds and old.get("inner_folds") == nested.INNER
            and old.get("configs") == {name: None if w is None else list(w) for name, w in nested.CONFIGS}
            and old.get("pool") == [name for name, _, _ in nested.POOL])
    if not same:
        print(f"[nested] {output} was written with other settings: every shuffle runs", file=sys.stderr)
        return {}
    return old.get("nested", {}).get("by_seed", {})


def _report_nested(args, rows, levels, folds, seeds) -> int:
    from bcc.atomic import write_text
    from bcc.grounding import nested
    output = args.output or str(HERE / "corpus_nested.json")

    def save(result, limits=None):
        out = {"pairs": args.pairs, "count": len(rows), "model": MODEL, "folds": folds, "inner_folds": nested.INNER,
               "configs": {name: None if w is None else list(w) for name, w in nested.CONFIGS}, "pool": [name for name, _, _ in nested.POOL],
               "seeds": seeds, "finished_seeds": len(result["by_seed"]), "target": TARGET,
               "target_mean": NESTED_MEAN_TARGET, "nested": result,
               "python": sys.version.split()[0], "machine": platform.machine()}
        if limits:
            out |= {"train_all_cpu_seconds": round(limits[0], 2), "command_cpu_ms": round(limits[1], 3)}
        write_text(output, json.dumps(out, indent=2) + "\n")
    result = _nested(rows, folds, seeds, args.workers, save, _resumable(args, output, rows, folds) if args.resume else None)
    train_cpu, command_ms = _limits(rows)
    print(f"{len(rows)} pairs, nested {folds}-fold cross-validation (inner {nested.INNER}-fold, "
          f"{len(nested.CONFIGS)} configurations), --from tasks, accuracy %; {result['cpu_seconds']:.0f} s CPU, "
          f"{result['seconds']:.0f} s wall")
    print(f"{'':<26}" + "".join(f"{lv:>8}" for lv in levels) + f"{'all':>8}")
    print(f"{'target, each shuffle':<26}" + "".join(f"{TARGET.get(lv, float('nan')):8.1f}" for lv in levels))
    print(f"{'target, mean':<26}" + "".join(f"{NESTED_MEAN_TARGET.get(lv, float('nan')):8.1f}" for lv in levels + ["all"]))
    for seed, one in result["by_seed"].items():
        print(f"{'seed ' + seed:<26}" + "".join(f"{one['pooled'][lv]:8.1f}" for lv in levels) + f"{one['overall']:8.1f}"
              + "  chose " + ", ".join(f"{k} {v}" for k, v in sorted(one["chosen"].items(), key=lambda x: -x[1])))
    summary = result["summary"]
    print(f"{'mean':<26}" + "".join(f"{summary[lv]['mean']:8.1f}" for lv in levels + ["all"]))
    print(f"{'lowest shuffle':<26}" + "".join(f"{summary[lv]['low']:8.1f}" for lv in levels + ["all"]))
    print(f"{'95% interval (Wilson)':<26}" + "".join(f"{summary[lv]['ci95'][0]:5.1f}-{summary[lv]['ci95'][1]:<4.1f}"
                                                  for lv in levels + ["all"]))
    print(f"training on all {len(rows)} pairs: {train_cpu:.1f} s CPU; one command: {command_ms:.2f} ms CPU")
    save(result, (train_cpu, command_ms))
    return 0


if __name__ == "__main__":
    sys.exit(main())
