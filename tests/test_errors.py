"""Bad input through the CLI: exit code 2, exactly one stderr line `FILE:LINE:COL: message`.

Each case writes a small dungeon (or a broken copy of the minecraft domain) with one typo,
runs `bcc solve FILE`, and checks the position against the text written here: positions are
computed by searching the written text, never copied from bcc's output. Most cases use
click's CliRunner (in-process, fast); a few run the real `bcc` executable. Unreachable goals
are not bad input: they exit 1 with `"solved": false`.
"""
from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import pytest
from click.testing import CliRunner

from bcc.cli import main

DOMAIN_FILE = Path(__file__).resolve().parent.parent / "domains" / "minecraft.yaml"

BASE = """\
dungeon: typo
domain: minecraft
description: A small room with a wall between the start and the gold.
height: 3
legend:
  "#": [bedrock, bedrock, bedrock]
  ".": [bedrock]
  "G": [gold]
  "S": [bedrock]
map: |
  #####
  #G..#
  ##..#
  #S..#
  #####
agent:
  start: S
  facing: north
  looking: ahead
  selected: 0
inventory:
  - {item: diamond_pickaxe, count: 1}
goal: agentOnBlock(agent, gold)
"""
ROOMS = "rooms:\n  - {name: hall, color: red, x: [0, 4], z: [0, 4]}\n"


# ---- positions in the text we wrote ------------------------------------------------------
def position(text: str, needle: str, nth: int = 1, plus: int = 0) -> tuple[int, int]:
    """1-based (line, col) of the nth occurrence of needle in text, plus `plus` columns."""
    i = -1
    for _ in range(nth):
        i = text.index(needle, i + 1)
    line = text.count("\n", 0, i) + 1
    col = i - (text.rfind("\n", 0, i) + 1) + 1
    return line, col + plus


def at(needle: str, nth: int = 1, plus: int = 0) -> Callable[[str], set]:
    return lambda text: {position(text, needle, nth, plus)}


def any_of(*locators) -> Callable[[str], set]:
    return lambda text: set().union(*(loc(text) for loc in locators))


def end_of_line(needle: str) -> Callable[[str], set]:
    """Just after the last character of the line containing needle."""
    def locate(text):
        line, _ = position(text, needle)
        return {(line, len(text.splitlines()[line - 1]) + 1)}
    return locate


# ---- running bcc ----------------------------------------------------------------------
@dataclass
class Run:
    code: int
    stdout: str
    stderr: str


def run_cli(*args: str) -> Run:
    result = CliRunner().invoke(main, list(args))
    # Anything but a clean exit is an exception escaping bcc (CliRunner catches it).
    assert result.exception is None or isinstance(result.exception, SystemExit), repr(result.exception)
    return Run(result.exit_code, result.stdout, result.stderr)


def run_process(*args: str, timeout: float = 120) -> Run:
    env = {k: v for k, v in os.environ.items() if k != "BCC_DEBUG"}
    exe = shutil.which("bcc")
    cmd = [exe, *args] if exe else [sys.executable, "-m", "bcc", *args]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=env)
    return Run(proc.returncode, proc.stdout, proc.stderr)


LINE = re.compile(r"^(?P<path>.+?):(?P<line>\d+):(?P<col>\d+): (?P<message>\S.*)$")


def check_bad_input(run: Run, path: Path, expected: set, says: tuple = ()) -> str:
    """Exit 2, one stderr line at one of the expected positions of `path`; returns the message."""
    assert "Traceback" not in run.stdout + run.stderr
    assert run.code == 2, (run.code, run.stderr, run.stdout[-500:])
    lines = run.stderr.splitlines()
    assert len(lines) == 1, run.stderr
    m = LINE.match(lines[0])
    assert m, lines[0]
    assert Path(m["path"]).resolve() == path.resolve(), lines[0]
    got = (int(m["line"]), int(m["col"]))
    assert got in expected, f"{lines[0]!r}: expected one of {sorted(expected)}"
    for fragment in says:
        assert fragment in m["message"], (fragment, lines[0])
    return m["message"]


# ---- typos in the dungeon file ----------------------------------------------------------
@dataclass
class Case:
    id: str
    old: str | None                  # replaced (first occurrence) by new; None: new is the whole file
    new: str
    where: Callable[[str], set]      # acceptable positions, computed from the new text
    says: tuple = field(default=())


