"""The compiled successor function against a slow, literal reading of the spec.

In the style of pyperplan's `tests/test_successor_generator.py`: two independent
implementations walk side by side. `spec_reference` starts from the section-4 maps as
printed in the spec (not from `dungeons/*.yaml`) and applies section 3 row by row; bcc
starts from its compiled initial state. At every step of a random walk both must offer
the same applicable actions and agree on every successor: the agent, the nine hotbar
slots and every grid cell. Random small dungeons (lava, holes, stones, odd inventories)
cover what the five reference dungeons rarely reach.

Invariants checked on bcc's own states along random walks: the agent stays in bounds at
its height, slot counts stay in 0..64, a slot is empty exactly when its type is air, the
terrain above the mutable layers never changes, and mineable blocks are conserved (in
the world plus the inventory) while the agent is alive.
"""
from __future__ import annotations

import inspect
import random
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from bcc.compiler import compile_dungeon

import spec_reference as ref
from conftest import compiled

DUNGEONS = ["grid", "bridge", "easy_maze", "tough_maze", "four_rooms"]
STEPS = 60
# Derandomized (each run sees the same examples) and without the example database or the
# slow "explain" phase, so a failure is reported, shrunk, in about a minute.
SETTINGS = settings(max_examples=30, deadline=None, derandomize=True, database=None,
                    phases=[Phase.explicit, Phase.generate, Phase.shrink],
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])

# Goals of the reference dungeons, read from the spec: agentOnBlock(agent, gold), and
# for four rooms agentInRoom(agent, blue) with blue x 0..4, z 6..11 (strictly inside).
SPEC_GOALS = {
    "grid": lambda w: ref.agent_on(w, "gold"),
    "bridge": lambda w: ref.agent_on(w, "gold"),
    "easy_maze": lambda w: ref.agent_on(w, "gold"),
    "tough_maze": lambda w: ref.agent_on(w, "gold"),
    "four_rooms": lambda w: 0 < w.x < 4 and 6 < w.z < 11,
}

# Random walks pick among the applicable actions, weighted so that walks get somewhere
# and change the world: mining and placing are favoured, stepping into lava is rare,
# the agent mostly looks down and skips empty hotbar slots quickly.
def weight(name: str, nxt: ref.World, world: ref.World) -> int:
    if name == "move_forward":
        return 12 if nxt.alive else 2
    if name == "destroy_block":
        return 40
    if name == "place_block":
        return 12
    if name == "look_down":
        return 6 if world.vert == 0 else 1
    if name == "look_ahead":
        return 1
    if name == "change_item":
        return 5 if world.inventory[world.sel][1] == 0 else 1
    return 3


def searched(model) -> list[int]:
    """The actions `successors` generates: all of them unless the model prunes some."""
    search = getattr(model, "search_actions", None)
    return list(range(len(model.action_names))) if search is None else list(search)


def candidates(pairs: dict, world: ref.World) -> list[str]:
    """The applicable actions, each repeated by its weight (pick one uniformly)."""
    return [n for n in sorted(pairs) for _ in range(weight(n, pairs[n][1], world))]


def compare_step(model, state: bytes, world: ref.World, cache: dict, goal=None) -> dict:
    """Check one state: bcc's view equals the reference world, and both agree on which
    actions apply and on every successor. Returns name -> (bcc next state, reference next world)."""
    here = ref.world_from_model(model, state, cache)
    assert here == world, "states diverged:\n" + "\n".join(ref.diff(here, world))
    assert model.is_failure(state) == ref.is_failure(world)
    if goal is not None:
        assert model.is_goal(state) == goal(world)
    expected = ref.successors(world)
    got = {}
    for i, name in enumerate(model.action_names):
        nxt = model.apply(i, state)
        assert (model.why_not(i, state) is None) == (nxt is not None), f"why_not({name}) disagrees with apply"
        if nxt is not None:
            got[name] = nxt
    # successors() generates the applicable actions, less those the compiler pruned as
    # irrelevant to the goal (Model.search_actions), with the same next states as apply()
    listed = {}
    for i, nxt in model.successors(state):
        name = model.action_names[i]
        assert name not in listed, f"{name} listed twice"
        listed[name] = nxt
    search = {model.action_names[i] for i in searched(model)}
    assert listed == {n: s for n, s in got.items() if n in search}, "successors() differs from apply()"
    pose = (world.x, world.y, world.z, world.rot, world.vert, world.sel, world.inventory)
    assert set(got) == set(expected), (
        f"applicable actions differ at pose {pose}: bcc {sorted(got)}, spec {sorted(expected)}")
    for name, nxt in got.items():
        mine = ref.world_from_model(model, nxt, cache)
        assert mine == expected[name], (
            f"{name} from pose {pose}:\n" + "\n".join(ref.diff(mine, expected[name])))
    return {name: (got[name], expected[name]) for name in got}


