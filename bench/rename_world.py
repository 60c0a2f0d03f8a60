"""A copy of a dungeon and its whole domain chain with the domain's names renamed, so a
benchmark can show that no code reads them (issue 30: the houses "with the domain's names
renamed"; the PDDL bench renames its tasks the same way).

Every name the domain defines -- the domains themselves, types and their values and
properties, constants, classes and attributes, functions, actions, tasks and methods --
becomes `n<k>` (k in a seeded shuffled order), as a whole word wherever it occurs in the
files (keys, expressions, legends, stock entries), so the copy is the same problem. Words
the file format or the expression language reserve (`agent:`, `count:`, `and`, `width`,
...) stay: renaming them would make another file, not the same one under other names;
`kept` lists them.

    python bench/rename_world.py DUNGEON.yaml OUT_DIR [--seed N]
"""
from __future__ import annotations

import argparse
import random
import re
import sys
from pathlib import Path

# Keys of the file format (compiler/domain.py, dungeon.py, tasks.py, structure goals) and
# words of the expression language (grammar/expressions.lark) and its built-in constants.
RESERVED = {
    "domain", "description", "extends", "types", "constants", "classes", "dungeon", "functions", "failure",
    "actions", "tasks", "methods", "params", "body", "override", "grid", "agent", "agent_fields", "inventory",
    "rooms", "lists", "start", "facing", "looking", "selected", "class", "required", "fields", "values",
    "properties", "type", "default", "per", "id", "attributes", "key", "position", "range", "names", "let",
    "pre", "effect", "cost", "item", "count", "slot", "name", "task", "vars", "subtasks", "height", "legend",
    "map", "goal", "structure", "at", "layers", "blocks", "width", "depth", "stock",
    "add", "and", "elif", "else", "exists", "false", "first", "forall", "if", "in", "not", "or", "remove",
    "true", "where", "int", "bool",
}


def chain(path: Path) -> list:
    """The dungeon's domain file and every file it extends, nearest first."""
    from bcc.compiler.domain import resolve_domain_path
    from bcc.compiler.source import load_yaml
    data = load_yaml(path)
    files = []
    ref, here = data["domain"], path
    while ref is not None:
        found = resolve_domain_path(str(ref), here)
        files.append(found)
        ref, here = load_yaml(found).get("extends"), found
    return files


def defined_names(domain_file: Path) -> set:
    from bcc.compiler.domain import load_domain
    d = load_domain(domain_file)
    names = {d.name} | set(d.constants) | set(d.classes) | set(d.functions) | set(d.actions)
    names |= set(d.tasks) | set(d.methods)
    for e in d.enums.values():
        names |= {e.name, *e.values, *e.properties}
    for c in d.classes.values():
        names |= set(c.attrs)
    return names


def rename_world(dungeon: Path, out: Path, seed: int = 0) -> tuple[Path, dict, list]:
    """Write the renamed dungeon and domain files into `out`: (the new dungeon's path, the
    renaming, the names kept because the format reserves them)."""
    from bcc.compiler.source import load_yaml
    files = chain(dungeon)
    domain_names = [str(load_yaml(f)["domain"]) for f in files]   # nearest first, as `files`
    names = set(domain_names)
    for f in files:
        names |= defined_names(f)
    kept = sorted(names & RESERVED)
    order = sorted(names - RESERVED)
    random.Random(seed).shuffle(order)
    mapping = {name: f"n{k}" for k, name in enumerate(order)}
    word = re.compile(r"(?<![A-Za-z0-9_])(" + "|".join(map(re.escape, sorted(mapping, key=len, reverse=True)))
                      + r")(?![A-Za-z0-9_])")

    def rename(text: str) -> str:
        return word.sub(lambda m: mapping[m.group(1)], text)
    out.mkdir(parents=True, exist_ok=True)
    renamed = [mapping[name] for name in domain_names]
    for k, f in enumerate(files):    # `extends:` names the renamed file of the next domain, beside it
        text = rename(f.read_text())
        if k + 1 < len(files):
            text = re.sub(r"(?m)^extends:.*$", f"extends: {renamed[k + 1]}.yaml", text)
        (out / f"{renamed[k]}.yaml").write_text(text)
    target = out / f"renamed_{dungeon.name}"
    text = re.sub(r"(?m)^domain:.*$", f"domain: {(out / renamed[0]).resolve()}.yaml", rename(dungeon.read_text()))
    target.write_text(text)
    return target, mapping, kept


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dungeon")
    ap.add_argument("out")
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    target, mapping, kept = rename_world(Path(args.dungeon), Path(args.out), args.seed)
    print(f"wrote {target}: {len(mapping)} names renamed; kept (reserved words of the format): {', '.join(kept)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
