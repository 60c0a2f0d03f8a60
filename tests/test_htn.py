"""The `htn` solver (solvers/htn/) on hand-made HDDL problems whose plans are derived by
hand below, its budgets, `bcc import hddl` end to end, and the independent verifier
(hddl/verify.py) on good and bad plans."""
from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from bcc.cli import main
from bcc.errors import BccError
from bcc.hddl.plan import ipc_plan_text
from bcc.hddl.read import read_hddl
from bcc.hddl.verify import verify
from bcc.solvers import Budget, get_solver

HERE = Path(__file__).parent / "hddl"
SHELVES = HERE / "shelves-domain.hddl"
htn = get_solver("htn")


def load(domain: str, problem: str):
    return read_hddl(str(HERE / f"{domain}-domain.hddl"), str(HERE / f"{problem}.hddl"))


def test_delivery_drives_to_the_package_and_on_to_its_destination():
    # By hand: deliver p1 d has one method, m-deliver, with ?from = c (p1 is at c) and the
    # one truck t1: get-to t1 c, load, get-to t1 d, unload. get-to t1 c from a: m-there
    # fails (t1 is at a), m-drive needs (road a c), so m-via via b (a's one road): drive
    # a b, then get-to t1 c from b by m-drive. get-to t1 d from c: m-drive.
    result = htn(load("delivery", "delivery-1"), Budget(time_limit=30))
    assert result.solved and result.plan == ["(drive t1 a b)", "(drive t1 b c)", "(load t1 p1 c)",
                                             "(drive t1 c d)", "(unload t1 p1 d)"]
    assert result.cost == 5


def test_a_loop_back_to_a_state_and_network_met_before_is_cut():
    # By hand (facts are bound in :init order): from b, m-via first takes b's first road, to a; from a the only road leads
    # back to b, where (t1 at b, get-to t1 d) is the network met at the start: cut. Back at
    # b the next road is c, and from c m-drive reaches d. Without loop detection the
    # search would drive a-b-a-b... for ever.
    result = htn(load("delivery", "delivery-2"), Budget(time_limit=30))
    assert result.solved and result.plan == ["(drive t1 b c)", "(drive t1 c d)"]
    assert result.expanded == 3   # get-to at b, at a, at c


def test_a_failed_subtask_backtracks_into_the_next_method_binding_and_forall_holds():
    # By hand: the :ordering puts store i1 first. store-free (3 steps) is tried before
    # store-swept (5), on slots in :init order: s1 passes the method's precondition but its
    # check fails (s1 is not clean), so the search backtracks to s2. tidy: tidy-done needs
    # (forall item: not in the bin), false while i2 is there; tidy-more stores i2: the only
    # free slot is s1, whose check fails again; store-swept sweeps (the forall effect cleans
    # the free s1) and stores i2 in s1. Then tidy-done holds.
    result = htn(load("shelves", "shelves-1"), Budget(time_limit=30))
    assert result.solved and result.plan == ["(move i1 bin s2)", "(check s2)", "(sweep)", "(move i2 bin s1)",
                                             "(check s1)"]
    tree = result.decomposition
    assert tree["root"] == [5, 6]
    assert tree["tasks"][0] == {"id": 5, "task": "store i1", "method": "store-free", "subtasks": [0, 1]}
    assert tree["tasks"][-1] == {"id": 9, "task": "tidy", "method": "tidy-done", "subtasks": []}


def test_no_plan_when_every_decomposition_fails(tmp_path):
    # Neither slot is clean and sweeping cleans only free slots: after i1 takes a slot the
    # sweep would clean the other, so make both slots taken by nothing but unclean and not
    # free: store-free has no slot, store-swept sweeps to no effect and meets itself again.
    problem = (HERE / "shelves-1.hddl").read_text().replace("(free s1) (free s2) (clean s2)", "")
    path = tmp_path / "p.hddl"
    path.write_text(problem)
    result = htn(read_hddl(str(HERE / "shelves-domain.hddl"), str(path)), Budget(time_limit=30))
    assert result.status == "no_solution" and not result.solved


