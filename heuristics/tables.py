"""The tables heuristics build from a model: once per model, and kept in the on-disk cache.

| data name | what | built from |
|---|---|---|
| `pattern_database` | patterns.py: distances over the agent's position and facing | a compiled dungeon |
| `relaxed_task` | the delete-relaxed view (relaxed_task.py) | a compiled dungeon (relaxed_view.py) or an imported PDDL task (relaxed_pddl.py) |
| `counting_database` | counting.py: distances in the counting abstraction | a compiled dungeon |
| `counting_wanted` | whether the goal needs cells changed (counting.goal_changes_cells) | a compiled dungeon |

A compiled dungeon gives what they are built from as `model.data("compiled")`
(compiler/pipeline.py, `Compiled`), an imported PDDL task as `model.data("ground_task")`.
`register()` (run when bcc.heuristics is imported, as bcc.solvers does) makes each name a
data name of every model, `model.data("relaxed_task")`, as solvers and plugins ask for
them; what is built is kept in `model.memo`. A build stopped by its time limit keeps
nothing: another call, with more time, may still build it.
"""
from __future__ import annotations


def _key(c, *more) -> bytes:
    """The on-disk cache key of a table of the compiled dungeon `c`: its generated code
    (actions, goal, layout), the grid, the start and what else the build reads."""
    return b"\0".join([c.source.encode(), c.layout.static_grid, c.initial, *more])


def pattern_database(model):
    """The pattern database, or None where there is none (no agent position to pattern)."""
    memo = model.memo
    if "pattern_database" not in memo:
        c = model.data("compiled")
        if c is None:
            return None
        from ..compiler.cache import cached_analysis
        from . import patterns
        key = _key(c, repr((c.n_values, [v.label for v in c.position_vars], c.search)).encode())
        memo["pattern_database"] = cached_analysis("patterns", key, lambda: patterns.build(
            c.layout, c.actions, c.search, c.goal, c.reach, c.n_values, c.position_vars, c.initial))
    return memo["pattern_database"]


def relaxed_task(model, time_limit: float | None = None):
    """The delete-relaxed view; None past its limits (or `time_limit` seconds)."""
    memo = model.memo
    if "relaxed_task" not in memo:
        c = model.data("compiled")
        if c is not None:
            from ..compiler.cache import cached_analysis
            from .relaxed_task import RelaxedTooBig
            key = _key(c, c.layout.start_cells, repr((c.n_values, c.search)).encode())
            try:
                found = cached_analysis("relaxed", key, lambda: _relaxed_or_none(c, time_limit))
            except RelaxedTooBig:
                return None
            memo["relaxed_task"] = found.get("task") if isinstance(found, dict) else None
        else:
            task = model.data("ground_task")
            if task is None:
                return None
            from .relaxed_pddl import relaxed_task as view_of
            memo["relaxed_task"] = view_of(task)
    return memo["relaxed_task"]


def _relaxed_or_none(c, time_limit) -> dict:
    """{"task": the relaxed view, or None past its size limits}; raises RelaxedTooBig when
    the time limit stops it (nothing to remember then)."""
    from . import relaxed_view
    try:
        task = relaxed_view.build(c.layout, c.actions, c.search, c.goal, c.reach, c.n_values,
                                  c.initial + c.layout.start_cells, time_limit)  # dense
    except relaxed_view.RelaxedTooBig as exc:
        if "time" in str(exc):
            raise
        task = None
    return {"task": task}


def counting_database(model, time_limit: float | None = None):
    """The counting abstraction's distances; None outside what it handles or past its limits."""
    memo = model.memo
    if "counting_database" not in memo:
        c = model.data("compiled")
        if c is None:
            return None
        from ..compiler.cache import cached_analysis
        from . import counting
        key = _key(c, c.layout.start_cells, repr((c.n_values, c.search)).encode())
        try:
            found = cached_analysis("counting", key, lambda: counting.build_or_none(*counting_args(c), time_limit))
        except counting.TooBig:
            return None
        memo["counting_database"] = found.get("db") if isinstance(found, dict) else None
    return memo["counting_database"]


def counting_args(c) -> tuple:
    """What counting.build reads of the compiled dungeon `c`, in its order."""
    fns = c.functions
    return (c.layout, c.actions, c.search, c.goal, c.failure, c.reach, c.n_values, c.initial,
            [fns[f"apply_{i}"] for i in range(len(c.actions))], fns["goal"], fns["failure"])


def counting_wanted(model) -> bool | None:
    """Whether the goal needs cells of the grid changed (counting.goal_changes_cells)."""
    memo = model.memo
    if "counting_wanted" not in memo:
        c = model.data("compiled")
        if c is None:
            return None
        from . import counting
        memo["counting_wanted"] = counting.goal_changes_cells(c.layout, c.actions, c.search, c.goal, c.failure,
                                                              c.reach, c.n_values, c.initial)
    return memo["counting_wanted"]


TABLES = {"pattern_database": pattern_database, "relaxed_task": relaxed_task,
          "counting_database": counting_database, "counting_wanted": counting_wanted}


def register() -> None:
    """Make every table a data name of every model (`Model.data`)."""
    from ..model import PROVIDED
    PROVIDED.update(TABLES)
