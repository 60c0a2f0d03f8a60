"""`bcc import mineplanner`: a MinePlanner task as a builder dungeon, and its plan back.

tests/mineplanner/tiny_*.pddl is a small task in MinePlanner's form (six of its actions,
a checkgoal asking for a stone at x = 4 and one cobblestone). Its optimal cost, 5, by hand: the
agent has no stone, so it breaks the one in front (1); it must stand at x = 3 to place
at x = 4 (3 moves east, the second onto the cobblestone, picking it up); then it places (1)."""
from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

from bcc.mineplanner import import_task, task_plan
from bcc.pddl_io.replay import replay

HERE = Path(__file__).parent / "mineplanner"
DOMAIN, PROBLEM = str(HERE / "tiny_domain.pddl"), str(HERE / "tiny_problem.pddl")


def bcc(*args, stdin=None):
    return subprocess.run([sys.executable, "-m", "bcc", *args], capture_output=True, text=True, input=stdin)


def test_import_solve_and_map_back_through_the_cli(tmp_path):
    dungeon = tmp_path / "tiny.yaml"
    out = bcc("import", "mineplanner", DOMAIN, PROBLEM, "-o", str(dungeon), "--json")
    assert out.returncode == 0, out.stderr
    summary = json.loads(out.stdout)
    assert summary["size"] == {"width": 6, "depth": 1, "height": 5}
    assert summary["goal"] == "block[4, 1, 0].kind == stone and cobblestone.count >= 1"
    solved = bcc("solve", str(dungeon), "--solver", "bfs")
    assert solved.returncode == 0, solved.stderr
    plan = solved.stdout.splitlines()
    assert len(plan) == 5
    (tmp_path / "plan.txt").write_text(solved.stdout)
    back = bcc("import", "mineplanner", DOMAIN, PROBLEM, "--plan", str(tmp_path / "plan.txt"))
    assert back.returncode == 0, back.stderr
    actions = back.stdout.splitlines()
    assert actions[-1] == "(checkgoal steve)" and len(actions) == 6
    assert "_and_pickup-cobblestone-east steve cobblestone0 " in back.stdout
    assert replay(DOMAIN, PROBLEM, actions) == (True, "valid: the goal holds after step 6")


def test_the_replay_validator_refuses_a_wrong_plan():
    imported = import_task(DOMAIN, PROBLEM)
    plan = ["break_east", "move_east", "move_east", "move_east", "place_east(agent, stone)"]
    actions = task_plan(imported, plan)
    ok, why = replay(DOMAIN, PROBLEM, actions[1:])   # without the break, the first move is blocked
    assert not ok and why.startswith("step 1: the precondition of (move-east")
    ok, why = replay(DOMAIN, PROBLEM, actions[:2] + actions[-1:])
    assert not ok and why == "step 3: the precondition of (checkgoal steve) does not hold"


def test_the_replay_validator_agrees_with_pddl_pyvalidator(tmp_path):
    pyval = pytest.importorskip("pyval")
    # pyval, like Fast Downward, wants the problem objects that checkgoal names declared as
    # the domain's constants: move exactly those (and nothing else) for it.
    domain, problem = Path(DOMAIN).read_text(), Path(PROBLEM).read_text()
    goal = domain[domain.index("(:action checkgoal"):]
    names = sorted(set(re.findall(r"\b(position\d+|count\d+)\b", goal)))
    constants = " ".join(n for n in names if n.startswith("position")) + " - position " + \
        " ".join(n for n in names if n.startswith("count")) + " - count"
    domain = domain.replace("(:predicates", f"(:constants {constants})\n(:predicates", 1)
    for n in names:
        problem = re.sub(rf"(\(:objects.*?)\b{n}\b ", r"\1", problem, count=1, flags=re.S)
    (tmp_path / "d.pddl").write_text(domain)
    (tmp_path / "p.pddl").write_text(problem)
    actions = task_plan(import_task(DOMAIN, PROBLEM), ["break_east", "move_east", "move_east", "move_east",
                                                       "place_east(agent, stone)"])
    for plan in (actions, actions[1:]):
        (tmp_path / "plan").write_text("\n".join(plan) + "\n")
        theirs = pyval.PDDLValidator().validate(str(tmp_path / "d.pddl"), str(tmp_path / "p.pddl"),
                                                str(tmp_path / "plan"))
        assert theirs.is_valid == replay(str(tmp_path / "d.pddl"), str(tmp_path / "p.pddl"), plan)[0]


@pytest.mark.parametrize("old,new,message", [
    ("(:objects", "(:objectz", "tiny_problem.pddl:3:1: no `(:objects ...)` section"),
    ("(at-x cobblestone0 position2)", "(at-x cobblestone0 nowhere)", "`(at-x OBJECT POSITION)` names no position"),
    ("(are-seq position2 position3)", "", "the position objects do not form one `are-seq` chain (2 starts)"),
])
def test_bad_problems_are_one_positioned_line(tmp_path, old, new, message):
    bad = tmp_path / "tiny_problem.pddl"
    bad.write_text(Path(PROBLEM).read_text().replace(old, new, 1))
    out = bcc("import", "mineplanner", DOMAIN, str(bad))
    assert out.returncode == 2 and len(out.stderr.strip().splitlines()) == 1, out.stderr
    assert message in out.stderr and re.match(rf"{re.escape(str(bad))}:\d+:\d+: ", out.stderr), out.stderr


def test_an_unsupported_goal_is_refused_at_its_place(tmp_path):
    bad = tmp_path / "tiny_domain.pddl"
    bad.write_text(Path(DOMAIN).read_text().replace("(or (agent-has-n-cobblestone", "(or (goal-achieved ?ag) (agent-has-n-cobblestone"))
    out = bcc("import", "mineplanner", str(bad), PROBLEM)
    assert out.returncode == 2
    assert re.match(rf"{re.escape(str(bad))}:\d+:\d+: `goal-achieved` is not supported in checkgoal", out.stderr), \
        out.stderr


def test_a_plan_step_that_does_not_apply_is_named(tmp_path):
    (tmp_path / "plan.txt").write_text("move_east\n")
    out = bcc("import", "mineplanner", DOMAIN, PROBLEM, "--plan", str(tmp_path / "plan.txt"))
    assert out.returncode == 2 and "step 1" in out.stderr
