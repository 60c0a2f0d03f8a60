#!/usr/bin/env python3
"""MinePlanner through PDDL: `bcc import pddl` beside Fast Downward lama-first, 45 tasks.

    python bench/mineplanner_pddl.py --data DIR                  # DIR holds data/pddl, data/human-solutions
    python bench/mineplanner_pddl.py --data DIR --levels Easy --time-limit 600
    python bench/mineplanner_pddl.py --data DIR --only 'Gather|Move' --levels Easy,Medium

The tasks are not in this repository: DIR is a copy of the public repository
IretonLiu/mine-pddl (Hill et al. 2023), or the environment variable MINEPLANNER_DATA
names one; the script says so and stops if neither is there. Each task is
DIR/data/pddl/<Task>/<Level>/propositional/<Task>_<Level>_{domain,problem}.pddl, and
DIR/data/human-solutions/<Task>/<Task>_<Level>.json is a human's solution.

Two changes are made to a copy of each task, and to nothing else. (1) The domain's
`checkgoal` action names a few problem objects (the goal's position or structure), which
Fast Downward rightly refuses: exactly those names are moved from the problem's
:objects into the domain's :constants (with their types); bcc reads both the original
and this copy. (2) A renamed copy: every predicate, action, type, object and the
domain's and problem's names replaced by meaningless ones (`p3`, `a7`, `t2`, `o41`, in
order of first appearance), the same task otherwise: bcc's results on it must match
(solved, plan length; the plan mapped back by name is compared too).

Each run is a whole process under a CPU-time limit (RLIMIT_CPU, as Fast Downward's
--overall-time-limit): bcc `import pddl --solver gbfs` (its default `--grounding
auto`), the same on the renamed copy, and Fast Downward `--alias lama-first`. Recorded:
solved, CPU seconds (the process and its children), peak memory (the largest resident
set of the process tree), plan length beside the human solution's (`checkgoal` not
counted, as the human's has none), and the verdict of an independent validator
(pddl-pyvalidator: unified-planning's reader, no code of bcc's) on bcc's plan. Prints a
table and writes bench/mineplanner_pddl.json.
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import re
import resource
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from timed_env import timed_env  # noqa: E402
from mineplanner_tasks import LEVELS, TASKS  # noqa: E402

VALIDATE_SECONDS = 120
FD_MEMORY_MB = 4000  # Fast Downward's translator took 1.8 GB on an Easy task; the machine is shared
WALL_FACTOR = 6      # the wall-clock cap, in CPU limits (a shared machine runs a process at a fraction of a core)
GOAL_ACTION = "checkgoal"
# Words of PDDL itself: never renamed.
RESERVED = {"define", "domain", "problem", "and", "or", "not", "imply", "exists", "forall", "when", "either",
            "object", "increase", "decrease", "total-cost", "minimize", "maximize", "number", "="}

# ---- the two copies -------------------------------------------------------------------
TOKEN = re.compile(r";[^\n]*|\(|\)|[^\s()]+")


def tokens(text: str) -> list:
    return [t for t in TOKEN.findall(text) if not t.startswith(";")]


def parse(text: str):
    stack, top = [], []
    cur = top
    for t in tokens(text.lower()):
        if t == "(":
            new: list = []
            cur.append(new)
            stack.append(cur)
            cur = new
        elif t == ")":
            cur = stack.pop()
        else:
            cur.append(t)
    return top[0]


def show(node, indent: int = 0) -> str:
    if isinstance(node, str):
        return node
    if not node or all(isinstance(x, str) for x in node):
        return "(" + " ".join(node) + ")"
    pad = "\n" + " " * (indent + 1)
    return "(" + pad.join(show(x, indent + 1) for x in node) + ")"


def section(tree: list, key: str):
    return next((s for s in tree[2:] if isinstance(s, list) and s and s[0] == key), None)


def typed_names(items: list) -> list:
    """(name, type) of a typed list `a b - t c - u`."""
    out, pending, i = [], [], 0
    while i < len(items):
        if items[i] == "-":
            out += [(p, items[i + 1]) for p in pending]
            pending, i = [], i + 2
        else:
            pending.append(items[i])
            i += 1
    return out + [(p, "object") for p in pending]


def words(node) -> set:
    return {node} if isinstance(node, str) else set().union(*(words(x) for x in node)) if node else set()


def with_constants(domain: list, problem: list) -> tuple[list, list, list]:
    """Move the problem objects the domain's actions name into the domain's :constants:
    (domain, problem, the names moved)."""
    objects = section(problem, ":objects")
    typed = dict(typed_names(objects[1:]))
    used = set()
    for s in domain[2:]:
        if isinstance(s, list) and s and s[0] == ":action":
            used |= {w for w in words(s) if w in typed}
    moved = sorted(used)
    if not moved:
        return domain, problem, []
    domain = [list(s) if isinstance(s, list) else s for s in domain]
    consts = section(domain, ":constants")
    entry = [x for n in moved for x in (n, "-", typed[n])]
    if consts is None:
        at = next(k for k, s in enumerate(domain) if isinstance(s, list) and s and s[0] in (":predicates",))
        domain.insert(at, [":constants", *entry])
    else:
        consts.extend(entry)
    kept = [(n, t) for n, t in typed_names(objects[1:]) if n not in used]
    problem = [([":objects", *[x for n, t in kept for x in (n, "-", t)]] if s is objects else s) for s in problem]
    return domain, problem, moved


def renaming(domain: list, problem: list) -> dict:
    """Every predicate, action, type, object and constant, and the two names -> a new name."""
    names: dict = {}

    def add(name: str, prefix: str):
        if name not in names and name not in RESERVED and not name.startswith(("?", ":")):
            names[name] = f"{prefix}{sum(1 for v in names.values() if v.startswith(prefix) and v[len(prefix):].isdigit())}"
    add(domain[1][1], "d")
    add(problem[1][1], "q")
    for s in domain[2:]:
        if not isinstance(s, list) or not s:
            continue
        if s[0] == ":types":
            for n, t in typed_names(s[1:]):
                add(n, "t")
                add(t, "t")
        elif s[0] == ":constants":
            for n, t in typed_names(s[1:]):
                add(n, "o")
        elif s[0] == ":predicates":
            for p in s[1:]:
                add(p[0], "p")
        elif s[0] == ":action":
            add(s[1], "a")
    for n, t in typed_names(section(problem, ":objects")[1:]):
        add(n, "o")
    return names


def renamed(node, names: dict):
    if isinstance(node, str):
        return names.get(node, node)
    return [renamed(x, names) for x in node]


def prepare(task: str, level: str, data: Path, out: Path) -> dict | None:
    """Write OUT/{domain,problem}.pddl (constants moved) and OUT/renamed/...: their paths."""
    folder = data / "data" / "pddl" / task / level / "propositional"
    dom_f, prob_f = folder / f"{task}_{level}_domain.pddl", folder / f"{task}_{level}_problem.pddl"
    if not dom_f.exists() or not prob_f.exists():
        return None
    domain, problem = parse(dom_f.read_text()), parse(prob_f.read_text())
    domain, problem, moved = with_constants(domain, problem)
    names = renaming(domain, problem)
    (out / "renamed").mkdir(parents=True, exist_ok=True)
    paths = {"domain": out / "domain.pddl", "problem": out / "problem.pddl",
             "renamed_domain": out / "renamed" / "domain.pddl", "renamed_problem": out / "renamed" / "problem.pddl"}
    paths["domain"].write_text(show(domain) + "\n")
    paths["problem"].write_text(show(problem) + "\n")
    paths["renamed_domain"].write_text(show(renamed(domain, names)) + "\n")
    paths["renamed_problem"].write_text(show(renamed(problem, names)) + "\n")
    return {"paths": {k: str(v) for k, v in paths.items()}, "moved_to_constants": moved,
            "names": names, "original": {"domain": str(dom_f), "problem": str(prob_f)}}


# ---- runs -----------------------------------------------------------------------------
MEASURE = ("import resource, subprocess, sys\n"
           "p = subprocess.run(sys.argv[2:])\n"
           "u = resource.getrusage(resource.RUSAGE_CHILDREN)\n"
           "open(sys.argv[1], 'w').write('%d %f' % (u.ru_maxrss, u.ru_utime + u.ru_stime))\n"
           "sys.exit(p.returncode if p.returncode >= 0 else 128 - p.returncode)\n")


def cpu_limit(seconds: float):
    def apply():
        resource.setrlimit(resource.RLIMIT_CPU, (int(seconds), int(seconds) + 1))
    return apply


def timed(cmd: list, limit: float, cwd: str | None = None, cpu_capped: bool = True) -> dict:
    """Run `cmd` as a whole process (inside a small launcher that reads its tree's peak
    resident memory and CPU seconds); killed after WALL_FACTOR x limit of wall time."""
    with tempfile.NamedTemporaryFile(prefix="bcc-mp-", suffix=".usage", delete=False) as f:
        usage = f.name
    start = time.perf_counter()
    child = subprocess.Popen([sys.executable, "-c", MEASURE, usage, *cmd], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, cwd=cwd, env=timed_env(), start_new_session=True,
                             preexec_fn=cpu_limit(limit) if cpu_capped else None)
    killed = False
    try:
        out, err = child.communicate(timeout=WALL_FACTOR * limit + 30)
    except subprocess.TimeoutExpired:
        os.killpg(child.pid, signal.SIGKILL)
        out, err = child.communicate()
        killed = True
    wall = time.perf_counter() - start
    peak_kb, cpu = 0, None
    try:
        text = Path(usage).read_text().split()
        peak_kb, cpu = int(text[0]), float(text[1])
    except (OSError, ValueError, IndexError):
        pass
    finally:
        Path(usage).unlink(missing_ok=True)
    return {"returncode": child.returncode, "stdout": out, "stderr": err, "killed": killed,
            "wall_seconds": round(wall, 2), "cpu_seconds": None if cpu is None else round(cpu, 2),
            "peak_mb": round(peak_kb / 1024, 1)}


def steps_of(plan: list) -> int:
    return sum(1 for a in plan if not a.strip("()").split()[0].startswith(GOAL_ACTION))


def run_bcc(domain: str, problem: str, limit: float, plan_file: str) -> dict:
    cmd = [sys.executable, "-m", "bcc", "import", "pddl", domain, problem, "--solver", "gbfs", "--json",
           "--time-limit", str(WALL_FACTOR * limit), "-o", plan_file]
    r = timed(cmd, limit)
    row = {k: r[k] for k in ("cpu_seconds", "wall_seconds", "peak_mb")}
    try:
        data = json.loads(r["stdout"])
    except ValueError:
        tail = (r["stderr"].strip().splitlines() or ["?"])[-1][:200]
        return {**row, "solved": False, "status": "killed" if r["killed"] else "budget" if r["returncode"] in
                (128 + signal.SIGXCPU, 128 + signal.SIGKILL) else "error", "message": tail}
    plan = data.get("plan") or []
    return {**row, "solved": bool(data.get("solved")), "status": data.get("status"), "plan": plan,
            "length": steps_of(plan) if data.get("solved") else None, "expanded": data.get("expanded"),
            "lifted": data.get("lifted"), "search_seconds": data.get("seconds")}


def run_first(domain: str, problem: str, limit: float) -> dict:
    """How long `bcc import pddl` takes to its first expansion (the issue's target: under 10 s
    on every Easy task): the same command stopped by `--max-states 1` once the start is
    expanded; the whole process's CPU seconds."""
    cmd = [sys.executable, "-m", "bcc", "import", "pddl", domain, problem, "--solver", "gbfs", "--json",
           "--time-limit", str(WALL_FACTOR * limit), "--max-states", "1"]
    r = timed(cmd, limit)
    try:
        data = json.loads(r["stdout"])
    except ValueError:
        return {"cpu_seconds": r["cpu_seconds"], "expanded": None, "status": "killed" if r["killed"] else "no result"}
    return {"cpu_seconds": r["cpu_seconds"], "peak_mb": r["peak_mb"], "expanded": data.get("expanded"),
            "status": data.get("status"), "lifted": data.get("lifted")}


