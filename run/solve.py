"""One run: a solver on a model under one budget, the path every edge takes.

`bcc solve`, `bcc import pddl`, the server's solve jobs and batch rows need the same steps
around a solver, in this order: check the options against the solver's declaration (bad
options are bad input before anything runs), fill in the default memory budget (half the
machine), start one deadline that loading the model, a reference search and the solve
share, back the budget with hard limits (a timer and an address-space cap; a job process
that caps itself says `hard=False`), load the model, end with no plan at once when some
goal cell atom can never hold (heuristics/cell_reach.py: proved, whatever the solver),
give a solver that declares `optimal_cost` A*'s cost within half the time left (a
learner's `converged_episode` is measured against it), and solve. A budget spent outside
the solver's own checks (compiling, a heuristic's table) still ends as a Result with
status "budget".

What is loaded is usually a `Model` (a dungeon, a grounded PDDL task); it may be another
task a solver reads (an HDDL task network, a PDDL task too big to ground, searched
lifted): the steps are the same, and choosing the solver by the model or giving it a
reference cost applies to a Model only.
"""
from __future__ import annotations

import contextlib
from dataclasses import dataclass, field
from typing import Callable

from ..heuristics.cell_reach import goal_never_holds
from ..model import Model
from ..solvers import Budget, Result, check_options, default_solver, get_solver, optimal_cost
from ..solvers.base import Meter
from ..solvers.limits import BudgetExceeded, Deadline, exceeded_result, hard_limits
from ..solvers.options import keywords_of


@dataclass
class Request:
    """What to run. `options` maps option names, as users write them, to values (text from
    the command line, typed from JSON or YAML; None for not given); `spell(name)` names an
    option in an error as the caller's users write it (`--known-after`)."""
    load: Callable[[], object]           # compiles or imports the model (or task), inside the budget
    solver: str = "astar"
    options: dict = field(default_factory=dict)
    budget: Budget = field(default_factory=Budget)
    progress: Callable | None = None
    hard: bool = True                    # back the budget with hard_limits (see solvers/limits.py)
    spell: Callable[[str], str] | None = None
    solve: Callable | None = None        # called instead of the solver's own function (the PDDL portfolio)
    search_share: float = 1.0            # of the time left once the model is loaded, for the search
    pick: bool = False                   # choose the solver by the loaded model (solvers.default_solver)


@dataclass
class Ran:
    result: Result
    model: object                        # what `load` returned (a Model, ...); None when the budget ran out first


def run(request: Request) -> Ran:
    """Run `request`; BccError for an unknown solver or a bad option (before anything runs)."""
    solver = request.solver
    solve = request.solve or get_solver(solver)
    options = check_options(solver, request.options, *([request.spell] if request.spell else []))
    given = request.budget
    budget = Budget(max_states=given.max_states, time_limit=given.time_limit,
                    max_memory_mb=given.max_memory_mb if given.max_memory_mb is not None
                    else Budget.default().max_memory_mb)
    deadline = Deadline(budget)
    model = None
    try:
        with hard_limits(budget) if request.hard else contextlib.nullcontext():
            model = request.load()
            is_model = isinstance(model, Model)
            if request.pick and is_model and default_solver(model) != solver:
                solver = default_solver(model)
                solve = get_solver(solver)
            never = goal_never_holds(model) if is_model else None
            if never:   # proved before any search: every solver would end with no plan
                result = Meter(budget).finish(Result(solver=solver, solved=False, status="no_solution", message=never))
            else:
                if is_model and "optimal_cost" in keywords_of(get_solver(solver)):
                    options["optimal_cost"] = optimal_cost(model, deadline.remaining(share=0.5))
                result = solve(model, deadline.remaining(request.search_share), progress=request.progress, **options)
    except BudgetExceeded as exc:
        result = exceeded_result(solver, exc.which, deadline)
    return Ran(result, model)