def apply(base: str, case: Case) -> str:
    if case.old is None:
        return case.new
    assert case.old in base, case.old
    return base.replace(case.old, case.new, 1)


DUNGEON_CASES = [
    # YAML itself
    Case("yaml-mapping-in-value", "height: 3", "height: 3: 4", at("3: 4", plus=1), ("invalid YAML",)),
    Case("yaml-tab-indent", "  facing: north", "\tfacing: north", at("\tfacing"), ("invalid YAML",)),
    Case("yaml-colon-in-goal", "goal: agentOnBlock(agent, gold)",
         "goal: exists b: block . blockIsType(b, gold)", at("b: block", plus=1), ("invalid YAML",)),
    Case("yaml-duplicate-key", "height: 3\n", "height: 3\nheight: 4\n", at("height: 4"), ("duplicate",)),
    # the map
    Case("map-unknown-char-middle", "  ##..#\n", "  ##.X#\n", at("X"), ("'X'",)),
    Case("map-unknown-char-first-row", "  #####\n  #G", "  ####Q\n  #G", at("Q"), ("'Q'",)),
    Case("map-unknown-char-last-row", "  #S..#\n  #####", "  #S..#\n  #~###", at("~"), ("'~'",)),
    Case("map-short-row", "  ##..#\n", "  ##..\n",
         any_of(at("  ##..\n", plus=2), at("  ##..\n", plus=6)), ("row 2",)),
    Case("map-long-row", "  ##..#\n", "  ##..##\n",
         any_of(at("  ##..##", plus=2), at("  ##..##", plus=7)), ("row 2",)),
    # the legend
    Case("legend-unknown-block", '"G": [gold]', '"G": [glod]', at("glod"),
         ("'glod'", "did you mean 'gold'")),
    Case("legend-unknown-block-second", '"#": [bedrock, bedrock, bedrock]', '"#": [bedrock, bedrok, bedrock]',
         at("bedrok"), ("bedrok",)),
    Case("legend-two-characters", '"G": [gold]', '"GG": [gold]', at('"GG"'), ("'GG'",)),
    Case("legend-not-a-list", '"G": [gold]', '"G": gold', at("gold\n")),
    Case("column-taller-than-height", '"#": [bedrock, bedrock, bedrock]',
         '"#": [bedrock, bedrock, bedrock, bedrock]', any_of(at('[bedrock, bedrock, bedrock, bedrock]'), at('"#"')),
         ("height",)),
    Case("height-too-small", "height: 3", "height: 2",
         any_of(at('[bedrock, bedrock, bedrock]'), at('"#"'), at("height: 2", plus=8))),
    Case("height-zero", "height: 3", "height: 0", at("height: 0", plus=8), ("height",)),
    Case("height-not-a-number", "height: 3", "height: three", at("three"), ("height",)),
    # the goal
    Case("goal-syntax", "goal: agentOnBlock(agent, gold)", "goal: agentOnBlock(agent,, gold)",
         at(",,", plus=1), ("syntax error", "','")),
    Case("goal-unexpected-character", "goal: agentOnBlock(agent, gold)", "goal: agentOnBlock(agent, gold) & true",
         at("&"), ("'&'",)),
    Case("goal-ends-too-early", "goal: agentOnBlock(agent, gold)", "goal: agentOnBlock(agent, gold) and",
         end_of_line("goal:"), ("ends too early",)),
    Case("goal-unclosed-paren", "goal: agentOnBlock(agent, gold)", "goal: agentOnBlock(agent, gold",
         end_of_line("goal:"), ("')'",)),
    Case("goal-block-scalar-second-line", "goal: agentOnBlock(agent, gold)",
         "goal: |\n  agentOnBlock(agent, gold) and\n    agentHasBlock(agent, diamond_pickaxe))\n",
         at("pickaxe))", plus=8), ("')'",)),
    Case("goal-block-scalar-unknown-function", "goal: agentOnBlock(agent, gold)",
         "goal: |\n  agentOnBlock(agent, gold)\n  and agentHasBlok(agent, gold)\n", at("agentHasBlok"),
         ("agentHasBlok", "did you mean 'agentHasBlock'")),
    Case("goal-quoted", "goal: agentOnBlock(agent, gold)", 'goal: "agentOnBlock(agent, gold) and $"', at("$"),
         ("'$'",)),
    Case("goal-unknown-function", "goal: agentOnBlock(agent, gold)", "goal: agentOnBlok(agent, gold)",
         at("agentOnBlok"), ("agentOnBlok", "did you mean 'agentOnBlock'")),
    Case("goal-unknown-function-later", "goal: agentOnBlock(agent, gold)",
         "goal: agentOnBlock(agent, gold) or not agentHasBlocks(agent, gold)", at("agentHasBlocks"),
         ("agentHasBlocks",)),
    Case("goal-too-few-arguments", "goal: agentOnBlock(agent, gold)", "goal: agentOnBlock(agent)",
         at("agentOnBlock"), ("agentOnBlock", "2")),
    Case("goal-too-many-arguments", "goal: agentOnBlock(agent, gold)", "goal: agentOnBlock(agent, gold, gold)",
         any_of(at("agentOnBlock"), at("gold", nth=3)), ("agentOnBlock", "2")),
    Case("goal-swapped-arguments", "goal: agentOnBlock(agent, gold)", "goal: agentOnBlock(gold, agent)",
         at("gold, agent"), ("type error",)),
    Case("goal-wrong-argument-type", "goal: agentOnBlock(agent, gold)", "goal: agentHasBlock(agent, agent)",
         at("agent)"), ("type error",)),
    Case("goal-is-an-int", "goal: agentOnBlock(agent, gold)", "goal: agent.x + 1",
         any_of(at("agent.x"), at("+")), ("type error", "bool", "int")),
    Case("goal-is-a-block-type", "goal: agentOnBlock(agent, gold)", "goal: gold", at("gold\n"), ("type error",)),
    Case("goal-compares-types", "goal: agentOnBlock(agent, gold)", "goal: agent.x == gold",
         any_of(at("agent.x"), at("=="), at("gold\n")), ("type error",)),
    Case("goal-unknown-attribute", "goal: agentOnBlock(agent, gold)", "goal: agent.xx == 1 and agent.alive",
         at("xx"), ("'xx'",)),
    Case("goal-unknown-name", "goal: agentOnBlock(agent, gold)", "goal: agentOnBlock(agnet, gold)",
         at("agnet"), ("'agnet'", "did you mean 'agent'")),
    Case("goal-unknown-class-in-quantifier", "goal: agentOnBlock(agent, gold)",
         "goal: exists b in blocks . b.blockType == gold",
         any_of(at("exists"), at("blocks")), ("'blocks'",)),
    # the agent
    Case("agent-start-missing", "  start: S\n", "",
         any_of(at("agent:"), at("facing")), ("start",)),
    Case("agent-start-not-in-map", "  start: S", "  start: P", at("P\n"), ("'P'",)),
    Case("agent-start-twice-in-map", "  ##..#\n", "  ##S.#\n", any_of(at("##S.#", plus=2), at("#S..#", plus=1)),
         ("more than once",)),
    Case("agent-start-outside", "  start: S", "  start: [1, 1, 9]", at("[1, 1, 9]"), ("outside",)),
    Case("agent-bad-facing", "facing: north", "facing: nort", at("nort\n"), ("'nort'",)),
    Case("agent-selected-out-of-range", "selected: 0", "selected: 9", at("9\n"), ("9",)),
    Case("agent-unknown-key", "  looking: ahead", "  lookin: ahead", at("lookin"), ("did you mean 'looking'",)),
    # top level, domain, inventory
    Case("unknown-top-level-key", "description:", "descripton:", at("descripton"),
         ("'descripton'", "did you mean 'description'")),
    Case("unknown-top-level-key-goal", "goal: agentOnBlock", "gaol: agentOnBlock", at("gaol"),
         ("did you mean 'goal'",)),
    Case("missing-map", "map: |\n  #####\n  #G..#\n  ##..#\n  #S..#\n  #####\n", "",
         any_of(at("dungeon:"), at("legend:")), ("map",)),
    Case("unknown-domain", "domain: minecraft", "domain: minecrafty", at("minecrafty"),
         ("minecrafty", "did you mean 'minecraft'")),
    Case("inventory-count-above-range", "count: 1}", "count: 65}", at("65"), ("65",)),
    Case("inventory-count-negative", "count: 1}", "count: -1}", at("-1"), ("count",)),
    Case("inventory-count-not-a-number", "count: 1}", "count: lots}", at("lots"), ("count",)),
    Case("inventory-unknown-item", "item: diamond_pickaxe", "item: diamond_pickax", at("diamond_pickax"),
         ("did you mean 'diamond_pickaxe'",)),
    Case("inventory-unknown-key", "count: 1}", "cuont: 1}", at("cuont"), ("did you mean 'count'",)),
    # the short forms: a slot as its item alone, the inventory as a mapping item -> count
    Case("inventory-short-slot-unknown-item", "{item: diamond_pickaxe, count: 1}", "diamond_pickax",
         at("diamond_pickax"), ("did you mean 'diamond_pickaxe'",)),
    Case("inventory-mapping-unknown-item", "  - {item: diamond_pickaxe, count: 1}", "  diamond_pickax: 1",
         at("diamond_pickax"), ("did you mean 'diamond_pickaxe'",)),
    Case("inventory-mapping-count-not-a-number", "  - {item: diamond_pickaxe, count: 1}", "  diamond_pickaxe: lots",
         at("lots"), ("count",)),
    Case("inventory-slot-a-list", "{item: diamond_pickaxe, count: 1}", "[diamond_pickaxe]",
         at("[diamond_pickaxe]"), ("inventory slot",)),
    Case("rooms-unknown-color", None, BASE + ROOMS.replace("color: red", "color: purple"), at("purple"),
         ("'purple'",)),
    Case("rooms-but-goal-names-no-room", None, BASE.replace("goal: agentOnBlock(agent, gold)",
                                                          "goal: agentInRoom(agent, hal)") + ROOMS,
         at("hal)"), ("'hal'",)),
]


