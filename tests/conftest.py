"""Shared fixtures: compiled shipped dungeons are cached per session (compiling is pure)."""
from __future__ import annotations

import functools

import pytest

from bcc.compiler import compile_dungeon

REFERENCE = ["grid", "bridge", "easy_maze", "tough_maze", "four_rooms"]
FOUR_ROOMS_GOALS = ["red", "orange", "green", "blue"]


@functools.lru_cache(maxsize=None)
def compiled(name: str, goal: str | None = None):
    return compile_dungeon(name, goal=goal)


@pytest.fixture
def model_of():
    return compiled


def replays(model, plan) -> bool:
    """The plan, stepped through the simulator's apply, reaches the goal."""
    s = model.initial
    for name in plan:
        s = model.apply(model.action_index(name), s)
        assert s is not None, name
    return model.is_goal(s)
