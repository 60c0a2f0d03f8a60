"""`bcc import pddl`: PDDL compiled by bcc's own front-end, solved by bcc's solvers.

Optimal costs are derived by hand in the comments of tests/pddl/*.pddl; A* (blind on a
model without a grid) must find them, and BFS too where all actions cost the same.
No extra is needed: the front-end is bcc's own (grammar/pddl.lark).
"""
import json
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from bcc.cli import main
from bcc.errors import BccError
from bcc.pddl_io.importer import import_pddl
from bcc.solvers import Budget, get_solver

HERE = Path(__file__).parent / "pddl"
HAND_COSTS = {"gripper-3": ("gripper-domain", 9), "blocksworld-4": ("blocksworld-domain", 8),
              "logistics-2": ("logistics-domain", 9), "road-1": ("road-domain", 2),
              "sokoban-corridor": ("sokoban-domain", 2), "briefcase-1": ("briefcase-domain", 6),
              # lights-1: r2 is entered only when lit (l2 on), l2 is switched from r1, r1 is
              # entered only when lit (l1 on), l1 is switched from home: 4 steps. lights-2 also
              # wants r1 dark again: one switch-off of l1, from r2, while l2 is on: 5.
              "lights-1": ("lights-domain", 4), "lights-2": ("lights-domain", 5)}
UNIT = {"gripper-3", "blocksworld-4", "logistics-2", "briefcase-1", "lights-1", "lights-2"}


def load(problem):
    return import_pddl(str(HERE / f"{HAND_COSTS[problem][0]}.pddl"), str(HERE / f"{problem}.pddl"))


def replay(model, plan):
    s = model.initial
    cost = 0
    for name in plan:
        k = model.action_index(name)
        s = model.apply(k, s)
        assert s is not None, name
        cost += model.action_costs[k]
    return s, cost


@pytest.mark.parametrize("problem", sorted(HAND_COSTS))
def test_imported_problem_has_the_hand_derived_cost(problem):
    model = load(problem)
    for solver in ("astar", "idastar") + (("bfs",) if problem in UNIT else ()):
        result = get_solver(solver)(model, Budget(time_limit=60))
        assert result.solved and result.cost == HAND_COSTS[problem][1], solver
        end, cost = replay(model, result.plan)
        assert model.is_goal(end) and cost == result.cost


def test_the_road_costs_are_honoured():
    # a -> c costs 10, a -> b -> c costs 1 + 1: A* takes the two roads; BFS takes the one
    # road and reports its true cost, 10, saying a cheaper plan may exist.
    # Blind A* too: the goal is generated first by the expensive road, so it may test goals
    # at generation only when all costs are equal.
    model = load("road-1")
    for heuristic in ("auto", "blind"):
        astar = get_solver("astar")(model, Budget(time_limit=60), heuristic=heuristic)
        assert astar.plan == ["(drive a b)", "(drive b c)"] and astar.cost == 2, heuristic
    bfs = get_solver("bfs")(model, Budget(time_limit=60))
    assert bfs.plan == ["(drive a c)"] and bfs.cost == 10 and "cheaper plan" in bfs.message


def test_sokoban_moves_are_free_and_pushes_cost_one():
    # IPC rule: under (:metric minimize (total-cost)) an action without a cost effect costs 0.
    model = load("sokoban-corridor")
    costs = dict(zip(model.action_names, model.action_costs))
    assert costs["(move me p1 p2 right)"] == 0
    assert costs["(push-to-goal me box p3 p4 p5 right)"] == 1
    result = get_solver("astar")(model, Budget(time_limit=60))
    assert result.cost == 2 and len(result.plan) == 3


@pytest.mark.parametrize("problem", ["road-1", "sokoban-corridor"])
def test_blind_search_by_cost_matches_the_general_astar_loop(problem):
    # Costs differ (road: 1 and 10; sokoban: moves 0, pushes 1): blind A* runs the
    # generated search by cost (solvers/uniform_cost.py); without it, A*'s general loop.
    # Both find the hand-derived optimum; the general loop is the independent check.
    import dataclasses
    model = load(problem)
    assert model.data("cost_expander") is not None
    general = dataclasses.replace(model, lazy={k: v for k, v in model.lazy.items() if k != "cost_expander"})
    by_cost = get_solver("astar")(model, Budget(time_limit=60), heuristic="blind")
    plain = get_solver("astar")(general, Budget(time_limit=60), heuristic="blind")
    assert by_cost.solved and by_cost.cost == plain.cost == HAND_COSTS[problem][1]
    end, cost = replay(model, by_cost.plan)
    assert model.is_goal(end) and cost == by_cost.cost
    # every state stored at its cheapest cost: the generic loop stores the same states
    assert by_cost.stored <= plain.stored + len(model.action_names)


