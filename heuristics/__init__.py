"""Heuristics: every estimate of the cost to the goal, its tables and its evaluators.

One module per job: `registry.py` names them; `position.py` (blind, manhattan),
`patterns.py` (the pattern database), `counting*.py` (the counting abstraction),
`backward.py` (their one backward search), and the relaxed family: `relaxed_task.py`
(the one relaxed task type), `relaxed_view.py`, `relaxed_build.py`, `relaxed_eval.py`,
`relaxed_last.py` (the view of a compiled dungeon), `relaxed_pddl.py` (of an imported
PDDL task), `relaxed.py` and `relaxed_additive.py` (hmax, hadd, hff, LM-cut).
Layer: above the back end (compiler/, pddl_io/), below the solvers.
"""
