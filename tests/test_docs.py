"""The documentation is tested, so it cannot drift from bcc.

- docs/reference.md quotes grammar/expressions.lark verbatim, documents every keyword and
  operator of the grammar, and every key the domain and dungeon loaders accept.
- The tutorials are followed word for word in a temporary folder: every code block right
  after a `<!-- file: NAME -->` line is written to NAME (`<!-- append: NAME -->`: appended
  to it), and every ```sh block is run, one
  command a line (a trailing `\\` continues a line), in page order. A command must exit 0,
  or N when its line says `# exit status N`. A ```text block right after a ```sh block is
  what that block prints (stdout, then stderr, of each command in turn); it must match,
  except for timings.
- docs/add-a-solver.md is followed the same way, except that `pip install` installs into
  a temporary folder put on PYTHONPATH, so the surrounding environment is never touched.
- docs/add-a-heuristic.md changes bcc itself: it is followed in a copy of this checkout
  (its files are written there), which `bcc` then runs (the copy comes first on PYTHONPATH).
- Every relative link in README.md and docs/*.md points to an existing file (and heading).

The pages run in parallel, each in its own folder; the module takes about 25 s (each
`bcc` command costs most of a second).
To see what a page prints now: `python tests/test_docs.py docs/first-dungeon.md`.
"""
from __future__ import annotations

import ast
import importlib.metadata
import importlib.util
import os
import re
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
GRAMMAR = ROOT / "grammar" / "expressions.lark"
REFERENCE = DOCS / "reference.md"
PAGES = ["first-dungeon.md", "object-class.md", "add-a-solver.md", "grounding.md", "batch.md", "pddl.md", "hddl.md",
         "learning-curves.md", "add-a-heuristic.md", "crafting.md"]
IN_CHECKOUT = {"add-a-heuristic.md"}   # pages that change bcc's own files: followed in a copy of the checkout
NEEDS = {"learning-curves.md": "matplotlib"}  # pages whose commands need an optional extra: page -> the module it brings

FENCE = re.compile(r"^```([^\n`]*)\n(.*?)^```[ \t]*$", re.M | re.S)
FILE_MARK = re.compile(r"<!--\s*(file|append):\s*(\S+)\s*-->\s*\Z")
EXIT_MARK = re.compile(r"#\s*exit status (\d+)\s*$")
TIMINGS = [(re.compile(r"\b\d+\.\d+ s\b"), "<t> s"),
           (re.compile(r'("seconds"|"peak_mb"): [0-9.e-]+'), r"\1: <n>")]


# ---- reading pages ---------------------------------------------------------------------

@dataclass
class Block:
    lang: str
    text: str
    before: str          # the page text between the previous block and this one


def code_blocks(markdown: str) -> list[Block]:
    out, last = [], 0
    for m in FENCE.finditer(markdown):
        out.append(Block(m.group(1).strip(), m.group(2), markdown[last:m.start()]))
        last = m.end()
    return out


@dataclass
class Step:
    kind: str                                    # "file", "append" or "run"
    name: str = ""                               # file name
    text: str = ""                               # file content
    commands: list = field(default_factory=list)  # [(command, expected exit status)]
    output: str | None = None                    # expected output of the block, if shown


def steps_of(markdown: str) -> list[Step]:
    blocks = code_blocks(markdown)
    steps = []
    for i, b in enumerate(blocks):
        mark = FILE_MARK.search(b.before)
        if mark:
            steps.append(Step(mark.group(1), name=mark.group(2), text=b.text))
        elif b.lang == "sh":
            nxt = blocks[i + 1] if i + 1 < len(blocks) else None
            shown = nxt.text if nxt and nxt.lang == "text" and not nxt.before.strip() else None
            steps.append(Step("run", commands=commands_of(b.text), output=shown))
    return steps


