"""The counting abstraction (heuristics/counting.py) and its heuristic (`counting`).

Optimal costs come from independent searches (BFS, or an exhaustive backward Dijkstra
over every reachable state) or from a hand derivation in a comment. The heuristic must
never exceed the optimal cost-to-go (admissible) and must be consistent on every
transition; A* with it must find BFS's cost.
"""
from __future__ import annotations

import pytest

from bcc.compiler import compile_dungeon
from bcc.heuristics import counting
from bcc.heuristics.tables import counting_args
from bcc.generate_rooms import generate_manipulation
from bcc.simulate import replay
from bcc.solvers import Budget, get_solver
from bcc.heuristics.registry import make
from test_relaxed import TINY_ROOMS, exact_distances

BUDGET = Budget(time_limit=1200, max_memory_mb=6000)

# A corridor: the agent at (1, 1) faces north; a stone at (4, 1); it must end at x < 3
# and not in hand. The only way: rotate_right (face east), move, move (to x = 3, the
# stone in front), look_down, destroy_block (the stone goes to slot 1), rotate_right
# twice (face west: the front cell (2, 1) is free), change_item (select slot 1),
# place_block: 1 + 2 + 1 + 1 + 2 + 1 + 1 = 9 steps. Nothing can be skipped: mining needs
# the stone in front (only from x = 3 facing east) and looking down with the pickaxe
# selected; placing needs the stone selected and a free front cell at x < 3 (west).
CORRIDOR = """dungeon: corridor
domain: minecraft
height: 3
legend:
  "#": [bedrock, bedrock, bedrock]
  ".": [bedrock]
  "S": [bedrock]
  "M": [bedrock, burlap_stone]
map: |
  ######
  #S..M#
  ######
agent: {start: S, facing: north, looking: ahead, selected: 0}
inventory:
  - {item: diamond_pickaxe, count: 1}
goal: not agentHasBlock(agent, burlap_stone) and forall b in block . (b.blockType != burlap_stone or b.x < 3)
"""


def _write(tmp_path, name, text):
    path = tmp_path / f"{name}.yaml"
    path.write_text(text)
    return str(path)


