"""A seeded mutator of bcc's own input files, and one run of `bcc` on a mutated input.

Shared by tests/test_fuzz_inputs.py (a few hundred inputs in CI) and bench/fuzz.py (10,000+).
Every case starts from a shipped domain or dungeon file and applies 1-3 mutations from
four families, so each stage of the compiler is reached by inputs that get past the ones
before it:

- text: characters deleted, inserted or replaced; lines dropped, swapped or duplicated;
  a token replaced by an odd YAML value (tags, anchors, aliases, huge numbers, ...);
- structure: the file is parsed, a random key or item is deleted, renamed, duplicated,
  retyped (a list for a name, a mapping for a number, ...), deeply nested, or replaced by
  a value copied from elsewhere in the file, and the tree is written back as YAML;
- expression: a goal, precondition, effect, function body or range is re-tokenized and
  tokens are dropped, repeated, swapped or replaced by names the domain defines,
  keywords and operators; or a subexpression is wrapped in `not`, brackets, `and` chains;
- goal: a random well-formed expression over the domain's names goes in `--goal`.

`run_case` writes the files to a directory and runs the CLI in-process through
`bcc.cli.main` (the `bcc` entry point) with `BCC_DEBUG=1`, so a bug escapes as an
exception whose innermost bcc frame names its code site. Outcomes: "ok" (exit 0),
"no-plan" (exit 1: no plan or a budget ran out), "bad-input" (exit 2 with one line
`file:line:col: message` or `file: message`), "bad-message" (exit 2 but not one such
line), "internal" (an exception: a bug), "exit-3"/"exit-N" (any other exit code).
"""
from __future__ import annotations

import copy
import os
import random
import re
import traceback
from dataclasses import dataclass, field
from pathlib import Path

import yaml

import bcc

# The shipped files the cases start from; BCC_FUZZ_ROOT=another checkout replays the cases
# of that checkout's file set (seed i is the same input only over the same files).
ROOT = Path(os.environ.get("BCC_FUZZ_ROOT") or Path(__file__).resolve().parent.parent)
DOMAINS = {p.stem: p.read_text(encoding="utf-8") for p in sorted((ROOT / "domains").glob("*.yaml"))}
DUNGEONS = {p.stem: p.read_text(encoding="utf-8") for p in sorted((ROOT / "dungeons").glob("*.yaml"))}
BCC_DIR = str(Path(bcc.__file__).resolve().parent)  # the code under test (installed or not)

# Odd values for the text and structure families: YAML features bcc refuses, values of
# the wrong type, numbers at and past the limits, long and hostile text.
ODD_TEXT = ["-1", "0", "1", "3", "9", "64", "255", "256", "999999999999", "2147483647", "2147483648",
            "9" * 4301, "0x7fffffffffffffffff", "1:2:3", "1_000", "null", "~", "[]", "{}", "true", "no",
            ".inf", ".nan", "-.inf", "1.5", "1e400", '"x"', "''", "[1, 2, 3]", "[0, 0, 0]", "[[1]]", "{a: 1}",
            "S", "SS", "G", "air", "gold", "lava", "[air]", "agent", "red", "north", "block", "room",
            "!!binary aGk=", "!!timestamp 2001-13-99x", "2020-01-01", "!!set {a, b}", "!!omap [a: 1]",
            "!!python/object:os.system x", "!custom x", "!!str 1", "!!int x", "!!float x", "&a x", "*a",
            "&a [*a]", "&b {k: *b}", "|\n  x", ">", "|", "#", "x: y", "? x", "- x", "<<: {a: 1}",
            '"\\ud800"', '"\\x00"', '"\\e[31m"', '"a\\nb"', '"\\u202e"', "'" + "a" * 300 + "'",
            "[" * 70 + "]" * 70, "{" * 5, "]", "*undefined", "\t", "%YAML 1.1", "---", "...",
            "agentOnBlock(agent, gold)", "agentInRoom(agent, red)", "not", "and", "exists b in block .",
            "block[0, 0, 0].blockType == gold", "agent.x", "bridge", "grid", "four_rooms", "minecraft", "farm"]
ODD_VALUES = [None, True, False, 0, -1, 1, 2, 255, 256, 2**31 - 1, 2**31, 10**40, 1.5, float("inf"), "",
              "x", "a" * 300, "agent", "block", "room", "int", "bool", "air", "gold", "red", "north",
              "\x1b[31m", "a\nb", "a b", "1abc", "é", [], {}, [None], [1, 2, 3], [[[[1]]]], {"a": 1},
              {"type": "int"}, {"class": "agent"}, ["agent"], {"x": {"a": 1}}, "$(reboot)", "a{b}c", "'\"'"]
