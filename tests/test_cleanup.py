"""The cleanup domain and dungeon (issue 20): Cleanup World in YAML only, every corpus task plannable."""
from __future__ import annotations

import pytest

from bcc.compiler import compile_dungeon
from bcc.solvers import Budget, get_solver

BUDGET = Budget(time_limit=120)


def final_state(model, plan):
    state = model.initial
    for name in plan:
        state = model.apply(model.action_index(name), state)
        assert state is not None, name
    return state

# The six tasks of the cleanup-amt corpus, with optimal costs derived by hand. The agent
# starts at (6, 2) facing south, the chair stands at (2, 6), doorways at (2, 4) and (6, 4).
HAND = {
    # three steps south: (6,3), the doorway (6,4), (6,5) in the red room
    "agentInRoom(agent, red)": 3,
    # 3 south to (6,5), turn west, 4 west to (2,5), turn north, 2 north to (2,3)
    "agentInRoom(agent, green)": 11,
    # pick up: 4 south to (6,6), turn west, 3 west to (3,6) facing the chair, look down, mine (10);
    # back: turn north, (3,5), turn east, 3 east to (6,5), turn north, into the doorway (6,4) (8);
    # select the chair, place it on (6,3) in the blue room (2): 20
    "blockInRoom(chair, blue)": 20,
}
OTHERS = ["agentInRoom(agent, green) and blockInRoom(chair, blue)",
          "agentInRoom(agent, blue) and blockInRoom(chair, green)", "blockInRoom(chair, green)"]


@pytest.mark.parametrize("goal", list(HAND))
def test_hand_derived_optimal_costs(goal):
    model = compile_dungeon("cleanup", goal=goal)
    result = get_solver("astar")(model, BUDGET)
    assert result.solved and result.cost == HAND[goal]
    assert model.is_goal(final_state(model, result.plan))


@pytest.mark.parametrize("goal", OTHERS)
def test_astar_matches_breadth_first_search(goal):
    # BFS is optimal for unit costs and shares nothing with A*'s heuristics.
    model = compile_dungeon("cleanup", goal=goal)
    astar, bfs = get_solver("astar")(model, BUDGET), get_solver("bfs")(model, BUDGET)
    assert astar.solved and bfs.solved and astar.cost == bfs.cost
    assert model.is_goal(final_state(model, astar.plan))


def test_carrying_the_chair_is_mining_then_placing_it():
    model = compile_dungeon("cleanup", goal="blockInRoom(chair, blue)")
    plan = get_solver("astar")(model, BUDGET).plan
    assert "destroy_block" in plan and plan[-1] == "place_block"
    start = model.decode(model.initial)
    assert start["agent.x"] == 6 and start["agent.z"] == 2


def test_two_hands_not_a_hotbar():
    # change_item is overridden: the robot alternates between the pickaxe and what it carries.
    model = compile_dungeon("cleanup")
    i = model.action_index("change_item")
    s = model.apply(i, model.apply(i, model.initial))
    assert model.decode(s)["agent.selectedItem"] == 0
