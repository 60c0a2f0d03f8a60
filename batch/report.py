"""`bcc batch report`: a results file summarised per solver setting, and a size plot."""
from __future__ import annotations

import statistics

from ..errors import BccError


def label(row: dict) -> str:
    """The solver and its options, e.g. `astar heuristic=manhattan`."""
    options = row.get("options") or {}
    return " ".join([str(row.get("solver"))] + [f"{k}={v}" for k, v in sorted(options.items())])


def summarise(rows: list[dict]) -> list[dict]:
    """Per solver setting (sorted by name): runs, solved, failures, and the median and max
    of time and expansions over the solved runs."""
    groups: dict[str, list] = {}
    for row in rows:
        groups.setdefault(label(row), []).append(row)
    out = []
    for name, group in sorted(groups.items()):
        solved = [r for r in group if r.get("solved")]
        times = [r.get("seconds") or 0.0 for r in solved]
        expanded = [r.get("expanded") or 0 for r in solved]
        out.append({
            "solver": name, "runs": len(group), "solved": len(solved),
            "budget_exhausted": sum(1 for r in group if r.get("status") == "budget"),
            "no_solution": sum(1 for r in group if r.get("status") == "no_solution"),
            "errors": sum(1 for r in group if r.get("error")),
            "median_seconds": round(statistics.median(times), 6) if times else None,
            "max_seconds": round(max(times), 6) if times else None,
            "median_expanded": statistics.median(expanded) if expanded else None,
            "max_expanded": max(expanded) if expanded else None,
        })
    return out


def table(summary: list[dict]) -> str:
    head = (f"{'solver':<28} {'runs':>5} {'solved':>6} {'budget':>6} {'errors':>6} "
            f"{'median s':>9} {'max s':>9} {'median exp':>11} {'max exp':>11}")
    lines = [head, "-" * len(head)]

    def num(value, spec):
        return format(value, spec) if value is not None else "-"
    for s in summary:
        lines.append(f"{s['solver']:<28} {s['runs']:>5} {s['solved']:>6} {s['budget_exhausted']:>6} "
                     f"{s['errors']:>6} {num(s['median_seconds'], '>9.3f')} {num(s['max_seconds'], '>9.3f')} "
                     f"{num(s['median_expanded'], '>11,.0f')} {num(s['max_expanded'], '>11,')}")
    return "\n".join(lines)


def plot(rows: list[dict], output: str) -> int:
    """Cost and time of the solved runs against problem size (cells), one series per
    solver setting; returns how many points were drawn."""
    from ..extras import pyplot
    plt = pyplot()
    import io
    series: dict[str, list] = {}
    for row in rows:
        if row.get("solved") and row.get("size") is not None:
            series.setdefault(label(row), []).append((row["size"], row.get("cost"), row.get("seconds") or 0.0))
    if not series:
        raise BccError("no solved runs with a size to plot", output)
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    points = 0
    for name, pts in series.items():
        pts.sort()
        points += len(pts)
        sizes = [p[0] for p in pts]
        for ax, k in ((axes[0], 1), (axes[1], 2)):
            ax.scatter(sizes, [p[k] for p in pts], s=12, alpha=0.6, label=name)
            medians = _medians(pts, k)
            ax.plot([m[0] for m in medians], [m[1] for m in medians], alpha=0.8)
    for ax, what in zip(axes, ("plan cost", "seconds (solver)")):
        ax.set_xlabel("problem size (cells, width x depth)")
        ax.set_ylabel(what)
        ax.grid(True, alpha=0.3)
    axes[1].set_yscale("log")
    axes[0].set_title("cost against size")
    axes[1].set_title("time against size (line: median per size)")
    axes[1].legend(fontsize=8)
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100)
    plt.close(fig)
    from ..atomic import write_bytes
    write_bytes(output, buf.getvalue())
    return points


def _medians(pts: list, k: int) -> list:
    by_size: dict = {}
    for p in pts:
        by_size.setdefault(p[0], []).append(p[k])
    return [(size, statistics.median(v)) for size, v in sorted(by_size.items())]
