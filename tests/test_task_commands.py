"""Commands to task calls (issue 31): numbers read from words, task parameters and their
defaults, the learned parameter reader, `bcc command` on a dungeon with tasks end to end,
`bcc train` / `bcc corpus evaluate` on task-call pairs, and the held-out measurement."""
from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import given, settings, strategies as st

from bcc.cli import main
from bcc.errors import BccError
from bcc.grounding import task_pairs
from bcc.grounding.calls import CallSpace, Param
from bcc.grounding.numbers import NUMBER_WORDS, numbers, tokens
from bcc.grounding.slots import ValueReader, mentions

HELDOUT = Path(__file__).parent / "data" / "task_commands_heldout.jsonl"

# ---- the number reader: an independent speller of English cardinals ---------------------
ONES = "zero one two three four five six seven eight nine ten eleven twelve thirteen fourteen fifteen " \
       "sixteen seventeen eighteen nineteen".split()
TENS_WORDS = {2: "twenty", 3: "thirty", 4: "forty", 5: "fifty", 6: "sixty", 7: "seventy", 8: "eighty", 9: "ninety"}


def spell(n: int, hyphen: bool, with_and: bool) -> str:
    """n (0..999) in words, as people write it: 'twenty-one' or 'twenty one', 'one hundred
    and five' or 'one hundred five'."""
    hundreds, rest = divmod(n, 100)
    parts = []
    if hundreds:
        parts.append(f"{ONES[hundreds]} hundred")
        if rest and with_and:
            parts.append("and")
    if rest or not hundreds:
        if rest < 20:
            parts.append(ONES[rest])
        else:
            tens, unit = divmod(rest, 10)
            parts.append(TENS_WORDS[tens] + (("-" if hyphen else " ") + ONES[unit] if unit else ""))
    return " ".join(parts)


@settings(max_examples=300, deadline=None)
@given(st.integers(0, 999), st.booleans(), st.booleans())
def test_a_number_in_words_reads_as_itself(n, hyphen, with_and):
    assert numbers(spell(n, hyphen, with_and)) == [n]


@settings(max_examples=200, deadline=None)
@given(st.integers(0, 999_999))
def test_digits_read_as_themselves(n):
    assert numbers(f"build {n} blocks") == [n]


FILLER = ["build", "a", "wall", "of", "stone", "wide", "long", "high", "by", "x", "at", "please", "house", "here"]


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 999), st.sampled_from(["digits", "words"]), st.booleans(),
                          st.lists(st.sampled_from(FILLER), min_size=1, max_size=3)), min_size=1, max_size=5))
def test_numbers_between_words_read_in_order(parts):
    """Numbers separated by at least one word that is not a number word are read apart, in
    order, written as digits or words."""
    text = []
    for n, how, hyphen, words in parts:
        text.append(str(n) if how == "digits" else spell(n, hyphen, False))
        text += words
    assert numbers(" ".join(text)) == [n for n, _, _, _ in parts]


@settings(max_examples=200, deadline=None)
@given(st.lists(st.integers(0, 99), min_size=2, max_size=4), st.sampled_from(["x", "X", " x ", " by ", "by", "*"]))
def test_compact_sizes_split(sizes, joiner):
    assert numbers(joiner.join(map(str, sizes)) + " house") == sizes


@settings(max_examples=200, deadline=None)
@given(st.text(alphabet="abcdefghijklmnopqrstuvwyz_ ,", max_size=40))
def test_no_number_without_digits_or_number_words(text):
    if not any(w in NUMBER_WORDS for w in tokens(text)):
        assert numbers(text) == []


def test_number_runs_and_word_boundaries():
    assert numbers("a 3x4x2 house") == [3, 4, 2]
    assert numbers("five wide and six long") == [5, 6]
    assert numbers("three four") == [3, 4]            # two units never make one number
    assert numbers("at (5, 4)") == [5, 4]
    assert numbers("a 1234567 block wall") == []      # too long for a size: left as a word


