"""An HTN planning problem as read from HDDL: the lifted domain of the PDDL front end plus
compound tasks, methods and the problem's initial task network.

Why lifted: the IPC's construction tasks have tens of thousands of locations, and
grounding every method over them is far larger than the part a progression search ever
touches; the planner binds methods and actions against the state as it goes.

Formulas, effects and actions are those of pddl_io/lifted.py; a subtask is (name, args),
each arg a variable of its method or an object. Every network here is totally ordered:
the reader refuses any other at its place.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from ..pddl_io.lifted_types import Domain, Problem


@dataclass(frozen=True)
class Task:
    """A compound task: its name and typed parameters (frozensets of types)."""
    name: str
    params: tuple
    where: tuple = (0, 0)


@dataclass(frozen=True)
class Method:
    """Decomposes `task` (name, args) into `subtasks`, in this order, where `pre` holds
    (its :precondition and :constraints together)."""
    name: str
    params: tuple                # ((variable, frozenset of types), ...)
    task: tuple                  # (task name, argument terms)
    pre: tuple                   # formula
    subtasks: tuple              # ((name, argument terms), ...)
    where: tuple = (0, 0)


@dataclass
class HtnProblem:
    """What `bcc import hddl` hands to the `htn` solver."""
    domain: Domain
    problem: Problem
    tasks: dict                  # name -> Task
    methods: list                # [Method], in the file's order
    network: Method              # the problem's :htn as a method of no task ("root")
    name: str = ""
    path: str = ""
    report: dict = field(default_factory=dict)

    @property
    def actions(self) -> dict:
        return {a.name: a for a in self.domain.actions}
