"""The run layer, between the edges and the solvers: one path from a request to a Result
(solve.py), and work run in child processes under hard limits (children.py, pool.py).

    from bcc.run import Request, run
    ran = run(Request(load=lambda: compile_dungeon("bridge"), solver="astar", budget=Budget(time_limit=10)))
    ran.result.cost, ran.model.name

The command line, the server's jobs, batch rows and the PDDL import all run a solver
through `run`; batch's sweeps and the grounding cross-validation fan work out to child
processes through `pool.map_local`.
"""
from .solve import Ran, Request, run

__all__ = ["Ran", "Request", "run"]
