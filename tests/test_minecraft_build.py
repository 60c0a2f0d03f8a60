"""The Minecraft bridge for building models, without a server: the inventory read from the
model's actions, the generic controller (moves.py), the parser for positions and stocks,
the known differences of the real game, and the closed loop against a fake world that
keeps the game's rules as the bridge does (a block is placed only against a solid face
and never into the player; the bot walks one cell onto a block, jumps up one, walks off
an edge down one; anything else needs the bot held without physics)."""
from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from bcc.cli import main
from bcc.compiler.pipeline import compile_dungeon
from bcc.errors import BccError
from bcc.minecraft.differences import fall_depth, known
from bcc.minecraft.inventory import derive
from bcc.minecraft.moves import controls
from bcc.minecraft.run import prepare, run
from bcc.minecraft.world import ORIGIN, WorldMap, check_playable

TESTS = Path(__file__).parent
WALL = TESTS / "builder" / "wall.yaml"


@pytest.fixture(scope="module")
def house(tmp_path_factory):
    path = tmp_path_factory.mktemp("house") / "house.yaml"
    r = CliRunner().invoke(main, ["generate", "house", "--width", "3", "--length", "3", "--height", "3",
                                  "-o", str(path)])
    assert r.exit_code == 0, r.output
    return compile_dungeon(path)


