"""Commands given as steps on the map (grounding/steps.py): "go down four, left five, up two".

`route_line` (tests/data/route_line.yaml) is three rooms in a row, a doorway in each wall:

    x  0123456789012
       #############
       #...#...#.C.#      kitchen (x 1-3) | hall (x 5-7) | study (x 9-11)
       #.S.........#      doorways at (4, 2) and (8, 2); z grows downwards (south)
       #...#...#...#
       #############

The agent starts at (2, 2) facing east, the chair stands at (10, 1). `cleanup` is the
corpus's world (dungeons/cleanup.yaml). Every expected end below is read off these
pictures by hand.
"""
from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from bcc.errors import BccError
from bcc.grounding import route, steps
from bcc.grounding.learn import space_for
from bcc.grounding.route_model import RouteModel
from bcc.grounding.steps import Move

LINE = str(Path(__file__).parent / "data" / "route_line.yaml")
EXACT = 60.0         # a fault weighs exp(-60): only the reading as said counts


def scene(ref: str = LINE):
    return route.scene_of(space_for(ref))


def ends(command: str, ref: str = LINE, beta: float = EXACT) -> dict:
    """{(agent's room, chair's room, chair moved): share}, shares over 1e-9 rounded."""
    out: dict = {}
    for share, o in route.read(command, scene(ref), beta):
        (_, room, moved), = o.things
        key = (o.agent, room, moved)
        out[key] = out.get(key, 0.0) + share
    return {k: round(v, 6) for k, v in out.items() if v > 1e-9}


def test_the_map_is_read_from_the_dungeon():
    cells = scene().world.map
    assert cells.start == (2, 2) and cells.facing == "east"
    assert cells.compass == {"north": (0, -1), "south": (0, 1), "east": (1, 0), "west": (-1, 0)}
    assert cells.things == {"chair": (10, 1)}
    assert cells.room[(4, 2)] is None and cells.room[(5, 1)] == "hall" and (4, 1) not in cells.room


@pytest.mark.parametrize("command, expected", [
    ("go down four left five up two", [Move("south", 4), Move("west", 5), Move("north", 2)]),
    ("three steps down , two over", [Move("south", 3), Move("sideways", 2)]),
    ("move south three spaces then west twice", [Move("south", 3), Move("west", 2)]),
    ("go north to spaces", [Move("north", 2)]),
    ("go down and left", [Move("south"), Move("west")]),
    ("turn right go one step", [Move("turn-right"), Move("ahead", 1)]),
    ("go 3 steps east", [Move("east", 3)]),
])
def test_moves_are_read_with_their_counts(command, expected):
    assert steps.moves(command, scene().world.map.compass) == expected


@pytest.mark.parametrize("command, expected", [
    # (2, 2) east 7: 3, 4 (door), 5, 6, 7 (hall), 8 (door), 9: the study
    ("go right seven", {("study", "study", False): 1.0}),
    ("go east 3", {("hall", "study", False): 1.0}),
    # no count: a stop on entering each room, (5, 2) the hall and (9, 2) the study, or as
    # far as it goes, (11, 2) in the study: a third each
    ("go right", {("hall", "study", False): round(1 / 3, 6), ("study", "study", False): round(2 / 3, 6)}),
    # a word a step: (3, 2), the doorway (4, 2), (5, 2) in the hall
    ("right , right , right", {("hall", "study", False): 1.0}),
    # (2, 2) north one is (2, 1), still the kitchen; then right one is (3, 1)
    ("go up one , right one", {("kitchen", "study", False): 1.0}),
    # right 7 to (9, 2), up 1 to (9, 1), right 1 walks into the chair and pushes it to (11, 1)
    ("right seven , up one , right one", {("study", "study", False): 1.0}),
    # facing east, a right turn faces south: one step to (2, 3); the kitchen
    ("turn right and go one step", {("kitchen", "study", False): 1.0}),
    # ahead is east: 6 steps end in the doorway at (8, 2), in no room
    ("go forward six", {(None, "study", False): 1.0}),
])
def test_steps_end_where_the_map_says(command, expected):
    assert ends(command) == expected


