"""Compile a dungeon (and its domain) into a `Model`: load -> ground -> lay out -> emit.

    model = compile_dungeon("bridge")                 # a shipped name or a path
    model = compile_dungeon("four_rooms", goal="agentInRoom(agent, red)")

The pipeline (pipeline.py) is loaded on first use of these names: importing one
sub-module (`bcc.compiler.ir`, as `bcc import pddl` does) does not load the YAML
front-end and numpy with it, which cost a PDDL import a quarter of a second.
"""
from __future__ import annotations

__all__ = ["compile_dungeon", "load_dungeon", "load_domain", "shipped_dungeons", "resolve_dungeon_path"]


def __getattr__(name: str):
    if name in __all__:
        from . import pipeline
        return getattr(pipeline, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
