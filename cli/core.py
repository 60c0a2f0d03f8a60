"""The `bcc` group and its core commands (compile, solve, validate, show, list, solvers,
generate, learn-curve); the feature commands are loaded from this package's other modules
when asked for.

Exit codes: 0 success, 1 no solution / budget exhausted / plan invalid, 2 bad input.
Results and JSON go to stdout; errors, warnings and progress to stderr.
"""
from __future__ import annotations

import json
import os
import sys

import click

# numpy's BLAS starts a thread per core even for the grounding model's small matrices; on
# a busy machine they spin against each other and `bcc train` on the cleanup corpus took
# 4x the wall time and CPU (138 s / 52 s CPU against 35 s / 12 s, load 8, 2 cores).
# bcc's numpy work is small: one thread, unless the user chose otherwise. Set before any
# command imports numpy.
for _blas_threads in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_blas_threads, "1")

from ..errors import BccError, ModelError

from .shared import (budget_options, clear_progress, compile_model, emit_json, goal_option, json_option, max_memory_option,
                         print_result, progress_enabled, solver_flags, solver_given, task_option, time_limit_option,
                         within_budget, write_output)
from ..exit_codes import EXIT_BAD_INPUT, EXIT_INTERNAL, EXIT_INTERRUPTED, EXIT_NO_SOLUTION, EXIT_OK


class BccGroup(click.Group):
    """Prints a BccError once, as `file:line:col: message`, and exits 2. The feature
    commands' modules are imported when a command not yet known is asked for (or all of
    them are listed): `bcc import pddl` need not import the Minecraft, batch, serve and
    grounding commands (about 8 ms of a 0.12 s run)."""

    def get_command(self, ctx, cmd_name):
        while cmd_name not in self.commands and _load_feature_commands():
            pass
        return super().get_command(ctx, cmd_name)

    def list_commands(self, ctx):
        while _load_feature_commands():
            pass
        return super().list_commands(ctx)

    def invoke(self, ctx):
        try:
            return super().invoke(ctx)
        except BccError as exc:
            click.echo(str(exc), err=True)
            ctx.exit(EXIT_BAD_INPUT)
        except ModelError as exc:
            click.echo(f"domain error: {exc}", err=True)
            ctx.exit(EXIT_BAD_INPUT)
        except KeyboardInterrupt:
            click.echo("interrupted", err=True)
            ctx.exit(EXIT_INTERRUPTED)
        except BrokenPipeError:  # `bcc solve ... | head -1`: the reader left; not an error of ours
            sys.stdout = None
            os._exit(0)
        except (click.exceptions.Exit, click.ClickException, click.Abort):
            raise
        except Exception as exc:  # noqa: BLE001 - a bug in bcc: one line, unless debugging
            if os.environ.get("BCC_DEBUG"):
                raise
            click.echo(f"bcc: internal error: {type(exc).__name__}: {exc} (set BCC_DEBUG=1 for a traceback)", err=True)
            ctx.exit(EXIT_INTERNAL)


@click.group(cls=BccGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="bcc", prog_name="bcc")
def main():
    """bcc compiles declarative YAML dungeons into an OO-MDP and solves them.

    \b
    Examples:
      bcc solve bridge                  # solve a shipped dungeon with A*
      bcc solve my.yaml --solver bfs --json
      bcc validate bridge plan.txt
      bcc show bridge --plan plan.txt
    """


