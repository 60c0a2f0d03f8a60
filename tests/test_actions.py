"""Each action of spec section 3 on tiny hand-made dungeons, edge cases first.

Every test writes a small dungeon file (spec section 5) into `tmp_path`, compiles it and
checks the resulting state through the model's public API (`decode`, `grid.cell`,
`agent_position`). Maps are top views: row k is z = k, column i is x = i; the agent
stands at y = 1 on a one-block floor unless a test says otherwise.
"""
from __future__ import annotations

import itertools

import pytest

from bcc.compiler import compile_dungeon

from spec_reference import dungeon_yaml

# Legend of the test maps: columns of block names from y = 0 up.
LEGEND = {
    "#": ["bedrock", "bedrock", "bedrock"],   # wall: foot and head level
    ".": ["bedrock"],                         # floor
    "S": ["bedrock"],                         # start (floor)
    "L": ["lava"],                            # lava floor
    "G": ["gold"],                            # gold floor (the goal)
    "M": ["bedrock", "burlap_stone"],         # mineable stone at foot level
    "B": ["bedrock", "bedrock"],              # bedrock at foot level only
    "H": ["bedrock", "air", "bedrock"],       # a block at head level only
    "O": [],                                  # a hole: nothing at all
    "g": ["bedrock", "gold"],                 # gold at foot level
    "w": ["bedrock", "red_wool"],             # wool at foot level
    "l": ["bedrock", "lava"],                 # lava at foot level on a solid floor
    "s": ["burlap_stone"],                    # a floor of stone (foot level free)
    "f": ["air", "burlap_stone"],             # a stone at foot level over a hole
}

PICKAXE = ("diamond_pickaxe", 1)


def stone(n: int) -> tuple:
    return ("burlap_stone", n)


def searched(model) -> set:
    """The actions `successors` generates: all of them unless the model prunes some."""
    search = getattr(model, "search_actions", None)
    return set(range(len(model.action_names))) if search is None else set(search)


class Sim:
    """A compiled model and a current state, with checks on every step."""

    def __init__(self, model):
        self.m = model
        self.s = model.initial

    def _index(self, name: str) -> int:
        return self.m.action_index(name)

    def _checked_apply(self, name: str):
        i = self._index(name)
        nxt = self.m.apply(i, self.s)
        # apply, successors and why_not must tell one story (successors may leave out
        # actions the compiler proved irrelevant to the goal: those not in search_actions)
        succ = dict(self.m.successors(self.s))
        if i in searched(self.m):
            assert succ.get(i) == nxt, f"successors() and apply() disagree on {name}"
        else:
            assert i not in succ, f"successors() lists {name}, which is not in search_actions"
        assert (self.m.why_not(i, self.s) is None) == (nxt is not None), f"why_not disagrees on {name}"
        return nxt

    def can(self, name: str) -> bool:
        return self._checked_apply(name) is not None

    def do(self, *names: str) -> "Sim":
        for name in names:
            nxt = self._checked_apply(name)
            assert nxt is not None, f"{name} refused: {self.m.why_not(self._index(name), self.s)}"
            self.s = nxt
        return self

    def refuses(self, name: str) -> str:
        nxt = self._checked_apply(name)
        assert nxt is None, f"{name} was applicable: {self.m.decode(nxt)}"
        return self.m.why_not(self._index(name), self.s)

    @property
    def d(self) -> dict:
        return self.m.decode(self.s)

    def cell(self, x: int, y: int, z: int) -> str:
        return self.m.grid.value_names[self.m.grid.cell(self.s, x, y, z)]

    @property
    def pos(self) -> tuple:
        return tuple(self.m.agent_position(self.s))

    def slot(self, i: int) -> tuple:
        d = self.d
        return d[f"inventoryBlock[{i}].blockType"], d[f"inventoryBlock[{i}].count"]

    def inventory(self) -> list:
        return [self.slot(i) for i in range(9)]


