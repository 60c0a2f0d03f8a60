"""Hostile text in any field of a domain or dungeon file never runs, never crashes bcc.

Every string in every shipped file -- mapping keys and values alike -- is replaced in turn
by strings a hostile or careless author might write: line breaks followed by code, quotes,
comment and brace characters, triple quotes, NUL, lone surrogates, terminal escapes and
10,000 characters. Each file is compiled through the CLI. The outcome must be a result
(exit 0, or 1) or bad input (exit 2, one `file:line:col: message` line without raw control
characters), never exit 3, and the code in the strings must never run: it would create a
canary file. The posted-text path of `bcc serve` gets the same strings (400, never 5xx).

The sweep over every field is marked slow; the quick loop runs a seeded sample.
"""
from __future__ import annotations

import functools
import json
import random
import re
import subprocess
import sys
import tokenize
from io import StringIO
from pathlib import Path

import pytest
import yaml
from click.testing import CliRunner

from bcc.cli import main
from bcc.compiler import compile_dungeon, shipped_dungeons
from bcc.compiler.domain import DOMAINS_DIR
from bcc.compiler.dungeon import DUNGEONS_DIR

LINE = re.compile(r"^[^\n]+:\d+:\d+: [^\n]+$")
RAW_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f\ud800-\udfff]")


def hostile_strings(canary: Path) -> list[str]:
    code = f"__import__('pathlib').Path({str(canary)!r}).write_text('ran')"
    return [
        f"b\n    {code}\n    #",          # a line break, then code at the generated code's indentation
        f"x\r{code}",
        "it's \"quoted\"",
        f"# {code}",
        "{" + code + "}",
        f"'''{code}'''",
        f'"""\n{code}\n"""',
        "a\x00b",
        "\ud800",
        "\x1b[31mred\x1b[0m\x1b]0;title\x07",
        "n" * 10_000,
    ]


