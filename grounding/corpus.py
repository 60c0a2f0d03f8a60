"""The shipped corpus: generated (command, demonstration) pairs with a held-out split.

`python -m bcc.grounding.corpus` (or `bcc corpus generate`) rebuilds it with a fixed seed:
dungeons (the reference ones, generated mazes with stones and lava, generated four-room
dungeons), a task per pair (a room by color, the gold block, a stone to pick up), a start
reached by a short random walk, a demonstration planned by A* from there, and a command
from templates with varied verbs and phrasings. Each line of `corpus/pairs.jsonl` keeps
the walk (`prefix`), the demonstration's `actions`, the true `task` (for evaluation only)
and the inferred `explanations` (what training sees), so training needs no compiling.
The demonstrations are planned through `bcc.run.pool.map_local`, on `workers` processes, with
the same output for any number of them (see `generate`).
"""
from __future__ import annotations

import dataclasses
import hashlib
import json
import random
import time
from pathlib import Path

from ..atomic import write_text
from ..errors import BccError

CORPUS_DIR = Path(__file__).parent / "corpus"
PAIRS = CORPUS_DIR / "pairs.jsonl"
REFERENCE = ["grid", "bridge", "easy_maze", "tough_maze", "four_rooms"]
MAZES = [(9, 9, 2, 1, 0.0, 1), (11, 11, 2, 1, 0.1, 2), (11, 9, 1, 0, 0.2, 3), (13, 13, 3, 1, 0.1, 4),
         (9, 11, 1, 1, 0.0, 5), (15, 11, 2, 0, 0.1, 6)]
ROOM_SEEDS = [1, 2, 3, 4, 5, 6, 7, 8]
TEST_FRACTION = 0.2

ROOM = ["go to the {c} room", "walk to the {c} room", "move to the {c} room", "head to the {c} room",
        "get to the {c} room", "navigate to the {c} room", "enter the {c} room", "go into the {c} room",
        "walk into the {c} room", "move into the {c} room", "head into the {c} room", "go toward the {c} room",
        "walk over to the {c} room", "head over to the {c} room", "make your way to the {c} room",
        "go inside the {c} room", "run to the {c} room", "please go to the {c} room", "take me to the {c} room",
        "find the {c} room", "go to {c}", "step into the {c} room", "navigate into the {c} room",
        "move over to the {c} room", "head toward the {c} room"]
GOLD = ["go to the gold block", "walk to the gold block", "move to the gold", "head to the gold block",
        "get to the gold block", "navigate to the gold block", "stand on the gold block", "stand on the gold",
        "go stand on the gold block", "walk onto the gold block", "step onto the gold", "go toward the gold block",
        "head over to the gold block", "move over to the gold", "get on the gold block", "find the gold block",
        "reach the gold block", "walk over to the gold", "navigate to the gold", "head toward the gold",
        "go over to the gold block", "move onto the gold block"]
STONE = ["pick up the stone", "get a stone", "get the stone block", "mine the stone", "mine a stone block",
         "collect the stone", "grab a stone", "take the stone", "dig up the stone", "go get the stone",
         "fetch a stone block", "gather a stone", "get some stone", "pick up a stone block", "collect a stone"]
FAMILIES = {"room": (0.45, ROOM), "gold": (0.35, GOLD), "stone": (0.2, STONE)}


def resolve(ref: str, base: Path = CORPUS_DIR) -> str:
    """A corpus dungeon reference: a shipped name, or a path relative to the corpus folder."""
    return ref if ref in REFERENCE else str(Path(base) / ref)


def load(path: str | Path = PAIRS) -> list[dict]:
    try:
        lines = Path(path).read_text(encoding="utf-8").splitlines()
    except FileNotFoundError:
        raise BccError("the shipped corpus is missing: rebuild it with `bcc corpus generate`", str(path)) from None
    out = []
    for n, line in enumerate(lines, 1):
        try:
            out.append(json.loads(line))
        except json.JSONDecodeError as exc:
            raise BccError(f"invalid JSON line: {exc.msg}", str(path), n, exc.colno) from None
    return out


