"""The build solver's run as a whole: its tries, what happens when serialising stops
short of the goal, and the shorter plan made of what it found.

- **Tries.** The builder (solvers/build.py) is deterministic, and which of two equally
  near places or atoms it takes first can decide whether it strands itself (the last
  cell walled in by scaffolding). When a try stops short of the goal, another one starts
  from the start, while the budget lasts, at most len(TRIES) in all; the try that reached
  the goal, or else the one that left the fewest atoms, is kept. The first plans ahead
  (solvers/build.py: the supports of atoms that rest on nothing the goal builds, which
  must rise early inside what the goal encloses, and the orders that fill an enclosed
  region from the inside out) and may take a quarter of the time left; it is skipped when
  there is nothing to plan. The others make supports when their atom comes (an open
  structure needs its blocks to climb): the second keeps what the pending atoms take (no
  search spends it, on scaffolding say: a world holding just the blocks its top needs),
  the third does not (a structure whose scaffolds must borrow the blocks it is made of,
  and give them back), the others keep it, with other ties (their walks' action order
  shuffled by a seed); the last also looks for footing deeper (solvers/scaffold.py
  DEEP_DEPTH: a stair to a place ten levels up), which the others do not, as it costs
  time where a shallow footing does. Each try but the first and the last may take half
  the time left: one way that grinds cannot starve the others.
- **The fallback rule** (`search_may_help`, the one place of it). gbfs gets what is left
  of the budget from the state reached only where a search may help: the goal has a
  conjunct other than cell atoms and amounts to gather (which the builder does not
  pursue), an atom waits for a value that no gathering walk raised (it must be made from
  others), or at most FALLBACK_UP_TO atoms are left and no amount is short; never where an
  atom left can never hold from there (heuristics/cell_reach.py). Otherwise the
  run ends with no plan (`no_solution`; its message says the builder is not complete):
  on a world of any size gbfs's relaxed view alone takes longer than the builder did.
- **Shorter plans.** Greedy action elimination (solvers/shorten.py) on plans of at most
  SHORTEN_UP_TO actions; then blind A* on plans of at most `improve` actions.
"""
from __future__ import annotations

import dataclasses

from ..heuristics.cell_reach import never_hold
from .base import Budget, Result, budget_result
from .shorten import eliminate

NAME = "build"
TRIES = ((0, True, True, False), (0, True, False, False), (0, False, False, False), (1, True, False, False),
         (2, True, False, False), (3, True, False, False), (1, True, False, True))
# (seed of the ties, keep, plan ahead, deep footing) of each try
AHEAD_SHARE = 4         # the try that plans ahead may take 1/AHEAD_SHARE of the time left
FALLBACK_UP_TO = 3      # atoms left (and no amount short) for which the gbfs fallback still runs
SHORTEN_UP_TO = 600     # plans this short go through action elimination (solvers/shorten.py)
IMPROVE_STATES = 100_000
IMPROVE_FLOOR = 1.0     # seconds the improving A* may always take (more if finding the plan took more)
IMPROVE_MB = 400        # the process's memory at which A*'s try stops


def _amount(node) -> bool:
    """A goal conjunct that bounds one variable by constants (`5 <= v`, `5 <= v <= 63`)."""
    from ..compiler import ir
    return isinstance(node, ir.Cmp) and sum(isinstance(o, ir.Var) for o in node.operands) == 1 \
        and all(isinstance(o, (ir.Var, ir.Const)) for o in node.operands) \
        and all(op in ("<=", "<", ">=", ">") for op in node.ops)


def _never(builder, state) -> list:
    """The goal's atoms (planned supports aside) that can never hold from `state`."""
    cells = builder.cells
    goal = dataclasses.replace(cells, atoms=[a for a in cells.atoms if a[0] in builder.goal])
    return never_hold(goal, builder.model, state, builder.read) or []


def search_may_help(builder, state) -> bool:
    """Whether the gbfs fallback runs from `state`, where serialising stopped (the rule
    in the module docstring)."""
    if _never(builder, state):
        return False   # proved: no search can reach the goal from here
    if any(not _amount(g) for g in builder.cells.rest):
        return True
    sup = builder.supplies
    short = sup.short(state, (), builder.wanted) if sup else {}
    if builder.goal_left() <= FALLBACK_UP_TO and not short:
        return True
    return bool(sup) and any(builder._starved(state, v) for v in builder.todo.values())


def gave_up(builder, state) -> str:
    sup = builder.supplies
    short = sup.short(state, (), builder.wanted) if sup else {}
    never = _never(builder, state)
    if never:
        return (f"the build solver stopped where {len(never)} goal cell atom(s) can no longer be written "
                f"(first: {never[0][0]}): it is not complete; --solver gbfs searches the whole space")
    return (f"the build solver stopped with {builder.goal_left()} goal cell atom(s) unwritten and {len(short)} "
            "amount(s) short: it is not complete; --solver gbfs searches the whole space")


