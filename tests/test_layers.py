"""The layered search's pieces: which actions undo which and which commute
(compiler/inverses.py), checked against brute force; the generated layer expanders
(`Model.search_layers`) against `fresh`; every layer they reach against a search that
skips nothing; and plans and costs against independent solvers."""
import dataclasses
import functools
from collections import deque

import pytest

from bcc.compiler import compile_dungeon
from bcc.compiler.dungeon import shipped_dungeons
from bcc.compiler.inverses import commute, undoes
from bcc.solvers import Budget, get_solver


def reachable(model, limit=3000):
    """The first `limit` states a breadth-first walk over `successors` reaches, failing ones included."""
    seen, frontier = {model.initial: None}, deque([model.initial])
    while frontier and len(seen) < limit:
        state = frontier.popleft()
        for _, n in model.successors(state):
            if n not in seen:
                seen[n] = None
                frontier.append(n)
    return list(seen)


def by_index(model, key: str) -> dict:
    names = model.action_names
    return {names.index(a): [names.index(b) for b in bs] for a, bs in model.data("layer_skips")[key].items()}


def undone_by(model) -> dict:
    return by_index(model, "undone_by")


def skipped_after(model) -> dict:
    return by_index(model, "skipped_after")


@pytest.mark.parametrize("name", shipped_dungeons())
def test_every_inverse_found_undoes_its_action_on_every_reachable_state(name):
    model = compile_dungeon(name, prune=False)
    undo = undone_by(model)
    checked = 0
    for s in reachable(model):
        for a, bs in undo.items():
            t = model.apply(a, s)
            if t is None or t == s:
                continue
            for b in bs:
                assert model.apply(b, t) == s, (model.action_names[a], model.action_names[b])
                checked += 1
    assert checked or not undo


@pytest.mark.parametrize("name", shipped_dungeons())
def test_every_commuting_pair_found_commutes_on_every_reachable_state(name):
    """b is skipped after a, other than as a's inverse, only where a then b and b then a
    apply alike with the same result; and b comes first in the action order."""
    model = compile_dungeon(name, prune=False)
    undo, skips = undone_by(model), skipped_after(model)
    pairs = [(a, b) for a, bs in skips.items() for b in bs if b not in undo.get(a, ())]
    assert all(b < a for a, b in pairs)
    apply = model.apply
    for s in reachable(model):
        for a, b in pairs:
            ta, tb = apply(a, s), apply(b, s)
            assert (None if ta is None else apply(b, ta)) == (None if tb is None else apply(a, tb)), \
                (model.action_names[a], model.action_names[b])


def test_the_minecraft_turns_looks_and_item_changes():
    # By hand: rotate_left sets d = (d + 3) % 4 and rotate_right d = (d + 1) % 4, each the
    # other's inverse on all 4 facings; look_down sets looking = 1, look_ahead 0, so where
    # one changes the state the other puts it back. change_item (+1 mod 9) is undone by
    # no single action. Turning, looking and changing the item touch different variables
    # with no preconditions, so they commute; each is skipped after the later ones.
    # move_forward reads the facing and cells and writes the position and `alive`, which
    # the failure test reads; looking and changing the item touch none of these, and
    # write nothing the failure test or the goal (the position) reads: it is skipped
    # after them. destroy_block and place_block read the selected slot by its index (a
    # keyed attribute): never skipped.
    model = compile_dungeon("tough_maze")
    assert model.data("layer_skips") == {
        "undone_by": {"rotate_left": ["rotate_right"], "rotate_right": ["rotate_left"],
                      "look_down": ["look_ahead"], "look_ahead": ["look_down"]},
        "skipped_after": {"rotate_left": ["rotate_right"], "rotate_right": ["rotate_left"],
                          "look_down": ["move_forward", "rotate_left", "rotate_right", "look_ahead"],
                          "look_ahead": ["move_forward", "rotate_left", "rotate_right", "look_down"],
                          "change_item": ["move_forward", "rotate_left", "rotate_right", "look_down",
                                          "look_ahead"]}}
    assert model.compile_report()["layered_search"] == model.data("layer_skips")


def test_undoes_tries_every_value_where_the_action_changes_the_state():
    wrap = lambda s: bytes([(s[0] + 1) % 4])                      # turn: 3 -> 0
    back = lambda s: bytes([s[0] - 1]) if s[0] > 0 else None      # un-turn, not from 0
    back_wrap = lambda s: bytes([(s[0] + 3) % 4])
    assert not undoes(wrap, back, [(0, 3)], 1)        # fails only at 3 -> 0 -> (not applicable)
    assert undoes(wrap, back_wrap, [(0, 3)], 1)
    toggle = lambda s: bytes([1 - s[0]])
    assert undoes(toggle, toggle, [(0, 1)], 1)
    keep = lambda s: s
    assert not undoes(keep, keep, [(0, 3)], 1)        # never changes anything: nothing proven
    assert not undoes(lambda s: bytes([1]), lambda s: bytes([0]), [(0, 2)], 1)   # 2 -> 1 -> 0


