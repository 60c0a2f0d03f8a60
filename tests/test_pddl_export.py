"""The grounded PDDL export is exactly the compiled model (no PDDL tools needed).

Exactness is checked on the export's own STRIPS semantics (`Task.successors`): along
random walks (including the tough maze), every state's successor set (action name, next state) in the export equals
the model's, over *all* actions (not just the ones search keeps); failure states have no
successors in the export; the goal holds in the same states.
"""
import functools
import json
import random

import pytest

from bcc.compiler import compile_dungeon
from bcc.errors import BccError
from bcc.generate import generate_maze
from bcc.model_json import FORMAT, model_json
from bcc.pddl_export.plans import to_pddl_plan
from bcc.pddl_export.task import build_task
from bcc.pddl_export.writer import domain_text, problem_text
from bcc.solvers import Budget, get_solver


@functools.lru_cache(maxsize=None)
def compiled(dungeon):
    """A shipped dungeon's model and export, built once per test session (tough_maze takes ~20 s)."""
    m = compile_dungeon(dungeon)
    return m, build_task(m)


def model_successors(m, s):
    out = set()
    for a, fn in enumerate(m.apply_fns):
        t = fn(s)
        if t is not None:
            out.add((m.action_names[a], t))
    return out


def export_successors(task, s):
    return {(task.action_names[op.action], task.state_of(f)) for op, f in task.successors(task.facts_of(s))}


def check_walks(m, task, walks=4, steps=60, seed=0):
    rng = random.Random(seed)
    checked = 0
    for _ in range(walks):
        s = m.initial
        for _ in range(steps):
            assert task.is_goal(task.facts_of(s)) == bool(m.is_goal(s))
            if m.is_failure(s):
                assert export_successors(task, s) == set()
                break
            succ = model_successors(m, s)
            assert export_successors(task, s) == succ
            checked += 1
            if not succ:
                break
            s = rng.choice(sorted(succ))[1]
    return checked


@pytest.mark.parametrize("dungeon", ["grid", "bridge", "easy_maze", "four_rooms", "barnyard",
                                     pytest.param("tough_maze", marks=pytest.mark.slow)])
def test_export_matches_model_on_random_walks(dungeon):
    m, task = compiled(dungeon)
    assert check_walks(m, task) > 20


@pytest.mark.slow
def test_tough_maze_walks_that_mine_and_place():
    # Uniform walks rarely reach a stone, so these start from every state along bcc's
    # optimal plan (which mines three stones) and branch off it, preferring to destroy
    # and place blocks: the inventory counts and the mined cells move.
    m, task = compiled("tough_maze")
    plan = get_solver("astar")(m, Budget(time_limit=60)).plan
    counts = [v.index for v in m.variables if v.label.endswith(".count")][1:]  # slot 0: the pickaxe
    rng = random.Random(7)
    checked, mined, placed = 0, 0, 0
    start = m.initial
    for name in plan:
        s = start
        for _ in range(12):
            mined = max(mined, max(s[i] for i in counts))
            succ = model_successors(m, s)
            assert export_successors(task, s) == succ
            checked += 1
            if not succ:
                break
            useful = [x for x in sorted(succ) if x[0] in ("destroy_block", "place_block")]
            placed += any(x[0] == "place_block" for x in useful)
            s = rng.choice(useful if useful and rng.random() < 0.7 else sorted(succ))[1]
        start = m.apply(m.action_index(name), start)
    assert checked > 300 and mined >= 3 and placed > 0


def test_fixpoint_domains_cover_every_reachable_state():
    # Exact enumeration (feasible on the bridge: ~16,500 states) is the independent check:
    # every value of every reachable state must be in the fixpoint's domains.
    m, task = compiled("bridge")
    seen, stack = {m.initial}, [m.initial]
    while stack:
        s = stack.pop()
        if m.is_failure(s):
            continue
        for fn in m.apply_fns:
            t = fn(s)
            if t is not None and t not in seen:
                seen.add(t)
                stack.append(t)
    assert len(seen) > 10_000
    for s in seen:
        assert all(v in task.domains.values[i] for i, v in enumerate(m.dense(s)))


def test_position_domains_are_the_positions_the_agent_reaches(tmp_path):
    # The fixpoint starts the position with its whole range (so it needs few rounds) and
    # cuts it back by a flood over the moves. On a maze without stones (every state
    # enumerable) the kept x and z values must be exactly those of reachable states,
    # walls on the border included in the range but never reached.
    path = tmp_path / "m.yaml"
    path.write_text(generate_maze(11, 11, seed=5))
    m = compile_dungeon(str(path))
    task = build_task(m)
    seen, stack = {m.initial}, [m.initial]
    while stack:
        for _, t in m.successors(stack.pop()):
            if t not in seen:
                seen.add(t)
                stack.append(t)
    for axis in (0, 2):
        index = m.position[axis][0]
        reached = {m.dense(s)[index] for s in seen}
        assert set(task.domains.values[index]) == reached
        assert len(reached) < m.variables[[v.index for v in m.variables].index(index)].hi + 1
    assert task.stats["rounds"] <= 10   # grown one value per round from the start, it took 20
    assert check_walks(m, task, walks=4, steps=60, seed=2) > 30


