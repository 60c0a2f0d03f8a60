"""The minimal bad inputs of issue 21, each once an internal error (exit 3): now exit 2 with
`file:line:col: message`, or a result. And the limits each input meets, with their messages.

Each case is a shipped file with one change, run through the CLI in-process
(`fuzz_harness.run_cli`, BCC_DEBUG=1 so a bug would escape as an exception and fail here).
"""
from __future__ import annotations

import re
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from bcc.compiler.limits import MAX_ALIAS_VALUES, MAX_EXPRESSION_DEPTH, MAX_GROUND_DEPTH, MAX_YAML_DEPTH
from fuzz_harness import DOMAINS, DUNGEONS, run_cli

BRIDGE, FOUR_ROOMS, MINECRAFT = DUNGEONS["bridge"], DUNGEONS["four_rooms"], DOMAINS["minecraft"]
GOAL = "goal: agentOnBlock(agent, gold)"
ROOMS = "rooms: {class: room, fields: {x: [xMin, xMax], z: [zMin, zMax], color: color}}"


def laughs(levels: int) -> str:
    lines = ['l0: &l0 ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]']
    lines += [f"l{i}: &l{i} [{', '.join([f'*l{i - 1}'] * 9)}]" for i in range(1, levels + 1)]
    return "\n".join(lines) + "\n"


# name -> (dungeon text, domain text or None, expected message (a regex), expected line or None)
DUNGEON_CASES = {
    "nul byte": (BRIDGE.replace("height: 4", "height: 4\x00"), r"character #x0000 is not allowed", 4),
    "4,301-digit height": (BRIDGE.replace("height: 4", "height: " + "9" * 4301), r"4,301 digits", 4),
    "huge hex number": (BRIDGE.replace("height: 4", "height: 0x" + "f" * 30), r"too large", 4),
    "300-character domain": (BRIDGE.replace("domain: minecraft", "domain: " + "a" * 300), r"unknown domain", 2),
    "300-character extends": ("extends: " + "a" * 300 + "\ngoal: x\n", r"no dungeon file", 1),
    "timestamp tag": (BRIDGE.replace("description: Mine", "description: !!timestamp 2001-13-99x #"),
                      r"tag !!timestamp is not supported", 3),
    "binary tag": (BRIDGE.replace("description: Mine", "description: !!binary aGk= #"), r"!!binary", 3),
    "set tag": (BRIDGE.replace("selected: 0", "selected: !!set {a, b}"), r"!!set", 24),
    "int tag on text": (BRIDGE.replace("selected: 0", "selected: !!int x"), r"not a valid !!int", 24),
    "1,000 nested brackets": (BRIDGE + "extra: " + "[" * 1000 + "]" * 1000 + "\n",
                              rf"nested more than {MAX_YAML_DEPTH} levels", 28),
    "not 198 times": (BRIDGE.replace(GOAL, "goal: " + "not " * 198 + "agentOnBlock(agent, gold)"),
                      rf"nested more than {MAX_EXPRESSION_DEPTH} levels", 27),
    "1,000 nested parentheses": (BRIDGE.replace(GOAL, "goal: " + "(" * 1000 + "agentOnBlock(agent, gold)" + ")" * 1000),
                                 None, None),
    "self-referencing alias": (BRIDGE.replace("selected: 0", "selected: &a [*a]"), r"contains it \(a YAML loop\)", 24),
    "mapping alias loop": (BRIDGE.replace("selected: 0", "selected: &a {k: *a}"), r"YAML loop", 24),
    "lone surrogate": (BRIDGE.replace("dungeon: bridge", 'dungeon: "\\ud800"'), r"lone surrogate", 1),
    "billion laughs": (BRIDGE + laughs(9), rf"repeat more than {MAX_ALIAS_VALUES:,} values", None),
    "aliases past the depth": (BRIDGE + "a: &a " + "[" * 60 + "1" + "]" * 60 + "\nb: &b " + "[" * 10 + "*a" +
                               "]" * 10 + "\n", rf"nested more than {MAX_YAML_DEPTH} levels deep once", 29),
    "not UTF-8": (BRIDGE.replace("height: 4", "height: 4 # \udcff"), r"not UTF-8", 4),
    "huge number in a goal": (BRIDGE.replace(GOAL, "goal: agent.x == " + "9" * 5000), r"5,000 digits", 27),
    "long name in a goal": (BRIDGE.replace(GOAL, "goal: " + "a" * 500 + " == 1"), r"longer than", 27),
}