CHARS = "#.SLGMrogbX :[]{},-\"'\n\t|>&*!%@`0123456789abcdefghijklmnopqrstuvwxyz_()=<é\\"
KEYWORDS = ["and", "or", "not", "exists", "forall", "in", "if", "elif", "else", "first", "where", "add",
            "remove", "true", "false", ":"]
OPERATORS = ["==", "!=", "<=", ">=", "<", ">", "+", "-", "*", "//", "%", "=", ";", ".", ",", "(", ")", "[", "]",
             "{", "}", "+=", "-=", "*=", "//=", "%=", "&&", "||", "!", "'"]
NUMBERS = ["0", "1", "2", "-1", "3", "8", "9", "63", "64", "255", "256", "65536", "2147483647", "2147483648",
           "99999999999999999999", "9" * 4301]
EXPR_TOKEN = re.compile(r"[A-Za-z_][A-Za-z0-9_]*|\d+|==|!=|<=|>=|//|\S")
TEXT_TOKEN = re.compile(r"[A-Za-z_][A-Za-z0-9_]*|-?\d+|\"[^\"\n]*\"|\[[^\]\n]*\]|\{[^}\n]*\}")
# Keys whose values are expressions (or effect lists) in domain and dungeon files.
EXPR_KEYS = {"goal", "pre", "effect", "body", "failure", "range"}


@dataclass
class Case:
    """Files to write (name -> text), the dungeon to run (or, for a PDDL case, the domain,
    with the problem in args), and extra CLI arguments."""
    files: dict
    target: str
    args: list = field(default_factory=list)
    label: str = ""
    front: str = "yaml"   # "yaml": `bcc solve TARGET ARGS`; "pddl": `bcc import pddl TARGET PROBLEM`


def _load(text: str):
    """The file as plain data, or None where PyYAML cannot read it (the mutator never fails)."""
    try:
        return yaml.safe_load(text)
    except Exception:  # noqa: BLE001 - PyYAML raises ValueError, RecursionError, ... on odd text
        return None


def _dump(tree, fallback: str) -> str:
    try:
        return yaml.safe_dump(tree, sort_keys=False, allow_unicode=True, width=100000)
    except Exception:  # noqa: BLE001
        return fallback


# ---- names a domain defines (for expression mutations and random goals) ---------------
def _names(domain_text: str) -> list[str]:
    data = _load(domain_text)
    out = set()
    for section in ("types", "constants", "classes", "functions", "actions"):
        part = data.get(section) if isinstance(data, dict) else None
        if isinstance(part, dict):
            out.update(map(str, part))
            for v in part.values():
                if isinstance(v, dict):
                    for sub in ("attributes", "values", "properties", "params"):
                        if isinstance(v.get(sub), dict):
                            out.update(map(str, v[sub]))
                        elif isinstance(v.get(sub), list):
                            out.update(map(str, v[sub]))
    return sorted(out | {"agent", "width", "height", "depth", "red", "gold", "air"})


NAMES = {name: _names(text) for name, text in DOMAINS.items()}
for _name, _text in list(DOMAINS.items()):  # an extending domain also sees its base's names
    _base = re.search(r"^extends:\s*(\S+)", _text, re.M)
    if _base and _base.group(1) in NAMES:
        NAMES[_name] = sorted(set(NAMES[_name]) | set(NAMES[_base.group(1)]))


def domain_of(dungeon: str) -> str:
    text = DUNGEONS[dungeon]
    m = re.search(r"^domain:\s*(\S+)", text, re.M)
    if m:
        return m.group(1)
    base = re.search(r"^extends:\s*(\S+)", text, re.M)
    return domain_of(base.group(1)) if base and base.group(1) in DUNGEONS else "minecraft"


