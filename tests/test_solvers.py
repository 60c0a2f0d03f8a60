"""BFS and A* on every reference dungeon: equal optimal costs, A* expanding fewer states.

Optimal costs are checked against hand derivations (explained per dungeon) and against
each other (two independent algorithms over the same model); plans are replayed.
"""
from __future__ import annotations

import pytest

from bcc.simulate import replay
from bcc.solvers import Budget, get_solver, list_solvers
from bcc.heuristics.registry import make

from conftest import FOUR_ROOMS_GOALS, compiled

BUDGET = Budget(time_limit=120, max_memory_mb=6000)

CASES = [("grid", None), ("bridge", None), ("easy_maze", None), ("tough_maze", None)] + \
    [("four_rooms", f"agentInRoom(agent, {room})") for room in FOUR_ROOMS_GOALS]

# Hand-derived optimal costs (every action costs 1):
# - grid: start (1,3) facing north, gold at (1,1), wall at (1,2). The agent must go round
#   via x = 2: 4 moves (east, north, north, west) and 3 turns (to east, to north, to west) = 7.
# - bridge: the lava column x = 3 blocks every path; crossing needs one stone placed in it,
#   and the only stone is at (1,5). From (1,3) facing north: turn twice to face south (2),
#   step to (1,4) (1), look down (1), mine (1,5) (1), step onto (1,5) (1), turn east (1),
#   step to (2,5) (1), select slot 1 holding the stone (1), place it into the lava at (3,5)
#   (1), then walk (3,5), (4,5), (5,5) onto the gold (3): 13.
# - four rooms, red: the agent starts at (1,3), strictly inside red (0 < 1 < 5, 0 < 3 < 5),
#   so the empty plan (cost 0) already satisfies the goal.
# - four rooms, orange: orange's interior is x 7..9, z 1..3. Turn east (1) and walk along
#   z = 3 through the door at (5,3)/(6,3) to x = 7 (6 moves): 7.
HAND = {("grid", None): 7, ("bridge", None): 13,
        ("four_rooms", "agentInRoom(agent, red)"): 0,
        ("four_rooms", "agentInRoom(agent, orange)"): 7}


@pytest.mark.parametrize("name,goal", CASES)
def test_bfs_and_astar_agree_and_plans_replay(name, goal):
    model = compiled(name, goal)
    bfs = get_solver("bfs")(model, BUDGET)
    astar = get_solver("astar")(model, BUDGET)
    assert bfs.solved and astar.solved
    assert bfs.cost == astar.cost
    if (name, goal) in HAND:
        assert astar.cost == HAND[(name, goal)]
    if bfs.cost > 0:
        assert astar.expanded < bfs.expanded
    for result in (bfs, astar):
        r = replay(model, [(a, 1, 1) for a in result.plan])
        assert r.valid and r.cost == result.cost


def test_tough_maze_needs_more_than_the_easy_maze():
    # The tough maze is the easy maze plus stones: anything it can do the easy maze could
    # do at least as cheaply, so its optimum is >= the easy maze's (and here strictly more,
    # because stones sit on the easy maze's shortest path).
    easy = get_solver("astar")(compiled("easy_maze"), BUDGET)
    tough = get_solver("astar")(compiled("tough_maze"), BUDGET)
    assert tough.cost > easy.cost


def test_blind_astar_equals_bfs_cost():
    model = compiled("bridge")
    blind = get_solver("astar")(model, BUDGET, heuristic="blind")
    bfs = get_solver("bfs")(model, BUDGET)
    assert blind.cost == bfs.cost


def test_manhattan_is_admissible_along_the_optimal_plan():
    # h never exceeds the true remaining cost at any state of an optimal plan.
    model = compiled("bridge")
    h = make("manhattan", model)
    result = get_solver("bfs")(model, BUDGET)
    r = replay(model, [(a, 1, 1) for a in result.plan])
    for i, state in enumerate(r.states):
        assert h(state) <= result.cost - i


@pytest.mark.parametrize("solver", ["bfs", "astar"])
def test_state_budget_stops_cleanly(solver):
    result = get_solver(solver)(compiled("tough_maze"), Budget(max_states=2000))
    assert not result.solved and result.status == "budget" and result.budget == "max_states"
    assert "--max-states" in result.message


def test_time_budget_stops_cleanly():
    result = get_solver("bfs")(compiled("tough_maze"), Budget(time_limit=0.05))
    assert result.status == "budget" and result.budget == "time_limit"


def test_memory_budget_stops_cleanly():
    result = get_solver("bfs")(compiled("tough_maze"), Budget(max_memory_mb=1))
    assert result.status == "budget" and result.budget == "max_memory"


def test_unreachable_goal_is_no_solution(tmp_path):
    # The gold is walled in on every side: BFS explores everything and reports no plan.
    text = """\
domain: minecraft
height: 3
legend:
  "#": [bedrock, bedrock, bedrock]
  ".": [bedrock]
  "G": [gold]
  "S": [bedrock]
map: |
  #######
  #S.#G##
  #..####
  #######
agent: {start: S}
goal: agentOnBlock(agent, gold)
"""
    path = tmp_path / "walled.yaml"
    path.write_text(text)
    model = compiled(str(path))
    for solver in ("bfs", "astar"):
        result = get_solver(solver)(model, BUDGET)
        assert not result.solved and result.status == "no_solution"


def test_registry_lists_builtins():
    assert {"bfs", "astar"} <= set(list_solvers())


@pytest.mark.parametrize("solver", ["bfs", "astar", "gbfs"])
def test_small_state_budgets_are_honoured_exactly(solver):
    # Checked at every expansion, not only every CHECK_EVERY expansions.
    result = get_solver(solver)(compiled("tough_maze"), Budget(max_states=50))
    assert result.status == "budget" and result.stored <= 50 + 8  # one expansion adds <= 8 states


def test_slow_expansions_are_checked_often_enough_to_keep_the_time_limit():
    """A loop checks its budget when `expanded & meter.mask` is 0. With 1,024 expansions
    between checks, a heuristic costing 10 ms a state ran 10 s past a 0.3 s limit (LM-cut
    on large PDDL tasks: seconds); the mask adapts so checks come about CHECK_GAP apart,
    and fast loops still check only every 1,024 expansions."""
    import time
    from bcc.solvers.base import CHECK_EVERY, Meter

    def run(seconds_per_expansion, limit):
        meter = Meter(Budget(time_limit=limit))
        expanded, start = 0, time.perf_counter()
        while True:
            expanded += 1
            if seconds_per_expansion:
                time.sleep(seconds_per_expansion)
            if not expanded & meter.mask and meter.check(expanded, expanded, expanded):
                return time.perf_counter() - start, meter.mask
    overshoot, _ = run(0.01, 0.3)
    assert overshoot < 0.3 + 0.5
    _, mask = run(0, 0.05)
    assert mask == CHECK_EVERY - 1