DOMAIN_CASES = {
    "params: {a: [agent]}": (MINECRAFT.replace("  rotate_left:\n    params: {a: agent}",
                                               "  rotate_left:\n    params: {a: [agent]}"), r"unknown type or class"),
    "fields: {x: {a: 1}}": (MINECRAFT.replace("fields: {x: [xMin, xMax]", "fields: {x: {a: 1}"),
                            r"a field fills one attribute"),
    "constants: abc": (re.sub(r"constants:\n(  .*\n)+", "constants: abc\n", MINECRAFT), r"`constants` maps names"),
    "empty enumeration as a type": (MINECRAFT.replace("values: [red, orange, green, blue, white]", "values: []"),
                                    r"has no values"),
    "required: null": (MINECRAFT.replace(ROOMS, ROOMS[:-1] + ", required: null}"), r"`required` is a list"),
    "required: [1, x]": (MINECRAFT.replace(ROOMS, ROOMS[:-1] + ", required: [1, x]}"), r"`required` lists fields"),
    "101 nested if blocks": (MINECRAFT.replace("effect: a.verticalDirection = 1", "effect: " + "if a.x > 0 { " * 101 +
                                               "a.verticalDirection = 1" + " }" * 101), r"nested more than"),
    # the next two compare two attributes: a comparison with a constant outside the attribute's
    # declared range is folded to true (the compiler's range folding), which would leave no limit to hit
    "120 preconditions": (MINECRAFT.replace("  look_down:\n    params: {a: agent}\n", "  look_down:\n    params: {a: agent}\n"
                                            "    pre:\n" + "".join(f"      - a.x != a.z + {i} or a.z != a.x + {i}\n" for i in range(120))),
                          r"120 preconditions"),
    # an elif chain is one indented block of the generated code, but each branch is one
    # level for Python's compiler and the analyses: 400 branches pass MAX_EFFECT_LEVELS (300)
    "400 elif branches": (MINECRAFT.replace("effect: a.verticalDirection = 1", "effect: if a.x == 0 { a.verticalDirection = 1 } " +
                                            " ".join(f"elif a.x == a.z + {i} {{ a.verticalDirection = 1 }}" for i in range(1, 400))),
                          r"nested 400 deep .* exceed 300 levels"),
    "functions nested past the limit": (MINECRAFT.replace("functions:\n", "functions:\n  f0:\n    params: {a: agent}\n"
                                                          "    body: a.x > 0\n" + "".join(
                                                              f"  f{i}:\n    params: {{a: agent}}\n    body: {'not ' * 30}f{i - 1}(a)\n"
                                                              for i in range(1, 4)), 1),
                                        rf"more than {MAX_GROUND_DEPTH} levels deep once the functions"),
    # f0 is about 28 levels deep: called alone it fits, under 30 `not`s it does not; the
    # second call repeats the first's arguments, so the grounder's reuse of a call's
    # grounding must still see the limit
    "a function repeated past the limit": (MINECRAFT.replace("functions:\n", "functions:\n  f0:\n    params: {a: agent}\n"
                                                             f"    body: {'not ' * 25}a.x > 0\n", 1).replace(
        "  look_down:\n    params: {a: agent}\n",
        f"  look_down:\n    params: {{a: agent}}\n    pre: [f0(a), {'not ' * 30}f0(a)]\n"),
        rf"more than {MAX_GROUND_DEPTH} levels deep once the functions"),
    "a keyed class of 2^40 objects": (MINECRAFT.replace("slot: {type: int, range: [0, 8]}",
                                                        "slot: {type: int, range: [0, 1099511627775]}"), r"too large"),
    "an effect sets a constant out of range": (MINECRAFT.replace("effect: a.verticalDirection = 1",
                                                                 "effect: a.verticalDirection = 256"),
                                               r"sets agent.verticalDirection to 256, outside its range \[0, 1\]"),
    "types: abc": (re.sub(r"^types:\n(?:(?:  .*)?\n)*", "types: abc\n", MINECRAFT, flags=re.M), r"`types` must map"),
    "a keyed class of 10^6 objects": (MINECRAFT.replace("slot: {type: int, range: [0, 8]}",
                                                        "slot: {type: int, range: [0, 999999]}"), r"at most 65,536"),
}


