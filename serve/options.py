"""A solve request's solver options, checked as `bcc solve` checks its flags."""
from __future__ import annotations

from ..errors import BccError
from ..solvers import list_solvers

LEARNING = ("rmax", "qlearning")


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
    if (req.episodes is not None or req.seed is not None) and req.solver not in LEARNING:
        raise BccError("`episodes` and `seed` apply to the learning solvers (rmax, qlearning)")
    if req.episodes is not None:
        options["episodes"] = req.episodes
    if req.seed is not None:
        options["seed"] = req.seed
    return options
