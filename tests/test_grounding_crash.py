"""The grounding dataset survives a SIGKILL in the middle of `bcc learn`: whole row or none."""
from __future__ import annotations

import os
import signal
import sqlite3
import subprocess
import sys
import time

from bcc.grounding.dataset import CRASH_HOOK, Dataset
from test_grounding import _one_shot_demo


def test_a_kill_during_learn_loses_no_row_and_half_writes_none(tmp_path):
    demo = _one_shot_demo(tmp_path / "demo.json")
    db = tmp_path / "d.sqlite"
    cmd = [sys.executable, "-m", "bcc", "learn", "bridge", "go to the gold block", "--demo", str(demo), "--db", str(db)]
    assert subprocess.run(cmd, capture_output=True).returncode == 0
    proc = subprocess.Popen(cmd, env=dict(os.environ, **{CRASH_HOOK: "60"}),
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    journal = tmp_path / "d.sqlite-journal"
    deadline = time.monotonic() + 120
    while not (journal.exists() and journal.stat().st_size > 0) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert journal.exists(), "the second learn never started its transaction"
    time.sleep(0.2)  # inside the transaction: the row is written to the database file's pages or the journal
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    conn = sqlite3.connect(db)
    assert conn.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
    rows = conn.execute("SELECT command, task, explanations FROM pairs").fetchall()
    conn.close()
    assert len(rows) == 1 and rows[0][1] == "agentOnBlock(agent, gold)"   # the killed row is not there at all
    assert subprocess.run(cmd, capture_output=True).returncode == 0
    assert Dataset(db).count() == 2
