"""`bcc serve`: the JSON API against a real server on 127.0.0.1 (see serve_harness.py).

Solves run in worker processes, so these tests start the real thing: `python -m bcc
serve` with 2 workers, a 64 KB body limit and 256 MB per job.
"""
from __future__ import annotations

import json
import time

import pytest

pytest.importorskip("fastapi")
pytest.importorskip("uvicorn")

from click.testing import CliRunner  # noqa: E402

from bcc.cli import main  # noqa: E402
from bcc.compiler import compile_dungeon, shipped_dungeons  # noqa: E402
from bcc.compiler.dungeon import DUNGEONS_DIR  # noqa: E402
from bcc.errors import BccError  # noqa: E402
from bcc.generate import generate_maze  # noqa: E402
from bcc.simulate import replay  # noqa: E402
from bcc.solvers import Budget, get_solver  # noqa: E402
from serve_harness import running_server  # noqa: E402

BODY_LIMIT_KB = 64
BIG_MAZE = generate_maze(65, 65, stones=10, seed=1)  # BFS: far more than 5 MB, less than 256 in a minute


@pytest.fixture(scope="module")
def api():
    with running_server("--workers", "2", "--max-body", str(BODY_LIMIT_KB), "--job-memory", "256") as client:
        yield client


def bfs_cost(name: str, goal: str | None = None) -> int:
    """The optimal cost from a second solver run in this process, independent of the server."""
    result = get_solver("bfs")(compile_dungeon(name, goal=goal), Budget(time_limit=60))
    assert result.solved
    return result.cost


# ---- the API's description and the dungeons --------------------------------------
def test_openapi_describes_the_api(api):
    status, spec = api.get("/openapi.json")
    assert status == 200
    for path in ("/compile", "/solve", "/jobs/{job_id}", "/dungeons", "/dungeons/{name}", "/replay"):
        assert path in spec["paths"], path
    assert "delete" in spec["paths"]["/jobs/{job_id}"]
    job = spec["components"]["schemas"]["JobStatus"]["properties"]["status"]
    assert set(job["enum"]) == {"queued", "running", "done", "failed", "cancelled"}


def test_dungeons_lists_the_shipped_ones(api):
    status, body = api.get("/dungeons")
    assert status == 200
    assert [d["name"] for d in body["dungeons"]] == shipped_dungeons()
    status, bridge = api.get("/dungeons/bridge")
    assert status == 200
    assert bridge["yaml"] == (DUNGEONS_DIR / "bridge.yaml").read_text(encoding="utf-8")
    assert bridge["goal"] == "agentOnBlock(agent, gold)"
    for name in ("nope", "..%2F..%2Fpyproject", "bridge.yaml"):
        assert api.get(f"/dungeons/{name}")[0] == 404


# ---- compile ------------------------------------------------------------------------
def test_compile_returns_the_cli_report(api):
    cli = CliRunner().invoke(main, ["compile", "four_rooms", "--json", "--goal", "agentInRoom(agent, red)"],
                             catch_exceptions=False)
    status, report = api.post("/compile", {"dungeon": "four_rooms", "goal": "agentInRoom(agent, red)"})
    assert status == 200
    assert report == json.loads(cli.stdout)


BROKEN = """dungeon: broken
extends: bridge
goal: agentOnBlok(agent, gold)
"""


def test_malformed_dungeon_is_400_with_its_position(api, tmp_path):
    # The same text compiled from a file must fail at the same line and column.
    path = tmp_path / "broken.yaml"
    path.write_text(BROKEN)
    with pytest.raises(BccError) as expected:
        compile_dungeon(path)
    status, body = api.post("/compile", {"dungeon": BROKEN})
    assert status == 400
    assert (body["line"], body["column"]) == (expected.value.line, expected.value.col) == (3, 7)
    assert body["error"] == expected.value.message and "agentOnBlock" in body["error"]
    assert body["file"] == "<posted>"
    assert "/tmp" not in json.dumps(body) and "bcc-serve-" not in json.dumps(body)


def test_a_bad_goal_is_400_at_its_column(api):
    status, body = api.post("/compile", {"dungeon": "bridge",
                                         "goal": "agentOnBlock(agent, gold) and agentInRom(agent, red)"})
    assert status == 400 and body["file"] == "goal"
    # `agentInRom` starts after "agentOnBlock(agent, gold) and " (30 characters): column 31.
    assert (body["line"], body["column"]) == (1, 31) and "agentInRoom" in body["error"]


