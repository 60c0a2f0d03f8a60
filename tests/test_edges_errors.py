"""Bad input at the edges (grounding, PDDL, serve, batch, Minecraft): one line, the right
exit status, nothing written, never a traceback. Each test is a case a review found
answered badly (a wrong status, a foreign file appended to, a KeyError's bare name, a
port in use reported by uvicorn with exit 3); all run in-process, without Node or a
server."""
from __future__ import annotations

import json
import socket
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from bcc.cli import main
from bcc.errors import BccError

PDDL = Path(__file__).parent / "pddl"


def bcc(*args: str):
    return CliRunner().invoke(main, list(args))


def one_line_error(result, status: int = 2) -> str:
    """The single stderr line of a refused command (and no traceback)."""
    assert result.exit_code == status, (result.exit_code, result.output)
    assert result.exception is None or isinstance(result.exception, SystemExit), result.exception
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    return lines[0]


# ---- grounding and Minecraft: an empty command ----------------------------------------

def test_command_with_empty_text_is_bad_input_not_not_understood():
    assert one_line_error(bcc("command", "bridge", "   ")) == "the command is empty"


def test_minecraft_record_with_an_empty_command_fails_before_starting_a_server():
    # No Node is needed: the check comes before the bridge starts (it would say so otherwise).
    line = one_line_error(bcc("minecraft", "record", "bridge", ""))
    assert line.startswith("the command is empty")


@pytest.mark.parametrize("args", [
    ("minecraft", "run", "bridge", "--max-steps", "0"),
    ("minecraft", "run", "bridge", "--time-limit", "0"),
    ("minecraft", "run", "bridge", "--watch", "-1"),
    ("minecraft", "serve", "bridge", "--duration", "-5"),
    ("minecraft", "record", "bridge", "go", "--timeout", "0"),
])
def test_minecraft_options_out_of_range_are_usage_errors(args):
    result = bcc(*args)
    assert result.exit_code == 2 and "is not in the range" in result.output


def test_waiting_for_nobody_is_a_budget_not_bad_input():
    from bcc.minecraft.record import NobodyJoined, wait_for_player

    class EmptyWorld:
        def players(self):
            return []

        def next_event(self, timeout):
            return None
    with pytest.raises(NobodyJoined, match="nobody joined within 0.01 s"):
        wait_for_player(EmptyWorld(), None, 0.01)
    assert issubclass(NobodyJoined, BccError)


def test_world_and_demonstration_differences_share_one_comparison(model_of):
    from bcc.demonstration import changes
    from bcc.minecraft.world import difference
    m = model_of("bridge")
    down = m.apply(m.action_names.index("look_down"), m.initial)
    assert changes(m, m.initial, down) == [("agent.verticalDirection", 0, 1)]
    assert difference(m, m.initial, down) == ["agent.verticalDirection: predicted 0, observed 1"]
    assert changes(m, down, down) == []


# ---- batch: results files and sweep files -------------------------------------------

def test_batch_refuses_to_append_to_a_file_that_is_not_results(tmp_path):
    other = tmp_path / "bridge.yaml"
    other.write_text("dungeon: bridge\nsize: [5, 5]")  # no final newline: would be "torn"
    line = one_line_error(bcc("batch", "bridge", "--out", str(other)))
    assert line == f"{other}:1:1: not a bcc batch results file (JSON Lines, one row per run)"
    assert other.read_text() == "dungeon: bridge\nsize: [5, 5]"


@pytest.mark.parametrize("text, where", [
    ("garbage\nmore garbage\n", ":1:1: "),
    ('{"a": 1}\n[1, 2]\n', ":1:1: "),        # JSON, but no object is a row
    ('\n\n{"unfinished": ', ": "),            # only a torn line: no line to point at
])
def test_batch_report_refuses_a_file_that_is_not_results(tmp_path, text, where):
    path = tmp_path / "r.jsonl"
    path.write_text(text)
    line = one_line_error(bcc("batch", "report", str(path)))
    assert line == f"{path}{where}not a bcc batch results file (JSON Lines, one row per run)"


def test_batch_report_still_skips_a_stray_line_among_rows(tmp_path):
    out = tmp_path / "r.jsonl"
    assert bcc("batch", "grid", "--out", str(out)).exit_code == 0
    out.write_text(out.read_text() + "not a row\n")
    result = bcc("batch", "report", str(out), "--json")
    assert result.exit_code == 0 and json.loads(result.stdout)["rows"] == 1
    assert "ignored lines that are not rows: 2" in result.stderr


def test_a_limit_beside_budget_in_a_sweep_says_where_it_goes(tmp_path):
    sweep = tmp_path / "sweep.yaml"
    sweep.write_text("dungeons: [bridge]\ntime_limit: 30\n")
    line = one_line_error(bcc("batch", "--sweep", str(sweep), "--out", str(tmp_path / "r.jsonl")))
    assert line == f"{sweep}:2:1: time_limit goes under `budget:` in a sweep, e.g. budget: {{time_limit: ...}}"
    assert not (tmp_path / "r.jsonl").exists()