@pytest.fixture
def build(tmp_path):
    counter = itertools.count()

    def build(rows: str, height: int = 3, legend: dict | None = None, **agent) -> Sim:
        rows = rows.strip("\n").splitlines()
        used = {ch for row in rows for ch in row}
        legend = {ch: col for ch, col in {**LEGEND, **(legend or {})}.items() if ch in used}
        path = tmp_path / f"dungeon{next(counter)}.yaml"
        path.write_text(dungeon_yaml(rows, legend, height, **agent))
        return Sim(compile_dungeon(path))

    return build


OPEN = """
#####
#...#
#.S.#
#...#
#####
"""


def ahead_of(front: str) -> str:
    """A 3x4 dungeon whose start (1, 2) faces north onto `front` at (1, 1)."""
    return f"""
###
#{front}#
#S#
###
"""


# ---------------------------------------------------------------- the starting state

def test_start_stands_on_its_column_and_reads_the_agent_fields(build):
    sim = build(OPEN, facing="east", looking="down", selected=4,
                inventory=[PICKAXE, None, stone(3)])
    assert sim.pos == (2, 1, 2)
    d = sim.d
    assert (d["agent.rotationalDirection"], d["agent.verticalDirection"], d["agent.selectedItem"]) == (3, 1, 4)
    assert d["agent.alive"] is True
    assert sim.inventory() == [("diamond_pickaxe", 1), ("air", 0), ("burlap_stone", 3)] + [("air", 0)] * 6
    assert [sim.cell(2, y, 2) for y in range(3)] == ["bedrock", "air", "air"]
    assert [sim.cell(0, y, 0) for y in range(3)] == ["bedrock"] * 3


# ---------------------------------------------------------------- move_forward

@pytest.mark.parametrize("facing,expected", [
    ("south", (2, 1, 3)), ("west", (1, 1, 2)), ("north", (2, 1, 1)), ("east", (3, 1, 2))])
def test_move_forward_steps_one_cell_the_way_the_agent_faces(build, facing, expected):
    sim = build(OPEN, facing=facing).do("move_forward")
    assert sim.pos == expected
    assert sim.d["agent.alive"] is True
    assert not sim.m.is_failure(sim.s)


@pytest.mark.parametrize("front", ["#", "B", "M", "g", "w"])
def test_move_forward_is_refused_by_a_solid_block_at_foot_level(build, front):
    sim = build(ahead_of(front))
    assert sim.refuses("move_forward")
    assert sim.pos == (1, 1, 2)


def test_move_forward_is_refused_by_a_solid_block_at_head_level(build):
    sim = build(ahead_of("H"))
    assert sim.cell(1, 1, 1) == "air" and sim.cell(1, 2, 1) == "bedrock"
    assert sim.refuses("move_forward")


def test_lava_at_foot_level_is_not_solid_and_not_deadly(build):
    # Only the block *under* the target kills (spec: "the block under the target is lava").
    sim = build(ahead_of("l")).do("move_forward")
    assert sim.pos == (1, 1, 1)
    assert sim.d["agent.alive"] is True
    assert not sim.m.is_failure(sim.s)


def test_head_level_above_the_top_layer_is_free(build):
    # height 2: the agent stands at y = 1 and its head would be at y = 2, outside the world
    sim = build("S.\n..", height=2, facing="east").do("move_forward")
    assert sim.pos == (1, 1, 0)


@pytest.mark.parametrize("rows,facing", [
    ("...\nS..\n...", "west"),     # x = -1; a flat-index wrap-around would find floor at (2, 0)
    ("S..\n...", "north"),          # z = -1
    ("..S\n...", "east"),           # x = width; a wrap-around would find floor at (0, 1)
    ("...\n.S.", "south"),          # z = depth
])
def test_move_forward_never_leaves_the_map(build, rows, facing):
    sim = build(rows, facing=facing)
    assert sim.refuses("move_forward")