def test_search_by_cost_stops_at_the_state_budget_and_proves_no_plan(tmp_path):
    from bcc.solvers.base import Meter
    from bcc.solvers.uniform_cost import uniform_cost
    model = load("sokoban-corridor")
    expander, levels = model.data("cost_expander")
    assert levels == (0, 1)
    stopped = uniform_cost(model, Meter(Budget(max_states=3)), "astar", expander, levels)
    assert not stopped.solved and stopped.budget == "max_states" and stopped.stored <= 3 + len(model.action_names)
    # the goal made unreachable (at c and at a at once): the three states explored, no plan
    text = (HERE / "road-1.pddl").read_text().replace("(:goal (at c))", "(:goal (and (at c) (at a)))")
    (tmp_path / "p.pddl").write_text(text)
    road = import_pddl(str(HERE / "road-domain.pddl"), str(tmp_path / "p.pddl"))
    none = uniform_cost(road, Meter(Budget()), "astar", *road.data("cost_expander"))
    assert not none.solved and none.status == "no_solution" and none.stored == 3


def test_without_a_metric_every_action_costs_one(tmp_path):
    text = (HERE / "road-1.pddl").read_text().replace("(:metric minimize (total-cost))", "")
    (tmp_path / "p.pddl").write_text(text)
    model = import_pddl(str(HERE / "road-domain.pddl"), str(tmp_path / "p.pddl"))
    assert set(model.action_costs) == {1} and not model.report["action_costs"]
    assert get_solver("astar")(model, Budget(time_limit=60)).plan == ["(drive a c)"]


def test_static_facts_are_folded_and_unreachable_actions_are_not_grounded():
    model = load("road-1")
    # `road` and `road-length` never change: they are not state atoms; only `at` is.
    assert [v.label for v in model.variables] == ["(at a)", "(at c)", "(at b)"] or \
        sorted(v.label for v in model.variables) == ["(at a)", "(at b)", "(at c)"]
    # drive(c, ...) has no road: never grounded (3 roads, 3 actions)
    assert sorted(model.action_names) == ["(drive a b)", "(drive a c)", "(drive b c)"]


def test_actions_that_cannot_matter_for_the_goal_are_dropped(tmp_path):
    # The lamp can be switched forever, but the goal never reads it: relevance drops it.
    domain = tmp_path / "d.pddl"
    domain.write_text("(define (domain lamp) (:predicates (on) (there))\n"
                      " (:action switch :parameters () :precondition (not (on)) :effect (on))\n"
                      " (:action unswitch :parameters () :precondition (on) :effect (not (on)))\n"
                      " (:action go :parameters () :precondition (and) :effect (there)))\n")
    problem = tmp_path / "p.pddl"
    problem.write_text("(define (problem p) (:domain lamp) (:init) (:goal (there)))")
    model = import_pddl(str(domain), str(problem))
    assert model.action_names == ("(go)",) and len(model.variables) == 1


def test_either_types_constants_equality_and_negative_preconditions():
    model = load("briefcase-1")   # `either`, a constant, (not (= ?from ?to)), (not (in ?x)), forall/when
    assert "(move home home)" not in model.action_names
    assert "(move home office)" in model.action_names


