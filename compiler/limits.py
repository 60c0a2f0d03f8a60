"""How big an input bcc accepts: one place for every size limit on domain and dungeon files.

Without them a small file can exhaust the interpreter (a 1 KB file of nested YAML aliases
expands to billions of values; 1,000 nested brackets or 200 `not`s overflow a recursion
limit; a 5,000-digit number trips Python's int-to-string guard). Each limit is far above
what a real domain or dungeon needs, and crossing it is bad input: a `BccError` with a
position and a message that names the limit.
"""
from __future__ import annotations

MAX_FILE_BYTES = 4 * 1024 * 1024      # a domain or dungeon file (a 1,000 x 1,000 map is 1 MB)
MAX_YAML_DEPTH = 64                   # lists and mappings inside each other
MAX_ALIAS_VALUES = 100_000            # values that YAML aliases (*name) add by repeating anchors
MAX_INT = 2**31 - 1                   # numbers lie in [-MAX_INT, MAX_INT]
MAX_INT_DIGITS = 40                   # longer digit strings are refused before conversion
MAX_REF_LENGTH = 1024                 # `domain:` / `extends:` references (a name or a path)
MAX_EXPRESSION_DEPTH = 40             # brackets, operators and blocks inside each other
MAX_GROUND_DEPTH = 50                 # the same after inlining functions into their callers
MAX_GENERATED_NESTING = 90            # preconditions + nested conditional effects of one action (an elif chain is one)
MAX_EFFECT_LEVELS = 300               # conditional effects inside each other, each elif and `first` object one level
MAX_GROUND_EFFECTS = 100_000          # effect nodes grounded for one dungeon (nested first/forall multiply)
MAX_GRID_CELLS = 2**24                # cells of the grid (x * y * z)
MAX_KEYED_OBJECTS = 65_536            # objects of another keyed class (inventory slots, ...)
MAX_METHOD_VARS = 16                  # a method's own variables (each a loop or an assignment in its code)
# The length of names is the names rule's (names.MAX_NAME), for names in expressions too.


def number_error(text: str) -> str | None:
    """Why an integer written as `text` (digits, maybe a sign) is refused, or None."""
    digits = text.lstrip("+-").replace("_", "")
    if len(digits) > MAX_INT_DIGITS:
        return f"the number has {len(digits):,} digits; numbers lie between {-MAX_INT:,} and {MAX_INT:,}"
    return None

def int_error(value: int) -> str | None:
    if -MAX_INT <= value <= MAX_INT:
        return None
    return f"the number {shorten(str(value), 30)} is too large; numbers lie between {-MAX_INT:,} and {MAX_INT:,}"

def shorten(text: str, limit: int = 60) -> str:
    """`text`, or its start and end around an ellipsis, so a message stays one short line."""
    if len(text) <= limit:
        return text
    half = max(limit // 2 - 2, 1)
    return f"{text[:half]}...{text[-half:]} ({len(text):,} characters)"