def digest(path: str | Path = PAIRS) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()[:16]


def _write_dungeons(out: Path) -> list[str]:
    from ..generate import generate_maze
    from .rooms import generate_rooms
    (out / "dungeons").mkdir(parents=True, exist_ok=True)
    refs = []
    for w, d, stones, lava, loops, seed in MAZES:
        name = f"maze_{w}x{d}_seed{seed}"
        write_text(out / "dungeons" / f"{name}.yaml",
                   generate_maze(w, d, stones=stones, lava=lava, loops=loops, seed=seed, name=name))
        refs.append(f"dungeons/{name}.yaml")
    for seed in ROOM_SEEDS:
        write_text(out / "dungeons" / f"rooms_seed{seed}.yaml", generate_rooms(seed))
        refs.append(f"dungeons/rooms_seed{seed}.yaml")
    return refs


def _family_tasks(space) -> dict:
    """The tasks of each command family this dungeon offers (the templates' English knows them)."""
    out = {"room": [], "gold": [], "stone": []}
    for a in space.atoms:
        if a.function == "agentInRoom":
            out["room"].append((a.text, {"c": a.args[1]}))
        elif a.text == "agentOnBlock(agent, gold)":
            out["gold"].append((a.text, {}))
        elif a.text == "agentHasBlock(agent, burlap_stone)":
            out["stone"].append((a.text, {}))
    return {k: v for k, v in out.items() if v}


def generate(n: int = 360, seed: int = 0, out: Path = CORPUS_DIR, progress=None, workers: int = 1) -> dict:
    """Write the corpus (dungeons and pairs.jsonl); return its statistics.

    The pairs are drawn one after another from one random stream, and whether a draw
    becomes a pair depends on its demonstration (planned, then explained). The planning
    goes through `bcc.run.pool.map_local`, `workers` at a time: the draws ahead are guessed
    assuming each succeeds (`_plan_ahead`), planned in parallel, and then the sequential
    loop below consumes the results; a draw it has no result for (a guess after a
    failure was wrong) is planned in the next round. So the output is the same, byte for
    byte, for any number of workers."""
    from .learn import space_for
    t0 = time.perf_counter()
    if workers < 1:
        raise BccError(f"workers must be at least 1, got {workers}")
    rng = random.Random(seed)
    refs = REFERENCE + _write_dungeons(out)
    spaces = {ref: space_for(resolve(ref, out)) for ref in refs}
    offers = {ref: _family_tasks(spaces[ref]) for ref in refs}
    draw = _Draws(refs, offers, spaces)
    planned: dict = {}   # (ref, task, start) -> (actions, explanations), or None: no pair
    rows, inferred = [], 0
    while len(rows) < n:
        before = rng.getstate()
        family, ref, task, slots, prefix, state = draw.candidate(rng)
        if state is None:
            continue
        if (ref, task, state) not in planned:
            rng.setstate(before)   # draw it again once this round is planned
            planned.update(_plan_ahead(rng, draw, planned, out, window=1 if workers == 1 else 3 * workers,
                                       workers=workers))
            continue
        found = planned[(ref, task, state)]
        if found is None:
            continue
        actions, explained = found
        inferred += explained[0]["task"] == task
        command, split = draw.phrase(rng, family, slots)
        rows.append({"id": len(rows), "split": split,
                     "command": command, "dungeon": ref, "task": task, "prefix": prefix,
                     "actions": actions, "explanations": explained})
        if progress:
            progress(len(rows), n)
    write_text(out / "pairs.jsonl", "".join(json.dumps(r, separators=(",", ":")) + "\n" for r in rows))
    write_model(out)
    return {"pairs": len(rows), "train": sum(r["split"] == "train" for r in rows),
            "test": sum(r["split"] == "test" for r in rows), "dungeons": len(refs),
            "inferred_top_is_true_task": inferred / len(rows), "seconds": round(time.perf_counter() - t0, 1)}