def lockstep_walk(model, world: ref.World, choose, steps: int = STEPS, goal=None) -> list[str]:
    """Walk bcc and the reference side by side; `choose(options)` picks the next action
    name. Stops when the agent dies. Returns the actions taken (for failure reports)."""
    cache: dict = {}
    state = model.initial
    taken = []
    for _ in range(steps):
        pairs = compare_step(model, state, world, cache, goal)
        if ref.is_failure(world) or not pairs:
            break
        name = choose(candidates(pairs, world))
        taken.append(name)
        state, world = pairs[name]
    else:
        compare_step(model, state, world, cache, goal)
    return taken


# ---------------------------------------------------------------- the reference dungeons

@pytest.mark.parametrize("name", DUNGEONS + ["four_rooms_red", "four_rooms_orange", "four_rooms_green"])
def test_initial_state_is_the_spec_map(name):
    model = compiled(name)
    world = ref.spec_world("four_rooms" if name.startswith("four_rooms") else name)
    got = ref.world_from_model(model, model.initial)
    assert got == world, "\n".join(ref.diff(got, world))
    assert not model.is_failure(model.initial)


@pytest.mark.parametrize("name", DUNGEONS)
@SETTINGS
@given(data=st.data())
def test_random_walks_agree_with_the_spec(name, data):
    model = compiled(name)
    lockstep_walk(model, ref.spec_world(name),
                  lambda options: options[data.draw(st.integers(0, len(options) - 1))],
                  goal=SPEC_GOALS[name])


@pytest.mark.parametrize("name", DUNGEONS)
def test_seeded_walks_agree_with_the_spec(name):
    """Longer walks from fixed seeds, so the stones of the bridge and the tough maze get
    mined and placed again (each run is the same)."""
    model = compiled(name)
    for seed in range(8):
        rng = random.Random(f"{name}-{seed}")
        lockstep_walk(model, ref.spec_world(name), rng.choice, steps=150, goal=SPEC_GOALS[name])


def test_the_bridge_plan_agrees_with_the_spec():
    """The 13-step optimal bridge plan (mine the stone, bridge the lava, reach the gold)
    exercises every kind of action; walk it in lockstep."""
    plan = ["rotate_left", "rotate_left", "move_forward", "look_down", "destroy_block", "move_forward",
            "rotate_left", "move_forward", "change_item", "place_block", "move_forward", "move_forward",
            "move_forward"]
    model = compiled("bridge")
    steps = iter(plan)
    taken = lockstep_walk(model, ref.spec_world("bridge"), lambda options: next(steps),
                          steps=len(plan), goal=SPEC_GOALS["bridge"])
    assert taken == plan
    state = model.initial
    for name in plan:
        state = model.apply(model.action_index(name), state)
    assert model.is_goal(state)


@pytest.mark.skipif("prune" not in inspect.signature(compile_dungeon).parameters,
                    reason="compile_dungeon has no `prune` option")
@pytest.mark.parametrize("name", ["bridge", "tough_maze", "four_rooms"])
def test_unpruned_successors_are_exactly_the_applicable_actions(name):
    """Without pruning, `successors` lists every action the spec allows, and nothing else."""
    model = compile_dungeon(name, prune=False)
    assert searched(model) == list(range(len(model.action_names)))
    rng = random.Random(name)
    lockstep_walk(model, ref.spec_world(name), rng.choice, steps=100, goal=SPEC_GOALS[name])


# ---------------------------------------------------------------- random small dungeons

PALETTE = {
    ".": ["bedrock"], "S": ["bedrock"], "#": ["bedrock", "bedrock", "bedrock"],
    "L": ["lava"], "G": ["gold"], "O": [], "M": ["bedrock", "burlap_stone"],
    "B": ["bedrock", "bedrock"], "H": ["bedrock", "air", "bedrock"], "s": ["burlap_stone"],
    "f": ["air", "burlap_stone"], "l": ["bedrock", "lava"], "w": ["bedrock", "blue_wool"],
    "g": ["bedrock", "gold"], "m": ["lava", "burlap_stone"],
}
# floors and stones are common, the rest rarer
TILES = list("....MMssLLOGB#Hflwgm")

slot_contents = st.one_of(
    st.none(), st.none(),
    st.just(("diamond_pickaxe", 1)),
    st.tuples(st.just("burlap_stone"), st.integers(1, 64)),
    st.tuples(st.just("burlap_stone"), st.sampled_from([1, 2, 63, 64])),
    st.tuples(st.sampled_from(["gold", "bedrock"]), st.integers(1, 3)),
)


@st.composite
def small_dungeons(draw):
    width, depth = draw(st.integers(2, 5)), draw(st.integers(2, 5))
    cells = draw(st.lists(st.sampled_from(TILES), min_size=width * depth, max_size=width * depth))
    start = draw(st.integers(0, width * depth - 1))
    cells[start] = "S"
    rows = ["".join(cells[z * width:(z + 1) * width]) for z in range(depth)]
    inventory = draw(st.lists(slot_contents, max_size=9))
    if draw(st.booleans()):        # usually a pickaxe somewhere
        inventory = (inventory + [None])[:9]
        inventory[draw(st.integers(0, len(inventory) - 1))] = ("diamond_pickaxe", 1)
    return dict(
        rows=rows, height=draw(st.sampled_from([2, 3, 4])),
        facing=draw(st.sampled_from(sorted(ref.FACING))),
        looking=draw(st.sampled_from(sorted(ref.LOOKING))),
        selected=draw(st.integers(0, 8)),
        inventory=inventory,
    )