def test_derived_predicates_are_replaced_by_their_rules():
    from bcc.pddl_io.lifted import read_domain
    dom = read_domain(str(HERE / "lights-domain.pddl"))
    switch_off = next(a for a in dom.actions if a.name == "switch-off")
    # (another-on ?y): its rule's own ?y is renamed apart, so it still compares two lamps
    inlined = [f for f in switch_off.pre[1] if f[0] == "exists"]
    assert len(inlined) == 1
    kind, ((bound, _),), body = inlined[0]
    assert bound.startswith("?y~") and body == ("and", (("atom", "on", (bound,)), ("not", ("=", "?y", bound))))
    # (safe ?b) has two rules: their `or`
    move = next(a for a in dom.actions if a.name == "move")
    assert [f[0] for f in move.pre[1]] == ["atom", "atom", "or"]
    # (dark ?r) is (not (lit ?r)), itself a rule: switching a lit room's lamp does not apply
    model = load("lights-1")
    s = model.apply(model.action_index("(switch-on home r1 l1)"), model.initial)
    assert s is not None and model.apply(model.action_index("(switch-on home r1 l1)"), s) is None


def test_conditional_effects_read_the_state_before_the_action():
    model = load("briefcase-1")
    s = model.apply(model.action_index("(put-in paper home)"), model.initial)
    s = model.apply(model.action_index("(move home office)"), s)
    facts = {v.label for v in model.variables if s >> v.index & 1}   # a state is an int: bit i is atom i
    assert "(at paper office)" in facts and "(at paper home)" not in facts and "(in paper)" in facts


@pytest.mark.parametrize("tree", ["by frequency", "by pruning"])
@pytest.mark.parametrize("problem", ["briefcase-1", "gripper-3", "road-1", "logistics-2", "blocksworld-4"])
def test_generated_successors_agree_with_the_ground_task_interpreter(problem, tree, monkeypatch):
    # The generated bit code (pddl_io/bits.py) against compile.action_functions, which
    # interprets the ground formulas one atom at a time: same successors in every
    # reachable state (conditional effects, negative preconditions and `or` included).
    # Blind search's `expand` moves to a sampled tree on big tasks: forced here at once.
    # `successors` answers its first calls from the ground task, then compiles: both checked.
    from bcc.pddl_io import compile as pddl_compile
    monkeypatch.setattr(pddl_compile, "SAMPLED_TREE_ACTIONS", 0 if tree == "by pruning" else 10 ** 9)
    monkeypatch.setattr(pddl_compile, "SAMPLE_STATES", 5)     # a sample of a few states only
    monkeypatch.setattr(pddl_compile, "PRUNED_TREE_AFTER", 0)
    monkeypatch.setattr(pddl_compile, "INTERPRETED_CALLS", 3)
    model = load(problem)
    (expand,) = model.search_layers()
    seen, todo = {model.initial}, [model.initial]
    goals = 0
    while todo:
        s = todo.pop()
        expected = [(a, n) for a in range(len(model.action_names)) if (n := model.apply_fns[a](s)) is not None]
        assert sorted(model.successors(s)) == sorted(expected)
        if not model.is_goal(s):   # the layer expander (one group), handed only non-goal states
            old = {t: "old" for t in list(seen)[::3] if t != s}
            parents, outs = {s: None, **old}, [[]]
            k = expand([s], parents, outs)
            new = list(dict.fromkeys(n for _, n in expected if n != s and n not in old))
            if any(model.is_goal(n) for n in new):
                # stopped at the first new goal, made last; nothing after it stored
                goals += 1
                assert k < 0 and 1 <= ~k <= len(expected)
                assert model.is_goal(outs[0][-1]) and not any(map(model.is_goal, outs[0][:-1]))
                assert len(set(outs[0])) == len(outs[0]) and set(outs[0]) <= set(new)
            else:
                assert k == len(expected) and sorted(outs[0]) == sorted(new)
            assert all(parents[n] == s for n in outs[0]) and len(parents) == 1 + len(old) + len(outs[0])
        for _, n in expected:
            if n not in seen:
                seen.add(n)
                todo.append(n)
    assert len(seen) >= 3 and goals


def test_the_pruning_tree_tests_rarely_true_atoms_first():
    # Atoms 0 and 1 are each needed by two of three actions; atom 0 holds in every sampled
    # state and atom 1 in none: testing 1 first skips two actions at once, testing 0 none.
    from bcc.pddl_io.bits import _tree_by_pruning, atom_shares
    keys = [[0, 1], [0, 1], [2]]
    shares = atom_shares([0b001, 0b101])
    assert shares == {0: 1.0, 2: 0.5}      # atom 1 never holds
    tree = _tree_by_pruning(keys, shares)
    assert list(tree) == [1, 2] and tree[1] == {0: {None: [0, 1]}} and tree[2] == {None: [2]}