class _Draws:
    """The random choices of one pair, in the order the corpus has always drawn them."""

    def __init__(self, refs, offers, spaces):
        self.refs, self.offers, self.spaces = refs, offers, spaces
        self.families = list(FAMILIES)
        self.weights = [FAMILIES[f][0] for f in self.families]

    def candidate(self, rng: random.Random):
        """(family, ref, task, slots, prefix, start); start is None when the start already
        satisfies the task or is dead (no demonstration to plan)."""
        family = rng.choices(self.families, weights=self.weights)[0]
        ref = rng.choice([r for r in self.refs if family in self.offers[r]])
        task, slots = rng.choice(self.offers[ref][family])
        space = self.spaces[ref]
        prefix, state = _random_walk(space.model, rng, rng.randint(0, 12))
        if space.predicates.predicate(task)(state) or space.model.is_failure(state):
            state = None
        return family, ref, task, slots, prefix, state

    @staticmethod
    def phrase(rng: random.Random, family: str, slots: dict) -> tuple[str, str]:
        """The command and the split of a pair that has its demonstration."""
        command = rng.choice(FAMILIES[family][1]).format(**slots)
        return command, "test" if rng.random() < TEST_FRACTION else "train"


@dataclasses.dataclass(frozen=True)
class _Demo:
    """One demonstration to plan: small and picklable (a work item of `map_local`)."""
    dungeon: str      # resolved: a shipped name or a path
    task: str
    start: bytes


def _plan_ahead(rng: random.Random, draw: _Draws, planned: dict, out: Path, window: int, workers: int) -> dict:
    """Plan the next `window` draws not planned yet, guessing that each one becomes a pair
    (so that its phrase draws come before the next), on `workers` processes."""
    from ..run.children import Limits
    from ..run.pool import map_local
    guess = random.Random()
    guess.setstate(rng.getstate())
    keys, seen = [], set()
    for _ in range(window * 4):   # draws with no demonstration to plan do not count
        if len(keys) >= window:
            break
        family, ref, task, slots, _, state = draw.candidate(guess)
        if state is None:
            continue
        key = (ref, task, state)
        if key in planned and planned[key] is None:
            continue   # known to make no pair: no phrase drawn
        if key not in planned and key not in seen:
            seen.add(key)
            keys.append(key)
        draw.phrase(guess, family, slots)
    items = [_Demo(resolve(ref, out), task, state) for ref, task, state in keys]
    found = {}
    limits = Limits.around(SAFETY_SECONDS, None)
    for outcome in map_local(_demonstrate, items, workers, lambda item: limits, _prepare_demo):
        if not outcome.ok:
            item = items[outcome.index]
            raise BccError(f"corpus: planning {item.task} in {item.dungeon} failed: {outcome.error}")
        found[keys[outcome.index]] = outcome.value
    return found


# A*'s budget per demonstration, in states stored, so that the corpus depends only on the
# seed (a wall-clock budget made hard demonstrations succeed or not with the machine's load).
PLAN_STATES = 2_000_000
# Only a safety net: a demonstration still running after this long makes generation fail
# loudly (dropping the pair would again make the output depend on the machine).
SAFETY_SECONDS = 600


def _prepare_demo(item: _Demo) -> None:
    """Compile in the process that forks the item's child, which then inherits the model."""
    from .interpret import goal_model
    from .learn import space_for
    space_for(item.dungeon)
    goal_model(item.dungeon, item.task)


def _demonstrate(item: _Demo):
    """(actions, explanations) of an A* demonstration of the task from the start, or None
    when there is no plan within PLAN_STATES states or no explanation of it."""
    from ..solvers import Budget
    from ..demonstration import from_actions
    from .interpret import plan
    from .learn import explain, space_for
    result = plan(item.dungeon, item.task, item.start, Budget(max_states=PLAN_STATES, time_limit=SAFETY_SECONDS))
    if result.budget == "time_limit":
        raise BccError(f"A* used up its {SAFETY_SECONDS} s safety limit before its budget of {PLAN_STATES} "
                       f"states: the pair would depend on this machine's speed (raise corpus.SAFETY_SECONDS)")
    if not result.solved:
        return None
    demo = from_actions(space_for(item.dungeon).model, result.plan, start=item.start)
    explained = explain(demo, item.dungeon)
    return (list(result.plan), explained) if explained else None