def test_move_forward_along_the_map_edge_is_allowed(build):
    sim = build("S..\n...", facing="east").do("move_forward", "move_forward")
    assert sim.pos == (2, 1, 0)
    assert sim.refuses("move_forward")


@pytest.mark.parametrize("front", ["O", "f"])
def test_move_forward_needs_a_block_under_the_target(build, front):
    sim = build(ahead_of(front))
    assert sim.cell(1, 0, 1) == "air"
    assert sim.refuses("move_forward")


def test_move_forward_onto_a_stone_floor(build):
    sim = build(ahead_of("s")).do("move_forward")
    assert sim.pos == (1, 1, 1) and sim.d["agent.alive"] is True


def test_stepping_onto_lava_kills_the_agent(build):
    sim = build(ahead_of("L"))
    assert not sim.m.is_failure(sim.s)
    sim.do("move_forward")
    assert sim.pos == (1, 1, 1)                  # x, z move; y unchanged
    assert sim.d["agent.alive"] is False
    assert sim.m.is_failure(sim.s)
    assert sim.m.is_terminal(sim.s)
    assert not sim.m.is_goal(sim.s)


def test_stepping_onto_gold_reaches_the_goal(build):
    sim = build(ahead_of("G"))
    assert not sim.m.is_goal(sim.s)
    sim.do("move_forward")
    assert sim.m.is_goal(sim.s) and not sim.m.is_failure(sim.s)


def test_move_forward_changes_only_the_position(build):
    sim = build(OPEN, facing="west", looking="down", selected=3, inventory=[PICKAXE, stone(2)])
    before = sim.d
    sim.do("move_forward")
    after = sim.d
    assert {k for k in before if before[k] != after[k]} == {"agent.x"}


# ---------------------------------------------------------------- turning, looking, items

@pytest.mark.parametrize("action,order", [
    ("rotate_left", [2, 1, 0, 3, 2]),     # north -> west -> south -> east -> north
    ("rotate_right", [2, 3, 0, 1, 2]),    # north -> east -> south -> west -> north
])
def test_rotation_cycles_through_the_four_directions(build, action, order):
    sim = build(OPEN)
    seen = [sim.d["agent.rotationalDirection"]]
    for _ in range(4):
        sim.do(action)
        seen.append(sim.d["agent.rotationalDirection"])
    assert seen == order
    assert sim.pos == (2, 1, 2)


def test_rotate_left_undoes_rotate_right(build):
    sim = build(OPEN, facing="east")
    start = sim.s
    assert sim.do("rotate_right", "rotate_left").s == start


def test_look_down_and_look_ahead_set_the_vertical_direction(build):
    sim = build(OPEN)
    assert sim.d["agent.verticalDirection"] == 0
    sim.do("look_down")
    assert sim.d["agent.verticalDirection"] == 1
    sim.do("look_down")                      # always applicable, idempotent
    assert sim.d["agent.verticalDirection"] == 1
    sim.do("look_ahead")
    assert sim.d["agent.verticalDirection"] == 0
    sim.do("look_ahead")
    assert sim.d["agent.verticalDirection"] == 0


def test_change_item_wraps_from_slot_8_to_slot_0(build):
    sim = build(OPEN, selected=8)
    sim.do("change_item")
    assert sim.d["agent.selectedItem"] == 0
    seen = []
    for _ in range(9):
        sim.do("change_item")
        seen.append(sim.d["agent.selectedItem"])
    assert seen == [1, 2, 3, 4, 5, 6, 7, 8, 0]


def test_change_item_does_not_touch_the_inventory(build):
    sim = build(OPEN, inventory=[PICKAXE, stone(5)])
    inv = sim.inventory()
    sim.do(*["change_item"] * 5)
    assert sim.inventory() == inv


