#!/usr/bin/env python3
"""MinePlanner natively: `bcc import mineplanner` + `bcc solve` on the 45 tasks.

    python bench/mineplanner_native.py                       # data from $MINEPLANNER_DATA
    python bench/mineplanner_native.py --data DIR --levels Easy --time-limit 60
    python bench/mineplanner_native.py --variants original,mirror,rotate --only 'Bridge|Wall'

The tasks are not in this repository: DIR is the `data` folder of a copy of
IretonLiu/mine-pddl (DIR/pddl/TASK/LEVEL/propositional/*.pddl, DIR/human-solutions/...).
Without it the bench says so and exits 0.

Per task, whole processes, each timed by the kernel (CPU seconds user + system, and the
child's peak resident memory from wait4): `bcc import mineplanner` (the dungeon), then
`bcc solve` (its default solver, A* auto, or --solver) under --time-limit. A plan is
mapped back to the task's PDDL actions by `bcc import mineplanner --plan` and checked on
the task's own PDDL files by bcc.pddl_io.replay, a lifted PDDL validator that knows
nothing of the builder domain (run in a child too). Beside it: the human solution's
length (`checkgoal` not counted) and whether the human solution is a plan of the PDDL
task (replayed the same way). Variants: `mirror` (x -> -x) and `rotate` (90 degrees:
x -> z, z -> -x) rewrite the problem's and checkgoal's positions, so the same world is
met in other directions. Prints a table, writes bench/mineplanner_native.json.
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import re
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from engine import peak_of  # noqa: E402  (bench/engine.py: a child's CPU and peak)
from mineplanner_tasks import LEVELS, TASKS  # noqa: E402

HUMAN_KINDS = {"move": "move", "move_and_pickup": "move", "jumpup": "jump", "jumpdown": "drop",
               "break": "break", "place": "place"}


def files(data: Path, task: str, level: str) -> tuple[Path, Path]:
    base = data / "pddl" / task / level / "propositional"
    return base / f"{task}_{level}_domain.pddl", base / f"{task}_{level}_problem.pddl"


def human_plan(data: Path, task: str, level: str) -> list:
    steps = json.loads((data / "human-solutions" / task / f"{task}_{level}.json").read_text())
    out = []
    for a in steps:
        if a["action"] == "checkgoal":
            continue
        name = f"{HUMAN_KINDS[a['action']]}_{a['direction']}"
        out.append(f"{name}(agent, {a['block']})" if a["action"] == "place" else name)
    return out


def variant(domain: Path, problem: Path, kind: str, out: Path) -> tuple[Path, Path]:
    """The task mirrored (x -> -x) or rotated (x -> z, z -> -x): every `(at-x O P)` and
    `(at-z O P)` of the problem and of checkgoal rewritten over the position chain."""
    if kind == "original":
        return domain, problem
    from bcc.mineplanner.task import read_task
    positions = read_task(str(domain), str(problem)).positions
    index = {p: i for i, p in enumerate(positions)}
    flip = lambda p: positions[len(positions) - 1 - index[p]]

    def rewrite(m):
        axis, obj, pos = m[1], m[2], m[3]
        if pos not in index:
            return m[0]
        if kind == "mirror":
            return f"(at-x {obj} {flip(pos)})" if axis == "x" else m[0]
        return f"(at-z {obj} {pos})" if axis == "x" else f"(at-x {obj} {flip(pos)})"

    pattern = re.compile(r"\(at-([xz])\s+(\S+)\s+([^\s()]+)\)", re.I)
    out.mkdir(parents=True, exist_ok=True)
    d, p = out / domain.name, out / problem.name
    d.write_text(pattern.sub(rewrite, domain.read_text()))
    p.write_text(pattern.sub(rewrite, problem.read_text()))
    return d, p


def bcc(*args) -> list:
    return [sys.executable, "-m", "bcc", *map(str, args)]


def validate_child(domain: Path, problem: Path, plan: Path, human: bool = False) -> dict:
    cmd = [sys.executable, str(Path(__file__).resolve()), "--validate", str(domain), str(problem), str(plan)]
    if human:
        cmd.append("--human")
    r = peak_of(cmd, timeout=600)
    try:
        return json.loads(r["stdout"])
    except ValueError:
        return {"valid": False, "reason": (r["stderr"].strip().splitlines() or ["no output"])[-1], "steps": None}


def run_one(data: Path, task: str, level: str, kind: str, args, tmp: Path) -> dict:
    domain, problem = files(data, task, level)
    row = {"task": task, "level": level, "variant": kind}
    domain, problem = variant(domain, problem, kind, tmp / f"{task}_{level}_{kind}")
    dungeon, plan, pddl = (tmp / f"{task}_{level}_{kind}.{ext}" for ext in ("yaml", "plan", "pddlplan"))
    imp = peak_of(bcc("import", "mineplanner", domain, problem, "-o", dungeon, "--json"), timeout=600)
    row.update(import_cpu_s=imp["cpu"], import_peak_mb=imp["peak_mb"])
    if imp["code"] != 0:
        return {**row, "solved": False, "status": "import failed", "message": imp["stderr"].strip()[-300:]}
    summary = json.loads(imp["stdout"])
    row.update(size=summary["size"], blocks=summary["blocks"], items=summary["items"])
    cmd = bcc("solve", dungeon, "--json", "-o", plan, "--time-limit", args.time_limit, "--max-memory", args.max_memory)
    if args.solver:
        cmd += ["--solver", args.solver]
    solve = peak_of(cmd, timeout=args.time_limit * 3 + 60)
    try:
        result = json.loads(solve["stdout"])
    except ValueError:
        result = {"solved": False, "status": f"exit {solve['code']}", "message": solve["stderr"].strip()[-300:]}
    row.update(solve_cpu_s=solve["cpu"], solve_peak_mb=solve["peak_mb"], cpu_s=round(imp["cpu"] + solve["cpu"], 2),
               peak_mb=max(imp["peak_mb"], solve["peak_mb"]), solved=bool(result.get("solved")),
               status=result.get("status"), solver=result.get("solver"), heuristic=result.get("heuristic"),
               expanded=result.get("expanded"))
    if not row["solved"]:
        row["message"] = result.get("message") or solve["stderr"].strip()[-300:]
        return row
    row["plan_length"] = len([s for s in plan.read_text().splitlines() if s.strip()])
    back = peak_of(bcc("import", "mineplanner", domain, problem, "--plan", plan, "-o", pddl), timeout=600)
    if back["code"] != 0:
        return {**row, "valid": False, "reason": back["stderr"].strip()[-300:]}
    check = validate_child(domain, problem, pddl)
    row.update(valid=check["valid"], reason=check["reason"])
    return row


def human_row(data: Path, task: str, level: str, tmp: Path) -> dict:
    domain, problem = files(data, task, level)
    plan = tmp / f"{task}_{level}.human"
    plan.write_text("".join(s + "\n" for s in human_plan(data, task, level)))
    check = validate_child(domain, problem, plan, human=True)
    return {"human_length": len(human_plan(data, task, level)), "human_valid": check["valid"],
            "human_reason": check["reason"]}


def validate_main(domain: str, problem: str, plan: str, human: bool) -> None:
    """Child mode: print {valid, reason} for a PDDL plan (or, --human, a native plan mapped
    without checks, so the PDDL replay judges every step)."""
    from bcc.pddl_io.replay import replay
    lines = Path(plan).read_text().splitlines()
    if human:
        from bcc.errors import BccError
        from bcc.mineplanner import import_task, task_plan
        try:
            lines = task_plan(import_task(domain, problem), lines, check=False)
        except BccError as exc:
            print(json.dumps({"valid": False, "reason": exc.message}))
            return
    ok, why = replay(domain, problem, lines)
    print(json.dumps({"valid": ok, "reason": why}))


def table(rows: list) -> str:
    head = f"{'task':<21}{'level':<7}{'variant':<9}{'solved':<7}{'cpu s':>7}{'peak MB':>8}{'plan':>6}{'human':>6}" \
           f"  {'valid':<6}{'human ok':<9}"
    lines = [head, "-" * len(head)]
    for r in rows:
        lines.append(f"{r['task']:<21}{r['level']:<7}{r['variant']:<9}{'yes' if r.get('solved') else 'no':<7}"
                     f"{r.get('cpu_s', r.get('import_cpu_s', 0)):>7}{r.get('peak_mb', r.get('import_peak_mb', 0)):>8}"
                     f"{r.get('plan_length', '-'):>6}{r.get('human_length', '-'):>6}  "
                     f"{str(r.get('valid', '-')):<6}{str(r.get('human_valid', '-')):<9}")
    return "\n".join(lines)


def summary(rows: list, time_limit: float) -> dict:
    out = {}
    for kind in sorted({r["variant"] for r in rows}):
        rs = [r for r in rows if r["variant"] == kind]
        solved = [r for r in rs if r.get("solved")]
        out[kind] = {"tasks": len(rs), "solved": len(solved),
                     "valid": sum(1 for r in solved if r.get("valid")),
                     "under_60_s": sum(1 for r in solved if r["cpu_s"] < 60),
                     "no_longer_than_human": sum(1 for r in solved if r.get("human_length") is not None
                                                 and r["plan_length"] <= r["human_length"]),
                     "hard_peak_mb_max": max((r.get("peak_mb", 0) for r in rs if r["level"] == "Hard"), default=None)}
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--data", default=os.environ.get("MINEPLANNER_DATA", "/work/data/mineplanner/data"))
    ap.add_argument("--levels", default=",".join(LEVELS))
    ap.add_argument("--only", default="", help="a regular expression over task names")
    ap.add_argument("--variants", default="original", help="original, mirror, rotate (comma-separated)")
    ap.add_argument("--time-limit", type=float, default=60)
    ap.add_argument("--max-memory", type=int, default=1500)
    ap.add_argument("--solver", default="", help="bcc solve's --solver (default: its own default)")
    ap.add_argument("-o", "--output", default=str(HERE / "mineplanner_native.json"))
    ap.add_argument("--validate", nargs=3, metavar=("DOMAIN", "PROBLEM", "PLAN"), help=argparse.SUPPRESS)
    ap.add_argument("--human", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.validate:
        validate_main(*args.validate, args.human)
        return
    data = Path(args.data)
    if not (data / "pddl").is_dir():
        print(f"MinePlanner data not found at {data} (set --data or MINEPLANNER_DATA to the `data` folder of "
              "a copy of IretonLiu/mine-pddl); skipping")
        return
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        for level in args.levels.split(","):
            for task in TASKS:
                if args.only and not re.search(args.only, task):
                    continue
                human = human_row(data, task, level, tmp)
                for kind in args.variants.split(","):
                    row = {**run_one(data, task, level, kind, args, tmp), **human}
                    rows.append(row)
                    print(table([row]).splitlines()[-1], flush=True)
                    write(args, rows)   # after every task: a run cut short keeps what it measured
    print(table(rows))
    print(json.dumps(write(args, rows)["summary"], indent=2))


def write(args, rows: list) -> dict:
    result = {"machine": platform.node(), "python": platform.python_version(), "time_limit_s": args.time_limit,
              "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "summary": summary(rows, args.time_limit),
              "rows": rows}
    Path(args.output).write_text(json.dumps(result, indent=1) + "\n")
    return result


if __name__ == "__main__":
    main()
