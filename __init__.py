"""bcc: declarative YAML domains and dungeons compiled to an OO-MDP, solved by pluggable solvers.

Pipeline (one folder per step): grammar/ -> compiler/ -> model.py -> solvers/.
The CLI (cli.py) is an edge that only translates between the shell and the library.
"""
from importlib.metadata import PackageNotFoundError, version as _version

try:
    __version__ = _version("bcc")
except PackageNotFoundError:  # running from a source tree that was never installed
    __version__ = "0.0.0"

if __package__:  # imported as bcc (or as the checkout's folder name, by pytest)
    from .errors import BccError  # noqa: E402
    __all__ = ["BccError", "__version__"]
# else: pytest collecting a checkout whose folder is no Python name (e.g. `bcc-main`)
# imports this file alone, as `__init__`; the tests use the installed bcc.