@main.command("compile")
@click.argument("dungeon")
@json_option
@click.option("-o", "--output", type=click.Path(dir_okay=False, writable=True), help="Also write the compiled model as JSON (format bcc-model/2, the report included) to FILE, atomically.")
@click.option("--emit-python", type=click.Path(dir_okay=False, writable=True), help="Write the generated successor code to FILE.")
@goal_option
@task_option
@budget_options
def compile_cmd(dungeon, as_json, output, emit_python, goal, task, time_limit, max_memory):
    """Parse, type-check and compile DUNGEON (a file or a shipped name); report the model."""
    with within_budget(time_limit, max_memory, as_json, dungeon):
        model = compile_model(dungeon, goal, task)
        report = model.compile_report()
    if output:
        from ..model_json import model_json
        write_output(output, json.dumps(model_json(model), indent=2) + "\n")
    if emit_python:
        write_output(emit_python, model.source)
    if as_json:
        emit_json(report)
        return
    r = report
    click.echo(f"dungeon {r['dungeon']} (domain {r['domain']}): "
               f"{r['size']['width']} wide x {r['size']['depth']} deep x {r['size']['height']} high")
    click.echo("classes:")
    for c, info in r["classes"].items():
        key = f" key[{', '.join(info['key'])}]" if info["key"] else ""
        attrs = ", ".join(f"{a}: {t}" for a, t in info["attributes"].items())
        objs = r["objects"][c]
        objs = ", ".join(objs) if isinstance(objs, list) else objs
        click.echo(f"  {c}{key} ({attrs}) -- objects: {objs or 'none'}")
    click.echo("propositional functions: " + ", ".join(f"{f}({', '.join(p)})" for f, p in r["functions"].items()))
    click.echo("action schemas: " + ", ".join(f"{a}({', '.join(p)})" for a, p in r["action_schemas"].items()))
    click.echo(f"grounded actions: {r['grounded_actions']}")
    click.echo(f"state variables: {r['state_variables']} (+ {r['mutable_cells']} mutable cells in layers "
               f"{r['mutable_layers']})")
    b = r["state_bytes"]
    click.echo(f"bytes per state: {b['start']} at the start + {b['per_changed_cell']} per changed cell; "
               f"typical {b['typical']}, largest {b['largest']} over the first {b['sampled']:,} states; "
               f"worst {b['worst']:,} (every mutable cell changed)")
    click.echo(f"goal: {r['goal']}")
    if r.get("tasks") is not None:
        click.echo(f"tasks: {len(r['tasks'])}, methods: {len(r['methods'])}; task: "
                   f"{'; '.join(r['task']) if r.get('task') else 'none'}")


@main.command("solve")
@click.argument("dungeon")
@click.option("--solver", default=None, help="Solver name (see `bcc solvers`) [default: htn for a task, build for "
              "a structure goal, else astar].")
@json_option
@click.option("--max-states", type=click.IntRange(min=1), help="Stop after storing this many states.")
@time_limit_option()
@max_memory_option()
@click.option("-o", "--output", type=click.Path(dir_okay=False, writable=True), help="Write the plan to FILE, one action a line (atomically).")
@solver_flags
@goal_option
@task_option
def solve_cmd(dungeon, solver, as_json, max_states, time_limit, max_memory, output, goal, task, **solver_options):
    """Solve DUNGEON: the plan on stdout (one action a line), the summary on stderr.
    Exit 0 solved, 1 no plan or a budget ran out. Options that a solver does not take
    are refused; `bcc solvers` lists each solver's."""
    from ..run import Request, run
    from ..solvers import Budget
    given, spell = solver_given(solver_options)

    def load():
        model = compile_model(dungeon, goal, task)
        if output:
            from ..atomic import check_writable
            check_writable(output)   # before a long solve, not after it
        return model

    progress = progress_enabled()
    pick = solver is None and all(v is None for v in given.values())   # bcc solve's default: by the goal
    ran = run(Request(load, solver or "astar", given, Budget(max_states, time_limit, max_memory), progress, spell=spell,
                      pick=pick))
    clear_progress(progress)
    result, model = ran.result, ran.model
    if output and result.solved:
        write_output(output, "".join(a + "\n" for a in result.plan))
    name, path, goal_text = (dungeon, dungeon, goal) if model is None else (model.name, model.path, model.goal_text)
    sys.exit(print_result(result, name, path, as_json, {"dungeon": name, "goal": goal_text}))


def _read_plan_arg(plan: str):
    from ..simulate import read_plan
    if plan == "-":
        return read_plan(sys.stdin.read(), "<stdin>"), "<stdin>"
    from ..errors import read_input
    return read_plan(read_input(plan, "plan"), plan), plan


