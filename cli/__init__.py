"""The `bcc` command line: translates between the shell and the library, nothing more.

An edge: it imports the library, and no library module imports it. core.py holds the
`bcc` group and the commands on a dungeon (compile, solve, validate, show, ...); each
feature's commands sit in a module of their own here (pddl.py with hddl.py, grounding.py, serve.py,
batch.py, minecraft.py), loaded only when one of them is asked for; shared.py holds what
they all use (options, JSON output, printing a result).
"""
from .core import main

__all__ = ["main"]
