"""A grounding model saved as one JSON object: the file side shared by every model kind.

Each model class says what it is as JSON (`to_json`, `from_json(data, path)`); saving
(atomically) and loading (with `file:line:col` for broken JSON) are written once, here.
"""
from __future__ import annotations

import json
from pathlib import Path

from ..errors import BccError, read_input


def expect_format(data, fmt: str, path: str | None) -> None:
    """Refuse JSON that is not a model of format `fmt` (each model kind checks its own)."""
    if not isinstance(data, dict) or data.get("format") != fmt:
        raise BccError(f"not a grounding model: expected \"format\": \"{fmt}\"", path)


class JsonModelFile:
    def save(self, path: str | Path) -> None:
        from ..atomic import write_text
        write_text(path, json.dumps(self.to_json(), separators=(",", ":")) + "\n")

    @classmethod
    def load(cls, path: str | Path):
        text = read_input(path, "model")
        try:
            data = json.loads(text)
        except json.JSONDecodeError as exc:
            raise BccError(f"invalid JSON: {exc.msg}", str(path), exc.lineno, exc.colno) from None
        return cls.from_json(data, str(path))
