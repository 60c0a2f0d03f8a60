"""MinePlanner (Hill et al. 2023) as bcc dungeons: an edge beside minecraft/, not part of
the compiler, solvers or PDDL front end. `import_task` turns a task's propositional
domain and problem into a dungeon on domains/builder.yaml; `task_plan` maps a plan of
that dungeon back to the task's PDDL actions."""
from __future__ import annotations

from dataclasses import dataclass


@dataclass
class Imported:
    text: str          # the dungeon file
    task: object       # mineplanner.task.Task
    frame: object      # mineplanner.world.Frame
    goal: str          # the goal expression
    items: list        # the items' names in the dungeon, in the task's order


def import_task(domain: str, problem: str, headroom: int | None = None) -> Imported:
    from ..compiler.domain import load_domain, resolve_domain_path
    from .goal import goal_cells, goal_expression
    from .task import read_task
    from .world import HEADROOM, dungeon_text, frame, item_names
    task = read_task(domain, problem)
    fr = frame(task, goal_cells(task), HEADROOM if headroom is None else headroom)
    goal = goal_expression(task, fr)
    materials = set(load_domain(resolve_domain_path("builder")).enums["material"].values)
    source = f"imported by `bcc import mineplanner` from {domain} and {problem}"
    return Imported(dungeon_text(task, goal, fr, materials, source), task, fr, goal, item_names(task))


def task_plan(imported: Imported, plan: list, check: bool = True) -> list:
    """The PDDL actions (text, fully parameterised) of a plan of the imported dungeon."""
    from .plan import pddl_plan
    return pddl_plan(imported.task, imported.frame, imported.items, plan, check)