def string_paths(node, path=()):
    """Paths to every string scalar and every mapping key: ("key", path, k) or ("value", path)."""
    if isinstance(node, dict):
        for k, v in node.items():
            if isinstance(k, str):
                yield ("key", path, k)
            yield from string_paths(v, path + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from string_paths(v, path + (i,))
    elif isinstance(node, str):
        yield ("value", path)


def mutated(doc, where, text):
    """A deep copy of `doc` with the string at `where` replaced by `text`."""
    doc = json.loads(json.dumps(doc))  # YAML of plain types: a JSON round trip copies it
    kind, path = where[0], where[1]
    parent = doc
    for step in path[:-1] if kind == "value" else path:
        parent = parent[step]
    if kind == "value":
        parent[path[-1]] = text
    else:
        key = where[2]
        parent[text] = parent.pop(key)
    return doc


def cases():
    """(label, dungeon file name, domain file name or None, which document is mutated, doc)."""
    out = []
    for name in shipped_dungeons():
        doc = yaml.safe_load((DUNGEONS_DIR / f"{name}.yaml").read_text())
        out.append((f"dungeon:{name}", name, doc, "dungeon"))
    for path in sorted(DOMAINS_DIR.glob("*.yaml")):
        doc = yaml.safe_load(path.read_text())
        dungeon = "grid" if path.stem == "minecraft" else "barnyard"
        out.append((f"domain:{path.stem}", dungeon, doc, "domain"))
    return out


def all_mutations(canary: Path, every_string: bool = True):
    """Every field with every hostile string; or (every_string=False) every field with the
    line-break-and-code string, and every fourth field with one other string besides,
    taken in turn, so each string still reaches dozens of fields of every kind. (With the
    building and crafting domains the shipped files hold about 3,500 fields: two strings
    each took some 40 CPU minutes, most of CI's budget.)"""
    strings = hostile_strings(canary)
    k = 0
    for label, dungeon, doc, kind in cases():
        for where in string_paths(doc):
            if every_string:
                chosen = range(len(strings))
            else:
                chosen = (0, 1 + (k // 4) % (len(strings) - 1)) if k % 4 == 0 else (0,)
            k += 1
            for i in chosen:
                yield label, dungeon, doc, kind, where, i, strings[i]


def write_case(tmp: Path, dungeon: str, doc, kind: str, where, text) -> Path:
    """Write the mutated file (and what it needs) into `tmp`; return the dungeon's path."""
    bad = mutated(doc, where, text)
    base = shipped_doc(dungeon)
    if kind == "domain":
        (tmp / "hostile_domain.yaml").write_text(_dump(bad), encoding="utf-8")
        base = dict(base, domain="hostile_domain.yaml")
        base.pop("extends", None)
        dungeon_doc = base
    else:
        dungeon_doc = bad
        if isinstance(bad, dict) and isinstance(bad.get("extends"), str) and bad["extends"] in shipped_dungeons():
            # an `extends:` names a sibling file: give it one
            (tmp / f"{bad['extends']}.yaml").write_text((DUNGEONS_DIR / f"{bad['extends']}.yaml").read_text())
    path = tmp / "hostile.yaml"
    path.write_text(_dump(dungeon_doc), encoding="utf-8")
    return path


def _dump(doc) -> str:
    """YAML text of plain data (libyaml's emitter where PyYAML has it: thousands of cases)."""
    try:
        return yaml.dump(doc, Dumper=getattr(yaml, "CSafeDumper", yaml.SafeDumper), allow_unicode=False)
    except UnicodeEncodeError:      # a lone surrogate: only PyYAML's own emitter writes it (escaped)
        return yaml.safe_dump(doc, allow_unicode=False)


@functools.lru_cache(maxsize=None)
def _shipped_text(dungeon: str) -> str:
    return (DUNGEONS_DIR / f"{dungeon}.yaml").read_text()


def shipped_doc(dungeon: str):
    """A fresh copy of a shipped dungeon's plain data."""
    return yaml.load(_shipped_text(dungeon), Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))


def check_outcome(result, what: str) -> None:
    assert result.exit_code in (0, 1, 2), f"{what}: exit {result.exit_code}: {result.output[-500:]}"
    if result.exit_code == 2:
        lines = result.stderr.strip().splitlines()
        assert len(lines) == 1 and LINE.match(lines[0]), f"{what}: not one positioned line: {result.stderr[:300]!r}"
    assert not RAW_CONTROL.search(result.stderr), f"{what}: raw control characters printed: {result.stderr[:300]!r}"
    assert not RAW_CONTROL.search(result.stdout), f"{what}: raw control characters printed: {result.stdout[:300]!r}"


def run_mutations(tmp_path: Path, sample: int | None, every_string: bool = True) -> int:
    canary = tmp_path / "canary"
    work = tmp_path / "work"
    work.mkdir()
    mutations = list(all_mutations(canary, every_string))
    if sample is not None:
        mutations = random.Random(21).sample(mutations, sample)
    runner = CliRunner()
    for label, dungeon, doc, kind, where, i, text in mutations:
        path = write_case(work, dungeon, doc, kind, where, text)
        result = runner.invoke(main, ["compile", str(path), "--json"], catch_exceptions=False)
        check_outcome(result, f"{label} {where[:2]} string {i}")
        assert not canary.exists(), f"{label} {where}: the code in a string ran"
    return len(mutations)


def test_hostile_strings_in_a_sample_of_fields(tmp_path):
    assert run_mutations(tmp_path, sample=150) == 150


@pytest.mark.slow
def test_hostile_strings_in_every_field_of_every_shipped_file(tmp_path):
    # ~4,400 compiles (every field with the code string, every fourth with one more); all
    # 11 strings on every field is about 39,000 and runs in bench/fuzz.py's league, not here.
    assert run_mutations(tmp_path, sample=None, every_string=False) > 4000


# ---- the reported attack, through the real executable -----------------------------------
def test_an_animal_named_with_code_is_refused_and_never_runs(tmp_path):
    canary = tmp_path / "PWNED"
    doc = yaml.safe_load((DUNGEONS_DIR / "barnyard.yaml").read_text())
    # Before the fix, this name became a line of generated Python (a comment broken by the
    # newline) and `bcc solve` ran it.
    doc["animals"][0]["name"] = f"b\n    open({str(canary)!r}, 'w').write('x')\n    #"
    doc["goal"] = "animalFed(wilbur)"
    path = tmp_path / "evil.yaml"
    path.write_text(yaml.safe_dump(doc))
    for command in ("compile", "solve"):
        proc = subprocess.run([sys.executable, "-m", "bcc", command, str(path)], capture_output=True, text=True,
                              timeout=120)
        assert proc.returncode == 2, proc.stderr
        assert re.match(rf"^{re.escape(str(path))}:\d+:\d+: an animal's name (must be|is)", proc.stderr)
        assert not canary.exists()


# ---- what the generated code may contain -----------------------------------------------------
GENERATED_NAME = re.compile(r"(v|_t|T|apply_|why_)\d+\Z")
ALLOWED_NAMES = {"def", "return", "if", "else", "elif", "not", "and", "or", "in", "for", "None", "True", "False",
                 "pass", "s", "n", "out", "append", "bytes", "bytearray", "range", "any", "all", "successors",
                 "goal", "failure", "SG", "_cell", "_set_cell", "_index", "_range", "ModelError",
                 "c", "w", "_cells", "_merge",   # compact states: expanded cells, cell writes
                 "len", "_S0", "_expand",        # ... the start's cells, or a changed state's expanded
                 "live", "t", "_live_slow",      # successors for search: the next state, failing starts
                 "_CC", "get",                   # ... expansions already made, per diff
                 "_I", "_L", "_d", "_from_bytes", "to_bytes",   # next states built as one integer sum
                 "fresh", "seen", "_k", "_fresh_slow"}          # fused with the duplicate check


@pytest.mark.parametrize("name", shipped_dungeons())
def test_generated_code_holds_no_text_from_the_input(name):
    """Every identifier in the generated module is bcc's own (numbered locals, tables,
    helpers); every comment is an action's index. Input text appears only inside string
    literals, which `repr()` made."""
    source = compile_dungeon(name).source
    for tok in tokenize.generate_tokens(StringIO(source).readline):
        if tok.type == tokenize.NAME:
            assert tok.string in ALLOWED_NAMES or GENERATED_NAME.match(tok.string), tok
        elif tok.type == tokenize.COMMENT:
            assert re.fullmatch(r"# action \d+", tok.string), tok


# ---- the server: posted text ---------------------------------------------------------------
def test_hostile_posted_dungeons_get_400_never_5xx(tmp_path):
    pytest.importorskip("fastapi")
    pytest.importorskip("uvicorn")
    from serve_harness import running_server
    canary = tmp_path / "canary"
    rng = random.Random(7)
    posted = []
    for name in ("barnyard", "bridge"):
        doc = yaml.safe_load((DUNGEONS_DIR / f"{name}.yaml").read_text())
        wheres = list(string_paths(doc))
        for where in rng.sample(wheres, min(8, len(wheres))):
            for text in hostile_strings(canary):
                posted.append(yaml.safe_dump(mutated(doc, where, text), allow_unicode=False))
    # Raw text too: a lone surrogate, NUL and an escape straight in the posted YAML.
    bridge = (DUNGEONS_DIR / "bridge.yaml").read_text()
    posted += [bridge.replace("dungeon: bridge", "dungeon: \ud800"), bridge.replace("bridge", "br\x00idge", 1),
               bridge.replace("description:", "description: \x1b[2J")]
    with running_server("--workers", "1", "--job-memory", "256") as api:
        for text in posted:
            for path, body in (("/compile", {"dungeon": text}), ("/replay", {"dungeon": text, "actions": ["rotate_left"]}),
                               ("/solve", {"dungeon": text, "time_limit": 5})):
                status, answer = api.post(path, body)
                assert status < 500, (path, status, answer)
                if status == 400:
                    assert answer["file"] in ("<posted>", None) or isinstance(answer["file"], str)
                    assert not RAW_CONTROL.search(answer["error"]), answer
        assert api.get("/health")[0] == 200
    assert not canary.exists()
