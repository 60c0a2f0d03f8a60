"""Heuristics: every estimate of the cost to the goal, with the tables it is built from.

One module per job: `registry.py` names them with their traits (admissible, costly,
preferred actions, the relaxed view, the models they serve); `tables.py` builds their
tables from a model and makes them model data (`model.data("pattern_database")`);
`position.py` (blind, manhattan), `patterns.py` (the pattern database), `counting*.py`
(the counting abstraction), `backward.py` (the backward search of both), and the relaxed
family: `relaxed_task.py` (the one relaxed task type), `relaxed_view.py`,
`relaxed_build.py`, `relaxed_eval.py`, `relaxed_last.py` (the view of a compiled
dungeon), `relaxed_pddl.py` (of an imported PDDL task), `relaxed.py` (hmax, hadd, hff,
LM-cut) and `relaxed_explore.py` (the one exploration of the view's facts they all run).
docs/add-a-heuristic.md adds one.
Layer: above the back end (compiler/, pddl_io/) and the model, below the solvers.
"""
from . import tables

tables.register()
