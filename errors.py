"""One error type for every piece of bad input, carrying where in which file it is.

The loader, the parser and the compiler raise `BccError`; the CLI prints it once as
`file:line:col: message` and exits 2. Positions are 1-based. `InternalError` is the other
side of that line: a check bcc makes of itself failed, so it is a bug in bcc (exit 3),
never something the user can fix in the input.
"""
from __future__ import annotations

import re
from pathlib import Path

# C0/C1 control characters (tab and newline allowed), line separators and lone surrogates:
# what must never reach a terminal or a log raw.
CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f\u2028\u2029\ud800-\udfff]")


def printable(text: str) -> str:
    """`text` with control characters, terminal escapes and lone surrogates escaped, for
    printing anything that may hold input (an error message, a path, a name)."""
    return CONTROL.sub(lambda m: m.group().encode("unicode_escape", "backslashreplace").decode("ascii"), text)


class BccError(Exception):
    """Bad input (a dungeon, a domain, a plan, an expression), with its position when known."""

    MAX_MESSAGE = 600  # a message quoting a huge value keeps its start and end

    def __init__(self, message: str, path: str | None = None,
                 line: int | None = None, col: int | None = None):
        if len(message) > self.MAX_MESSAGE:
            half = self.MAX_MESSAGE // 2
            message = f"{message[:half]} ... {message[-half:]}"
        super().__init__(message)
        self.message = message
        self.path = path
        self.line = line
        self.col = col

    def at(self, path: str | None, line: int | None, col: int | None) -> "BccError":
        """Fill in a position the raiser did not know (keeps one it did know)."""
        if self.path is None:
            self.path = path
        if self.line is None:
            self.line, self.col = line, col
        return self

    def __str__(self) -> str:
        """`file:line:col: message`, with any control character or terminal escape escaped
        (a message may quote input)."""
        where = [str(p) for p in (self.path, self.line, self.col) if p is not None]
        return printable(":".join(where + [" " + self.message]) if where else self.message)


class InternalError(Exception):
    """A bug in bcc caught by one of its own consistency checks (the CLI exits 3).

    Deliberately not a BccError: bad input is reported as bad input, and nothing the user
    writes should ever reach one of these."""


class ModelError(Exception):
    """A domain bug found while running a compiled model (e.g. a value outside its range).

    Raised from generated code; the CLI reports it like bad input (exit 2)."""


def read_input(path: str | Path, what: str | None = None) -> str:
    """The text of a file the user named (a dungeon, a plan, a demonstration...), or a
    one-line BccError saying why it cannot be read: `what` names the kind of file."""
    try:
        return Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        raise BccError(f"no such {what + ' ' if what else ''}file", str(path)) from None
    except (OSError, UnicodeDecodeError) as exc:
        raise BccError(f"cannot read {what or 'file'}: {exc}", str(path)) from None