def run_fd(domain: str, problem: str, limit: float) -> dict:
    from bcc.solvers.fast_downward import driver
    with tempfile.TemporaryDirectory(prefix="bcc-mp-fd-") as tmp:
        cmd = [sys.executable, str(driver()), "--alias", "lama-first", "--overall-time-limit", f"{int(limit)}s",
               "--overall-memory-limit", f"{FD_MEMORY_MB}M", "--plan-file", os.path.join(tmp, "plan"), os.path.abspath(domain), os.path.abspath(problem)]
        r = timed(cmd, limit, cwd=tmp, cpu_capped=False)    # the driver limits its components itself
        row = {k: r[k] for k in ("cpu_seconds", "wall_seconds", "peak_mb")}
        plan_path = os.path.join(tmp, "plan")
        if r["returncode"] == 0 and os.path.exists(plan_path):
            plan = [ln.strip() for ln in Path(plan_path).read_text().splitlines() if ln.strip() and ln[0] != ";"]
            return {**row, "solved": True, "status": "solved", "length": steps_of(plan)}
        phase = "translate" if "Done! [" not in r["stdout"] and "translator" in r["stdout"].lower() else "search"
        return {**row, "solved": False, "status": "killed" if r["killed"] else f"exit {r['returncode']}",
                "phase": phase}


