"""Fuzzing the shipped dungeon files: a mutated dungeon compiles or raises `BccError`, nothing else.

Mutations act on the text (delete, insert or replace a few characters, replace a token with
an odd YAML value, swap, drop or duplicate lines), so they hit every stage: YAML, the dungeon
format, the map, the expression parser, the type checker and the compiler. The library is
fuzzed in-process (fast); a handful of mutated files also go through the `bcc` executable,
which must never print a traceback and must exit 0 or 2 (one stderr line).
"""
from __future__ import annotations

import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from bcc.compiler import compile_dungeon
from bcc.errors import BccError

DUNGEONS = sorted((Path(__file__).resolve().parent.parent / "dungeons").glob("*.yaml"))
TEXTS = {p.name: p.read_text(encoding="utf-8") for p in DUNGEONS}
CHARS = "#.SLGMrogbX :[]{},-\"'\n\t|>&*!%@`0123456789abcdefghijklmnopqrstuvwxyz_()=<é"
VALUES = ["-1", "0", "1", "3", "9", "64", "65", "255", "256", "999999999999", "null", "~", "[]", "{}", "true",
          "false", ".inf", "1.5", '"x"', "''", "[1, 2, 3]", "[0, 0, 0]", "[1, 1]", "{a: 1}", "S", "SS", "G",
          "air", "gold", "lava", "[air]", "[lava, lava, lava, lava, lava]", "agent", "red", "north", "down",
          "!!binary aGk=", "2020-01-01", "0x10", "[[1]]", "&a x", "*a", "|\n  x", ">", "|", "#", "x: y",
          "agentOnBlock(agent, gold)", "agentInRoom(agent, red)", "not", "and", "exists b in block .",
          "block[0, 0, 0].blockType == gold", "agent.x", "bridge", "grid", "four_rooms", "minecraft"]
TOKEN = re.compile(r"[A-Za-z_][A-Za-z0-9_]*|-?\d+|\"[^\"\n]*\"|\[[^\]\n]*\]|\{[^}\n]*\}")

assert DUNGEONS, "no shipped dungeons found"


def mutate(text: str, ops: list) -> str:
    """Apply mutation ops; every op's numbers are reduced modulo the current text's size."""
    for op, *args in ops:
        lines = text.split("\n")
        if op in ("swap", "drop", "dup"):
            i = args[0] % len(lines)
            j = args[1] % len(lines)
            if op == "swap":
                lines[i], lines[j] = lines[j], lines[i]
            elif op == "drop" and len(lines) > 1:
                del lines[i]
            elif op == "dup":
                lines.insert(j, lines[i])
            text = "\n".join(lines)
            continue
        if op == "token":
            spans = [m.span() for m in TOKEN.finditer(text)]
            if spans:
                a, b = spans[args[0] % len(spans)]
                text = text[:a] + args[1] + text[b:]
            continue
        i = args[0] % (len(text) + 1)
        if op == "delete":
            text = text[:i] + text[i + args[1]:]
        elif op == "insert":
            text = text[:i] + args[1] + text[i:]
        elif op == "replace":
            text = text[:i] + args[1] + text[i + len(args[1]):]
    return text


index = st.integers(0, 10**6)
snippet = st.text(alphabet=CHARS, min_size=1, max_size=4)
operation = st.one_of(
    st.tuples(st.just("delete"), index, st.integers(1, 4)),
    st.tuples(st.just("insert"), index, snippet),
    st.tuples(st.just("replace"), index, snippet),
    st.tuples(st.just("token"), index, st.sampled_from(VALUES)),
    st.tuples(st.just("swap"), index, index),
    st.tuples(st.just("drop"), index, index),
    st.tuples(st.just("dup"), index, index),
)