def test_commute_needs_both_orders_to_apply_alike():
    inc = lambda s: bytes([s[0] + 1, s[1]]) if s[0] < 3 else None
    dec = lambda s: bytes([s[0] - 1, s[1]]) if s[0] > 0 else None
    flip = lambda s: bytes([s[0], 1 - s[1]])
    slots = [(0, 3), (1, 1)]
    assert commute(inc, flip, slots, 2) and commute(flip, dec, slots, 2)
    assert not commute(inc, dec, slots, 2)    # at 0: inc then dec works, dec then inc does not
    gated = lambda s: bytes([s[0], 1]) if s[0] == 0 else None    # applies only at 0
    assert not commute(inc, gated, slots, 2)  # at 0: gated then inc works, inc then gated does not


LINE_DOMAIN = """\
domain: lamps
types:
  tile: {values: [empty, floor, goal]}
classes:
  token:
    position: [x, y, z]
    attributes:
      x: {type: int, range: [0, width - 1]}
      y: {type: int, range: [0, 0]}
      z: {type: int, range: [0, 0]}
      lamp: {type: bool, default: false}
      dial: {type: int, range: [0, 3]}
  cell:
    key: [x, y, z]
    attributes:
      x: {type: int, range: [0, width - 1]}
      y: {type: int, range: [0, height - 1]}
      z: {type: int, range: [0, depth - 1]}
      kind: {type: tile, default: empty}
dungeon:
  grid: cell
  agent: token
functions:
  done: {params: {t: token}, body: "cell[t.x, 0, t.z].kind == goal and t.lamp and t.dial == 2"}
actions:
  right:
    params: {t: token}
    pre: t.x + 1 < width
    effect: t.x = t.x + 1
  left:
    params: {t: token}
    pre: t.x > 0
    effect: t.x = t.x - 1
  switch:
    params: {t: token}
    effect: t.lamp = not t.lamp
  turn:
    params: {t: token}
    effect: t.dial = (t.dial + 1) % 4
  unturn:
    params: {t: token}
    pre: t.dial > 0
    effect: t.dial = t.dial - 1
"""


def lamps(tmp_path):
    (tmp_path / "lamps.yaml").write_text(LINE_DOMAIN)
    (tmp_path / "d.yaml").write_text('domain: lamps.yaml\nheight: 1\nlegend: {".": [floor], "G": [goal]}\n'
                                     'map: |\n  ....G.\nagent: {start: [0, 0, 0]}\ngoal: done(agent)\n')
    return compile_dungeon(tmp_path / "d.yaml")


def test_inverses_in_a_domain_of_its_own(tmp_path):
    # right/left move x by one within the line: each undoes the other where it applies.
    # switch toggles the lamp: its own inverse. unturn undoes turn except from 3 (turn
    # gives 0, where unturn does not apply), so it is not an inverse of turn; turn undoes
    # unturn (d - 1 then + 1, d > 0).
    # Commuting (skipped after the later action): switch, turn and unturn with right and
    # left (different variables, preconditions on their own); turn and unturn with switch.
    # right/left do not commute (from 0 only right then left applies), nor turn/unturn.
    model = lamps(tmp_path)
    assert model.data("layer_skips") == {
        "undone_by": {"right": ["left"], "left": ["right"], "switch": ["switch"], "unturn": ["turn"]},
        "skipped_after": {"right": ["left"], "left": ["right"], "switch": ["right", "left", "switch"],
                          "turn": ["right", "left", "switch"], "unturn": ["right", "left", "switch", "turn"]}}
    assert layers_reached(model, model.search_layers()) == \
        layers_reached(model, unskipped(model).search_layers())
    # By hand: 4 steps right, 1 switch, 2 turns (or... unturn from 0 does not apply): 7.
    for solver, options in [("bfs", {}), ("astar", {"heuristic": "blind"})]:
        result = get_solver(solver)(model, Budget(), **options)
        assert result.cost == 7
        assert replay(model, result.plan)


def replay(model, plan) -> bool:
    s = model.initial
    for name in plan:
        s = model.apply(model.action_index(name), s)
        if s is None:
            return False
    return model.is_goal(s)


def expands_as_fresh(model, expander, groups: int, s, seen: dict) -> None:
    """`expander([s], ...)` makes the new states `fresh(s, ...)` does, with the same
    parents; where one is a goal it stops there: the goal last of its group, and no more."""
    expected_seen, out = dict(seen), []
    count = model.search_fresh()(s, expected_seen, out)
    outs = [[] for _ in range(groups)]
    got_seen = dict(seen)
    k = expander([s], got_seen, outs)
    new = [t for o in outs for t in o]
    if any(map(model.is_goal, out)):
        assert k < 0 and ~k <= count
        assert set(new) <= set(out) and got_seen.items() <= expected_seen.items()
        assert sum(model.is_goal(o[-1]) for o in outs if o) == 1
        assert not any(model.is_goal(t) for o in outs for t in o[:-1])
    else:
        assert 0 <= k <= count
        assert sorted(new) == sorted(out)
        assert got_seen == expected_seen
    return k, count