@main.command("validate")
@click.argument("dungeon")
@click.argument("plan")
@json_option
@goal_option
@task_option
@budget_options
def validate_cmd(dungeon, plan, as_json, goal, task, time_limit, max_memory):
    """Replay PLAN (a file, one action a line, or - for stdin) in DUNGEON.

    Exit 0 when it reaches the goal, 1 when it does not (saying at which step and why).
    In a dungeon with a task every step is run and the goal checked after the last."""
    from ..simulate import replay
    with within_budget(time_limit, max_memory, as_json, dungeon):
        model = compile_model(dungeon, goal, task)
        actions, path = _read_plan_arg(plan)
        result = replay(model, actions, path)
    if as_json:
        emit_json({"dungeon": model.name, "goal": model.goal_text, **result.to_json()})
    else:
        click.echo(("valid: " if result.valid else "invalid: ") + result.message)
    sys.exit(EXIT_OK if result.valid else EXIT_NO_SOLUTION)


@main.command("show")
@click.argument("dungeon")
@click.option("--plan", "plan", help="Replay this plan (file or -) and draw the agent's path and where it ends.")
@click.option("--view", type=click.Choice(["auto", "top", "layers"]), default="auto", show_default=True,
              help="top: from above, one character a column; layers: each level y of a 3D world, with a "
                   "structure goal's progress; auto: layers when the goal has cell atoms or the agent "
                   "changes level.")
@click.option("--layer", "only", type=int, multiple=True, help="Draw only this level y (repeatable; with layers).")
@json_option
@goal_option
@budget_options
def show_cmd(dungeon, plan, view, only, as_json, goal, time_limit, max_memory):
    """Draw DUNGEON from above (rows are z, columns x) or layer by layer, optionally with a
    plan's path and the state it ends in."""
    from ..render import draws_layers, layer_view, render, render_layers
    from ..simulate import replay
    with within_budget(time_limit, max_memory, as_json, dungeon):
        model = compile_model(dungeon, goal)
        bad = [y for y in only if not 0 <= y < model.grid.height]
        if bad:
            raise click.BadParameter(f"level {bad[0]} is outside the world (y = 0 .. {model.grid.height - 1})",
                                     param_hint="--layer")
        state, path, note = model.initial, None, None
        if plan:
            actions, ppath = _read_plan_arg(plan)
            result = replay(model, actions, ppath)
            path = [model.agent_position(s) for s in result.states]
            state = result.states[-1]
            note = ("valid: " if result.valid else "invalid: ") + result.message
        picture = render(model, state, path)
        layered = view == "layers" or view == "auto" and (draws_layers(model) or bool(only))
        layers = layer_view(model, state, path, list(only)) if layered else None
    if as_json:
        out = {"dungeon": model.name, "goal": model.goal_text, "view": "layers" if layered else "top",
               "rows": picture.splitlines(), "agent": list(model.agent_position(state)),
               "path": [list(p) for p in path or []], "plan_note": note}
        if layers is not None:
            out.update(layers)
        emit_json(out)
        return
    click.echo(f"{model.name}: goal {model.goal_text}")
    click.echo(render_layers(layers) if layered else picture)
    if note:
        click.echo(note)


@main.command("list")
@json_option
def list_cmd(as_json):
    """List the shipped dungeons and domains."""
    from ..compiler.domain import DOMAINS_DIR
    from ..compiler.dungeon import DUNGEONS_DIR, shipped_dungeons
    from ..compiler.source import load_yaml
    from ..compiler.structure import listed_goal
    dungeons = []
    for name in shipped_dungeons():
        data = load_yaml(DUNGEONS_DIR / f"{name}.yaml")
        task = data.get("task")
        dungeons.append({"name": name, "goal": listed_goal(data.get("goal")), "extends": data.get("extends"),
                         "task": "; ".join(map(str, task)) if isinstance(task, list) else task,
                         "description": " ".join(str(data.get("description", "")).split())})
    domains = sorted(p.stem for p in DOMAINS_DIR.glob("*.yaml"))
    if as_json:
        emit_json({"dungeons": dungeons, "domains": domains})
        return
    click.echo("dungeons:")
    for d in dungeons:
        click.echo(f"  {d['name']:<18} {d['goal'] or ('task: ' + d['task'] if d['task'] else '(inherits its goal)')}")
    click.echo("domains:")
    for d in domains:
        click.echo(f"  {d}")