@pytest.mark.slow
def test_tough_maze_counts_stay_within_the_stones_that_exist():
    # A plain relaxed fixpoint would let every inventory count reach 64; the histogram
    # abstraction bounds them by the stones of the grid (counted here from the grid).
    m, task = compiled("tough_maze")
    g = m.grid
    stone = g.value_names.index("burlap_stone")
    stones = sum(m.grid.cell(m.initial, x, y, z) == stone
                 for y in g.layers for z in range(g.depth) for x in range(g.width))
    assert stones == 6
    labels = {v.label: v for v in m.variables}
    for k in range(9):
        count = labels[f"inventoryBlock[{k}].count"]
        assert max(task.domains.values[count.index]) <= stones
    assert task.stats["facts"] < 400 and task.stats["operators"] < 10_000


def test_export_matches_model_with_lava_and_stones():
    text = generate_maze(7, 7, stones=1, lava=1, seed=3)
    import tempfile, os
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "g.yaml")
        open(path, "w").write(text)
        m = compile_dungeon(path)
    task = build_task(m)
    assert check_walks(m, task, walks=8, steps=80, seed=1) > 50


def test_walk_into_lava_is_a_dead_end():
    # The bridge: from the start (x=1, z=3, facing north) turn right to face east, walk
    # to x=2, then one more step east is the lava at x=3: the agent dies there.
    m = compile_dungeon("bridge")
    task = build_task(m)
    s = m.initial
    for name in ["rotate_right", "move_forward", "move_forward"]:
        s = m.apply(m.action_index(name), s)
    assert m.is_failure(s)
    assert export_successors(task, s) == set()


def test_plans_translate_and_reach_the_goal():
    for dungeon in ["bridge", "four_rooms"]:
        m = compile_dungeon(dungeon)
        task = build_task(m)
        result = get_solver("astar")(m, Budget(time_limit=30))
        ops = to_pddl_plan(task, result.plan)
        assert [task.action_of(op) for op in ops if task.action_of(op)] == result.plan
        with pytest.raises(BccError):
            to_pddl_plan(task, result.plan[1:])


def test_pddl_text_names_and_header():
    m = compile_dungeon("bridge")
    task = build_task(m)
    d, p = domain_text(task), problem_text(task)
    assert d.startswith("; PDDL domain for dungeon bridge (domain minecraft), written by bcc ")
    assert "(:action move_forward__0" in d and "(agent-x n1)" in p and "(cell x3 y0 z1 lava)" in p
    assert d.count("(:action ") == task.stats["operators"]
    # every operator name maps back to a canonical action
    assert {task.action_of(op.name) for op in task.operators} <= set(m.action_names)


def test_export_refuses_a_state_space_beyond_its_limit():
    with pytest.raises(BccError, match="more than 100 abstract states"):
        build_task(compile_dungeon("bridge"), max_states=100)


def test_cli_export(tmp_path):
    from click.testing import CliRunner
    from bcc.cli import main
    r = CliRunner().invoke(main, ["export", "pddl", "grid", "-o", str(tmp_path / "out"), "--json"])
    assert r.exit_code == 0, r.output
    info = json.loads(r.output)
    assert (tmp_path / "out" / "domain.pddl").read_text().count("(:action ") == info["operators"]
    r = CliRunner().invoke(main, ["export", "pddl", "bridge", "-o", str(tmp_path / "o2"), "--max-states", "10"])
    assert r.exit_code == 2 and "more than 10 abstract states" in r.output


def test_model_json_round_trips_the_layout():
    m = compile_dungeon("bridge")
    data = json.loads(json.dumps(model_json(m)))
    assert data["format"] == FORMAT
    assert bytes(data["initial"]) == m.initial
    g = data["grid"]
    for y in range(g["height"]):
        for z in range(g["depth"]):
            for x in range(g["width"]):
                assert g["cells"][y][z][x] == m.grid.cell(m.initial, x, y, z)
    labels = {v["label"]: v for v in data["variables"]}
    assert data["initial"][labels["agent.x"]["index"]] + labels["agent.x"]["lo"] == data["initial_values"]["agent.x"]
    assert [a["name"] for a in data["actions"]] == list(m.action_names)


def test_a_time_limit_is_never_kept_as_a_value_by_the_export():
    """The export's symbolic engine keeps an exception per value (`except Exception`), to
    raise it only if that value is chosen. A time limit raised by a timer inside it must
    pass through: as an Exception it was kept, the export ran on, and `fd` took 7.7 s on
    a 0.02 s budget (a CI run)."""
    from bcc.pddl_export import symbolic
    from bcc.solvers import fast_downward
    from bcc.solvers.limits import BudgetExceeded
    for stop in (fast_downward._Expired(), BudgetExceeded("time_limit")):
        def interrupted(a, b, stop=stop):
            raise stop
        with pytest.raises(type(stop)):
            symbolic._apply(interrupted, 1, 2)
    kept = symbolic._apply(lambda a, b: a // b, 1, 0)   # an ordinary error is still kept, not raised
    assert type(kept).__name__ == "_Err"
