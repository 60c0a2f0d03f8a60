"""Optional dependencies (pyproject's extras): one way to import them and one wording of
the hint when one is missing, spelled as the README installs bcc, from a checkout."""
from __future__ import annotations

from .errors import BccError


def install_hint(extra: str) -> str:
    """`pip install ".[EXTRA]"`: the README installs bcc from its checkout, not from PyPI."""
    return f'pip install ".[{extra}]" in the bcc checkout'


def missing(what: str, package: str, extra: str) -> BccError:
    """The error for a feature whose optional package is not installed."""
    return BccError(f"{what} needs {package}: {install_hint(extra)}")


def pyplot():
    """matplotlib.pyplot on the file-only Agg backend, or a BccError saying how to get it."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise missing("plotting", "matplotlib", "plot") from None
    return plt
