"""PDDL at the edge: export a compiled model to PDDL, import STRIPS PDDL into a model,
and run Fast Downward on an export (issue 7)."""