@pytest.mark.parametrize("case", DUNGEON_CASES, ids=[c.id for c in DUNGEON_CASES])
def test_dungeon_typo_is_one_line_at_its_position(tmp_path, case):
    text = apply(BASE, case)
    path = tmp_path / "typo.yaml"
    path.write_text(text, encoding="utf-8")
    check_bad_input(run_cli("solve", str(path)), path, case.where(text), case.says)


@pytest.mark.parametrize("inventory", ["inventory:\n  - diamond_pickaxe\n", "inventory:\n  diamond_pickaxe: 1\n",
                                       "inventory: [diamond_pickaxe]\n", "inventory: {diamond_pickaxe: 1}\n"])
def test_short_inventories_mean_the_long_form(tmp_path, inventory):
    from bcc.compiler import compile_dungeon
    long_form = "inventory:\n  - {item: diamond_pickaxe, count: 1}\n"
    assert long_form in BASE
    (tmp_path / "long.yaml").write_text(BASE)
    (tmp_path / "short.yaml").write_text(BASE.replace(long_form, inventory))
    assert compile_dungeon(tmp_path / "short.yaml").initial == compile_dungeon(tmp_path / "long.yaml").initial


def test_a_mapping_inventory_fills_slots_in_the_order_written(tmp_path):
    from bcc.compiler import compile_dungeon
    listed = "inventory:\n  - {item: burlap_stone, count: 3}\n  - {item: diamond_pickaxe, count: 1}\n"
    mapped = "inventory: {burlap_stone: 3, diamond_pickaxe: 1}\n"
    (tmp_path / "a.yaml").write_text(BASE.replace("inventory:\n  - {item: diamond_pickaxe, count: 1}\n", listed))
    (tmp_path / "b.yaml").write_text(BASE.replace("inventory:\n  - {item: diamond_pickaxe, count: 1}\n", mapped))
    a, b = compile_dungeon(tmp_path / "a.yaml"), compile_dungeon(tmp_path / "b.yaml")
    assert a.initial == b.initial
    # and the order matters: slot 0 holds the stones
    (tmp_path / "c.yaml").write_text(BASE.replace("inventory:\n  - {item: diamond_pickaxe, count: 1}\n",
                                                  "inventory: {diamond_pickaxe: 1, burlap_stone: 3}\n"))
    assert compile_dungeon(tmp_path / "c.yaml").initial != a.initial


