"""`bcc batch` and `bcc batch report`: the shell side of the batch API (engine.py)."""
from __future__ import annotations

import sys

import click

from .shared import (emit_json, goal_option, json_option, max_memory_option, solver_flags, solver_request,
                          time_limit_option)
from ..exit_codes import EXIT_NO_SOLUTION, EXIT_OK
from ..errors import BccError


class BatchGroup(click.Group):
    """`bcc batch ARGS` runs a sweep (the `run` subcommand); `bcc batch report ...` reports."""

    def parse_args(self, ctx, args):
        if args and args[0] not in self.commands and args[0] not in ctx.help_option_names:
            args = ["run", *args]
        return super().parse_args(ctx, args)


@click.group("batch", cls=BatchGroup)
def batch_group():
    """Run sweeps of solves in parallel (a process pool or Ray) and report on them.

    \b
    Examples:
      bcc batch "maze:width=21,depth=21,stones=2,seed=1..200" --solver astar --out results.jsonl
      bcc batch --sweep sweep.yaml --workers 4 --out results.jsonl
      bcc batch --sweep sweep.yaml --backend ray --address auto --out results.jsonl
      bcc batch report results.jsonl --plot sizes.png

    `bcc batch ARGS` is short for `bcc batch run ARGS`; see `bcc batch run --help` for
    the options. Guide: docs/batch.md.
    """


@batch_group.command("run")
@click.argument("dungeons", nargs=-1, metavar="[DUNGEON]...")
@click.option("--sweep", "sweep_path", type=click.Path(dir_okay=False), help="A sweep file (YAML): dungeons, solvers, seeds, budgets.")
@click.option("--solver", "solvers", multiple=True, help="A solver (repeat for more) [default: the sweep's, else astar].")
@click.option("--seeds", type=click.IntRange(min=1), help="Seeds 0..N-1 for the seeded solvers (rmax, qlearning).")
@click.option("--backend", type=click.Choice(["local", "ray"]), default="local", show_default=True)
@click.option("--workers", type=click.IntRange(min=1), help="Runs at once [default: the CPUs (local) or the cluster's CPUs (ray)].")
@click.option("--address", help="ray: the cluster to join, `auto` or `ray://HOST:PORT` [default: start a local Ray].")
@time_limit_option("Per run.")
@click.option("--max-states", type=click.IntRange(min=1), help="Per run.")
@max_memory_option("Per run [default: half the RAM / CPUs].")
@goal_option
@click.option("--out", required=True, type=click.Path(dir_okay=False), help="The results file (JSON Lines); runs already in it are skipped.")
@json_option
@solver_flags
def run_cmd(dungeons, sweep_path, solvers, seeds, backend, workers, address, time_limit, max_states, max_memory,
            goal, out, as_json, **solver_options):
    """Solve every DUNGEON x solver x seed; append one JSON row per run to --out.

    A DUNGEON is a file, a shipped name, a glob ('mazes/*.yaml') or a generator spec
    ('maze:width=21,depth=21,stones=2,seed=1..200'). Rerunning the same command skips the
    runs already in --out. Exit 0 when every run has its row (solved or not)."""
    from ..batch.dungeons import expand_dungeons
    from ..batch.engine import run_batch
    from ..batch.progress import ProgressBar
    from ..batch.runs import build_runs, check_limits
    from ..batch.sweep import Sweep, expand_setting, load_sweep, seeds_from
    sweep = load_sweep(sweep_path) if sweep_path else Sweep()
    names = list(dict.fromkeys(sweep.dungeons + expand_dungeons(dungeons)))
    if not names:
        raise BccError("no dungeons: give DUNGEON arguments or a --sweep file with `dungeons`")
    settings = [s for name in solvers for s in expand_setting(name, {})] if solvers else sweep.settings
    settings = settings or expand_setting("astar", {})
    # the command line's solver options, checked for each solver, over the sweep's own
    settings = [(solver, {**options, **solver_request(solver, dict(solver_options))}, limits)
                for solver, options, limits in settings]
    budget = dict(sweep.budget)
    budget.update(check_limits({"time_limit": time_limit, "max_states": max_states, "max_memory": max_memory}))
    settings = [(solver, options, {**budget, **limits}) for solver, options, limits in settings]
    seed_list = seeds_from(seeds) if seeds else (sweep.seeds or [0])
    runs = build_runs(names, settings, seed_list, goal or sweep.goal)
    bar = ProgressBar(len(runs)) if sys.stderr.isatty() else None
    summary = run_batch(runs, out=out, backend=backend, workers=workers, address=address, progress=bar)
    if summary["torn_bytes_dropped"]:
        click.echo(f"{out}: dropped a torn last line ({summary['torn_bytes_dropped']} bytes) "
                   "left by an interrupted write", err=True)
    if summary["ignored_lines"]:
        click.echo(f"{out}: ignored lines that are not rows: {', '.join(map(str, summary['ignored_lines']))}", err=True)
    if as_json:
        emit_json(summary)
    else:
        click.echo(f"{summary['runs']} runs ({summary['skipped']} already in {out}, {summary['ran']} run now, "
                   f"{summary['seconds']:.1f} s): {summary['solved']} solved, {summary['budget_exhausted']} "
                   f"budget exhausted, {summary['no_solution']} without solution, {summary['errors']} errors")
    sys.exit(EXIT_OK)


@batch_group.command("report")
@click.argument("results", type=click.Path(dir_okay=False))
@click.option("--plot", "plot_path", type=click.Path(dir_okay=False), help="Draw cost and time against size to a PNG (needs matplotlib).")
@json_option
def report_cmd(results, plot_path, as_json):
    """Summarise RESULTS per solver: solved, median/max time, expansions."""
    import os
    from ..batch.report import plot, summarise, table
    from ..batch.store import read_rows
    if not os.path.exists(results):
        raise BccError("no such results file", results)
    contents = read_rows(results)
    contents.check_is_results(results)
    if contents.bad_lines:
        click.echo(f"{results}: ignored lines that are not rows: {', '.join(map(str, contents.bad_lines))}", err=True)
    if contents.torn_tail:
        click.echo(f"{results}: ignored a torn last line ({contents.torn_tail} bytes)", err=True)
    if not contents.rows:  # nothing to summarise (or plot): say so, and exit 1 as for no result
        if as_json:
            emit_json({"results": results, "rows": 0, "solvers": [], "plot": None, "plotted_points": None})
        click.echo(f"{results}: no runs recorded yet", err=True)
        sys.exit(EXIT_NO_SOLUTION)
    summary = summarise(contents.rows)
    points = plot(contents.rows, plot_path) if plot_path else None
    if as_json:
        emit_json({"results": results, "rows": len(contents.rows), "solvers": summary, "plot": plot_path,
                   "plotted_points": points})
        return
    click.echo(table(summary))
    if plot_path:
        click.echo(f"wrote {plot_path} ({points} solved runs)")


COMMANDS = [batch_group]