def _random_walk(model, rng: random.Random, steps: int):
    """A start somewhere else: a few random moves and turns from the dungeon's start."""
    moves = [model.action_index(a) for a in ("move_forward", "rotate_left", "rotate_right") if a in model.action_names]
    state, prefix = model.initial, []
    for _ in range(steps):
        i = rng.choice(moves)
        nxt = model.apply(i, state)
        if nxt is None or model.is_failure(nxt):
            continue
        state = nxt
        prefix.append(model.action_names[i])
    return prefix, state


def start_state(row: dict):
    """The (space, start state) of a corpus row."""
    from ..demonstration import from_actions
    from .learn import space_for
    space = space_for(resolve(row["dungeon"]))
    return space, from_actions(space.model, row["prefix"]).states[-1]


def candidates(row: dict) -> list[str]:
    """The candidate task texts of a corpus row, from its start."""
    space, start = start_state(row)
    return [t.text for t in space.tasks(start)]


def train(rows: list[dict]):
    """A grounding model trained on corpus rows (negatives: each row's candidates from its start)."""
    from .learn import train as train_rows
    return train_rows([r | {"dungeon": resolve(r["dungeon"])} for r in rows], candidates_of=candidates,
                      scene_of_row=scene)


def scene(row: dict):
    """The scene of a corpus row from its start (route.py), or None in a dungeon without rooms."""
    from .route import scene_of
    return scene_of(*start_state(row))


def evaluate(model, rows: list[dict]) -> dict:
    """Held-out accuracy: the interpreted task equals the task the pair was generated for."""
    from .interpret import rank
    right, wrong = 0, []
    for row in rows:
        space, start = start_state(row)
        got = rank(model, space, start, row["command"]).task
        if got == row["task"]:
            right += 1
        else:
            wrong.append({"command": row["command"], "dungeon": row["dungeon"], "task": row["task"], "got": got})
    return {"pairs": len(rows), "correct": right, "accuracy": right / len(rows) if rows else None, "errors": wrong}


@dataclasses.dataclass
class _Cache:
    digest: str = ""
    model: object = None


_cache = _Cache()


MODEL = CORPUS_DIR / "model.json"   # the model of the training split, shipped: training compiles every dungeon


def corpus_model(split: str | None = "train"):
    """The grounding model trained on the shipped corpus (`split` rows, or all with None),
    cached in memory; the training split's is shipped (`MODEL`, written by `generate` or
    `write_model`) and used while the digest it records matches the pairs."""
    key = f"{digest()}:{split}"
    if _cache.digest != key:
        _cache.model = _shipped(key)
        if _cache.model is None:
            rows = [r for r in load() if split is None or r["split"] == split]
            _cache.model, _ = train(rows)
        _cache.digest = key
    return _cache.model


def _shipped(key: str):
    from .models import from_json
    try:
        data = json.loads(MODEL.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if not isinstance(data, dict) or data.get("corpus") != key:
        return None
    return from_json(data, str(MODEL))


def write_model(out: Path = CORPUS_DIR) -> None:
    """Train on the training split and ship the model beside the pairs."""
    model, _ = train([r for r in load(out / "pairs.jsonl") if r["split"] == "train"])
    write_text(out / "model.json", json.dumps(model.to_json() | {"corpus": f"{digest(out / 'pairs.jsonl')}:train"},
                                              separators=(",", ":")) + "\n")


if __name__ == "__main__":
    print(json.dumps(generate(progress=lambda k, n: print(f"\r{k}/{n}", end="", flush=True)), indent=2))
