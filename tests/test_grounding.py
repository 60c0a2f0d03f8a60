"""The grounding layer: candidate tasks, task inference, IBM Model 2, the dataset, the CLI."""
from __future__ import annotations

import json
import random

import pytest
from bcc.cli import main
from bcc.compiler import compile_dungeon
from bcc.grounding.dataset import Dataset
from bcc.demonstration import Demonstration, from_actions, snapshot
from bcc.grounding.infer import explanations, optimal_steps
from bcc.grounding.learn import space_for
from bcc.grounding.tasks import canonical
from bcc.grounding.translation import IBMModel2, words
from bcc.solvers import Budget, get_solver
from click.testing import CliRunner
from conftest import compiled


def plan_for(name, goal=None):
    return get_solver("astar")(compiled(name, goal), Budget(time_limit=30)).plan


# ---- candidate tasks -----------------------------------------------------------------------

def test_candidates_come_from_the_domain_and_the_dungeon():
    space = space_for("four_rooms")
    texts = {t.text for t in space.tasks(space.model.initial)}
    # the agent starts in the red room, so that is no task; the three others are
    assert {"agentInRoom(agent, orange)", "agentInRoom(agent, green)", "agentInRoom(agent, blue)"} <= texts
    assert "agentInRoom(agent, red)" not in texts
    assert not any("blockIsType" in t for t in texts)          # never made true: dropped
    assert "agentInRoom(agent, blue) and agentInRoom(agent, green)" not in texts   # exclusive
    bridge = {t.text for t in space_for("bridge").tasks(compiled("bridge").initial)}
    assert {"agentOnBlock(agent, gold)", "agentHasBlock(agent, burlap_stone)"} <= bridge
    assert "agentHasBlock(agent, burlap_stone) and agentOnBlock(agent, gold)" in bridge
    assert "agentHasBlock(agent, bedrock)" not in bridge       # bedrock is not mineable
    assert not any("agentInRoom" in t for t in bridge)          # the bridge has no rooms


def test_canonical_text():
    assert canonical("agentInRoom( agent,red )  and agentHasBlock(agent,burlap_stone)") == \
        "agentHasBlock(agent, burlap_stone) and agentInRoom(agent, red)"
    space = space_for("bridge")
    assert space.task("agentOnBlock(agent,gold)").text == "agentOnBlock(agent, gold)"
    assert space.task("agentInRoom(agent, red)") is None


def test_predicates_agree_with_the_compiled_goal():
    """Each candidate compiled by grounding/predicates.py must test states exactly like
    compile_dungeon(goal=...) does (an independent compilation of the same expression)."""
    rng = random.Random(1)
    for name in ("bridge", "four_rooms"):
        space = space_for(name)
        m = space.model
        states = [m.initial]
        for _ in range(300):   # a random walk over every action
            nxt = m.apply(rng.randrange(len(m.action_names)), states[-1])
            if nxt is not None and not m.is_failure(nxt):
                states.append(nxt)
        for task in space.tasks(m.initial)[:8]:
            reference = compile_dungeon(name, goal=task.text)
            test = [space.predicates.predicate(a.text) for a in task.atoms]
            assert [all(t(s) for t in test) for s in states] == [reference.is_goal(s) for s in states], task.text


# ---- task inference ------------------------------------------------------------------------

def test_a_plan_is_explained_by_its_goal():
    for name, goal in [("bridge", None), ("four_rooms", "agentInRoom(agent, green)"),
                       ("bridge", "agentHasBlock(agent, burlap_stone)"), ("easy_maze", None)]:
        m = compiled(name, goal)
        demo = from_actions(m, plan_for(name, goal))
        found = explanations(space_for(name), demo.states)
        assert found[0].task.text == m.goal_text, (name, [e.task.text for e in found])


def test_a_task_true_before_the_end_does_not_explain():
    # walk from the red room through the orange room's door area into the green room:
    # entering orange first means agentInRoom(orange) cannot explain the whole walk
    m = compiled("four_rooms")
    go_orange = plan_for("four_rooms", "agentInRoom(agent, orange)")
    mid = from_actions(m, go_orange).states[-1]
    rest = get_solver("bfs")(__import__("dataclasses").replace(
        compiled("four_rooms", "agentInRoom(agent, green)"), initial=mid), Budget(time_limit=30)).plan
    demo = from_actions(m, go_orange + rest)
    found = [e.task.text for e in explanations(space_for("four_rooms"), demo.states)]
    assert "agentInRoom(agent, green)" in found and "agentInRoom(agent, orange)" not in found