# ---- text mutations --------------------------------------------------------------------
def mutate_text(text: str, rng: random.Random) -> str:
    op = rng.choice(["delete", "insert", "replace", "token", "token", "swap", "drop", "dup"])
    lines = text.split("\n")
    if op in ("swap", "drop", "dup"):
        i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
        if op == "swap":
            lines[i], lines[j] = lines[j], lines[i]
        elif op == "drop" and len(lines) > 1:
            del lines[i]
        else:
            lines.insert(j, lines[i])
        return "\n".join(lines)
    if op == "token":
        spans = [m.span() for m in TEXT_TOKEN.finditer(text)]
        if spans:
            a, b = rng.choice(spans)
            return text[:a] + rng.choice(ODD_TEXT) + text[b:]
        return text
    i = rng.randrange(len(text) + 1)
    snippet = "".join(rng.choice(CHARS) for _ in range(rng.randint(1, 4)))
    if op == "delete":
        return text[:i] + text[i + rng.randint(1, 6):]
    if op == "insert":
        return text[:i] + snippet + text[i:]
    return text[:i] + snippet + text[i + len(snippet):]


# ---- structure mutations ---------------------------------------------------------------
def _paths(node, prefix=()):
    """Every (path, value) in a loaded YAML tree; a path is a tuple of keys and indices."""
    out, todo = [], [(prefix, node)]
    while todo:
        path, value = todo.pop()
        out.append((path, value))
        if isinstance(value, dict):
            todo += [(path + (k,), v) for k, v in value.items()]
        elif isinstance(value, list):
            todo += [(path + (i,), v) for i, v in enumerate(value)]
    return out


def _get(tree, path):
    for k in path:
        tree = tree[k]
    return tree


def mutate_structure(text: str, rng: random.Random) -> str:
    tree = _load(text)
    if not isinstance(tree, dict):
        return mutate_text(text, rng)
    paths = [p for p, _ in _paths(tree) if p]
    if not paths:
        return text
    path = rng.choice(paths)
    parent, key = _get(tree, path[:-1]), path[-1]
    op = rng.choice(["odd", "odd", "delete", "copy", "rename", "wrap", "nest", "dup", "swap", "empty"])
    if op == "odd":
        parent[key] = copy.deepcopy(rng.choice(ODD_VALUES))
    elif op == "delete":
        del parent[key]
    elif op == "copy":
        parent[key] = copy.deepcopy(_get(tree, rng.choice(paths)))
    elif op == "rename" and isinstance(parent, dict):
        new = rng.choice([str(rng.choice(paths)[-1]), str(key) + "x", str(key)[:-1] or "k", 7, True, None])
        if new not in parent:
            parent[new] = parent.pop(key)
    elif op == "wrap":
        parent[key] = rng.choice([[parent[key]], {"x": parent[key]}, {str(key): parent[key]}])
    elif op == "nest":
        value = parent[key]
        for _ in range(rng.choice([3, 20, 63, 64, 70])):
            value = [value]
        parent[key] = value
    elif op == "dup" and isinstance(parent, list):
        parent.insert(key, copy.deepcopy(parent[key]))
    elif op == "dup" and isinstance(parent, dict):
        parent[f"{key}2"] = copy.deepcopy(parent[key])
    elif op == "swap":
        other = rng.choice(paths)
        try:
            oparent = _get(tree, other[:-1])
            parent[key], oparent[other[-1]] = oparent[other[-1]], parent[key]
        except (KeyError, IndexError, TypeError):
            pass
    elif op == "empty":
        parent[key] = type(parent[key])() if isinstance(parent[key], (list, dict, str)) else None
    return _dump(tree, text)


# ---- expression mutations --------------------------------------------------------------
def mutate_expression(expr: str, rng: random.Random, names: list[str]) -> str:
    tokens = EXPR_TOKEN.findall(expr)
    if not tokens:
        return rng.choice(names)
    op = rng.choice(["drop", "repeat", "swap", "name", "name", "keyword", "operator", "number",
                     "not", "brackets", "chain", "call", "attr", "index", "nest"])
    i = rng.randrange(len(tokens))
    if op == "drop":
        del tokens[i]
    elif op == "repeat":
        tokens.insert(i, tokens[i])
    elif op == "swap" and len(tokens) > 1:
        j = rng.randrange(len(tokens))
        tokens[i], tokens[j] = tokens[j], tokens[i]
    elif op == "name":
        tokens[i] = rng.choice(names)
    elif op == "keyword":
        tokens[i] = rng.choice(KEYWORDS)
    elif op == "operator":
        tokens[i] = rng.choice(OPERATORS)
    elif op == "number":
        tokens[i] = rng.choice(NUMBERS)
    elif op == "not":
        return "not " * rng.choice([1, 2, 39, 40, 41, 60, 198]) + f"({expr})"
    elif op == "brackets":
        n = rng.choice([1, 30, 100, 1000])
        return "(" * n + expr + ")" * n
    elif op == "chain":
        return f" {rng.choice(['and', 'or', '+'])} ".join([f"({expr})"] * rng.choice([2, 3, 50, 330, 1000]))
    elif op == "call":
        tokens[i:i + 1] = [rng.choice(names), "(", *tokens[i:i + 1], ",", rng.choice(names), ")"]
    elif op == "attr":
        tokens[i:i + 1] = [tokens[i], ".", rng.choice(names)]
    elif op == "index":
        tokens[i:i + 1] = [tokens[i], "[", rng.choice(NUMBERS[:8] + names), "]"]
    elif op == "nest":
        block = rng.choice(["if a.x > 0 {", "forall i in inventoryBlock {", "first i in inventoryBlock where true {"])
        n = rng.choice([2, 20, 41, 101])
        return block * n + expr + "}" * n
    return " ".join(tokens)


