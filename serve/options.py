"""A solve request's solver options, checked as `bcc solve` checks its flags."""
from __future__ import annotations

from ..errors import BccError
from ..solvers import LEARNING, list_solvers


def solver_options(req) -> dict:
    """The keyword options for the solver named in `req`; BccError for a combination it cannot take."""
    if req.solver not in list_solvers():
        import difflib
        close = difflib.get_close_matches(req.solver, list(list_solvers()), n=1)
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        raise BccError(f"unknown solver {req.solver!r}{hint}; available: {', '.join(list_solvers())}")
    options = {}
    if req.heuristic is not None:
        from ..solvers.heuristics import HEURISTICS
        if req.heuristic != "auto" and req.heuristic not in HEURISTICS:
            raise BccError(f"unknown heuristic {req.heuristic!r}; available: auto, {', '.join(HEURISTICS)}")
        if req.solver == "bfs" or req.solver in LEARNING:
            raise BccError(f"{req.solver} uses no heuristic; drop `heuristic` or pick an informed solver (astar, ...)")
        options["heuristic"] = req.heuristic
    if req.weight is not None:
        if req.solver not in ("astar", "wastar"):
            raise BccError("`weight` applies to astar and wastar only")
        options["weight"] = req.weight
    rmax_only = {"learner": req.model, "delta": req.delta, "m": req.known_after}
    for (key, value), field in zip(rmax_only.items(), ("model", "delta", "known_after")):
        if value is not None:
            if req.solver != "rmax":
                raise BccError(f"`{field}` applies to rmax only")
            options[key] = value
    tuning = {"episodes": req.episodes, "seed": req.seed, "gamma": req.gamma, "max_steps": req.max_steps}
    given = [k for k, v in tuning.items() if v is not None]
    if given and req.solver not in LEARNING:
        raise BccError(f"{', '.join(f'`{k}`' for k in given)}: for the learning solvers (rmax, qlearning) only")
    options.update((k, v) for k, v in tuning.items() if v is not None)
    return options
