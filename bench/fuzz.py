#!/usr/bin/env python3
"""Fuzz bcc with mutated domain and dungeon files; count outcomes (not a unit test).

    python bench/fuzz.py                       # 10,000 inputs, 2 worker processes
    python bench/fuzz.py --inputs 500 --first 20000 --workers 1
    python bench/fuzz.py --show 1234 --out /tmp/case   # write input 1234's files to look at
    python bench/fuzz.py --pddl --inputs 3000          # mutated PDDL through `bcc import pddl`

Input i is `tests/fuzz_harness.make_case(i)`: a shipped file with 1-3 text, structure or
expression mutations, a mutated domain, or a random `--goal` (see that module); with
--pddl it is `make_pddl_case(i)`, a PDDL test pair with 1-3 mutations of its s-expression
tree, run as `bcc import pddl DOMAIN PROBLEM` with the same options. Each runs
`bcc solve --solver bfs --max-states 3000 --time-limit 3 FILE` in a worker process,
in-process through `bcc.cli.main` (the entry point of the `bcc` command) with
BCC_DEBUG=1 so a bug surfaces with its code site. A worker that does not answer within
--timeout seconds is killed and the input counted as a hang; a worker that dies is
counted as a crash; workers run under an address-space limit (--memory MB).

Outcomes: ok (exit 0), no-plan (exit 1: no plan, or a budget ran out), bad-input (exit 2,
one line `file:line:col: message`, or `file: message` where no position applies),
bad-message (exit 2 but not one such line), internal (an exception: a bug in bcc, grouped
by the innermost bcc frame), exit-N (any other code), hang, crash. Prints a table and
writes JSON (--json, default bench/fuzz.json).
"""
from __future__ import annotations

import argparse
import collections
import json
import multiprocessing as mp
import os
import platform
import resource
import sys
import tempfile
import time
from multiprocessing.connection import wait
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))
import fuzz_harness as fh  # noqa: E402

make_case = fh.make_case  # or fh.make_pddl_case (--pddl); set before the workers fork

FAILURES = ("bad-message", "internal", "hang", "crash", "harness-error")


def worker(conn, memory_mb: int) -> None:
    """Run cases sent as seeds; answer (seed, outcome fields, seconds)."""
    if memory_mb:
        limit = memory_mb * 2**20
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    while True:
        seed = conn.recv()
        if seed is None:
            return
        start = time.perf_counter()
        try:
            case = make_case(seed)
        except Exception as exc:  # noqa: BLE001 - a bug of the mutator, not of bcc: counted apart
            conn.send((seed, "?", {"kind": "harness-error", "detail": repr(exc)[:200], "site": ""}, 0.0))
            continue
        with tempfile.TemporaryDirectory(prefix="bcc-fuzz-") as tmp:
            outcome = fh.run_case(case, Path(tmp))
        conn.send((seed, case.label, outcome.__dict__, time.perf_counter() - start))


class Pool:
    """Worker processes, each given one seed at a time; a late worker is killed and replaced."""

    def __init__(self, n: int, memory_mb: int):
        self.ctx = mp.get_context("fork")
        self.memory_mb = memory_mb
        self.workers = [self.start() for _ in range(n)]

    def start(self):
        parent, child = self.ctx.Pipe()
        proc = self.ctx.Process(target=worker, args=(child, self.memory_mb), daemon=True)
        proc.start()
        child.close()
        return {"proc": proc, "conn": parent, "seed": None, "since": 0.0}

    def replace(self, w) -> None:
        w["proc"].kill()
        w["proc"].join()
        w["conn"].close()
        self.workers[self.workers.index(w)] = self.start()

    def close(self) -> None:
        for w in self.workers:
            try:
                w["conn"].send(None)
            except OSError:
                pass
            w["proc"].join(timeout=5)
            if w["proc"].is_alive():
                w["proc"].kill()


def run(seeds: list[int], workers: int, timeout: float, memory_mb: int, progress: bool) -> list[dict]:
    pool = Pool(workers, memory_mb)
    todo = collections.deque(seeds)
    results: list[dict] = []
    try:
        while todo or any(w["seed"] is not None for w in pool.workers):
            for w in pool.workers:
                if w["seed"] is None and todo:
                    w["seed"], w["since"] = todo.popleft(), time.monotonic()
                    w["conn"].send(w["seed"])
            busy = [w for w in pool.workers if w["seed"] is not None]
            deadline = min(w["since"] for w in busy) + timeout
            ready = wait([w["conn"] for w in busy], timeout=max(deadline - time.monotonic(), 0))
            for w in list(busy):
                if w["conn"] in ready:
                    try:
                        seed, label, outcome, seconds = w["conn"].recv()
                    except (EOFError, OSError):
                        results.append({"seed": w["seed"], "label": make_case(w["seed"]).label, "kind": "crash",
                                        "detail": f"the worker died (exit {w['proc'].exitcode})", "site": "",
                                        "seconds": time.monotonic() - w["since"]})
                        w["seed"] = None
                        pool.replace(w)
                        continue
                    results.append({"seed": seed, "label": label, **outcome, "seconds": seconds})
                    w["seed"] = None
                elif time.monotonic() - w["since"] >= timeout:
                    results.append({"seed": w["seed"], "label": make_case(w["seed"]).label, "kind": "hang",
                                    "detail": f"no answer within {timeout:g} s", "site": "", "seconds": timeout})
                    w["seed"] = None
                    pool.replace(w)
            if progress and len(results) % 500 == 0 and results:
                counts = collections.Counter(r["kind"] for r in results)
                print(f"  {len(results):6d}/{len(seeds)}  " + "  ".join(f"{k} {v}" for k, v in sorted(counts.items())),
                      file=sys.stderr, flush=True)
    finally:
        pool.close()
    return results