def check_bad_input(outcome, pattern: str | None, line: int | None, path: Path) -> None:
    assert outcome.kind == "bad-input", (outcome.kind, outcome.detail, outcome.site)
    assert outcome.positioned, outcome.detail
    where = re.match(r"^(.+?):(\d+):(\d+): ", outcome.detail)
    assert Path(where.group(1)).name == path.name or Path(where.group(1)).name.endswith(".yaml"), outcome.detail
    if pattern:
        assert re.search(pattern, outcome.detail), outcome.detail
    if line is not None and Path(where.group(1)) == path:
        assert int(where.group(2)) == line, outcome.detail
    assert len(outcome.detail) < 700, len(outcome.detail)


@pytest.mark.parametrize("name", sorted(DUNGEON_CASES))
def test_bad_dungeon_is_bad_input_with_a_position(name, tmp_path):
    text, pattern, line = DUNGEON_CASES[name]
    path = tmp_path / "case.yaml"
    path.write_bytes(text.encode("utf-8", "surrogateescape"))
    outcome = run_cli(["compile", str(path)])
    if pattern is None:  # deep brackets are no nesting of the expression: a result
        assert outcome.kind == "ok", (outcome.kind, outcome.detail, outcome.site)
        return
    check_bad_input(outcome, pattern, line, path)


@pytest.mark.parametrize("name", sorted(DOMAIN_CASES))
def test_bad_domain_is_bad_input_with_a_position(name, tmp_path):
    domain, pattern = DOMAIN_CASES[name]
    assert domain != MINECRAFT, "the case must change the domain"
    (tmp_path / "dom.yaml").write_text(domain, encoding="utf-8")
    path = tmp_path / "case.yaml"
    path.write_text(FOUR_ROOMS.replace("domain: minecraft", "domain: dom.yaml"), encoding="utf-8")
    outcome = run_cli(["compile", str(path)])
    check_bad_input(outcome, pattern, None, path)
    assert "dom.yaml:" in outcome.detail


def test_a_goal_of_330_terms_is_solved(tmp_path):
    """Chains of one operator are balanced trees, not 330 levels of nesting."""
    path = tmp_path / "case.yaml"
    path.write_text(BRIDGE.replace(GOAL, "goal: " + " and ".join(["agentOnBlock(agent, gold)"] * 330)), encoding="utf-8")
    outcome = run_cli(["solve", str(path)])
    assert outcome.kind == "ok", (outcome.kind, outcome.detail, outcome.site)


def test_a_sum_of_500_terms_keeps_its_value(tmp_path):
    # agent.x starts at 1 (column of S in bridge); 1 + 1 + ... (500 ones) == 500 + 0: true
    # only if the balanced sum adds every term once.
    path = tmp_path / "case.yaml"
    path.write_text(BRIDGE.replace(GOAL, "goal: " + " + ".join(["1"] * 500) + " == 500 and agentOnBlock(agent, gold)"),
                    encoding="utf-8")
    assert run_cli(["solve", str(path)]).kind == "ok"
    path.write_text(BRIDGE.replace(GOAL, "goal: " + " + ".join(["1"] * 500) + " == 499 and agentOnBlock(agent, gold)"),
                    encoding="utf-8")
    assert run_cli(["solve", str(path)]).kind == "no-plan"


def test_an_unquoted_date_is_text_not_a_timestamp(tmp_path):
    path = tmp_path / "case.yaml"
    path.write_text(re.sub(r"description: .*", "description: 2001-01-01", BRIDGE), encoding="utf-8")
    from bcc.compiler import load_dungeon
    assert load_dungeon(str(path)).description == "2001-01-01"


