"""The relaxed view and its heuristics (heuristics/relaxed_view.py, heuristics/relaxed.py).

Every optimal cost-to-go here comes from an independent exhaustive search: all states
reachable from the start, then a backward Dijkstra from the goal states over the
reversed transitions. hmax and LM-cut must never exceed it (admissible), hmax must be
consistent on every transition, and LM-cut dominates hmax (a theorem of Helmert and
Domshlak 2009, so a violation is a bug). A* with LM-cut must find BFS's cost.
"""
from __future__ import annotations

import dataclasses

import heapq

import pytest

from bcc.compiler import compile_dungeon
from bcc.generate import generate_maze
from bcc.generate_rooms import generate_manipulation
from bcc.simulate import replay
from bcc.solvers import Budget, get_solver
from bcc.heuristics.relaxed import relaxed_of

BUDGET = Budget(time_limit=1200, max_memory_mb=6000)  # generous: the machine may be shared

# Two rooms; one stone in the red room to carry into the blue one through the door (4, 2).
TINY_ROOMS = """dungeon: tiny_rooms
domain: minecraft
height: 3
legend:
  "r": [red_wool, red_wool, red_wool]
  "b": [blue_wool, blue_wool, blue_wool]
  ".": [bedrock]
  "S": [bedrock]
  "M": [bedrock, burlap_stone]
map: |
  rrrrbbbb
  r.M.b..b
  rS.....b
  rrrrbbbb
agent: {start: S, facing: north, looking: ahead, selected: 0}
inventory:
  - {item: diamond_pickaxe, count: 1}
rooms:
  - {name: red, color: red, x: [0, 4], z: [0, 3]}
  - {name: blue, color: blue, x: [4, 7], z: [0, 3]}
goal: not agentHasBlock(agent, burlap_stone) and forall b in block . (b.blockType != burlap_stone or blockInRoom(b, blue))
"""


def _write(tmp_path, name, text):
    path = tmp_path / f"{name}.yaml"
    path.write_text(text)
    return str(path)


def exact_distances(model, limit=200_000):
    """State -> optimal cost to the goal, for every reachable state that can reach it."""
    preds = {model.initial: []}
    order = [model.initial]
    i = 0
    while i < len(order):
        s = order[i]
        i += 1
        if model.is_goal(s) or model.is_failure(s):
            continue
        for a, n in model.successors(s):
            if n not in preds:
                preds[n] = []
                order.append(n)
                assert len(order) <= limit, "the model is too big for an exhaustive check"
            preds[n].append((s, a))
    dist = {s: 0 for s in order if model.is_goal(s)}
    heap = [(0, s) for s in dist]
    while heap:
        d, s = heapq.heappop(heap)
        if d > dist[s]:
            continue
        for p, a in preds[s]:
            nd = d + model.action_costs[a]
            if nd < dist.get(p, nd + 1):
                dist[p] = nd
                heapq.heappush(heap, (nd, p))
    return order, dist