def commands_of(script: str) -> list[tuple[str, int]]:
    out, pending = [], ""
    for line in script.splitlines():
        if line.rstrip().endswith("\\"):
            pending += line.rstrip()[:-1] + " "
            continue
        line, pending = pending + line, ""
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        m = EXIT_MARK.search(line)
        out.append((line.strip(), int(m.group(1)) if m else 0))
    return out


def normalize(text: str) -> str:
    for pattern, repl in TIMINGS:
        text = pattern.sub(repl, text)
    return "\n".join(line.rstrip() for line in text.strip("\n").splitlines())


# ---- following pages -------------------------------------------------------------------

def environment(site: Path | None = None) -> dict:
    env = dict(os.environ)
    # `bcc` is the one installed next to this Python (no shims, no other installation).
    env["PATH"] = os.pathsep.join([str(Path(sys.executable).parent), env.get("PATH", "")])
    env.pop("BCC_DEBUG", None)
    if site is not None:
        env["PYTHONPATH"] = os.pathsep.join(p for p in (str(site), env.get("PYTHONPATH")) if p)
    return env


def pip_into(site: Path, command: str) -> str:
    """`pip install X` -> install X into `site` only, offline, without build isolation."""
    args = command.split(None, 2)[2]
    return (f'"{sys.executable}" -m pip install --no-deps --no-build-isolation --no-index '
            f"--disable-pip-version-check --no-input --quiet --target \"{site}\" {args}")


def write(workdir: Path, step: Step) -> None:
    target = workdir / step.name
    target.parent.mkdir(parents=True, exist_ok=True)
    with open(target, "a" if step.kind == "append" else "w", encoding="utf-8") as f:
        f.write(step.text)


def follow(page: str, workdir: Path, echo: bool = False) -> list[str]:
    """Follow a page in `workdir`; the list of what went wrong (empty: the page works).
    Stops at the first failing command, since later steps build on earlier ones.
    With `echo`, print each command and what it prints (to paste into a page)."""
    site = workdir / ".site"
    env = environment(site)
    if page in IN_CHECKOUT:
        workdir = checkout_copy(workdir / "bcc")
        env["PYTHONPATH"] = os.pathsep.join([str(workdir.parent), env["PYTHONPATH"]])
    for step in steps_of((DOCS / page).read_text(encoding="utf-8")):
        if step.kind != "run":
            write(workdir, step)
            continue
        printed = []
        for command, expected in step.commands:
            run = pip_into(site, command) if command.startswith("pip install ") else command
            proc = subprocess.run(run, shell=True, cwd=workdir, env=env, capture_output=True, text=True, timeout=120)
            printed.append(proc.stdout + proc.stderr)
            if echo:
                print(f"$ {command}\n{proc.stdout}{proc.stderr}", end="")
            if proc.returncode != expected:
                return [f"{page}: `{command}` exited {proc.returncode}, the page says {expected}\n"
                        f"{proc.stdout}{proc.stderr}"]
        if step.output is not None and normalize("".join(printed)) != normalize(step.output):
            return [f"{page}: the output of\n  " + "\n  ".join(c for c, _ in step.commands) +
                    f"\nis not what the page shows.\n--- page\n{step.output}--- printed\n{''.join(printed)}"]
    return []


def checkout_copy(target: Path) -> Path:
    """This checkout's package (code and data, without tests, benchmarks, docs or build
    output) copied to `target`, a folder named `bcc`."""
    shutil.copytree(ROOT, target, ignore=shutil.ignore_patterns(".*", "__pycache__", "*.egg-info", "tests", "bench",
                                                                "docs", "build", "dist", "node_modules"))
    return target


def can_build_plugins() -> str | None:
    if importlib.util.find_spec("pip") is None or importlib.util.find_spec("setuptools") is None:
        return "pip and setuptools are needed to install the solver example"
    version = importlib.metadata.version("setuptools")
    parts = tuple(int(n) for n in re.findall(r"\d+", version)[:2])
    if parts < (70, 1) and importlib.util.find_spec("wheel") is None:
        return f"setuptools {version} needs the `wheel` package to build the solver example offline"
    return None