def validate(domain: str, problem: str, plan: list) -> str:
    """pddl-pyvalidator's verdict on the plan, in a process of its own."""
    code = ("import json, sys\nfrom bcc.pddl_export.plans import validate\n"
            "print(json.dumps(validate(*sys.argv[1:4])))")
    with tempfile.NamedTemporaryFile("w", suffix=".plan", delete=False) as f:
        f.write("".join(a + "\n" for a in plan))
        plan_file = f.name
    try:
        proc = subprocess.run([sys.executable, "-c", code, domain, problem, plan_file], capture_output=True,
                              text=True, timeout=VALIDATE_SECONDS)
        ok, why = json.loads(proc.stdout.strip().splitlines()[-1])
        return "valid (pddl-pyvalidator)" if ok else f"INVALID: {why}"
    except subprocess.TimeoutExpired:
        return f"not checked (pddl-pyvalidator took over {VALIDATE_SECONDS} s)"
    except (ValueError, IndexError):
        return f"not checked ({(proc.stderr.strip().splitlines() or ['?'])[-1][:160]})"
    finally:
        os.unlink(plan_file)


class Replay:
    """A plan replayed on the task by a reader of its own (this file's `parse`, no code of
    bcc's): typing, and/or/not/imply/exists/forall/= in preconditions, unconditional
    effects, deletes before adds. pddl-pyvalidator is the independent validator of
    record, but on these tasks it took over 300 s a plan; this check takes a second."""

    def __init__(self, domain_file: str, problem_file: str):
        domain, problem = parse(Path(domain_file).read_text()), parse(Path(problem_file).read_text())
        parents: dict = {}
        types = section(domain, ":types")
        for n, t in typed_names(types[1:] if types else []):
            parents[n] = t
        self.objects: dict = {}
        consts = section(domain, ":constants")
        for n, t in typed_names(consts[1:] if consts else []) + typed_names(section(problem, ":objects")[1:]):
            self.objects[n] = t
        self.parents = parents
        self.actions = {s[1]: s for s in domain[2:] if isinstance(s, list) and s and s[0] == ":action"}
        self.state = {tuple(f) for f in section(problem, ":init")[1:] if f and f[0] != "not"}
        self.goal = section(problem, ":goal")[1]

    def is_a(self, t: str, want: str) -> bool:
        while t is not None:
            if t == want or want == "object":
                return True
            t = self.parents.get(t)
        return False

    def holds(self, f, env: dict) -> bool:
        head = f[0] if f else "and"
        if head == "and":
            return all(self.holds(g, env) for g in f[1:])
        if head == "or":
            return any(self.holds(g, env) for g in f[1:])
        if head == "not":
            return not self.holds(f[1], env)
        if head == "imply":
            return not self.holds(f[1], env) or self.holds(f[2], env)
        if head in ("exists", "forall"):
            params = typed_names(f[1])
            combos = [[o for o, t in self.objects.items() if self.is_a(t, want)] for _, want in params]
            import itertools
            results = (self.holds(f[2], {**env, **dict(zip((v for v, _ in params), c))})
                       for c in itertools.product(*combos))
            return any(results) if head == "exists" else all(results)
        if head == "=":
            return env.get(f[1], f[1]) == env.get(f[2], f[2])
        return tuple([head] + [env.get(a, a) for a in f[1:]]) in self.state

    def effects(self, f, env: dict, adds: list, dels: list) -> None:
        head = f[0] if f else "and"
        if head == "and":
            for g in f[1:]:
                self.effects(g, env, adds, dels)
        elif head == "not":
            dels.append(tuple([f[1][0]] + [env.get(a, a) for a in f[1][1:]]))
        elif head in ("increase", "decrease"):
            pass
        else:
            adds.append(tuple([head] + [env.get(a, a) for a in f[1:]]))

    def run(self, plan: list) -> str:
        for k, step in enumerate(plan, 1):
            words = step.strip("()").lower().split()
            a = self.actions.get(words[0])
            if a is None:
                return f"INVALID: step {k} names no action"
            parts = dict(zip(a[2::2], a[3::2]))
            params = typed_names(parts.get(":parameters", []))
            if len(params) != len(words) - 1:
                return f"INVALID: step {k} has {len(words) - 1} arguments"
            env = dict(zip((v for v, _ in params), words[1:]))
            if any(not self.is_a(self.objects.get(o, "?"), t) for (_, t), o in zip(params, words[1:])):
                return f"INVALID: step {k} has an argument of the wrong type"
            if not self.holds(parts.get(":precondition", []), env):
                return f"INVALID: step {k} ({step}) is not applicable"
            adds, dels = [], []
            self.effects(parts.get(":effect", []), env, adds, dels)
            self.state = (self.state - set(dels)) | set(adds)
        return "valid (replayed)" if self.holds(self.goal, {}) else "INVALID: the goal does not hold after the plan"


