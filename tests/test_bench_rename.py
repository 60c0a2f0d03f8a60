"""bench/rename_world.py: a copy of a dungeon and its domain chain with every name the
domains define renamed is the same problem -- the build solver finds the same plan
(renamed back) with the same expansions -- and no renamed name is left in the files."""
import re

from bcc.compiler import compile_dungeon
from bcc.generate_structures import generate_structure
from bcc.solvers import Budget, get_solver
from bench_harness import load_bench


def test_a_renamed_world_is_the_same_problem(tmp_path):
    bench = load_bench("rename_world")
    original = tmp_path / "wall.yaml"
    original.write_text(generate_structure("wall", 3, 1, 2, material="planks"))
    renamed, mapping, kept = bench.rename_world(original, tmp_path / "renamed", seed=3)
    assert {"agent", "count"} <= set(kept) and "planks" in mapping and "place_north" in mapping
    texts = [renamed.read_text(), *(p.read_text() for p in (tmp_path / "renamed").glob("n*.yaml"))]
    for name in ("planks", "place_north", "mason", "builder", "solid"):
        assert not any(re.search(rf"(?<![A-Za-z0-9_]){name}(?![A-Za-z0-9_])", t) for t in texts), name
    budget = Budget(max_states=20_000, time_limit=120)
    # improve=0: the improving A* stops on a clock, so its expansions vary from run to run
    a = get_solver("build")(compile_dungeon(original), budget, improve=0)
    b = get_solver("build")(compile_dungeon(renamed), budget, improve=0)
    assert a.solved and b.solved and (a.cost, a.expanded) == (b.cost, b.expanded)
    back = {new: old for old, new in mapping.items()}
    assert [re.sub(r"\w+", lambda m: back.get(m.group(0), m.group(0)), step) for step in b.plan] == a.plan
