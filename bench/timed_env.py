"""The environment every benchmark gives the processes it times (one rule for all of bench/).

Python may cache bytecode, as it does for an installed bcc (pip compiles it) and for Fast
Downward's translator in site-packages: with PYTHONDONTWRITEBYTECODE set (as in some shells
and containers), every bcc process would recompile its modules, 0.1-0.2 s a run."""
from __future__ import annotations

import os


def timed_env(**extra: str) -> dict:
    env = dict(os.environ, **extra)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    return env