def human_length(data: Path, task: str, level: str) -> int | None:
    path = data / "data" / "human-solutions" / task / f"{task}_{level}.json"
    try:
        steps = json.loads(path.read_text())
    except (OSError, ValueError):
        return None
    return sum(1 for s in steps if s.get("action") != GOAL_ACTION)


def run_task(task: str, level: str, data: Path, work: Path, limit: float, planners: set,
             renamed_always: bool = False) -> dict | None:
    prep = prepare(task, level, data, work / f"{task}_{level}")
    if prep is None:
        return None
    p = prep["paths"]
    row = {"task": task, "level": level, "time_limit": limit, "moved_to_constants": prep["moved_to_constants"],
           "human_length": human_length(data, task, level)}
    if "fd" in planners:
        row["fd_lama_first"] = run_fd(p["domain"], p["problem"], limit)
    if "first" in planners:
        row["bcc_first_expansion"] = run_first(p["domain"], p["problem"], limit)
    if "bcc" not in planners:
        return row
    plan_file = str(work / f"{task}_{level}" / "bcc.plan")
    bcc = run_bcc(p["domain"], p["problem"], limit, plan_file)
    if bcc.get("solved"):
        bcc["replay"] = Replay(p["domain"], p["problem"]).run(bcc["plan"])
        bcc["validation"] = validate(p["domain"], p["problem"], bcc["plan"])
    if not bcc.get("solved") and not renamed_always:
        row["bcc"], row["bcc_renamed"] = bcc, {"status": "not run (the original was not solved)"}
        return row
    ren = run_bcc(p["renamed_domain"], p["renamed_problem"], limit, plan_file + ".renamed")
    back = {v: k for k, v in prep["names"].items()}
    if ren.get("solved"):
        mapped = ["(" + " ".join(back.get(w, w) for w in a.strip("()").split()) + ")" for a in ren["plan"]]
        ren["same_plan"] = mapped == bcc.get("plan")
        ren["length"] = steps_of(mapped)
        ren["replay"] = Replay(p["renamed_domain"], p["renamed_problem"]).run(ren["plan"])
    row["bcc"] = bcc
    row["bcc_renamed"] = ren
    row["match"] = bcc.get("solved") == ren.get("solved") and bcc.get("length") == ren.get("length")
    return row


