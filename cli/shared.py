"""What the `bcc` commands (core.py and the feature modules beside it) share: the common
click options, JSON output, compiling a dungeon argument, progress, and printing a
solver's `Result`.
"""
from __future__ import annotations

import contextlib
import json
import sys
from typing import Callable

import click

from ..exit_codes import EXIT_NO_SOLUTION, EXIT_OK

def time_limit_option(help: str = "Stop after this many seconds.", **kwargs):
    return click.option("--time-limit", type=click.FloatRange(min=0, min_open=True), metavar="SECONDS", help=help,
                        **kwargs)


def max_memory_option(help: str = "Stop when the process uses this much memory [default: half the RAM].", **kwargs):
    return click.option("--max-memory", type=click.FloatRange(min=1), metavar="MB", help=help, **kwargs)


def budget_options(command):
    """--time-limit and --max-memory for a command that is not a search: with
    `within_budget`, they bound everything the command does."""
    return time_limit_option()(max_memory_option()(command))


@contextlib.contextmanager
def within_budget(time_limit: float | None, max_memory: float | None, as_json: bool, where: str,
                  grace: float | None = 0.0):
    """Run a command's work under --time-limit and --max-memory (default: half the RAM);
    yields the Budget. A budget that runs out ends the command the way a solve's does: one
    line `where: stopped: ... ran out` on stderr (with --json also one object on stdout,
    status "budget"), exit 1. Files are written atomically, so none is left half written.
    `grace` (None: hard_limits' own) lets a search inside stop itself first, with its result."""
    from ..solvers import Budget
    from ..solvers.base import BUDGET_WORDS
    from ..solvers.limits import BudgetExceeded, hard_limits
    budget = Budget(time_limit=time_limit,
                    max_memory_mb=max_memory if max_memory is not None else Budget.default().max_memory_mb)
    try:
        with hard_limits(budget, grace=grace):   # by default nothing inside checks the budget: stop at the limit
            yield budget
    except BudgetExceeded as exc:
        message = f"stopped: {BUDGET_WORDS[exc.which]} ran out"
        if as_json:
            emit_json({"status": "budget", "budget": exc.which, "message": message})
        click.echo(f"{where}: {message}", err=True)
        sys.exit(EXIT_NO_SOLUTION)


goal_option = click.option("--goal", metavar="EXPR", help="Use this goal instead of the dungeon's, e.g. 'agentInRoom(agent, red)', or a "
                           "blueprint file (FILE.yaml holding `structure:`).")
json_option = click.option("--json", "as_json", is_flag=True, help="Print one JSON object on stdout.")
task_option = click.option("--task", metavar="CALL", help="Do this task of the domain instead of the dungeon's "
                           "`task:`, e.g. 'house(2, 2, 5, 5, 4, planks)' (bcc solve then picks htn).")


def emit_json(data) -> None:
    click.echo(json.dumps(data, indent=2, default=str))


def compile_model(dungeon: str, goal: str | None, task: str | None = None):
    """Compile what the user named; its warnings (e.g. an unused legend character) go to
    stderr, one `file:line:col: warning: ...` line each."""
    from ..compiler import compile_dungeon
    model = compile_dungeon(dungeon, goal=goal, task=task)
    for warning in model.report.get("warnings", ()):
        click.echo(warning, err=True)
    return model


def write_output(path: str, text: str) -> None:
    from ..atomic import write_text
    write_text(path, text)


def progress_enabled():
    """A progress callback drawing one line on a terminal's stderr, or None off a terminal."""
    if not sys.stderr.isatty():
        return None

    def report(expanded, generated, stored, seconds):
        click.echo(f"\r  {seconds:7.1f}s  expanded {expanded:>12,}  stored {stored:>12,}", err=True, nl=False)
    return report


def clear_progress(progress) -> None:
    if progress:
        click.echo("\r" + " " * 60 + "\r", err=True, nl=False)


def print_result(result, name: str, where: str, as_json: bool, extra: dict | None = None,
                 details: str = "") -> int:
    """Print a solver's Result the one way every command does: with --json one object on
    stdout; else the plan on stdout (action names, one a line, so `> plan.txt` makes a
    file `bcc validate` reads) and the summary, or why there is no plan, on stderr as
    `where: message`. Returns the exit code."""
    if as_json:
        emit_json({**(extra or {}), **result.to_json()})
        if not result.solved:
            click.echo(f"{where}: not solved: {result.message}", err=True)
    elif result.solved:
        steps = f"{len(result.plan)} step" + ("" if len(result.plan) == 1 else "s")
        click.echo(f"solved {name} with {result.solver}: cost {result.cost}, {steps}, "
                   f"{result.expanded:,} expanded, {result.seconds:.3f} s{details}", err=True)
        for a in result.plan:
            click.echo(a)
    else:
        click.echo(f"{where}: not solved: {result.message} ({result.expanded:,} expanded, "
                   f"{result.seconds:.3f} s)", err=True)
    return EXIT_OK if result.solved else EXIT_NO_SOLUTION