def summarize(results: list[dict]) -> dict:
    counts = collections.Counter(r["kind"] for r in results)
    sites: dict = {}
    for r in results:
        if r["kind"] in FAILURES or r["kind"].startswith("exit-"):
            key = r["site"] or f"{r['kind']}: {r['detail'][:80]}"
            entry = sites.setdefault(key, {"kind": r["kind"], "count": 0, "seeds": [], "example": r["detail"]})
            entry["count"] += 1
            if len(entry["seeds"]) < 5:
                entry["seeds"].append(r["seed"])
    families = collections.Counter(r["label"].split(":")[0] for r in results)
    bad = [r for r in results if r["kind"] == "bad-input"]
    seconds = sorted(r["seconds"] for r in results)
    return {
        "inputs": len(results),
        "outcomes": dict(sorted(counts.items())),
        "bad_input_with_line_col": sum(1 for r in bad if r.get("positioned")),
        "bad_input_without_line_col": sorted({r["detail"][:160] for r in bad if not r.get("positioned")})[:20],
        "failure_sites": dict(sorted(sites.items(), key=lambda kv: -kv[1]["count"])),
        "families": dict(sorted(families.items())),
        "seconds_per_input": {"median": seconds[len(seconds) // 2] if seconds else 0,
                              "max": seconds[-1] if seconds else 0},
    }


def print_table(summary: dict) -> None:
    n = summary["inputs"]
    print(f"\n{n:,} inputs")
    print(f"{'outcome':<14}{'count':>8}{'share':>9}")
    for kind in ("ok", "no-plan", "bad-input", "bad-message", "internal", "hang", "crash"):
        c = summary["outcomes"].get(kind, 0)
        print(f"{kind:<14}{c:>8,}{c / max(n, 1):>9.1%}")
    for kind, c in summary["outcomes"].items():
        if kind.startswith("exit-"):
            print(f"{kind:<14}{c:>8,}{c / max(n, 1):>9.1%}")
    print(f"bad-input with file:line:col: {summary['bad_input_with_line_col']:,} of "
          f"{summary['outcomes'].get('bad-input', 0):,}")
    for message in summary["bad_input_without_line_col"][:8]:
        print(f"  without: {message[:120]}")
    if summary["failure_sites"]:
        print("\nfailures by code site:")
        for site, e in summary["failure_sites"].items():
            print(f"  {e['count']:5d}  {site}   seeds {e['seeds']}  ({e['example'][:90]})")
    else:
        print("no failures")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--inputs", type=int, default=10_000, help="number of inputs [10000]")
    ap.add_argument("--first", type=int, default=0, help="seed of the first input [0]")
    ap.add_argument("--workers", type=int, default=2, help="worker processes [2]")
    ap.add_argument("--timeout", type=float, default=30.0, help="seconds before an input counts as a hang [30]")
    ap.add_argument("--memory", type=int, default=3000, help="address-space limit per worker, MB [3000]")
    ap.add_argument("--json", default=str(HERE / "fuzz.json"), help="where to write the JSON [bench/fuzz.json]")
    ap.add_argument("--seeds", help="comma-separated seeds to run instead (e.g. the failures of a run)")
    ap.add_argument("--pddl", action="store_true", help="mutated PDDL pairs through `bcc import pddl`")
    ap.add_argument("--show", type=int, metavar="SEED", help="write input SEED's files to --out and exit")
    ap.add_argument("--out", default=".", help="with --show: a directory")
    args = ap.parse_args()
    global make_case
    if args.pddl:
        make_case = fh.make_pddl_case
    if args.show is not None:
        case = make_case(args.show)
        out = Path(args.out)
        out.mkdir(parents=True, exist_ok=True)
        fh.write_case(case, out)
        print(f"{case.label}: bcc {' '.join(map(repr, fh.case_argv(case, out)))}")
        return 0
    seeds = [int(x) for x in args.seeds.split(",")] if args.seeds else list(range(args.first, args.first + args.inputs))
    start = time.perf_counter()
    results = run(seeds, args.workers, args.timeout, args.memory, progress=True)
    summary = summarize(results)
    summary.update({"seconds": round(time.perf_counter() - start, 1), "first_seed": args.first,
                    "command": fh.COMMAND, "front": "pddl" if args.pddl else "yaml", "timeout_s": args.timeout, "memory_mb": args.memory,
                    "python": platform.python_version(), "machine": platform.machine(), "cpus": os.cpu_count()})
    print_table(summary)
    print(f"\n{summary['seconds']:.0f} s; JSON: {args.json}")
    Path(args.json).write_text(json.dumps(summary, indent=2) + "\n", encoding="utf-8")
    return 1 if any(summary["outcomes"].get(k) for k in FAILURES) else 0


if __name__ == "__main__":
    sys.exit(main())