def _expression_paths(tree) -> list:
    out = []
    for path, value in _paths(tree):
        if isinstance(value, (str, int, bool)) and any(str(k) in EXPR_KEYS for k in path if isinstance(k, str)):
            out.append(path)
    return out


def mutate_expressions(text: str, rng: random.Random, names: list[str]) -> str:
    tree = _load(text)
    paths = _expression_paths(tree) if isinstance(tree, dict) else []
    if not paths:
        return mutate_structure(text, rng)
    path = rng.choice(paths)
    parent = _get(tree, path[:-1])
    parent[path[-1]] = mutate_expression(str(parent[path[-1]]), rng, names)
    return _dump(tree, text)


# ---- random well-formed goals ----------------------------------------------------------
def random_expression(rng: random.Random, names: list[str], depth: int = 0) -> str:
    if depth > 4 or rng.random() < 0.3:
        return rng.choice(names + NUMBERS[:6] + ["true", "false", "agent.x", "agent.y"])
    kind = rng.choice(["cmp", "bool", "not", "call", "quant", "arith", "attr", "index"])
    sub = lambda: random_expression(rng, names, depth + 1)  # noqa: E731
    if kind == "cmp":
        return f"{sub()} {rng.choice(['==', '!=', '<', '<=', '>', '>='])} {sub()}"
    if kind == "bool":
        return f"({sub()}) {rng.choice(['and', 'or'])} ({sub()})"
    if kind == "not":
        return f"not ({sub()})"
    if kind == "call":
        return f"{rng.choice(names)}({', '.join(sub() for _ in range(rng.randint(0, 3)))})"
    if kind == "quant":
        return f"{rng.choice(['exists', 'forall'])} v in {rng.choice(names)} . {sub()}"
    if kind == "arith":
        return f"({sub()}) {rng.choice(['+', '-', '*', '//', '%'])} ({sub()})"
    if kind == "attr":
        return f"{sub()}.{rng.choice(names)}"
    return f"{rng.choice(names)}[{', '.join(sub() for _ in range(rng.randint(1, 3)))}]"


# ---- cases -----------------------------------------------------------------------------
def make_case(seed: int) -> Case:
    """Case number `seed`: the same seed gives the same files on every machine."""
    rng = random.Random(seed)
    dungeon = rng.choice(sorted(DUNGEONS))
    domain = domain_of(dungeon)
    names = NAMES.get(domain, NAMES["minecraft"])
    files = {f"{dungeon}.yaml": DUNGEONS[dungeon]}
    # A dungeon that extends another needs the base beside it (a mutated copy is found first).
    base = re.search(r"^extends:\s*(\S+)", DUNGEONS[dungeon], re.M)
    if base and base.group(1) in DUNGEONS:
        files[f"{base.group(1)}.yaml"] = DUNGEONS[base.group(1)]
    family = rng.choices(["text", "structure", "expression", "domain", "goal"], [25, 20, 20, 25, 10])[0]
    args: list = []
    n = rng.choice([1, 1, 1, 2, 3])
    if family == "domain":
        # The dungeon names the domain by file: the mutated copy beside it is the one loaded.
        dname = domain if domain in DOMAINS else "minecraft"
        files[f"{dungeon}.yaml"] = re.sub(r"^domain:.*$", f"domain: {dname}.yaml", DUNGEONS[dungeon],
                                          count=1, flags=re.M)
        if base and base.group(1) in DUNGEONS:
            files[f"{base.group(1)}.yaml"] = re.sub(r"^domain:.*$", f"domain: {dname}.yaml",
                                                    DUNGEONS[base.group(1)], count=1, flags=re.M)
        text = DOMAINS[dname]
        for _ in range(n):
            text = _mutate_any(text, rng, names)
        files[f"{dname}.yaml"] = text
    elif family == "goal":
        args = ["--goal", random_expression(rng, names) if rng.random() < 0.7 else
                mutate_expression(rng.choice(["agentOnBlock(agent, gold)", "agentInRoom(agent, red)",
                                              "exists b in block . b.blockType == gold and b.y == agent.y - 1"]),
                                  rng, names)]
    else:
        text = files[f"{dungeon}.yaml"]
        mutate = {"text": mutate_text, "structure": mutate_structure,
                  "expression": lambda t, r: mutate_expressions(t, r, names)}[family]
        for _ in range(n):
            text = mutate(text, rng)
        files[f"{dungeon}.yaml"] = text
    return Case(files, f"{dungeon}.yaml", args, f"{family}:{dungeon}")


