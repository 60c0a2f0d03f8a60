"""Imports point down the layers (docs: README "Architecture"; STYLE.md §8), never up and
never sideways between two edges. Every module of bcc is read as a syntax tree, so an
import inside a function counts as much as one at the top: a lazy import still ties the
importer to what it imports.

From the top (imports the most) to the bottom (imported by all):

    cli           the shell: the one place that puts edges together
    edges         serve, batch, grounding, minecraft, gym: each on its own, never importing another
    run           one run path (options, budgets, deadline, solve, result); stepping the world
    solvers       search loops and learners
    heuristics    estimates of the distance to a goal, and the tables behind them
    back end      state layout, generated successor code -> Model; PDDL written from a Model
    front ends    YAML, PDDL and HDDL text -> a ground task, with positioned errors
    analysis      the ground task type; reachability, relevance, abstract values
    base          errors, Model, the grammar files, atomic files, the on-disk cache

A module may import from its own layer (an edge only from itself) and from any layer
below. `LAYER_OF` places every module by the longest name that covers it; a module it
does not place fails the test, so a new package says where it belongs. `EXCEPTIONS` lists
each import that breaks the rule today, with the reason, and fails the test when one is
no longer needed.
"""
from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

import bcc

ROOT = Path(bcc.__file__).resolve().parent
NOT_CODE = {"tests", "bench", "docs", "build", "dist"}

# The layers from the bottom; an edge is ("edge", its name): edges never import one another.
ORDER = ["base", "analysis", "front end", "back end", "heuristics", "solvers", "run", "edge", "cli"]