def test_cli_import_solves_and_prints_pddl_actions():
    r = CliRunner().invoke(main, ["import", "pddl", str(HERE / "gripper-domain.pddl"), str(HERE / "gripper-3.pddl"),
                                  "--json"])
    assert r.exit_code == 0, r.output
    out = json.loads(r.output)
    assert out["cost"] == 9 and out["plan"][0].startswith("(pick ") and out["heuristic"] == "auto (blind)"


def test_the_plan_file_holds_one_action_a_line(tmp_path):
    plan = tmp_path / "plan.txt"
    r = CliRunner().invoke(main, ["import", "pddl", str(HERE / "road-domain.pddl"), str(HERE / "road-1.pddl"),
                                  "-o", str(plan)])
    assert r.exit_code == 0, r.output
    assert plan.read_text() == "(drive a b)\n(drive b c)\n"


def test_an_unsolvable_problem_exits_1(tmp_path):
    problem = tmp_path / "p.pddl"
    problem.write_text((HERE / "road-1.pddl").read_text().replace("(:goal (at c))", "(:goal (and (at c) (at a)))"))
    r = subprocess.run([sys.executable, "-m", "bcc", "import", "pddl", str(HERE / "road-domain.pddl"), str(problem)],
                       capture_output=True, text=True)
    assert r.returncode == 1 and "no plan" in r.stderr


def test_missing_file():
    with pytest.raises(BccError, match="no such PDDL file"):
        import_pddl(str(HERE / "nope.pddl"), str(HERE / "gripper-3.pddl"))


