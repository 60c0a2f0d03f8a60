"""Commands read against the world (issue 32, item 3): rooms and doors read from the map
(grounding/world.py), the route a command describes and where it ends (grounding/route.py),
and the member that turns where a route ends into a task (grounding/route_model.py).

The two hand-made dungeons are three rooms in a row, a doorway in each wall between them:

    #############
    #...#...#.C.#      kitchen (x 1-3, colour white) | hall (x 5-7, orange) | study (x 9-11, green)
    #.S.........#      doorways at (4, 2) and (8, 2)
    #...#...#...#
    #############

In `route_line` the agent starts in the kitchen at (2, 2) and the chair stands in the
study; `route_line_east` is its mirror image (the agent in the study, the chair in the
kitchen). Every expected end below is read off this picture by hand.
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import given, settings, strategies as st

from bcc.cli import main
from bcc.grounding import route
from bcc.grounding.ensemble import Ensemble, member_scores, vote
from bcc.grounding.learn import candidates, space_for
from bcc.grounding.route_model import RouteModel, features
from bcc.grounding.world import read_world

DATA = Path(__file__).parent / "data"
LINE = str(DATA / "route_line.yaml")
EAST = str(DATA / "route_line_east.yaml")


def scene(ref: str):
    return route.scene_of(space_for(ref))


def ends(command: str, ref: str = LINE) -> dict:
    """{(agent's room, chair's room): share} of the command's reading."""
    out: dict = {}
    for share, o in route.read(command, scene(ref)):
        key = (o.agent, dict((t, r) for t, r, _ in o.things)["chair"])
        out[key] = out.get(key, 0.0) + share
    return {k: round(v, 6) for k, v in out.items()}


def test_rooms_doors_and_things_come_from_the_map():
    world = read_world(space_for(LINE))
    assert set(world.rooms) == {"kitchen", "hall", "study"}
    assert world.rooms["kitchen"] == {"kitchen", "white"}         # a room's name and its colour field
    # the doorway in x = 4 is 2 steps from the start (2, 2), the one in x = 8 six: nearest first
    assert [(d.rooms, d.position) for d in world.doors] == [
        (frozenset({"kitchen", "hall"}), (4, 2)), (frozenset({"hall", "study"}), (8, 2))]
    assert world.neighbours == {"kitchen": {"hall": [0]}, "hall": {"kitchen": [0], "study": [1]},
                                "study": {"hall": [1]}}
    assert set(world.things) == {"chair"}                         # bedrock lies in every room: no thing
    s = scene(LINE)
    assert (s.agent, s.things) == ("kitchen", (("chair", "study"),))
    assert scene(EAST).agent == "study" and scene(EAST).things == (("chair", "kitchen"),)


def test_a_dungeon_without_rooms_has_no_world_and_no_route():
    assert read_world(space_for("grid")) is None
    assert route.scene_of(space_for("grid")) is None
    assert route.read("go through the door", None) is None


@pytest.mark.parametrize("command, expected", [
    # one door out of the kitchen: through it is the hall
    ("go through the door", {("hall", "study"): 1.0}),
    # the first door (kitchen-hall), then the second (hall-study)
    ("go through the first door , then the second", {("study", "study"): 1.0}),
    # the next room from the kitchen is the hall; the one after it, not yet been in, the study
    ("go to the next room then go to the next room", {("study", "study"): 1.0}),
    # a room by its colour field: the study is green
    ("go to the green room", {("study", "study"): 1.0}),
    # to the study (through the hall), then back to the room it came from: the hall
    ("go to the study , then back to the room you came from", {("hall", "study"): 1.0}),
    # the chair is in the study; carried to where the agent started: the kitchen
    ("bring the chair to the room you started in", {("kitchen", "kitchen"): 1.0}),
    ("push the chair back into the original room", {("kitchen", "kitchen"): 1.0}),
    # the thing by a word the dungeon does not know, after a verb of carrying
    ("push the box to the hall", {("hall", "hall"): 1.0}),
    # the chair left in the hall once it got there; the agent goes on to the kitchen
    ("bring the chair to the hall , then go to the kitchen", {("kitchen", "hall"): 1.0}),
    # a colour the dungeon does not have: a room other than the kitchen (where the agent is)
    # and not named elsewhere in the command, either equally likely
    ("go to the pink room", {("hall", "study"): 0.5, ("study", "study"): 0.5}),
    ("go to the study , then go to the pink room", {("kitchen", "study"): 0.5, ("hall", "study"): 0.5}),
    # "put" takes the thing (a box, by a word the dungeon does not know) along, and "in the
    # hall" is where it goes, not where it stands (as in "move the chair in the study to ...")
    ("put the box in the hall", {("hall", "hall"): 1.0}),
    ("move the chair in the study to the hall", {("hall", "hall"): 1.0}),
    # standing in a door at the end: on either side
    ("go to the door", {("kitchen", "study"): 0.5, ("hall", "study"): 0.5}),
])
def test_routes_end_where_the_map_says(command, expected):
    assert ends(command) == expected