def cell(r: dict | None) -> str:
    if not r:
        return "-"
    if r.get("solved"):
        return f"{r['length']:>4} {r['cpu_seconds']:>6.1f}s {r['peak_mb']:>5.0f}MB"
    return f"  -- {r.get('cpu_seconds') or 0:>6.1f}s {r.get('status', '')[:8]}"


def print_table(rows: list) -> None:
    print(f"{'task':<28}{'human':>6}  {'bcc (len cpu mem)':<24}{'bcc renamed':<24}{'FD lama-first':<24}"
          f"{'1st exp.':>9}  valid")
    for r in rows:
        b = r.get("bcc", {})
        first = r.get("bcc_first_expansion") or {}
        at = f"{first['cpu_seconds']:.1f}s" if first.get("expanded") else "-"
        print(f"{r['task'] + ' ' + r['level']:<28}{r['human_length'] or '-':>6}  {cell(b):<24}"
              f"{cell(r.get('bcc_renamed')):<24}{cell(r.get('fd_lama_first')):<24}{at:>9}  {b.get('validation', '')[:24]}")
    for level in LEVELS:
        mine = [r for r in rows if r["level"] == level]
        if mine:
            print(f"{level}: bcc {sum(bool(r.get('bcc', {}).get('solved')) for r in mine)}/{len(mine)}, renamed "
                  f"{sum(bool(r.get('bcc_renamed', {}).get('solved')) for r in mine)}/{len(mine)}, FD lama-first "
                  f"{sum(bool(r.get('fd_lama_first', {}).get('solved')) for r in mine)}/{len(mine)}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--data", default=os.environ.get("MINEPLANNER_DATA"),
                    help="a copy of IretonLiu/mine-pddl (or MINEPLANNER_DATA)")
    ap.add_argument("--levels", default="Easy,Medium,Hard")
    ap.add_argument("--only", default=None, help="a regular expression the task's name must match")
    ap.add_argument("--time-limit", type=float, default=600, help="CPU seconds a run [600]")
    ap.add_argument("--limits", default=None, help="per level, e.g. Easy=120,Medium=30,Hard=30 (overrides)")
    ap.add_argument("--planners", default="bcc,fd,first",
                    help="bcc, fd, first (bcc stopped at its first expansion), comma-separated [bcc,fd,first]")
    ap.add_argument("--renamed-always", action="store_true",
                    help="run the renamed copy also where the original was not solved (else it is skipped)")
    ap.add_argument("--merge", nargs="+", default=None,
                    help="only merge these JSON files of earlier runs (e.g. bcc and fd run side by side) into --json")
    ap.add_argument("--json", default=str(HERE / "mineplanner_pddl.json"))
    ap.add_argument("--work", default=None, help="folder for the task copies and plans [a temporary one]")
    args = ap.parse_args(argv)
    if args.merge:
        return merge(args.merge, args.json)
    if not args.data or not (Path(args.data) / "data" / "pddl").is_dir():
        print("MinePlanner's files are missing: pass --data DIR (a copy of github.com/IretonLiu/mine-pddl) "
              "or set MINEPLANNER_DATA; nothing was run", file=sys.stderr)
        return 0
    data = Path(args.data)
    limits = {lv: args.time_limit for lv in LEVELS}
    for part in filter(None, (args.limits or "").split(",")):
        lv, value = part.split("=")
        limits[lv.strip()] = float(value)
    levels = [lv for lv in args.levels.split(",") if lv]
    rows = []
    with tempfile.TemporaryDirectory(prefix="bcc-mineplanner-") as tmp:
        work = Path(args.work or tmp)
        for level in levels:
            for task in TASKS:
                if args.only and not re.search(args.only, task):
                    continue
                row = run_task(task, level, data, work, limits[level], set(args.planners.split(",")),
                               args.renamed_always)
                if row is None:
                    print(f"{task} {level}: files missing, skipped", file=sys.stderr)
                    continue
                rows.append(row)
                save(args, limits, rows)          # after every task: a run cut short keeps what it measured
                print(f"{task} {level}: bcc {cell(row.get('bcc'))} | renamed {cell(row.get('bcc_renamed'))} | "
                      f"FD {cell(row.get('fd_lama_first'))}", file=sys.stderr, flush=True)
    print_table(rows)
    save(args, limits, rows)
    print(f"wrote {args.json}", file=sys.stderr)
    return 0


