"""The user's dataset of (command, dungeon, demonstration, inferred task) rows, in SQLite.

Every write is one transaction (`BEGIN IMMEDIATE ... COMMIT`, SQLite's rollback journal),
so a crash or a kill in the middle of `bcc learn` leaves either the whole row or none,
never half of one. Trained translation models are stored in the same file, so the
newest model always matches the data it was trained on.

Where: `--db PATH`, else `$BCC_HOME/grounding.sqlite`, else
`$XDG_DATA_HOME/bcc/grounding.sqlite` (default `~/.local/share/bcc/grounding.sqlite`).
"""
from __future__ import annotations

import json
import os
import sqlite3
import time
from pathlib import Path

from ..errors import BccError

SCHEMA = """
CREATE TABLE IF NOT EXISTS pairs (
    id INTEGER PRIMARY KEY,
    command TEXT NOT NULL,
    dungeon TEXT NOT NULL,
    demonstration TEXT NOT NULL,      -- the demonstration file's JSON
    task TEXT NOT NULL,               -- the inferred task (most likely explanation)
    explanations TEXT NOT NULL,       -- JSON [{task, tokens, weight}], the latent task's support
    created REAL NOT NULL
);
CREATE TABLE IF NOT EXISTS models (
    id INTEGER PRIMARY KEY,
    model TEXT NOT NULL,              -- IBMModel2.to_json()
    pairs INTEGER NOT NULL,
    with_corpus INTEGER NOT NULL,
    seconds REAL NOT NULL,
    created REAL NOT NULL
);
"""
CRASH_HOOK = "BCC_GROUNDING_SLEEP_IN_WRITE"   # tests: seconds to sleep inside a write transaction


def default_path() -> Path:
    if os.environ.get("BCC_HOME"):
        return Path(os.environ["BCC_HOME"]) / "grounding.sqlite"
    base = os.environ.get("XDG_DATA_HOME") or str(Path.home() / ".local" / "share")
    return Path(base) / "bcc" / "grounding.sqlite"


class Dataset:
    def __init__(self, path: str | Path | None = None):
        self.path = Path(path) if path else default_path()
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            self.conn = sqlite3.connect(str(self.path), isolation_level=None, timeout=30)
            self.conn.executescript(SCHEMA)
        except sqlite3.DatabaseError as exc:
            raise BccError(f"cannot open the dataset: {exc}", str(self.path)) from None
        except OSError as exc:
            raise BccError(f"cannot create the dataset: {exc.strerror}", str(self.path)) from None

    def close(self) -> None:
        self.conn.close()

    def _write(self, sql: str, args: tuple) -> int:
        try:
            self.conn.execute("BEGIN IMMEDIATE")
            try:
                cur = self.conn.execute(sql, args)
                pause = os.environ.get(CRASH_HOOK)
                if pause:
                    time.sleep(float(pause))
                self.conn.execute("COMMIT")
            except BaseException:
                self.conn.execute("ROLLBACK")
                raise
        except sqlite3.DatabaseError as exc:
            raise BccError(f"cannot write the dataset: {exc}", str(self.path)) from None
        return cur.lastrowid

    def add_pair(self, command: str, dungeon: str, demonstration: dict, explanations: list) -> int:
        """Store one pair; `explanations` is [{task, tokens, weight}], most likely first."""
        if not explanations:
            raise BccError("the demonstration explains no task: its last state must achieve something "
                           "that no earlier state did")
        return self._write("INSERT INTO pairs (command, dungeon, demonstration, task, explanations, created) "
                           "VALUES (?, ?, ?, ?, ?, ?)",
                           (command, dungeon, json.dumps(demonstration, separators=(",", ":")),
                            explanations[0]["task"], json.dumps(explanations), time.time()))

    def pairs(self) -> list[dict]:
        rows = self.conn.execute("SELECT id, command, dungeon, task, explanations FROM pairs ORDER BY id").fetchall()
        return [{"id": i, "command": c, "dungeon": d, "task": t, "explanations": json.loads(e)}
                for i, c, d, t, e in rows]

    def count(self) -> int:
        return self.conn.execute("SELECT COUNT(*) FROM pairs").fetchone()[0]

    def add_model(self, model_json: dict, pairs: int, with_corpus: bool, seconds: float) -> int:
        return self._write("INSERT INTO models (model, pairs, with_corpus, seconds, created) VALUES (?, ?, ?, ?, ?)",
                           (json.dumps(model_json, separators=(",", ":")), pairs, int(with_corpus), seconds,
                            time.time()))

    def latest_model(self, formats=None) -> dict | None:
        """The newest stored model; with `formats`, the newest of those formats (goal models
        and task-call models share the table)."""
        for (text,) in self.conn.execute("SELECT model FROM models ORDER BY id DESC"):
            data = json.loads(text)
            if formats is None or (isinstance(data, dict) and data.get("format") in formats):
                return data
        return None

    def integrity(self) -> str:
        return self.conn.execute("PRAGMA integrity_check").fetchone()[0]