def _mutate_any(text: str, rng: random.Random, names: list[str]) -> str:
    family = rng.choice(["text", "structure", "expression", "expression"])
    if family == "text":
        return mutate_text(text, rng)
    if family == "structure":
        return mutate_structure(text, rng)
    return mutate_expressions(text, rng, names)


# ---- running a case --------------------------------------------------------------------
POSITIONED = re.compile(r"^[^\n]+?:\d+:\d+: \S")
PLACED = re.compile(r"^[^\n]+?: \S")
COMMAND = ["solve", "--solver", "bfs", "--max-states", "3000", "--time-limit", "3"]


@dataclass
class Outcome:
    kind: str            # ok | no-plan | bad-input | bad-message | internal | exit-N
    detail: str = ""     # the stderr line, or the exception and its code site
    site: str = ""       # for "internal": file:line (function) of the innermost bcc frame
    positioned: bool = False


def write_case(case: Case, directory: Path) -> Path:
    for name, text in case.files.items():
        (directory / name).write_text(text, encoding="utf-8", errors="surrogatepass")
    return directory / case.target


def run_cli(args: list[str]) -> Outcome:
    """`bcc ARGS` in this process, through the entry point the `bcc` command uses."""
    from click.testing import CliRunner

    from bcc.cli import main
    result = CliRunner().invoke(main, args, env={"BCC_DEBUG": "1"}, catch_exceptions=True)
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        return internal_outcome(result.exc_info)
    code = result.exit_code
    err = result.stderr.strip()
    if code == 0:
        return Outcome("ok")
    if code == 1:
        return Outcome("no-plan", err.splitlines()[-1] if err else "")
    if code == 2:
        lines = err.splitlines()
        if len(lines) == 1 and PLACED.match(lines[0]):
            return Outcome("bad-input", lines[0], positioned=bool(POSITIONED.match(lines[0])))
        return Outcome("bad-message", err[:300])
    return Outcome(f"exit-{code}", err[:300])


def internal_outcome(exc_info) -> Outcome:
    etype, exc, tb = exc_info
    frames = [f for f in traceback.extract_tb(tb) if f.filename.startswith(BCC_DIR) and "/tests/" not in f.filename]
    inner = frames[-1] if frames else traceback.extract_tb(tb)[-1]
    site = f"{Path(inner.filename).relative_to(BCC_DIR) if inner.filename.startswith(BCC_DIR) else inner.filename}" \
           f":{inner.lineno} ({inner.name})"
    return Outcome("internal", f"{etype.__name__}: {str(exc)[:200]}", f"{etype.__name__} at {site}")


def case_argv(case: Case, directory: Path) -> list[str]:
    """The `bcc` arguments that run `case` once its files are in `directory`."""
    if case.front == "pddl":
        return ["import", "pddl", str(directory / case.target), *(str(directory / a) for a in case.args),
                *COMMAND[1:]]
    return [*COMMAND, str(directory / case.target), *case.args]


def run_case(case: Case, directory: Path) -> Outcome:
    write_case(case, directory)
    return run_cli(case_argv(case, directory))