def check_admissible(model, sample=None):
    r = relaxed_of(model)
    assert r is not None
    order, dist = exact_distances(model)
    states = order if sample is None else order[::max(1, len(order) // sample)]
    checked = 0
    for s in states:
        if model.is_failure(s):
            continue
        hmax, lmcut = r.hmax(s), r.lmcut(s)
        assert hmax <= lmcut, (model.name, hmax, lmcut)
        if s in dist:
            assert lmcut <= dist[s], (model.name, r.facts_of(s), lmcut, dist[s])
            checked += 1
        # hmax is consistent: h(s) <= c(a) + h(s') on every transition.
        if not model.is_goal(s):
            for a, n in model.successors(s):
                if not model.is_failure(n):
                    assert hmax <= model.action_costs[a] + r.hmax(n)
    assert checked > 0
    return dist[model.initial]


def test_grid_exhaustive():
    model = compile_dungeon("grid")
    assert check_admissible(model) == 7   # hand-derived in tests/test_solvers.py


@pytest.mark.slow
def test_tiny_rooms_exhaustive(tmp_path):
    model = compile_dungeon(_write(tmp_path, "tiny_rooms", TINY_ROOMS))
    cost = check_admissible(model)
    result = get_solver("astar")(model, BUDGET, heuristic="lmcut")
    assert result.solved and result.cost == cost


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(4))
def test_generated_mazes_admissible_and_optimal(tmp_path, seed):
    text = generate_maze(7, 7, stones=1 + seed % 2, lava=seed % 2, seed=seed)
    model = compile_dungeon(_write(tmp_path, f"maze{seed}", text))
    cost = check_admissible(model, sample=300)
    bfs = get_solver("bfs")(model, BUDGET)
    assert bfs.cost == cost
    for heuristic in ("lmcut", "hmax"):
        result = get_solver("astar")(model, BUDGET, heuristic=heuristic)
        assert result.solved and result.cost == cost, heuristic
        assert replay(model, [(p, 1, 1) for p in result.plan]).valid


@pytest.mark.slow
@pytest.mark.parametrize("heuristic", ["hff", "hadd"])
def test_greedy_plans_replay(tmp_path, heuristic):
    model = compile_dungeon(_write(tmp_path, "rooms2", generate_manipulation(2)))
    result = get_solver("gbfs")(model, BUDGET, heuristic=heuristic)
    assert result.solved
    check = replay(model, [(p, 1, 1) for p in result.plan])
    assert check.valid and check.cost == result.cost


@pytest.mark.parametrize("evaluation", ["eager", "lazy"])
def test_greedy_evaluation_modes(tmp_path, monkeypatch, evaluation):
    """Lazy evaluation computes h once per expanded state (plus the start), eager once per
    new successor; both plans replay."""
    from bcc.heuristics import registry as heuristics
    model = compile_dungeon(_write(tmp_path, "tiny", TINY_ROOMS))
    calls = [0]
    entry = heuristics.HEURISTICS["hff"]

    def counted(m, *args, **kw):
        h = entry.build(m, *args, **kw)

        def wrapped(state):
            calls[0] += 1
            return h(state)
        return wrapped
    monkeypatch.setitem(heuristics.HEURISTICS, "hff", dataclasses.replace(entry, make=counted))
    result = get_solver("gbfs")(model, BUDGET, heuristic="hff", evaluation=evaluation)
    assert result.solved
    assert replay(model, [(p, 1, 1) for p in result.plan]).valid
    if evaluation == "lazy":
        assert calls[0] <= result.expanded + 1
    else:
        assert calls[0] > result.expanded + 1


def test_last_step_view_sees_the_carry(tmp_path):
    """hff and hadd read the view whose goal is reached by a last action
    (heuristics/relaxed_last.py). Carrying the stone into the blue room: the plain delete
    relaxation empties the hand anywhere (its relaxed plan ignores the walk), the
    last-step view must place it in the blue room. Once the stone is in hand, what is
    left (walk, select, place) has no deletes that matter, so its hff is the exact cost
    to go (from the exhaustive backward search); at the goal it is 0."""
    model = compile_dungeon(_write(tmp_path, "tiny", TINY_ROOMS))
    r = relaxed_of(model)
    assert r.guide is not None and r.task.guide.goal != r.task.goal
    order, dist = exact_distances(model)
    plan = get_solver("bfs")(model, BUDGET).plan
    guide, state, carrying = r.guide, model.initial, False
    for name in [None] + plan:
        if name is not None:
            state = model.apply(model.action_index(name), state)
            carrying = carrying or name == "destroy_block"
        h = r.hff(state)
        r.guide = None
        plain = r.hff(state)
        r.guide = guide
        assert h >= plain
        if carrying:
            assert h == dist[state], (name, h, dist[state])
    assert model.is_goal(state) and r.hff(state) == r.hadd(state) == 0
    assert r.hff(model.initial) > r.lmcut(model.initial)


def test_guiding_view_counts_each_thing_put_down(tmp_path):
    """A count that an action moves by one (stones in hand) walks through its values in
    the relaxed view by fired steps; in the guiding view each step costs the action, and
    the last placing needs a hand holding one stone (the slot empties only then). An
    action's own operator in the relaxed plan makes one of its steps (it is charged once,
    not once more for the step), so k stones in hand cost k placings. Along BFS's plan
    (every suffix of an optimal plan is optimal, so the steps left are the exact cost to
    go), with two stones in hand hff is therefore never more than two short (it counts
    both placings, not the turn between them: without deletes the relaxed plan puts both
    in the same free cell, and the walk shares moves), where steps costing nothing (one
    placing seen) leave it three short after the second stone is mined; from the doorway
    on it is at most one short. LM-cut, admissible, stays below the exact cost."""
    text = TINY_ROOMS.replace("r.M.b..b", "rMM.b..b")
    model = compile_dungeon(_write(tmp_path, "two", text))
    r = relaxed_of(model)
    plan = get_solver("bfs")(model, BUDGET).plan
    assert plan.count("place_block") == 2
    state, mined = model.initial, 0
    for i, name in enumerate(plan):
        state = model.apply(model.action_index(name), state)
        mined += name == "destroy_block"
        left = len(plan) - i - 1
        assert r.lmcut(state) <= left
        if mined == 2 and "place_block" not in plan[:i + 1]:
            assert left - 2 <= r.hff(state) <= left, (name, r.hff(state), left)
        if i >= plan.index("change_item"):
            assert left - 1 <= r.hff(state) <= left, (name, r.hff(state), left)
    assert r.hff(state) == 0


def test_gbfs_auto_picks_hff_where_the_pattern_database_is_blind(tmp_path):
    """gbfs's `auto`: on a carrying goal the position pattern database says 0 at the start
    although the goal does not hold, so hff guides; on a position goal (grid) the pattern
    database is kept. Both plans replay to the goal."""
    from bcc.heuristics import registry as heuristics
    carry = compile_dungeon(_write(tmp_path, "tiny", TINY_ROOMS))
    assert heuristics.make("pdb", carry)(carry.initial) == 0
    for model, expected in ((carry, "hff"), (compile_dungeon("grid"), "pdb")):
        result = get_solver("gbfs")(model, BUDGET)
        assert result.solved and result.heuristic == expected
        assert replay(model, [(p, 1, 1) for p in result.plan]).valid


def test_relaxed_view_facts_and_goal():
    """The grid's goal is the agent on the gold at (1, 1): one fact of the merged (x, z) group."""
    model = compile_dungeon("grid")
    task = model.data("relaxed_task")
    assert [task.labels[g] for g in task.goal] == ["agent.x=1, agent.z=1"]
    assert ["agent.x", "agent.z"] in task.stats["groups"]
    facts = task.state_facts(model.dense(model.initial))
    assert any(task.labels[f] == "agent.x=1, agent.z=3" for f in facts)


def test_goal_that_cannot_hold_is_infinite(tmp_path):
    model = compile_dungeon("four_rooms", goal="agentHasBlock(agent, gold)")
    r = relaxed_of(model)
    assert r.hmax(model.initial) == r.lmcut(model.initial) == float("inf")
    result = get_solver("astar")(model, BUDGET, heuristic="lmcut")
    assert not result.solved and result.status == "no_solution"


@pytest.mark.parametrize("seed", range(3))
def test_pruning_keeps_bfs_optimal(tmp_path, seed):
    """Backward relevance (compiler/relevance.py) and the static folding of unchanged
    attributes and layers: BFS on the pruned model finds the unpruned model's cost."""
    text = generate_maze(7, 7, stones=1 + seed, seed=10 + seed)
    path = _write(tmp_path, f"prune{seed}", text)
    pruned, full = compile_dungeon(path), compile_dungeon(path, prune=False)
    assert len(pruned.search_actions) <= len(full.search_actions)
    a, b = get_solver("bfs")(pruned, BUDGET), get_solver("bfs")(full, BUDGET)
    assert a.solved and b.solved and a.cost == b.cost
    assert a.expanded <= b.expanded


@pytest.mark.slow
def test_manipulation_rooms_pruned_and_relaxed_agree_with_bfs(tmp_path):
    model = compile_dungeon(_write(tmp_path, "rooms1", generate_manipulation(1)))
    full = compile_dungeon(_write(tmp_path, "rooms1", generate_manipulation(1)), prune=False)
    bfs = get_solver("bfs")(full, BUDGET)
    assert get_solver("bfs")(model, BUDGET).cost == bfs.cost
    result = get_solver("astar")(model, BUDGET, heuristic="lmcut")
    assert result.solved and result.cost == bfs.cost
    assert result.expanded < bfs.expanded


def test_the_relaxed_view_is_built_once_and_cached(tmp_path, monkeypatch):
    """A second compile of the same dungeon reads the relaxed view from the on-disk cache
    (the same facts, operators and goal, and the same heuristic values); another goal
    builds its own; with the cache off it is rebuilt, equal to the cached one."""
    from bcc.heuristics import relaxed_view as relaxed
    monkeypatch.setenv("BCC_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.delenv("BCC_NO_CACHE", raising=False)
    calls = []
    build = relaxed.build
    monkeypatch.setattr(relaxed, "build", lambda *a, **k: calls.append(1) or build(*a, **k))
    path = _write(tmp_path, "tiny", TINY_ROOMS)

    def view(task):
        return (task.n_facts, task.pre, task.add, task.cost, task.action, task.goal,
                task.guide.pre, task.guide.add, task.guide.cost, task.guide.goal)

    first = compile_dungeon(path)
    again = compile_dungeon(path)
    assert view(again.data("relaxed_task")) == view(first.data("relaxed_task")) and len(calls) == 1
    assert list((tmp_path / "cache" / "relaxed").glob("*.pickle"))
    states = [first.initial] + [n for _, n in first.successors(first.initial)]
    assert [relaxed_of(again).hff(s) for s in states] == [relaxed_of(first).hff(s) for s in states]
    other = compile_dungeon(path, goal="not agentHasBlock(agent, burlap_stone)")
    assert other.data("relaxed_task") is not None and len(calls) == 2
    monkeypatch.setenv("BCC_NO_CACHE", "1")
    assert view(compile_dungeon(path).data("relaxed_task")) == view(first.data("relaxed_task"))
    assert len(calls) == 3


def test_incremental_exploration_matches_a_fresh_one(tmp_path):
    """The fast exploration keeps its operator counters from the last state it saw and
    moves them by the facts that changed: on states visited in a scrambled order (far
    jumps, repeats) its hadd and hmax costs of the goal facts must equal those of the
    plain exploration (LM-cut's), which starts from nothing each time."""
    import random
    model = compile_dungeon(_write(tmp_path, "rooms2", generate_manipulation(2)))
    r = relaxed_of(model)
    rng = random.Random(7)
    states, frontier = [model.initial], [model.initial]
    seen = {model.initial}
    while frontier and len(states) < 150:
        s = frontier.pop(rng.randrange(len(frontier)))
        for _, n in model.successors(s):
            if n not in seen and not model.is_failure(n):
                seen.add(n)
                states.append(n)
                frontier.append(n)
    order = states + rng.sample(states, len(states))
    for view in (r, r.guide):
        for s in order:
            facts = view.facts_of(s)
            for additive in (True, False):
                fast, _, _ = view.fast().explore(facts, view.cost, additive)
                slow, _, _ = view.exact().explore(facts, view.cost, additive)
                assert view.goal_cost(fast, additive) == view.goal_cost(slow, additive)
                assert all(fast[g] == slow[g] for g in view.goal)


def test_a_build_stopped_by_its_time_limit_is_not_cached(tmp_path, monkeypatch):
    """The view's time limit stops its build (None: search without it); nothing is kept
    for the next solve, and a later call with time builds the view and keeps it."""
    monkeypatch.setenv("BCC_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.delenv("BCC_NO_CACHE", raising=False)
    model = compile_dungeon(_write(tmp_path, "rooms2", generate_manipulation(2)))
    assert model.data("relaxed_task", time_limit=1e-9) is None
    assert not list((tmp_path / "cache").glob("relaxed/*.pickle"))
    assert model.data("relaxed_task") is not None
    assert len(list((tmp_path / "cache").glob("relaxed/*.pickle"))) == 1
