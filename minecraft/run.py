"""Closed-loop execution: plan in the model, act in the real world, check, replan.

Each step: the model predicts the next state (`model.apply`); an action the model forbids
or one it predicts to be fatal is refused here, because the server would not stop or
kill the bot the way bcc's rules do (it applies no lava damage and lets a player mine
gold). The bot performs the action, the state parser reads the world back, and the
observed state is compared with the prediction. On a difference the world wins: the
plan is recomputed from the observed state.
"""
from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass, field
from typing import Callable

from ..errors import BccError
from ..model import Model
from ..solvers import Budget, get_solver
from ..solvers.options import check_options, options_of
from .actions import changed_cells, geometry
from .bridge import BOT, Bridge
from .differences import known_step
from .moves import controls
from .world import WorldMap, check_playable, difference


@dataclass
class Step:
    number: int
    action: str
    predicted: bytes
    observed: bytes
    seconds: float               # from sending the action to having parsed the world again
    differences: list            # empty when the world matched the prediction
    notes: list                  # what the state parser could not fit into the model


@dataclass
class RunResult:
    dungeon: str
    solver: str
    reached_goal: bool = False
    status: str = "running"
    message: str = ""
    steps: list = field(default_factory=list)
    plans: list = field(default_factory=list)       # each plan: {"from_step", "plan", "seconds"}
    setup_seconds: float = 0.0
    total_seconds: float = 0.0

    def to_json(self, model: Model) -> dict:
        act = [s.seconds for s in self.steps]
        return {
            "dungeon": self.dungeon, "solver": self.solver, "reached_goal": self.reached_goal,
            "status": self.status, "message": self.message,
            "actions": [s.action for s in self.steps],
            "replans": max(0, len(self.plans) - 1), "plans": self.plans,
            "steps": [{"step": s.number, "action": s.action, "seconds": round(s.seconds, 3),
                       "predicted": model.decode(s.predicted), "observed": model.decode(s.observed),
                       "matched": not s.differences, "differences": s.differences, "notes": s.notes}
                      for s in self.steps],
            "seconds": {"setup": round(self.setup_seconds, 3), "total": round(self.total_seconds, 3),
                        "actions": round(sum(act), 3),
                        "per_action_mean": round(sum(act) / len(act), 3) if act else None,
                        "per_action_max": round(max(act), 3) if act else None},
        }


def solve_from(model: Model, state: bytes, solver: str, budget: Budget, replanning: bool,
               solver_options: dict | None = None):
    """A plan from `state` (the compiled model with its start moved there), with the
    user's checked `solver_options`, through the run layer: the budget binds all of it
    (a solver's preparation too), as in `bcc solve`."""
    from functools import partial
    from ..run.solve import Request, run as run_request
    solve = get_solver(solver)
    options = dict(solver_options or {})
    # replanning must be quick: the cheap heuristic, for the solvers that take one, unless the user chose
    informed = any(o.name == "heuristic" for o in options_of(solve))
    if replanning and informed and "heuristic" not in options:
        options.update(check_options(solver, {"heuristic": "manhattan"}))
    start = dataclasses.replace(model, initial=state)
    return run_request(Request(lambda: start, solver, {}, budget, solve=partial(solve, **options))).result


def prepare(bridge: Bridge, world: WorldMap, port: int, player: str = BOT) -> None:
    """Start the server, build the dungeon, bring the bot in at the start."""
    bridge.start(port=port)
    bridge.build(world)
    bridge.spawn_bot(player)
    args = world.setup_args(world.model.initial)
    bridge.setup(player, args, args["hotbar"], args.get("inventory"))


def observe_state(bridge: Bridge, world: WorldMap, player: str, hint: bytes | None = None):
    return world.parse(bridge.observe(player), hint)