def test_a_network_that_can_no_longer_add_a_goal_atom_is_dropped(monkeypatch):
    # flags-1: the goal (flagged) is added only by `raise`. m-tour and m-flag tie on the
    # estimate (2 each: the method and one step, `tour` costing 1 by m-done), so m-tour is
    # tried first; `tour` reaches only `visit`, which never adds (flagged): the network
    # (tour) is dropped before it is expanded, and m-flag raises the flag. Expanded: `top`
    # alone. Without the cut, `tour` is expanded once in each of the 2^8 states of seen
    # spots (every subset; a state met again is cut by loop detection) before the search
    # backs up to m-flag: 1 + 256.
    from bcc.solvers.htn import hddl_network
    result = htn(load("flags", "flags-1"), Budget(time_limit=30))
    assert result.solved and result.plan == ["(raise)"] and result.expanded == 1
    real = hddl_network.HddlNetwork.__init__

    def without_cut(self, problem):
        real(self, problem)
        self.goal_atoms = []
    monkeypatch.setattr(hddl_network.HddlNetwork, "__init__", without_cut)
    result = htn(load("flags", "flags-1"), Budget(time_limit=30))
    assert result.solved and result.plan == ["(raise)"] and result.expanded == 1 + 2 ** 8


def test_goal_reach_needs_the_chain_of_adders_and_reads_task_arguments():
    # goal (l2). obs2 alone adds it and requires (l1); obs1 adds (l1), requiring nothing:
    # needed atoms [(l2), (l1) for (l2)]. (l1) is unmet only while (l2) is.
    # Task t ?a: m-obs (= ?a x) -> obs2; m-other -> noop; r -> r (recursion) or t ?b.
    # t x may add (l2) (bit 0); t y may not (m-obs's constraint fails); t with its
    # argument unknown may; r reaches t with an unknown argument, so it may too.
    from types import SimpleNamespace as N
    from bcc.pddl_io.lifted_types import TRUE
    from bcc.solvers.htn.goal_reach import GoalReach

    def effect(pred, *args):
        return N(add=True, pred=pred, args=args, params=(), cond=TRUE)
    actions = [N(name="obs1", pre=TRUE, effects=[effect("l1")]),
               N(name="obs2", pre=("atom", "l1", ()), effects=[effect("l2")]),
               N(name="noop", pre=TRUE, effects=[])]
    methods = {"t": [N(task=("t", ("?a",)), pre=("=", "?a", "x"), subtasks=(("obs2", ()),)),
                     N(task=("t", ("?a",)), pre=TRUE, subtasks=(("noop", ()),))],
               "r": [N(task=("r", ()), pre=TRUE, subtasks=(("r", ()),)),
                     N(task=("r", ()), pre=TRUE, subtasks=(("t", ("?b",)),))]}
    reach = GoalReach(("atom", "l2", ()), actions, methods)
    assert reach.atoms == [("l2", ()), ("l1", ())] and reach.parent == [-1, 0]
    assert reach.unmet(set()) == 0b11 and reach.unmet({("l1", ())}) == 0b01 and reach.unmet({("l2", ())}) == 0
    assert reach.mask("obs1", ()) == 0b10 and reach.mask("obs2", ()) == 0b01
    assert reach.mask("t", ("x",)) == 0b01 and reach.mask("t", ("y",)) == 0 and reach.mask("t", (None,)) == 0b01
    assert reach.mask("r", ()) == 0b01


def test_the_state_budget_stops_the_search():
    result = htn(load("delivery", "delivery-2"), Budget(max_states=1, time_limit=30))
    assert result.status == "budget" and result.budget == "max_states"