@dataclasses.dataclass
class Run:
    builder: object
    plan: list
    state: bytes
    why: str | None          # a budget's name, or None
    stats: dict
    bound: int


class _TryMeter:
    """The run's meter, which also says TRY_SPENT once this try's share of the time is gone."""

    def __init__(self, meter, until: float | None):
        self.meter, self.until = meter, until

    @property
    def mask(self) -> int:
        return self.meter.mask

    def check(self, *counts):
        which = self.meter.check(*counts)
        if which is None and self.until is not None and self.meter.elapsed() > self.until:
            return TRY_SPENT
        return which


TRY_SPENT = "try"


def serialise(model, make_builder, meter, budget: Budget) -> Run:
    """The builder's tries (module docstring): the first that reaches the goal, else the
    one that left the fewest atoms. Its stats count every try."""
    from ..heuristics.goal_cells import lower_bound
    best, stats = None, dict(expanded=0, generated=0, stored=0)
    for k, (seed, keep, ahead, deep) in enumerate(TRIES):
        until = None
        if budget.time_limit is not None and k < len(TRIES) - 1:
            until = meter.elapsed() + max(0.0, budget.time_limit - meter.elapsed()) / (AHEAD_SHARE if ahead else 2)
        builder = make_builder(seed, keep, ahead, deep, _TryMeter(meter, until))
        if ahead and not builder.plans_ahead(model.initial):
            continue
        if best is None:
            bound = lower_bound(builder.cells, model, model.initial, builder.read)
        plan, state, why = builder.run(model.initial)
        if why == TRY_SPENT:       # this try's share is gone: the next one starts
            why = None
        stats = dict(expanded=stats["expanded"] + builder.expanded, generated=stats["generated"] + builder.generated,
                     stored=stats["stored"] + builder.expanded)
        run = Run(builder, plan, state, why, stats, bound)
        if best is None or (why is None and builder.goal_left() < best.builder.goal_left()):
            best = run
        if why is not None or model.is_goal(state):
            return run if why is None else dataclasses.replace(best, why=why)
        if meter.check(stats["expanded"], stats["generated"], stats["expanded"]):
            break
    return best


def finish(model, budget: Budget, meter, run: Run, improve: int, progress) -> Result:
    """The result of the tries: the fallback where it may help, then a shorter plan."""
    from . import get_solver
    stats, bound, state = dict(run.stats), run.bound, run.state
    if run.why is not None:
        return budget_result(NAME, run.why, meter, lower_bound=bound, **stats)
    tail = []
    if not model.is_goal(state) and not search_may_help(run.builder, state):
        return meter.finish(Result(solver=NAME, solved=False, status="no_solution", lower_bound=bound, **stats,
                                   message=gave_up(run.builder, state)))
    if not model.is_goal(state):   # the fallback: gbfs from here, with what is left of the budget
        left = None if budget.time_limit is None else max(0.0, budget.time_limit - meter.elapsed())
        rest = get_solver("gbfs")(dataclasses.replace(model, initial=state),
                                  Budget(budget.max_states, left, budget.max_memory_mb), progress)
        stats = {k: stats[k] + getattr(rest, k) for k in stats}
        if not rest.solved:
            rest.solver, rest.lower_bound = NAME, bound
            rest.expanded, rest.generated, rest.stored = stats["expanded"], stats["generated"], stats["stored"]
            return meter.finish(rest)
        tail = [model.action_index(n) for n in rest.plan]
    actions = [*run.plan, *tail]
    if len(actions) <= SHORTEN_UP_TO:   # detours out: O(n^2) steps of the simulator
        actions = eliminate(model, actions, lambda: budget.time_limit is not None and meter.elapsed() > budget.time_limit)
    if 0 < len(actions) <= improve:   # short: an optimal search may finish and find a shorter plan
        actions = _improve(model, budget, meter, actions, stats)
    return meter.finish(Result(solver=NAME, solved=True, status="solved",
                               plan=[model.action_names[a] for a in actions],
                               cost=sum(model.action_costs[a] for a in actions),
                               lower_bound=bound, **stats))


def _improve(model, budget, meter, actions, stats) -> list:
    """Blind A* for a plan shorter than `actions` (as long again as the plan took, at least
    IMPROVE_FLOOR s, at most a quarter of the time left): its plan when shorter."""
    from . import get_solver
    left = max(IMPROVE_FLOOR, meter.elapsed())   # anytime doubling
    if budget.time_limit is not None:
        left = min(left, max(0.0, budget.time_limit - meter.elapsed()) / 4)
    mem = min(IMPROVE_MB, budget.max_memory_mb / 2) if budget.max_memory_mb else IMPROVE_MB
    better = get_solver("astar")(model, Budget(min(budget.max_states or IMPROVE_STATES, IMPROVE_STATES), left, mem),
                                 heuristic="blind")
    for k in stats:
        stats[k] += getattr(better, k) or 0
    if better.solved and better.cost < sum(model.action_costs[a] for a in actions):
        return [model.action_index(n) for n in better.plan]
    return actions