# ---- parameters and defaults -------------------------------------------------------------
def test_defaults_come_from_the_domain_and_the_dungeon():
    space = CallSpace("mason_yard")
    house = space.by_name["house"]
    # stated in domains/mason_tasks.yaml: x, z = agent.x, agent.z; the yard starts the agent
    # at S, column 1 of row 1; w, l, h stated numbers; k: the first stock listed (stone)
    assert house.defaults == {"x": 1, "z": 1, "w": 5, "l": 5, "h": 3, "k": "stone"}
    assert "d" not in space.by_name["row"].defaults    # no default: a command must say it


def test_calls_are_checked_against_the_tasks():
    space = CallSpace("mason_yard")
    assert space.canonical("wall(1,1, 3,4 ,stone)") == "wall(1, 1, 3, 4, stone)"
    for bad, words in [("wal(1)", "not a task"), ("wall(1, 1, 3, 4)", "takes 5"),
                       ("wall(1, 1, x, 4, stone)", "whole number"), ("wall(1, 1, 3, 4, cheese)", "one of"),
                       ("wall", "not a task call")]:
        with pytest.raises(BccError) as e:
            space.parse(bad, ("p.jsonl", 7, 1))
        assert str(e.value).startswith("p.jsonl:7:1: ") and words in str(e.value)


DOMAIN = """domain: tiny_tasks
extends: mason_tasks
tasks:
  pile:
    params:
      n: {type: int, default: %s}
      k: material
methods:
  pile_done: {task: pile, subtasks: []}
"""


@pytest.mark.parametrize("default, words", [("stone", "whole number or object.attribute"),
                                             ("1.5", "whole number or object.attribute")])
def test_a_bad_default_is_refused_at_its_place(tmp_path, default, words):
    from bcc.compiler.pipeline import load_dungeon
    (tmp_path / "tiny.yaml").write_text(DOMAIN % default)
    dungeon = (Path(__file__).parent / "htn_yaml" / "yard.yaml").read_text().replace("domain: errands.yaml",
                                                                                      "domain: tiny.yaml")
    (tmp_path / "yard.yaml").write_text(dungeon)
    with pytest.raises(BccError) as e:
        load_dungeon(str(tmp_path / "yard.yaml"))
    assert str(e.value).startswith(f"{tmp_path / 'tiny.yaml'}:6:") and words in str(e.value)


def test_an_enumeration_default_must_be_a_value(tmp_path):
    from bcc.compiler.pipeline import load_dungeon
    (tmp_path / "tiny.yaml").write_text(DOMAIN.replace("k: material", "k: {type: material, default: cheese}") % 2)
    dungeon = (Path(__file__).parent / "htn_yaml" / "yard.yaml").read_text().replace("domain: errands.yaml",
                                                                                      "domain: tiny.yaml")
    (tmp_path / "yard.yaml").write_text(dungeon)
    with pytest.raises(BccError) as e:
        load_dungeon(str(tmp_path / "yard.yaml"))
    assert ":7:" in str(e.value) and "'cheese' is not a value of 'material'" in str(e.value)


def test_value_names_longest_first_and_before_learned_words():
    p = Param("k", "material", "enum", ("stone", "bricks", "stone_bricks", "planks"))
    assert mentions("a house of stone bricks".split(), p, {}) == ["stone_bricks"]
    assert mentions("a stone house".split(), p, {}) == ["stone"]
    # a learned word counts only when no value is named
    assert mentions("a wooden house".split(), p, {"wooden": "planks"}) == ["planks"]
    assert mentions("a wooden house of bricks".split(), p, {"wooden": "planks"}) == ["bricks"]


def test_synonyms_are_learned_from_pairs_that_do_not_name_the_value():
    space = CallSpace("mason_yard")
    house = space.by_name["house"]
    d = house.defaults
    call = lambda k: (d["x"], d["z"], d["w"], d["l"], d["h"], k)   # noqa: E731
    pairs = [("a wooden house".split(), house, call("planks")),
             ("build a wooden house".split(), house, call("planks")),
             ("a house of bricks".split(), house, call("bricks")),     # named: teaches nothing
             ("a wooden house of bricks".split(), house, call("bricks")),
             ("build a house".split(), house, call("stone"))]          # the default: teaches nothing
    reader = ValueReader.learn(pairs)
    # "wooden": 3 commands, 2 with planks unnamed (2 >= 0.6 * 3); "house" is in all 5, 2 planks
    assert reader.synonyms == {"wooden": "planks"}