def test_a_pushed_chair_ends_in_another_room():
    # cleanup: the agent at (6, 2), the chair at (2, 6). Down 5 to (6, 7), left 5 to (1, 7),
    # up 1 to (1, 6), right 4 pushes the chair from (2, 6) to (6, 6) (the agent at (5, 6)),
    # down 1, right 1 to (6, 7), up 3 pushes it through the doorway (6, 4) to (6, 3): the blue
    # room, the agent in the doorway below; down 1, left 4 to (2, 5), up 2 through the green
    # room's doorway (2, 4) to (2, 3): the green room.
    got = ends("go down five left five up one right four down one right one up three down one left four up two",
               "cleanup")
    assert got == {("green", "blue", True): 1.0}


def test_a_walk_without_counts_stops_where_people_stop():
    # cleanup, from (6, 2): south stops on entering the red room at (6, 5), or at the wall
    # (6, 7). From (6, 5) west stops below the green room's doorway at (2, 5), where the next
    # move (north) opens into it, or at the wall (1, 5); from (6, 7) only at the wall (1, 7).
    # North from (2, 5) ends in the green room ((2, 3) on entering it, or (2, 1)); from (1, 5)
    # it cannot take a step (a fault: nothing at this beta); from (1, 7) it ends at (1, 5),
    # red. Shares: green 1/2 x 1/2 = 1/4, red 1/2, normalised: 1/3 and 2/3.
    got = ends("go south then west then north", "cleanup")
    assert got == {("green", "red", False): round(1 / 3, 6), ("red", "red", False): round(2 / 3, 6)}


def test_miscounts_and_mirrored_frames_share_by_their_faults():
    # "right six" from (2, 2): six steps end in the doorway (8, 2); one fewer in the hall
    # (7, 2), one more in the study (9, 2), a fault each. Mirrored north/south (a fault) the
    # same. Mirrored east/west (a fault), left walks one step to (1, 2) and then into the
    # wall: 5 steps take 4 faults (+1 miscount), 6 take 5, 7 take 6 (+1): all the kitchen.
    b = 2.0
    f = math.exp(-b)
    said = 1 + f                                       # as said, and mirrored north/south
    kitchen = (f + f * f) * (math.exp(-5 * b) + math.exp(-5 * b) + math.exp(-7 * b))
    total = said * (1 + 2 * f) + kitchen
    got = ends("go right six", beta=b)
    assert got[(None, "study", False)] == pytest.approx(said / total, abs=1e-6)
    assert got[("hall", "study", False)] == pytest.approx(said * f / total, abs=1e-6)
    assert got[("study", "study", False)] == pytest.approx(said * f / total, abs=1e-6)
    assert got[("kitchen", "study", False)] == pytest.approx(kitchen / total, abs=1e-6)


def test_a_step_list_is_read_as_steps_a_route_as_a_route():
    # one direction, no count, and a room: the route reader's ("go to the hall")
    assert ends("go right to the hall") == {("hall", "study", False): 1.0}
    # one direction and nothing else: steps
    assert ends("go down") == {("kitchen", "study", False): 1.0}


def test_the_route_member_fits_the_weight_of_a_fault():
    rows = [("go right seven", "agentInRoom(agent, study)"), ("go east 3", "agentInRoom(agent, hall)"),
            ("go forward two", "agentInRoom(agent, kitchen)"), ("go right five", "agentInRoom(agent, hall)")]
    tasks = sorted({t for _, t in rows})
    sc = scene()
    model = RouteModel.train([(c, tasks, {t: 1.0}) for c, t in rows], [sc] * len(rows))
    assert model.beta in steps.BETAS
    again = RouteModel.from_json(model.to_json())
    assert again.beta == model.beta and again.weights == model.weights
    scores = model.log_posterior("go right seven", tasks, sc)
    assert tasks[max(range(len(tasks)), key=scores.__getitem__)] == "agentInRoom(agent, study)"
    with pytest.raises(BccError):
        RouteModel.from_json({"format": "bcc-route/1", "weights": {}, "beta": "high"})


