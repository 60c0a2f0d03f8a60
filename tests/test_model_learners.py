"""What R-max's model learners generalise from a few observations, one property each.

The world here is the compiled model used as the environment (spec section 3: an
inapplicable action is a no-op); the learners only see `observe(s, a, next)`.
"""
from __future__ import annotations

import pytest

from bcc.solvers.model_learners import ObjectOriented, Tabular

from conftest import compiled

SOUTH, WEST, NORTH, EAST = 0, 1, 2, 3   # rotationalDirection (domains/minecraft.yaml)


def step(model, s, name):
    a = model.action_index(name)
    n = model.apply(a, s)
    return a, (s if n is None else n)


def placed(model, s, x, z, facing):
    """State s with the agent moved to (x, z) and turned to `facing`."""
    (ix, lx), _, (iz, lz) = model.position
    b = bytearray(s)
    b[ix], b[iz], b[2] = x - lx, z - lz, facing
    return bytes(b)


def seen(learner, model, s, *names):
    """Act `names` from s, letting the learner observe each step; the last state."""
    for name in names:
        a, n = step(model, s, name)
        learner.observe(s, a, n)
        s = n
    return s


def test_a_move_seen_facing_east_is_expected_facing_north():
    grid = compiled("grid")           # start (1, 3) facing north; (2, 3), (3, 3), (2, 2) are floor
    oo, tab = ObjectOriented(grid), Tabular(grid)
    s = seen(oo, grid, grid.initial, "rotate_right", "move_forward")   # now at (2, 3) facing east
    north = placed(grid, s, 2, 3, NORTH)
    move, expected = step(grid, north, "move_forward")
    assert grid.agent_position(expected)[::2] == (2, 2)
    assert oo.predict(north, move) == expected        # in its own frame it is the same move
    assert tab.predict(north, move) is None           # tabular knows only what it saw


def test_a_bump_into_one_wall_predicts_a_bump_into_another():
    grid = compiled("grid")
    oo = ObjectOriented(grid)
    s = seen(oo, grid, grid.initial, "move_forward")   # (1, 2) is wall: nothing happens
    assert s == grid.initial
    seen(oo, grid, grid.initial, "rotate_right", "move_forward")      # a real move: where moves act
    east_wall = placed(grid, grid.initial, 3, 3, EAST)                # (4, 3) is wall
    move, _ = step(grid, east_wall, "move_forward")
    assert oo.predict(east_wall, move) == east_wall
    open_floor = placed(grid, grid.initial, 3, 3, NORTH)              # (3, 2) is floor
    assert oo.predict(open_floor, move) == step(grid, open_floor, "move_forward")[1]


def test_one_death_in_lava_is_expected_from_the_other_bank_too():
    bridge = compiled("bridge")       # lava in column x = 3; start (1, 3)
    oo = ObjectOriented(bridge)
    s = seen(oo, bridge, bridge.initial, "rotate_right", "move_forward")   # (2, 3) facing east
    move, dead = step(bridge, s, "move_forward")
    assert bridge.is_failure(dead)
    oo.observe(s, move, dead)
    other_bank = placed(bridge, bridge.initial, 4, 1, WEST)              # lava ahead, from the east
    predicted = oo.predict(other_bank, move)
    assert predicted == step(bridge, other_bank, "move_forward")[1] and bridge.is_failure(predicted)


def test_an_effect_is_not_trusted_where_what_it_acts_on_is_new():
    # Moving was only ever seen onto bedrock; onto gold the same condition holds, but what
    # the move acts on (the column ahead) was never seen so: unknown, hence worth trying.
    grid = compiled("grid")           # gold at (1, 1)
    oo = ObjectOriented(grid)
    seen(oo, grid, grid.initial, "rotate_right", "move_forward", "move_forward")
    facing_gold = placed(grid, grid.initial, 2, 1, WEST)
    move, _ = step(grid, facing_gold, "move_forward")
    assert oo.predict(facing_gold, move) is None


def test_a_wrong_generalisation_is_corrected_where_it_failed():
    grid = compiled("grid")
    oo = ObjectOriented(grid)
    seen(oo, grid, grid.initial, "rotate_right", "move_forward")
    s = placed(grid, grid.initial, 2, 3, NORTH)
    move, truth = step(grid, s, "move_forward")
    assert oo.predict(s, move) == truth
    # pretend the world answered differently here: that state is then known as seen
    oo.observe(s, move, s)
    assert oo.predict(s, move) == s


@pytest.mark.parametrize("learner", [Tabular, ObjectOriented])
def test_nothing_is_predicted_before_anything_is_seen(learner):
    grid = compiled("grid")
    know = learner(grid)
    assert all(know.predict(grid.initial, a) is None for a in range(len(grid.action_names)))
