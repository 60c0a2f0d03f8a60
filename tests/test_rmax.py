"""R-max learns the dynamics from experience and ends up acting optimally (A*'s cost)."""
from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from bcc.cli import main
from bcc.simulate import replay
from bcc.solvers import Budget, get_solver

from conftest import compiled

BUDGET = Budget(time_limit=120)


def optimal(name):
    return get_solver("astar")(compiled(name), BUDGET).cost


@pytest.mark.parametrize("learner", ["tabular", "oo"])
def test_rmax_converges_on_grid_to_the_optimal_plan(learner):
    cost = optimal("grid")  # 7, hand-derived in test_solvers.py
    result = get_solver("rmax")(compiled("grid"), BUDGET, learner=learner, episodes=8, seed=0, optimal_cost=cost)
    assert result.solved and result.cost == cost
    assert replay(compiled("grid"), [(a, 1, 1) for a in result.plan]).valid
    assert result.converged_episode is not None and result.converged_episode <= 4
    assert [e["steps"] for e in result.episodes][-1] == cost


def test_oo_learner_generalises_across_cells_in_the_maze():
    # Tabular R-max must try every (state, action) near its path; the local model learns a
    # move once per surrounding and reuses it, so it explores far less in the first episode.
    cost = optimal("easy_maze")
    tab = get_solver("rmax")(compiled("easy_maze"), BUDGET, learner="tabular", episodes=3, seed=0, optimal_cost=cost)
    oo = get_solver("rmax")(compiled("easy_maze"), BUDGET, learner="oo", episodes=3, seed=0, optimal_cost=cost)
    assert oo.episodes[0]["steps"] < tab.episodes[0]["steps"]
    assert oo.episodes[-1]["success"] and oo.episodes[-1]["steps"] == cost


def test_rmax_learns_only_from_experience():
    # The learner never calls successors(): it only sees apply() outcomes of actions it took.
    model = compiled("grid")
    calls = []
    import dataclasses
    spy = dataclasses.replace(model, successors=lambda s: calls.append(s) or model.successors(s))
    get_solver("rmax")(spy, BUDGET, episodes=2, seed=0)
    assert calls == []


def test_cli_reports_episodes_and_convergence():
    result = CliRunner().invoke(main, ["solve", "grid", "--solver", "rmax", "--model", "oo", "--episodes", "6",
                                       "--seed", "0", "--json"], catch_exceptions=False)
    data = json.loads(result.stdout)
    assert result.exit_code == 0 and data["solved"]
    assert len(data["episodes"]) == 6 and {"steps", "return", "success"} <= set(data["episodes"][0])
    assert data["converged_episode"] is not None
    bad = CliRunner().invoke(main, ["solve", "grid", "--model", "oo"])
    assert bad.exit_code == 2


def test_learn_curve_reports_both_learners(tmp_path):
    result = CliRunner().invoke(main, ["learn-curve", "grid", "--episodes", "4", "--json"], catch_exceptions=False)
    data = json.loads(result.stdout)
    assert set(data["runs"]) == {"rmax/tabular", "rmax/oo"} and data["optimal_cost"] == 7
    assert all(len(run["steps"]) == 4 for run in data["runs"].values())
    pytest.importorskip("matplotlib")
    png = tmp_path / "curve.png"
    assert CliRunner().invoke(main, ["learn-curve", "grid", "--episodes", "3", "-o", str(png)]).exit_code == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