@main.command("solvers")
@json_option
def solvers_cmd(as_json):
    """List the solvers (built-in and plugins), each with its options, and say which
    cannot run here and how to get them."""
    from ..solvers import describe_solvers
    solvers = describe_solvers()
    if as_json:
        emit_json({"solvers": solvers})
        return
    width = max(map(len, solvers))
    for name, info in solvers.items():
        click.echo(f"  {name:<{width}} {info['description']}")
        if info["unavailable"]:
            click.echo(f"  {'':<{width}} unavailable: {info['unavailable']}")
        for o in info["options"]:
            click.echo(f"  {'':<{width}}   --{o['name'].replace('_', '-')}: {o['help']}; {o['accepts']} "
                       f"[default: {o['default']}]")


@main.group("generate")
def generate_group():
    """Generate dungeons."""


@generate_group.command("maze")
@click.option("--width", type=int, default=15, show_default=True, help="Columns (odd, >= 5).")
@click.option("--depth", type=int, default=15, show_default=True, help="Rows (odd, >= 5).")
@click.option("--stones", type=int, default=0, show_default=True, help="Mineable stones on corridors.")
@click.option("--lava", type=int, default=0, show_default=True, help="Lava rivers (each comes with a stone to bridge it).")
@click.option("--loops", type=float, default=0.0, show_default=True, help="Fraction of inner walls knocked out (0..1).")
@click.option("--seed", type=int, default=0, show_default=True)
@click.option("--name", default=None, help="Dungeon name [default: from the parameters].")
@click.option("-o", "--output", type=click.Path(dir_okay=False, writable=True), help="Write to FILE (atomically) instead of stdout.")
@json_option
def generate_maze_cmd(width, depth, stones, lava, loops, seed, name, output, as_json):
    """A perfect maze (plus optional loops, stones and lava rivers), solvable by construction."""
    from ..generate import generate_maze
    text = generate_maze(width, depth, stones=stones, lava=lava, loops=loops, seed=seed, name=name)
    _generated(text, output, as_json, {"width": width, "depth": depth, "stones": stones, "lava": lava,
                                       "loops": loops, "seed": seed})


def _generated(text: str, output, as_json: bool, info: dict) -> None:
    """A generated dungeon: to FILE (atomically) or stdout; with --json, `info` and the
    output's path, or the YAML itself when it went to no file."""
    if output:
        write_output(output, text)
    if as_json:
        emit_json({"output": output, **info, "yaml": None if output else text})
    elif not output:
        click.echo(text, nl=False)


@generate_group.command("rooms")
@click.option("--stones", type=int, default=4, show_default=True, help="Stones to carry into the blue room (1..8).")
@click.option("--name", default=None, help="Dungeon name [default: manipulation_STONES].")
@click.option("-o", "--output", type=click.Path(dir_okay=False, writable=True), help="Write to FILE (atomically) instead of stdout.")
@json_option
def generate_rooms_cmd(stones, name, output, as_json):
    """Three rooms in a row; carry every stone into the blue room (a manipulation task)."""
    from ..generate_rooms import generate_manipulation
    text = generate_manipulation(stones, name=name)
    _generated(text, output, as_json, {"stones": stones})


def _structure_command(kind: str, summary: str):
    @generate_group.command(kind, help=summary)
    @click.option("--width", type=int, default=5, show_default=True, help="Cells along x.")
    @click.option("--length", type=int, default=5, show_default=True, help="Cells along z.")
    @click.option("--height", type=int, default=5, show_default=True, help="Cells along y (a house's walls; the roof is on top).")
    @click.option("--material", default="planks", show_default=True, help="The block the structure is made of (a mason material).")
    @click.option("--name", default=None, help="Dungeon name [default: KIND_WxLxH].")
    @click.option("-o", "--output", type=click.Path(dir_okay=False, writable=True), help="Write to FILE (atomically) instead of stdout.")
    @click.option("--as-task", is_flag=True, help="Also give the structure as one task (domain mason_tasks; "
                  "houses only): bcc solve then plans it with htn.")
    @json_option
    def command(width, length, height, material, name, output, as_task, as_json):
        from ..generate_structures import generate_structure
        text = generate_structure(kind, width, length, height, material=material, name=name, as_task=as_task)
        _generated(text, output, as_json, {"kind": kind, "width": width, "length": length, "height": height,
                                           "material": material, "as_task": as_task})
    return command


