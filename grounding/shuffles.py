"""Held-out accuracy over several shuffles of the folds: mean, spread and a 95 % interval.

A level of the cleanup-amt corpus holds about 650 commands, so one command is 0.15
points and the shuffle alone moves a level's figure by up to a point and a half: one
shuffle's figure says little about a change of a point. Each shuffle tests every command
once, so the shuffles are not independent samples of commands; the interval is the
Wilson score interval (95 %, z = 1.96) of the mean accuracy over the shuffles, taken as
a proportion of the level's commands (n = the commands of the level, not n times the
shuffles): it says how far the figure may lie from what the same procedure would score on
new commands from the same crowd, while the spread (lowest and highest shuffle) says how
much the folds alone move it.
"""
from __future__ import annotations

import math

Z95 = 1.959964


def wilson(p: float, n: int, z: float = Z95) -> tuple[float, float]:
    """The Wilson score interval of a proportion `p` observed on `n` trials."""
    if n <= 0:
        return 0.0, 1.0
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z / (1 + z * z / n) * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    return max(0.0, centre - half), min(1.0, centre + half)


def summarise(reports: list[dict]) -> dict:
    """Per level and overall, over `reports` (one per shuffle, as pairs.evaluate returns):
    {"mean", "low", "high" (the lowest and highest shuffle), "ci95": [lo, hi], "total"}."""
    levels = sorted({lv for r in reports for lv in r["by_level"]})
    out = {}
    for lv in levels + ["all"]:
        if lv == "all":
            figs = [r["accuracy"] for r in reports]
            total = len(reports[0]["pairs"])
        else:
            figs = [r["by_level"][lv]["accuracy"] for r in reports]
            total = reports[0]["by_level"][lv]["total"]
        mean = sum(figs) / len(figs)
        lo, hi = wilson(mean, total)
        out[lv] = {"mean": mean, "low": min(figs), "high": max(figs), "ci95": [lo, hi], "total": total,
                   "shuffles": figs}
    return out
