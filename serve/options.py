"""A solve request's solver options, checked by the solver's declaration (solvers/options.py),
the one check `bcc solve`, batch and minecraft use too."""
from __future__ import annotations

from ..solvers.options import check_options

# the SolveRequest fields that are not solver options; every other field is one, spelled
# as the solvers declare it (tests/test_solver_contract.py: every built-in option is a field)
NOT_OPTIONS = ("dungeon", "goal", "solver", "time_limit", "max_states", "max_memory_mb")


def option_fields(request_class) -> tuple[str, ...]:
    return tuple(name for name in request_class.model_fields if name not in NOT_OPTIONS)


def given_options(req) -> dict:
    """The solver options `req` carries, by name as declared (None: not given)."""
    return {name: getattr(req, name) for name in option_fields(type(req))}


def solver_options(req) -> dict:
    """The keyword options for the solver named in `req`; BccError for an unknown solver, an
    option it does not take, or a bad value."""
    return check_options(req.solver, given_options(req))
