"""Safety of the compiler's analyses: reachability, relevance pruning, heuristics.

Each claim is checked against exhaustive search on instances small enough for it:
pruned search must find the same optimal cost as unpruned BFS; actions reported never
applicable must not apply in any reachable state; the pattern database and Manhattan
must never overestimate the true remaining cost and must be consistent.
"""
from __future__ import annotations

import dataclasses
import random
from collections import deque

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bcc.compiler import compile_dungeon
from bcc.solvers import Budget, get_solver
from bcc.heuristics.registry import make

from conftest import compiled

SMALL = ["grid", "bridge", "easy_maze", "four_rooms", "four_rooms_orange", "four_rooms_green"]
BUDGET = Budget(time_limit=120)


def reachable_states(model, limit=200_000):
    """Every state reachable with all actions (unpruned successors via apply)."""
    seen = {model.initial}
    queue = deque([model.initial])
    while queue:
        s = queue.popleft()
        if model.is_failure(s) or model.is_goal(s):
            continue
        for a in range(len(model.action_names)):
            n = model.apply(a, s)
            if n is not None and n not in seen:
                seen.add(n)
                queue.append(n)
                if len(seen) > limit:
                    raise AssertionError("state space too large for this test")
    return seen


@pytest.mark.parametrize("name", SMALL)
def test_pruned_search_keeps_the_optimal_cost(name):
    full = compile_dungeon(name, prune=False)
    pruned = compiled(name)
    assert len(full.search_actions) == len(full.action_names)
    reference = get_solver("bfs")(full, BUDGET)
    for solver in ("bfs", "astar", "idastar"):
        assert get_solver(solver)(pruned, BUDGET).cost == reference.cost, solver


@pytest.mark.parametrize("name", ["grid", "bridge", "four_rooms"])
def test_never_applicable_actions_never_apply(name):
    model = compile_dungeon(name, prune=False)
    never = {model.action_index(a) for a in model.report["never_applicable"]}
    for s in reachable_states(model):
        for a in never:
            assert model.apply(a, s) is None


def test_maze_without_stones_prunes_looking_and_slots():
    # No mineable block exists and nothing placeable can enter the inventory, so mining
    # and placing can never apply, and looking down / changing slots then matter to nothing.
    report = compiled("easy_maze").report
    assert set(report["never_applicable"]) == {"destroy_block", "place_block"}
    assert set(report["pruned_from_search"]) == {"look_down", "look_ahead", "change_item",
                                                 "destroy_block", "place_block"}
    assert compiled("bridge").report["pruned_from_search"] == []


def test_unchanged_layers_leave_the_state():
    # In the tough maze stones are mined at foot level and placed back only at foot level
    # (the floor is all bedrock and gold, never air or lava), so only layer 1 changes.
    assert compiled("tough_maze").report["mutable_layers"] == [1]
    assert compiled("bridge").report["mutable_layers"] == [0, 1]


def true_costs(model):
    """Exact cost-to-goal of every reachable state, by backward search over the full graph."""
    states = reachable_states(model)
    preds = {s: [] for s in states}
    for s in states:
        if model.is_failure(s) or model.is_goal(s):
            continue
        for a in range(len(model.action_names)):
            n = model.apply(a, s)
            if n is not None:
                preds[n].append((s, model.action_costs[a]))
    dist = {s: 0 for s in states if model.is_goal(s)}
    queue = deque(dist)  # unit costs: a BFS backwards is exact
    while queue:
        u = queue.popleft()
        for p, c in preds[u]:
            if p not in dist:
                dist[p] = dist[u] + c
                queue.append(p)
    return states, dist


