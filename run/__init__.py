"""The run layer, between the edges and the solvers: work run in child processes under
hard limits (children.py: one child, with its memory cap and wall-clock deadline;
pool.py: many, a few at a time). Batch sweeps and the grounding cross-validation fan
work out through `pool.map_local`; batch adds Ray on top (batch/engine.py).
"""