@pytest.mark.parametrize("action", ["rotate_left", "rotate_right", "look_down", "look_ahead", "change_item"])
def test_turning_looking_and_changing_items_are_always_applicable(build, action):
    # even boxed in on every side and with an empty inventory
    sim = build("###\n#S#\n###", inventory=[])
    assert sim.can(action)


# ---------------------------------------------------------------- destroy_block

def test_destroy_block_mines_the_stone_into_the_first_empty_slot(build):
    sim = build(ahead_of("M"), looking="down")
    assert sim.cell(1, 1, 1) == "burlap_stone"
    sim.do("destroy_block")
    assert sim.cell(1, 1, 1) == "air"
    assert sim.cell(1, 0, 1) == "bedrock"    # the floor stays
    assert sim.inventory() == [("diamond_pickaxe", 1), ("burlap_stone", 1)] + [("air", 0)] * 7
    assert sim.pos == (1, 1, 2)
    sim.do("move_forward")                   # the way is open now
    assert sim.pos == (1, 1, 1)


def test_destroy_block_needs_looking_down(build):
    sim = build(ahead_of("M"), looking="ahead")
    assert sim.refuses("destroy_block")
    sim.do("look_down", "destroy_block")
    assert sim.cell(1, 1, 1) == "air"


@pytest.mark.parametrize("inventory,selected", [
    ([PICKAXE], 1),                                       # an empty slot selected
    ([PICKAXE, stone(3)], 1),                             # a stone, not a pickaxe
    ([PICKAXE, ("gold", 2)], 1),                          # another block
    ([], 0),                                              # nothing at all
    ([("diamond_pickaxe", 0)], 0),                        # a pickaxe slot holding none
])
def test_destroy_block_needs_the_pickaxe_selected(build, inventory, selected):
    sim = build(ahead_of("M"), looking="down", inventory=inventory, selected=selected)
    assert sim.refuses("destroy_block")
    assert sim.cell(1, 1, 1) == "burlap_stone"


def test_destroy_block_with_the_pickaxe_in_another_slot(build):
    sim = build(ahead_of("M"), looking="down", inventory=[None, None, None, PICKAXE], selected=3)
    sim.do("destroy_block")
    assert sim.slot(0) == ("burlap_stone", 1)
    assert sim.slot(3) == ("diamond_pickaxe", 1)


@pytest.mark.parametrize("front", ["#", "B", "g", "w", ".", "s", "L", "l", "O"])
def test_destroy_block_only_mines_mineable_blocks_at_foot_level(build, front):
    # bedrock, gold, wool, air, lava and a stone one below foot level ("s") are not mined
    sim = build(ahead_of(front), looking="down")
    before = [sim.cell(1, y, 1) for y in range(3)]
    assert sim.refuses("destroy_block")
    assert [sim.cell(1, y, 1) for y in range(3)] == before


def test_destroy_block_facing_out_of_the_map(build):
    # (0, 1) faces west onto x = -1; a flat-index wrap-around would find the stone at (2, 0)
    sim = build("..M\nS..", facing="west", looking="down")
    assert sim.refuses("destroy_block")
    assert sim.cell(2, 1, 0) == "burlap_stone"


def test_destroy_block_stacks_onto_a_stone_stack(build):
    sim = build(ahead_of("M"), looking="down", inventory=[PICKAXE, None, stone(5)])
    sim.do("destroy_block")
    assert sim.slot(1) == ("air", 0)
    assert sim.slot(2) == ("burlap_stone", 6)


def test_destroy_block_fills_the_first_empty_slot(build):
    sim = build(ahead_of("M"), looking="down", inventory=[PICKAXE, ("gold", 1), None, None])
    sim.do("destroy_block")
    assert sim.inventory()[:4] == [("diamond_pickaxe", 1), ("gold", 1), ("burlap_stone", 1), ("air", 0)]


