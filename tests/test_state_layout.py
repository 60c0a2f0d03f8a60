"""Compact states: the variables, then only the cells that differ from the start.

Checked against the dense layout (every mutable cell one byte), which the compiler still
emits for the PDDL export: on random walks, the compact successor code and the dense
code must make the same worlds, the state must be canonical (equal worlds, equal bytes),
and the one accessor, `Model.view`, must read what the dense state holds.
"""
from __future__ import annotations

import random

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bcc.compiler import compile_dungeon
from bcc.compiler.emit_helpers import one_entry_apart
from bcc.generate import generate_maze
from bcc.model import pack_entry

from conftest import compiled

DUNGEONS = ["bridge", "tough_maze", "four_rooms", "grid", "easy_maze"]


def walk(model, steps: int, seed: int):
    rng = random.Random(seed)
    state = model.initial
    for _ in range(steps):
        yield state
        nexts = model.successors(state)
        if not nexts or model.is_terminal(state):
            state = model.initial
            continue
        _, state = rng.choice(nexts)


def dense_cell(model, dense: bytes, x, y, z) -> int:
    g = model.grid
    k = g.mutable_index(x, y, z)
    if k is None:
        return g.cell(model.initial, x, y, z)
    return dense[g.base + k]


@pytest.mark.parametrize("name", DUNGEONS)
def test_compact_code_matches_the_dense_code_on_random_walks(name):
    model = compiled(name)
    dense_fns = model.data("dense_functions")
    g = model.grid
    for state in walk(model, 400, seed=len(name)):
        d = model.dense(state)
        assert model.compact(d) == state, "dense and compact are inverse; the diff is canonical"
        assert (len(state) - g.base) % 4 == 0
        index = [int.from_bytes(state[p:p + 4], "little") >> 8 for p in range(g.base, len(state), 4)]
        assert index == sorted(set(index))
        view = model.view(state)
        for (x, y, z), v in view.changed().items():
            assert v != g.cell(model.initial, x, y, z), "only cells that differ from the start are stored"
        assert np.array_equal(view.grid()[list(g.layers)] if g.layers else view.grid()[:0],
                              np.array([[[dense_cell(model, d, x, y, z) for x in range(g.width)]
                                         for z in range(g.depth)] for y in g.layers], dtype=np.uint8)
                              .reshape(len(g.layers), g.depth, g.width))
        assert dense_fns["goal"](d) == model.is_goal(state)
        assert dense_fns["failure"](d) == model.is_failure(state)
        for a in range(len(model.action_names)):
            compact_next = model.apply(a, state)
            dense_next = dense_fns[f"apply_{a}"](d)
            assert (compact_next is None) == (dense_next is None)
            if compact_next is not None:
                assert model.dense(compact_next) == dense_next
        for a, nxt in model.successors(state):
            assert nxt == model.apply(a, state)


def test_mining_and_placing_back_gives_the_start_bytes():
    """A stone mined and put back where it was: the same world, so the same state."""
    model = compiled("bridge")
    seen = {}
    for state in walk(model, 3000, seed=3):
        world = model.dense(state)
        assert seen.setdefault(world, state) == state


def test_view_reads_variables_and_cells():
    model = compiled("bridge")
    view = model.view(model.initial)
    for i, v in enumerate(model.variables):
        assert view.raw(i) == model.initial[v.index]
        assert view.var(i) == model.initial[v.index] + v.lo
    assert view.changed() == {}
    g = model.grid
    static = np.frombuffer(g.static, dtype=np.uint8).reshape(g.height, g.depth, g.width)
    assert np.array_equal(view.grid(), static)
    assert view.cell(-1, 0, 0) == g.default


def test_bytes_per_state_do_not_grow_with_the_map(tmp_path):
    """51x51 with 12 stones: 64 bytes at most at the start, 4 per changed cell (the dense
    layout needed 5,226)."""
    path = tmp_path / "maze.yaml"
    path.write_text(generate_maze(51, 51, stones=12, seed=1))
    model = compile_dungeon(path)
    report = model.report["state_bytes"]
    assert report["start"] == len(model.initial) <= 64
    assert report["per_changed_cell"] == 4 and report["dense"] == 5226
    for state in walk(model, 2000, seed=1):
        assert len(state) == report["start"] + 4 * len(model.view(state).changed())
    sizes = model.state_sizes(2000)
    assert sizes["largest"] <= 64 + 4 * 12


@settings(max_examples=300, deadline=None)
@given(st.dictionaries(st.integers(0, 40), st.integers(0, 255), max_size=12), st.integers(0, 40),
       st.integers(0, 255), st.integers(0, 40))
def test_one_entry_apart_finds_the_one_changed_cell(cells, cell, value, other):
    """Two changed-cell diffs (sorted packed entries of the cells that differ from the
    start) a single write apart give that write back; diffs further apart give None."""
    start = bytes(41)

    def diff(changed):
        return b"".join(pack_entry(k, v) for k, v in sorted(changed.items()) if v != start[k])

    before = diff(cells)
    after_cells = {**cells, cell: value}
    after = diff(after_cells)
    found = one_entry_apart(before, after, start)
    if before == after:
        return                       # no change: nothing to patch (derive returns before asking)
    assert found == (cell, value)
    further = {**after_cells, other: (after_cells.get(other, 0) + 1) % 256}
    if other != cell and diff(further) != after:
        assert one_entry_apart(before, diff(further), start) is None
