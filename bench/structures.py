#!/usr/bin/env python3
"""Structures built by `bcc solve` (the build solver), whole processes.

    python bench/structures.py                          # houses 5, 10; variants; blueprints
    python bench/structures.py --sizes 5,10,15,25 --time-limit 120
    python bench/structures.py --only house_5           # rows whose name matches

Per row: `bcc generate` (or a blueprint written here) into a temporary dungeon, then
`bcc solve DUNGEON --json` under --time-limit, timed by the kernel (CPU seconds user +
system of the child), then `bcc validate` on the plan (the replay check). Reported: CPU
s, plan length, the solver's admissible lower bound, their ratio, and whether the plan
replays. Variants of the smallest house: mirrored (x -> -x), rotated (90 degrees: the
layers' rows and columns swapped), the goal's atoms shuffled (written as a `goal:` list
of cell atoms in a random order), and every name of the domains renamed (bench/rename_world.py).
Blueprints: a bridge (an overhang on four posts), a
tower (an enclosed room) and a seeded random blueprint with overhangs. Targets (issue
30): 10^3 under 5 s, 25^3 under 60 s, length within 1.5 x of the bound. Prints a table,
writes bench/structures.json.
"""
from __future__ import annotations

import argparse
import json
import platform
import random
import re
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from engine import peak_of  # noqa: E402  (bench/engine.py: a child's CPU and peak)

BCC = [sys.executable, "-m", "bcc"]


def _layers_of(text: str) -> tuple[str, list[list[str]]]:
    """The dungeon text before its blueprint's layers, and the layers as rows."""
    head, _, body = text.partition("    layers:\n")
    layers = [[line[8:] for line in block.splitlines()[1:]] for block in body.split("      - |")[1:]]
    return head, layers


def _with_layers(head: str, layers) -> str:
    return head + "    layers:\n" + "".join("      - |\n" + "".join(f"        {r}\n" for r in lay) for lay in layers)


def mirrored(text: str) -> str:
    head, layers = _layers_of(text)
    return _with_layers(head, [[r[::-1] for r in lay] for lay in layers])


def rotated(text: str) -> str:
    head, layers = _layers_of(text)
    return _with_layers(head, [["".join(r[i] for r in reversed(lay)) for i in range(len(lay[0]))] for lay in layers])


def shuffled(text: str, seed: int = 0) -> str:
    """The same structure as a `goal:` list of cell atoms in a random order."""
    head, layers = _layers_of(text)
    at = [int(v) for v in re.search(r"at: \[(\d+), (\d+), (\d+)\]", head).groups()]
    legend = dict(re.findall(r'"(.)": (\w+)', head.partition("legend: ")[2].splitlines()[0]))
    atoms = [f"block[{at[0] + i}, {at[1] + j}, {at[2] + k}].kind == {legend[ch]}"
             for j, lay in enumerate(layers) for k, row in enumerate(lay) for i, ch in enumerate(row) if ch != " "]
    random.Random(seed).shuffle(atoms)
    return head.partition("goal:\n")[0] + "goal:\n" + "".join(f"  - {a}\n" for a in atoms)


def random_blueprint(seed: int, w: int = 5, l: int = 5, h: int = 4) -> str:
    """A seeded blueprint of columns with overhangs: each layer keeps most of the cells of
    the one below and adds a few that hang over air."""
    rng = random.Random(seed)
    text = _generate("wall", w, l, h)
    head, _ = _layers_of(text)
    below = {(x, z) for x in range(w) for z in range(l) if rng.random() < 0.4}
    layers = []
    for _ in range(h):
        lay = [["#" if (x, z) in below else "." for x in range(w)] for z in range(l)]
        layers.append(["".join(r) for r in lay])
        keep = {c for c in below if rng.random() < 0.8}
        grow = {(x + dx, z + dz) for x, z in keep for dx, dz in ((1, 0), (-1, 0), (0, 1), (0, -1))
                if 0 <= x + dx < w and 0 <= z + dz < l and rng.random() < 0.3}
        below = keep | grow
    return _with_layers(head.replace("wall_", f"random{seed}_"), layers)


def _generate(kind, w, l, h, material="planks") -> str:
    sys.path.insert(0, str(HERE.parent.parent))
    from bcc.generate_structures import generate_structure
    return generate_structure(kind, w, l, h, material=material)


def run_row(name: str, text: str, time_limit: float, tmp: Path) -> dict:
    path = tmp / f"{name}.yaml"
    path.write_text(text)
    r = peak_of([*BCC, "solve", str(path), "--json", "--time-limit", str(time_limit)], timeout=time_limit * 3 + 60)
    row = {"name": name, "cpu_s": r["cpu"], "wall_s": r["wall"], "exit": r["code"]}
    try:
        result = json.loads(r["stdout"])
    except json.JSONDecodeError:
        return {**row, "solved": False, "error": r["stderr"].strip()[-200:]}
    row.update(solved=result["solved"], solver=result["solver"], length=len(result["plan"]) if result["solved"] else None,
               lower_bound=result.get("lower_bound"), expanded=result["expanded"])
    row["ratio"] = round(row["length"] / row["lower_bound"], 2) if row["solved"] and row["lower_bound"] else None
    if result["solved"]:
        plan = tmp / f"{name}.plan"
        plan.write_text("".join(a + "\n" for a in result["plan"]))
        v = peak_of([*BCC, "validate", str(path), str(plan)], timeout=600)
        row["replays"] = v["code"] == 0
    return row


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sizes", default="5,10", help="house sizes (W = L = H), comma-separated")
    ap.add_argument("--time-limit", type=float, default=120)
    ap.add_argument("--only", default=None, help="a regular expression over row names")
    ap.add_argument("--out", default=str(HERE / "structures.json"))
    args = ap.parse_args()
    sizes = [int(s) for s in args.sizes.split(",")]
    rows = []
    cases = [(f"house_{n}", _generate("house", n, n, n)) for n in sizes]
    small = _generate("house", sizes[0], sizes[0], sizes[0])
    cases += [(f"house_{sizes[0]}_mirrored", mirrored(small)), (f"house_{sizes[0]}_rotated", rotated(small)),
              (f"house_{sizes[0]}_shuffled", shuffled(small)),
              ("bridge_5x3x3", _generate("bridge", 5, 3, 3)), ("tower_4x4x5", _generate("tower", 4, 4, 5)),
              ("random_1", random_blueprint(1)), ("random_2", random_blueprint(2))]
    with tempfile.TemporaryDirectory() as d:
        from rename_world import rename_world   # bench/rename_world.py: every name the domains define, renamed
        (Path(d) / "small.yaml").write_text(small)
        renamed, _, _ = rename_world(Path(d) / "small.yaml", Path(d) / "renamed")
        cases.insert(3, (f"house_{sizes[0]}_renamed", renamed.read_text()))
        for name, text in cases:
            if args.only and not re.search(args.only, name):
                continue
            row = run_row(name, text, args.time_limit, Path(d))
            rows.append(row)
            print(f"{name:<22} {'solved' if row.get('solved') else 'NOT SOLVED':<10} cpu {row['cpu_s']:>7.2f} s  "
                  f"length {row.get('length')!s:>6}  bound {row.get('lower_bound')!s:>6}  ratio {row.get('ratio')!s:>5}"
                  f"  replays {row.get('replays')}", flush=True)
            Path(args.out).write_text(json.dumps({"machine": platform.platform(), "python": platform.python_version(),
                                                  "time_limit": args.time_limit, "rows": rows}, indent=2) + "\n")


if __name__ == "__main__":
    main()