def test_destroy_block_can_complete_a_stack_of_64(build):
    sim = build(ahead_of("M"), looking="down", inventory=[PICKAXE, stone(63)])
    sim.do("destroy_block")
    assert sim.slot(1) == ("burlap_stone", 64)
    assert sim.slot(2) == ("air", 0)


def test_a_full_stack_of_64_takes_no_more(build):
    sim = build(ahead_of("M"), looking="down", inventory=[PICKAXE, stone(64), None])
    sim.do("destroy_block")
    assert sim.slot(1) == ("burlap_stone", 64)
    assert sim.slot(2) == ("burlap_stone", 1)


def test_a_later_open_stack_is_preferred_to_an_empty_slot(build):
    sim = build(ahead_of("M"), looking="down", inventory=[PICKAXE, stone(64), None, stone(10)])
    sim.do("destroy_block")
    assert sim.inventory()[:4] == [("diamond_pickaxe", 1), ("burlap_stone", 64), ("air", 0), ("burlap_stone", 11)]


@pytest.mark.parametrize("others", [("gold", 1), ("burlap_stone", 64)], ids=["other-types", "full-stacks"])
def test_destroy_block_with_a_full_inventory_still_removes_the_block(build, others):
    inventory = [PICKAXE] + [others] * 8
    sim = build(ahead_of("M"), looking="down", inventory=inventory)
    before = sim.inventory()
    sim.do("destroy_block")
    assert sim.cell(1, 1, 1) == "air"
    assert sim.inventory() == before


# ---------------------------------------------------------------- place_block

BRIDGE = """
#####
#.L.#
#.S.#
#####
"""


def test_place_block_into_lava_builds_a_bridge(build):
    sim = build(BRIDGE, looking="down", inventory=[PICKAXE, stone(1)], selected=1)
    sim.do("place_block")
    assert sim.cell(2, 0, 1) == "burlap_stone"     # the lava is replaced
    assert sim.cell(2, 1, 1) == "air"
    assert sim.slot(1) == ("air", 0)               # the last stone: the slot empties
    sim.do("move_forward")
    assert sim.pos == (2, 1, 1)
    assert sim.d["agent.alive"] is True and not sim.m.is_failure(sim.s)


def test_place_block_into_a_hole_fills_the_floor(build):
    sim = build(ahead_of("O"), looking="down", inventory=[PICKAXE, stone(2)], selected=1)
    assert sim.refuses("move_forward")
    sim.do("place_block")
    assert [sim.cell(1, y, 1) for y in range(3)] == ["burlap_stone", "air", "air"]
    assert sim.slot(1) == ("burlap_stone", 1)
    sim.do("move_forward")
    assert sim.pos == (1, 1, 1)


def test_place_block_under_a_floating_stone_fills_the_floor(build):
    # The first case of the spec only asks that the cell one below foot level is air or lava.
    sim = build(ahead_of("f"), looking="down", inventory=[PICKAXE, stone(2)], selected=1)
    sim.do("place_block")
    assert [sim.cell(1, y, 1) for y in range(3)] == ["burlap_stone", "burlap_stone", "air"]


def test_place_block_on_a_solid_floor_stands_at_foot_level(build):
    sim = build(ahead_of("."), looking="down", inventory=[PICKAXE, stone(3)], selected=1)
    sim.do("place_block")
    assert [sim.cell(1, y, 1) for y in range(3)] == ["bedrock", "burlap_stone", "air"]
    assert sim.slot(1) == ("burlap_stone", 2)      # the count drops, the type stays
    assert sim.refuses("move_forward")             # a new obstacle
    assert sim.refuses("place_block")              # and its cell is no longer free


def test_placing_the_second_to_last_stone_keeps_the_slot(build):
    sim = build(ahead_of("."), looking="down", inventory=[PICKAXE, stone(2)], selected=1)
    sim.do("place_block")
    assert sim.slot(1) == ("burlap_stone", 1)


