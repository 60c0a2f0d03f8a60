#!/usr/bin/env python3
"""Building in the real server: `bcc minecraft run --json` on generated houses and on
MinePlanner's tasks (imported by `bcc import mineplanner`), one whole process each.

    python bench/minecraft_build.py                              # houses 3, 5x5x4; MinePlanner Easy
    python bench/minecraft_build.py --houses 3x3x3 --levels Easy,Medium --only 'Wall|Bridge'

With --only, the rows run replace those of the same name in the output file; the others
are kept.
Needs the Node packages (`bcc minecraft setup`, or $BCC_MINECRAFT_DIR); MinePlanner's tasks
come from --data (the `data` folder of a copy of IretonLiu/mine-pddl, default
$MINEPLANNER_DATA), and are skipped without it. Per row: the status, steps, how many
steps matched the model's prediction, how many carried a known difference of the real
game (differences.py), replans, the mean and max seconds a step (wall clock: the server
runs in real time), the run's and the whole command's seconds, and the CPU seconds of
bcc and the Node server it ran (kernel: user + system, from wait4). A task the bridge
cannot show (an item lying on the ground) is a row with its one-line reason. Prints a
table, writes bench/minecraft_build.json.
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import re
import socket
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from engine import peak_of  # noqa: E402  (bench/engine.py: a child's CPU and peak)
from mineplanner_tasks import TASKS  # noqa: E402

BCC = [sys.executable, "-m", "bcc"]


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def run_row(name: str, dungeon: Path, time_limit: float, max_steps: int) -> dict:
    r = peak_of(BCC + ["minecraft", "run", str(dungeon), "--json", "--port", str(free_port()),
                       "--time-limit", str(time_limit), "--max-steps", str(max_steps)], timeout=1800)
    out, err, code = r["stdout"], r["stderr"], r["code"]
    row = {"name": name, "exit": code, "whole_s": round(r["wall"], 1), "cpu_s": round(r["cpu"], 2)}
    try:
        data = json.loads(out)
    except ValueError:
        row.update(status="refused" if code == 2 else "error", message=(err.strip().splitlines() or [""])[-1][:200])
        return row
    steps = data["steps"]
    row.update(status=data["status"], steps=len(steps), matched=sum(s["matched"] for s in steps),
               known=sum(1 for s in steps if any(n.startswith("known difference") for n in s["notes"])),
               replans=data["replans"], step_mean_s=data["seconds"]["per_action_mean"],
               step_max_s=data["seconds"]["per_action_max"], run_s=data["seconds"]["total"],
               setup_s=data["seconds"]["setup"], message=data["message"])
    return row


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--houses", default="3x3x3,5x5x4", help="W x L x H of each generated house ('' for none)")
    ap.add_argument("--data", default=os.environ.get("MINEPLANNER_DATA", "/work/data/mineplanner/data"))
    ap.add_argument("--levels", default="Easy")
    ap.add_argument("--only", default="", help="a regular expression: only rows whose name matches")
    ap.add_argument("--time-limit", type=float, default=60.0, help="seconds for each (re)plan")
    ap.add_argument("--max-steps", type=int, default=1000, help="actions in the world, at most")
    ap.add_argument("-o", "--output", default=str(HERE / "minecraft_build.json"))
    args = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        jobs = []
        for size in filter(None, args.houses.split(",")):
            w, l, h = size.split("x")
            path = tmp / f"house_{size}.yaml"
            subprocess.run(BCC + ["generate", "house", "--width", w, "--length", l, "--height", h, "-o", str(path)],
                           check=True, capture_output=True)
            jobs.append((f"house_{size}", path))
        data = Path(args.data)
        if data.is_dir():
            for level in args.levels.split(","):
                for task in TASKS:
                    base = data / "pddl" / task / level / "propositional"
                    path = tmp / f"{task}_{level}.yaml"
                    r = subprocess.run(BCC + ["import", "mineplanner", str(base / f"{task}_{level}_domain.pddl"),
                                              str(base / f"{task}_{level}_problem.pddl"), "-o", str(path)],
                                       capture_output=True, text=True)
                    if r.returncode == 0:
                        jobs.append((f"{task}_{level}", path))
                    elif not args.only or re.search(args.only, f"{task}_{level}"):
                        rows.append({"name": f"{task}_{level}", "status": "not imported",
                                     "message": (r.stderr.strip().splitlines() or [""])[-1][:200]})
        else:
            print(f"MinePlanner data not found at {data}: houses only", file=sys.stderr)
        for name, path in jobs:
            if args.only and not re.search(args.only, name):
                continue
            row = run_row(name, path, args.time_limit, args.max_steps)
            rows.append(row)
            print(f"{name:34} {row['status']:9} {row.get('steps', '-'):>4} steps {row.get('matched', '-'):>4} match "
                  f"{row.get('known', '-'):>3} known  {row.get('step_mean_s', '-')} s/step  run {row.get('run_s', '-')} s  "
                  f"whole {row['whole_s']} s  {row.get('message', '')[:60]}", flush=True)
    out = Path(args.output)
    if args.only and out.exists():
        # a partial rerun: keep the other rows of the file, in their order
        ran = {r["name"]: r for r in rows}
        old = json.loads(out.read_text())["rows"]
        rows = [ran.pop(r["name"], r) for r in old] + list(ran.values())
    out.write_text(json.dumps({"machine": platform.platform(), "python": platform.python_version(),
                               "rows": rows}, indent=1) + "\n")
    print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