def test_invalid_yaml_is_400_with_its_position(api):
    status, body = api.post("/compile", {"dungeon": "dungeon: x\nlegend: [a, b\nmap: |\n"})
    assert status == 400
    assert body["error"].startswith("invalid YAML") and body["line"] == 3


def test_posted_text_may_reference_only_shipped_files(api):
    for text, line in (("dungeon: x\nextends: /etc/passwd\n", 2),
                       ("dungeon: x\nextends: ../dungeons/bridge.yaml\n", 2),
                       ("dungeon: x\nheight: 2\ndomain: /etc/hostname\n", 3)):
        status, body = api.post("/compile", {"dungeon": text})
        assert status == 400, text
        assert "must name a shipped" in body["error"] and body["line"] == line
    status, body = api.post("/compile", {"dungeon": "a: &x [1]\nb: *x\n"})
    assert status == 400 and "aliases" in body["error"] and body["line"] == 2
    status, body = api.post("/compile", {"dungeon": "/etc/passwd"})  # a name that is not shipped, never a path
    assert status == 400 and "no shipped dungeon" in body["error"]


def test_oversized_body_is_413(api):
    text = "dungeon: big\n" + "#" * (BODY_LIMIT_KB * 1000)
    status, body = api.post("/compile", {"dungeon": text})
    assert status == 413 and "limit" in body["error"]
    status, body = api.post("/solve", {"dungeon": text})
    assert status == 413
    assert api.get("/dungeons")[0] == 200