def requests(world: WorldMap, action: str, before: bytes, after: bytes) -> list:
    """What the bot does for one action: the minecraft domain's controller by action (its
    view and hotbar), else the generic one read from the states (moves.py)."""
    if world.kind == "poses":
        return [geometry(world, action, before, after)]
    return controls(world, before, after)


def run(model: Model, bridge: Bridge, solver: str = "astar", budget: Budget | None = None,
        solver_options: dict | None = None,
        player: str = BOT, max_steps: int = 200, max_replans: int = 5, delay: float = 0.0,
        log: Callable[[str], None] = lambda line: None,
        after_step: Callable[[int, Bridge], None] | None = None) -> RunResult:
    """Solve, execute in the world step by step, replan on divergence (the bot must be in
    the world at the dungeon's start: see `prepare`). `after_step(n, bridge)` lets a test
    disturb the world between steps."""
    check_playable(model)
    world = WorldMap(model)
    budget = budget or Budget(time_limit=60)
    result = RunResult(model.name, solver)
    started = time.perf_counter()
    parsed = observe_state(bridge, world, player, model.initial)
    state = parsed.state
    if state != model.initial:
        diffs = difference(model, model.initial, state)
        log(f"the world differs from the dungeon's start: {'; '.join(diffs[:4])}")
    plan: list = []
    step = 0
    while not _stopped(model, result, state, step, max_steps):
        if not plan:
            plan = _replan(model, result, state, step, solver, budget, solver_options, max_replans, log)
            if plan is None:
                break
        if delay and step:
            time.sleep(delay)     # slow enough for a person watching in the game
        action = plan.pop(0)
        predicted = model.apply(model.action_index(action), state)
        notes = _refused(model, world, result, state, predicted, step, action)
        if notes is None:
            break
        step += 1
        t0 = time.perf_counter()
        for request in requests(world, action, state, predicted):
            bridge.act(player, **request)
        parsed = observe_state(bridge, world, player, predicted)
        seconds = time.perf_counter() - t0
        diffs = difference(model, predicted, parsed.state)
        result.steps.append(Step(step, action, predicted, parsed.state, seconds, diffs, notes + parsed.notes))
        _log_step(model, world, log, step, action, seconds, state, predicted, parsed, diffs, notes)
        state = parsed.state
        if after_step is not None:
            after_step(step, bridge)
            parsed = observe_state(bridge, world, player, state)
            if parsed.state != state:
                diffs = difference(model, state, parsed.state)
                log(f"        the world changed after step {step}: {'; '.join(diffs[:4])}")
                state = parsed.state
                plan = []
                continue
        if diffs:
            plan = []   # the world wins: replan from what is really there
    result.total_seconds = time.perf_counter() - started
    return result


def _stopped(model: Model, result: RunResult, state, step: int, max_steps: int) -> bool:
    """Whether the run ends at `state` (the goal, the agent dead, the step limit); the
    result says why."""
    if model.is_goal(state):
        result.reached_goal, result.status = True, "goal"
        result.message = f"goal reached in {step} steps"
    elif model.is_failure(state):
        result.status, result.message = "failure", "the agent is dead (bcc's rules)"
    elif step >= max_steps:
        result.status, result.message = "max_steps", f"stopped after {max_steps} steps"
    else:
        return False
    return True


def _replan(model: Model, result: RunResult, state, step: int, solver: str, budget: Budget, solver_options,
            max_replans: int, log) -> list | None:
    """A plan from `state` (recorded in the result), or None when the run ends: too many
    replans, or no plan."""
    if len(result.plans) > max_replans:
        result.status, result.message = "diverged", f"the world diverged {max_replans} times; giving up"
        return None
    res = solve_from(model, state, solver, budget, replanning=bool(result.plans), solver_options=solver_options)
    result.plans.append({"from_step": step, "plan": list(res.plan), "seconds": round(res.seconds, 3),
                         "solved": res.solved})
    if not res.solved:
        result.status, result.message = "no_plan", f"{solver}: {res.message or res.status}"
        return None
    log(f"{'plan' if len(result.plans) == 1 else 'replan'} ({solver}, {res.seconds:.2f} s): "
        f"{len(res.plan)} actions: {' '.join(res.plan)}")
    return list(res.plan)