def test_optimal_steps_matches_bfs():
    space = space_for("bridge")
    task = space.task("agentOnBlock(agent, gold)")
    bfs = get_solver("bfs")(compiled("bridge"), Budget(time_limit=60))
    assert optimal_steps(space, task, space.model.initial, 100) == bfs.cost


# ---- IBM Model 2 ---------------------------------------------------------------------------

ROOMS = [("go to the red room", ["agentInRoom", "red"]), ("walk into the blue room", ["agentInRoom", "blue"]),
         ("go to the blue room", ["agentInRoom", "blue"]), ("enter the green room", ["agentInRoom", "green"]),
         ("stand on the gold block", ["agentOnBlock", "gold"]), ("go to the gold block", ["agentOnBlock", "gold"]),
         ("pick up the stone", ["agentHasBlock", "burlap_stone"]), ("get a stone", ["agentHasBlock", "burlap_stone"])]


def test_em_learns_word_alignments():
    model = IBMModel2.train([(words(c), [(tuple(t), 1.0, t[0])]) for c, t in ROOMS])
    assert model.lexical("red", "red") > 5 * model.lexical("red", "blue")
    assert model.lexical("gold", "gold") > 5 * model.lexical("gold", "agentInRoom")
    ll = {t: model.log_likelihood(words("walk to the green room"), t)
          for t in [("agentInRoom", "green"), ("agentInRoom", "red"), ("agentOnBlock", "gold")]}
    assert max(ll, key=ll.get) == ("agentInRoom", "green")
    # unseen words are left out; chance is the baseline
    assert model.log_likelihood(words("zzz go to the red room"), ("agentInRoom", "red")) == \
        model.log_likelihood(words("go to the red room"), ("agentInRoom", "red"))
    assert model.log_likelihood(words("go to the red room"), ("agentInRoom", "red")) > model.chance(words("go to the red room"))


def test_em_resolves_an_ambiguous_latent_task(tmp_path):
    """A pair whose demonstration also entered the blue room: EM picks the reading the words support."""
    pairs = [(words(c), [(tuple(t), 1.0, t[0])]) for c, t in ROOMS]
    ambiguous = (words("walk to the gold block"), [(("agentOnBlock", "gold"), 1.0, "agentOnBlock"),
                                                    (("agentInRoom", "blue"), 1.0, "agentInRoom")])
    model = IBMModel2.train(pairs + [ambiguous])
    e = ambiguous[0]
    assert model.log_likelihood(e, ("agentOnBlock", "gold")) > model.log_likelihood(e, ("agentInRoom", "blue"))
    path = tmp_path / "m.json"
    model.save(path)
    again = IBMModel2.load(path)
    assert again.log_likelihood(e, ("agentOnBlock", "gold")) == pytest.approx(model.log_likelihood(e, ("agentOnBlock", "gold")))


# ---- dataset -------------------------------------------------------------------------------

def _one_shot_demo(path):
    """The one-shot demonstration: two steps from the gold in the bridge, at (5, 3) facing
    south (rotationalDirection 0), then move_forward twice onto the gold at (5, 5)."""
    m = compiled("bridge")
    s = snapshot(m, m.initial)
    s["variables"].update({"agent.x": 5, "agent.z": 3, "agent.rotationalDirection": 0})
    path.write_text(json.dumps({"format": "bcc-demonstration/1", "dungeon": "bridge", "command": "go to the gold block",
                                "start": s, "actions": ["move_forward", "move_forward"]}))
    return path


def test_dataset_rows(tmp_path):
    data = Dataset(tmp_path / "d.sqlite")
    with pytest.raises(Exception, match="explains no task"):
        data.add_pair("x", "bridge", {}, [])
    data.add_pair("go to the gold block", "bridge", {"format": "bcc-demonstration/1"},
                  [{"task": "agentOnBlock(agent, gold)", "tokens": ["agentOnBlock", "gold"], "weight": 1.0}])
    rows = data.pairs()
    assert [r["task"] for r in rows] == ["agentOnBlock(agent, gold)"] and data.count() == 1
    assert data.integrity() == "ok"


# ---- CLI -----------------------------------------------------------------------------------

def run(*args, input=None):
    return CliRunner().invoke(main, list(args), input=input)


