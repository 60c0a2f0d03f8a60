"""`bcc import mineplanner`: a MinePlanner task as a builder dungeon, and a plan back."""
from __future__ import annotations

import sys

import click

from .shared import emit_json, json_option


@click.command("mineplanner")
@click.argument("domain", type=click.Path(dir_okay=False))
@click.argument("problem", type=click.Path(dir_okay=False))
@click.option("-o", "--output", type=click.Path(dir_okay=False, writable=True),
              help="Write the dungeon (or, with --plan, the PDDL plan) to FILE (atomically).")
@click.option("--plan", "plan_file", type=click.Path(dir_okay=False, allow_dash=True),
              help="Map this plan of the imported dungeon (a file, one action a line, or -) to the "
                   "task's PDDL actions instead.")
@click.option("--headroom", type=click.IntRange(min=0), default=None,
              help="Layers kept above the highest block, item, goal cell or head [default: 2].")
@json_option
def import_mineplanner_cmd(domain, problem, output, plan_file, headroom, as_json):
    """Import a MinePlanner task (its propositional DOMAIN and PROBLEM PDDL) as a dungeon
    on the builder domain; `bcc solve` plans it. With --plan, print that plan as the task's
    own PDDL actions, fully parameterised, `(checkgoal ...)` last."""
    from ..atomic import write_text
    from ..mineplanner import import_task, task_plan
    imported = import_task(domain, problem, headroom)
    fr = imported.frame
    if plan_file:
        stream = click.open_file(plan_file)
        with stream:
            plan = [line.strip() for line in stream if line.strip()]
        actions = task_plan(imported, plan)
        text = "".join(a + "\n" for a in actions)
        if output:
            write_text(output, text)
        if as_json:
            emit_json({"problem": problem, "steps": len(actions) - 1, "plan": actions})
        elif not output:
            click.echo(text, nl=False)
        sys.exit(0)
    if output:
        write_text(output, imported.text)
    summary = {"dungeon": output, "size": {"width": fr.width, "depth": fr.depth, "height": fr.height},
               "origin": {"x": fr.x0, "y": fr.y0, "z": fr.z0}, "blocks": len(imported.task.blocks),
               "items": len(imported.task.items), "goal": imported.goal}
    if as_json:
        emit_json(summary)
    elif output:
        click.echo(f"wrote {output}: {fr.width} x {fr.depth} x {fr.height}, {summary['blocks']} blocks, "
                   f"{summary['items']} items; goal: {imported.goal}", err=True)
    else:
        click.echo(imported.text, nl=False)