def test_the_base_dungeon_is_fine(tmp_path):
    """The cases above break a dungeon that compiles (so each typo is the only problem)."""
    path = tmp_path / "fine.yaml"
    path.write_text(BASE + ROOMS, encoding="utf-8")
    run = run_cli("compile", str(path))
    assert run.code == 0, run.stderr
    assert run.stderr == ""


def test_typo_in_an_extending_dungeon_points_into_that_file(tmp_path):
    base = tmp_path / "base.yaml"
    base.write_text(BASE, encoding="utf-8")
    text = "dungeon: child\nextends: base.yaml\ngoal: agentOnBlock(agent, golld)\n"
    child = tmp_path / "child.yaml"
    child.write_text(text, encoding="utf-8")
    check_bad_input(run_cli("solve", str(child)), child, at("golld")(text), ("'golld'",))


def test_extends_cycle_and_unknown_base(tmp_path):
    a = tmp_path / "a.yaml"
    a.write_text("dungeon: a\nextends: b.yaml\n", encoding="utf-8")
    b = tmp_path / "b.yaml"
    b.write_text("dungeon: b\nextends: a.yaml\n", encoding="utf-8")
    run = run_cli("solve", str(a))
    assert run.code == 2 and len(run.stderr.splitlines()) == 1
    assert "cycle" in run.stderr
    text = "dungeon: c\nextends: brige\n"
    c = tmp_path / "c.yaml"
    c.write_text(text, encoding="utf-8")
    check_bad_input(run_cli("solve", str(c)), c, at("brige")(text), ("did you mean 'bridge'",))