def test_one_shot_transfer(tmp_path):
    demo = _one_shot_demo(tmp_path / "demo.json")
    db = str(tmp_path / "d.sqlite")
    r = run("learn", "bridge", "go to the gold block", "--demo", str(demo), "--db", db, "--json")
    assert r.exit_code == 0, r.output
    assert json.loads(r.output)["task"] == "agentOnBlock(agent, gold)"
    assert run("train", "--db", db).exit_code == 0
    r = run("command", "bridge", "go to the gold block", "--db", db, "--json")
    assert r.exit_code == 0, r.output
    out = json.loads(r.output)
    assert out["task"] == "agentOnBlock(agent, gold)" and out["solved"]
    assert {"task", "candidates", "solved", "plan", "cost"} <= set(out)
    # the plan is the mine-and-bridge solution: it mines and places the stone, reaches the
    # gold, and is as short as BFS's (an independent optimal solver)
    assert "destroy_block" in out["plan"] and "place_block" in out["plan"]
    m = compiled("bridge")
    s = from_actions(m, out["plan"]).states[-1]
    assert m.is_goal(s)
    assert out["cost"] == get_solver("bfs")(m, Budget(time_limit=60)).cost
    r = run("command", "easy_maze", "go to the gold block", "--db", db, "--json")
    out = json.loads(r.output)
    assert r.exit_code == 0 and out["task"] == "agentOnBlock(agent, gold)" and out["solved"]
    assert compiled("easy_maze").is_goal(from_actions(compiled("easy_maze"), out["plan"]).states[-1])
    # unknown words do not crash; a command made of them is not understood (exit 1)
    r = run("command", "bridge", "please go to the gold block now", "--db", db, "--json")
    assert r.exit_code == 0 and set(json.loads(r.output)["unknown_words"]) == {"please", "now"}
    r = run("command", "bridge", "fly to the moon", "--db", db)
    assert r.exit_code == 1 and "not understood" in r.output
    r = run("command", "bridge", "xyzzy", "--db", db, "--json")
    assert r.exit_code == 1 and json.loads(r.output)["task"] is None


def test_train_on_an_empty_dataset_is_bad_input(tmp_path):
    r = run("train", "--db", str(tmp_path / "e.sqlite"))
    assert r.exit_code == 2 and "no pairs" in r.output


def test_learn_rejects_a_demonstration_that_achieves_nothing(tmp_path):
    p = tmp_path / "d.json"
    p.write_text(json.dumps({"format": "bcc-demonstration/1", "dungeon": "bridge", "actions": ["rotate_left"]}))
    r = run("learn", "bridge", "turn left", "--demo", str(p), "--db", str(tmp_path / "d.sqlite"))
    assert r.exit_code == 2 and "explains no task" in r.output


def test_play_records_a_demonstration(tmp_path):
    rec = tmp_path / "demo.json"
    # a, a: turn round; w: step south; s: look down; x: mine the stone; then an unknown key and quit
    r = run("play", "bridge", "--record", str(rec), "--command", "get a stone", input="aa\nwsx\n?\nq\n")
    assert r.exit_code == 0, r.output
    assert "w=move_forward" in r.output and "s=look_down" in r.output
    # the item in hand is the selected slot's; the mined stone is carried, not held
    assert "slot 0 in hand: diamond_pickaxe x1; also carrying burlap_stone x1" in r.output
    demo = Demonstration.load(rec)
    assert demo.actions == ["rotate_left", "rotate_left", "move_forward", "look_down", "destroy_block"]
    assert demo.command == "get a stone"
    r = run("learn", "bridge", "get a stone", "--demo", str(rec), "--db", str(tmp_path / "d.sqlite"), "--json")
    assert json.loads(r.output)["task"] == "agentHasBlock(agent, burlap_stone)"


def test_after_dying_play_waits_for_q_and_ignores_other_keys():
    """Stepping into lava ends the episode, but the session only ends at `q`: on a
    terminal, keys typed after a sudden exit would go to the shell."""
    from bcc.compiler import compile_dungeon
    from bcc.grounding.play import play
    model = compile_dungeon("bridge")
    # bridge: the agent starts at (1, 3) facing north; d, d turn it east... (3, 3) is lava:
    # turn right (east), step, step into the lava.
    frames = []
    states = play(model, iter("dwwwwaq"), frames.append)
    assert model.is_failure(states[-1])
    assert "you died" in frames[-1] and "Press q to quit" in frames[-1]
    assert len(states) == 3 + 1  # the start and three moves: the keys after death changed nothing
