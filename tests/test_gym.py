"""The Gymnasium environment (bcc.gym) and the Q-learning baseline (solvers/qlearning.py)."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

gymnasium = pytest.importorskip("gymnasium", reason="gymnasium is not installed (pip install 'gymnasium>=1.0')")

import bcc.gym  # noqa: E402  (registers bcc/Dungeon-v0)
from bcc.gym import ENV_ID, DungeonEnv  # noqa: E402
from bcc.solvers import get_solver  # noqa: E402
from bcc.solvers.base import Budget  # noqa: E402
from bcc.solvers.qlearning import solve as qlearning  # noqa: E402

CANONICAL = ("move_forward", "rotate_left", "rotate_right", "look_down", "look_ahead", "change_item",
             "destroy_block", "place_block")


def act(env, name):
    return env.unwrapped.action_names.index(name)


def optimal_plan(model_of, name):
    result = get_solver("bfs")(model_of(name), Budget())
    assert result.solved
    return result.plan


@pytest.mark.parametrize("dungeon", ["bridge", "grid"])
def test_env_checker_passes(model_of, dungeon):
    from gymnasium.utils.env_checker import check_env
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check_env(DungeonEnv(model_of(dungeon)).unwrapped, skip_render_check=True)
        for mode in ("ansi", "rgb_array"):
            # made through the registry, the checker also tries the other render modes
            check_env(gymnasium.make(ENV_ID, dungeon=dungeon, render_mode=mode).unwrapped)
    assert [str(w.message) for w in caught] == []


def test_spaces_follow_the_model(model_of):
    model = model_of("bridge")
    env = DungeonEnv(model)
    assert env.action_space == gymnasium.spaces.Discrete(len(model.action_names))
    assert env.action_names[:8] == CANONICAL
    obs, info = env.reset(seed=0)
    assert set(obs) == {"pose", "inventory", "nearby"}
    assert env.observation_space.contains(obs)
    start = model.decode(model.initial)
    assert obs["pose"].tolist() == [start["agent.x"], start["agent.z"], start["agent.rotationalDirection"],
                                    start["agent.verticalDirection"], start["agent.selectedItem"]]
    assert obs["inventory"].shape == (9, 2)
    assert env.block_types[obs["inventory"][0, 0]] == "diamond_pickaxe" and obs["inventory"][0, 1] == 1
    assert obs["inventory"][1:].sum() == 0
    assert obs["nearby"].shape == (3, 5, 5)
    names = np.array(env.block_types)[obs["nearby"]]
    # bridge: agent at (1, 1, 3); the lava column is x = 3, the stone stands at (1, 1, 5)
    assert names[1, 2, 2] == "air" and names[0, 2, 2] == "bedrock"
    assert names[0, 2, 4] == "lava"
    assert names[1, 4, 2] == "burlap_stone"
    assert (names[:, :, 0] == "air").all()          # x = -1: outside the map reads as air
    assert info["state"] == model.initial
    assert info["action_mask"].tolist() == [int(model.apply(a, model.initial) is not None)
                                            for a in range(len(model.action_names))]


def test_same_seed_same_episode(model_of):
    def episode(seed):
        env = DungeonEnv(model_of("bridge"), max_episode_steps=60)
        env.action_space.seed(seed)
        obs, info = env.reset(seed=seed)
        trace = [info["state"]]
        done = False
        while not done:
            obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
            trace.append((info["state"], reward, terminated, truncated))
            done = terminated or truncated
        return trace

    assert episode(3) == episode(3)
    assert episode(3) != episode(4)


def test_inapplicable_action_is_a_costly_no_op(model_of):
    env = DungeonEnv(model_of("bridge"))
    obs, info = env.reset(seed=0)
    destroy = act(env, "destroy_block")
    assert info["action_mask"][destroy] == 0          # looking ahead: cannot mine
    obs2, reward, terminated, truncated, info2 = env.step(destroy)
    assert reward == -1.0
    assert not terminated and not truncated
    assert info2["state"] == info["state"] and not info2["applied"]
    assert info2["why_not"]
    assert all(np.array_equal(obs[k], obs2[k]) for k in obs)
    assert env.steps == 1


def test_following_the_optimal_plan_reaches_the_goal(model_of):
    plan = optimal_plan(model_of, "bridge")
    env = gymnasium.make(ENV_ID, dungeon="bridge")
    env.reset(seed=0)
    total = 0.0
    for i, name in enumerate(plan):
        obs, reward, terminated, truncated, info = env.step(act(env, name))
        assert info["applied"], f"step {i + 1} ({name}) did not apply"
        total += reward
        assert terminated == (i == len(plan) - 1)
        assert not truncated
    assert info["is_success"] and not info["is_failure"]
    assert total == -len(plan)
    assert env.unwrapped.model.is_goal(info["state"])


def test_walking_into_lava_is_death(model_of):
    env = DungeonEnv(model_of("bridge"))
    env.reset(seed=0)
    env.step(act(env, "rotate_right"))                # north -> east
    _, _, terminated, _, info = env.step(act(env, "move_forward"))     # (2, 3)
    assert not terminated
    _, reward, terminated, truncated, info = env.step(act(env, "move_forward"))   # (3, 3): lava
    assert terminated and not truncated
    assert not info["is_success"] and info["is_failure"]
    assert reward == -1.0
    env = DungeonEnv(model_of("bridge"), death_penalty=50)
    env.reset()
    for name in ("rotate_right", "move_forward", "move_forward"):
        _, reward, terminated, _, _ = env.step(act(env, name))
    assert terminated and reward == -51.0


def test_truncation_at_max_episode_steps(model_of):
    env = DungeonEnv(model_of("grid"), max_episode_steps=3)
    env.reset()
    left = act(env, "rotate_left")
    flags = [env.step(left)[2:4] for _ in range(3)]
    assert flags == [(False, False), (False, False), (False, True)]


def test_reset_from_a_given_state(model_of):
    model = model_of("bridge")
    env = DungeonEnv(model)
    start = model.apply(model.action_index("rotate_right"), model.initial)
    obs, info = env.reset(options={"state": start})
    assert info["state"] == start and obs["pose"][2] == 3
    with pytest.raises(ValueError):
        env.reset(options={"state": b"\x00"})


def test_ansi_render_shows_the_agent_arrow(model_of):
    env = DungeonEnv(model_of("bridge"), render_mode="ansi")
    env.reset()
    text = env.render()
    assert isinstance(text, str)
    rows = text.splitlines()
    assert rows[3][1] == "^"                          # facing north at (1, 3)
    env.step(act(env, "rotate_right"))
    assert env.render().splitlines()[3][1] == ">"


def test_rgb_array_render(model_of):
    model = model_of("bridge")
    env = DungeonEnv(model, render_mode="rgb_array")
    env.reset()
    img = env.render()
    assert img.dtype == np.uint8
    assert img.shape == (model.grid.depth * 16, model.grid.width * 16, 3)
    cell = img[3 * 16:4 * 16, 1 * 16:2 * 16]
    assert (cell == 255).all(axis=-1).any()           # the agent (white) is drawn in its cell
    lava = img[1 * 16 + 8, 3 * 16 + 8]
    assert tuple(lava) == bcc.gym.colour_of("lava")
    env.step(act(env, "rotate_left"))
    assert not np.array_equal(env.render(), img)      # the marker turned
    assert DungeonEnv(model, render_mode="rgb_array", cell_size=8).render().shape == (56, 56, 3)


def test_gymnasium_make(model_of):
    assert ENV_ID in gymnasium.registry
    import importlib
    importlib.reload(bcc.gym)                         # registering twice is harmless
    env = gymnasium.make(ENV_ID, dungeon="grid", render_mode="ansi")
    assert env.spec.max_episode_steps == 200
    env = gymnasium.make(ENV_ID, dungeon="grid", render_mode="ansi", max_episode_steps=5)
    obs, info = env.reset(seed=1)
    assert env.observation_space.contains(obs)
    assert isinstance(env.render(), str)
    assert env.spec.max_episode_steps == 5 and env.unwrapped.max_episode_steps is None
    flags = [env.step(act(env, "rotate_left"))[3] for _ in range(5)]
    assert flags == [False] * 4 + [True]              # gymnasium's TimeLimit does the cutting
    with pytest.raises(ValueError):
        DungeonEnv("grid", render_mode="human")


def test_qlearning_learns_the_optimal_grid_plan(model_of):
    model = model_of("grid")
    optimal = optimal_plan(model_of, "grid")
    assert len(optimal) == 7
    result = qlearning(model, Budget(), episodes=300, seed=0, optimal_cost=len(optimal))
    assert result.solved and result.status == "solved"
    assert len(result.plan) == len(optimal) == result.cost
    assert result.expanded == sum(e["steps"] for e in result.episodes)
    assert len(result.episodes) == 300
    assert set(result.episodes[0]) >= {"steps", "return", "success"}
    assert result.episodes[-1]["greedy_steps"] == 7
    assert result.converged_episode is not None and 1 <= result.converged_episode <= 300
    # The plan is real: replaying it in the environment reaches the gold.
    env = DungeonEnv(model)
    env.reset()
    for name in result.plan:
        *_, terminated, _, info = env.step(act(env, name))
    assert terminated and info["is_success"]
    # Same seed, same run.
    again = qlearning(model, Budget(), episodes=300, seed=0, optimal_cost=7)
    assert again.plan == result.plan and again.episodes == result.episodes


def test_qlearning_reports_when_it_has_not_learned(model_of):
    result = qlearning(model_of("grid"), Budget(), episodes=2, seed=0)
    assert not result.solved and result.status == "no_solution"
    assert "not complete" in result.message
    assert result.converged_episode is None and len(result.episodes) == 2


def test_qlearning_respects_the_time_budget(model_of):
    result = qlearning(model_of("bridge"), Budget(time_limit=0.0), episodes=1000, seed=0)
    assert result.status == "budget" and result.budget == "time_limit"
