"""Sweep files: the run set of `bcc batch --sweep SWEEP.yaml`, with errors at file:line:col.

    dungeons:                       # files, shipped names, globs, generator specs
      - bridge
      - "maze:width=21,depth=21,stones=2,seed=1..50"
    solvers:                        # a name, or a mapping; list values are swept
      - bfs
      - {solver: astar, heuristic: [manhattan, pdb]}
      - {solver: wastar, weight: [1.5, 3], time_limit: 30}
    seeds: 3                        # N (0..N-1) or a list; only rmax and qlearning use them
    goal: agentOnBlock(agent, gold) # optional, overrides every dungeon's goal
    budget: {time_limit: 60, max_states: 1000000, max_memory: 2000}
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import BccError
from .runs import BUDGETS, check_limits, check_options, check_size

TOP_KEYS = {"dungeons", "solvers", "seeds", "goal", "budget"}


@dataclass
class Sweep:
    dungeons: list = field(default_factory=list)
    settings: list = field(default_factory=list)    # (solver, options, limits) triples
    seeds: list | None = None
    goal: str | None = None
    budget: dict = field(default_factory=dict)


def seeds_from(value) -> list[int]:
    """`N` means seeds 0..N-1; a list is taken as it is."""
    if isinstance(value, bool):
        raise BccError(f"seeds must be a whole number or a list of them, got {value!r}")
    if isinstance(value, int):
        if value < 1:
            raise BccError(f"seeds must be at least 1, got {value}")
        check_size(value, f"seeds: {value}")
        return list(range(value))
    if isinstance(value, list) and value and all(isinstance(s, int) and not isinstance(s, bool) for s in value):
        return list(dict.fromkeys(value))
    raise BccError(f"seeds must be a whole number or a non-empty list of them, got {value!r}")


def expand_setting(solver: str, values: dict) -> list[tuple[str, dict, dict]]:
    """One (solver, options, limits) per combination of the list values in `values`."""
    keys = list(values)
    axes = [v if isinstance(v, list) else [v] for v in values.values()]
    out = []
    for combo in itertools.product(*axes):
        chosen = dict(zip(keys, combo))
        options = {k: v for k, v in chosen.items() if k not in BUDGETS}
        limits = {k: v for k, v in chosen.items() if k in BUDGETS}
        check_options(solver, options)
        out.append((solver, options, check_limits(limits)))
    return out


def load_sweep(path: str) -> Sweep:
    from ..compiler.source import YList, YMap, check_keys, error_at, load_yaml
    from .dungeons import expand_dungeons
    data = load_yaml(path)
    for key in data:
        if key in BUDGETS:  # a likely slip: a limit written beside `budget` instead of in it
            raise error_at(data, key, f"{key} goes under `budget:` in a sweep, e.g. budget: {{{key}: ...}}",
                           on_key=True)
    check_keys(data, TOP_KEYS, set(), "a sweep")
    sweep = Sweep()

    def at(container, key):
        def wrap(exc: BccError) -> BccError:
            return error_at(container, key, exc.message)
        return wrap

    dungeons = data.get("dungeons", [])
    if isinstance(dungeons, str):
        dungeons = YList([dungeons])
        dungeons.node, dungeons.nodes, dungeons.src = data.nodes["dungeons"][1], [data.nodes["dungeons"][1]], data.src
    if not isinstance(dungeons, YList):
        raise error_at(data, "dungeons", "dungeons must be a list of files, shipped names, globs or generator specs")
    sweep.dungeons = expand_dungeons(dungeons, Path(path).parent,
                                     where=lambda i, message: error_at(dungeons, i, message))
    if "budget" in data:
        budget = data["budget"]
        if not isinstance(budget, YMap):
            raise error_at(data, "budget", f"budget must be a mapping of {', '.join(BUDGETS)}")
        check_keys(budget, set(BUDGETS), set(), "budget")
        for key in budget:
            try:
                sweep.budget.update(check_limits({key: budget[key]}))
            except BccError as exc:
                raise at(budget, key)(exc) from None
    solvers = data.get("solvers")
    if solvers is not None:
        if not isinstance(solvers, YList) or not solvers:
            raise error_at(data, "solvers", "solvers must be a non-empty list of names or mappings")
        for i, entry in enumerate(solvers):
            sweep.settings.extend(_setting(solvers, i, entry))
    if "seeds" in data:
        try:
            sweep.seeds = seeds_from(data["seeds"])
        except BccError as exc:
            raise at(data, "seeds")(exc) from None
    if "goal" in data:
        if not isinstance(data["goal"], str) or not data["goal"].strip():
            raise error_at(data, "goal", "goal must be an expression, e.g. agentOnBlock(agent, gold)")
        sweep.goal = data["goal"]
    return sweep


def _setting(solvers, i, entry) -> list:
    from ..compiler.source import YMap, check_keys, error_at
    if isinstance(entry, str):
        try:
            return expand_setting(entry, {})
        except BccError as exc:
            raise error_at(solvers, i, exc.message) from None
    if not isinstance(entry, YMap):
        raise error_at(solvers, i, "a solver is a name or a mapping {solver: NAME, option: value, ...}")
    # any key but `solver` is a budget or an option, checked against the solver's declaration below
    check_keys(entry, {"solver", *entry}, {"solver"}, "a solver entry")
    if not isinstance(entry["solver"], str):
        raise error_at(entry, "solver", "solver must be a solver name (see `bcc solvers`)")
    try:
        expand_setting(entry["solver"], {})
    except BccError as exc:
        raise error_at(entry, "solver", exc.message) from None
    values = {k: v for k, v in entry.items() if k != "solver"}
    from ..solvers import get_solver
    from ..solvers.options import not_taken, options_of
    declared = [o.name for o in options_of(get_solver(entry["solver"])) if o.name != "seed"]
    for key in values:
        if key == "seed":
            raise error_at(entry, key, "seeds are swept with `seeds:` at the top of a sweep (or --seeds)", on_key=True)
        if key not in BUDGETS and key not in declared:
            raise error_at(entry, key, not_taken(entry["solver"], key, declared).message, on_key=True)
    for key, value in values.items():
        if isinstance(value, list) and not value:
            raise error_at(entry, key, f"{key}: an empty list sweeps nothing")
    for key, value in values.items():  # each value alone first, so an error points at the item
        items = value if isinstance(value, list) else [value]
        for j, item in enumerate(items):
            try:
                expand_setting(entry["solver"], {key: item})
            except BccError as exc:
                raise (error_at(value, j, exc.message) if isinstance(value, list)
                       else error_at(entry, key, exc.message)) from None
    try:
        return expand_setting(entry["solver"], values)
    except BccError as exc:
        raise error_at(entry, "solver", exc.message) from None
