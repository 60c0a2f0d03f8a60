"""Recording play in a real Minecraft server: a scripted mineflayer bot stands in for a
person, and the recorder (polling, gap filling, the grounding extractor) must recover
what it did. CI installs the Node packages (`npm ci` in minecraft/) first; the
tests skip, saying why, only where Node or those packages are missing."""
from __future__ import annotations

import threading
import time

import pytest

from bcc.minecraft.actions import geometry
from bcc.minecraft.record import host, record
from bcc.minecraft.world import WorldMap
from minecraft_harness import free_port, open_bridge, require_minecraft

require_minecraft()


@pytest.fixture
def bridge(tmp_path):
    yield from open_bridge(tmp_path)


def drive(bridge, model, player, actions, pause=0.05):
    """A scripted player: each action through the action controller, from its model state."""
    world = WorldMap(model)
    state = model.initial
    for a in actions:
        nxt = model.apply(model.action_index(a), state)
        bridge.act(player, **geometry(world, a, state, nxt))
        state = nxt
        time.sleep(pause)
    return state


def test_recorded_play_gives_the_demonstrated_actions(bridge, model_of):
    m = model_of("bridge")
    bridge.start(port=free_port())
    bridge.build(WorldMap(m))
    bridge.spawn_bot("alex", person=True)          # plays the person: recorded like one
    # A walk of a person who does not take the shortest way: east to the lava's edge,
    # back, then round to the stone (hand-written; it must replay in the model).
    walk = ["rotate_right", "move_forward", "rotate_left", "rotate_left", "move_forward", "rotate_left",
            "move_forward", "look_down", "destroy_block", "change_item"]
    out = {}

    def recorder():
        try:
            out["result"] = record(m, bridge, None, player="alex", timeout=60, stop_at_goal=False)
        except Exception as exc:  # noqa: BLE001 - handed to the test thread
            out["error"] = exc

    t = threading.Thread(target=recorder, daemon=True)
    t.start()
    time.sleep(1.5)                                 # the recorder puts alex at the start first
    drive(bridge, m, "alex", walk)
    bridge.say("alex", "learn get the stone")
    t.join(30)
    assert not t.is_alive()
    assert "error" not in out, out.get("error")
    demo, recording = out["result"]
    assert demo.command == "get the stone"
    assert demo.actions == walk
    assert recording.corrections == []
    assert recording.polls > len(walk)              # polled, not told
    v = m.decode(demo.states[-1])
    assert v["inventoryBlock[1].blockType"] == "burlap_stone" and v["agent.selectedItem"] == 1


def test_serve_learns_from_chat_and_resets(bridge, model_of, tmp_path, monkeypatch):
    stored = []

    def save_only(demo, path):   # the grounding dataset is not this test's subject
        demo.save(path)
        stored.append(path)
        return {"stored": False, "message": "saved"}

    m = model_of("bridge")
    bridge.start(port=free_port())
    bridge.build(WorldMap(m))
    stop = threading.Event()
    server = threading.Thread(target=host, args=(m, bridge, tmp_path),
                              kwargs={"log": lambda line: None, "duration": 60, "stop": stop, "keep": save_only}, daemon=True)
    server.start()
    bridge.spawn_bot("sam", person=True)
    time.sleep(1.5)
    drive(bridge, m, "sam", ["rotate_left", "rotate_left", "move_forward"])
    bridge.say("sam", "learn walk south")
    deadline = time.monotonic() + 10
    while not stored and time.monotonic() < deadline:
        time.sleep(0.1)
    assert stored, "no demonstration was stored"
    from bcc.demonstration import Demonstration
    demo = Demonstration.load(stored[0], model=m)
    assert demo.command == "walk south"
    assert demo.actions == ["rotate_left", "rotate_left", "move_forward"]
    # after 'learn' the player is back at the start
    deadline = time.monotonic() + 5
    while time.monotonic() < deadline:
        if WorldMap(m).parse(bridge.observe("sam")).state == m.initial:
            break
        time.sleep(0.1)
    assert WorldMap(m).parse(bridge.observe("sam")).state == m.initial
    stop.set()
    server.join(5)
    assert not server.is_alive()




def test_a_change_no_action_explains_is_put_back(bridge, model_of):
    m = model_of("bridge")
    world = WorldMap(m)
    bridge.start(port=free_port())
    bridge.build(world)
    bridge.spawn_bot("kim", person=True)
    out = {}

    def recorder():
        try:
            out["result"] = record(m, bridge, "stay", player="kim", timeout=60)
        except Exception as exc:  # noqa: BLE001 - handed to the test thread
            out["error"] = exc

    t = threading.Thread(target=recorder, daemon=True)
    t.start()
    time.sleep(1.5)
    # kim appears across the lava (a /tp, say): no sequence of model actions does that
    start = world.pose(m.initial)
    pose = dict(start, position=[c + d for c, d in zip(start["position"], (3, 0, -2))])
    bridge.setup("kim", pose, None)
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline and world.parse(bridge.observe("kim")).state != m.initial:
        time.sleep(0.1)
    assert world.parse(bridge.observe("kim")).state == m.initial      # put back at the start
    bridge.say("kim", "done")
    t.join(30)
    assert "error" not in out, out.get("error")
    demo, recording = out["result"]
    assert demo.actions == [] and demo.command == "stay"
    assert len(recording.corrections) == 1 and "no move of bcc's model" in recording.corrections[0]