def check_error(exc: BccError, allowed_paths: set[str]) -> None:
    text = str(exc)
    assert "\n" not in text and "\r" not in text, repr(text)
    assert exc.message and exc.message.strip()
    if exc.path is not None:
        assert str(Path(exc.path).resolve()) in allowed_paths, exc.path
    if exc.line is not None:
        assert isinstance(exc.line, int) and exc.line >= 1, text
        assert exc.col is None or (isinstance(exc.col, int) and exc.col >= 1), text
        assert text.startswith(f"{exc.path}:{exc.line}:"), text


def allowed_paths(mutated: Path) -> set[str]:
    """Errors may point into the mutated file, a shipped dungeon it extends, or a domain."""
    domains = (Path(__file__).resolve().parent.parent / "domains").glob("*.yaml")
    return {str(p.resolve()) for p in [mutated, *DUNGEONS, *domains]}


@settings(max_examples=120, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(st.sampled_from(sorted(TEXTS)), st.lists(operation, min_size=1, max_size=4))
def test_mutated_dungeon_compiles_or_raises_bcc_error(name, ops):
    text = mutate(TEXTS[name], ops)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / name  # same name: `extends: four_rooms` still finds the shipped base
        path.write_text(text, encoding="utf-8")
        try:
            compile_dungeon(str(path))
            event("compiled")
        except BccError as exc:
            event("BccError: " + re.sub(r"'[^']*'|\d+|\(.*", "_", exc.message)[:40])
            check_error(exc, allowed_paths(path))


@pytest.mark.parametrize("name", ["grid.yaml", "four_rooms_red.yaml"])
def test_each_line_dropped_compiles_or_raises_bcc_error(name, tmp_path):
    """Deterministic sweep: drop each line of each shipped dungeon in turn (a cheap,
    exhaustive mutation that removes keys, legend entries, map rows and list items)."""
    lines = TEXTS[name].split("\n")
    path = tmp_path / name
    for i in range(len(lines)):
        path.write_text("\n".join(lines[:i] + lines[i + 1:]), encoding="utf-8")
        try:
            compile_dungeon(str(path))
        except BccError as exc:
            check_error(exc, allowed_paths(path))


# ---- the executable ------------------------------------------------------------------------
def _random_ops(rng: random.Random, n: int) -> list:
    ops = []
    for _ in range(n):
        kind = rng.choice(["delete", "insert", "replace", "token", "swap", "drop", "dup"])
        i, j = rng.randrange(10**6), rng.randrange(10**6)
        if kind == "delete":
            ops.append((kind, i, rng.randint(1, 4)))
        elif kind in ("insert", "replace"):
            ops.append((kind, i, "".join(rng.choice(CHARS) for _ in range(rng.randint(1, 4)))))
        elif kind == "token":
            ops.append((kind, i, rng.choice(VALUES)))
        else:
            ops.append((kind, i, j))
    return ops


PROCESS_RUNS = [(name, seed) for seed, name in enumerate(
    ["grid.yaml", "bridge.yaml", "four_rooms.yaml", "four_rooms_red.yaml", "easy_maze.yaml"])]


@pytest.mark.parametrize("name,seed", PROCESS_RUNS)
def test_bcc_compile_on_a_mutated_file_never_prints_a_traceback(tmp_path, name, seed):
    rng = random.Random(seed)
    text = mutate(TEXTS[name], _random_ops(rng, 3))
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    env = {k: v for k, v in os.environ.items() if k != "BCC_DEBUG"}
    exe = shutil.which("bcc")
    cmd = [exe, "compile", str(path)] if exe else [sys.executable, "-m", "bcc", "compile", str(path)]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=300, env=env)
    assert "Traceback" not in proc.stdout + proc.stderr, proc.stderr
    assert proc.returncode in (0, 2), (proc.returncode, proc.stderr)
    if proc.returncode == 2:
        lines = proc.stderr.splitlines()
        assert len(lines) == 1, proc.stderr
        assert re.match(r"^.+:\d+:\d+: \S|^.+: \S", lines[0]), lines[0]
    else:
        assert proc.stderr == "" or "warning" in proc.stderr.lower(), proc.stderr