def test_a_route_member_may_vote_on_steps_or_on_routes_only():
    rows = [("go right seven", "agentInRoom(agent, study)"), ("go to the hall", "agentInRoom(agent, hall)")]
    tasks = sorted({t for _, t in rows})
    sc = scene()
    examples = [(c, tasks, {t: 1.0}) for c, t in rows]
    steps_only = RouteModel.train(examples, [sc] * 2, reads="steps")
    routes_only = RouteModel.train(examples, [sc] * 2, reads="routes")
    assert steps_only.log_posterior("go right seven", tasks, sc) is not None
    assert steps_only.log_posterior("go to the hall", tasks, sc) is None
    assert routes_only.log_posterior("go to the hall", tasks, sc) is not None
    assert routes_only.log_posterior("go right seven", tasks, sc) is None
    assert all(f.startswith("steps:") for f in steps_only.weights)
    assert not any(f.startswith("steps:") for f in routes_only.weights)
    assert RouteModel.from_json(steps_only.to_json()).reads == "steps"
    with pytest.raises(BccError):
        RouteModel.train(examples, [sc] * 2, reads="doors")
    with pytest.raises(BccError):
        RouteModel.from_json({"format": "bcc-route/1", "weights": {}, "reads": "doors"})


WORDS = ["go", "up", "down", "left", "right", "north", "south", "east", "west", "over", "forward", "turn",
         "two", "three", "5", "0", "99", "steps", "twice", ",", "then", "the", "chair", "to", "room"]


@settings(max_examples=150, deadline=None)
@given(st.lists(st.sampled_from(WORDS), max_size=14), st.sampled_from(steps.BETAS))
def test_any_words_read_to_shares_that_sum_to_one(words, beta):
    sc = scene()
    got = route.read(" ".join(words), sc, beta)
    if got is None:
        return
    assert sum(s for s, _ in got) == pytest.approx(1.0)
    for _, o in got:
        assert o.agent in set(sc.world.rooms) | {None}


def test_cli_trains_on_steps_and_walks_new_ones(tmp_path):
    # route_hall_west: the map above with the agent in the hall at (5, 2). By hand, the
    # training commands end: left 2, right 6 at (9, 2), the study; right 2, left 6 at (1, 2),
    # the kitchen; left 1, right 5 at (9, 2); right 1, left 5 at (1, 2). Every command holds
    # "go left" and "go right", so the words are about even; the walk decides: right four to
    # (9, 2) then left seven to (2, 2), the kitchen; left four to (1, 2) then right eight to
    # (9, 2), the study.
    import json
    from click.testing import CliRunner
    from bcc.cli import main
    west = str(Path(__file__).parent / "data" / "route_hall_west.yaml")
    rows = [("go left two go right six", "study"), ("go right two go left six", "kitchen"),
            ("go left one go right five", "study"), ("go right one go left five", "kitchen")]
    pairs = tmp_path / "pairs.jsonl"
    pairs.write_text("".join(json.dumps({"command": c, "task": f"agentInRoom(agent, {t})", "dungeon": west}) + "\n"
                             for c, t in rows))
    db = str(tmp_path / "my.sqlite")
    r = CliRunner().invoke(main, ["train", "--pairs", str(pairs), "--db", db])
    assert r.exit_code == 0, r.output
    for command, end in (("go right four go left seven", "kitchen"), ("go left four go right eight", "study")):
        r = CliRunner().invoke(main, ["command", west, command, "--db", db, "--json"])
        assert r.exit_code == 0, r.output
        out = json.loads(r.stdout)
        assert out["task"] == f"agentInRoom(agent, {end})" and out["solved"], out
