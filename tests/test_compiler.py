"""The compiler's own contracts: domain independence, state layout, folding, goal positions."""
from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest

from bcc.compiler import compile_dungeon
from bcc.compiler.dungeon import shipped_dungeons

from conftest import compiled

ROOT = Path(__file__).resolve().parent.parent


# Three modules of the PDDL export (task.py, writer.py, domains.py) write bcc's own dungeons,
# and their docstrings show a cell of one as an example; the rest of pddl_export is checked.
PDDL_EXPORT = {"task.py", "writer.py", "domains.py"}


def test_compiler_heuristics_solvers_run_path_and_pddl_front_end_know_no_minecraft_words():
    # The HTN planner and the HDDL front end too: they plan the IPC's houses from the files alone.
    words = re.compile(r"lava|pickaxe|gold|bedrock|burlap|minecraft|agentOnBlock|stone|chair"
                       r"|house|roof|plank|craft|furnace|cabin|mineplanner", re.I)
    paths = [p for folder in ("compiler", "heuristics", "solvers", "solvers/htn", "run", "pddl_io",
                                                "pddl_export", "hddl") for p in (ROOT / folder).glob("*.py")
             if not (folder == "pddl_export" and p.name in PDDL_EXPORT)]
    assert len(paths) > 40
    assert {"registry.py", "relaxed.py", "counting.py", "patterns.py"} <= {p.name for p in paths
                                                                          if p.parent.name == "heuristics"}
    assert {"solve.py", "children.py", "pool.py"} <= {p.name for p in paths if p.parent.name == "run"}
    assert {"build.py", "structure.py", "goal_cells.py"} <= {p.name for p in paths}
    for path in paths:
        for n, line in enumerate(path.read_text().splitlines(), 1):
            assert not words.search(line), f"{path.parent.name}/{path.name}:{n}: {line.strip()}"


@pytest.mark.parametrize("name", shipped_dungeons())
def test_every_shipped_dungeon_compiles_deterministically(name):
    a, b = compile_dungeon(name), compile_dungeon(name)
    assert a.initial == b.initial and a.source == b.source
    assert not a.is_failure(a.initial)
    if a.report["domain"] not in ("crafting", "mason_tasks"):   # these move as the mason does
        assert a.action_names[:8] == ("move_forward", "rotate_left", "rotate_right", "look_down", "look_ahead",
                                      "change_item", "destroy_block", "place_block")


def test_static_layers_stay_out_of_the_state():
    m = compiled("bridge")
    # Actions only add/remove blocks at y = a.y - 1 = 0 and y = a.y = 1 (a.y never changes).
    assert m.grid.layers == (0, 1)
    assert len(m.initial) == 24                       # no cell has changed yet
    assert len(m.dense(m.initial)) == 24 + 2 * 7 * 7  # dense: every cell of the two layers
    # agent.y is folded into the code as a constant: it is no state variable.
    assert "agent.y" not in m.decode(m.initial)


def test_goal_is_one_lookup_not_a_loop():
    m = compiled("bridge")
    goal_src = m.source[m.source.index("def goal"):m.source.index("def failure")]
    assert "any(" not in goal_src and "for " not in goal_src


def test_goal_positions_are_the_gold_cells_only():
    # Gold is not placeable, so the only cell where agentOnBlock(agent, gold) can hold is
    # the one gold block at (5, 0, 5), the agent standing on it at y = 1.
    m = compiled("bridge")
    assert [list(p) for p in m.goal_positions] == [[5, 1, 5]]


def test_room_goal_positions_are_strictly_inside():
    m = compiled("four_rooms", "agentInRoom(agent, orange)")
    cells = {(x, z) for x, _, z in [list(p) for p in m.goal_positions]}
    assert cells == {(x, z) for x in range(7, 10) for z in range(1, 4)}


def test_placeable_blocks_count_as_possible_goal_cells():
    # A stone can be placed into lava, so agentOnBlock(agent, burlap_stone) may hold on
    # any lava cell as well as where stones lie.
    m = compiled("bridge", "agentOnBlock(agent, burlap_stone)")
    cells = {(x, z) for x, _, z in [list(p) for p in m.goal_positions]}
    assert {(3, z) for z in range(1, 6)} <= cells


