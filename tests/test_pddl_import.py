"""`bcc import pddl`: STRIPS PDDL compiled into a bcc model that bcc's solvers solve.

Optimal costs are derived by hand in the comments of tests/pddl/*.pddl; BFS and A*
(blind, as the model has no grid) must both find them. Needs unified-planning (the
`pddl` extra) to parse; skipped without it.
"""
import json
from pathlib import Path

import pytest
from click.testing import CliRunner

pytest.importorskip("unified_planning", reason='PDDL import needs unified-planning: pip install ".[pddl]"')

from bcc.cli import main  # noqa: E402
from bcc.errors import BccError  # noqa: E402
from bcc.pddl_io.importer import import_pddl  # noqa: E402
from bcc.solvers import Budget, get_solver  # noqa: E402

HERE = Path(__file__).parent / "pddl"
HAND_COSTS = {"gripper-3": ("gripper-domain", 9), "blocksworld-4": ("blocksworld-domain", 8),
              "logistics-2": ("logistics-domain", 9)}


@pytest.mark.parametrize("problem", sorted(HAND_COSTS))
def test_imported_problem_has_the_hand_derived_cost(problem):
    domain, cost = HAND_COSTS[problem]
    model = import_pddl(str(HERE / f"{domain}.pddl"), str(HERE / f"{problem}.pddl"))
    for solver in ("bfs", "astar"):
        result = get_solver(solver)(model, Budget(time_limit=60))
        assert result.solved and result.cost == cost


def test_imported_plan_replays_in_the_model():
    model = import_pddl(str(HERE / "gripper-domain.pddl"), str(HERE / "gripper-3.pddl"))
    plan = get_solver("astar")(model, Budget(time_limit=60)).plan
    s = model.initial
    for name in plan:
        s = model.apply(model.action_index(name), s)
        assert s is not None
    assert model.is_goal(s) and not model.is_goal(model.initial)


def test_cli_import_solves_and_prints_pddl_actions():
    r = CliRunner().invoke(main, ["import", "pddl", str(HERE / "gripper-domain.pddl"), str(HERE / "gripper-3.pddl"),
                                  "--json"])
    assert r.exit_code == 0, r.output
    out = json.loads(r.output)
    assert out["cost"] == 9 and out["plan"][0].startswith("(pick ")


def test_parse_error_is_one_line_with_a_position():
    r = CliRunner().invoke(main, ["import", "pddl", str(HERE / "broken-domain.pddl"), str(HERE / "gripper-3.pddl")])
    assert r.exit_code == 2
    assert r.output.strip() == f"{HERE / 'broken-domain.pddl'}:8:1: cannot read PDDL: Expected ')'"


def test_missing_file():
    with pytest.raises(BccError, match="no such PDDL file"):
        import_pddl(str(HERE / "nope.pddl"), str(HERE / "gripper-3.pddl"))
