"""End-to-end: the `bcc` command on the shipped dungeons, through click and as a process."""
from __future__ import annotations

import json
import subprocess
import sys

import pytest
from click.testing import CliRunner

from bcc.cli import main

from conftest import FOUR_ROOMS_GOALS, REFERENCE


def run(*args, input=None):
    return CliRunner().invoke(main, list(args), input=input, catch_exceptions=False)


@pytest.mark.parametrize("name", [d for d in REFERENCE if d != "tough_maze"])
@pytest.mark.parametrize("solver", ["bfs", "astar"])
def test_solve_json_then_validate(name, solver, tmp_path):
    result = run("solve", name, "--solver", solver, "--json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["solved"] is True and data["cost"] == len(data["plan"])
    for key in ("plan", "cost", "expanded", "seconds", "generated", "peak_mb"):
        assert key in data
    plan = tmp_path / "plan.txt"
    plan.write_text("\n".join(data["plan"]) + "\n")
    check = run("validate", name, str(plan))
    assert check.exit_code == 0, check.output


@pytest.mark.parametrize("room", FOUR_ROOMS_GOALS)
def test_four_rooms_goal_override_matches_shipped_goal_files(room):
    by_flag = json.loads(run("solve", "four_rooms", "--goal", f"agentInRoom(agent, {room})", "--json").stdout)
    by_file = json.loads(run("solve", "four_rooms" if room == "blue" else f"four_rooms_{room}", "--json").stdout)
    assert by_flag["solved"] and by_flag["cost"] == by_file["cost"]


@pytest.mark.parametrize("bcc_style,python_style", [
    ("agentInRoom(agent, orange) or agentInRoom(agent, green)",
     "exists r in room: r.color in [orange, green] and agentInRoom(agent, r)"),
    ("not agentInRoom(agent, red) and not agentInRoom(agent, orange)",
     "forall r in room: r.color not in {red, orange} or not agentInRoom(agent, r)"),
])
def test_goals_written_python_style_mean_the_same(bcc_style, python_style):
    # The second form uses spellings people bring from Python (`in [...]`, a `:` before the
    # body); solved apart, BFS must find the same optimal cost for both.
    costs = []
    for goal in (bcc_style, python_style):
        result = run("solve", "four_rooms", "--solver", "bfs", "--goal", goal, "--json")
        assert result.exit_code == 0, result.output
        costs.append(json.loads(result.stdout)["cost"])
    assert costs[0] == costs[1] > 0


def test_solve_writes_plan_file_and_validate_reads_stdin(tmp_path):
    out = tmp_path / "plan.txt"
    assert run("solve", "bridge", "-o", str(out)).exit_code == 0
    lines = out.read_text().split()
    assert len(lines) == 13 and lines[-1] == "move_forward"
    piped = run("validate", "bridge", "-", input=out.read_text())
    assert piped.exit_code == 0 and "valid" in piped.stdout
    as_json = run("validate", "bridge", "-", input=json.dumps({"plan": lines}))
    assert as_json.exit_code == 0


def test_validate_says_which_step_fails_and_why(tmp_path):
    plan = tmp_path / "plan.txt"
    plan.write_text("move_forward\nmove_forward\nmove_forward\n")  # from (1,3) north: (1,2), (1,1), then the wall
    result = run("validate", "bridge", str(plan), "--json")
    assert result.exit_code == 1
    data = json.loads(result.stdout)
    assert data["valid"] is False and data["failed_step"] == 3
    assert "passable(tx, a.y, tz)" in data["message"]  # the wall at foot level


def test_validate_incomplete_plan_exits_1(tmp_path):
    plan = tmp_path / "plan.txt"
    plan.write_text("rotate_left\n")
    result = run("validate", "bridge", str(plan))
    assert result.exit_code == 1 and "does not hold" in result.stdout


def test_validate_lava_death(tmp_path):
    # From (1,3) facing north: turn east, walk (2,3), then onto the lava at (3,3): death.
    plan = tmp_path / "plan.txt"
    plan.write_text("rotate_right\nmove_forward\nmove_forward\n")
    result = run("validate", "bridge", str(plan))
    assert result.exit_code == 1 and "failure" in result.stdout


def test_validate_unknown_action_is_bad_input_with_position(tmp_path):
    plan = tmp_path / "plan.txt"
    plan.write_text("rotate_left\n  move_forwrd\n")
    result = run("validate", "bridge", str(plan))
    assert result.exit_code == 2
    assert result.stderr.strip() == f"{plan}:2:3: unknown action 'move_forwrd' (did you mean 'move_forward'?)"


def test_budget_exhaustion_exits_1_and_names_the_budget():
    result = run("solve", "tough_maze", "--solver", "bfs", "--max-states", "500", "--json")
    assert result.exit_code == 1
    data = json.loads(result.stdout)
    assert data["solved"] is False and data["budget"] == "max_states"
    assert "--max-states" in result.stderr


def test_tough_maze_astar_solves_optimally():
    result = run("solve", "tough_maze", "--json")
    assert result.exit_code == 0
    assert json.loads(result.stdout)["solved"] is True


def test_compile_report_and_atomic_output(tmp_path):
    out = tmp_path / "report.json"
    result = run("compile", "bridge", "--json", "-o", str(out))
    assert result.exit_code == 0
    report = json.loads(result.stdout)
    written = json.loads(out.read_text())  # the model itself (see model_json.py), report included
    assert written["format"] == "bcc-model/2" and written["report"]["grounded_actions"] == report["grounded_actions"]
    assert len(written["initial"]) == written["state_bytes"]
    assert [a["name"] for a in written["actions"]][:2] == ["move_forward", "rotate_left"]
    assert report["grounded_actions"] == 8
    assert set(report["action_schemas"]) == {"move_forward", "rotate_left", "rotate_right", "look_down",
                                             "look_ahead", "change_item", "destroy_block", "place_block"}
    assert {"agentOnBlock", "agentInRoom", "blockInRoom", "blockIsType", "agentHasBlock"} <= set(report["functions"])
    # 6 agent attributes change (x, z, facing, looking, slot, alive) + 9 slots x (type, count).
    assert report["state_variables"] == 6 + 18
    assert [p.name for p in tmp_path.iterdir()] == ["report.json"]  # no temp file left behind
    text = run("compile", "bridge")
    assert "grounded actions: 8" in text.stdout and "state variables: 24" in text.stdout


def test_show_draws_agent_and_path(tmp_path):
    plan = tmp_path / "plan.txt"
    plan.write_text("rotate_right\nmove_forward\n")
    result = run("show", "bridge", "--plan", str(plan), "--json")
    data = json.loads(result.stdout)
    assert data["rows"][3] == "#o>L..#"  # visited (1,3), now at (2,3) facing east
    plain = run("show", "grid")
    assert "#^..#" in plain.stdout


def test_list_and_solvers():
    data = json.loads(run("list", "--json").stdout)
    assert set(REFERENCE) <= {d["name"] for d in data["dungeons"]}
    assert data["domains"] == ["builder", "cleanup", "crafting", "farm", "mason", "mason_tasks", "minecraft"]
    assert {"bfs", "astar"} <= set(json.loads(run("solvers", "--json").stdout)["solvers"])


def test_unknown_solver_and_dungeon_are_bad_input():
    assert run("solve", "bridge", "--solver", "bfz").exit_code == 2
    result = run("solve", "brigde")
    assert result.exit_code == 2 and "did you mean 'bridge'" in result.stderr


def test_installed_command_runs_as_a_process(tmp_path):
    # The console script and `python -m bcc` both exist and behave the same.
    proc = subprocess.run([sys.executable, "-m", "bcc", "solve", "grid", "--json"], capture_output=True, text=True)
    assert proc.returncode == 0 and json.loads(proc.stdout)["cost"] == 7
    proc = subprocess.run(["bcc", "solve", "grid", "--goal", "agentOnBlock(agent, lava)"], capture_output=True, text=True)
    assert proc.returncode == 1 and "Traceback" not in proc.stderr


def test_generate_maze_then_solve(tmp_path):
    out = tmp_path / "maze.yaml"
    result = run("generate", "maze", "--width", "11", "--depth", "11", "--stones", "2", "--lava", "1",
                 "--seed", "4", "-o", str(out))
    assert result.exit_code == 0, result.output
    solved = json.loads(run("solve", str(out), "--json").stdout)
    assert solved["solved"] and "place_block" in solved["plan"]  # the river needs a bridge
    assert run("generate", "maze", "--width", "11", "--depth", "11", "--seed", "4").stdout == \
        run("generate", "maze", "--width", "11", "--depth", "11", "--seed", "4").stdout
    bad = run("generate", "maze", "--width", "10")
    assert bad.exit_code == 2 and "odd" in bad.stderr


def test_the_command_runs_numpy_on_one_blas_thread_unless_told_otherwise():
    # A BLAS thread per core made `bcc train` 4x slower on a busy machine (see cli/core.py).
    code = ("import os, sys\nimport bcc.cli\nimport numpy\n"
            "print(os.environ.get('OPENBLAS_NUM_THREADS'), os.environ.get('OMP_NUM_THREADS'))")
    env = {k: v for k, v in __import__("os").environ.items() if not k.endswith("_NUM_THREADS")}
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, env=env).stdout
    assert out.split() == ["1", "1"]
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                         env={**env, "OPENBLAS_NUM_THREADS": "4"}).stdout
    assert out.split() == ["4", "1"]


