"""Learning curves: steps per episode of the learning solvers, over seeds, through the batch API.

`bcc learn-curve` and bench/learn_curves.py share this. Each (learner, seed) is one item of
`bcc.batch.map_runs` (issue 12: learning-curve runs go through the same batch API as
`bcc batch`), so runs go in parallel with `workers`, each in a process of its own under
hard limits, and the numbers do not depend on how many workers ran them: every learner
is seeded, and a run's outcome depends only on its item.
"""
from __future__ import annotations

import os
from dataclasses import dataclass

from .errors import BccError

# learner name -> (solver, options); the order is the default order of runs and legends
LEARNERS = {"rmax/tabular": ("rmax", {"learner": "tabular"}), "rmax/oo": ("rmax", {"learner": "oo"}),
            "qlearning": ("qlearning", {})}
SOLVER_LEARNERS = {"rmax": ["rmax/tabular", "rmax/oo"], "qlearning": ["qlearning"]}


@dataclass(frozen=True)
class CurveRun:
    """One learning run: small and picklable, so it travels to a Ray worker as well."""
    dungeon: str
    goal: str | None
    learner: str
    seed: int
    episodes: int
    optimal_cost: int | None
    max_memory_mb: float | None = None
    time_limit: float | None = None


_models: dict = {}   # (dungeon, goal) -> compiled model, per process


def _model(dungeon: str, goal: str | None):
    key = (dungeon, goal)
    if key not in _models:
        from .compiler import compile_dungeon
        _models[key] = compile_dungeon(dungeon, goal=goal)
    return _models[key]


def prepare(run: CurveRun) -> None:
    """Compile in the process that forks the run's child: every child inherits the model."""
    _model(run.dungeon, run.goal)
    from .solvers import get_solver
    get_solver(LEARNERS[run.learner][0])


def run_curve(run: CurveRun) -> dict:
    """The work of one item: learn for `episodes` episodes; the steps of each."""
    from .solvers import Budget, get_solver
    solver, options = LEARNERS[run.learner]
    result = get_solver(solver)(_model(run.dungeon, run.goal),
                                Budget(time_limit=run.time_limit, max_memory_mb=run.max_memory_mb),
                                episodes=run.episodes, seed=run.seed, optimal_cost=run.optimal_cost, **options)
    return {"steps": [e["steps"] for e in result.episodes], "success": [e["success"] for e in result.episodes],
            "converged_episode": result.converged_episode,
            "solved": result.solved, "status": result.status, "seconds": round(result.seconds, 3)}


def learners_from(learners: list[str] | None = None, solvers: list[str] | None = None) -> list[str]:
    """The learners asked for: names, plus every learner of each solver; default all."""
    out = []
    for name in list(learners or []) + [n for s in solvers or [] for n in _solver_learners(s)]:
        if name not in LEARNERS:
            raise BccError(f"unknown learner {name!r}; learners: {', '.join(LEARNERS)}")
        if name not in out:
            out.append(name)
    return out or list(LEARNERS)


def _solver_learners(solver: str) -> list[str]:
    if solver not in SOLVER_LEARNERS:
        raise BccError(f"learn-curve takes a learning solver: {' or '.join(SOLVER_LEARNERS)}; got {solver!r}")
    return SOLVER_LEARNERS[solver]


