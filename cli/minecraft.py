"""`bcc minecraft setup|serve|run|record`: bcc against a real Minecraft server.

Everything Minecraft (Node, the server, the bot) is imported lazily, so `bcc --help`
stays fast and works where Node is not installed.
"""
from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

import click

from .shared import (compile_model, emit_json, goal_option, json_option, solver_flags, solver_request,
                          time_limit_option)
from ..exit_codes import EXIT_NO_SOLUTION, EXIT_OK
from ..errors import BccError

db_option = click.option("--db", type=click.Path(dir_okay=False), default=None,
                         help="The grounding dataset to add demonstrations to (default: `bcc learn`'s).")
port_option = click.option("--port", type=click.IntRange(1, 65535), default=25565, show_default=True,
                           help="Port of the local server (it listens on 127.0.0.1 only).")


def _log_path(port: int) -> Path:
    return Path(tempfile.gettempdir()) / f"bcc-minecraft-{port}.log"


@click.group("minecraft")
def minecraft():
    """Play dungeons in a real Minecraft world: a local server, a bot, recorded play.

    \b
    Examples:
      bcc minecraft setup                    # install the server and bot (npm ci)
      bcc minecraft run bridge               # the bot solves the bridge in the game
      bcc minecraft serve bridge             # join with a Minecraft 1.16.5 client
      bcc minecraft record bridge "go to the gold block"
    """


@minecraft.command("setup")
@json_option
def setup_cmd(as_json):
    """Install the Node packages (flying-squid server, mineflayer bot) with `npm ci`."""
    from ..minecraft.install import install
    info = install(echo=None if as_json else lambda line: click.echo(line, err=True))
    if as_json:
        emit_json(info)
        return
    click.echo(f"installed {', '.join(f'{k} {v}' for k, v in info['packages'].items())} "
               f"in {info['directory']} (Node {info['node']}, Minecraft {info['minecraft']})")


@minecraft.command("serve")
@click.argument("dungeon")
@port_option
@goal_option
@click.option("--out", "out_dir", type=click.Path(file_okay=False), default=".", show_default=True,
              help="Directory for the demonstrations recorded with the in-game 'learn' command.")
@click.option("--duration", type=click.FloatRange(min=0, min_open=True), default=None, metavar="SECONDS",
              help="Stop after this many seconds (default: until Ctrl-C).")
@db_option
@json_option
def serve_cmd(dungeon, port, goal, out_dir, duration, db, as_json):
    """Start a server on 127.0.0.1 with DUNGEON built block by block, for a person to play.

    Join with a Minecraft 1.16.5 client (Multiplayer, Direct Connection, 127.0.0.1:PORT; the
    server is in offline mode, any name works). In the chat, 'learn <command>' stores what you
    did since the start as a demonstration of <command>; 'reset' puts you back at the start.
    """
    from ..minecraft.bridge import VERSION, Bridge
    from ..minecraft.record import host
    from ..minecraft.world import WorldMap, check_supported
    model = compile_model(dungeon, goal)
    check_supported(model)
    log_path = _log_path(port)
    say = (lambda line: click.echo(line, err=True)) if as_json else click.echo
    written: list = []
    with Bridge(log_path=log_path) as bridge:
        bridge.start(port=port)
        bridge.build(WorldMap(model))
        say(f"Minecraft {VERSION} server on 127.0.0.1:{port} (offline mode) with {model.name} built at "
            f"(0, 64, 0); server log: {log_path}")
        say(f"Join with a Minecraft {VERSION} client: Multiplayer > Direct Connection > 127.0.0.1:{port}. "
            "In the chat: 'learn <command>' stores a demonstration, 'reset' starts over. Ctrl-C stops.")
        try:
            host(model, bridge, Path(out_dir), log=say, duration=duration,
                 keep=lambda demo, path: store(demo, path, db), written=written)
        except KeyboardInterrupt:
            say("stopping the server")
    if as_json:
        emit_json({"dungeon": model.name, "port": port, "log": str(log_path),
                   "demonstrations": [str(p) for p in written]})


@minecraft.command("run")
@click.argument("dungeon")
@click.option("--solver", default=None, help="The planner (see `bcc solvers`) [default: `bcc solve`'s choice: "
              "build for a structure goal, astar for most others].")
@port_option
@goal_option
@time_limit_option("Seconds for each (re)plan.", default=60.0, show_default=True)
@click.option("--max-steps", type=click.IntRange(min=1), default=200, show_default=True,
              help="Stop after this many actions.")
@click.option("--watch", type=click.FloatRange(min=0), default=0.0, metavar="SECONDS",
              help="Wait up to SECONDS for a person to join and watch; the bot then pauses between actions.")
@click.option("--picture", type=click.Path(dir_okay=False), default=None, metavar="FILE.svg",
              help="At the end, draw the world as the server reports it (an isometric SVG).")
