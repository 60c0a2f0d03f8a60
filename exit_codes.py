"""The exit codes of every `bcc` command, in one table (as Fast Downward's
driver/returncodes.py): the CLI, its edge commands and the tests import them from here.
"""
from __future__ import annotations

EXIT_OK = 0            # solved, valid, done
EXIT_NO_SOLUTION = 1   # no plan exists, a budget ran out, a plan is invalid
EXIT_BAD_INPUT = 2     # bad input: one line `file:line:col: message` on stderr
EXIT_INTERNAL = 3      # a bug in bcc itself
EXIT_INTERRUPTED = 130  # Ctrl-C, as the shell reports SIGINT