def test_blockInRoom_and_blockIsType_quantify_over_cells(tmp_path):
    m = compiled("four_rooms", "blockInRoom(red_wool, red)")
    assert not m.is_goal(m.initial)  # red wool is the wall, strictly outside the interior
    m = compiled("bridge", "blockIsType(gold, gold) and agentHasBlock(agent, diamond_pickaxe)")
    assert m.is_goal(m.initial)


def test_emitted_python_can_be_written(tmp_path):
    out = tmp_path / "model.py"
    proc = subprocess.run(["bcc", "compile", "grid", "--emit-python", str(out)], capture_output=True, text=True)
    assert proc.returncode == 0
    assert "def successors(s):" in out.read_text()


def test_new_object_class_in_yaml_only(tmp_path):
    # A domain that is not Minecraft at all: a token on a line, moved by `step`, must
    # reach the end. Nothing in bcc is changed for it.
    (tmp_path / "line.yaml").write_text("""\
domain: line
types:
  tile: {values: [empty, floor, goal]}
classes:
  token:
    position: [x, y, z]
    attributes:
      x: {type: int, range: [0, width - 1]}
      y: {type: int, range: [0, 0]}
      z: {type: int, range: [0, 0]}
      steps: {type: int, range: [0, 9]}
  cell:
    key: [x, y, z]
    attributes:
      x: {type: int, range: [0, width - 1]}
      y: {type: int, range: [0, height - 1]}
      z: {type: int, range: [0, depth - 1]}
      kind: {type: tile, default: empty}
dungeon:
  grid: cell
  agent: token
functions:
  atGoal: {params: {t: token}, body: "cell[t.x, 0, t.z].kind == goal"}
actions:
  step:
    params: {t: token}
    pre: t.x + 1 < width
    effect: t.x = t.x + 1; t.steps = t.steps + 1
  jump:
    params: {t: token}
    pre: t.x + 2 < width
    effect: t.x = t.x + 2
    cost: 3
""")
    (tmp_path / "d.yaml").write_text("""\
domain: line.yaml
height: 1
legend: {".": [floor], "G": [goal]}
map: |
  .....G
agent: {start: [0, 0, 0]}
goal: atGoal(agent)
""")
    from bcc.solvers import Budget, get_solver
    m = compile_dungeon(tmp_path / "d.yaml")
    assert m.action_names == ("step", "jump")
    result = get_solver("astar")(m, Budget())
    # Five cells to go: 5 steps cost 5; any jump costs 3 for 2 cells, so steps are optimal.
    assert result.cost == 5 and result.plan == ["step"] * 5


@pytest.mark.parametrize("goal", ["True", "not False", "FALSE"])
def test_pythons_true_and_false_are_pointed_at_bccs(goal):
    from bcc.errors import BccError
    with pytest.raises(BccError, match=r"unknown name '(True|False|FALSE)' \(did you mean '(true|false)'\?\)"):
        compile_dungeon("grid", goal=goal)


def test_a_domain_written_with_augmented_assignment_compiles_to_the_same_code(tmp_path):
    """`count -= 1` and `count += 1` are the long forms: the shipped minecraft domain with
    its counter updates rewritten so generates the very same successor code."""
    from bcc.compiler.domain import DOMAINS_DIR
    from bcc.compiler.dungeon import DUNGEONS_DIR
    text = (DOMAINS_DIR / "minecraft.yaml").read_text()
    short = text.replace("inventoryBlock[a.selectedItem].count = inventoryBlock[a.selectedItem].count - 1",
                         "inventoryBlock[a.selectedItem].count -= 1").replace("i.count = i.count + 1", "i.count += 1")
    assert short.count("-= 1") == 1 and short.count("+= 1") == 1
    (tmp_path / "short.yaml").write_text(short.replace("domain: minecraft", "domain: short", 1))
    dungeon = (DUNGEONS_DIR / "bridge.yaml").read_text().replace("domain: minecraft", "domain: short.yaml", 1)
    (tmp_path / "bridge.yaml").write_text(dungeon)
    assert compile_dungeon(tmp_path / "bridge.yaml").source == compile_dungeon("bridge").source