# ---- the trained model on commands of neither file -----------------------------------
@pytest.fixture(scope="module")
def model():
    return task_pairs.shipped_model()


@pytest.mark.parametrize("command, call", [
    ("build a house", "house(1, 1, 5, 5, 3, stone)"),                  # every parameter its default
    ("build a 7 by 3 wall of bricks", "wall(1, 1, 7, 3, bricks)"),
    ("a house 8 wide and 6 long made of planks", "house(1, 1, 8, 6, 3, planks)"),
])
def test_commands_become_calls(model, command, call):
    assert model.interpret(command, CallSpace("mason_yard")).task == call


def test_not_understood_without_known_words(model):
    found = model.interpret("dance a jig", CallSpace("mason_yard"))
    assert found.task is None and "never seen" in found.message


def test_a_task_without_a_default_needs_the_command_to_say_it(model):
    space = CallSpace("mason_yard")
    row = space.by_name["row"]      # row(d, n, k): d and n have no default
    assert model.fill(row, [], []) is None


def test_the_model_file_round_trips(tmp_path, model):
    from bcc.grounding.models import load
    model.save(tmp_path / "m.json")
    again = load(tmp_path / "m.json")
    space = CallSpace("mason_yard")
    for command in ("build a 3x4x2 house", "a wooden wall 6 long"):
        assert again.interpret(command, space).task == model.interpret(command, space).task


# ---- the held-out measurement ------------------------------------------------------------
def test_heldout_set_is_apart_from_the_training_pairs():
    held = [json.loads(line) for line in HELDOUT.read_text().splitlines() if line.strip()]
    train = [json.loads(line) for line in task_pairs.SHIPPED.read_text().splitlines() if line.strip()]
    assert len(held) >= 100 and len(train) < len(held)
    assert not {r["command"].lower() for r in held} & {r["command"].lower() for r in train}


def test_heldout_accuracy_is_computed_per_pair_and_per_kind(model):
    from bcc.grounding.pairs import load
    rows = load(HELDOUT)
    task_pairs.check(rows)          # every expected call is a task of mason_yard with typed values
    report = task_pairs.evaluate(model, rows)
    assert report["total"] == len(rows) == len(HELDOUT.read_text().splitlines())
    # the accuracy is the share of pairs whose predicted call is the expected one, recounted here
    space = CallSpace("mason_yard")
    right = sum(model.interpret(r["command"], space).task == r["task"] for r in rows)
    assert report["correct"] == right and report["accuracy"] == right / len(rows)
    assert sum(v["total"] for v in report["by_kind"].values()) == len(rows)
    assert sum(v["correct"] for v in report["by_kind"].values()) == right


# ---- the command line --------------------------------------------------------------------
YARD = """dungeon: small_yard
domain: mason_tasks
description: A 5 x 5 yard with a stock of bricks.
height: 6
legend:
  ".": [bedrock]
  "S": [bedrock]
map: |
  .....
  .S...
  .....
  .....
  .....
agent:
  start: S
stock:
  - {name: bricks_stock, kind: bricks, count: 64, full: 0}
"""


def run(*args):
    return CliRunner().invoke(main, list(args))


def test_command_plans_a_task_end_to_end(tmp_path, monkeypatch):
    monkeypatch.setenv("BCC_HOME", str(tmp_path))
    (tmp_path / "yard.yaml").write_text(YARD)
    r = run("command", str(tmp_path / "yard.yaml"), "build a 2 by 2 wall of bricks")
    assert r.exit_code == 0, r.output
    assert "task: wall(1, 1, 2, 2, bricks)" in r.stderr
    # By hand: the agent already stands at (1, 1). Layer 1: climb (a block where it stood),
    # lay one block east one below the feet and step onto it (row of n - 1 = 1); layer 2
    # the same going west: 6 actions.
    assert [a.split("(")[0] for a in r.stdout.split()] == \
        ["climb", "place_down_east", "move_east", "climb", "place_down_west", "move_west"]
    plan = tmp_path / "plan.txt"
    plan.write_text(r.stdout)
    v = run("validate", str(tmp_path / "yard.yaml"), str(plan), "--task", "wall(1, 1, 2, 2, bricks)")
    assert v.exit_code == 0, v.output
    j = run("command", str(tmp_path / "yard.yaml"), "build a 2 by 2 wall of bricks", "--json")
    out = json.loads(j.stdout)
    assert out["task"] == "wall(1, 1, 2, 2, bricks)" and out["solved"] and len(out["plan"]) == 6
    assert out["candidates"][0]["task"] == out["task"] and out["model"] == "shipped task pairs"