# The solver options with a flag of their own on the command line (`--known-after`); the
# values are text, checked by the chosen solver's declaration (solvers/options.py).
# tests/test_solver_contract.py holds this list to the built-in solvers' declarations.
SOLVER_FLAGS = ("heuristic", "weight", "preferred", "evaluation", "model", "episodes", "seed", "gamma", "alpha", "epsilon",
                "delta", "known_after", "max_steps", "fd_search", "local_limit", "improve")


def flag(name: str) -> str:
    """A solver option's command-line spelling: `known_after` -> `--known-after`."""
    return "--" + name.replace("_", "-")


class SolverFlag(click.Option):
    """A solver option's flag; its help is read from the solvers' declarations only when
    --help is shown (loading every solver costs start-up time)."""

    def get_help_record(self, ctx):
        if not self.help:
            self.help = _flag_help(self.name.removeprefix("opt_"))
        return super().get_help_record(ctx)


def _flag_help(name: str) -> str:
    from ..solvers import get_solver, list_solvers
    from ..solvers.options import options_of
    uses = []
    for solver in list_solvers():
        try:
            option = next((o for o in options_of(get_solver(solver)) if o.name == name), None)
        except Exception:  # noqa: BLE001 - a broken plugin must not break --help
            continue
        if option is not None:
            uses.append((solver, option))
    if not uses:
        return "(no installed solver takes it)"
    first = uses[0][1]
    defaults = ", ".join(f"{s} {o.default}" for s, o in uses)
    what = (first.what() if len({o.what() for _, o in uses}) == 1
            else "; ".join(f"{s}: {o.what()}" for s, o in uses))
    return f"{', '.join(s for s, _ in uses)}: {first.help}; {what} [default: {defaults}]"


def solver_flags(command=None, *, skip: tuple = ()):
    """The SOLVER_FLAGS and `-O NAME=VALUE` (any declared option, e.g. a plugin's) on a
    command; it receives them as `opt_NAME` and `extra_options`. See `solver_request`.
    `skip` leaves out flags a command already has in another sense (`bcc minecraft run`'s
    --max-steps counts actions in the world); those options stay reachable with -O."""
    if command is None:
        return lambda c: solver_flags(c, skip=skip)
    for name in reversed([n for n in SOLVER_FLAGS if n not in skip]):
        command = click.option(flag(name), "opt_" + name, cls=SolverFlag, default=None,
                               metavar=name.upper().replace("_", "-") if name != "fd_search" else "CONFIG")(command)
    return click.option("-O", "--option", "extra_options", multiple=True, metavar="NAME=VALUE",
                        help="Any option the solver declares (see `bcc solvers`), e.g. -O weight=1.5.")(command)


def solver_request(solver: str, kwargs: dict) -> dict:
    """The checked keyword options for `solver` from a command's `opt_*` and
    `extra_options` parameters (popped from `kwargs`)."""
    from ..solvers.options import check_options
    return check_options(solver, *solver_given(kwargs))


def solver_given(kwargs: dict) -> tuple[dict, Callable[[str], str]]:
    """(option name -> value as typed, how the command line spells each name) from a
    command's `opt_*` and `extra_options` parameters (popped from `kwargs`): what a
    `bcc.run.Request` takes, checked by the run."""
    from ..errors import BccError
    given = {name[4:]: kwargs.pop(name) for name in list(kwargs) if name.startswith("opt_")}
    spelled = {name: flag(name) for name in given}
    for item in kwargs.pop("extra_options", ()):
        name, eq, value = item.partition("=")
        name = name.strip().replace("-", "_")
        if not eq or not name:
            raise BccError(f"-O {item}: write NAME=VALUE, e.g. -O weight=1.5")
        if given.get(name) is not None:
            raise BccError(f"-O {name}: given twice")
        given[name], spelled[name] = value, f"-O {name}"
    return given, lambda name: spelled.get(name, flag(name))