def _bridge_with(tmp_path, goal_yaml: str, domain_text: str | None = None) -> Path:
    from bcc.compiler.dungeon import DUNGEONS_DIR
    text = re.sub(r"^goal: .*\n", goal_yaml, (DUNGEONS_DIR / "bridge.yaml").read_text(), flags=re.M)
    if domain_text is not None:
        (tmp_path / "dom.yaml").write_text(domain_text)
        text = text.replace("domain: minecraft", "domain: dom.yaml", 1)
    path = tmp_path / "b.yaml"
    path.write_text(text)
    return path


def test_a_goal_written_as_a_list_is_their_conjunction(tmp_path):
    listed = _bridge_with(tmp_path, "goal:\n  - agentOnBlock(agent, gold)\n  - not agentHasBlock(agent, gold)\n")
    one = compile_dungeon("bridge", goal="agentOnBlock(agent, gold) and not agentHasBlock(agent, gold)")
    assert compile_dungeon(listed).source == one.source


@pytest.mark.parametrize("goal_yaml,where,says", [
    ("goal:\n  - agentOnBlock(agent, gold)\n  - agentHasBlok(agent, gold)\n", (29, 5), "unknown function 'agentHasBlok'"),
    ("goal:\n  - true\n  - >-\n    agentOnBlock(agent,\n    gold) and\n    agentOnBlok(agent, gold)\n", (32, 5),
     "unknown function 'agentOnBlok'"),
    ("goal:\n  - agentOnBlock(agent, gold)\n  - [a, b]\n", (29, 5), "expected an expression as text, found a list"),
    ("goal: []\n", (27, 7), "`goal` is an empty list"),
    ("goal:\n  - agentOnBlock(agent, gold)\n  - agentOnBlock(agent,\n", (29, 24), "the expression ends too early"),
    ("goal: 1.5\n", (27, 7), "found the number 1.5"),
])
def test_an_error_in_a_listed_goal_points_into_its_item(tmp_path, goal_yaml, where, says):
    from bcc.errors import BccError
    with pytest.raises(BccError) as caught:
        compile_dungeon(_bridge_with(tmp_path, goal_yaml))
    assert (caught.value.line, caught.value.col) == where and says in caught.value.message, str(caught.value)


def test_an_error_in_a_listed_effect_points_into_its_item(tmp_path):
    """An effect written as a list is parsed as one text whose characters keep their file
    positions (before, an error in the second item pointed at the first item's line)."""
    from bcc.compiler.domain import DOMAINS_DIR
    from bcc.errors import BccError
    listed = (DOMAINS_DIR / "minecraft.yaml").read_text().replace(
        "    effect: |\n      a.x = tx; a.z = tz;\n", "    effect:\n      - a.x = tx\n      - a.z = tzz\n      - ", 1)
    assert "- a.z = tzz" in listed
    path = _bridge_with(tmp_path, "goal: agentOnBlock(agent, gold)\n", listed.replace("domain: minecraft", "domain: d", 1))
    line = listed.splitlines().index("      - a.z = tzz") + 1
    with pytest.raises(BccError, match="unknown name 'tzz'") as caught:
        compile_dungeon(path)
    assert (caught.value.path, caught.value.line, caught.value.col) == (str(tmp_path / "dom.yaml"), line, 15)