@pytest.mark.parametrize("name", shipped_dungeons())
def test_layer_expanders_are_fresh_less_the_skipped_actions(name):
    """Group 0 expands as `fresh` does. A state t made by action a (its parent seen)
    yields `live`'s next states of every action but those skipped after a, once each,
    with t as their parent; an inverse's next state would have been the parent."""
    model = compile_dungeon(name)
    expanders, live = model.search_layers(), model.search_successors()
    assert expanders is model.data("layer_expanders")   # generated, not the fallback
    skips, undo = skipped_after(model), undone_by(model)
    makers = [a for a in model.search_actions if a in skips]
    assert len(expanders) == 1 + len(makers)
    states = [s for s in reachable(model, 600) if not model.is_goal(s)]
    skipped = 0
    for i, s in enumerate(states):
        if model.is_failure(s) and i:
            continue
        k, count = expands_as_fresh(model, expanders[0], len(expanders), s, dict.fromkeys(states[:i:3], "old"))
        assert k < 0 or k == count
        for g, a in enumerate(makers, 1):
            t = model.apply(a, s)
            if t is None or t == s or model.is_goal(t) or model.is_failure(t):
                continue
            nexts = live(t)
            assert all(n == s for b, n in nexts if b in undo.get(a, ()))
            kept = [n for b, n in nexts if b not in skips[a]]
            expected = list(dict.fromkeys(n for n in kept if n not in (s, t)))
            outs = [[] for _ in expanders]
            seen = {s: None, t: s}
            got = expanders[g]([t], seen, outs)
            new = [n for out in outs for n in out]
            if any(map(model.is_goal, expected)):
                assert got < 0 and set(new) <= set(expected)
            else:
                assert got == len(kept) and sorted(new) == sorted(expected)
                assert seen == {s: None, t: s, **dict.fromkeys(expected, t)}
            skipped += len(nexts) - len(kept)
    assert skipped or not makers


def unskipped(model):
    """The model with no generated expanders: one group over `fresh`, nothing skipped."""
    return dataclasses.replace(model, lazy={k: v for k, v in model.lazy.items() if k != "layer_expanders"})


def layers_reached(model, expanders, limit=20000) -> list:
    """The sets of states of each layer a layered search completes, up to the layer where
    it meets a goal or passes `limit` states."""
    seen, layer, done = {model.initial: None}, [[model.initial]] + [[] for _ in expanders[1:]], []
    while any(layer) and len(seen) < limit:
        below = [[] for _ in expanders]
        for expand, states in zip(expanders, layer):
            if expand(states, seen, below) < 0:
                return done
        layer = below
        done.append(frozenset(s for out in below for s in out))
    return done


@pytest.mark.parametrize("name", shipped_dungeons())
def test_skipping_reaches_every_state_of_every_layer(name):
    """Layer by layer, the search that skips inverses and commuting actions holds exactly
    the states of one that skips nothing (so the first goal is met at the same depth)."""
    model = compile_dungeon(name)
    skipping = layers_reached(model, model.search_layers())
    assert skipping == layers_reached(model, unskipped(model).search_layers())
    if name in ("tough_maze", "bridge", "manipulation", "cleanup"):   # goals far enough to compare many layers
        assert len(skipping) >= 5


@pytest.mark.parametrize("name", ["bridge", "easy_maze", "four_rooms", "grid"])
def test_layered_searches_find_bfs_costs_with_and_without_generated_expanders(name):
    """Blind A* (layered) and BFS, over the generated expanders and over the one-group
    fallback (`fresh` only), agree on the cost with an A* that keeps a priority queue
    (the pattern database, consistent), and every plan replays to a goal."""
    model = compile_dungeon(name)
    plain = unskipped(model)
    assert plain.search_layers() != model.search_layers()
    reference = get_solver("astar")(model, Budget(), heuristic="pdb")
    assert reference.solved
    for m in (model, plain):
        for solver, options in [("bfs", {}), ("astar", {"heuristic": "blind"})]:
            result = get_solver(solver)(m, Budget(), **options)
            assert result.solved and result.cost == reference.cost, (solver, m is plain)
            assert replay(m, result.plan)


def test_a_state_budget_is_not_overshot_by_more_than_one_expansion():
    model = compile_dungeon("tough_maze")
    for solver, options in [("bfs", {}), ("astar", {"heuristic": "blind"})]:
        result = get_solver(solver)(model, Budget(max_states=5000), **options)
        assert result.status == "budget" and result.budget == "max_states"
        assert 5000 < result.stored <= 5000 + len(model.search_actions)