LAYER_OF = {
    # base: imported by everything
    "bcc": "base",                         # the package: BccError and the version only
    "bcc.errors": "base",
    "bcc.exit_codes": "base",
    "bcc.atomic": "base",
    "bcc.extras": "base",                  # which optional packages are installed
    "bcc.model": "base",
    "bcc.model_json": "base",              # the Model as JSON
    "bcc.keys": "base",                    # the key of each action, for a person playing
    "bcc.grammar": "base",
    "bcc.domains": "base",                 # the shipped YAML files
    "bcc.dungeons": "base",
    "bcc.compiler.cache": "base",          # the on-disk cache of both front ends and of costly tables
    "bcc.compiler.limits": "base",         # the size limits of input files
    # analysis: the ground task and what is known about it without search
    "bcc.compiler.ir": "analysis",
    "bcc.compiler.abstract": "analysis",
    "bcc.compiler.reachability": "analysis",
    "bcc.compiler.relevance": "analysis",
    "bcc.compiler.access": "analysis",     # what an expression reads, what effects write: the one such analysis
    "bcc.compiler.inverses": "analysis",
    # front ends: YAML (compiler/) and PDDL (pddl_io/) text to a ground task
    "bcc.compiler.source": "front end",
    "bcc.compiler.names": "front end",
    "bcc.compiler.ast": "front end",
    "bcc.compiler.parse": "front end",
    "bcc.compiler.definitions": "front end",    # a loaded domain as data: Expr, EnumType, ClassDef, Domain, ...
    "bcc.compiler.domain": "front end",
    "bcc.compiler.domain_enums": "front end",   # a domain's `types:` section
    "bcc.compiler.domain_exprs": "front end",   # expression text read out of YAML and parsed
    "bcc.compiler.dungeon": "front end",
    "bcc.compiler.ground": "front end",
    "bcc.compiler.ground_effects": "front end",   # effects grounded: a mixin of the Grounder
    "bcc.compiler.ground_refs": "front end",      # objects, keyed objects, classes, tables; the scope
    "bcc.compiler.blocks": "front end",    # a dungeon's `blocks:` text
    "bcc.compiler.structure": "front end", # a dungeon's `structure:` goal (a blueprint) read into atoms
    "bcc.compiler.tasks": "front end",     # a domain's `tasks:` and `methods:`, a dungeon's `task:`
    "bcc.generate": "front end",           # writes dungeon YAML, checking names as the front end does
    "bcc.generate_rooms": "front end",
    "bcc.generate_structures": "front end",  # writes structure dungeons (house, wall, tower, bridge)
    "bcc.pddl_io": "front end",            # the package docstring
    "bcc.pddl_io.read": "front end",
    "bcc.pddl_io.lifted": "front end",
    "bcc.pddl_io.lifted_types": "front end",  # the lifted task's formulas, actions, domain and problem
    "bcc.pddl_io.derived": "front end",       # derived predicates inlined
    "bcc.pddl_io.ground": "front end",
    "bcc.hddl": "front end",               # HTN domains and problems (IPC HDDL), plans and their check
    # back end: the ground task laid out as states, successor code generated -> Model
    "bcc.compiler": "back end",            # compile_dungeon, the YAML pipeline's entry
    "bcc.compiler.layout": "back end",
    "bcc.compiler.emit": "back end",
    "bcc.compiler.emit_layers": "back end",   # the layer expanders, a mixin of the emitter
    "bcc.compiler.emit_helpers": "back end",  # the run-time helpers generated code calls (cells, merges)
    "bcc.compiler.pipeline": "back end",
    "bcc.compiler.hierarchy": "back end",  # methods compiled into generated functions for one dungeon
    "bcc.pddl_io.bits": "back end",
    "bcc.pddl_io.compile": "back end",
    "bcc.pddl_io.importer": "back end",
    "bcc.pddl_io.lifted_states": "back end",   # the lifted task's states and successors (no grounding)
    "bcc.pddl_io.lifted_joins": "back end",    # an action schema's bindings in a state, as generated code
    "bcc.pddl_io.lifted_successors": "back end",   # the lifted successor function and its tests
    "bcc.pddl_io.replay": "back end",          # a plan replayed on the lifted task: a validator
    "bcc.pddl_export": "back end",             # a compiled Model written as PDDL, plans in its names
    # heuristics
    "bcc.heuristics": "heuristics",
    # solvers
    "bcc.solvers": "solvers",
    # run: one run path, and stepping the world (replay, drawing) that every edge shows
    "bcc.run": "run",
    "bcc.demonstration": "run",            # the demonstration format the grounding, the server and Minecraft share
    "bcc.simulate": "run",
    "bcc.render": "run",
    # edges
    "bcc.serve": ("edge", "serve"),
    "bcc.batch": ("edge", "batch"),
    "bcc.learning_curves": ("edge", "batch"),   # learning curves are runs of the batch API
    "bcc.grounding": ("edge", "grounding"),
    "bcc.minecraft": ("edge", "minecraft"),
    "bcc.mineplanner": ("edge", "mineplanner"),   # MinePlanner's tasks as dungeons: an edge beside minecraft/
    "bcc.gym": ("edge", "gym"),
    # the shell
    "bcc.cli": "cli",
    "bcc.__main__": "cli",
}

# (importer, imported): why the import is allowed for now. Each must still occur.
EXCEPTIONS = {
}


def module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(["bcc", *parts])


def modules() -> dict[str, Path]:
    out = {}
    for path in sorted(ROOT.rglob("*.py")):
        rel = path.relative_to(ROOT).parts
        if rel[0] in NOT_CODE or any(p.startswith(".") or p.endswith(".egg-info") for p in rel):
            continue
        out[module_name(path)] = path
    return out


MODULES = modules()
BCC_NAME = re.compile(r"bcc(\.[A-Za-z_]\w*)+")