def check(model, sample=None) -> int:
    """h <= the exact cost-to-go on every (sampled) reachable state, h consistent on
    each of their transitions, h = 0 on goal states; returns the start's optimal cost."""
    h = make("counting", model)
    assert not getattr(h, "fallback", None)
    order, dist = exact_distances(model)
    states = order if sample is None else order[::max(1, len(order) // sample)]
    for s in states:
        hs = h(s)
        if s in dist:
            assert hs <= dist[s], (model.name, hs, dist[s])
        else:
            assert hs >= 0
        if model.is_goal(s):
            assert hs == 0
            continue
        if model.is_failure(s):
            continue
        for a, n in model.search_successors()(s):
            assert hs <= model.action_costs[a] + h(n), (model.name, model.action_names[a])
    return dist[model.initial]


def test_corridor_distances_are_hand_derived(tmp_path):
    model = compile_dungeon(_write(tmp_path, "corridor", CORRIDOR))
    db = model.data("counting_database")
    # The stone's cell is the one cell kept exactly; the abstraction loses nothing here,
    # so the start's abstract distance is the true 9 (derived above).
    assert len(db.exact) == 1
    assert make("counting", model)(model.initial) == 9
    assert check(model) == 9
    assert get_solver("bfs")(model, BUDGET).cost == 9
    result = get_solver("astar")(model, BUDGET)
    assert result.heuristic == "counting" and result.cost == 9 and result.expanded == 9


def test_tiny_rooms_exhaustive(tmp_path):
    model = compile_dungeon(_write(tmp_path, "tiny_rooms", TINY_ROOMS))
    cost = check(model)
    result = get_solver("astar")(model, BUDGET)
    assert result.heuristic == "counting" and result.solved and result.cost == cost


@pytest.mark.parametrize("goal", [
    "forall b in block . (b.blockType != burlap_stone or b.x > 4)",
    "agentInRoom(agent, red) and forall b in block . (b.blockType != burlap_stone or b.z == 2)",
    "not agentHasBlock(agent, burlap_stone) and forall b in block . (b.y != 1 or b.x != 5 or b.z != 2 "
    "or b.blockType == burlap_stone)",
])
def test_other_goals_exhaustive(tmp_path, goal):
    """Other partitions of the cells (by column, by row, a goal that also pins the agent,
    a goal that asks a cell to be filled): admissible and consistent on every reachable
    state, and A* with the abstraction finds the exhaustive search's cost."""
    model = compile_dungeon(_write(tmp_path, "tiny_rooms", TINY_ROOMS), goal=goal)
    assert model.data("counting_database") is not None
    cost = check(model)
    result = get_solver("astar")(model, BUDGET, heuristic="counting")
    assert result.solved and result.cost == cost


@pytest.mark.parametrize("stones", [1, 2])
def test_manipulation_rooms_admissible_and_optimal(tmp_path, stones):
    model = compile_dungeon(_write(tmp_path, f"rooms{stones}", generate_manipulation(stones)))
    bfs = get_solver("bfs")(model, BUDGET)
    assert bfs.cost == {1: 19, 2: 25}[stones]   # also notes/manipulation.md's BFS figures
    result = get_solver("astar")(model, BUDGET)
    assert result.heuristic == "counting" and result.cost == bfs.cost
    assert result.expanded * 20 < bfs.expanded
    assert replay(model, [(p, 1, 1) for p in result.plan]).valid
    h = make("counting", model)
    assert bfs.cost - 2 <= h(model.initial) <= bfs.cost


@pytest.mark.slow
def test_manipulation_two_stones_consistent_on_a_sample(tmp_path):
    """Consistent on every transition of the first 40,000 states in breadth-first order,
    and 0 on goal states (with consistency, what makes it admissible)."""
    model = compile_dungeon(_write(tmp_path, "rooms2", generate_manipulation(2)))
    h = make("counting", model)
    successors = model.search_successors()
    seen, order = {model.initial}, [model.initial]
    for s in order:
        if len(order) > 40_000:
            break
        hs = h(s)
        if model.is_goal(s):
            assert hs == 0
            continue
        for a, n in successors(s):
            assert hs <= model.action_costs[a] + h(n)
            if n not in seen:
                seen.add(n)
                order.append(n)


@pytest.mark.parametrize("name", ["bridge", pytest.param("tough_maze", marks=pytest.mark.slow),
                                  pytest.param("pasture", marks=pytest.mark.slow)])
def test_other_dungeons_stay_optimal_with_counting(model_of, name):
    """Where the abstraction builds (the tough maze's stones, pasture's inventory), A* with
    it finds BFS's cost; where it does not (bridge's goal reads the cell under the agent),
    it falls back to blind search, still optimal."""
    model = model_of(name)
    bfs = get_solver("bfs")(model, BUDGET)
    result = get_solver("astar")(model, BUDGET, heuristic="counting")
    assert result.solved and result.cost == bfs.cost
    h = make("counting", model)
    assert h(model.initial) <= bfs.cost


def test_auto_uses_counting_only_where_the_goal_needs_cells_changed(model_of, tmp_path):
    # pasture's goal reads variables alone (an animal fed): blind search solves it in
    # 189 expansions, far cheaper than the abstraction's 265,000 states.
    assert not model_of("pasture").data("counting_wanted")
    assert get_solver("astar")(model_of("pasture"), BUDGET).heuristic == "blind"
    assert compile_dungeon(_write(tmp_path, "corridor", CORRIDOR)).data("counting_wanted")


def test_a_goal_no_abstract_state_meets_is_infinite(tmp_path):
    # Every cell at (5, y, 2) must hold a stone, the floor's bedrock too: no plan.
    goal = "forall b in block . (b.blockType == burlap_stone or b.x != 5 or b.z != 2)"
    model = compile_dungeon(_write(tmp_path, "tiny_rooms", TINY_ROOMS), goal=goal)
    assert make("counting", model)(model.initial) == float("inf")
    result = get_solver("astar")(model, BUDGET, heuristic="counting")
    assert not result.solved and result.status == "no_solution" and result.expanded == 0


def test_auto_uses_counting_where_the_goal_also_pins_the_agent(tmp_path):
    """With "and the agent in the red room" the position heuristics see the agent's part
    only; auto takes the counting abstraction (which keeps the agent's position too)."""
    goal = ("not agentHasBlock(agent, burlap_stone) and agentInRoom(agent, red) and "
            "forall b in block . (b.blockType != burlap_stone or blockInRoom(b, blue))")
    model = compile_dungeon(_write(tmp_path, "rooms1", generate_manipulation(1)), goal=goal)
    bfs = get_solver("bfs")(model, BUDGET)
    result = get_solver("astar")(model, BUDGET)
    assert result.heuristic == "counting" and result.cost == bfs.cost and result.expanded * 20 < bfs.expanded


def test_unsupported_goals_give_no_database(model_of):
    # bridge: the goal reads the cell under the agent, whose position changes.
    assert model_of("bridge").data("counting_database") is None
    # grid: nothing in the grid can change; the abstraction would be the whole model.
    assert model_of("grid").data("counting_database") is None


def test_a_build_stopped_by_its_time_limit_is_not_cached(tmp_path, monkeypatch):
    monkeypatch.setenv("BCC_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.delenv("BCC_NO_CACHE", raising=False)
    path = _write(tmp_path, "rooms2", generate_manipulation(2))
    assert compile_dungeon(path).data("counting_database", time_limit=1e-9) is None
    assert not list((tmp_path / "cache").glob("counting/*.pickle"))
    calls = []
    build = counting.build
    monkeypatch.setattr(counting, "build", lambda *a, **k: calls.append(1) or build(*a, **k))
    first = compile_dungeon(path).data("counting_database")
    again = compile_dungeon(path).data("counting_database")
    assert first is not None and again.table == first.table and len(calls) == 1
    assert list((tmp_path / "cache").glob("counting/*.pickle"))


def test_variables_are_projected_away_past_the_first_limit(tmp_path, monkeypatch):
    """Past FULL_STATES the selected slot (9 values, read by no goal and no cell position)
    is projected away: fewer abstract states, still admissible and consistent everywhere
    (exhaustive), and A* still finds BFS's cost."""
    monkeypatch.setenv("BCC_NO_CACHE", "1")
    path = _write(tmp_path, "tiny_rooms", TINY_ROOMS)
    full = compile_dungeon(path).data("counting_database")
    assert full.projected == ()
    monkeypatch.setattr(counting, "FULL_STATES", full.states - 1)
    model = compile_dungeon(path)
    db = model.data("counting_database")
    labels = [v.label for v in model.variables]
    assert [labels[j] for j, _ in db.projected] == ["agent.selectedItem"] and db.states < full.states
    cost = check(model)
    result = get_solver("astar")(model, BUDGET)
    assert result.heuristic == "counting" and result.cost == cost


def test_state_limit_gives_up(tmp_path):
    model = compile_dungeon(_write(tmp_path, "rooms2", generate_manipulation(2)))
    args = counting_args(model.data("compiled"))
    assert counting.build_or_none(*args, max_states=1000) == {"db": None}
    assert counting.build(*args, max_states=20_000).projected    # 26,568 states with every variable
    with pytest.raises(counting.TooBig):
        counting.build(*args, max_states=1000)


def test_cli_solves_manipulation_with_counting(tmp_path):
    import json
    import subprocess
    import sys
    path = _write(tmp_path, "rooms2", generate_manipulation(2))
    out = subprocess.run([sys.executable, "-m", "bcc", "solve", path, "--json"], capture_output=True, text=True,
                         env={**__import__("os").environ, "BCC_CACHE_DIR": str(tmp_path / "cache")})
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert data["cost"] == 25 and data["heuristic"] == "counting" and data["expanded"] < 200


def test_cli_time_limit_bounds_the_build(tmp_path):
    """8 stones: the abstraction takes about 5 s of CPU to build (here; its first try
    stops at 500,000 states, then the selected slot is projected away), 10x the limit:
    --time-limit 0.5 stops the command (exit 1, a budget result) and leaves no database
    in the cache."""
    import json
    import os
    import subprocess
    import sys
    path = _write(tmp_path, "rooms8", generate_manipulation(8))
    cache = tmp_path / "cache"
    out = subprocess.run([sys.executable, "-m", "bcc", "solve", path, "--json", "--time-limit", "0.5"],
                         capture_output=True, text=True, env={**os.environ, "BCC_CACHE_DIR": str(cache)})
    assert out.returncode == 1, out.stderr
    assert json.loads(out.stdout)["status"] == "budget"
    assert not list(cache.glob("counting/*.pickle"))
