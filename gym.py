"""A Gymnasium environment over a compiled dungeon: the OO-MDP as an RL environment.

BurlapCraft exposed Minecraft to BURLAP so that the same dungeons could be both planned
in (BFS, A*) and learned in (R-max). bcc compiles a dungeon into a `Model` whose
transition function is plain Python over `bytes` states; this module wraps that model
in the standard reinforcement-learning interface, so any Gymnasium agent (stable-
baselines3, CleanRL, a hand-written Q-learner) can learn the same dungeons the
planners solve, and its results can be compared with their optimal plans.

    import gymnasium
    import bcc.gym                                   # registers "bcc/Dungeon-v0"
    env = gymnasium.make("bcc/Dungeon-v0", dungeon="bridge", render_mode="ansi")
    obs, info = env.reset(seed=0)
    obs, reward, terminated, truncated, info = env.step(env.action_space.sample())

Semantics (spec section 3, RL reading):
- Actions are `Discrete(n)` in the model's canonical order (`env.action_names`):
  move_forward, rotate_left, rotate_right, look_down, look_ahead, change_item,
  destroy_block, place_block (a domain may add more after these).
- Every action is offered in every state. One whose precondition fails is a no-op that
  still costs a step; `info["action_mask"]` says which actions apply (1) and
  `info["why_not"]` gives the failed precondition of an inapplicable step.
- Reward is minus the action's cost: -1 per step for the minecraft domain. Reaching the
  goal terminates with `info["is_success"] = True`; dying (walking onto lava)
  terminates with `is_success = False` and `info["is_failure"] = True`. With the
  default `death_penalty=0` dying is only one more -1 step, as in the spec; an agent
  that should learn to avoid lava rather than end a long episode early may want
  `death_penalty` > 0 (subtracted from the reward of the fatal step).
- Episodes are truncated after `max_episode_steps` steps (None: never). Constructed
  directly, the environment enforces the limit itself (default 200). Through
  `gymnasium.make("bcc/Dungeon-v0", max_episode_steps=N)` (default 200) Gymnasium's
  `TimeLimit` wrapper enforces it instead, `env.spec.max_episode_steps` reports it, and
  the inner limit is off (`env.unwrapped.max_episode_steps` is None).

Observation (a `Dict`; all integer arrays of dtype int64):
- "pose": MultiDiscrete [x, z, facing, looking, selected slot] (the agent's y is
  constant in the shipped dungeons and left out; see `env.pose_labels`).
- "inventory": MultiDiscrete of shape (slots, 2): (block type, count) per hotbar slot;
  block types index `env.block_types`.
- "nearby": MultiDiscrete of shape (3, 2r+1, 2r+1), r = `view_radius`:
  nearby[k, j, i] is the block type (index into `env.block_types`) of the cell
  (x - r + i, y - 1 + k, z - r + j), world-aligned (j grows with z, i with x); cells
  outside the map read as air.

`info["state"]` always carries the exact model state (`bytes`), so an agent or a test
can go back to the planner's view of the world (`env.model.decode(info["state"])`).
`reset(options={"state": s})` starts an episode from any model state.

Rendering: "ansi" is `bcc.render.render` (the same top view `bcc` prints); "rgb_array"
is a top view with `cell_size` pixels per column: each column in the colour of its
highest block (blocks at or above the agent's feet raised: lighter, with a dark rim),
named objects as dots, and the agent as a white triangle pointing where it faces (a
dark dot in it when looking down).
"""
from __future__ import annotations

import functools
import zlib
from pathlib import Path

import gymnasium
import numpy as np
from gymnasium import spaces

from .model import Model
from .render import facing_name
from .render import render as render_ascii

ENV_ID = "bcc/Dungeon-v0"
DEFAULT_MAX_STEPS = 200

POSE_LABELS = ("agent.x", "agent.z", "agent.rotationalDirection", "agent.verticalDirection", "agent.selectedItem")