@pytest.mark.parametrize("written", ["[blocktype]", "{a: 1}", "3"])
def test_a_property_type_that_is_not_a_name_is_bad_input(tmp_path, written):
    """Found by fuzzing: `food: {type: [blocktype], ...}` raised TypeError (a list is not
    hashable) instead of naming the line."""
    from bcc.compiler.domain import DOMAINS_DIR
    from bcc.compiler.dungeon import DUNGEONS_DIR
    from bcc.errors import BccError
    text = (DOMAINS_DIR / "farm.yaml").read_text()
    assert "food: {type: blocktype, default: wheat}" in text
    (tmp_path / "farm.yaml").write_text(text.replace("food: {type: blocktype,", f"food: {{type: {written},", 1))
    (tmp_path / "barnyard.yaml").write_text((DUNGEONS_DIR / "barnyard.yaml").read_text().replace(
        "domain: farm", "domain: farm.yaml", 1))
    with pytest.raises(BccError, match="unknown type") as caught:
        compile_dungeon(tmp_path / "barnyard.yaml")
    assert caught.value.path.endswith("farm.yaml") and caught.value.line is not None


def test_nested_firsts_that_multiply_are_refused_quickly(tmp_path):
    """Found by fuzzing: 20 nested `first i in inventoryBlock where true {...}` grounded the
    body 9^20 times (compiling never ended; only --time-limit stopped a solve). The grounder
    counts the effects it makes and refuses past the limit, at the effect that crosses it."""
    import time
    from bcc.compiler.domain import DOMAINS_DIR
    from bcc.errors import BccError
    nested = "a.verticalDirection = 1"
    for _ in range(20):
        nested = f"first i in inventoryBlock where true {{{nested}}}"
    text = (DOMAINS_DIR / "minecraft.yaml").read_text()
    assert "    effect: a.verticalDirection = 1\n" in text
    (tmp_path / "dom.yaml").write_text(text.replace("    effect: a.verticalDirection = 1\n", f"    effect: {nested}\n", 1))
    path = _bridge_with(tmp_path, "goal: agentOnBlock(agent, gold)\n", (tmp_path / "dom.yaml").read_text())
    start = time.process_time()
    with pytest.raises(BccError, match="more than 100,000 ground effects") as caught:
        compile_dungeon(path)
    assert time.process_time() - start < 30 and caught.value.path.endswith("dom.yaml") and caught.value.line


def test_a_first_over_150_objects_compiles_flat(tmp_path):
    """`first c in coin where ...` grounds to one branch per coin: an elif chain, which the
    generated code writes as one `if ... elif ...` block. With a block per branch, a world
    of more than about 85 coins (or items lying on the ground) was refused; 150 compile,
    and taking picks the coin under the token, not another."""
    n = 150
    (tmp_path / "coins.yaml").write_text("""\
domain: coins
types:
  tile: {values: [empty, floor]}
classes:
  token:
    position: [x, y, z]
    attributes:
      x: {type: int, range: [0, width - 1]}
      y: {type: int, range: [0, 0]}
      z: {type: int, range: [0, 0]}
      held: {type: int, range: [0, 3]}
  coin:
    attributes:
      x: int
      present: {type: bool, default: true}
  cell:
    key: [x, y, z]
    attributes:
      x: {type: int, range: [0, width - 1]}
      y: {type: int, range: [0, height - 1]}
      z: {type: int, range: [0, depth - 1]}
      kind: {type: tile, default: empty}
dungeon:
  grid: cell
  agent: token
  lists:
    coins: {class: coin, fields: {x: x}}
actions:
  step:
    params: {t: token}
    pre: t.x + 1 < width
    effect: t.x = t.x + 1
  take:
    params: {t: token}
    pre: t.held < 3
    effect: first c in coin where c.present and c.x == t.x { c.present = false; t.held = t.held + 1 }
""")
    coins = "\n".join(f"  - {{name: c{i}, x: {i}}}" for i in range(n))
    (tmp_path / "d.yaml").write_text(f"""\
domain: coins.yaml
height: 1
legend: {{".": [floor]}}
map: |
  {"." * n}
agent: {{start: [0, 0, 0]}}
coins:
{coins}
goal: agent.held == 2
""")
    m = compile_dungeon(tmp_path / "d.yaml")
    assert "elif" in m.source
    from bcc.solvers import Budget, get_solver
    result = get_solver("bfs")(m, Budget(time_limit=60))
    # one coin per cell: take, step, take (the coin taken is gone, so a second take in
    # place does nothing; BFS finds the 3 steps)
    assert result.cost == 3 and result.plan == ["take", "step", "take"]