def test_command_errors(tmp_path, monkeypatch):
    monkeypatch.setenv("BCC_HOME", str(tmp_path))
    (tmp_path / "yard.yaml").write_text(YARD)
    r = run("command", str(tmp_path / "yard.yaml"), "dance a jig")
    assert r.exit_code == 1 and r.stderr.startswith("not understood:")
    r = run("command", str(tmp_path / "yard.yaml"), "   ")
    assert r.exit_code == 2 and len(r.stderr.strip().splitlines()) == 1
    goal_model = Path(__file__).parents[1] / "grounding" / "corpus" / "model.json"
    r = run("command", str(tmp_path / "yard.yaml"), "build a wall", "--model", str(goal_model))
    assert r.exit_code == 2 and "goal model" in r.stderr


def test_train_and_evaluate_task_pairs(tmp_path, monkeypatch):
    monkeypatch.setenv("BCC_HOME", str(tmp_path))
    pairs = tmp_path / "p.jsonl"
    pairs.write_text("".join(json.dumps(r) + "\n" for r in [
        {"command": "build a wall of bricks", "task": "wall(1, 1, 5, 3, bricks)", "dungeon": "mason_yard"},
        {"command": "a 4 by 2 wall", "task": "wall(1, 1, 4, 2, stone)", "dungeon": "mason_yard"},
        {"command": "build a house", "task": "house(1, 1, 5, 5, 3, stone)", "dungeon": "mason_yard"},
        {"command": "a 6 by 7 house", "task": "house(1, 1, 6, 7, 3, stone)", "dungeon": "mason_yard"}]))
    r = run("train", "--pairs", str(pairs), "--db", str(tmp_path / "d.sqlite"), "-o", str(tmp_path / "m.json"))
    assert r.exit_code == 0, r.output
    assert "task-call model on 4 pair(s)" in r.stdout
    from bcc.grounding.models import load
    assert type(load(tmp_path / "m.json")).__name__ == "TaskCallModel"
    e = run("corpus", "evaluate", "--train", str(pairs), "--test", str(pairs), "--json")
    assert e.exit_code == 0, e.output
    report = json.loads(e.stdout)
    assert report["total"] == 4 and 0 <= report["correct"] <= 4
    bad = tmp_path / "bad.jsonl"
    bad.write_text(json.dumps({"command": "x", "task": "wall(1, 1)", "dungeon": "mason_yard"}) + "\n")
    r = run("train", "--pairs", str(bad), "--db", str(tmp_path / "d.sqlite"))
    assert r.exit_code == 2 and r.stderr.startswith(f"{bad}:1:1: wall takes 5 argument(s)")


def test_the_task_call_machinery_knows_no_word_of_the_building_domains():
    """Task names, parameters, values and words come from the domain and the pairs: the
    generic modules name none of the shipped building world's words (task_pairs.py, the glue
    with the shipped pairs, names their dungeon; it is left out, as corpus.py is)."""
    import re
    words = re.compile(r"lava|pickaxe|gold|bedrock|burlap|minecraft|agentOnBlock|stone|chair|house|roof|plank"
                       r"|craft|furnace|cabin|mineplanner|wall|brick|mason|material|wood|\bring\b", re.I)
    root = Path(__file__).resolve().parent.parent / "grounding"
    for name in ("numbers.py", "calls.py", "slots.py", "task_model.py"):
        for n, line in enumerate((root / name).read_text().splitlines(), 1):
            assert not words.search(line), f"grounding/{name}:{n}: {line.strip()}"


def test_list_shows_a_dungeon_commanded_by_its_task():
    listed = json.loads(run("list", "--json").stdout)
    yard = next(d for d in listed["dungeons"] if d["name"] == "mason_yard")
    assert yard["task"] == "house(1, 1, 5, 5, 3, stone)" and yard["goal"] is None
    assert "mason_yard         task: house(1, 1, 5, 5, 3, stone)" in run("list").stdout