@pytest.mark.parametrize("text", ["", "# only a comment\n", "- a\n- list\n", "just a string\n"])
def test_empty_or_non_mapping_files(tmp_path, text):
    path = tmp_path / "odd.yaml"
    path.write_text(text, encoding="utf-8")
    run = run_cli("solve", str(path))
    assert run.code == 2
    assert len(run.stderr.splitlines()) == 1
    assert run.stderr.startswith(str(path) + ":")
    assert "Traceback" not in run.stderr + run.stdout


def test_missing_file_and_unknown_shipped_name():
    run = run_cli("solve", "no/such/dungeon.yaml")
    assert run.code == 2 and len(run.stderr.splitlines()) == 1 and "Traceback" not in run.stderr
    run = run_cli("solve", "bridg")
    assert run.code == 2 and len(run.stderr.splitlines()) == 1
    assert "did you mean 'bridge'" in run.stderr


def test_goal_option_errors_are_positioned_in_the_option():
    run = run_cli("solve", "grid", "--goal", "agentOnBlock(agent,, gold)")
    assert run.code == 2 and len(run.stderr.splitlines()) == 1
    assert run.stderr.startswith("--goal:1:20: ")


def test_invalid_utf8_is_bad_input(tmp_path):
    path = tmp_path / "latin1.yaml"
    path.write_bytes(BASE.replace("A small room", "Une pi\xe8ce").encode("latin-1"))
    run = run_cli("solve", str(path))
    assert run.code == 2 and len(run.stderr.splitlines()) == 1
    assert run.stderr.startswith(str(path))


# ---- typos in a domain file ------------------------------------------------------------
@dataclass
class DomainCase:
    id: str
    old: str
    new: str
    where: Callable[[str], set]      # positions in the domain text
    says: tuple = field(default=())
    goal: str | None = None          # a different goal for the dungeon
    rooms: bool = False


