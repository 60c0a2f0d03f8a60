"""The values each state byte can take, which bounds the size of the grounded export.

Why: a grounded encoding needs one fact per (byte, value). The declared ranges are exact
but large (an inventory count has 65 values, and a mined block can land in any of 9
slots), so when the reachable state space is small enough we enumerate it -- every
action, from the initial state, not expanding failure states -- and keep only the values
that occur. That is exact for the export: a transition from a reachable state leads to a
reachable state, whose values are all kept, so the export's reachable graph is the
model's. When the enumeration exceeds its cap the export stops with a clear error: with
the declared ranges a grounded encoding of, e.g., the tough maze (six stones, nine
slots, counts to 64) runs to millions of operators, which no planner grounds in time.
"""
from __future__ import annotations

from dataclasses import dataclass

DEFAULT_MAX_STATES = 300_000


@dataclass
class Domains:
    values: tuple         # per state byte: the tuple of values kept
    source: str           # how they were found: "reachable" (enumerated)
    states: int           # reachable states enumerated


def reachable(model, max_states: int) -> tuple | None:
    """Per byte, the values seen in reachable states; None if there are more than max_states."""
    start = model.initial
    seen = {start}
    stack = [start]
    apply_fns, is_failure = model.apply_fns, model.is_failure
    while stack:
        s = stack.pop()
        if is_failure(s):
            continue
        for fn in apply_fns:
            t = fn(s)
            if t is not None and t not in seen:
                if len(seen) >= max_states:
                    return None
                seen.add(t)
                stack.append(t)
    import numpy as np
    table = np.frombuffer(b"".join(seen), dtype=np.uint8).reshape(len(seen), len(start))
    return tuple(tuple(int(v) for v in np.unique(table[:, i])) for i in range(len(start))), len(seen)


def domains_for(model, max_states: int = DEFAULT_MAX_STATES) -> Domains:
    """Reachable value sets, or BccError when more than `max_states` states are reachable."""
    from ..errors import BccError
    found = reachable(model, max_states)
    if found is None:
        raise BccError(f"{model.name}: more than {max_states:,} states are reachable; the grounded PDDL export "
                       "enumerates them to keep only reachable values (raise the limit with --max-states)",
                       model.path)
    return Domains(found[0], "reachable", found[1])
