"""Imported by the fork server only: compile every shipped dungeon once, before any job.

Jobs are forks of the fork server, so a solve of a shipped dungeon (with its own goal)
starts searching at once instead of compiling first. Importing this module is the
whole effect; nothing else should import it.
"""
from __future__ import annotations

from ..compiler import compile_dungeon, shipped_dungeons
from ..errors import BccError
from .worker import PRECOMPILED

for _name in shipped_dungeons():
    try:
        PRECOMPILED[_name] = compile_dungeon(_name)
    except BccError:  # a broken shipped file is reported when a job asks for it
        pass