DOMAIN_CASES = [
    DomainCase("unknown-class-in-failure-quantifier", "failure: exists a in agent . not a.alive",
               "failure: exists a in agnet . not a.alive", any_of(at("exists a in agnet"), at("agnet")),
               ("'agnet'", "did you mean 'agent'")),
    DomainCase("unknown-class-in-precondition-quantifier", "      - t.mineable\n",
               "      - t.mineable\n      - exists b in blocks . b.x == tx\n",
               any_of(at("exists b in blocks"), at("blocks .")), ("'blocks'",)),
    DomainCase("unknown-class-in-called-function", "exists i in inventoryBlock . i.blockType == t",
               "exists i in inventoryBlocks . i.blockType == t",
               any_of(at("exists i in inventoryBlocks"), at("inventoryBlocks")), ("'inventoryBlocks'",),
               goal="agentHasBlock(agent, gold)"),
    DomainCase("effect-assigns-unknown-attribute",
               "effect: a.rotationalDirection = (a.rotationalDirection + 3) % 4",
               "effect: a.rotationalDirectoin = (a.rotationalDirection + 3) % 4",
               any_of(at("rotationalDirectoin"), at("a.rotationalDirectoin")),
               ("'rotationalDirectoin'", "did you mean 'rotationalDirection'")),
    DomainCase("effect-assigns-unknown-attribute-in-block-scalar", "      a.x = tx; a.z = tz;",
               "      a.x = tx; a.zz = tz;", any_of(at("zz"), at("a.zz")), ("'zz'",)),
    DomainCase("effect-assigns-wrong-type", "effect: a.verticalDirection = 1", "effect: a.verticalDirection = gold",
               any_of(at("= gold", plus=2), at("a.verticalDirection = gold")), ("type error",)),
    DomainCase("effect-adds-unknown-attribute", "{blockType = t} }\n", "{blockTipe = t} }\n",
               any_of(at("blockTipe"), at("add block[tx, a.y - 1, tz] {blockTipe")), ("'blockTipe'",)),
    DomainCase("effect-syntax-error-on-second-line-of-block-scalar",
               "else { add block[tx, a.y, tz] {blockType = t} };",
               "else { add block[tx, a.y, tz] {blockType t} };", at("blockType t}", plus=10),
               ("syntax error", "'t'")),
    DomainCase("precondition-argument-type-error", "      - inBounds(tx, tz)\n", "      - inBounds(tx, air)\n",
               at("inBounds(tx, air)", plus=13), ("type error",)),
    DomainCase("precondition-is-an-int", "      - a.verticalDirection == 1\n", "      - a.verticalDirection + 1\n",
               any_of(at("a.verticalDirection + 1"), at("a.verticalDirection + 1", plus=20)),
               ("type error", "bool")),
    DomainCase("precondition-compares-int-with-block-type", "      - a.verticalDirection == 1\n",
               "      - a.verticalDirection == air\n",
               any_of(at("a.verticalDirection == air"), at("a.verticalDirection == air", plus=20),
                      at("a.verticalDirection == air", plus=23)), ("type error",)),
    DomainCase("precondition-syntax-error", "      - t.mineable\n", "      - t.mineable and\n",
               end_of_line("t.mineable and"), ("ends too early",)),
    DomainCase("recursive-function", "body: 0 <= x < width and 0 <= z < depth",
               "body: 0 <= x < width and 0 <= z < depth and inBounds(x, z)", at("inBounds(x, z)"),
               ("inBounds",)),
    DomainCase("mutually-recursive-functions", "body: r.xMin < x < r.xMax and r.zMin < z < r.zMax",
               "body: r.xMin < x < r.xMax and agentInRoom(agent, r)",
               any_of(at("agentInRoom(agent, r)"), at("inRoomArea(a.x")), ("agentInRoom",),
               goal="agentInRoom(agent, hall)", rooms=True),
    DomainCase("unknown-attribute-type", "color: {type: color}", "color: {type: colour}", at("colour"),
               ("'colour'",), rooms=True),
    DomainCase("unknown-top-level-key", "\nfunctions:\n", "\nfunctons:\n", at("functons"),
               ("did you mean 'functions'",)),
    DomainCase("yaml-error", "  rotate_left:\n", "  rotate_left: :\n", at("rotate_left: :", plus=13),
               ("invalid YAML",)),
    DomainCase("function-parameter-of-unknown-type", "params: {x: int, z: int}", "params: {x: int, z: integer}",
               at("z: integer", plus=3), ("'integer'",)),
    DomainCase("unknown-enum-property", "      - t.mineable\n", "      - t.minable\n", at("minable"),
               ("'minable'", "did you mean 'mineable'")),
]


def write_domain_case(tmp_path: Path, case: DomainCase) -> tuple[Path, str, Path]:
    original = DOMAIN_FILE.read_text(encoding="utf-8")
    assert case.old in original, case.old
    domain_text = original.replace(case.old, case.new, 1)
    domain = tmp_path / "broken.yaml"
    domain.write_text(domain_text, encoding="utf-8")
    dungeon_text = BASE.replace("domain: minecraft", "domain: broken.yaml")
    if case.goal:
        dungeon_text = dungeon_text.replace("goal: agentOnBlock(agent, gold)", f"goal: {case.goal}")
    if case.rooms:
        dungeon_text += ROOMS
    dungeon = tmp_path / "dungeon.yaml"
    dungeon.write_text(dungeon_text, encoding="utf-8")
    return domain, domain_text, dungeon


@pytest.mark.parametrize("case", DOMAIN_CASES, ids=[c.id for c in DOMAIN_CASES])
def test_domain_typo_is_one_line_at_its_position(tmp_path, case):
    domain, domain_text, dungeon = write_domain_case(tmp_path, case)
    check_bad_input(run_cli("solve", str(dungeon)), domain, case.where(domain_text), case.says)


