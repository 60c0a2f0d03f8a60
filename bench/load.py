#!/usr/bin/env python3
"""Load test of `bcc serve` (not a unit test): N clients submit solves for a bounded time.

    python bench/load.py                          # 8 clients, 20 s, a server it starts itself
    python bench/load.py --clients 16 --seconds 60 --workers 2
    python bench/load.py --url http://127.0.0.1:8765   # an already running server

Each client loops: POST /solve (a dungeon from --dungeons, in turn), poll GET /jobs/{id}
until the job has finished, repeat; it stops submitting after --seconds and waits for its
last job. Reported: throughput (finished jobs per second), p50/p95/max latency (submit to
finished, queueing included), statuses, and *lost*: accepted jobs that never reached
done/failed/cancelled or vanished. Some submissions can carry a tiny memory limit
(--fail-every: a 65 x 65 maze with a 5 MB limit) so the failing path is loaded too. Prints a table, writes bench/results/load-*.json.
"""
from __future__ import annotations

import argparse
import json
import platform
import sys
import threading
import time
import urllib.error
import urllib.request
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))
from bcc.generate import generate_maze  # noqa: E402

BIG_MAZE = generate_maze(65, 65, stones=10, seed=1)


def call(base: str, method: str, path: str, body=None, timeout: float = 30):
    data = json.dumps(body).encode() if body is not None else None
    req = urllib.request.Request(base + path, data=data, method=method,
                                 headers={"content-type": "application/json"} if data else {})
    try:
        with urllib.request.urlopen(req, timeout=timeout) as resp:
            return resp.status, json.loads(resp.read())
    except urllib.error.HTTPError as exc:
        return exc.code, json.loads(exc.read() or b"null")


def client(base: str, number: int, dungeons: list[str], stop_at: float, drain: float, fail_every: int,
           records: list, lock: threading.Lock) -> None:
    k = number
    while time.monotonic() < stop_at:
        dungeon = dungeons[k % len(dungeons)]
        body = {"dungeon": dungeon, "solver": "astar", "time_limit": 10}
        if fail_every and k % fail_every == 0:
            # A 65 x 65 maze needs ~85 MB of search: over a 5 MB limit it must come back
            # "failed" within a second, never vanish or take the server down.
            dungeon = "maze65 (max_memory_mb 5)"
            body = {"dungeon": BIG_MAZE, "solver": "astar", "time_limit": 10, "max_memory_mb": 5}
        k += len(dungeons) + 1
        t0 = time.monotonic()
        try:
            status, created = call(base, "POST", "/solve", body)
        except OSError as exc:
            with lock:
                records.append({"accepted": False, "error": str(exc)})
            continue
        if status != 202:
            with lock:
                records.append({"accepted": False, "http": status, "error": created})
            continue
        record = {"accepted": True, "id": created["id"], "dungeon": dungeon, "status": None}
        with lock:
            records.append(record)
        deadline = stop_at + drain
        while time.monotonic() < deadline:
            try:
                code, job = call(base, "GET", f"/jobs/{created['id']}")
            except OSError:
                time.sleep(0.05)
                continue
            if code != 200:
                record["status"] = f"http {code}"
                break
            if job["status"] in ("done", "failed", "cancelled"):
                record["status"] = job["status"]
                record["latency"] = time.monotonic() - t0
                record["solved"] = bool(job["result"] and job["result"]["solved"])
                break
            time.sleep(0.05)


def percentile(values: list[float], q: float) -> float | None:
    if not values:
        return None
    values = sorted(values)
    return values[min(len(values) - 1, int(round(q * (len(values) - 1))))]


def run(base: str, args) -> dict:
    records, lock = [], threading.Lock()
    start = time.monotonic()
    stop_at = start + args.seconds
    threads = [threading.Thread(target=client, args=(base, i, args.dungeons, stop_at, args.drain, args.fail_every,
                                                     records, lock)) for i in range(args.clients)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    elapsed = time.monotonic() - start
    accepted = [r for r in records if r["accepted"]]
    finished = [r for r in accepted if r["status"] in ("done", "failed", "cancelled")]
    latencies = [r["latency"] for r in finished]
    by_status = {s: sum(1 for r in accepted if r["status"] == s) for s in ("done", "failed", "cancelled")}
    return {
        "clients": args.clients, "seconds": args.seconds, "elapsed": round(elapsed, 2),
        "dungeons": args.dungeons, "workers": args.workers, "fail_every": args.fail_every,
        "submitted": len(records), "accepted": len(accepted), "rejected": len(records) - len(accepted),
        **by_status, "solved": sum(1 for r in finished if r.get("solved")),
        "lost": len(accepted) - len(finished),
        "throughput_per_s": round(len(finished) / elapsed, 2),
        "latency_p50_s": round(percentile(latencies, 0.5) or 0, 3),
        "latency_p95_s": round(percentile(latencies, 0.95) or 0, 3),
        "latency_max_s": round(max(latencies, default=0), 3),
        "lost_jobs": [r for r in accepted if r not in finished][:20],
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--url", help="An already running server (default: start one on a free port).")
    parser.add_argument("--clients", type=int, default=8)
    parser.add_argument("--seconds", type=float, default=20)
    parser.add_argument("--workers", type=int, default=2, help="--workers of the server this script starts.")
    parser.add_argument("--dungeons", nargs="+", default=["bridge", "grid", "easy_maze", "four_rooms_red"])
    parser.add_argument("--fail-every", type=int, default=10, help="Every K-th submission is a solve over its memory limit (0: none).")
    parser.add_argument("--drain", type=float, default=120, help="Seconds to wait for outstanding jobs after the end.")
    parser.add_argument("-o", "--output", help="JSON file [default: bench/results/load-TIMESTAMP.json].")
    args = parser.parse_args()
    if args.url:
        report = run(args.url.rstrip("/"), args)
    else:
        from serve_harness import running_server
        with running_server("--workers", str(args.workers)) as api:
            report = run(api.base, args)
            report["server_alive_after"] = api.get("/health")[0] == 200
    report["machine"] = {"python": platform.python_version(), "cpus": __import__("os").cpu_count()}
    rows = [("clients", report["clients"]), ("duration (s)", report["elapsed"]), ("server workers", report["workers"]),
            ("submitted", report["submitted"]), ("accepted", report["accepted"]), ("rejected", report["rejected"]),
            ("done", report["done"]), ("  of which solved", report["solved"]), ("failed", report["failed"]),
            ("cancelled", report["cancelled"]), ("lost", report["lost"]),
            ("throughput (jobs/s)", report["throughput_per_s"]), ("latency p50 (s)", report["latency_p50_s"]),
            ("latency p95 (s)", report["latency_p95_s"]), ("latency max (s)", report["latency_max_s"])]
    if "server_alive_after" in report:
        rows.append(("server alive after", report["server_alive_after"]))
    width = max(len(k) for k, _ in rows)
    for k, v in rows:
        print(f"{k:<{width}}  {v}")
    out = Path(args.output) if args.output else HERE / "results" / f"load-{time.strftime('%Y%m%d-%H%M%S')}.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    from bcc.atomic import write_text
    write_text(out, json.dumps(report, indent=2) + "\n")
    print(f"wrote {out}")
    return 0 if report["lost"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