def test_a_domain_without_actions_compiles_and_solves(tmp_path):
    """Found while measuring: a domain with no actions crashed the compiler (exit 3,
    NameError from the generated start check: its constants table was made only when an
    action's code needed it), then the layer expander (a loop with no body), the learners
    and the PDDL export. Now nothing can move: a goal away from the start has no plan
    (exit 1), one that holds at the start the plan of no steps, for every solver."""
    import yaml
    from bcc.compiler.domain import DOMAINS_DIR
    domain = yaml.safe_load((DOMAINS_DIR / "minecraft.yaml").read_text())
    domain.update(domain="still", actions={})
    (tmp_path / "still.yaml").write_text(yaml.safe_dump(domain, sort_keys=False))
    dungeon = ("dungeon: standstill\ndomain: still.yaml\nheight: 3\n"
               "legend:\n  '#': [bedrock, bedrock, bedrock]\n  '.': [bedrock]\n  S: [bedrock]\n  G: [gold]\n"
               "map: |\n  #####\n  #S.G#\n  #####\nagent: {start: S}\ngoal: agentOnBlock(agent, gold)\n")
    path = tmp_path / "standstill.yaml"
    path.write_text(dungeon)
    compiled = run("compile", str(path), "--json")
    assert compiled.exit_code == 0, compiled.output
    assert json.loads(compiled.stdout)["grounded_actions"] == 0
    for solver in ("bfs", "astar", "gbfs", "idastar", "rmax", "qlearning"):
        stuck = run("solve", str(path), "--solver", solver, "--json")
        assert stuck.exit_code == 1, stuck.output
        assert json.loads(stuck.stdout)["status"] == "no_solution"
        there = run("solve", str(path), "--solver", solver, "--goal", "not agentOnBlock(agent, gold)", "--json")
        assert there.exit_code == 0, there.output
        assert json.loads(there.stdout)["plan"] == []
    exported = run("export", "pddl", str(path), "-o", str(tmp_path / "pddl"), "--json")
    assert exported.exit_code == 0, exported.output