@json_option
@solver_flags(skip=("max_steps",))
def run_cmd(dungeon, solver, port, goal, time_limit, max_steps, watch, picture, as_json, **solver_options):
    """Solve DUNGEON, then let a bot execute the plan in a real Minecraft server.

    Each step prints the model's prediction and the state parsed from the world; on a
    difference the world wins and bcc replans from it. The server applies no lava damage
    and none of bcc's rules: the bridge checks each action with the model first.
    """
    from ..solvers import Budget, default_solver, get_solver
    from ..minecraft.run import run_dungeon
    pick = solver is None and all(v in (None, ()) for v in solver_options.values())
    solver = solver or "astar"
    get_solver(solver)   # an unknown solver or option is bad input, before starting anything
    options = solver_request(solver, solver_options)
    model = compile_model(dungeon, goal)
    if picture:
        from ..atomic import check_writable
        check_writable(picture)     # before the run, not after it
    if pick:             # bcc solve's default, by the goal (solvers.default_solver)
        solver = default_solver(model)
        options = solver_request(solver, {})
    budget = Budget(time_limit=time_limit, max_memory_mb=Budget.default().max_memory_mb)
    out = (lambda line: click.echo(line, err=True)) if as_json else click.echo
    result = run_dungeon(model, port, solver=solver, budget=budget, log=out, log_path=_log_path(port),
                         max_steps=max_steps, watch=watch, solver_options=options, picture=picture)
    data = result.to_json(model)
    if picture:
        data["picture"] = picture
    if as_json:
        emit_json(data)
    else:
        s = data["seconds"]
        click.echo(f"{'reached the goal' if result.reached_goal else 'did not reach the goal'}: {result.message}; "
                   f"{len(result.steps)} actions, {data['replans']} replans; per action {s['per_action_mean']} s "
                   f"(max {s['per_action_max']} s); setup {s['setup']} s, run {s['total']} s")
    sys.exit(EXIT_OK if result.reached_goal else EXIT_NO_SOLUTION)


@minecraft.command("record")
@click.argument("dungeon")
@click.argument("command", required=False)
@port_option
@click.option("--player", default=None, help="Record this player (default: the first person to join).")
@click.option("-o", "--output", type=click.Path(dir_okay=False), default=None,
              help="Demonstration file to write (default: DUNGEON-demo-TIME.json).")
@click.option("--timeout", type=click.FloatRange(min=0, min_open=True), default=600.0, show_default=True,
              metavar="SECONDS",
              help="Seconds to wait for a player and for the demonstration.")
@click.option("--keep-going", is_flag=True, help="Do not stop at the dungeon's goal; wait for 'done' in the chat.")
@db_option
@json_option
def record_cmd(dungeon, command, port, player, output, timeout, keep_going, db, as_json):
    """Record a demonstration of COMMAND while a person plays DUNGEON in Minecraft.

    The state is polled every 100 ms, duplicates dropped, and the actions inferred by the
    grounding layer's extractor. The recording ends at the dungeon's goal, at death, or when
    the player types 'done' (or 'learn <command>', which also names the command).
    """
    from ..minecraft.bridge import VERSION, Bridge
    from ..minecraft.record import NobodyJoined, record, wait_for_player
    from ..minecraft.world import WorldMap, check_supported
    if command is not None and not command.strip():
        raise BccError("the command is empty: give the words the demonstration carries out, or leave COMMAND out")
    model = compile_model(dungeon, None)
    check_supported(model)
    say = (lambda line: click.echo(line, err=True)) if as_json else click.echo
    t0 = time.monotonic()
    with Bridge(log_path=_log_path(port)) as bridge:
        bridge.start(port=port)
        bridge.build(WorldMap(model))
        say(f"Minecraft {VERSION} server on 127.0.0.1:{port} with {model.name}: join with a {VERSION} client "
            f"(Direct Connection, 127.0.0.1:{port}); waiting up to {timeout:g} s ...")
        try:
            name = wait_for_player(bridge, player, timeout)
        except NobodyJoined as exc:
            click.echo(str(exc), err=True)
            sys.exit(EXIT_NO_SOLUTION)
        say(f"{name} joined: recording{f' {command!r}' if command else ''} (type 'done' in the chat to finish)")
        demo, recording = record(model, bridge, command, player=name, log=say,
                                 timeout=max(1.0, timeout - (time.monotonic() - t0)), stop_at_goal=not keep_going)
    path = Path(output) if output else Path(f"{model.name}-demo-{time.strftime('%Y%m%d-%H%M%S')}.json")
    if demo.dungeon == model.path:
        demo.dungeon = dungeon          # as the user named it
    stored = store(demo, path, db)
    data = {"dungeon": demo.dungeon, "command": demo.command, "actions": demo.actions, "file": str(path),
            "polls": recording.polls, "ended": recording.ended, "corrections": recording.corrections, **stored}
    if as_json:
        emit_json(data)
        return
    click.echo(f"recorded {len(demo.actions)} actions ({recording.ended}): {' '.join(demo.actions)}")
    click.echo(f"demonstration written to {path}")
    click.echo(stored["message"])


def store(demo, path, db: str | None = None) -> dict:
    """Save a demonstration recorded in Minecraft, then add the (command, demonstration)
    pair to the grounding dataset as `bcc learn` does (the same function: the dataset's
    own checks and transaction apply); a pair it refuses is saved only, and the message
    says why. Here, in the command line, because it puts two edges together."""
    import shlex
    from ..grounding.learn import add_pair
    demo.save(path)
    argv = ["learn", demo.dungeon, demo.command, "--demo", str(path)] + (["--db", str(db)] if db else [])
    shown = "bcc " + " ".join(shlex.quote(a) for a in argv)
    try:
        info = add_pair(demo.dungeon, demo.command, str(path), db)
    except BccError as exc:
        return {"stored": False, "message": f"not stored in the grounding dataset: `{shown}` says: {exc}"}
    return {"stored": True, "task": info["task"], "db": info["db"],
            "message": f"stored in the grounding dataset {info['db']} as {info['task']!r} ({shown})"}


COMMANDS = [minecraft]
