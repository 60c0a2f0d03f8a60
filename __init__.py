"""bcc: declarative YAML domains and dungeons compiled to an OO-MDP, solved by pluggable solvers.

Pipeline (one folder per step): grammar/ -> compiler/ -> model.py -> solvers/.
The CLI (cli/) is an edge that only translates between the shell and the library.
"""
if __package__:  # imported as bcc (or as the checkout's folder name, by pytest)
    from .errors import BccError  # noqa: E402
    __all__ = ["BccError", "__version__"]
# else: pytest collecting a checkout whose folder is no Python name (e.g. `bcc-main`)
# imports this file alone, as `__init__`; the tests use the installed bcc.


def __getattr__(name: str):
    """`__version__`, read from the installed metadata on first use (importlib.metadata
    scans every installed distribution: too slow for every start of the command)."""
    if name != "__version__":
        raise AttributeError(f"module 'bcc' has no attribute {name!r}")
    from importlib.metadata import PackageNotFoundError, version
    try:
        value = version("bcc")
    except PackageNotFoundError:  # running from a source tree that was never installed
        value = "0.0.0"
    globals()["__version__"] = value
    return value
