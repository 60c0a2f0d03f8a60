"""Request and response bodies of the JSON API (pydantic), hence its OpenAPI schema."""
from __future__ import annotations

from typing import Literal

import re

from pydantic import BaseModel, ConfigDict, Field, model_validator

SURROGATE = re.compile("[\ud800-\udfff]")

DUNGEON_HELP = ("A shipped dungeon's name (see GET /dungeons), or the YAML text of a dungeon. "
                "Posted text may `extends:` shipped dungeons and name shipped domains only.")


class Strict(BaseModel):
    """Every body: numbers are finite (NaN would break the JSON of any answer) and text
    holds no lone surrogates (they cannot be written, logged or sent back as UTF-8)."""
    model_config = ConfigDict(allow_inf_nan=False)

    @model_validator(mode="after")
    def _no_surrogates(self):
        for name, value in self:
            if name == "dungeon":  # posted text: refused with its line and column (`posted.check_policy`)
                continue
            for text in (value if isinstance(value, list) else [value]):
                if isinstance(text, str) and SURROGATE.search(text):
                    raise ValueError(f"`{name}` holds a lone surrogate (text must be valid Unicode)")
        return self


class DungeonRequest(Strict):
    dungeon: str = Field(description=DUNGEON_HELP, examples=["bridge"])
    goal: str | None = Field(None, description="Use this goal instead of the dungeon's, e.g. 'agentInRoom(agent, red)'.")


class SolveRequest(DungeonRequest):
    solver: str = Field("astar", description="A solver name (GET /solvers).")
    time_limit: float = Field(10, gt=0, description="Seconds the solver may search (capped by the server).")
    max_states: int | None = Field(None, ge=1, description="Stop after storing this many states.")
    max_memory_mb: float | None = Field(None, ge=1, description="Memory the job may add to its process "
                                                                "[default and cap: the server's --job-memory].")
    # The solver options: each is checked against the chosen solver's declaration (the one
    # check of bcc solve and batch too; GET /solvers lists them with their ranges), so an
    # option the solver does not take or a value out of range is a 400 naming it.
    heuristic: str | None = Field(None, description="Informed solvers: the heuristic (GET /solvers lists them).")
    weight: float | None = Field(None, description="astar/wastar: f = g + W h, W >= 1.")
    preferred: bool | None = Field(None, description="gbfs with hff: also expand by its preferred actions.")
    evaluation: str | None = Field(None, description="gbfs: when h is computed, eager, lazy or auto.")
    episodes: int | None = Field(None, description="Learning solvers: number of episodes.")
    seed: int | None = Field(None, description="Learning solvers: random seed.")
    model: str | None = Field(None, description="rmax: the model learner, tabular or oo [default: tabular].")
    gamma: float | None = Field(None, description="Learning solvers: discount [default: 0.99].")
    alpha: float | None = Field(None, description="qlearning: learning rate [default: 0.5].")
    epsilon: float | None = Field(None, description="qlearning: exploration rate [default: 0.1].")
    delta: float | None = Field(None, description="rmax: value iteration stops below this change [default: 0.01].")
    known_after: int | None = Field(None, description="rmax: visits before a (state, action) is known [default: 1].")
    max_steps: int | None = Field(None, description="Learning solvers: steps before an episode is cut.")
    local_limit: int | None = Field(None, description="build: expansions of one goal atom's search [default: 4000].")
    improve: int | None = Field(None, description="build: plans of at most this many actions are handed to A* "
                                "for a shorter one; 0: never [default: 40].")


MAX_ACTIONS = 20_000  # a frame is ~1 KB of JSON: bounds one answer to tens of MB


class ReplayRequest(DungeonRequest):
    actions: list[str] = Field(default_factory=list, max_length=MAX_ACTIONS,
                               description="Canonical action names, run from the start.")
    include_scene: bool = Field(True, description="Also return the static drawing data (`scene`).")


class DemonstrationRequest(DungeonRequest):
    actions: list[str] = Field(max_length=MAX_ACTIONS, description="The actions played, from the dungeon's start.")
    command: str | None = Field(None, description="What the player was asked to do, if anything.")


class ErrorBody(BaseModel):
    error: str
    line: int | None = None
    column: int | None = None
    file: str | None = Field(None, description="'<posted>' for posted text, else the shipped file's name.")


class JobCreated(BaseModel):
    id: str
    status: Literal["queued"] = "queued"


class SolveResult(BaseModel):
    """The fields of `bcc solve --json`."""
    dungeon: str
    goal: str
    solver: str
    solved: bool
    status: str = Field(description="solved | no_solution | budget")
    plan: list[str]
    cost: int | None
    expanded: int
    generated: int
    stored: int
    seconds: float
    peak_mb: float
    budget: str | None = Field(description="Which budget ran out: max_states | time_limit | max_memory.")
    message: str
    heuristic: str | None
    initial_h: int | float | None
    episodes: list
    converged_episode: int | None
    lower_bound: int | None = Field(None, description="build: an admissible lower bound on the plan's cost.")


class JobStatus(BaseModel):
    id: str
    status: Literal["queued", "running", "done", "failed", "cancelled"]
    result: SolveResult | None = Field(None, description="When done: the solver's result (solved or not).")
    error: str | None = Field(None, description="When failed or cancelled: why.")
    dungeon: str | None
    solver: str | None
    submitted: float
    started: float | None
    finished: float | None


class DungeonInfo(BaseModel):
    name: str
    goal: str | None
    extends: str | None
    description: str


class DungeonList(BaseModel):
    dungeons: list[DungeonInfo]
    domains: list[str]


class DungeonFile(DungeonInfo):
    domain: str | None
    yaml: str = Field(description="The dungeon file's text (edit it and post it back).")


class Frame(BaseModel):
    agent: list[int]
    facing: str | None
    variables: dict
    changed: list = Field(description="[x, z, [block indices from y = 0 up]] for columns unlike the start.")
    goal: bool
    failure: bool


class Scene(BaseModel):
    dungeon: str
    goal: str
    width: int
    depth: int
    height: int
    blocks: list[str]
    columns: list = Field(description="columns[z][x]: block indices from y = 0 up (rows are z, columns x).")
    rooms: list[dict]
    objects: list[dict]
    actions: list[str]
    keys: dict[str, str] = Field(default_factory=dict,
                                 description="key -> action played by it: the same table as `bcc play`.")


class ReplayResponse(BaseModel):
    scene: Scene | None
    valid: bool
    steps: int
    cost: int
    reached_goal: bool
    failed_step: int | None
    message: str
    frames: list[Frame]