def test_a_dungeon_is_refused_as_bad_input():
    from conftest import compiled
    with pytest.raises(BccError, match="plans task networks"):
        htn(compiled("grid"), Budget(time_limit=5))


# ---- the verifier ------------------------------------------------------------------------
def _ipc(domain: str, problem: str) -> tuple:
    task = load(domain, problem)
    result = htn(task, Budget(time_limit=30))
    return task, ipc_plan_text(result.plan, result.decomposition)


@pytest.mark.parametrize("domain,problem", [("delivery", "delivery-1"), ("delivery", "delivery-2"),
                                            ("shelves", "shelves-1")])
def test_the_verifier_accepts_the_planners_plans(domain, problem):
    task, text = _ipc(domain, problem)
    assert verify(task, text) is None


SHELVES_PLAN = """==>
0 move i1 bin s2
1 check s2
2 sweep
3 move i2 bin s1
4 check s1
root 5 6
5 store i1 -> store-free 0 1
6 tidy -> tidy-more 7 9
7 store i2 -> store-swept 2 8
8 store i2 -> store-free 3 4
9 tidy -> tidy-done
<==
"""


@pytest.mark.parametrize("old,new,why", [
    ("", "", None),   # the plan as written by hand is valid
    ("3 move i2 bin s1", "3 move i2 bin s2", "?s would be both"),
    ("7 store i2 -> store-swept 2 8\n8 store i2 -> store-free 3 4", "7 store i2 -> store-free 3 4\n8 store i2 -> "
     "store-swept 2 8", "line 2 is not part of the tree"),
    ("root 5 6", "root 6 5", "not the plan's order"),
    ("9 tidy -> tidy-done", "9 tidy -> tidy-more", "2 subtasks, found 0"),
    ("5 store i1 -> store-free 0 1", "5 store i1 -> store-free 0 1 2", "line 2 is used twice"),
    ("8 store i2 -> store-free 3 4", "8 store i2 -> store-free 3", "line 4 is not part of the tree"),
    ("4 check s1\n", "4 check s1\n11 check s1\n", "line 11 is not part of the tree"),
    ("6 tidy -> tidy-more 7 9", "6 tidy -> tidy-done 7 9", "0 subtasks, found 2"),
    ("0 move i1 bin s2\n1 check s2", "0 move i1 bin s1\n1 check s1", "(check s1): its precondition does not hold"),
    ("9 tidy -> tidy-done\n", "9 tidy -> tidy-done\n10 tidy -> tidy-done\n", "line 10 is not part of the tree"),
    ("2 sweep\n3 move i2 bin s1", "2 move i2 bin s1\n3 sweep", "line 2 is (move ...), the method's subtask is (sweep"),
    ("0 move i1 bin s2\n1 check s2", "1 check s2\n0 move i1 bin s2", "not the plan's order"),
    ("root 5 6", "root 5", "line 2 is not part of the tree"),
    ("root 5 6", "root 5 6 9", "line 9 is used twice"),
    ("1 check s2", "0 check s2", "id 0 is used for two lines"),                    # two actions
    ("5 store i1 -> store-free 0 1", "4 store i1 -> store-free 0 1", "id 4 is used for two lines"),  # action, task
    ("8 store i2 -> store-free 3 4", "7 store i2 -> store-free 3 4", "id 7 is used for two lines"),  # two tasks
])
def test_the_verifier_refuses_bad_plans_with_their_reason(old, new, why):
    # Each edit breaks one rule of hddl/verify.py's docstring: a method's variables bound
    # two ways, a line used nowhere, the root out of the network's order, a method with
    # the wrong number of subtasks, an action whose precondition fails, leaves out of order.
    task = load("shelves", "shelves-1")
    text = SHELVES_PLAN.replace(old, new, 1) if old else SHELVES_PLAN
    found = verify(task, text)
    assert (found is None) if why is None else (found is not None and why in found), found