# ---- PDDL import: names the domain does not declare ----------------------------------

def test_a_problem_for_another_domain_names_the_unknown_name():
    line = one_line_error(bcc("import", "pddl", str(PDDL / "gripper-domain.pddl"),
                              str(PDDL / "blocksworld-4.pddl")))
    # line 8 is `  (:objects a b c d - block)`: `block` starts at column 23
    assert line == f"{PDDL / 'blocksworld-4.pddl'}:8:23: unknown type 'block'"


def test_an_undeclared_object_points_at_its_line_and_column(tmp_path):
    problem = tmp_path / "p.pddl"
    problem.write_text("(define (problem g) (:domain gripper-typed)\n"
                       "  (:objects rooma roomb - room ball1 - ball)\n"
                       "  (:init (at-robby rooma) (free left) (at ball1 rooma))\n"
                       "  (:goal (and (at ball9 roomb))))\n")
    line = one_line_error(bcc("import", "pddl", str(PDDL / "gripper-domain.pddl"), str(problem)))
    # line 4 is `  (:goal (and (at ball9 roomb))))`: 18 characters precede ball9, so column 19
    assert line == f"{problem}:4:19: unknown object or constant 'ball9'"


# ---- serve: the listening socket ----------------------------------------------------

def test_serve_on_a_port_in_use_is_one_line_and_exit_2():
    pytest.importorskip("uvicorn")
    pytest.importorskip("fastapi")
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        line = one_line_error(bcc("serve", "--port", str(port), "--json"))
    assert line == f"cannot listen on 127.0.0.1:{port}: Address already in use"


def test_serve_on_an_unknown_host_is_one_line_and_exit_2():
    pytest.importorskip("uvicorn")
    pytest.importorskip("fastapi")
    line = one_line_error(bcc("serve", "--host", "no-such-host.invalid", "--port", "8765"))
    assert line.startswith("cannot listen on no-such-host.invalid:8765: ")


def test_port_0_binds_a_free_port_and_the_url_names_it():
    from bcc.serve.listen import bind, url
    with bind("127.0.0.1", 0) as sock:
        port = sock.getsockname()[1]
        assert port > 0 and url(sock) == f"http://127.0.0.1:{port}/"


# ---- the fd solver: a budget is not bad input -----------------------------------------

@pytest.mark.parametrize("code, status", [(232, "budget"), (21, "budget"), (23, "budget"), (12, "no_solution"),
                                          (33, "error")])
def test_fast_downward_exit_codes_map_to_statuses(monkeypatch, tmp_path, code, status):
    """232 is what `bcc solve grid --solver fd --time-limit 0.001` got: the driver's exit
    status for a translator killed by SIGXCPU; it was reported as bad input (exit 2)."""
    import subprocess
    from bcc.solvers import fast_downward
    monkeypatch.setattr(fast_downward, "driver", lambda: tmp_path / "fast-downward.py")
    monkeypatch.setattr(fast_downward, "_bounded", lambda cmd, cwd, limit: subprocess.CompletedProcess(cmd, code, "", "log line"))
    assert fast_downward.run("d.pddl", "p.pddl", time_limit=1).status == status


# ---- a missing optional dependency says which extra to install -----------------------

@pytest.mark.parametrize("module, args, extra", [
    ("up_fast_downward", ["import", "pddl", str(PDDL / "gripper-domain.pddl"), str(PDDL / "gripper-3.pddl"),
                          "--solver", "fd"], ".[pddl]"),   # importing itself needs no extra
    ("uvicorn", ["serve", "--port", "0"], ".[serve]"),
    ("matplotlib", ["batch", "report", "{results}", "--plot", "{tmp}/p.png"], ".[plot]"),
])
def test_a_missing_extra_is_one_line_naming_it(monkeypatch, tmp_path, module, args, extra):
    results = tmp_path / "r.jsonl"
    results.write_text(json.dumps({"key": "k", "solver": "astar", "solved": False}) + "\n")
    for name in list(sys.modules):
        if name == module or name.startswith(module + "."):
            monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, module, None)   # `import module` now fails
    args = [a.format(results=results, tmp=tmp_path) for a in args]
    line = one_line_error(bcc(*args))
    assert f'pip install "{extra}"' in line


# ---- outputs that cannot be written are refused before the work, not after -------------

@pytest.mark.parametrize("args", [["play", "grid", "--record", "{missing}/demo.json"],
                                  ["solve", "grid", "-o", "{missing}/plan.txt"]])
def test_an_unwritable_output_is_refused_before_the_work(tmp_path, args):
    missing = tmp_path / "no" / "such" / "folder"
    args = [a.format(missing=missing) for a in args]
    result = CliRunner().invoke(main, args, input="llq\n")
    line = one_line_error(result)
    assert line.startswith(f"cannot write {missing}/") and "No such file or directory" in line
    assert "action(s)" not in result.stdout and "solved" not in result.stdout   # nothing ran
    assert not missing.exists()
