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
