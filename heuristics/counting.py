"""A counting abstraction of the whole model: exact distances in a smaller state space.

The position pattern database (patterns.py) sees only where the agent stands, so a goal
about the grid's contents ("no cell outside region R holds value v") gets h = 0, and the
delete relaxation (relaxed_view.py) never has to put anything down. This abstraction keeps
what both lose:

- every state variable, exactly (the agent, what it holds);
- exactly, each mutable cell whose start value breaks the goal's condition on that cell
  (or that the goal reads at a fixed position): these must change;
- every other mutable cell only as a count: cells are grouped into classes of equal
  start value and equal goal treatment (for each value, does the goal's per-cell
  condition hold?), and an abstract state keeps, per class, how many of its cells hold
  each value other than the start's. The goal holds or fails alike in every arrangement
  of the counts, so the abstract goal test is exact.

An action's cells are read and written at coordinates computed from the variables (the
agent's pose), so the abstract transition knows which exact cell or which class it
touches. A counted cell may hold any value its class still counts (an over-
approximation: the abstraction cannot tell which cell of a class holds what). The
action itself runs as generated code (`apply`) on a concrete state built from the
abstract one with each choice of values for the counted cells it touches; what it
changes updates the exact part and the counts. Every real transition s -> t has an
abstract one alpha(s) -> alpha(t) of the same cost, so the exact abstract distance
(backward from the abstract goal states) never overestimates and is consistent.

Built by a forward exploration of the abstract states reachable from the start's, then
a backward search by cost; bounded by a state limit and a time limit (None past them).
"""
from __future__ import annotations

import math
import time

from ..model import Model, cell_entries
from .counting_build import Builder as _Builder
from .position import blind
from .counting_data import FULL_STATES, MAX_STATES, CountingDatabase, TooBig, Unsupported  # noqa: F401 - the public names


def build(layout, actions, search, goal, failure, reach, n_values, initial: bytes, apply_fns, is_goal, is_failure,
          time_limit: float | None = None, max_states: int = MAX_STATES) -> CountingDatabase:
    """The database; raises Unsupported outside the abstraction, TooBig past its limits.

    First with every variable; past FULL_STATES abstract states, again with variables
    projected away (any of their values: coarser, still admissible), the one with the
    most values first, until it fits in `max_states`. Only variables that neither the
    goal nor a cell's position reads are projected (a selected slot, a gaze)."""
    deadline = math.inf if time_limit is None else time.process_time() + time_limit
    args = (layout, actions, search, goal, failure, reach, n_values, initial, apply_fns, is_goal, is_failure,
            deadline)
    first = _Builder(*args, min(max_states, FULL_STATES))
    try:
        return first.run()
    except TooBig as exc:
        if exc.timed_out:
            raise
    project: list = []
    for j in first.projectable():
        project.append(j)
        try:
            return _Builder(*args, max_states, project=tuple(project)).run()
        except TooBig as exc:
            if exc.timed_out:
                raise
    raise TooBig(f"more than {max_states:,} abstract states")


def goal_changes_cells(layout, actions, search, goal, failure, reach, n_values, initial: bytes, *rest) -> bool:
    """Whether the goal needs some cell of the grid changed (a cell kept exactly): where
    it does not (the goal reads variables alone), search without the abstraction is
    usually cheaper than building it. Cheap: no state is explored."""
    try:
        return bool(_Builder(layout, actions, search, goal, failure, reach, n_values, initial, None, None, None,
                             math.inf, 0).exact)
    except (Unsupported, TooBig):
        return False


def build_or_none(*args, **kw) -> dict:
    """{"db": the database, or None outside the abstraction or past its size limits} (to
    be cached); raises TooBig when the time limit stops it (nothing worth remembering)."""
    try:
        return {"db": build(*args, **kw)}
    except Unsupported:
        return {"db": None}
    except TooBig as exc:
        if exc.timed_out:
            raise
        return {"db": None}


def counting(model: Model, time_limit: float | None = None):
    """Exact distances in the counting abstraction (`build` above): every variable and the
    cells the goal needs changed kept exactly, the other cells counted. Admissible and
    consistent; falls back to blind search where it cannot be built."""
    db = model.data("counting_database", time_limit=time_limit)
    if db is None:
        h = blind(model)
        h.fallback = "blind"
        return h
    base, variables, parts, part, get, shift = db.base, db.variables.get, db.parts.get, db.part, db.table.get, db.shift

    project = db.project if db.projected else None
    part_of: dict = {}   # a state's changed cells (its tail) -> its cell part's id: states share a few tails

    def h(s):
        v = variables(project(s) if project else s[:base])
        tail = s[base:]
        r = part_of.get(tail, -1)
        if r == -1:
            r = part_of[tail] = parts(part(cell_entries(tail)))
        d = None if v is None or r is None else get(v << shift | r)
        return 0 if d is None else d   # None: never met by the abstraction (cannot happen); 0 stays admissible
    return h