def test_the_verifier_checks_method_preconditions_where_they_apply(tmp_path):
    # The same plan for a problem with a third item in the bin: every action still
    # applies, but tidy-done's forall (no item in the bin) fails where it is applied.
    problem = tmp_path / "p.hddl"
    problem.write_text((HERE / "shelves-1.hddl").read_text().replace("i1 i2 - item", "i1 i2 i3 - item").replace(
        "(on i2 bin)", "(on i2 bin) (on i3 bin)"))
    task = read_hddl(str(HERE / "shelves-domain.hddl"), str(problem))
    assert verify(task, SHELVES_PLAN) == "method tidy-done on (tidy): its precondition does not hold where it is applied"


def test_the_verifier_deletes_an_atom_that_is_false_without_complaint(tmp_path):
    # move also deletes (dusty bin), of a predicate no fact of the state has: no change, as
    # PDDL says (the verifier kept facts by predicate and failed on the unknown one).
    domain = tmp_path / "d.hddl"
    domain.write_text(SHELVES.read_text().replace("(clean ?s - slot))", "(clean ?s - slot) (dusty ?s - slot))").replace(
        "(not (free ?to))))", "(not (free ?to)) (not (dusty bin))))"))
    task = read_hddl(str(domain), str(HERE / "shelves-1.hddl"))
    assert verify(task, SHELVES_PLAN) is None


# ---- the command ---------------------------------------------------------------------------
def run(*args):
    return CliRunner().invoke(main, ["import", "hddl", *map(str, args)])


def test_cli_prints_the_plan_and_writes_both_files(tmp_path):
    plan, ipc = tmp_path / "plan.txt", tmp_path / "plan.ipc"
    r = run(HERE / "shelves-domain.hddl", HERE / "shelves-1.hddl", "-o", plan, "--ipc-plan", ipc)
    assert r.exit_code == 0, r.output
    assert r.stdout.splitlines() == ["(move i1 bin s2)", "(check s2)", "(sweep)", "(move i2 bin s1)", "(check s1)"]
    assert plan.read_text() == r.stdout
    assert ipc.read_text() == SHELVES_PLAN
    assert "solved shelves-1 with htn: cost 5, 5 steps" in r.stderr


def test_cli_json_carries_the_decomposition():
    r = run(HERE / "delivery-domain.hddl", HERE / "delivery-1.hddl", "--json")
    assert r.exit_code == 0
    data = json.loads(r.stdout)
    assert data["solved"] and data["cost"] == 5 and data["problem"] == "delivery-1" and data["methods"] == 4
    assert data["decomposition"]["root"] == [5]
    assert data["decomposition"]["tasks"][0]["method"] == "m-deliver"


def test_cli_bad_input_is_one_line_and_exit_2(tmp_path):
    bad = tmp_path / "d.hddl"
    bad.write_text((HERE / "shelves-domain.hddl").read_text().replace("(t2 (check ?s))", "(t2 (inspect ?s))"))
    r = run(bad, HERE / "shelves-1.hddl")
    assert r.exit_code == 2
    assert r.stderr.strip().count("\n") == 0 and "d.hddl:" in r.stderr and "'inspect' is neither" in r.stderr


def test_cli_no_plan_and_budget_exit_1(tmp_path):
    r = run(HERE / "delivery-domain.hddl", HERE / "delivery-2.hddl", "--max-states", "1")
    assert r.exit_code == 1 and "--max-states" in r.stderr
    problem = tmp_path / "p.hddl"
    problem.write_text((HERE / "delivery-2.hddl").read_text().replace("(road c d) (road d c)", ""))
    r = run(HERE / "delivery-domain.hddl", problem)
    assert r.exit_code == 1 and "no plan exists" in r.stderr


def test_cli_refuses_a_solver_of_dungeons():
    r = run(HERE / "delivery-domain.hddl", HERE / "delivery-1.hddl", "--solver", "astar")
    assert r.exit_code == 2 and "use --solver htn" in r.stderr