COLOURS = {
    "air": (0, 0, 0),
    "bedrock": (84, 84, 84),
    "lava": (230, 90, 10),
    "gold": (250, 205, 30),
    "burlap_stone": (150, 120, 80),
    "diamond_pickaxe": (90, 220, 220),
    "red_wool": (190, 40, 40),
    "orange_wool": (235, 130, 30),
    "green_wool": (60, 150, 50),
    "blue_wool": (50, 70, 190),
    "wheat_seeds": (110, 160, 60),
    "wheat": (220, 195, 90),
    "carrot": (240, 140, 40),
}
AGENT_COLOUR = (255, 255, 255)
AGENT_RIM = (0, 0, 0)
EMPTY_COLOUR = (0, 0, 0)


def colour_of(name: str) -> tuple[int, int, int]:
    """A block type's colour; unknown names get a stable colour from a hash of the name."""
    if name in COLOURS:
        return COLOURS[name]
    h = zlib.crc32(name.encode())
    return (64 + (h & 0xFF) % 192, 64 + (h >> 8 & 0xFF) % 192, 64 + (h >> 16 & 0xFF) % 192)


@functools.lru_cache(maxsize=32)
def _compiled(ref: str, goal: str | None) -> Model:
    from .compiler import compile_dungeon
    return compile_dungeon(ref, goal=goal)