class FakeWorld:
    """The bridge's protocol over a dict of blocks, with the game's rules the bridge keeps."""

    def __init__(self):
        self.blocks, self.position, self.inventory = {}, None, {}
        self.size = self.origin = None
        self.physics, self.hovers, self.kinds = True, 0, []

    # the operations run.prepare and run.run use
    def start(self, port):
        return {}

    def build(self, world, state=None):
        self.origin, self.size = list(world.origin), list(world.size)
        self.blocks = {tuple(world.world(x, y, z)): name for x, y, z, name in world.blocks(state)}

    def spawn_bot(self, player):
        return {}

    def setup(self, player, pose, hotbar, inventory=None):
        self.position = list(pose["position"])
        self.inventory = {name: n for name, n in inventory or ()}

    def observe(self, player=None, blocks=True):
        palette, cells = [], []
        ox, oy, oz = self.origin
        w, h, d = self.size
        for y in range(h):
            for z in range(d):
                for x in range(w):
                    name = self.blocks.get((ox + x, oy + y, oz + z), "air")
                    if name not in palette:
                        palette.append(name)
                    cells.append(palette.index(name))
        return {"position": list(self.position), "yaw": 0.0, "pitch": 0.0, "onGround": True, "selected": 0,
                "hotbar": [None] * 9, "inventory": {k: n for k, n in self.inventory.items() if n},
                "palette": palette, "cells": cells}

    def _feet(self):
        return tuple(int(c // 1) for c in self.position)

    def _solid(self, cell):
        return self.blocks.get(tuple(cell), "air") not in ("air", "water", "lava")

    def act(self, player, kind, **a):
        self.kinds.append(kind)
        fx, fy, fz = self._feet()
        if kind == "walk":
            tx, ty, tz = (int(c // 1) for c in a["target"])
            assert abs(tx - fx) + abs(tz - fz) == 1 and abs(ty - fy) <= 1, "a walk is one cell"
            assert self._solid((fx, fy - 1, fz)) and self._solid((tx, ty - 1, tz)), "a walk is on blocks"
            assert (ty == fy + 1) == a["jump"], "a jump exactly when going up"
            assert not self._solid((tx, ty, tz)) and not self._solid((tx, ty + 1, tz))
            assert {0.0: (0, 1), 90.0: (-1, 0), 180.0: (0, -1), 270.0: (1, 0)}[a["yaw"]] == (tx - fx, tz - fz)
            self.position = list(a["target"])
        elif kind == "hover":
            self.hovers += 1
            self.position = list(a["target"])
        elif kind == "fall":
            tx, ty, tz = (int(c // 1) for c in a["target"])
            assert (tx, tz) == (fx, fz) and ty < fy and self._solid((tx, ty - 1, tz))
            assert all(not self._solid((fx, y, fz)) for y in range(ty, fy))
            self.position = list(a["target"])
        elif kind == "dig":
            cell = tuple(a["block"])
            name = self.blocks.pop(cell)
            self.inventory[name] = self.inventory.get(name, 0) + 1
        elif kind in ("place", "pillar"):
            if kind == "pillar":
                self.position = list(a["target"])
            ref, face, at = tuple(a["reference"]), a["face"], tuple(a["at"])
            assert self._solid(ref), "a block is placed against a solid one"
            assert tuple(r + f for r, f in zip(ref, face)) == at and sum(map(abs, face)) == 1
            assert self.blocks.get(at, "air") == "air" and at != self._feet(), "not into a block or the player"
            assert self.inventory.get(a["item"], 0) > 0, f"the bot carries no {a['item']}"
            self.inventory[a["item"]] -= 1
            self.blocks[at] = a["block"]
        else:
            raise AssertionError(kind)
        if "hover" in a:
            self.physics = not a["hover"]
        return {}


def test_the_inventory_is_read_from_the_actions(house):
    # the generator gives the 3x3x3 house 47 planks in one stock: an open stack and full
    # stacks of 64 (mason.yaml's open_stack sets the open one to 64 and takes a full one)
    inv = derive(house)
    assert [(h.label, h.unit) for h in inv.holdings["planks"]] == [("planks_stock.count", 1),
                                                                   ("planks_stock.full", 64)]
    assert inv.totals(house.initial) == {"planks": 47}
    wall = compile_dungeon(WALL)
    assert derive(wall).totals(wall.initial) == {"stone": 6, "dirt": 0}


def test_reading_totals_back_keeps_the_predicted_split(house):
    inv = derive(house)
    count, full = inv.holdings["planks"]
    hint = bytearray(house.dense(house.initial))
    hint[count.index], hint[full.index] = 0, 1            # 64 carried as one full stack
    dense = bytearray(hint)
    assert inv.assign(dense, {"planks": 64}, bytes(hint)) == []
    assert (dense[count.index], dense[full.index]) == (0, 1)
    assert inv.assign(dense, {"planks": 130}, bytes(hint)) == []  # no hint of that total: fill the big unit
    assert (dense[count.index], dense[full.index]) == (2, 2)


def test_which_models_the_world_shows(house, tmp_path):
    assert check_playable(compile_dungeon("bridge")) == "poses"
    assert check_playable(house) == "positions"
    assert check_playable(compile_dungeon(WALL)) == "positions"
    with pytest.raises(BccError, match="daisy.fed, which a Minecraft world cannot show"):
        check_playable(compile_dungeon("barnyard"))
    # an item lying on the ground is state the world cannot show (it would be an entity)
    text = WALL.read_text().replace("stock:\n", "items:\n  - {name: a_log, kind: log, at: [4, 1, 0]}\nstock:\n  - {name: logs, kind: log, count: 0}\n")
    (tmp_path / "items.yaml").write_text(text)
    with pytest.raises(BccError, match=r"its state has a_log.present"):
        check_playable(compile_dungeon(tmp_path / "items.yaml"))


def states_of(model, plan):
    states = [model.initial]
    for a in plan:
        states.append(model.apply(model.action_index(a), states[-1]))
        assert states[-1] is not None, a
    return states


def test_controls_follow_what_the_model_changes():
    m = compile_dungeon(WALL)
    w = WorldMap(m)
    # from the start (0, 1, 0), walled in but for the dirt east under a low ceiling: break
    # it, walk east through its cell, south to (1, 1, 1); place stone south at feet level
    # on the floor; jump south onto it; drop north again
    plan = ["break_east", "move_east", "move_south", "place_south(agent, stones)", "jump_south", "drop_north"]
    s = states_of(m, plan)
    steps = [controls(w, a, b) for a, b in zip(s, s[1:])]
    ox, oy, oz = ORIGIN
    assert steps[0] == [{"kind": "dig", "block": [ox + 1, oy + 1, oz], "instant": True, "hover": False}]
    assert steps[1] == [{"kind": "walk", "target": [ox + 1.5, oy + 1, oz + 0.5], "yaw": 270.0, "pitch": 0.0,
                         "jump": False, "hover": False}]
    assert steps[2][0]["yaw"] == 0.0
    place = steps[3][0]
    assert (place["kind"], place["at"], place["reference"], place["face"], place["item"]) == \
        ("place", [ox + 1, oy + 1, oz + 2], [ox + 1, oy, oz + 2], [0, 1, 0], "stone")
    assert steps[4][0]["kind"] == "walk" and steps[4][0]["jump"] and steps[4][0]["target"][1] == oy + 2
    assert steps[5][0]["kind"] == "walk" and not steps[5][0]["jump"] and steps[5][0]["target"][1] == oy + 1


def test_mason_moves_climb_hang_and_come_down(house):
    w = WorldMap(house)
    # on the floor at (0, 1, 0): climb (a pillar), step off east hanging (climb_down), slide
    # to the floor, climb again and come down by breaking the block under the feet
    s = states_of(house, ["climb", "climb_down_east"])
    up, off = controls(w, s[0], s[1]), controls(w, s[1], s[2])
    assert [r["kind"] for r in up] == ["pillar"] and up[0]["at"] == w.world(0, 1, 0) and up[0]["face"] == [0, 1, 0]
    # onto the floor one level down: the game's own drop, walked
    assert off == [{"kind": "walk", "target": [1.5, ORIGIN[1] + 1, 0.5], "yaw": 270.0, "pitch": 0.0,
                    "jump": False, "hover": False}]
    assert fall_depth(w, s[2]) == 0 and fall_depth(w, s[1]) == 0
    s = states_of(house, ["climb", "climb", "climb_down_east"])
    assert fall_depth(w, s[3]) == 1
    notes, refusal = known(w, s[3])
    assert refusal is None and "would fall 1 level" in notes[0]
    assert controls(w, s[2], s[3]) == [{"kind": "hover", "target": [1.5, ORIGIN[1] + 2, 0.5], "hover": True}]
    slid = house.apply(house.action_index("slide_west"), s[3])
    assert controls(w, s[3], slid) == [{"kind": "fall", "target": [1.5, ORIGIN[1] + 1, 0.5], "hover": False}]
    down = states_of(house, ["climb", "descend"])
    assert [r["kind"] for r in controls(w, down[1], down[2])] == ["dig", "fall"]
    # repacking what is carried changes nothing the world shows
    empty = bytearray(house.dense(house.initial))
    count, full = derive(house).holdings["planks"]
    empty[count.index], empty[full.index] = 0, 1
    packed = house.compact(bytes(empty))
    assert controls(w, packed, house.apply(house.action_index("open_stack"), packed)) == []


def test_flowing_water_is_a_known_difference(tmp_path):
    text = WALL.read_text().replace('"d": [bedrock, dirt, air, bedrock]', '"d": [bedrock]\n  "w": [bedrock, water]').replace(
        "  .....\n  .....\n", "  .w...\n  .....\n", 1)
    (tmp_path / "water.yaml").write_text(text)
    m = compile_dungeon(tmp_path / "water.yaml")
    w = WorldMap(m)
    notes, refusal = known(w, m.initial)
    # the water at (1, 1, 2) flows into its four empty neighbours at its level
    assert sorted(n for n in notes if "water" in n) == sorted(
        f"known difference: the water at (1, 1, 2) would flow into {c} in Minecraft (this server, like the "
        "model, has no flowing water)" for c in [(2, 1, 2), (0, 1, 2), (1, 1, 3), (1, 1, 1)])
    assert refusal is None
    beside = states_of(m, ["move_east", "move_south"])[-1]       # (1, 1, 1): where the water flows
    assert "carry it" in known(w, beside)[1]


@pytest.mark.parametrize("which", ["house", "wall"])
def test_the_closed_loop_builds_in_a_fake_world(which, house):
    model = house if which == "house" else compile_dungeon(WALL)
    fake = FakeWorld()
    prepare(fake, WorldMap(model), port=0)
    result = run(model, fake, solver="build")
    assert result.reached_goal, result.message
    assert result.steps and all(not s.differences for s in result.steps)
    assert len(result.plans) == 1
    hanging = [s for s in result.steps if any("known difference: the agent stands" in n for n in s.notes)]
    moved_in_air = sum(1 for k in fake.kinds if k == "hover")
    assert fake.hovers == moved_in_air
    if which == "house":
        assert hanging and fake.hovers        # the mason's plan steps off into the air
        # the world holds the blueprint: every goal cell of the house
        m = model
        for (x, y, z), v in house_cells(m):
            assert fake.blocks.get(tuple(WorldMap(m).world(x, y, z)), "air") == ("oak_planks" if v else "air")
    else:
        assert not hanging and not fake.hovers  # the builder's moves are all walked


def house_cells(m):
    """The 3x3x3 house's blueprint from the generator's layers, anchor (2, 1, 2): walls on
    three levels (a door of two cells on the south side), a full roof on the fourth."""
    out = []
    for y in range(4):
        for z in range(3):
            for x in range(3):
                wall = x in (0, 2) or z in (0, 2)
                door = x == 1 and z == 2 and y < 2
                full = y == 3
                out.append(((2 + x, 1 + y, 2 + z), full or (wall and not door)))
    return out


def test_the_picture_draws_the_visible_faces_and_the_player():
    from bcc.minecraft.picture import svg
    # a 1 x 2 x 1 box: two planks stacked; the lower one's top touches the upper one, so
    # 2 + 3 faces are drawn, and the player's three (top, south, east)
    obs = {"palette": ["oak_planks"], "cells": [0, 0], "position": [10.5, 70.0, 20.5]}
    text = svg(obs, (1, 2, 1), (10, 64, 20), title="a <tower>")
    assert text.count("<polygon") == 5 + 3
    assert text.count('fill="#b8945f"') == 1          # one top (the upper block's) in the full colour
    assert "a &lt;tower&gt;" in text and text.startswith("<svg")


def test_the_world_wins_when_someone_takes_a_placed_block(house):
    fake = FakeWorld()
    prepare(fake, WorldMap(house), port=0)
    taken = []

    def take(step, bridge):
        # after the first placement, someone breaks that block and keeps it
        if not taken:
            placed = [c for c, name in bridge.blocks.items() if name == "oak_planks"]
            if placed:
                taken.append(placed[0])
                del bridge.blocks[placed[0]]

    lines = []
    result = run(house, fake, solver="build", after_step=take, log=lines.append)
    assert result.reached_goal, result.message
    assert len(taken) == 1 and len(result.plans) == 2
    assert any("the world changed after step" in line for line in lines)
    assert all(not s.differences for s in result.steps)
    assert fake.blocks[taken[0]] == "oak_planks"          # built again


def test_a_dungeon_the_world_cannot_show_is_one_line_and_exit_2(tmp_path):
    text = WALL.read_text().replace(
        "stock:\n", "items:\n  - {name: a_log, kind: log, at: [4, 1, 0]}\nstock:\n  - {name: logs, kind: log, count: 0}\n")
    (tmp_path / "items.yaml").write_text(text)
    r = CliRunner().invoke(main, ["minecraft", "run", str(tmp_path / "items.yaml")])
    assert r.exit_code == 2
    lines = r.output.strip().splitlines()
    assert len(lines) == 1 and "its state has a_log.present, which a Minecraft world cannot show" in lines[0]


def test_water_is_no_block_to_build_on_or_to_mine(tmp_path):
    from bcc.minecraft.differences import known_step
    # water at feet level at (1, 1, 2), and a water floor under (2, 1, 2)
    text = WALL.read_text().replace('"d": [bedrock, dirt, air, bedrock]', '"d": [bedrock]\n  "w": [bedrock, water]\n  "v": [water]').replace(
        "  .....\n  .....\n", "  .wv..\n  .....\n", 1).replace(
        "stock:\n", "stock:\n  - {name: water_stock, kind: water, count: 0}\n")
    (tmp_path / "pond.yaml").write_text(text)
    m = compile_dungeon(tmp_path / "pond.yaml")
    w = WorldMap(m)
    s = states_of(m, ["move_east", "move_east", "move_south"])          # at (2, 1, 1), facing the pond
    placed = m.apply(m.action_index("place_south(agent, stones)"), s[-1])
    assert placed is not None                                           # the model builds on water ...
    assert "no solid block touches it" in known_step(w, s[-1], placed)[1]   # ... Minecraft does not
    s = states_of(m, ["move_east", "move_south"])                       # at (1, 1, 1): the water south
    mined = m.apply(m.action_index("break_south"), s[-1])
    assert mined is not None and "a liquid is not mined" in known_step(w, s[-1], mined)[1]
