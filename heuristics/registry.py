"""Every heuristic by name, with the traits the solvers' rules read.

A heuristic is a function `make(model, time_limit=None)` returning h(state) -> number
(math.inf: no plan from this state). Its entry here says what it is, so no solver keeps
a list of its own:

- `admissible`: never above the true cost, so 0 on every goal state: A* keeps its plans
  optimal with it, and tests the goal only where it says 0;
- `costly`: one evaluation costs far more than generating a state: gbfs evaluates it
  lazily, on expansion;
- `preferred`: h also names *preferred actions*: after h(state), `h.preferred()` is the
  set of actions that gbfs's second queue follows from that state;
- `relaxed`: it reads the model's delete-relaxed view (`model.data("relaxed_task")`);
  where that cannot be built, `make` gives blind search instead (its h has
  `fallback = "blind"`);
- `models`: which models it serves: `"bytes"`, compiled dungeons (byte states, from the
  YAML back end), and `"bits"`, imported PDDL tasks (int bitset states). On another
  model it still runs, but says nothing more than blind search would.

Entries name their `make` as "module:function" in this package, imported on first use.
"""
from __future__ import annotations

import importlib
from dataclasses import dataclass
from typing import Callable

BYTES, BITS = "bytes", "bits"   # the models: compiled dungeons, imported PDDL tasks


@dataclass(frozen=True)
class Heuristic:
    name: str
    make: str | Callable        # "module:function" in bcc.heuristics (or the function)
    summary: str
    admissible: bool = False
    costly: bool = False
    preferred: bool = False
    relaxed: bool = False
    models: tuple = (BYTES, BITS)

    def build(self, model, time_limit: float | None = None):
        """h for `model`; `time_limit` bounds building what it needs (its tables)."""
        if self.relaxed:
            from .relaxed import relaxed_of
            if relaxed_of(model, time_limit) is None:   # the view is past its limits: search blind, say so
                from .position import blind
                h = blind(model)
                h.fallback = "blind"
                return h
        make = self.make
        if isinstance(make, str):
            module, function = make.split(":")
            make = getattr(importlib.import_module(f".{module}", __package__), function)
        return make(model, time_limit)


HEURISTICS = {h.name: h for h in (
    Heuristic("pdb", "patterns:pdb", "exact distances over the agent's position and facing (a pattern database)",
              admissible=True, models=(BYTES,)),
    Heuristic("manhattan", "position:manhattan", "the distance to the nearest position where the goal may hold",
              admissible=True, models=(BYTES,)),
    Heuristic("blind", "position:blind", "0 everywhere", admissible=True),
    Heuristic("hmax", "relaxed:hmax", "the costliest goal fact of the delete relaxation",
              admissible=True, costly=True, relaxed=True),
    Heuristic("hadd", "relaxed:hadd", "the summed costs of the goal facts of the delete relaxation",
              costly=True, relaxed=True),
    Heuristic("hff", "relaxed:hff", "the cost of a relaxed plan (FF), with its first steps as preferred actions",
              costly=True, preferred=True, relaxed=True),
    Heuristic("lmcut", "relaxed:lmcut", "LM-cut: landmark cuts of the delete relaxation",
              admissible=True, costly=True, relaxed=True),
    Heuristic("counting", "counting:counting", "exact distances in a counting abstraction of the grid's cells",
              admissible=True, models=(BYTES,)),
)}


def make(name: str, model, time_limit: float | None = None):
    """h(state) of the heuristic `name` on `model`."""
    return HEURISTICS[name].build(model, time_limit)


def model_kind(model) -> str | None:
    """BYTES for a compiled dungeon, BITS for an imported PDDL task (by what the back end
    gives the heuristics to build from), None for any other model."""
    if model.data("compiled") is not None:
        return BYTES
    if model.data("ground_task") is not None:
        return BITS
    return None


def serves(name: str, model) -> bool:
    """Whether the heuristic `name` says more on `model` than blind search."""
    return model_kind(model) in HEURISTICS[name].models
