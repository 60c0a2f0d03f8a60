"""bench/planning.py on the hand-written problems of tests/pddl (a manifest of its own):
it runs every configuration, checks costs across the optimal ones and writes its JSON."""
import json
from pathlib import Path

import pytest

from bench_harness import load_bench

ROOT = Path(__file__).resolve().parent.parent


@pytest.mark.slow
def test_the_planning_benchmark_reports_coverage_and_checks_costs(tmp_path):
    bench = load_bench("planning")
    from bcc.solvers.fast_downward import available
    manifest = tmp_path / "manifest.txt"
    manifest.write_text("# local problems\n"
                        "local/pddl road-domain.pddl road-1.pddl\n"
                        "local/pddl sokoban-domain.pddl sokoban-corridor.pddl\n"
                        "local/pddl gripper-domain.pddl missing.pddl\n")
    configs = ["bcc-astar", "bcc-blind"] + (["fd-blind"] if available() else [])
    out = tmp_path / "r.json"
    bench.main(["--ipc", str(ROOT / "tests"), "--manifest", str(manifest), "--configs", ",".join(configs),
                "--time-limit", "60", "--no-validate", "--no-dungeons", "--out", str(out),
                "--plot", str(tmp_path / "p.png")])
    report = json.loads(out.read_text())
    summary = report["ipc"]["summary"]
    assert summary["problems"] == 2                   # the missing file is skipped
    assert summary["coverage"]["bcc-astar"] == 2 and summary["wrong_costs"] == []
    costs = {p["name"]: p["runs"]["bcc-astar"]["cost"] for p in report["ipc"]["problems"]}
    assert costs == {"road-1": 2, "sokoban-corridor": 2}
    if available():
        assert all(p["cost_check"] == "ok" for p in report["ipc"]["problems"])


def test_the_second_validator_replays_plans_on_fast_downwards_translation(tmp_path):
    from bcc.solvers.fast_downward import available
    if not available():
        pytest.skip("Fast Downward is not installed (pip install '.[pddl]')")
    bench = load_bench("planning")
    domain, problem = str(ROOT / "tests" / "pddl" / "road-domain.pddl"), str(ROOT / "tests" / "pddl" / "road-1.pddl")
    cases = {"(drive a b)\n(drive b c)\n": "valid",                           # the optimum, by hand
             "(drive a c)\n": "valid",                                        # dearer, still a plan
             "(drive a b)\n": "the goal does not hold",
             "(drive b c)\n(drive a b)\n": "step 1 (drive b c) is not applicable",
             "(fly a c)\n": "not checked"}
    for text, verdict in cases.items():
        plan = tmp_path / "plan"
        plan.write_text(text)
        assert bench.sas_replay(domain, problem, str(plan)).startswith(verdict), text


def test_combining_runs_merges_configurations_and_says_where_each_came_from(tmp_path):
    # Fast Downward's rows from an earlier run (reused), bcc's from a fresh one: merged per
    # problem, and the JSON names each part's file, configurations and note.
    bench = load_bench("planning")

    def part(name, configs, cost, note=None):
        runs = {c: {"config": c, "seconds": 1.0, "cpu_seconds": 0.5, "solved": True, "status": "solved",
                    "cost": cost, "expanded": 3} for c in configs}
        data = {"time_limit": 120.0, "configs": configs,
                "ipc": {"problems": [{"name": "road/p1", "runs": runs}]}, **({"note": note} if note else {})}
        (tmp_path / name).write_text(json.dumps(data))
        return str(tmp_path / name)
    fd = part("fd.json", ["fd-blind", "fd-lmcut"], 2, note="Fast Downward 1.0.0, an earlier run")
    mine = part("bcc.json", ["bcc-astar"], 2)
    out = tmp_path / "all.json"
    bench.main(["--combine", fd, mine, "--note", "bcc rows fresh", "--out", str(out),
                "--plot", str(tmp_path / "p.png")])
    report = json.loads(out.read_text())
    assert report["note"] == "bcc rows fresh"
    assert report["combined_from"] == [
        {"file": "fd.json", "configs": ["fd-blind", "fd-lmcut"], "problems": 1,
         "note": "Fast Downward 1.0.0, an earlier run"},
        {"file": "bcc.json", "configs": ["bcc-astar"], "problems": 1}]
    (problem,) = report["ipc"]["problems"]
    assert sorted(problem["runs"]) == ["bcc-astar", "fd-blind", "fd-lmcut"] and problem["cost_check"] == "ok"
    assert report["ipc"]["summary"]["coverage"] == {"fd-blind": 1, "fd-lmcut": 1, "bcc-astar": 1}
