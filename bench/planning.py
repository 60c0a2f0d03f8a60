#!/usr/bin/env python3
"""Planning benchmark: bcc on IPC problems and manipulation dungeons, beside Fast Downward.

    python bench/planning.py --ipc /path/to/checkouts                   # the whole manifest
    python bench/planning.py --ipc DIR --only 'gripper|sokoban' --time-limit 30
    python bench/planning.py --dungeons-only                            # bcc's dungeons only

The IPC files are not in this repository: bench/planning_manifest.txt names each problem
as `REPOSITORY DOMAIN-PATH PROBLEM-PATH` inside a public repository
(AI-Planning/classical-domains, potassco/pddl-instances). `--ipc DIR` is a folder holding
a copy of each repository under its last name part (DIR/classical-domains/...,
DIR/pddl-instances/...); a problem whose files are missing is reported and skipped.

Every run is a whole process, timed from start to exit (import, parse, ground, search):
bcc `import pddl` with each bcc configuration, and Fast Downward's driver (translator and
search) with astar(blind()), astar(lmcut()) and lazy_greedy([ff()]) in the same run, each
with the same time limit. The limit counts CPU seconds for both, as Fast Downward's
`--overall-time-limit` does (RLIMIT_CPU): on a machine shared with other work, a
wall-clock limit for bcc beside a CPU limit for Fast Downward would compare unequal
budgets. Both are also killed after WALL_FACTOR times the limit of wall-clock time. Per problem: solved, cost, expansions, seconds. bcc's plans are
checked by an independent validator (pddl-pyvalidator, when installed) and their costs
against Fast Downward's optimal configurations. Prints coverage and ratio tables, writes
bench/planning.json and, with matplotlib, bench/planning.png.

The manipulation dungeons (bcc.generate_rooms: three rooms, N = 2, 4, 6, 8 stones to
carry into the blue room) run through `bcc solve` (A* with its default heuristic, GBFS
with hff) and through `--solver fd` (Fast Downward on bcc's own PDDL export of the
dungeon: astar(blind()), lazy_greedy([ff()])), beside each other; bcc runs with its
cache off (BCC_NO_CACHE), so each builds its heuristic's tables as a first solve does.
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import re
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))   # also when a test loads this file by its path
from timed_env import timed_env  # noqa: E402
MANIFEST = HERE / "planning_manifest.txt"
FD_CONFIGS = {"fd-blind": "astar(blind())", "fd-lmcut": "astar(lmcut())", "fd-ff": "lazy_greedy([ff()])"}
BCC_CONFIGS = {"bcc-astar": ["--solver", "astar"], "bcc-blind": ["--solver", "astar", "--heuristic", "blind"],
               "bcc-gbfs": ["--solver", "gbfs", "--heuristic", "hff"]}
OPTIMAL = {"bcc-astar", "bcc-blind", "fd-blind", "fd-lmcut"}
DUNGEON_GOAL = "every stone in the blue room"
VALIDATE_SECONDS = 120
WALL_FACTOR = 3      # the wall-clock cap of a run, in time limits (the budget itself is CPU time)


def read_manifest(path: Path) -> list[dict]:
    out = []
    for n, line in enumerate(path.read_text().splitlines(), 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        parts = line.split()
        if len(parts) != 3:
            sys.exit(f"{path}:{n}: expected REPOSITORY DOMAIN PROBLEM")
        repo, dom, prob = parts
        out.append({"repo": repo, "domain_path": dom, "problem_path": prob,
                    "name": "/".join(filter(None, (Path(dom).parent.name, Path(prob).stem)))})
    return out


CPU: dict = {}   # the CPU seconds (user + system, children included) of the last timed() run


def cpu_limit(seconds: float):
    """A `preexec_fn` giving the child `seconds` of CPU time, as Fast Downward's driver
    limits its components (soft limit: SIGXCPU, one second later SIGKILL)."""
    def apply():
        import resource
        resource.setrlimit(resource.RLIMIT_CPU, (int(seconds), int(seconds) + 1))
    return apply


def timed(cmd: list, limit: float, cwd: str | None = None,
          preexec=None, env: dict | None = None) -> tuple[subprocess.CompletedProcess | None, float]:
    """Run `cmd` as a whole process; (completed process or None if killed, wall seconds).
    Its CPU seconds (the process and its children: Fast Downward's translator and search)
    are left in CPU["last"]: on a loaded machine they vary less than wall time."""
    import resource
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    # A session of its own: at the wall-clock cap the whole group is killed. Killing only
    # the child left Fast Downward's search (a grandchild) running on, orphaned, for up to
    # its CPU limit, beside the next runs.
    child = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=cwd,
                             env=env or timed_env(), preexec_fn=preexec, start_new_session=True)
    try:
        out, err = child.communicate(timeout=WALL_FACTOR * limit + 15)
        proc = subprocess.CompletedProcess(cmd, child.returncode, out, err)
    except subprocess.TimeoutExpired:
        os.killpg(child.pid, signal.SIGKILL)
        child.communicate()
        proc = None
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    CPU["last"] = round(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime, 3)
    return proc, wall


def run_bcc(config: str, domain: str, problem: str, limit: float, plan_file: str) -> dict:
    # bcc's own --time-limit (wall clock) is the cap; the budget is the CPU limit
    cmd = [sys.executable, "-m", "bcc", "import", "pddl", domain, problem, "--json", "--time-limit",
           str(WALL_FACTOR * limit), "-o", plan_file, *BCC_CONFIGS[config]]
    proc, seconds = timed(cmd, limit, preexec=cpu_limit(limit))
    row = {"config": config, "seconds": round(seconds, 3), "cpu_seconds": CPU["last"], "solved": False}
    if proc is None:
        return {**row, "status": "killed"}
    if proc.returncode in (-signal.SIGXCPU, -signal.SIGKILL) and not proc.stdout.strip():
        return {**row, "status": "budget", "message": "CPU time limit"}
    try:
        data = json.loads(proc.stdout)
    except ValueError:
        msg = (proc.stderr.strip().splitlines() or ["?"])[-1]
        return {**row, "status": "error" if proc.returncode == 2 else "crash", "message": msg[:300]}
    return {**row, "solved": data.get("solved", False), "status": data.get("status"), "cost": data.get("cost"),
            "expanded": data.get("expanded"), "search_seconds": data.get("seconds"),
            "atoms": data.get("atoms"), "actions": data.get("grounded_actions"), "heuristic": data.get("heuristic")}


def run_fd(config: str, domain: str, problem: str, limit: float) -> dict:
    from bcc.solvers.fast_downward import driver
    with tempfile.TemporaryDirectory(prefix="bcc-bench-fd-") as tmp:
        cmd = [sys.executable, str(driver()), "--overall-time-limit", f"{int(limit)}s", "--plan-file",
               os.path.join(tmp, "plan"), os.path.abspath(domain), os.path.abspath(problem),
               "--search", FD_CONFIGS[config]]
        proc, seconds = timed(cmd, limit, cwd=tmp)
        row = {"config": config, "seconds": round(seconds, 3), "cpu_seconds": CPU["last"], "solved": False}
        if proc is None:
            return {**row, "status": "killed"}
        out = proc.stdout
        exp = re.findall(r"Expanded (\d+) state", out)
        if proc.returncode == 0 and os.path.exists(os.path.join(tmp, "plan")):
            cost = re.search(r"Plan cost: (\d+)", out)
            return {**row, "solved": True, "status": "solved", "cost": int(cost[1]) if cost else None,
                    "expanded": int(exp[-1]) if exp else None}
        status = {11: "no_solution", 12: "no_solution", 23: "budget", 22: "budget", 21: "budget", 20: "budget",
                  232: "budget"}.get(proc.returncode, f"error {proc.returncode}")
        return {**row, "status": status, "expanded": int(exp[-1]) if exp else None}


def validate_plan(domain: str, problem: str, plan_file: str) -> str:
    """pddl-pyvalidator's verdict; where it refuses the plan or cannot read the files, a
    second opinion from Fast Downward's translator (`sas_replay`). Neither shares code
    with bcc's reader or grounder."""
    code = ("import json, sys\nfrom bcc.pddl_export.plans import validate\n"
            "print(json.dumps(validate(*sys.argv[1:4])))")
    try:   # a process of its own, with a limit: unified-planning's parser can take many minutes (nomystery p02)
        proc = subprocess.run([sys.executable, "-c", code, domain, problem, plan_file], capture_output=True,
                              text=True, timeout=VALIDATE_SECONDS)
        ok, why = json.loads(proc.stdout.strip().splitlines()[-1])
        verdict = "valid" if ok else f"INVALID: {why}"
    except subprocess.TimeoutExpired:
        ok, verdict = False, f"not checked (pyvalidator took over {VALIDATE_SECONDS} s)"
    except (ValueError, IndexError):  # the validator is optional and may fail on its own
        ok, verdict = False, f"not checked ({(proc.stderr.strip().splitlines() or ['?'])[-1][:120]})"
    if ok:
        return verdict
    second = sas_replay(domain, problem, plan_file)
    if second.startswith("valid"):
        return f"{second}; pyvalidator: {verdict}"
    return verdict if second.startswith("not checked") else f"INVALID: {second}; pyvalidator: {verdict}"


def sas_replay(domain: str, problem: str, plan_file: str) -> str:
    """Replay the plan on Fast Downward's translation of the task (its finite-domain
    operators, by name): every step applicable and the goal reached. The translator only
    drops what no plan needs, so a plan whose operators it kept is checked in full."""
    with tempfile.TemporaryDirectory(prefix="bcc-bench-sas-") as tmp:
        sas = os.path.join(tmp, "output.sas")
        proc = subprocess.run([sys.executable, "-m", "fast_downward.translate", os.path.abspath(domain),
                               os.path.abspath(problem), "--sas-file", sas], capture_output=True, text=True, cwd=tmp)
        if proc.returncode != 0 or not os.path.exists(sas):
            return f"not checked (translator exit {proc.returncode})"
        lines = Path(sas).read_text().split("\n")
    pos = 0

    def take() -> str:
        nonlocal pos
        pos += 1
        return lines[pos - 1]

    def ints() -> list:
        return [int(x) for x in take().split()]

    while take() != "end_metric":
        pass
    variables = int(take())
    for _ in range(variables):
        while take() != "end_variable":
            pass
    for _ in range(int(take())):
        while take() != "end_mutex_group":
            pass
    take()
    state = [int(take()) for _ in range(variables)]
    take(), take()                     # end_state, begin_goal
    goal = [ints() for _ in range(int(take()))]
    take()
    operators: dict = {}
    for _ in range(int(take())):
        take()
        name = take().strip()
        prevail = [ints() for _ in range(int(take()))]
        effects = [ints() for _ in range(int(take()))]
        operators[name] = (prevail, effects, int(take()))
        take()
    if int(take()):
        return "not checked (the translation has axioms)"
    steps = [ln.strip().strip("()").strip().lower() for ln in Path(plan_file).read_text().splitlines()
             if ln.strip() and not ln.strip().startswith(";")]
    for k, step in enumerate(steps, 1):
        op = operators.get(" ".join(step.split()))
        if op is None:
            return f"not checked (step {k}, {step}, is not an operator of the translation)"
        prevail, effects, _ = op
        if any(state[v] != val for v, val in prevail) or any(e[-2] != -1 and state[e[-3]] != e[-2] for e in effects):
            return f"step {k} ({step}) is not applicable"
        old = list(state)
        for e in effects:
            conds = [e[1 + 2 * i: 3 + 2 * i] for i in range(e[0])]
            if all(old[v] == val for v, val in conds):
                state[e[-3]] = e[-1]
    if any(state[v] != val for v, val in goal):
        return "the goal does not hold after the plan"
    return "valid (Fast Downward's translation)"


# ---- the manipulation dungeons ------------------------------------------------------
def run_dungeon(path: Path, solver: list, limit: float, label: str) -> dict:
    cmd = [sys.executable, "-m", "bcc", "solve", str(path), "--json", "--time-limit", str(limit), *solver]
    # no cache: every run builds its tables, as a first solve of a new dungeon does
    proc, seconds = timed(cmd, limit, env=timed_env(BCC_NO_CACHE="1"))
    row = {"config": label, "seconds": round(seconds, 3), "cpu_seconds": CPU["last"], "solved": False}
    if proc is None:
        return {**row, "status": "killed"}
    try:
        data = json.loads(proc.stdout)
    except ValueError:
        return {**row, "status": "error", "message": (proc.stderr.strip().splitlines() or ["?"])[-1][:300]}
    return {**row, "solved": data.get("solved", False), "status": data.get("status"), "cost": data.get("cost"),
            "expanded": data.get("expanded"), "search_seconds": data.get("seconds"), "heuristic": data.get("heuristic")}


DUNGEON_CONFIGS = {"bcc-astar": ["--solver", "astar"], "bcc-gbfs": ["--solver", "gbfs", "--heuristic", "hff"],
                   "fd-blind": ["--solver", "fd", "--fd-search", "astar(blind())"],
                   "fd-ff": ["--solver", "fd", "--fd-search", "lazy_greedy([ff()])"]}


def check_costs(entry: dict) -> None:
    """Every optimal configuration that solved the problem must report the same cost."""
    runs = entry["runs"]
    costs = {c: r["cost"] for c, r in runs.items() if c in OPTIMAL and r.get("solved")}
    if any(c.startswith("bcc") for c in costs) and any(c.startswith("fd") for c in costs):
        entry["cost_check"] = "ok" if len(set(costs.values())) == 1 else f"WRONG: {costs}"


# ---- reports ------------------------------------------------------------------------
def _ratios(problems: list, mine: str, theirs: list, field: str) -> dict:
    """bcc's time over the fastest of `theirs` that solved it, on problems both solved."""
    rs = []
    for p in problems:
        run = p["runs"].get(mine, {})
        best = [p["runs"][f].get(field) for f in theirs if p["runs"].get(f, {}).get("solved")]
        best = [b for b in best if b]
        if run.get("solved") and run.get(field) and best:
            rs.append(run[field] / min(best))
    return {"median": round(statistics.median(rs), 2) if rs else None,
            "worst": round(max(rs), 2) if rs else None, "problems": len(rs)}


def summarize(problems: list, configs: list) -> dict:
    cov = {c: sum(1 for p in problems if p["runs"].get(c, {}).get("solved")) for c in configs}
    fd = [c for c in configs if c.startswith("fd-")]
    fd_optimal = [c for c in fd if c in OPTIMAL]
    ratios = {}
    for c in configs:
        if c.startswith("fd-"):
            continue
        r = _ratios(problems, c, fd, "seconds")
        ratios[c] = {"median_vs_best_fd": r["median"], "worst_vs_best_fd": r["worst"], "problems": r["problems"],
                     "cpu_vs_best_fd": _ratios(problems, c, fd, "cpu_seconds"),
                     "wall_vs_best_optimal_fd": _ratios(problems, c, fd_optimal, "seconds")}
    wrong = [p["name"] for p in problems if p.get("cost_check", "").startswith("WRONG")]
    invalid = [f"{p['name']} ({c})" for p in problems for c, r in p["runs"].items()
               if r.get("validation", "").startswith("INVALID")]
    invalid += [p["name"] for p in problems if p.get("validation", "").startswith("INVALID")]  # older runs
    return {"coverage": cov, "time_ratios": ratios, "wrong_costs": wrong, "invalid_plans": invalid,
            "problems": len(problems)}


def print_table(problems: list, configs: list, title: str):
    print(f"\n## {title}")
    head = f"{'problem':<44}" + "".join(f"{c:>22}" for c in configs)
    print(head)
    print("-" * len(head))
    for p in problems:
        cells = []
        for c in configs:
            r = p["runs"].get(c, {})
            if r.get("solved"):
                exp = r.get("expanded")
                cells.append(f"{r['cost']}/{exp if exp is not None else '-'}/{r['seconds']:.1f}s")
            else:
                cells.append(str(r.get("status", "-"))[:12])
        print(f"{p['name'][:43]:<44}" + "".join(f"{x:>22}" for x in cells))
    print("(cells: cost/expanded/whole-process seconds)")


def plot(problems: list, configs: list, path: Path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("(no plot: pip install matplotlib)")
        return
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for c in configs:
        times = sorted(p["runs"][c]["seconds"] for p in problems if p["runs"].get(c, {}).get("solved"))
        ax.step(times, range(1, len(times) + 1), where="post", label=f"{c} ({len(times)})")
    ax.set_xscale("log")
    ax.set_xlabel("whole-process seconds")
    ax.set_ylabel("problems solved")
    ax.set_title("Coverage against time")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")


def save(args, configs, problems, dungeons) -> dict:
    for entry in problems:
        check_costs(entry)
    report = {"machine": {"python": platform.python_version(), "cpus": os.cpu_count()},
              "time_limit": args.time_limit, "time_limit_clock": "cpu", "configs": configs}
    if not args.combine:
        report["wall_factor"] = WALL_FACTOR
    if getattr(args, "note", None):
        report["note"] = args.note
    if getattr(args, "sources", None):
        report["combined_from"] = args.sources
    if problems:
        report["ipc"] = {"summary": summarize(problems, configs), "problems": problems}
    if dungeons:
        report["dungeons"] = dungeons
    from bcc.atomic import write_text
    write_text(str(args.out), json.dumps(report, indent=1) + "\n")
    return report


def main(argv=None):
    global WALL_FACTOR
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ipc", type=Path, help="folder with copies of the repositories the manifest names")
    ap.add_argument("--manifest", type=Path, default=MANIFEST)
    ap.add_argument("--only", help="regular expression: only problems whose name matches")
    ap.add_argument("--per-domain", type=int, default=None, metavar="N",
                    help="only the first N problems of each domain of the manifest")
    ap.add_argument("--shard", default="0/1", metavar="K/N",
                    help="run only every N-th problem of the selection, starting at the K-th (halves run side by "
                         "side are merged with --combine)")
    ap.add_argument("--time-limit", type=float, default=120.0)
    ap.add_argument("--wall-factor", type=float, default=WALL_FACTOR,
                    help="a run is killed after this many time limits of wall-clock time (the budget is CPU time): "
                         "raise it on a loaded machine so that the CPU limit is what stops a run")
    ap.add_argument("--configs", default=",".join([*BCC_CONFIGS, *FD_CONFIGS]))
    ap.add_argument("--no-validate", action="store_true")
    ap.add_argument("--dungeons-only", action="store_true")
    ap.add_argument("--no-dungeons", action="store_true")
    ap.add_argument("--stones", type=int, nargs="+", default=[2, 4, 6, 8], help="manipulation dungeons to run")
    ap.add_argument("--combine", type=Path, nargs="+", metavar="JSON",
                    help="only merge the JSON of earlier runs (e.g. halves run side by side) and report")
    ap.add_argument("--note", help="a sentence kept in the JSON (e.g. which commit ran, or that rows were reused)")
    ap.add_argument("--out", type=Path, default=HERE / "planning.json")
    ap.add_argument("--plot", type=Path, default=HERE / "planning.png")
    args = ap.parse_args(argv)
    configs = args.configs.split(",")
    WALL_FACTOR = args.wall_factor
    problems, dungeons = [], []
    if args.combine:
        parts = [json.loads(p.read_text()) for p in args.combine]
        configs = list(dict.fromkeys(c for part in parts for c in part["configs"]))
        by_name: dict = {}
        for part in parts:     # runs of the same problem (other configurations) are merged
            for p in part.get("ipc", {}).get("problems", []):
                by_name.setdefault(p["name"], {**p, "runs": {}})["runs"].update(p["runs"])
        problems = list(by_name.values())
        if problems:   # the configurations that ran on IPC problems (a dungeons-only run lists its own)
            configs = [c for c in configs if any(c in p["runs"] for p in problems)]
        dungeons = [d for part in parts for d in part.get("dungeons", [])]
        args.time_limit = parts[0]["time_limit"]
        # Which run each configuration's rows come from: Fast Downward's rows may be reused
        # from an earlier run of the same Fast Downward (it does not change with bcc).
        args.sources = [{"file": p.name, "configs": part["configs"],
                         "problems": len(part.get("ipc", {}).get("problems", [])),
                         **({"note": part["note"]} if part.get("note") else {})}
                        for p, part in zip(args.combine, parts)]
    elif not args.dungeons_only:
        if args.ipc is None:
            ap.error("--ipc DIR is needed (or --dungeons-only)")
        seen: dict = {}
        shard, shards = (int(x) for x in args.shard.split("/"))
        selected = 0
        for entry in read_manifest(args.manifest):
            if args.only and not re.search(args.only, entry["name"]):
                continue
            domain_dir = entry["name"].split("/")[0]
            seen[domain_dir] = seen.get(domain_dir, 0) + 1
            if args.per_domain is not None and seen[domain_dir] > args.per_domain:
                continue
            selected += 1
            if (selected - 1) % shards != shard:
                continue
            base = args.ipc / entry["repo"].split("/")[-1]
            dom, prob = base / entry["domain_path"], base / entry["problem_path"]
            if not dom.is_file() or not prob.is_file():
                print(f"skip {entry['name']}: {dom if not dom.is_file() else prob} is missing", file=sys.stderr)
                continue
            runs = {}
            with tempfile.TemporaryDirectory(prefix="bcc-bench-") as tmp:
                plan_file = os.path.join(tmp, "plan")
                for c in configs:
                    if c in BCC_CONFIGS:
                        runs[c] = run_bcc(c, str(dom), str(prob), args.time_limit, plan_file)
                        if runs[c].get("solved") and not args.no_validate:
                            runs[c]["validation"] = validate_plan(str(dom), str(prob), plan_file)
                    else:
                        runs[c] = run_fd(c, str(dom), str(prob), args.time_limit)
            entry["runs"] = runs
            problems.append(entry)
            save(args, configs, problems, [])   # after each problem: a stopped run keeps what it measured
            print(f"{entry['name']:<44} " + " ".join(f"{c} {runs[c].get('cost')}/{runs[c].get('expanded')}/"
                                                     f"{runs[c]['seconds']}s {runs[c].get('validation', '')}"
                                                     for c in configs), file=sys.stderr, flush=True)
    if not args.no_dungeons and not args.combine:
        from bcc.generate_rooms import generate_manipulation
        with tempfile.TemporaryDirectory(prefix="bcc-bench-rooms-") as tmp:
            for n in args.stones:
                path = Path(tmp) / f"stones_{n}.yaml"
                path.write_text(generate_manipulation(n, name=f"stones_{n}"))
                runs = {c: run_dungeon(path, s, args.time_limit, c) for c, s in DUNGEON_CONFIGS.items()}
                dungeons.append({"name": path.stem, "runs": runs})
                save(args, configs, problems, dungeons)
                print(f"{path.stem}: " + " ".join(f"{c} {r.get('cost')}/{r.get('expanded')}/{r['seconds']}s"
                                                for c, r in runs.items()), file=sys.stderr, flush=True)
    report = save(args, configs, problems, dungeons)
    if problems:
        print_table(problems, configs, "IPC problems")
        s = report["ipc"]["summary"]
        print("\ncoverage: " + ", ".join(f"{c} {n}/{len(problems)}" for c, n in s["coverage"].items()))
        for c, r in s["time_ratios"].items():
            print(f"{c}: whole-process time / best Fast Downward configuration: median {r['median_vs_best_fd']}x, "
                  f"worst {r['worst_vs_best_fd']}x over {r['problems']} problems both solved")
            cpu, opt = r.get("cpu_vs_best_fd") or {}, r.get("wall_vs_best_optimal_fd") or {}
            print(f"{'':>{len(c)}}  CPU seconds: median {cpu.get('median')}x, worst {cpu.get('worst')}x; "
                  f"wall vs the best optimal FD configuration: median {opt.get('median')}x, worst {opt.get('worst')}x")
        print(f"wrong costs: {s['wrong_costs'] or 'none'}; invalid plans: {s['invalid_plans'] or 'none'}")
        plot(problems, configs, args.plot)
    if dungeons:
        print_table(dungeons, list(DUNGEON_CONFIGS), f"Manipulation dungeons ({DUNGEON_GOAL})")
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