def imports(name: str, path: Path) -> set[tuple[str, int]]:
    """(module of bcc, line) for every import in the file, lazy ones included, and every
    string naming a module of bcc ("bcc.solvers.astar:solve", as the solver table does)."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.Import):
            found |= {(a.name, node.lineno) for a in node.names if a.name.split(".")[0] == "bcc"}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[:len(package.split(".")) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if target.split(".")[0] != "bcc":
                continue
            for alias in node.names:   # `from . import corpus` imports the module bcc.grounding.corpus
                sub = f"{target}.{alias.name}"
                found.add((sub if sub in MODULES else target, node.lineno))
        elif isinstance(node, ast.Constant) and isinstance(node.value, str):
            match = BCC_NAME.fullmatch(node.value.split(":")[0])
            if match and node.value.split(":")[0] in MODULES:
                found.add((node.value.split(":")[0], node.lineno))
    return found


def shown(place) -> str:
    return f"edge {place[1]}" if isinstance(place, tuple) else str(place)


def layer(name: str):
    keys = [k for k in LAYER_OF if name == k or k != "bcc" and name.startswith(k + ".")]
    return LAYER_OF[max(keys, key=len)] if keys else None


def rank(place) -> int:
    return ORDER.index(place[0] if isinstance(place, tuple) else place)


def allowed(importer: str, imported: str) -> bool:
    a, b = layer(importer), layer(imported)
    if a is None or b is None:   # unplaced: test_every_module_has_a_layer says so
        return True
    if rank(b) < rank(a):
        return True
    return rank(b) == rank(a) and (not isinstance(a, tuple) or a == b)


def violations() -> dict[tuple[str, str], list[int]]:
    out: dict = {}
    for name, path in MODULES.items():
        for imported, line in imports(name, path):
            if imported in MODULES and not allowed(name, imported):
                out.setdefault((name, imported), []).append(line)
    return out


def test_every_module_has_a_layer():
    unplaced = sorted(name for name in MODULES if layer(name) is None)
    assert not unplaced, f"place these modules in LAYER_OF (tests/test_import_layers.py): {unplaced}"


def test_every_placed_name_is_a_module():
    """A name left in LAYER_OF after its module moved would place nothing and hide that
    the table no longer describes the tree."""
    stale = sorted(name for name in LAYER_OF if name not in MODULES)
    assert not stale, f"no such module: remove or rename in LAYER_OF: {stale}"


def test_imports_point_down_the_layers():
    found = violations()
    wrong = {pair: lines for pair, lines in found.items() if pair not in EXCEPTIONS}
    assert not wrong, "\n".join(
        f"{a} ({shown(layer(a))}) imports {b} ({shown(layer(b))}), line {', '.join(map(str, lines))}"
        for (a, b), lines in sorted(wrong.items()))
    stale = sorted(pair for pair in EXCEPTIONS if pair not in found)
    assert not stale, f"no longer needed: remove from EXCEPTIONS: {stale}"


def test_the_library_never_imports_the_command_line():
    users = sorted({name for name, path in MODULES.items() if layer(name) != "cli"
                    for imported, _ in imports(name, path) if layer(imported) == "cli"})
    assert not users


def test_no_modules_need_each_other():
    """Within a layer too, a module and what it imports form no cycle (a package's
    `__init__` and its own modules aside): two modules that need each other are one idea
    split in the wrong place."""
    graph = {name: {m for m, _ in imports(name, path)
                    if m in MODULES and m != name and not m.startswith(name + ".") and not name.startswith(m + ".")}
             for name, path in MODULES.items()}
    cycles = []
    for start in graph:   # a cycle through `start`: `start` reachable from one of its imports
        seen, todo = set(), list(graph[start])
        while todo:
            m = todo.pop()
            if m not in seen:
                seen.add(m)
                todo.extend(graph[m])
        if start in seen:
            cycles.append(start)
    assert not cycles, f"modules on an import cycle: {cycles}"


@pytest.mark.parametrize("importer, imported, expected", [
    ("bcc.solvers.astar", "bcc.model", True),              # down
    ("bcc.model", "bcc.solvers.astar", False),             # up
    ("bcc.grounding.pairs", "bcc.batch.engine", False),    # sideways between edges
    ("bcc.batch.rows", "bcc.batch.runs", True),            # within an edge
    ("bcc.cli.grounding", "bcc.grounding.learn", True),    # the shell puts edges together
    ("bcc.compiler.emit", "bcc.heuristics.counting", False), # back end up to a heuristic
])
def test_the_rule_itself(importer, imported, expected):
    assert allowed(importer, imported) is expected


def test_lazy_imports_are_seen(tmp_path):
    # An import inside a function body, relative and absolute, and a module named in a string.
    path = ROOT / "solvers" / "astar.py"
    found = {m for m, _ in imports("bcc.solvers.astar", path)}
    assert {"bcc.model", "bcc.solvers.uniform_cost"} <= found   # uniform_cost is imported inside _layered's caller
    table = {m for m, _ in imports("bcc.solvers", ROOT / "solvers" / "__init__.py")}
    assert "bcc.solvers.astar" in table                           # "bcc.solvers.astar:solve"
