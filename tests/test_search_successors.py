"""`Model.search_successors` (the generated `live`) against its definition: `successors`
less next states equal to the state and failure states that are not goals."""
import pytest

from bcc.compiler import compile_dungeon
from bcc.compiler.dungeon import shipped_dungeons


def reference(model, s):
    return [(a, n) for a, n in model.successors(s) if n != s and (not model.is_failure(n) or model.is_goal(n))]


@pytest.mark.parametrize("name", shipped_dungeons())
def test_live_successors_are_successors_less_self_loops_and_failures(name):
    model = compile_dungeon(name)
    live = model.search_successors()
    assert live is model.live_successors  # generated, not the fallback filter
    seen, frontier, failing = {model.initial}, [model.initial], 0
    while frontier and len(seen) < 400:
        state = frontier.pop(0)
        assert live(state) == reference(model, state)
        for _, n in model.successors(state):
            if n not in seen:
                seen.add(n)
                if model.is_failure(n):
                    failing += 1   # a failing state goes through the slow path: check it too
                    assert live(n) == reference(model, n)
                else:
                    frontier.append(n)
    if name == "bridge":
        assert failing, "bridge's lava should give failure states within 400 states"


def test_a_failure_state_is_kept_when_it_is_a_goal():
    """The goal wins when both hold (as `Model.step` says "goal" first)."""
    import dataclasses
    model = compile_dungeon("bridge")
    fallback = dataclasses.replace(model, live_successors=None, is_goal=lambda s: True,
                                   is_failure=lambda s: True).search_successors()
    nexts = fallback(model.initial)
    assert nexts and all(n != model.initial for _, n in nexts)
    dead = dataclasses.replace(model, live_successors=None, is_goal=lambda s: False,
                               is_failure=lambda s: True).search_successors()
    assert dead(model.initial) == []


def walk(model, limit=400):
    """The first `limit` states a breadth-first walk over `successors` reaches, failing ones included."""
    seen, frontier = {model.initial: None}, [model.initial]
    while frontier and len(seen) < limit:
        state = frontier.pop(0)
        for _, n in model.successors(state):
            if n not in seen:
                seen[n] = None
                frontier.append(n)
    return list(seen)


@pytest.mark.parametrize("name", shipped_dungeons())
def test_successors_build_the_states_apply_builds(name):
    """`successors` builds next states as integer sums where it can; each action's `apply`
    copies and writes a bytearray. Both must give the same bytes for every action."""
    model = compile_dungeon(name)
    for state in walk(model):
        expected = [(a, model.apply_fns[a](state)) for a in model.search_actions]
        assert model.successors(state) == [(a, n) for a, n in expected if n is not None]


@pytest.mark.parametrize("name", shipped_dungeons())
def test_fresh_is_live_with_the_duplicate_check(name):
    """`fresh(s, seen, out)` counts what `live` lists, stores each next state not yet in
    `seen` with `s` as its value and appends it to `out`, once, in `live`'s order."""
    model = compile_dungeon(name)
    fresh, live = model.search_fresh(), model.search_successors()
    assert fresh is model.fresh_successors   # generated, not the fallback
    states = walk(model)
    for i, state in enumerate(states):
        seen = dict.fromkeys(states[:i:3], "old")   # some next states were seen before
        out = ["x"]
        nexts = live(state)
        expected = []
        for _, n in nexts:
            if n not in seen and n not in expected:
                expected.append(n)
        assert fresh(state, seen, out) == len(nexts)
        assert out == ["x"] + expected
        assert all(seen[n] == state for n in expected)
        assert len(seen) == len(dict.fromkeys(states[:i:3])) + len(expected)


def test_the_fallback_fresh_filters_like_live():
    import dataclasses
    model = compile_dungeon("bridge")
    plain = dataclasses.replace(model, live_successors=None)   # no generated `fresh` either
    fresh = plain.search_fresh()
    assert fresh is not model.fresh_successors
    seen, out = {model.initial: None}, []
    assert fresh(model.initial, seen, out) == len(model.search_successors()(model.initial))
    assert out == [n for _, n in model.search_successors()(model.initial)]
