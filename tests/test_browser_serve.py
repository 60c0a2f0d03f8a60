"""The web page in a real browser: Debian's chromium, headless, driven by playwright.

Loads the page from a real `bcc serve`, solves the bridge, checks the drawn plan (the
plan list against BFS, the agent's drawn cell and the cells' colours on the canvas),
plays a few moves with the keyboard, saves a demonstration and shows an error. A
screenshot of the solved bridge is kept in test-artifacts/.
"""
from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

pytest.importorskip("fastapi", reason="bcc serve needs the serve extra: pip install '.[serve]'")
sync_api = pytest.importorskip("playwright.sync_api", reason="browser tests need playwright: pip install playwright")
CHROMIUM = shutil.which("chromium") or ("/usr/bin/chromium" if Path("/usr/bin/chromium").exists() else None)
if CHROMIUM is None:
    pytest.skip("browser tests need Debian's chromium: apt-get install -y chromium", allow_module_level=True)

from bcc.compiler import compile_dungeon  # noqa: E402
from bcc.simulate import replay  # noqa: E402
from bcc.solvers import Budget, get_solver  # noqa: E402
from serve_harness import running_server  # noqa: E402

ARTIFACTS = Path(__file__).resolve().parent.parent / "test-artifacts"
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync"]
# Colours the page draws (serve/static/draw.js): floor-level blocks and the agent.
COLORS = {"bedrock": (0x9a, 0x9a, 0x9a), "lava": (0xff, 0x5a, 0x1f), "burlap_stone": (0xb0, 0x8a, 0x5a),
          "gold": (0xff, 0xd2, 0x1f), "agent": (0x1f, 0x6f, 0xff)}


@pytest.fixture(scope="module")
def page():
    with running_server("--workers", "1") as client, sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        pg = browser.new_page(viewport={"width": 1400, "height": 950}, accept_downloads=True)
        errors = []
        pg.on("pageerror", lambda exc: errors.append(str(exc)))
        pg.goto(client.base + "/?dungeon=bridge")
        pg.wait_for_selector("body[data-ready='1']", timeout=30_000)
        pg.errors = errors
        yield pg
        browser.close()
    assert not errors, errors


def pixel(pg, x: int, z: int, fx: float = 0.25, fz: float = 0.75) -> tuple:
    """The colour drawn at a point inside cell (x, z), away from its border and path dot."""
    return tuple(pg.evaluate("""([x, z, fx, fz]) => {
        const c = document.getElementById('canvas'), s = Number(c.dataset.cell);
        return Array.from(c.getContext('2d').getImageData(Math.floor((x + fx) * s), Math.floor((z + fz) * s), 1, 1).data.slice(0, 3));
    }""", [x, z, fx, fz]))


def test_solve_the_bridge_and_watch_the_plan(page):
    model = compile_dungeon("bridge")
    assert pixel(page, 3, 5) == COLORS["lava"] and pixel(page, 5, 5) == COLORS["gold"]
    page.select_option("#solver", "astar")
    page.click("#solve-btn")
    page.wait_for_function("document.getElementById('status').textContent.startsWith('solved')", timeout=30_000)
    plan = page.locator("#plan li").all_inner_texts()
    optimal = get_solver("bfs")(model, Budget(time_limit=60))
    assert len(plan) == optimal.cost          # a second solver, in this process
    result = replay(model, [(a, 1, 1) for a in plan])
    assert result.reached_goal
    page.click("#last-btn")
    final = model.agent_position(result.states[-1])
    assert page.get_attribute("#canvas", "data-agent") == ",".join(map(str, final))
    assert "goal reached" in page.inner_text("#step-label")
    # The agent is drawn on the gold; the stone it mined is gone, and it lies in the lava.
    # (Behind the agent's arrow, which points east at the end: sample its west half.)
    assert pixel(page, final[0], final[2], 0.3, 0.5) == COLORS["agent"]
    assert pixel(page, 1, 5) == COLORS["bedrock"]
    assert pixel(page, 3, 5) == COLORS["burlap_stone"]
    ARTIFACTS.mkdir(exist_ok=True)
    page.screenshot(path=str(ARTIFACTS / "browser-bridge-solved.png"))
    page.click("#first-btn")
    assert page.get_attribute("#canvas", "data-agent") == ",".join(map(str, model.agent_position(model.initial)))
    assert pixel(page, 3, 5) == COLORS["lava"]


def test_play_with_the_keyboard_and_save_a_demonstration(page):
    model = compile_dungeon("bridge")
    page.click("#play-toggle")
    page.wait_for_function("document.getElementById('status').textContent.startsWith('playing')")
    played = ["rotate_left", "rotate_left", "move_forward"]
    for key in ("ArrowLeft", "ArrowLeft", "ArrowUp"):
        page.keyboard.press(key)
    page.wait_for_function("window.bccView.actions.length === 3")
    expected = replay(model, [(a, 1, 1) for a in played]).states[-1]
    assert page.get_attribute("#canvas", "data-agent") == ",".join(map(str, model.agent_position(expected)))
    page.keyboard.press("x")   # destroy_block needs the agent to look down: refused, nothing moves
    page.wait_for_function("document.getElementById('status').textContent.includes('not applicable')")
    assert page.evaluate("window.bccView.actions") == played
    with page.expect_download() as download:
        page.click("#save-demo-btn")
    demo = json.loads(Path(download.value.path()).read_text())
    assert demo["format"] == "bcc-demonstration/1" and demo["dungeon"] == "bridge"
    assert demo["actions"] == played and len(demo["states"]) == 4


def test_a_malformed_dungeon_shows_its_line(page):
    page.click("#play-toggle") if page.evaluate("window.bccView.playing") else None
    page.fill("#yaml", "dungeon: broken\nextends: bridge\ngoal: agentOnBlok(agent, gold)\n")
    page.click("#draw-btn")
    page.wait_for_selector("#error:not([hidden])")
    text = page.inner_text("#error")
    assert text.startswith("line 3, column 7:") and "agentOnBlock" in text


def test_a_pasted_dungeon_is_named_in_the_dropdown_and_a_failed_solve_looks_failed(page):
    page.click("#play-toggle") if page.evaluate("window.bccView.playing") else None
    page.fill("#yaml", "dungeon: mine\nextends: bridge\n")
    page.click("#draw-btn")
    page.wait_for_function("document.getElementById('status').textContent.startsWith('mine: drawn')")
    assert page.input_value("#dungeon-select") == ""           # not "bridge" any more
    assert "your dungeon" in page.inner_text("#dungeon-select option[data-own]")
    page.fill("#max-states", "1")                               # a solve that must run out of states
    page.click("#solve-btn")
    page.wait_for_function("document.getElementById('status').textContent.startsWith('not solved')")
    assert page.get_attribute("#status", "data-kind") == "bad"
    page.fill("#max-states", "")