@settings(SETTINGS, max_examples=30)
@given(spec=small_dungeons(), data=st.data())
def test_random_small_dungeons_agree_with_the_spec(spec, data):
    used = {ch for row in spec["rows"] for ch in row}
    legend = {ch: col[:spec["height"]] for ch, col in PALETTE.items() if ch in used}
    text = ref.dungeon_yaml(spec["rows"], legend, spec["height"], facing=spec["facing"],
                            looking=spec["looking"], selected=spec["selected"], inventory=spec["inventory"])
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "random.yaml"
        path.write_text(text)
        model = compile_dungeon(path)
    inventory = [e if e is not None else (ref.AIR, 0) for e in spec["inventory"]]
    world = ref.world_from_map("\n".join(spec["rows"]), legend, spec["height"], facing=spec["facing"],
                               looking=spec["looking"], selected=spec["selected"], inventory=inventory)
    lockstep_walk(model, world, lambda options: options[data.draw(st.integers(0, len(options) - 1))],
                  steps=80, goal=lambda w: ref.agent_on(w, "gold"))


# ---------------------------------------------------------------- invariants

def check_invariants(model, state: bytes, initial: bytes, cache: dict) -> None:
    g = model.grid
    d = model.decode(state)
    x, y, z = model.agent_position(state)
    assert 0 <= x < g.width and 0 <= z < g.depth
    assert y == model.agent_position(initial)[1], "the agent's height never changes"
    assert 0 <= d["agent.rotationalDirection"] <= 3
    assert d["agent.verticalDirection"] in (0, 1)
    assert 0 <= d["agent.selectedItem"] <= 8
    for i in range(ref.SLOTS):
        kind, count = d[f"inventoryBlock[{i}].blockType"], d[f"inventoryBlock[{i}].count"]
        assert 0 <= count <= ref.MAX_STACK, f"slot {i} holds {count}"
        assert (count == 0) == (kind == ref.AIR), f"slot {i} is ({kind}, {count})"
    # the agent never stands inside a solid block, and stands on something
    blocks = cache.get(state[g.base:])
    if blocks is None:
        blocks = cache[state[g.base:]] = ref.model_blocks(model, state)
    at = lambda cx, cy, cz: blocks[(cy * g.depth + cz) * g.width + cx] if 0 <= cy < g.height else ref.AIR
    assert at(x, y, z) not in ref.SOLID and at(x, y + 1, z) not in ref.SOLID
    assert at(x, y - 1, z) != ref.AIR
    # layers no action can reach stay as they were
    for cy in range(g.height):
        if cy not in (y - 1, y):
            for cz in range(g.depth):
                for cx in range(g.width):
                    assert g.cell(state, cx, cy, cz) == g.cell(initial, cx, cy, cz)


def mineable_total(model, state: bytes, cache: dict) -> int:
    g = model.grid
    blocks = cache.get(state[g.base:])
    if blocks is None:
        blocks = cache[state[g.base:]] = ref.model_blocks(model, state)
    d = model.decode(state)
    carried = sum(d[f"inventoryBlock[{i}].count"] for i in range(ref.SLOTS)
                  if d[f"inventoryBlock[{i}].blockType"] in ref.MINEABLE)
    return sum(1 for b in blocks if b in ref.MINEABLE) + carried


@pytest.mark.parametrize("name", DUNGEONS)
@SETTINGS
@given(data=st.data())
def test_random_walks_keep_the_invariants(name, data):
    model = compiled(name)
    cache: dict = {}
    state = model.initial
    world = ref.world_from_model(model, state)     # only to weigh the choices
    total = mineable_total(model, state, cache)
    check_invariants(model, state, model.initial, cache)
    for _ in range(STEPS):
        succ = {name: (n, ref.world_from_model(model, n, cache)) for i, name in enumerate(model.action_names)
                if (n := model.apply(i, state)) is not None}
        options = candidates(succ, world)
        state, world = succ[options[data.draw(st.integers(0, len(options) - 1))]]
        check_invariants(model, state, model.initial, cache)
        if model.is_failure(state):
            break
        # the shipped dungeons have at most six stones and eight free slots: nothing is lost
        assert mineable_total(model, state, cache) == total


@pytest.mark.parametrize("name", DUNGEONS)
def test_successors_are_deterministic_and_hashable(name):
    model = compiled(name)
    rng = random.Random(name)
    state = model.initial
    seen = {state}
    for _ in range(STEPS):
        first = model.successors(state)
        assert model.successors(state) == first
        assert all(isinstance(n, bytes) and len(n) == len(state) for _, n in first)
        state = rng.choice(first)[1]
        seen.add(state)
        if model.is_failure(state):
            break
    assert model.initial in seen