class DungeonEnv(gymnasium.Env):
    """A bcc dungeon as a Gymnasium environment (see the module docstring).

    `dungeon` is a shipped dungeon's name, a path to a dungeon file, or an already
    compiled `Model` (then `goal` must be None). Compiled models are cached per
    (dungeon, goal), so many environments over one dungeon compile it once.
    """

    metadata = {"render_modes": ["ansi", "rgb_array"], "render_fps": 4}

    def __init__(self, dungeon: str | Path | Model = "bridge", goal: str | None = None,
                 render_mode: str | None = None, max_episode_steps: int | None = DEFAULT_MAX_STEPS,
                 view_radius: int = 2, death_penalty: float = 0.0, cell_size: int = 16):
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode must be one of {self.metadata['render_modes']} or None, "
                             f"not {render_mode!r}")
        if view_radius < 0:
            raise ValueError(f"view_radius must be >= 0, not {view_radius}")
        if max_episode_steps is not None and max_episode_steps < 1:
            raise ValueError(f"max_episode_steps must be >= 1 or None, not {max_episode_steps}")
        if isinstance(dungeon, Model):
            if goal is not None:
                raise ValueError("goal applies when compiling; pass a dungeon name or path with it, not a Model")
            self.model = dungeon
        else:
            self.model = _compiled(str(dungeon), goal)
        m = self.model
        g = m.grid
        self.render_mode = render_mode
        self.max_episode_steps = max_episode_steps
        self.view_radius = view_radius
        self.death_penalty = float(death_penalty)
        self.cell_size = int(cell_size)
        self.action_names = tuple(m.action_names)
        self.block_types = tuple(g.value_names)
        self._air = self.block_types.index("air") if "air" in self.block_types else g.default

        by_label = {v.label: v for v in m.variables}
        self.pose_labels = tuple(label for label in POSE_LABELS if label in by_label)
        self._pose_idx = np.array([by_label[label].index for label in self.pose_labels], dtype=np.intp)
        pose_n = [by_label[label].hi - by_label[label].lo + 1 for label in self.pose_labels]
        slots = []
        while f"inventoryBlock[{len(slots)}].blockType" in by_label:
            k = len(slots)
            slots.append((by_label[f"inventoryBlock[{k}].blockType"], by_label.get(f"inventoryBlock[{k}].count")))
        self.n_slots = len(slots)
        self._slots = slots
        side = 2 * view_radius + 1
        n_types = len(self.block_types)
        spaces_ = {
            "pose": spaces.MultiDiscrete(pose_n or [1], dtype=np.int64),
            "inventory": spaces.MultiDiscrete(
                [[t.hi - t.lo + 1, (c.hi - c.lo + 1) if c is not None else 1] for t, c in slots] or [[1, 1]],
                dtype=np.int64),
            "nearby": spaces.MultiDiscrete(np.full((3, side, side), n_types), dtype=np.int64),
        }
        self.observation_space = spaces.Dict(spaces_)
        self.action_space = spaces.Discrete(len(self.action_names))

        # The whole world as a (height, depth, width) array; the mutable layers are
        # overwritten from the state at each observation.
        self._static = np.frombuffer(g.static, dtype=np.uint8).reshape(g.height, g.depth, g.width)
        self._area = g.width * g.depth
        self.state: bytes = m.initial
        self.steps = 0

    # ----------------------------------------------------------------- the world
    def world(self, state: bytes | None = None) -> np.ndarray:
        """Every cell's block type index, shape (height, depth, width), indexed [y, z, x]."""
        state = self.state if state is None else state
        return self.model.view(state).grid()

    def action_mask(self, state: bytes | None = None) -> np.ndarray:
        """1 for each action whose precondition holds in `state`, else 0 (dtype int8)."""
        state = self.state if state is None else state
        return np.array([f(state) is not None for f in self.model.apply_fns], dtype=np.int8)

    def _obs(self) -> dict:
        s = self.state
        raw = np.frombuffer(s, dtype=np.uint8)
        pose = raw[self._pose_idx].astype(np.int64) if len(self._pose_idx) else np.zeros(1, np.int64)
        if self._slots:
            inv = np.array([[s[t.index], s[c.index] if c is not None else 0] for t, c in self._slots], dtype=np.int64)
        else:
            inv = np.zeros((1, 2), dtype=np.int64)
        r = self.view_radius
        x, y, z = self.model.agent_position(s)
        g = self.model.grid
        padded = np.full((g.height + 2, g.depth + 2 * r, g.width + 2 * r), self._air, dtype=np.int64)
        padded[1:g.height + 1, r:r + g.depth, r:r + g.width] = self.world(s)
        # padded[y + 1] is layer y; the window's rows y-1..y+1 are padded[y .. y+2].
        ys = np.clip(np.arange(y, y + 3), 0, g.height + 1)
        nearby = padded[ys][:, z:z + 2 * r + 1, x:x + 2 * r + 1].copy()
        nearby[(np.arange(y - 1, y + 2) < 0) | (np.arange(y - 1, y + 2) >= g.height)] = self._air
        return {"pose": pose, "inventory": inv, "nearby": nearby}

    def _info(self) -> dict:
        return {"state": self.state, "action_mask": self.action_mask(), "steps": self.steps}

    # ----------------------------------------------------------------- Gymnasium API
    def reset(self, *, seed: int | None = None, options: dict | None = None):
        super().reset(seed=seed)
        start = (options or {}).get("state", self.model.initial)
        base = self.model.grid.base
        if not isinstance(start, (bytes, bytearray)) or len(start) < base or (len(start) - base) % 4:
            raise ValueError("options['state'] must be a model state: bytes, the variables then 4 per changed cell "
                             f"({base} + 4k long)")
        self.state = bytes(start)
        self.steps = 0
        info = self._info()
        info["is_success"] = bool(self.model.is_goal(self.state))
        return self._obs(), info

    def step(self, action):
        a = int(action)
        if not 0 <= a < len(self.action_names):
            raise ValueError(f"action {action!r} is not in {self.action_space}")
        m = self.model
        why = m.why_not(a, self.state)   # None: the preconditions hold and the action applies
        applied = why is None
        self.state, cost, outcome = m.step(self.state, a)
        self.steps += 1
        reward = float(cost)
        success, failure = outcome == "goal", outcome == "dead"
        if failure:
            reward -= self.death_penalty
        terminated = success or failure
        truncated = (not terminated and self.max_episode_steps is not None and self.steps >= self.max_episode_steps)
        info = self._info()
        info.update(is_success=success, is_failure=failure, applied=applied, action_name=self.action_names[a])
        if why is not None:
            info["why_not"] = why
        return self._obs(), reward, terminated, truncated, info

    def render(self):
        if self.render_mode == "ansi":
            return render_ascii(self.model, self.state)
        if self.render_mode == "rgb_array":
            return self.rgb_array()
        return None

    # ----------------------------------------------------------------- pictures
    def rgb_array(self, state: bytes | None = None) -> np.ndarray:
        """A top view of `state` (default: the current one) as a uint8 (depth*c, width*c, 3) image."""
        state = self.state if state is None else state
        m, g, c = self.model, self.model.grid, self.cell_size
        world = self.world(state)
        _, foot, _ = m.agent_position(state)
        palette = np.array([colour_of(n) for n in self.block_types], dtype=np.float64)
        solid = world != self._air
        any_block = solid.any(axis=0)
        top_y = g.height - 1 - np.argmax(solid[::-1], axis=0)           # highest non-air layer per column
        top = np.take_along_axis(world, top_y[None], axis=0)[0]
        colour = palette[top]
        raised = any_block & (top_y >= foot)
        colour[raised] = colour[raised] * 0.6 + 255 * 0.4
        colour[~any_block] = EMPTY_COLOUR
        img = np.repeat(np.repeat(colour, c, axis=0), c, axis=1)
        if c >= 4:
            rim = max(1, c // 8)
            edge = np.zeros((c, c), dtype=bool)
            edge[:rim, :] = edge[-rim:, :] = edge[:, :rim] = edge[:, -rim:] = True
            rim_mask = np.kron(raised, edge).astype(bool)
            img[rim_mask] = img[rim_mask] * 0.45
        img = img.astype(np.uint8)
        yy, xx = np.mgrid[0:c, 0:c] + 0.5
        dot = (yy - c / 2) ** 2 + (xx - c / 2) ** 2 <= (c * 0.28) ** 2
        for name, ox, oz in m.display.get("objects", []):
            if 0 <= ox < g.width and 0 <= oz < g.depth:
                img[oz * c:(oz + 1) * c, ox * c:(ox + 1) * c][dot] = colour_of("object:" + name)
        ax, _, az = m.agent_position(state)
        if 0 <= ax < g.width and 0 <= az < g.depth:
            cell = img[az * c:(az + 1) * c, ax * c:(ax + 1) * c]
            outer, inner = _triangle(c, facing_name(m, state))
            cell[outer] = AGENT_RIM
            cell[inner] = AGENT_COLOUR
            looking = {v.label: v for v in m.variables}.get("agent.verticalDirection")
            if looking is not None and state[looking.index] + looking.lo == 1:
                small = (yy - c / 2) ** 2 + (xx - c / 2) ** 2 <= (c * 0.12) ** 2
                cell[small & inner] = AGENT_RIM
        return img


@functools.lru_cache(maxsize=16)
def _triangle(c: int, facing: str | None) -> tuple[np.ndarray, np.ndarray]:
    """Masks (outline, fill) of a c x c cell's triangle pointing `facing` (north = up);
    with no facing, a disc."""
    yy, xx = np.mgrid[0:c, 0:c] + 0.5
    u, v = xx / c, yy / c                             # 0..1 across, 0..1 down

    def tri(margin):
        # apex at the top centre, base along the bottom: |u - 0.5| <= (v - top) / 2
        top, bottom = 0.1 + margin, 0.9 - margin
        return (v >= top) & (v <= bottom) & (np.abs(u - 0.5) <= (v - top) * 0.45)

    if facing is None or facing not in ("north", "south", "east", "west"):
        r2 = (u - 0.5) ** 2 + (v - 0.5) ** 2
        return r2 <= 0.4 ** 2, r2 <= 0.32 ** 2
    turns = {"north": 0, "west": 1, "south": 2, "east": 3}[facing]   # rot90 is counter-clockwise
    outer, inner = tri(0.0), tri(0.09)
    return np.rot90(outer, turns).copy(), np.rot90(inner, turns).copy()


def register() -> None:
    """Register "bcc/Dungeon-v0" with Gymnasium (idempotent)."""
    if ENV_ID not in gymnasium.registry:
        # gymnasium.make's own `max_episode_steps` (default 200) becomes a TimeLimit wrapper
        # and env.spec.max_episode_steps; the environment's internal limit is then off.
        gymnasium.register(id=ENV_ID, entry_point="bcc.gym:DungeonEnv", max_episode_steps=DEFAULT_MAX_STEPS,
                           kwargs={"max_episode_steps": None})


register()
