#!/usr/bin/env python3
"""HTN benchmark: `bcc import hddl` (solver htn) on the IPC 2020 total-order track, every
plan verified, beside the published results.

    python bench/htn.py --ipc DIR                          # Minecraft-Regular and -Player
    python bench/htn.py --ipc DIR --others 5               # + the first 5 of every other domain
    python bench/htn.py --ipc DIR --panda PATH/pandaPIparser --time-limit 60

DIR is a copy of the public repository panda-planner-dev/ipc2020-domains (its
total-order/ folder is read); nothing of it is in this repository. A snapshot may lack
its largest files (4 MB and more): with --repo (its git directory) the problems the
repository lists but the copy lacks are reported as missing, never counted as solved or
failed. --rebuilt DIR runs such Minecraft-Regular problems rebuilt elsewhere with the
repository's own generator (Minecraft-Player/generate-problem-hddl-player.py, less the
player's facts: that reproduces each of the 44 present problems exactly, whitespace
aside); their rows say `rebuilt`.

Each run is a whole process (`python -m bcc import hddl D P --json --ipc-plan F`), timed
in CPU seconds (RLIMIT_CPU is the budget; wall time on a shared machine is noisy). Each
plan is checked by bcc's verifier (hddl/verify.py, written apart from the planner) and,
with --panda, by the competition's own verifier (pandaPIparser -v -l, built from its public
source; -l ignores case, as bcc reads HDDL names). Prints one table beside the published IPC figures and writes bench/htn.json.
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import re
import statistics
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from planning import cpu_limit, timed, CPU  # noqa: E402

FIRST = ["Minecraft-Regular", "Minecraft-Player"]
# Published coverage (the figures: IPC 2020 total-order track, 30 min and 8 GB per
# problem; IPC 2023 the same track).
PUBLISHED = {
    "Minecraft-Regular": "IPC 2020: HyperTensioN score 57.1/59 (Lilotane 29.2, PDDL4J 23); IPC 2023 best 42/59",
    "Minecraft-Player": "best solved: 5/20 (IPC 2020), 4/20 (IPC 2023)",
}
IPC_SIZE = {"Minecraft-Regular": 59, "Minecraft-Player": 20}


def problems(folder: Path) -> list[tuple[str, str]]:
    """(domain file, problem file) of a domain folder, in name order."""
    files = sorted(p for p in folder.glob("*.hddl"))
    domains = [p for p in files if "domain" in p.name]
    out = []
    for p in files:
        if p in domains:
            continue
        if len(domains) == 1:
            out.append((str(domains[0]), str(p)))
        else:   # one domain file per problem: NAME-domain.hddl beside NAME.hddl
            d = p.with_name(p.stem + "-domain.hddl")
            if d.exists():
                out.append((str(d), str(p)))
    return out


def missing(folder: Path, repo: Path | None) -> list[str]:
    """Problems the repository names that this copy lacks (a snapshot drops big files)."""
    if repo is None:
        return []
    import subprocess
    listed = subprocess.run(["git", "-C", str(repo), "ls-tree", "--name-only", "HEAD", f"total-order/{folder.name}/"],
                            capture_output=True, text=True).stdout.split()
    return sorted(Path(p).name for p in listed if p.endswith(".hddl") and "domain" not in p
                  and not (folder / Path(p).name).exists())


def run(domain: str, problem: str, limit: float, panda: str | None, panda_limit: float = 120) -> dict:
    with tempfile.TemporaryDirectory(prefix="bcc-bench-htn-") as tmp:
        ipc = os.path.join(tmp, "plan.ipc")
        cmd = [sys.executable, "-m", "bcc", "import", "hddl", domain, problem, "--json", "--ipc-plan", ipc,
               "--time-limit", str(3 * limit)]
        proc, wall = timed(cmd, limit, preexec=cpu_limit(limit))
        row = {"problem": Path(problem).name, "cpu_seconds": CPU["last"], "seconds": round(wall, 3), "solved": False}
        if proc is None:
            return {**row, "status": "killed"}
        try:
            data = json.loads(proc.stdout)
        except ValueError:
            return {**row, "status": "budget" if proc.returncode < 0 else "error",
                    "message": (proc.stderr.strip().splitlines() or ["?"])[-1][:300]}
        row.update(status=data["status"], solved=data["solved"], length=data.get("cost"),
                   expanded=data.get("expanded"), search_seconds=data.get("seconds"))
        if data["solved"]:
            row["verified"] = verify(domain, problem, Path(ipc).read_text())
            if panda:
                row["panda"] = panda_verify(panda, domain, problem, ipc, panda_limit)
        return row


def verify(domain: str, problem: str, text: str) -> bool | str:
    from bcc.hddl.read import read_hddl
    from bcc.hddl.verify import verify as check
    why = check(read_hddl(domain, problem), text)
    return True if why is None else why


def panda_verify(panda: str, domain: str, problem: str, plan: str, limit: float) -> bool | str:
    import subprocess
    try:
        # -l (lenient): bcc reads HDDL case-insensitively and writes names lowercased, while
        # pandaPIparser is case-sensitive unless told otherwise (AssemblyHierarchical's CamelCase)
        out = subprocess.run([panda, "-v", "-l", domain, problem, plan], capture_output=True, text=True,
                             timeout=limit)
    except subprocess.TimeoutExpired:
        return "timeout"
    text = re.sub(r"\x1b\[[0-9;]*m", "", out.stdout + out.stderr)
    found = re.search(r"Plan verification result: (\w+)", text)
    return found is not None and found[1] == "true" or (found[1] if found else text.strip()[-200:])


def summary(name: str, rows: list, absent: list) -> dict:
    solved = [r for r in rows if r["solved"]]
    cpu = [r["cpu_seconds"] for r in solved]
    return {"domain": name, "run": len(rows), "missing": len(absent), "solved": len(solved),
            "no_plan": sum(r["status"] == "no_solution" for r in rows),
            "verified": sum(r.get("verified") is True for r in solved),
            "panda_verified": sum(r.get("panda") is True for r in solved) if any("panda" in r for r in solved)
            else None,
            "panda_refused": sum(r.get("panda") not in (True, "timeout", None) for r in solved),
            "cpu_median": round(statistics.median(cpu), 2) if cpu else None, "cpu_max": max(cpu) if cpu else None,
            "length_max": max((r["length"] for r in solved), default=None),
            "published": PUBLISHED.get(name, "")}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ipc", required=True, help="a copy of panda-planner-dev/ipc2020-domains")
    ap.add_argument("--repo", help="its git directory, to list problems the copy lacks")
    ap.add_argument("--others", type=int, default=0, help="also the first N problems of every other domain")
    ap.add_argument("--time-limit", type=float, default=60, help="CPU seconds per problem [60]")
    ap.add_argument("--panda", help="pandaPIparser, built from its public source, to verify plans too")
    ap.add_argument("--panda-limit", type=float, default=120,
                    help="wall seconds for pandaPIparser on one plan [120]; it grounds the problem, slow on big houses")
    ap.add_argument("--only", help="a regular expression over domain names")
    ap.add_argument("--rebuilt", help="a folder of Minecraft-Regular problems the copy lacks, rebuilt with the "
                                      "repository's own generator (run beside the others, marked rebuilt)")
    ap.add_argument("--player-limit", type=float, help="CPU seconds per Minecraft-Player problem [--time-limit]")
    ap.add_argument("-o", "--output", default=str(HERE / "htn.json"))
    args = ap.parse_args()
    base = Path(args.ipc) / "total-order"
    names = FIRST + sorted(d.name for d in base.iterdir() if d.is_dir() and d.name not in FIRST and args.others)
    if args.only:
        names = [n for n in names if re.search(args.only, n)]
    results = {}
    for name in names:
        folder = base / name
        todo = problems(folder) if name in FIRST else problems(folder)[:args.others]
        absent = missing(folder, Path(args.repo) if args.repo else None) if name in FIRST else []
        rebuilt = []
        if name == "Minecraft-Regular" and args.rebuilt:
            rebuilt = [p for p in sorted(Path(args.rebuilt).glob("p-*.hddl")) if p.name in absent]
            todo += [(str(folder / "domain.hddl"), str(p)) for p in rebuilt]
            absent = [a for a in absent if a not in {p.name for p in rebuilt}]
        limit = args.player_limit if name == "Minecraft-Player" and args.player_limit else args.time_limit
        rows = []
        for domain, problem in todo:
            row = run(domain, problem, limit, args.panda, args.panda_limit)
            row["rebuilt"] = Path(problem).parent != folder
            rows.append(row)
            print(f"{name:26} {row['problem']:34} {row['status']:11} cpu {row['cpu_seconds']:7.2f} s "
                  f"length {row.get('length') or '-':>5} verified {row.get('verified', '-')}"
                  f"{'' if 'panda' not in row else ' panda ' + str(row['panda'])}", flush=True)
        results[name] = {"rows": rows, "missing": absent, "rebuilt": [p.name for p in rebuilt], "time_limit_cpu_s": limit,
                         "summary": summary(name, rows, absent)}
    print()
    print(f"{'domain':26} {'run':>4} {'miss':>4} {'solved':>6} {'no plan':>7} {'verified':>8} {'panda':>5} "
          f"{'cpu med':>7} {'cpu max':>7} {'len max':>7}  published")
    for name, res in results.items():
        s = res["summary"]
        print(f"{name:26} {s['run']:4} {s['missing']:4} {s['solved']:6} {s['no_plan']:7} {s['verified']:8} "
              f"{'-' if s['panda_verified'] is None else s['panda_verified']:>5} {s['cpu_median'] or '-':>7} "
              f"{s['cpu_max'] or '-':>7} {s['length_max'] or '-':>7}  {s['published']}")
    out = {"machine": platform.platform(), "python": platform.python_version(), "time_limit_cpu_s": args.time_limit,
           "domains": results}
    from bcc.atomic import write_text
    write_text(args.output, json.dumps(out, indent=1) + "\n")
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