def test_the_same_words_end_elsewhere_in_another_map():
    # the mirror image: from the study, the first door leads to the hall, the second to the kitchen
    assert ends("go through the first door , then the second", EAST) == {("kitchen", "kitchen"): 1.0}
    assert ends("bring the chair to the room you started in", EAST) == {("study", "study"): 1.0}


def test_commands_that_are_no_route_are_not_read():
    assert route.read("please do it now", scene(LINE)) is None
    assert route.read("", scene(LINE)) is None
    # turns alone walk nowhere
    assert route.read("turn left , turn right", scene(LINE)) is None


def test_an_unknown_word_names_the_same_room_each_time():
    # "pink" is bound once: hall or study, and the chair ends where the agent went first
    got = ends("go to the pink room , then go to the kitchen , then bring the chair to the pink room")
    assert got == {("hall", "hall"): 0.5, ("study", "study"): 0.5}


def _examples(ref: str, rows):
    return [(c, candidates(ref), {t: 1.0}) for c, t in rows]


TRAIN = [("go through the door", "agentInRoom(agent, hall)"),
         ("go to the study", "agentInRoom(agent, study)"),
         ("bring the chair to the hall", "blockInRoom(chair, hall)"),
         ("bring the chair to the kitchen", "blockInRoom(chair, kitchen)"),
         ("go to the next room", "agentInRoom(agent, hall)"),
         ("go through the first door , then the second", "agentInRoom(agent, study)")]


def test_route_model_learns_which_task_an_outcome_asks_for():
    examples = _examples(LINE, TRAIN)
    model = RouteModel.train(examples, [scene(LINE)] * len(examples))
    assert model.weights["agent:end:moved"] > 0 and model.weights["thing:end:moved"] > 0
    tasks = candidates(EAST)
    # in the other map the words end elsewhere, and so does the task
    lp = model.log_posterior("go through the first door , then the second", tasks, scene(EAST))
    assert tasks[max(range(len(tasks)), key=lp.__getitem__)] == "agentInRoom(agent, kitchen)"
    lp = model.log_posterior("bring the chair to the room you started in", tasks, scene(EAST))
    assert tasks[max(range(len(tasks)), key=lp.__getitem__)] == "blockInRoom(chair, study)"
    assert model.log_posterior("please do it now", tasks, scene(EAST)) is None     # no route: abstains
    assert model.log_posterior("go through the door", tasks, None) is None      # no world: abstains
    again = RouteModel.from_json(json.loads(json.dumps(model.to_json())))
    assert again.weights == model.weights


def test_features_relate_atoms_to_the_outcome_not_to_names():
    outcomes = route.read("bring the chair to the hall", scene(LINE))
    f = features("blockInRoom(chair, hall)", outcomes, scene(LINE))
    assert f == {"atoms:1": 1.0, "agent:none:with-moved-thing": 1.0, "thing:end:moved": 1.0}
    f = features("agentInRoom(agent, kitchen) and blockInRoom(chair, study)", outcomes, scene(LINE))
    assert f == {"atoms:2": 1.0, "agent:start:moved": 1.0, "thing:start:moved": 1.0}