def learning_curves(dungeon: str, *, goal: str | None = None, learners: list[str] | None = None,
                    episodes: int = 10, seeds: list[int] = (0,), workers: int = 1, backend: str = "local",
                    address: str | None = None, time_limit: float | None = None, progress=None) -> dict:
    """Run every learner with every seed on `dungeon`; return the curves (the JSON of
    `bcc learn-curve`). Bad input raises BccError before anything runs. A run that fails
    (a hard limit, a crash) has null steps and its `errors` entry says why. `progress(run,
    outcome)`, if given, is called as each run finishes."""
    from .batch import Limits, map_runs
    from .solvers import Budget, optimal_cost as astar_cost
    learners = learners_from(learners)
    seeds = list(seeds)
    if episodes < 1 or not seeds:
        raise BccError("learn-curve needs at least one episode and one seed")
    model = _model(dungeon, goal)   # bad input fails here; the runs' children inherit it
    memory = Budget.default().max_memory_mb
    # the reference cost converged_episode compares with: A*, in this process
    optimal_cost = astar_cost(model, Budget(time_limit=time_limit or 60, max_memory_mb=memory))
    per_run = memory / max(workers, os.cpu_count() or 1)
    runs = [CurveRun(dungeon, goal, name, seed, episodes, optimal_cost, per_run, time_limit)
            for name in learners for seed in seeds]
    values: list = [None] * len(runs)
    errors: list = [None] * len(runs)
    walls: list = [None] * len(runs)   # the run's process, start to end (compiling is inherited)
    for outcome in map_runs(run_curve, runs, backend=backend, workers=workers, address=address,
                            limits=Limits.around(time_limit, per_run), prepare=prepare):
        walls[outcome.index] = round(outcome.seconds, 3)
        if progress is not None:
            progress(runs[outcome.index], outcome)
        if outcome.ok:
            values[outcome.index] = outcome.value
        else:
            errors[outcome.index] = outcome.error
    curves = {}
    for i, run in enumerate(runs):
        solver, options = LEARNERS[run.learner]
        c = curves.setdefault(run.learner, {"solver": solver, "options": dict(options), **{
            field: [] for field in ("steps", "success", "converged_episode", "solved", "status", "seconds", "wall_seconds",
                                    "errors")}})
        v = values[i] or {}
        c["steps"].append(v.get("steps"))
        c["success"].append(v.get("success"))
        c["converged_episode"].append(v.get("converged_episode"))
        c["solved"].append(v.get("solved"))
        c["status"].append(v.get("status", "error"))
        c["seconds"].append(v.get("seconds"))
        c["wall_seconds"].append(walls[i])
        c["errors"].append(errors[i])
    return {"dungeon": model.name, "goal": model.goal_text, "optimal_cost": optimal_cost, "episodes": episodes,
            "seeds": seeds, "workers": workers, "runs": curves}


def mean_curve(steps_per_seed: list) -> tuple[list, list, list]:
    """(mean, low, high) per episode over the seeds that reached that episode (a run
    stopped by its time limit has fewer episodes; a failed one has none)."""
    rows = [s for s in steps_per_seed if s]
    cols = [[r[e] for r in rows if e < len(r)] for e in range(max((len(r) for r in rows), default=0))]
    return [sum(c) / len(c) for c in cols], [min(c) for c in cols], [max(c) for c in cols]


def plot_curves(runs: dict, optimal, title: str, output: str) -> None:
    """Draw a PNG to `output`: mean steps per episode of each learner over its seeds,
    with the min-max band (needs the `plot` extra)."""
    import io
    from .extras import pyplot
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4))
    for name, run in runs.items():
        mean, low, high = mean_curve(run["steps"])
        if not mean:
            continue
        x = range(1, len(mean) + 1)
        n = sum(1 for s in run["steps"] if s)
        line, = ax.plot(x, mean, marker="o", markersize=3 if len(mean) <= 50 else 0,
                        label=f"{name} (mean of {n} seeds)" if n > 1 else name)
        if n > 1:
            ax.fill_between(x, low, high, color=line.get_color(), alpha=0.2, linewidth=0)
    if optimal is not None:
        ax.axhline(optimal, color="gray", linestyle="--", label=f"optimal ({optimal})")
    ax.set_xlabel("episode")
    ax.set_ylabel("steps (band: min to max over seeds)")
    ax.set_yscale("log")
    if max((len(mean_curve(run["steps"])[0]) for run in runs.values()), default=0) > 50:
        ax.set_xscale("log")  # hundreds of episodes: the first few, where most is learned, stay visible
    ax.set_title(title)
    ax.legend(fontsize="small")
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100)
    plt.close(fig)
    from .atomic import write_bytes
    write_bytes(output, buf.getvalue())