# ---- PDDL cases --------------------------------------------------------------------------
# The PDDL front-end's inputs: a domain and problem pair of tests/pddl with 1-3 mutations of
# its s-expression tree (an element deleted, duplicated, emptied, wrapped, replaced by a
# keyword, a name or number of the files or a subtree copied from elsewhere; a list's items
# swapped), so the reader, the typed-list parser, the formula and effect readers, grounding
# and the solver all see inputs that get past the stages before them.
PDDL_DIR = ROOT / "tests" / "pddl"
PDDL_PAIRS = [(d, p) for d in sorted(PDDL_DIR.glob("*-domain.pddl"))
              for p in sorted(PDDL_DIR.glob(d.name.replace("-domain.pddl", "-[0-9a-z]*.pddl"))) if p != d]
PDDL_WORDS = [":requirements", ":strips", ":typing", ":adl", ":action-costs", ":negative-preconditions",
              ":equality", ":conditional-effects", ":types", ":constants", ":predicates", ":functions",
              ":action", ":parameters", ":precondition", ":effect", ":objects", ":init", ":goal", ":metric",
              ":derived", ":durative-action", "minimize", "maximize", "total-cost", "increase", "decrease",
              "assign", "and", "or", "not", "imply", "forall", "exists", "when", "either", "=", "<", "-",
              "object", "number", "?x", "?y", "0", "1", "-1", "3.5", "1e9", "99999999999999999999", "9" * 4301,
              "at", "start", "define", "domain", "problem", "é", "a\\b"]
SEXPR_TOKEN = re.compile(r";[^\n]*|\(|\)|[^\s()]+")


def read_tree(text: str) -> list:
    """The top-level lists of PDDL text as nested Python lists of strings (comments
    dropped); written here, apart from bcc's reader, so the mutator does not share its bugs."""
    stack: list = [[]]
    for tok in SEXPR_TOKEN.findall(text):
        if tok.startswith(";"):
            continue
        if tok == "(":
            stack.append([])
        elif tok == ")":
            if len(stack) > 1:
                done = stack.pop()
                stack[-1].append(done)
        else:
            stack[-1].append(tok)
    while len(stack) > 1:
        done = stack.pop()
        stack[-1].append(done)
    return stack[0]


def write_tree(tree) -> str:
    if isinstance(tree, list):
        return "(" + " ".join(write_tree(t) for t in tree) + ")"
    return tree


def _tree_paths(tree, prefix=()):
    yield prefix
    if isinstance(tree, list):
        for i, item in enumerate(tree):
            yield from _tree_paths(item, (*prefix, i))


def mutate_tree(forest: list, rng: random.Random) -> None:
    """One mutation of `forest` (a list of top-level lists), in place."""
    paths = [p for p in _tree_paths(forest) if p]
    if not paths:
        return
    path = rng.choice(paths)
    parent = _get(forest, path[:-1])
    i = path[-1]
    words = [n for q in paths if isinstance(n := _get(forest, q), str)]
    how = rng.randrange(7)
    if how == 0:
        del parent[i]
    elif how == 1:
        parent.insert(i, copy.deepcopy(parent[i]))
    elif how == 2:
        parent[i] = rng.choice(PDDL_WORDS + words)
    elif how == 3:
        parent[i] = [rng.choice(PDDL_WORDS + words), parent[i]]
    elif how == 4:
        parent[i] = copy.deepcopy(_get(forest, rng.choice(paths)))
    elif how == 5 and isinstance(parent[i], list) and len(parent[i]) > 1:
        a, b = rng.randrange(len(parent[i])), rng.randrange(len(parent[i]))
        parent[i][a], parent[i][b] = parent[i][b], parent[i][a]
    else:
        parent[i] = []


def make_pddl_case(seed: int) -> Case:
    """PDDL case number `seed`: the same seed gives the same files on every machine."""
    rng = random.Random(seed)
    domain, problem = rng.choice(PDDL_PAIRS)
    texts = {"domain.pddl": domain.read_text(encoding="utf-8"), "problem.pddl": problem.read_text(encoding="utf-8")}
    which = rng.choice([["domain.pddl"], ["domain.pddl"], ["problem.pddl"], ["domain.pddl", "problem.pddl"]])
    for name in which:
        forest = read_tree(texts[name])
        for _ in range(rng.choice([1, 1, 2, 3])):
            mutate_tree(forest, rng)
        texts[name] = "\n".join(write_tree(t) for t in forest) + "\n"
    return Case(texts, "domain.pddl", ["problem.pddl"], f"pddl:{domain.stem}/{'+'.join(which)}", front="pddl")