for _kind, _summary in (
        ("house", "A house (four walls, a door opening, a roof) to build on a flat world (the mason domain)."),
        ("wall", "A wall to build on a flat world (the mason domain)."),
        ("tower", "A hollow tower to build on a flat world (the mason domain)."),
        ("bridge", "A deck on four corner posts, air under it, to build on a flat world (the mason domain).")):
    _structure_command(_kind, _summary)


@main.command("learn-curve")
@click.argument("dungeon")
@click.option("--learner", "learners", multiple=True, type=click.Choice(["rmax/tabular", "rmax/oo", "qlearning"]),
              help="A learner to run (repeat for more) [default: rmax/tabular, rmax/oo and qlearning].")
@click.option("--solver", "solvers", multiple=True, type=click.Choice(["rmax", "qlearning"]),
              help="Every learner of a learning solver (rmax: tabular and oo); repeatable, adds to --learner.")
@click.option("--episodes", type=click.IntRange(min=1), default=10, show_default=True)
@click.option("--seeds", "n_seeds", type=click.IntRange(min=1), default=1, show_default=True,
              help="Run each learner with this many seeds: --seed, --seed + 1, ...")
@click.option("--seed", type=int, default=0, show_default=True, help="The first seed.")
@click.option("--workers", type=click.IntRange(min=1), default=1, show_default=True,
              help="Runs at once (each a process of its own, through the batch API).")
@time_limit_option("Stop each run after this many seconds.")
@click.option("-o", "--output", type=click.Path(dir_okay=False, writable=True), help="Write a PNG plot (needs the `plot` extra).")
@json_option
@goal_option
def learn_curve_cmd(dungeon, learners, solvers, episodes, n_seeds, seed, workers, time_limit, output, as_json, goal):
    """Steps per episode of the learning solvers on DUNGEON: R-max with each model
    learner and Q-learning, each with --seeds seeds. Exit 1 if a run failed or ran out of time."""
    from ..learning_curves import learners_from, learning_curves, mean_curve, plot_curves
    names = learners_from(learners, solvers)
    if output:
        from ..extras import pyplot
        pyplot()  # a missing matplotlib is an error before anything runs
    data = learning_curves(dungeon, goal=goal, learners=names, episodes=episodes,
                           seeds=list(range(seed, seed + n_seeds)), workers=workers, time_limit=time_limit)
    if output:
        plot_curves(data["runs"], data["optimal_cost"], f"{data['dungeon']}: steps per episode", output)
    stopped = [(name, s, error or f"stopped by its time limit after {len(steps)} of {episodes} episodes")
               for name, run in data["runs"].items()
               for s, error, status, steps in zip(data["seeds"], run["errors"], run["status"], run["steps"])
               if error or status == "budget"]
    if as_json:
        emit_json(data)
    else:
        click.echo(f"{data['dungeon']}: optimal cost {data['optimal_cost']}, {episodes} episodes, "
                   f"seeds {', '.join(map(str, data['seeds']))}")
        for name, run in data["runs"].items():
            mean = mean_curve(run["steps"])[0]
            converged = ", ".join("-" if c is None else str(c) for c in run["converged_episode"])
            click.echo(f"  {name:<14} converged at episode {converged}; mean steps "
                       f"{' '.join(f'{m:g}' for m in (round(m, 1) for m in mean))}")
    for name, s, why in stopped:
        click.echo(f"{data['dungeon']}: {name} seed {s}: {why}", err=True)
    sys.exit(EXIT_NO_SOLUTION if stopped else EXIT_OK)


# The feature commands, one module each in this package (cli/pddl.py for pddl_io/, ...);
# each exposes `COMMANDS`, a list of click commands, and imports its heavy dependencies lazily.
FEATURE_MODULES = ["pddl", "grounding", "serve", "batch", "minecraft"]


def _load_feature_commands() -> bool:
    """Add the next feature module's commands to `main`; False when all are added."""
    if not FEATURE_MODULES:
        return False
    import importlib
    module = importlib.import_module(f".{FEATURE_MODULES.pop(0)}", __package__)
    for command in module.COMMANDS:
        main.add_command(command)
    return True