def save(args, limits: dict, rows: list) -> None:
    import copy
    rows = copy.deepcopy(rows)
    for r in rows:     # plans are long: the JSON keeps their lengths
        for key in ("bcc", "bcc_renamed"):
            r.get(key, {}).pop("plan", None)
    out = {"benchmark": "MinePlanner (IretonLiu/mine-pddl), propositional PDDL", "time_limits": limits,
           "note": "CPU seconds per run (RLIMIT_CPU); the issue's 600 s per task applies where time_limit is 600",
           "changes_to_the_tasks": "the problem objects named in the domain's checkgoal action are moved into "
                                   "the domain's :constants (moved_to_constants per task); nothing else",
           "renamed_copy": "run where the original was solved" + (" and where not" if args.renamed_always else ""),
           "validator": "pddl-pyvalidator (bcc.pddl_export.plans.validate), on the copy with constants moved",
           "machine": {"python": platform.python_version(), "cpus": os.cpu_count()},
           "tasks": rows}
    sys.path.insert(0, str(HERE.parent.parent))
    from bcc.atomic import write_text
    write_text(args.json, json.dumps(out, indent=1) + "\n")


def merge(paths: list, out_path: str) -> int:
    """Rows of several runs joined by (task, level); the time limits and notes of the first."""
    runs = [json.loads(Path(p).read_text()) for p in paths]
    rows: dict = {}
    for run in runs:
        for r in run["tasks"]:
            rows.setdefault((r["task"], r["level"]), {}).update(r)
    out = dict(runs[0], tasks=list(rows.values()), merged_from=[str(p) for p in paths],
               time_limits={k: v for run in runs for k, v in run["time_limits"].items()})
    print_table(out["tasks"])
    sys.path.insert(0, str(HERE.parent.parent))
    from bcc.atomic import write_text
    write_text(out_path, json.dumps(out, indent=1) + "\n")
    print(f"wrote {out_path}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