def test_an_unbroken_domain_copy_works(tmp_path):
    case = DomainCase("none", "domain: minecraft", "domain: minecraft", at("x"))
    _, _, dungeon = write_domain_case(tmp_path, case)
    run = run_cli("compile", str(dungeon))
    assert run.code == 0, run.stderr


UNUSED_CASES = [
    DomainCase("unused-function-with-unknown-class", "body: exists i in inventoryBlock . i.blockType == t",
               "body: exists i in inventoryBlocks . i.blockType == t",
               any_of(at("exists i in inventoryBlocks"), at("inventoryBlocks")), ("'inventoryBlocks'",)),
    DomainCase("unused-recursive-function", "body: r.xMin < x < r.xMax and r.zMin < z < r.zMax",
               "body: r.xMin < x < r.xMax and inRoomArea(x, z, r)", at("inRoomArea(x, z, r)"), ("inRoomArea",)),
]


@pytest.mark.parametrize("case", UNUSED_CASES, ids=[c.id for c in UNUSED_CASES])
def test_errors_in_functions_nobody_calls_are_reported(tmp_path, case):
    domain, domain_text, dungeon = write_domain_case(tmp_path, case)
    check_bad_input(run_cli("compile", str(dungeon)), domain, case.where(domain_text), case.says)


# ---- malformed domain sections (a value of the wrong YAML shape) ---------------------------
SHAPE_CASES = [
    DomainCase("cost-not-a-number", "  rotate_left:\n", "  rotate_left:\n    cost: two\n", at("two"), ("cost",)),
    DomainCase("params-a-list", "  rotate_left:\n    params: {a: agent}", "  rotate_left:\n    params: [a]",
               at("[a]"), ("params",)),
    DomainCase("values-a-number", "values: [red, orange, green, blue, white]", "values: 5", at("5\n"),
               ("values",)),
    DomainCase("empty-range", "selectedItem: {type: int, range: [0, 8]}", "selectedItem: {type: int, range: [8, 0]}",
               any_of(at("[8, 0]"), at("8, 0]")), ("range",)),
    DomainCase("range-not-constant", "selectedItem: {type: int, range: [0, 8]}",
               "selectedItem: {type: int, range: [0, agent.x]}", any_of(at("agent.x]"), at("x]"))),
    DomainCase("attribute-a-number", "xMin: {type: int}", "xMin: 5", at("5\n")),
    DomainCase("binding-unknown-class", "  grid: block ", "  grid: blocks ", at("grid: blocks", plus=6),
               ("did you mean 'block'",)),
    DomainCase("pre-not-text", "  rotate_left:\n", "  rotate_left:\n    pre: [{a: 1}]\n", at("{a: 1}"),
               ("expression",)),
    DomainCase("let-a-string", "  rotate_left:\n", "  rotate_left:\n    let: oops\n", at("oops"),
                            ("let",)),
    DomainCase("let-a-list", "  rotate_left:\n", "  rotate_left:\n    let: [tx, tz]\n",
                            at("[tx, tz]"), ("let",)),
    DomainCase("names-a-list", "names: {ahead: 0, down: 1}", "names: [ahead, down]",
                            at("[ahead, down]"), ("names",)),
    DomainCase("key-a-number", "key: [slot]", "key: 3", at("3\n"), ("key",)),
    DomainCase("key-a-string", "key: [slot]", "key: slot", at("slot\n"), ("key",)),
    DomainCase("enum-id-not-a-number", "air:             {id: 0, fillable: true}",
                            "air:             {id: zero, fillable: true}", at("zero"), ("id",)),
    DomainCase("binding-class-a-list", "  agent: agent ", "  agent: [agent] ", at("[agent]")),
    DomainCase("attribute-type-a-list", "xMin: {type: int}", "xMin: {type: [int]}", at("[int]"),
                            ("type",)),
]


@pytest.mark.parametrize("case", SHAPE_CASES, ids=[c.id for c in SHAPE_CASES])
def test_malformed_domain_section_is_bad_input(tmp_path, case):
    domain, domain_text, dungeon = write_domain_case(tmp_path, case)
    check_bad_input(run_cli("compile", str(dungeon)), domain, case.where(domain_text), case.says)