@pytest.fixture(scope="module")
def followed(tmp_path_factory):
    """Every tutorial page, followed in parallel, each in its own folder: page -> problems."""
    pool = ThreadPoolExecutor(max_workers=len(PAGES))
    futures = {page: pool.submit(follow, page, tmp_path_factory.mktemp(page.removesuffix(".md")))
               for page in PAGES if (page != "add-a-solver.md" or can_build_plugins() is None)
               and (page not in NEEDS or importlib.util.find_spec(NEEDS[page]) is not None)}
    yield futures
    pool.shutdown(wait=True)


# ---- the reference -----------------------------------------------------------------------

def lark_blocks() -> list[str]:
    return [b.text for b in code_blocks(REFERENCE.read_text(encoding="utf-8")) if b.lang == "lark"]


def reference_prose() -> str:
    """reference.md without its quotation of the grammar."""
    return FENCE.sub(lambda m: "" if m.group(1).strip() == "lark" else m.group(0),
                     REFERENCE.read_text(encoding="utf-8"))


def code_spans(markdown: str) -> set[str]:
    return set(re.findall(r"`([^`\n]+)`", markdown))


def grammar_literals() -> set[str]:
    text = "\n".join(line for line in GRAMMAR.read_text(encoding="utf-8").splitlines()
                     if not line.lstrip().startswith("//"))
    return {bytes(s, "utf-8").decode("unicode_escape") for s in re.findall(r'"((?:[^"\\]|\\.)*)"', text)}


def test_reference_quotes_the_grammar_verbatim():
    blocks = lark_blocks()
    assert len(blocks) == 1, "docs/reference.md needs exactly one ```lark block: grammar/expressions.lark"
    assert blocks[0] == GRAMMAR.read_text(encoding="utf-8"), \
        "the ```lark block in docs/reference.md differs from grammar/expressions.lark: copy the file into it"


def test_reference_explains_every_keyword_and_operator():
    literals = grammar_literals()
    assert {"exists", "forall", "first", "where", "add", "remove", "elif", "in", ":", "//"} <= literals
    missing = sorted(literals - code_spans(reference_prose()))
    assert not missing, f"docs/reference.md does not explain these grammar literals (as `code`): {missing}"