def test_import_does_not_load_third_party_planners():
    code = ("import sys; from bcc.pddl_io.importer import import_pddl; "
            f"import_pddl({str(HERE / 'gripper-domain.pddl')!r}, {str(HERE / 'gripper-3.pddl')!r}); "
            "print(sorted(m for m in sys.modules if m.split('.')[0] in "
            "('unified_planning', 'up_fast_downward', 'yaml', 'numpy')))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert "unified_planning" not in out and "up_fast_downward" not in out


def test_import_command_does_not_load_the_yaml_front_end():
    # Start-up is most of the time on small problems: `bcc import pddl` (A*, LM-cut) must not
    # load the YAML front-end, numpy or yaml (a quarter of a second together).
    code = ("import sys\nfrom bcc.cli import main\ntry:\n"
            f"    main(['import', 'pddl', {str(HERE / 'gripper-domain.pddl')!r}, {str(HERE / 'gripper-3.pddl')!r}])\n"
            "except SystemExit as e:\n    assert e.code == 0, e.code\n"
            "print('LOADED', sorted(m for m in sys.modules if m.split('.')[0] in ('yaml', 'numpy')"
            " or m == 'bcc.compiler.pipeline'))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.splitlines()[-1] == "LOADED []"


def test_generated_code_holds_no_name_from_the_files(tmp_path):
    # PDDL names are input: the generated successor function holds only indices.
    model = load("gripper-3")
    for word in ("ball1", "rooma", "pick", "carry", "left"):
        assert word not in model.source


def _fast_downward():
    fd = pytest.importorskip("bcc.solvers.fast_downward")
    if not fd.available():
        pytest.skip('Fast Downward is not installed: pip install "bcc[pddl]"')
    return fd


@pytest.mark.parametrize("problem", sorted(HAND_COSTS))
def test_costs_equal_fast_downwards_optimum(problem):
    fd = _fast_downward()
    domain = str(HERE / f"{HAND_COSTS[problem][0]}.pddl")
    theirs = fd.run(domain, str(HERE / f"{problem}.pddl"), "astar(blind())", 60)
    assert theirs.solved, theirs.message
    assert get_solver("astar")(load(problem), Budget(time_limit=60)).cost == theirs.cost


def test_the_fd_solver_runs_on_an_imported_model():
    _fast_downward()
    # It crashed with "TypeError: 'NoneType' object is not callable" (it exported the
    # model as if it were a compiled dungeon).
    r = subprocess.run([sys.executable, "-m", "bcc", "import", "pddl", str(HERE / "road-domain.pddl"),
                        str(HERE / "road-1.pddl"), "--solver", "fd", "--fd-search", "astar(blind())", "--json"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    out = json.loads(r.stdout)
    assert out["solver"] == "fd" and out["plan"] == ["(drive a b)", "(drive b c)"] and out["cost"] == 2


def test_gbfs_on_an_imported_problem_uses_the_relaxed_plan():
    # It used the grid's pattern database, h = 0 on a model without a grid.
    r = CliRunner().invoke(main, ["import", "pddl", str(HERE / "gripper-domain.pddl"), str(HERE / "gripper-3.pddl"),
                                  "--solver", "gbfs", "--json"])
    assert r.exit_code == 0, r.output
    out = json.loads(r.output)
    assert out["heuristic"] == "hff" and out["solved"] and out["cost"] >= 9


def test_parser_tables_are_cached_as_a_literal_and_a_damaged_entry_is_rebuilt(tmp_path, monkeypatch):
    # lark's parser reads what the fast scanner refuses (and says what is wrong): its
    # tables come from the cache, and the same items come back from the scanner.
    from bcc.pddl_io import read
    monkeypatch.setenv("BCC_CACHE_DIR", str(tmp_path))
    monkeypatch.delenv("BCC_NO_CACHE", raising=False)
    problem = str(HERE / "gripper-3.pddl")
    text = Path(problem).read_text()
    read._parser.cache_clear()
    try:
        fresh = read.parse_with_lark(text, problem)             # builds the tables, writes the entry
        entries = list(tmp_path.glob("pddl-parser-*.txt"))
        assert len(entries) == 1
        read._parser.cache_clear()
        assert read.parse_with_lark(text, problem) == fresh     # read back from the entry
        for damage in ("__import__('os').system('false')", "{'data': 1}", "((("):
            entries[0].write_text(damage)            # code is never run, only refused
            read._parser.cache_clear()
            got = read.parse_with_lark(text, problem)
            assert got == fresh and [(x.line, x.column) for x in got] == [(x.line, x.column) for x in fresh]
        assert read.read_sexpr(problem) == fresh
    finally:
        read._parser.cache_clear()


CHANNEL_DOMAIN = """(define (domain channel)
  (:requirements :strips)
  (:predicates (at ?x) (road ?x ?y) (free) (sent ?x) (have ?x))
  (:action move :parameters (?x ?y) :precondition (and (at ?x) (road ?x ?y))
           :effect (and (not (at ?x)) (at ?y)))
  (:action take :parameters (?x) :precondition (at ?x) :effect (have ?x))
  ; takes the channel and gives it back: (free) never changes
  (:action send :parameters (?x) :precondition (and (have ?x) (free))
           :effect (and (not (free)) (free) (sent ?x))))
"""
CHANNEL_PROBLEM = """(define (problem p) (:domain channel)
  (:objects a b c)
  (:init (at a) (road a b) (road b c) (road b a) (road c b) (free))
  (:goal (sent c)))
"""


def test_effects_that_change_nothing_neither_keep_atoms_nor_actions(tmp_path):
    # `(not (free)) (free)` leaves (free) true (deletes apply first), so (free) never
    # changes and folds away; sending a or b changes only atoms nothing relevant reads.
    # Optimal plan by hand: move a b, move b c, take c, send c = 4.
    (tmp_path / "d.pddl").write_text(CHANNEL_DOMAIN)
    (tmp_path / "p.pddl").write_text(CHANNEL_PROBLEM)
    model = import_pddl(str(tmp_path / "d.pddl"), str(tmp_path / "p.pddl"))
    task = model.data("ground_task")
    atoms = {task.atom_text(i) for i in range(len(task.atoms))}
    assert "(free)" not in atoms and "(sent a)" not in atoms and "(sent c)" in atoms
    assert sorted(a for a in model.action_names if a.startswith("(send")) == ["(send c)"]
    result = get_solver("bfs")(model, Budget())
    assert result.solved and result.cost == 4


def test_a_conditional_add_that_restores_a_deleted_precondition_is_kept(tmp_path):
    # `toggle` requires (on), deletes it, and adds it back only when (keep) holds (which
    # `forget` can clear, so it is no constant). By hand: the goal (lit) needs `light`, with
    # (on) and (seen), and only `toggle` gives (seen): toggle (keep holds, so on stays), light
    # = 2. Dropping the conditional add (its atom is required) would leave (on) false after
    # toggle, and no plan would exist.
    (tmp_path / "d.pddl").write_text("""(define (domain t) (:requirements :conditional-effects)
      (:predicates (on) (keep) (seen) (lit))
      (:action toggle :precondition (on) :effect (and (not (on)) (seen) (when (keep) (on))))
      (:action light :precondition (and (on) (seen)) :effect (lit))
      (:action forget :precondition (keep) :effect (not (keep))))""")
    (tmp_path / "p.pddl").write_text("(define (problem p) (:domain t) (:init (on) (keep)) (:goal (lit)))")
    model = import_pddl(str(tmp_path / "d.pddl"), str(tmp_path / "p.pddl"))
    result = get_solver("bfs")(model, Budget())
    assert result.solved and result.cost == 2 and result.plan == ["(toggle)", "(light)"]


@pytest.mark.parametrize("problem", sorted(HAND_COSTS))
@pytest.mark.parametrize("blind_seconds, lmcut_seconds, used", [
    (60.0, 60.0, "auto (blind)"),                               # blind search's slice suffices
    (1e-9, 60.0, "auto (blind, then lmcut)"),                   # blind stops at its first check
    (1e-9, 1e-9, "auto (blind, lmcut, then blind)")])           # both slices run out
def test_the_auto_portfolio_keeps_hand_derived_costs_in_every_phase(problem, blind_seconds, lmcut_seconds, used,
                                                                   monkeypatch):
    # `bcc import pddl` with A* auto: blind for a slice, LM-cut for a slice, then blind.
    # Whichever phase finds the plan, it has the hand-derived optimum and replays to the goal.
    from bcc.solvers import portfolio
    monkeypatch.setattr(portfolio, "BLIND_SECONDS", blind_seconds)
    monkeypatch.setattr(portfolio, "LMCUT_SECONDS", lmcut_seconds)
    model = load(problem)
    result = portfolio.solve(model, Budget(time_limit=600))
    assert result.solved and result.cost == HAND_COSTS[problem][1]
    assert result.heuristic == used
    end, cost = replay(model, result.plan)
    assert model.is_goal(end) and cost == result.cost


def test_the_portfolio_counts_every_phase():
    # Each phase starts afresh: the counters are the phases' sums, so an instant first
    # phase (one expansion, stopped at its first check) adds one to the last's count.
    from bcc.solvers import portfolio
    model = load("gripper-3")
    alone = get_solver("astar")(model, Budget(time_limit=600), heuristic="lmcut")
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(portfolio, "BLIND_SECONDS", 1e-9)
        both = portfolio.solve(model, Budget(time_limit=600))
    assert both.heuristic == "auto (blind, then lmcut)"
    assert both.expanded == alone.expanded + 1 and both.cost == alone.cost


def test_a_portfolio_slice_ends_on_cpu_time_at_a_progress_report(monkeypatch):
    # The slices count CPU seconds, checked when the search reports progress: a search
    # whose slice is spent is stopped at its report (its counters kept), and the next
    # phase runs. A stand-in for A* reports twice per call; the user's callback sees the
    # reports of phases that go on.
    from bcc.solvers import portfolio
    from bcc.solvers.base import Result
    calls, reports = [], []

    def fake_astar(model, budget, progress, heuristic):
        calls.append(heuristic)
        for n in (5, 9):
            progress(expanded=n, generated=2 * n, stored=n, seconds=0.5)
        return Result(solver="astar", solved=True, status="solved", plan=["(x)"], cost=1, expanded=3, generated=4,
                      stored=2, heuristic=heuristic, initial_h=1)

    import bcc.solvers
    monkeypatch.setattr(bcc.solvers, "get_solver", lambda name: fake_astar)
    monkeypatch.setattr(portfolio, "BLIND_SECONDS", -1.0)      # spent at the first report
    result = portfolio.solve(None, Budget(time_limit=600), progress=lambda **kw: reports.append(kw["expanded"]))
    assert calls == ["blind", "lmcut"] and result.heuristic == "auto (blind, then lmcut)"
    assert result.solved and result.expanded == 5 + 3 and result.generated == 10 + 4 and reports == [5, 9]


def test_the_portfolio_slices_follow_the_time_limit():
    from bcc.solvers.portfolio import phases
    assert phases(None) == [("blind", 1.0), ("lmcut", 2.0), ("blind", None)]
    assert phases(120) == [("blind", 1.0), ("lmcut", 2.0), ("blind", None)]
    assert phases(6) == [("blind", pytest.approx(0.3)), ("lmcut", pytest.approx(1.0)), ("blind", None)]


def test_the_portfolio_reports_a_proof_of_no_plan(tmp_path):
    # The goal needs (b), which no action adds: blind search's first phase explores the two
    # reachable states and proves there is no plan, so no other phase runs.
    (tmp_path / "d.pddl").write_text("""(define (domain n) (:predicates (a) (b))
      (:action flip :precondition (a) :effect (not (a))))""")
    (tmp_path / "p.pddl").write_text("(define (problem p) (:domain n) (:init (a)) (:goal (b)))")
    from bcc.solvers import portfolio
    result = portfolio.solve(import_pddl(str(tmp_path / "d.pddl"), str(tmp_path / "p.pddl")), Budget(time_limit=60))
    assert not result.solved and result.status == "no_solution"


def test_cli_import_uses_the_portfolio_for_astar_auto():
    r = CliRunner().invoke(main, ["import", "pddl", str(HERE / "gripper-domain.pddl"), str(HERE / "gripper-3.pddl"),
                                  "--json"])
    assert r.exit_code == 0 and json.loads(r.stdout)["heuristic"].startswith("auto (")


def _every_choice():
    """(solver, option name, value) for every built-in solver and every value of each of
    its options with choices; (solver, None, None) for its defaults."""
    from bcc.solvers import BUILTIN
    from bcc.solvers.options import options_of
    for name in BUILTIN:
        yield name, None, None
        for option in options_of(get_solver(name)):
            for value in option.allowed() or ():
                yield name, option.argument, value


@pytest.mark.parametrize("solver,option,value", list(_every_choice()))
def test_every_solver_and_choice_on_an_imported_task_solves_or_says_why(solver, option, value):
    """An imported task has an int state and no grid or agent: every solver and every choice
    either runs on it or refuses it as bad input (BccError, exit 2), never crashes (R-max's
    object-oriented learner, which perceives a grid around the agent, raised TypeError)."""
    model = load("gripper-3")
    options = {"episodes": 3} if solver in ("rmax", "qlearning") else {}
    if option is not None:
        options[option] = value
    try:
        result = get_solver(solver)(model, Budget(time_limit=20, max_states=200_000), **options)
    except BccError as exc:
        # the refusals name the alternative: R-max's oo model, and htn, which plans task networks
        assert "model=tabular" in exc.message or "bcc import hddl" in exc.message, exc.message
        return
    if result.solved:   # stepped, as a learner's plan may hold steps that changed nothing
        s = model.initial
        for name in result.plan:
            s = model.step(s, model.action_index(name))[0]
        assert model.is_goal(s)


TYPED_DERIVED = """(define (domain typed-derived)
  (:requirements :typing :derived-predicates)
  (:types a b - object)
  (:predicates (p ?x - object) (d ?x - a) (done))
  (:derived (d ?x - a) (p ?x))
  (:action go :parameters (?y - object) :precondition (d ?y) :effect (done)))
"""


@pytest.mark.parametrize("init,cost", [("(p o2)", None), ("(p o1) (p o2)", 1)])
def test_a_derived_predicate_holds_only_for_its_parameters_types(tmp_path, init, cost):
    # (d ?x - a) is (p ?x) for objects of type a only: o2 is a b, so (p o2) alone makes no
    # (d o2) and `go` never applies (Fast Downward's typed axiom agrees); (p o1) does
    (tmp_path / "d.pddl").write_text(TYPED_DERIVED)
    (tmp_path / "p.pddl").write_text(f"(define (problem t) (:domain typed-derived) (:objects o1 - a o2 - b)"
                                     f" (:init {init}) (:goal (done)))")
    model = import_pddl(str(tmp_path / "d.pddl"), str(tmp_path / "p.pddl"))
    result = get_solver("bfs")(model, Budget(time_limit=60))
    assert result.solved == (cost is not None) and (cost is None or result.cost == cost)
    if cost:
        assert result.plan == ["(go o1)"]