# ---- wrong positions (known bugs) --------------------------------------------------------
POSITION_BUGS = [
    Case("goal-plain-scalar-continued-on-next-line", "goal: agentOnBlock(agent, gold)",
         "goal: agentOnBlock(agent, gold) and\n  agentHasBlok(agent, gold)", at("agentHasBlok"), ("agentHasBlok",)),
    Case("goal-double-quoted-continued-on-next-line", "goal: agentOnBlock(agent, gold)",
         'goal: "agentOnBlock(agent, gold) and\n  agentHasBlok(agent, gold)"', at("agentHasBlok"), ("agentHasBlok",)),
    Case("goal-block-scalar-with-leading-blank-line", "goal: agentOnBlock(agent, gold)",
         "goal: |\n\n  agentOnBlock(agent, gold) and $\n", at("$"), ("'$'",)),
    Case("map-block-scalar-with-indentation-indicator", "map: |\n  #####\n  #G..#\n  ##..#\n  #S..#\n  #####",
         "map: |1\n   #####\n   #G..#\n   ##..#\n   #S..#\n   #####", at("   #####", plus=1), ("' '",)),
    Case("goal-double-quoted-with-escape", "goal: agentOnBlock(agent, gold)",
         'goal: "agentOnBlock(agent, \\x67old) and $"', at("$"), ("'$'",)),
]


@pytest.mark.parametrize("case", POSITION_BUGS, ids=[c.id for c in POSITION_BUGS])
def test_positions_inside_other_scalar_styles(tmp_path, case):
    text = apply(BASE, case)
    path = tmp_path / "typo.yaml"
    path.write_text(text, encoding="utf-8")
    check_bad_input(run_cli("solve", str(path)), path, case.where(text), case.says)


# ---- the real executable --------------------------------------------------------------------
PROCESS_CASES = ["yaml-mapping-in-value", "goal-swapped-arguments"]


@pytest.mark.parametrize("case_id", PROCESS_CASES)
def test_bcc_process_reports_one_line_and_exits_2(tmp_path, case_id):
    case = next(c for c in DUNGEON_CASES if c.id == case_id)
    text = apply(BASE, case)
    path = tmp_path / "typo.yaml"
    path.write_text(text, encoding="utf-8")
    check_bad_input(run_process("solve", str(path)), path, case.where(text), case.says)


def test_bcc_process_reports_domain_recursion(tmp_path):
    case = next(c for c in DOMAIN_CASES if c.id == "recursive-function")
    domain, domain_text, dungeon = write_domain_case(tmp_path, case)
    check_bad_input(run_process("solve", str(dungeon), "--json"), domain, case.where(domain_text), case.says)


# ---- unreachable goals: exit 1, not bad input ---------------------------------------------
@pytest.mark.parametrize("change", [
    ("goal: agentOnBlock(agent, gold)", "goal: agentOnBlock(agent, diamond_pickaxe)"),
    ("  #G..#\n", "  #G#.#\n"),  # the gold is walled off by bedrock on every side
], ids=["goal-on-an-item", "gold-walled-off"])
def test_unreachable_goal_exits_1_with_solved_false(tmp_path, change):
    path = tmp_path / "unreachable.yaml"
    path.write_text(BASE.replace(*change), encoding="utf-8")
    # the real executable once, CliRunner otherwise
    run = (run_process if "diamond" in change[1] else run_cli)("solve", str(path), "--json")
    assert "Traceback" not in run.stdout + run.stderr
    assert run.code == 1, (run.code, run.stderr)
    result = json.loads(run.stdout)
    assert result["solved"] is False
    assert result["plan"] == [] or result["plan"] is None
    assert run.stderr.strip(), "a reason on stderr"


@pytest.mark.parametrize("written,meant,options", [
    ("preconditions", "pre", {"params", "let", "pre", "effect", "cost"}),
    ("Requires", "pre", {"params", "let", "pre", "effect", "cost"}),
    ("parameters", "params", {"params", "let", "pre", "effect", "cost"}),
    ("integer", "int", {"int", "bool", "blocktype"}),
    ("name", "dungeon", {"dungeon", "domain", "goal"}),
    ("precondition", None, {"goal", "agent"}),        # the synonym's key is not offered here
])
def test_words_from_other_languages_suggest_bccs_key(written, meant, options):
    from bcc.compiler.source import suggest
    assert suggest(written, options) == (f" (did you mean {meant!r}?)" if meant else "")