def _refused(model: Model, world: WorldMap, result: RunResult, state, predicted, step: int, action: str):
    """The notes on a step the bot may take (where the real game differs from the model,
    differences.py), or None when it is refused (the result says why)."""
    if predicted is None:
        index = model.action_index(action)
        raise BccError(f"step {step + 1}: the plan's {action} does not apply: "
                       f"{model.why_not(index, state)} is false")
    if model.is_failure(predicted):
        # The server would let the bot walk into lava unharmed: the bridge enforces
        # bcc's rule by refusing the step instead.
        result.status = "refused"
        result.message = f"step {step + 1}: {action} would kill the agent in bcc's rules; not executed"
        return None
    notes = []
    if world.kind == "positions":
        notes, refusal = known_step(world, state, predicted)
        if refusal:
            result.status = "refused"
            result.message = f"step {step + 1}: {action}: {refusal}; not executed"
            return None
    return notes


def _log_step(model: Model, world: WorldMap, log, step: int, action: str, seconds: float, state, predicted,
              parsed, diffs: list, notes: list) -> None:
    """The step's lines in the run's log: predicted and observed, the blocks it changes, what differs."""
    log(f"{step:3d} {action:<14} {seconds * 1000:5.0f} ms  predicted {world.describe(predicted)}")
    log(f"    {'':<14} {'':>8}  observed  {world.describe(parsed.state)}"
        + ("  = match" if not diffs else "  DIVERGED"))
    g = model.grid
    for x, y, z, old, new in changed_cells(model, state, predicted):
        seen = g.value_names[g.cell(parsed.state, x, y, z)]
        log(f"        block ({x}, {y}, {z}): {g.value_names[old]} -> {g.value_names[new]}, observed {seen}")
    for d in diffs[:6]:
        log(f"        {d}")
    for n in (notes + parsed.notes)[:4]:
        log(f"        note: {n}")


def run_dungeon(model: Model, port: int, solver: str = "astar", budget: Budget | None = None,
                log: Callable[[str], None] = lambda line: None, log_path=None, watch: float = 0.0,
                picture=None, **options) -> RunResult:
    """Everything for `bcc minecraft run`: a bridge, the server, the bot, the closed loop.
    With `watch` > 0, first wait up to that many seconds for a person to join and watch
    (the bot then pauses between actions, and the world stays up a while at the end).
    With `picture` (a path), the world as the server reports it at the end is drawn there
    as an SVG (picture.py)."""
    from .bridge import VERSION
    from .record import wait_for_player
    check_playable(model)
    t0 = time.perf_counter()
    with Bridge(log_path=log_path) as bridge:
        log(f"starting the Minecraft server on 127.0.0.1:{port} and building {model.name} ...")
        prepare(bridge, WorldMap(model), port)
        setup = time.perf_counter() - t0
        log(f"server up, dungeon built, bot {BOT} at the start ({setup:.1f} s)")
        if watch > 0:
            log(f"to watch, join with a Minecraft {VERSION} client at 127.0.0.1:{port}; waiting up to {watch:g} s")
            try:
                log(f"{wait_for_player(bridge, None, watch)} is watching")
            except BccError:
                log("nobody joined; running anyway")
            options.setdefault("delay", 0.6)
        result = run(model, bridge, solver=solver, budget=budget, log=log, **options)
        result.setup_seconds = setup
        if picture:
            from ..atomic import write_text
            from .picture import svg
            world = WorldMap(model)
            write_text(picture, svg(bridge.observe(BOT), world.size, world.origin,
                                    title=f"{model.name}: {result.message}"))
            log(f"the world as the server reports it: {picture}")
        if watch > 0:
            time.sleep(min(10.0, watch))
    return result