def _check_keys_literals(module: Path) -> set[str]:
    """Every string in the `allowed` argument of a check_keys(...) call in a loader."""
    keys = set()
    for node in ast.walk(ast.parse(module.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "check_keys" and len(node.args) > 1:
            keys |= {n.value for n in ast.walk(node.args[1]) if isinstance(n, ast.Constant) and isinstance(n.value, str)}
    return keys


def test_reference_documents_every_domain_and_dungeon_key():
    from bcc.compiler.domain import DOMAIN_KEYS
    from bcc.compiler.dungeon import DUNGEON_KEYS, FACINGS_KEYS
    prose = reference_prose()
    domain_part, _, rest = prose.partition("\n## Dungeon files")
    dungeon_part = rest.partition("\n## Expressions")[0]
    assert dungeon_part, "docs/reference.md needs the sections `## Dungeon files` and `## Expressions`"
    rows = lambda text: set(re.findall(r"^\|\s*`([^`]+)`", text, re.M))  # noqa: E731 - first cells of table rows
    assert not DOMAIN_KEYS - rows(domain_part), f"top-level domain keys missing: {sorted(DOMAIN_KEYS - rows(domain_part))}"
    assert not DUNGEON_KEYS - rows(dungeon_part), f"dungeon keys missing: {sorted(DUNGEON_KEYS - rows(dungeon_part))}"
    from bcc.compiler.tasks import METHOD_KEYS, TASK_KEYS
    nested = _check_keys_literals(ROOT / "compiler" / "domain.py") | _check_keys_literals(ROOT / "compiler" / "dungeon.py")
    nested |= set(FACINGS_KEYS) | TASK_KEYS | METHOD_KEYS | _check_keys_literals(ROOT / "compiler" / "tasks.py")
    missing = sorted(nested - code_spans(prose))
    assert not missing, f"keys the loaders accept but docs/reference.md does not mention (as `code`): {missing}"


# ---- the tutorials ----------------------------------------------------------------------

def test_tutorial_pages_have_steps():
    for page in PAGES:  # the tutorials write files; every page runs commands
        steps = steps_of((DOCS / page).read_text(encoding="utf-8"))
        assert any(s.kind == "run" for s in steps), page
        assert any(s.kind == "file" for s in steps) or page not in PAGES[:3], page


@pytest.mark.slow   # the pages run in one module fixture, about 30 s together
def test_first_dungeon_page_works_word_for_word(followed):
    problems = followed["first-dungeon.md"].result()
    assert not problems, problems[0]


@pytest.mark.slow   # the pages run in one module fixture, about 30 s together
def test_object_class_page_works_word_for_word(followed):
    problems = followed["object-class.md"].result()
    assert not problems, problems[0]


@pytest.mark.slow   # the pages run in one module fixture, about 30 s together
def test_add_a_solver_page_works_word_for_word(followed):
    if "add-a-solver.md" not in followed:
        pytest.skip(can_build_plugins())
    problems = followed["add-a-solver.md"].result()
    assert not problems, problems[0]


@pytest.mark.slow   # the pages run in one module fixture, about 30 s together
def test_add_a_heuristic_page_works_word_for_word(followed):
    problems = followed["add-a-heuristic.md"].result()
    assert not problems, problems[0]


@pytest.mark.slow
@pytest.mark.parametrize("page", ["grounding.md", "batch.md", "pddl.md", "hddl.md", "learning-curves.md"])
def test_feature_pages_work_word_for_word(followed, page):
    if page not in followed:
        pytest.skip(f"docs/{page} needs the {NEEDS[page]} module (an optional extra)")
    problems = followed[page].result()
    assert not problems, problems[0]


# ---- links --------------------------------------------------------------------------------

LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")


def anchors(page: Path) -> set[str]:
    """GitHub's heading anchors: lower case, punctuation dropped, spaces -> '-'."""
    headings = re.findall(r"^#+\s+(.*)$", FENCE.sub("", page.read_text(encoding="utf-8")), re.M)
    return {re.sub(r"[^\w\- ]", "", h.strip().lower()).replace(" ", "-") for h in headings}


def test_relative_links_point_to_existing_files():
    broken = []
    for page in [ROOT / "README.md", *sorted(DOCS.glob("*.md"))]:
        text = re.sub(r"`[^`\n]*`", "", FENCE.sub("", page.read_text(encoding="utf-8")))  # not in code
        for target in LINK.findall(text):
            if re.match(r"[a-z][a-z0-9+.-]*:", target):
                continue
            path, _, anchor = target.partition("#")
            file = page.parent / path if path else page
            if not file.exists():
                broken.append(f"{page.relative_to(ROOT)}: {target}")
            elif anchor and file.suffix == ".md" and anchor not in anchors(file):
                broken.append(f"{page.relative_to(ROOT)}: {target} (no such heading)")
    assert not broken, f"broken links: {broken}"


def test_readme_links_the_documentation():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    for page in [*PAGES, "reference.md"]:
        assert f"(docs/{page})" in readme, f"README.md does not link docs/{page}"


if __name__ == "__main__":  # print what a page's commands print now, to update the page
    for name in sys.argv[1:] or PAGES:
        with tempfile.TemporaryDirectory() as tmp:
            for problem in follow(Path(name).name, Path(tmp), echo=True):
                print(f"\nPROBLEM: {problem}")