@pytest.mark.parametrize("name", ["grid", "bridge", "four_rooms_green"])
@pytest.mark.parametrize("heuristic", ["pdb", "manhattan"])
def test_heuristics_are_admissible_and_consistent(name, heuristic):
    model = compile_dungeon(name, prune=False)
    h = make(heuristic, model)
    states, dist = true_costs(model)
    for s in states:
        if s in dist:
            assert h(s) <= dist[s]
        if model.is_failure(s) or model.is_goal(s):
            continue
        for a in range(len(model.action_names)):
            n = model.apply(a, s)
            if n is not None and not model.is_failure(n):
                assert h(s) <= model.action_costs[a] + h(n)


def test_pdb_admissible_on_tough_maze_samples():
    # The tough maze is too large to enumerate; sample states along random walks and
    # compare h with the optimal cost found by A* from each (manhattan, an independent
    # admissible heuristic, so this does not trust the pdb it checks).
    model = compiled("tough_maze")
    h = make("pdb", model)
    rng = random.Random(7)
    s = model.initial
    for step in range(40):
        options = [n for _, n in model.successors(s) if not model.is_failure(n)]
        s = rng.choice(options)
        if step % 10 == 9:
            from_here = dataclasses.replace(model, initial=s)
            result = get_solver("astar")(from_here, BUDGET, heuristic="manhattan")
            assert result.solved and h(s) <= result.cost


@pytest.mark.parametrize("solver,bound", [("wastar", 2.0), ("gbfs", None)])
def test_suboptimal_solvers_find_valid_plans(solver, bound):
    from bcc.simulate import replay
    for name in ["bridge", "tough_maze", "easy_maze"]:
        model = compiled(name)
        result = get_solver(solver)(model, BUDGET)
        optimal = get_solver("astar")(model, BUDGET).cost
        assert result.solved and replay(model, [(a, 1, 1) for a in result.plan]).valid
        if bound:
            assert result.cost <= bound * optimal


def _layout(width, depth, height, grid, default):
    from types import SimpleNamespace
    return SimpleNamespace(width=width, depth=depth, height=height, static_grid=bytes(grid), grid_default=default)


@settings(max_examples=200, deadline=None)
@given(st.data())
def test_the_box_reader_is_the_union_of_its_cells(data):
    """reachability's `box` (every cell of a box at once) answers what the cell-by-cell
    union does, out-of-range coordinates and written layers included."""
    import itertools

    from bcc.compiler.reachability import Analysis
    w, d, h = (data.draw(st.integers(1, 4)) for _ in range(3))
    grid = data.draw(st.lists(st.integers(0, 5), min_size=w * d * h, max_size=w * d * h))
    an = Analysis(_layout(w, d, h, grid, 0), 6)
    written = {y: frozenset(data.draw(st.sets(st.integers(0, 9), max_size=3))) for y in range(h) if data.draw(st.booleans())}
    coords = st.sets(st.integers(-2, 6), max_size=4)
    xs, ys, zs = data.draw(coords), data.draw(coords), data.draw(coords)
    cell, _ = an.cells(written)
    expected = set()
    for x, y, z in itertools.product(xs, ys, zs):
        expected |= cell(x, y, z)
    assert an.box(written)(xs, ys, zs) == frozenset(expected)


@settings(max_examples=300, deadline=None)
@given(st.sampled_from(["==", "!=", "<", "<=", ">", ">="]),
       st.frozensets(st.integers(-3, 5), min_size=1, max_size=5),
       st.frozensets(st.integers(-3, 5), min_size=1, max_size=5))
def test_a_comparison_of_two_value_sets_has_the_outcomes_of_its_pairs(op, a, b):
    """The abstract comparison of two sets (compiler/abstract.py: by meeting sets and by
    bounds, without the pairs) answers what comparing every pair of values does."""
    import itertools

    from bcc.compiler import ir
    from bcc.compiler.abstract import _CMP, Abstract

    left, right = ir.Local("l", "int"), ir.Local("r", "int")
    ab = Abstract({}, None, pins={left: a, right: b})
    got = ab.eval(ir.Cmp((op,), (left, right)))
    assert got == frozenset(_CMP[op](x, y) for x, y in itertools.product(a, b))
