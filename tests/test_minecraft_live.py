"""Against a real Minecraft server: flying-squid on 127.0.0.1 and mineflayer bots, driven
through the bridge. CI installs the Node packages (`npm ci` in minecraft/) first; the
tests skip, saying why, only where Node or those packages are missing."""
from __future__ import annotations

import math
import socket
import time

import pytest

from bcc.minecraft.bridge import BOT, MinecraftError
from bcc.minecraft.run import prepare, run
from bcc.minecraft.world import ORIGIN, WorldMap
from bcc.solvers import Budget, get_solver
from minecraft_harness import free_port, open_bridge, require_minecraft

require_minecraft()


@pytest.fixture
def bridge(tmp_path):
    yield from open_bridge(tmp_path)


def cell_block(obs, x, y, z, size):
    width, _, depth = size
    return obs["palette"][obs["cells"][y * width * depth + z * width + x]]


def test_bot_bridges_the_lava_and_stands_on_the_gold(bridge, model_of):
    m = model_of("bridge")
    world = WorldMap(m)
    prepare(bridge, world, free_port())
    result = run(m, bridge, solver="astar", budget=Budget(time_limit=30))
    assert result.reached_goal, result.message
    # an optimal plan, checked against a second solver (BFS), and every step as predicted
    bfs = get_solver("bfs")(m, Budget(time_limit=30))
    assert len(result.steps) == bfs.cost
    assert all(not s.differences for s in result.steps)
    assert len(result.plans) == 1
    # the world itself, not only the parsed state: the bot on the gold, the lava bridged
    obs = bridge.observe(BOT)
    x, y, z = (math.floor(c - o) for c, o in zip(obs["position"], ORIGIN))
    assert (x, y, z) == (5, 1, 5)
    assert cell_block(obs, 5, 0, 5, world.size) == "gold_block"
    lava_row = [cell_block(obs, 3, 0, zz, world.size) for zz in range(1, 6)]
    assert lava_row.count("stone") == 1 and lava_row.count("lava") == 4
    assert cell_block(obs, 1, 1, 5, world.size) == "air"          # the stone was mined


def test_run_replans_when_the_world_diverges(bridge, model_of):
    m = model_of("bridge")
    world = WorldMap(m)
    prepare(bridge, world, free_port())

    def push(step, b):
        if step == 3:   # someone turns the bot round behind the planner's back
            b.act(BOT, kind="look", yaw=180.0, pitch=0.0)

    lines = []
    result = run(m, bridge, budget=Budget(time_limit=30), after_step=push, log=lines.append)
    assert result.reached_goal, result.message
    assert len(result.plans) == 2 and result.plans[1]["from_step"] == 3
    assert any("the world changed after step 3" in line for line in lines)
    assert any("replan" in line for line in lines)


def test_a_killed_bridge_fails_fast(bridge):
    bridge.start(port=free_port())
    bridge.proc.kill()
    t0 = time.monotonic()
    with pytest.raises(MinecraftError, match="exited"):
        bridge.observe()
    assert time.monotonic() - t0 < 5


def test_a_busy_port_is_reported(bridge):
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen()
        with pytest.raises(MinecraftError, match="in use"):
            bridge.start(port=s.getsockname()[1])


def test_bot_builds_a_small_house_with_every_step_as_predicted(bridge, tmp_path):
    # `bcc generate house` 3x3x3 (mason domain): walls, a door, a roof, 31 planks of 47 carried
    from click.testing import CliRunner
    from bcc.cli import main
    from bcc.compiler.pipeline import compile_dungeon
    path = tmp_path / "house.yaml"
    assert CliRunner().invoke(main, ["generate", "house", "--width", "3", "--length", "3", "--height", "3",
                                     "-o", str(path)]).exit_code == 0
    m = compile_dungeon(path)
    world = WorldMap(m)
    prepare(bridge, world, free_port())
    result = run(m, bridge, solver="build", budget=Budget(time_limit=30))
    assert result.reached_goal, result.message
    assert all(not s.differences for s in result.steps), [s.differences for s in result.steps if s.differences]
    assert len(result.plans) == 1
    # the world itself: the blueprint's 31 planks and 5 air cells (door and room), and the
    # bot carries what is left: 47 - 31
    obs = bridge.observe(BOT)
    layers = ["###/#.#/#.#", "###/#.#/#.#", "###/#.#/###", "###/###/###"]
    for y, layer in enumerate(layers):
        for z, row in enumerate(layer.split("/")):
            for x, ch in enumerate(row):
                want = "oak_planks" if ch == "#" else "air"
                assert cell_block(obs, 2 + x, 1 + y, 2 + z, world.size) == want, (x, y, z)
    assert obs["inventory"] == {"oak_planks": 16}


def test_bot_builds_a_builder_wall_walking_jumping_and_breaking(bridge):
    from pathlib import Path
    from bcc.compiler.pipeline import compile_dungeon
    m = compile_dungeon(Path(__file__).parent / "builder" / "wall.yaml")
    world = WorldMap(m)
    prepare(bridge, world, free_port())
    result = run(m, bridge, solver="build", budget=Budget(time_limit=30))
    assert result.reached_goal, result.message
    assert all(not s.differences for s in result.steps)
    # MinePlanner's moves only: nothing hangs in the air, so no step carries a known difference
    assert not any("known difference" in n for s in result.steps for n in s.notes)
    obs = bridge.observe(BOT)
    assert [cell_block(obs, x, y, 2, world.size) for y in (1, 2) for x in (1, 2, 3)] == ["stone"] * 6
