"""A solve request's solver options, checked as `bcc solve` checks its flags."""
from __future__ import annotations

from ..errors import BccError
from ..solvers import LEARNING, learning_options, list_solvers

# the JSON fields of the learning solvers' options (see schemas.SolveRequest)
FIELDS = {"learner": "model", "delta": "delta", "m": "known_after", "episodes": "episodes", "seed": "seed",
          "gamma": "gamma", "max_steps": "max_steps"}


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
    options.update(learning_options(req.solver, {key: getattr(req, field) for key, field in FIELDS.items()},
                                    {key: f"`{field}`" for key, field in FIELDS.items()}))
    return options