def test_oversized_chunked_body_is_413(api):
    """No Content-Length: the body is counted as it arrives. The server answers 413 and
    closes while the client is still sending, so the client's next write may fail (a reset,
    seen under load); the answer is read from what arrived either way."""
    import socket
    from urllib.parse import urlparse
    url = urlparse(api.base)
    chunks = (b'{"dungeon": "' if i == 0 else b"x" * 8192 for i in range(BODY_LIMIT_KB // 8 + 3))
    with socket.create_connection((url.hostname, url.port), timeout=30) as sock:
        try:
            sock.sendall(b"POST /compile HTTP/1.1\r\nHost: test\r\nContent-Type: application/json\r\n"
                         b"Transfer-Encoding: chunked\r\n\r\n")
            for chunk in chunks:
                sock.sendall(b"%x\r\n%s\r\n" % (len(chunk), chunk))
            sock.sendall(b"0\r\n\r\n")
        except (BrokenPipeError, ConnectionResetError):
            pass                                  # the server stopped reading: its answer is queued
        answer = b""
        try:
            while b"\r\n\r\n" not in answer or len(answer.partition(b"\r\n\r\n")[2]) < _length(answer):
                data = sock.recv(65536)
                if not data:
                    break
                answer += data
        except ConnectionResetError:
            pass
    head, _, body = answer.partition(b"\r\n\r\n")
    assert head.split(b" ")[1] == b"413", answer[:200]
    assert "limit" in json.loads(body[:_length(answer)])["error"]


def _length(answer: bytes) -> int:
    """The Content-Length of a raw HTTP answer's head (0 until the head is complete)."""
    for line in answer.partition(b"\r\n\r\n")[0].split(b"\r\n")[1:]:
        name, _, value = line.partition(b":")
        if name.strip().lower() == b"content-length":
            return int(value)
    return 0


# ---- solve jobs ---------------------------------------------------------------------
def test_solve_bridge_job(api):
    status, created = api.post("/solve", {"dungeon": "bridge", "solver": "astar", "time_limit": 10})
    assert status == 202 and created["status"] == "queued"
    job = api.wait_job(created["id"])
    assert job["status"] == "done", job
    result = job["result"]
    cli = json.loads(CliRunner().invoke(main, ["solve", "bridge", "--json"]).stdout)
    assert set(result) == set(cli)
    assert result["solved"] and result["cost"] == bfs_cost("bridge") == len(result["plan"])
    replayed = replay(compile_dungeon("bridge"), [(a, 1, 1) for a in result["plan"]])
    assert replayed.valid and replayed.reached_goal


def test_rmax_job_learns_the_bridge_and_reports_convergence(api):
    status, created = api.post("/solve", {"dungeon": "bridge", "solver": "rmax", "model": "oo", "episodes": 8,
                                          "seed": 0, "gamma": 0.99, "delta": 0.01, "known_after": 1})
    assert status == 202
    result = api.wait_job(created["id"])["result"]
    cli = json.loads(CliRunner().invoke(main, ["solve", "bridge", "--solver", "rmax", "--model", "oo", "--episodes", "8",
                                               "--seed", "0", "--json"]).stdout)
    assert result["solved"] and result["cost"] == bfs_cost("bridge")
    assert result["converged_episode"] == cli["converged_episode"] is not None
    assert [e["steps"] for e in result["episodes"]] == [e["steps"] for e in cli["episodes"]]
    for bad in ({"solver": "astar", "model": "oo"}, {"solver": "qlearning", "delta": 0.1},
                {"solver": "bfs", "gamma": 0.9}):
        status, body = api.post("/solve", {"dungeon": "bridge", **bad})
        assert status == 400 and "does not apply to" in body["error"], bad
    status, body = api.post("/solve", {"dungeon": "bridge", "solver": "rmax", "model": "deep"})
    assert status == 400 and body["error"] == "`model` must be one of tabular, oo, got 'deep'"
    status, body = api.post("/solve", {"dungeon": "bridge", "solver": "qlearning", "gamma": 1.5})
    assert status == 400 and body["error"] == "`gamma` must be a number >= 0 and <= 1, got 1.5"


def test_solve_posted_text_that_extends_a_shipped_dungeon(api):
    text = "dungeon: green_room\nextends: four_rooms\ngoal: agentInRoom(agent, green)\n"
    status, created = api.post("/solve", {"dungeon": text, "solver": "bfs"})
    assert status == 202
    job = api.wait_job(created["id"])
    assert job["status"] == "done" and job["result"]["dungeon"] == "green_room"
    assert job["result"]["cost"] == bfs_cost("four_rooms", "agentInRoom(agent, green)")


def test_bad_requests_are_400_before_any_job(api):
    assert api.post("/solve", {"dungeon": BROKEN})[0] == 400
    status, body = api.post("/solve", {"dungeon": "bridge", "solver": "astra"})
    assert status == 400 and "did you mean 'astar'" in body["error"]
    assert api.post("/solve", {"dungeon": "bridge", "solver": "bfs", "heuristic": "pdb"})[0] == 400
    assert api.post("/solve", {"dungeon": "bridge", "time_limit": -1})[0] == 422


def test_budget_exhaustion_is_a_clean_result(api):
    _, created = api.post("/solve", {"dungeon": "tough_maze", "solver": "bfs", "max_states": 50})
    job = api.wait_job(created["id"])
    assert job["status"] == "done"
    assert not job["result"]["solved"] and job["result"]["budget"] == "max_states"


def test_a_solve_over_its_memory_limit_fails_and_the_server_stays_up(api):
    status, created = api.post("/solve", {"dungeon": BIG_MAZE, "solver": "bfs", "time_limit": 60, "max_memory_mb": 5})
    assert status == 202
    job = api.wait_job(created["id"])
    # Stopped for memory either way: by the address-space cap (a failed job) or, when the
    # search grows slowly enough (compact states), by the solver's own memory budget.
    if job["status"] == "failed":
        assert "memory limit" in job["error"]
    else:
        assert job["status"] == "done" and job["result"]["budget"] == "max_memory", job
    assert api.get("/dungeons")[0] == 200
    _, again = api.post("/solve", {"dungeon": "bridge"})
    assert api.wait_job(again["id"])["status"] == "done"


def test_cancel_kills_a_running_job_and_the_queue_holds_the_rest(api):
    ids = [api.post("/solve", {"dungeon": BIG_MAZE, "solver": "bfs", "time_limit": 120})[1]["id"] for _ in range(3)]
    deadline = time.monotonic() + 30
    while api.get(f"/jobs/{ids[0]}")[1]["status"] != "running":
        assert time.monotonic() < deadline
        time.sleep(0.05)
    counts = api.get("/health")[1]["jobs"]
    assert counts["running"] <= 2 and counts["running"] + counts["queued"] >= 3
    assert api.get(f"/jobs/{ids[2]}")[1]["status"] == "queued"   # 2 workers: the third waits
    for job_id in ids:
        status, job = api.delete(f"/jobs/{job_id}")
        assert status == 200 and job["status"] == "cancelled"
    for job_id in ids:
        assert api.wait_job(job_id)["status"] == "cancelled"
    deadline = time.monotonic() + 10
    while api.get("/health")[1]["jobs"]["running"]:
        assert time.monotonic() < deadline
        time.sleep(0.05)
    status, body = api.delete("/jobs/no-such-job")
    assert status == 404
    _, done = api.post("/solve", {"dungeon": "grid"})
    api.wait_job(done["id"])
    assert api.delete(f"/jobs/{done['id']}")[0] == 409


# ---- drawing, stepping, demonstrations ------------------------------------------------
def test_replay_returns_one_frame_per_state(api):
    model = compile_dungeon("bridge")
    plan = get_solver("bfs")(model, Budget(time_limit=60)).plan
    status, body = api.post("/replay", {"dungeon": "bridge", "actions": plan})
    assert status == 200 and body["reached_goal"] and len(body["frames"]) == len(plan) + 1
    scene = body["scene"]
    assert (scene["width"], scene["depth"]) == (model.grid.width, model.grid.depth)
    # The map's 'M' column (x 1, z 5) holds a stone at the agent's level; 'G' (5, 5) is gold.
    assert [scene["blocks"][i] for i in scene["columns"][5][1]] == ["bedrock", "burlap_stone"]
    final = replay(model, [(a, 1, 1) for a in plan]).states[-1]
    last = body["frames"][-1]
    assert last["agent"] == list(model.agent_position(final)) and last["goal"]
    changed = {(x, z): [scene["blocks"][i] for i in col] for x, z, col in last["changed"]}
    assert changed == {(1, 5): ["bedrock"], (3, 5): ["burlap_stone"]}   # mined, and placed into the lava


def test_replay_stops_at_an_action_that_does_not_apply(api):
    status, body = api.post("/replay", {"dungeon": "bridge", "actions": ["rotate_left", "destroy_block"],
                                        "include_scene": False})
    assert status == 200 and body["scene"] is None
    assert body["steps"] == 1 and body["failed_step"] == 2 and len(body["frames"]) == 2
    assert "not applicable" in body["message"]
    status, body = api.post("/replay", {"dungeon": "bridge", "actions": ["fly"]})
    assert status == 400 and "unknown action" in body["error"]


def test_demonstration_from_played_actions(api):
    from bcc.demonstration import from_json
    actions = ["rotate_left", "rotate_left", "move_forward"]
    status, demo = api.post("/demonstration", {"dungeon": "bridge", "actions": actions, "command": "go south"})
    assert status == 200
    assert demo["format"] == "bcc-demonstration/1" and demo["dungeon"] == "bridge" and demo["actions"] == actions
    assert len(demo["states"]) == len(actions) + 1
    loaded = from_json(demo)   # states and actions must agree
    assert loaded.actions == actions and loaded.command == "go south"


def test_the_page_and_its_files_are_served(api):
    import urllib.request
    with urllib.request.urlopen(api.base + "/") as resp:
        html = resp.read().decode()
    assert '<canvas id="canvas"' in html and "/static/app.js" in html
    for asset in ("app.js", "draw.js", "style.css"):
        with urllib.request.urlopen(f"{api.base}/static/{asset}") as resp:
            assert resp.status == 200


# ---- pieces that need no server ------------------------------------------------------
def test_requests_name_shipped_dungeons_or_carry_text():
    from bcc.serve.posted import parse_ref
    assert parse_ref("bridge").name == "bridge"
    assert parse_ref("dungeon: x\n").text == "dungeon: x\n"
    for value in ("bridge.yaml", "../../etc/passwd", "dungeons/bridge"):
        with pytest.raises(BccError, match="no shipped dungeon"):
            parse_ref(value)


def test_errors_never_name_temporary_folders():
    import tempfile
    from bcc.serve.posted import public_error
    tmp = tempfile.gettempdir()
    exc = BccError(f"dungeon files extend each other in a cycle ({tmp}/bcc-serve-abc/posted.yaml)",
                   f"{tmp}/bcc-serve-abc/bridge", 4, 2)
    body = public_error(exc)
    assert body == {"error": "dungeon files extend each other in a cycle (<posted>)", "line": 4, "column": 2,
                    "file": "bridge"}