def test_an_abstaining_route_member_leaves_the_vote_to_the_others():
    examples = _examples(LINE, TRAIN)
    scenes = [scene(LINE)] * len(examples)
    from bcc.grounding.loglinear import LogLinear
    words = LogLinear.train(examples)
    ens = Ensemble([words, RouteModel.train(examples, scenes)], [1.0, 1.0])
    tasks = candidates(LINE)
    alone = vote([1.0], [words.log_posterior("please do it now", tasks)], [True])
    assert list(ens.log_posterior("please do it now", tasks, scene(LINE))) == pytest.approx(list(alone))
    scores, knows = member_scores(ens.members, ens.weights, "go through the door", tasks, scene(LINE))
    assert knows == [True, True] and all(s is not None for s in scores)
    _, knows = member_scores(ens.members, ens.weights, "go through the door", tasks, None)
    assert knows == [True, False]
    with pytest.raises(Exception, match="a member that reads words"):
        Ensemble([RouteModel({})], [1.0])


ROOM_WORDS = {"kitchen": ["kitchen", "white"], "hall": ["hall", "orange"], "study": ["study", "green"]}


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(sorted(ROOM_WORDS)), st.integers(0, 1),
                          st.sampled_from(["go to the {} room", "walk into the {} room", "then the {} room",
                                           "head to {}"])), min_size=1, max_size=5))
def test_a_route_of_named_rooms_ends_in_the_last(steps):
    command = " , ".join(form.format(ROOM_WORDS[room][k]) for room, k, form in steps)
    assert ends(command) == {(steps[-1][0], "study"): 1.0}


@settings(max_examples=150, deadline=None)
@given(st.lists(st.sampled_from(["go", "to", "the", "door", "room", "through", "back", "then", ",", "chair", "it",
                                 "bring", "other", "first", "second", "pink", "green", "hall", "started", "drop",
                                 "in", "next", "leave", "exit", "box", "push", "same", "of", "you"]), max_size=14))
def test_any_words_read_as_a_distribution_over_rooms(words):
    got = route.read(" ".join(words), scene(LINE))
    if got is None:
        return
    assert sum(share for share, _ in got) == pytest.approx(1.0)
    for share, o in got:
        assert share > 0 and o.agent in {"kitchen", "hall", "study"}
        assert all(r in {"kitchen", "hall", "study", None} for _, r, _ in o.things)


def test_cli_trains_the_route_member_and_reads_a_route_in_each_map(tmp_path):
    # route_hall_west and route_hall_east: the map above with the agent in the hall, at (5, 2)
    # next to the west doorway or at (7, 2) next to the east one, so the first door leads to
    # the kitchen or to the study. The same words ask for different tasks in the two maps,
    # both tasks candidates in each: the words alone cannot tell them apart, the route can.
    west, east = str(DATA / "route_hall_west.yaml"), str(DATA / "route_hall_east.yaml")
    rows = []
    for ref, first, other in ((west, "kitchen", "study"), (east, "study", "kitchen")):
        rows += [{"command": "go through the first door", "task": f"agentInRoom(agent, {first})", "dungeon": ref},
                 {"command": "go to the study", "task": "agentInRoom(agent, study)", "dungeon": ref},
                 {"command": "go to the kitchen", "task": "agentInRoom(agent, kitchen)", "dungeon": ref},
                 {"command": "bring the chair to the kitchen", "task": "blockInRoom(chair, kitchen)", "dungeon": ref}]
    pairs = tmp_path / "pairs.jsonl"
    pairs.write_text("".join(json.dumps(r) + "\n" for r in rows))
    db = str(tmp_path / "my.sqlite")
    r = CliRunner().invoke(main, ["train", "--pairs", str(pairs), "--db", db])
    assert r.exit_code == 0, r.output
    # by hand: through the first door into the kitchen (west) or the study (east), then
    # back across the hall and through the other door: the study (west), the kitchen (east)
    for ref, end in ((west, "study"), (east, "kitchen")):
        r = CliRunner().invoke(main, ["command", ref, "go through the first door , then the second door", "--db", db,
                                      "--json"])
        assert r.exit_code == 0, r.output
        out = json.loads(r.stdout)
        assert out["task"] == f"agentInRoom(agent, {end})" and out["solved"]