def test_placing_the_last_stone_empties_the_slot(build):
    sim = build(ahead_of("."), looking="down", inventory=[PICKAXE, stone(1)], selected=1)
    sim.do("place_block")
    assert sim.slot(1) == ("air", 0)
    assert sim.refuses("place_block")


def test_a_placed_stone_can_be_mined_again(build):
    sim = build(ahead_of("."), looking="down", inventory=[PICKAXE, stone(1)], selected=1)
    start = sim.s
    sim.do("place_block")
    sim.do(*["change_item"] * 8)                   # slot 1 -> ... -> 8 -> 0: the pickaxe
    assert sim.d["agent.selectedItem"] == 0
    sim.do("destroy_block")
    assert sim.cell(1, 1, 1) == "air"
    assert sim.slot(1) == ("burlap_stone", 1)      # back in the first empty slot
    sim.do("change_item")
    assert sim.s == start


def test_place_block_from_a_full_stack(build):
    sim = build(ahead_of("."), looking="down", inventory=[PICKAXE, stone(64)], selected=1)
    sim.do("place_block")
    assert sim.slot(1) == ("burlap_stone", 63)


@pytest.mark.parametrize("front", ["#", "B", "M", "g", "w", "l"])
def test_place_block_needs_a_free_foot_cell_over_a_solid_floor(build, front):
    sim = build(ahead_of(front), looking="down", inventory=[PICKAXE, stone(3)], selected=1)
    before = [sim.cell(1, y, 1) for y in range(3)]
    assert sim.refuses("place_block")
    assert [sim.cell(1, y, 1) for y in range(3)] == before


def test_place_block_needs_looking_down(build):
    sim = build(BRIDGE, looking="ahead", inventory=[PICKAXE, stone(1)], selected=1)
    assert sim.refuses("place_block")
    sim.do("look_down", "place_block")
    assert sim.cell(2, 0, 1) == "burlap_stone"


@pytest.mark.parametrize("inventory,selected", [
    ([PICKAXE, stone(3)], 0),                 # the pickaxe is not placeable
    ([PICKAXE, stone(3)], 2),                 # an empty slot
    ([PICKAXE, ("gold", 3)], 1),              # gold is not placeable
    ([PICKAXE, ("bedrock", 3)], 1),           # nor is bedrock
    ([PICKAXE, stone(0)], 1),                 # a stone slot holding none
])
def test_place_block_needs_a_placeable_block_selected(build, inventory, selected):
    sim = build(BRIDGE, looking="down", inventory=inventory, selected=selected)
    before = sim.inventory()
    assert sim.refuses("place_block")
    assert sim.cell(2, 0, 1) == "lava"
    assert sim.inventory() == before


def test_place_block_facing_out_of_the_map(build):
    # (0, 1) faces west onto x = -1; a flat-index wrap-around would find the free floor (2, 0)
    sim = build("...\nS..", facing="west", looking="down", inventory=[PICKAXE, stone(3)], selected=1)
    assert sim.refuses("place_block")
    assert sim.cell(2, 1, 0) == "air"
    sim = build("S..\n...", facing="north", looking="down", inventory=[PICKAXE, stone(3)], selected=1)
    assert sim.refuses("place_block")


# ---------------------------------------------------------------- the bottom layer

def test_place_block_with_no_layer_below_the_feet_is_not_applicable(build):
    # An empty start column puts the agent at y = 0: there is no cell below its feet.
    rows = "S..\n..."
    sim = build(rows, height=2, legend={"S": [], ".": []}, facing="east", looking="down", selected=1,
                inventory=[PICKAXE, stone(3)])
    assert sim.pos == (0, 0, 0)
    try:
        nxt = sim.m.apply(sim.m.action_index("place_block"), sim.s)
    except Exception as exc:   # a planner would crash here
        raise AssertionError(f"place_block raised {exc!r}") from exc
    assert nxt is None
    assert sim.refuses("move_forward")       # nothing to stand on either