def test_a_file_past_the_size_limit_is_refused_unread(tmp_path, monkeypatch):
    from bcc.compiler import source
    monkeypatch.setattr(source, "MAX_FILE_BYTES", 1000)
    path = tmp_path / "case.yaml"
    path.write_text(BRIDGE + "#" * 2000, encoding="utf-8")
    outcome = run_cli(["compile", str(path)])
    assert outcome.kind == "bad-input" and "larger than" in outcome.detail, outcome.detail


def test_a_message_quoting_a_huge_value_stays_short(tmp_path):
    path = tmp_path / "case.yaml"
    path.write_text(BRIDGE.replace("  facing: north", "  facing: " + "n" * 100_000), encoding="utf-8")
    outcome = run_cli(["compile", str(path)])
    assert outcome.kind == "bad-input" and len(outcome.detail) < 700, outcome.detail[:200]


# ---- exit 3 is for bcc's own bugs ----------------------------------------------------------
def test_an_internal_check_exits_3_and_bad_input_exits_2(tmp_path):
    """InternalError (a failed self-check, once `BccError("internal: ...")`, exit 2) exits 3
    through the real command; a bad file next to it still exits 2."""
    script = textwrap.dedent("""
        import sys
        from bcc.compiler import emit
        from bcc.errors import InternalError
        def broken(self, *args, **kwargs):
            raise InternalError("a state variable has no place in the state")
        emit.Emitter.build = broken
        from bcc.cli import main
        sys.argv = ["bcc", "compile", sys.argv[1]]
        main()
    """)
    ok = subprocess.run([sys.executable, "-c", script, "bridge"], capture_output=True, text=True, timeout=120)
    assert ok.returncode == 3, ok.stderr
    assert "internal error" in ok.stderr and "Traceback" not in ok.stderr
    bad = tmp_path / "bad.yaml"
    bad.write_text(BRIDGE.replace("height: 4", "height: 4\x00"), encoding="utf-8")
    proc = subprocess.run([sys.executable, "-c", script, str(bad)], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2 and re.match(r"^.+:\d+:\d+: ", proc.stderr), proc.stderr


def test_no_internal_error_is_reported_as_bad_input():
    root = Path(__file__).resolve().parent.parent
    sources = [*root.glob("*.py"), *(p for d in ("compiler", "solvers", "pddl_io", "grounding", "serve", "batch",
                                                 "minecraft") for p in (root / d).glob("*.py"))]
    offenders = [str(p.relative_to(root)) for p in sources if 'BccError(f"internal' in p.read_text(encoding="utf-8")]
    assert not offenders, offenders


@pytest.mark.parametrize("op", ["//", "%"])
def test_a_division_by_zero_at_run_time_is_a_positioned_domain_error(op, tmp_path):
    """`a.x - a.x` is 0 in every state but is no constant the compiler folds: the first
    look_down divides by it. A domain error at the division's place, exit 2 (it was a
    ZeroDivisionError, exit 3)."""
    domain = MINECRAFT.replace("effect: a.verticalDirection = 1", f"effect: a.verticalDirection = 1 {op} (a.x - a.x)")
    assert domain != MINECRAFT
    (tmp_path / "dom.yaml").write_text(domain, encoding="utf-8")
    path = tmp_path / "case.yaml"
    path.write_text(BRIDGE.replace("domain: minecraft", "domain: dom.yaml"), encoding="utf-8")
    outcome = run_cli(["solve", str(path), "--solver", "bfs"])
    assert outcome.kind == "bad-input", (outcome.kind, outcome.detail, outcome.site)
    assert re.search(rf"dom\.yaml:\d+:\d+: `{re.escape(op)}` by zero", outcome.detail), outcome.detail


def test_a_divisor_whose_bounds_exclude_zero_is_divided_directly(tmp_path):
    from bcc.compiler import compile_dungeon
    domain = MINECRAFT.replace("effect: a.verticalDirection = 1", "effect: a.verticalDirection = 1 // (a.x + 1)")
    (tmp_path / "dom.yaml").write_text(domain, encoding="utf-8")
    path = tmp_path / "case.yaml"
    path.write_text(BRIDGE.replace("domain: minecraft", "domain: dom.yaml"), encoding="utf-8")
    source = compile_dungeon(str(path)).source
    assert " // " in source and "_divide(" not in source
