"""Where the real game differs from a block-world model, found in a predicted state.

bcc's building models have no gravity and no fluids; Minecraft has both. The check runs
on every predicted state of `bcc minecraft run` and says, for that state:

- **falls**: the agent stands on nothing (the model lets it hang beside a block, or step
  off into the air). In Minecraft it would fall to the first block below (hurt from a
  fall of more than three levels; out of the world when nothing is below). The bot is
  held in the model's cell instead (moves.py), and the step carries the note.
- **flowing water**: a water block beside or above an empty cell would flow into it.
  The server here (flying-squid) runs no fluids, so its world still matches the model;
  a step that puts the agent into such a cell is refused, as a step into lava is: in
  the game the current would carry the agent where the model cannot say.
- **falling blocks**: sand or gravel over an empty cell would fall (the server does not
  do that either).
- **water is no block**: the model may place a block on top of water or mine water; in
  Minecraft a block is placed only against a solid face, and water is taken with a
  bucket. Such a step is refused.
"""
from __future__ import annotations

from .world import WorldMap

FALLING = frozenset({"sand", "red_sand", "gravel"})
SIDES = ((1, 0, 0), (-1, 0, 0), (0, 0, 1), (0, 0, -1), (0, -1, 0))


def fall_depth(world: WorldMap, state: bytes) -> int | None:
    """Levels the agent of `state` would fall in the game: 0 when it stands on a block,
    None when nothing is below it in the dungeon (out of the world)."""
    from .moves import solid
    x, y, z = world.model.agent_position(state)
    depth = 0
    while not solid(world, state, x, y - 1 - depth, z):
        depth += 1
        if y - 1 - depth < 0:
            return None
    return depth


def flows(world: WorldMap, state: bytes) -> list:
    """[(water cell, empty cell it would flow into)] of a state."""
    g = world.model.grid
    out = []
    names = [world.mc_name(n) for n in g.value_names]
    for y in range(g.height):
        for z in range(g.depth):
            for x in range(g.width):
                if names[g.cell(state, x, y, z)] != "water":
                    continue
                for dx, dy, dz in SIDES:
                    n = (x + dx, y + dy, z + dz)
                    if 0 <= n[0] < g.width and 0 <= n[1] < g.height and 0 <= n[2] < g.depth \
                            and g.cell(state, *n) == g.default:
                        out.append(((x, y, z), n))
    return out


def known_step(world: WorldMap, before: bytes, after: bytes) -> tuple:
    """(notes, refusal) for one predicted step: the known differences of the state it
    leads to that were not there before (the agent's fall each time), and why the step
    must not be executed (or None)."""
    from .actions import changed_cells
    from .moves import solid
    g = world.model.grid
    notes, refusal = known(world, after)
    earlier = set(known(world, before)[0])
    notes = [n for n in notes if n not in earlier or "the agent stands" in n]
    for x, y, z, old, new in changed_cells(world.model, before, after):
        if new == g.default and world.mc_name(g.value_names[old]) in ("water", "lava"):
            refusal = refusal or (f"the model mines the {g.value_names[old]} at {(x, y, z)}; in Minecraft a "
                                  "liquid is not mined (a bucket takes it)")
        elif new != g.default and not any(solid(world, before, x + dx, y + dy, z + dz)
                                          for dx, dy, dz in SIDES + ((0, 1, 0),)):
            refusal = refusal or (f"the model places {g.value_names[new]} at {(x, y, z)}, where no solid block "
                                  "touches it (the model counts water as a block); in Minecraft a block is "
                                  "placed only against a solid face")
    return notes, refusal


def known(world: WorldMap, state: bytes) -> tuple:
    """(notes, refusal) for a predicted state: what the game would do differently, and
    why the step must not be executed (or None)."""
    g = world.model.grid
    notes = []
    depth = fall_depth(world, state)
    x, y, z = world.model.agent_position(state)
    if depth is None:
        notes.append("known difference: the agent stands over nothing; in Minecraft it would fall out of "
                     "the world (the model has no gravity): the bot is held in its cell")
    elif depth:
        hurt = " and be hurt" if depth > 3 else ""
        notes.append(f"known difference: the agent stands over {depth} empty cell{'s' if depth > 1 else ''}; "
                     f"in Minecraft it would fall {depth} level{'s' if depth > 1 else ''}{hurt} "
                     "(the model has no gravity): the bot is held in its cell")
    refusal = None
    body = {(x, y, z), (x, y + 1, z)}
    for water, into in flows(world, state):
        if into in body:
            refusal = (f"the agent would stand in water flowing from {water} into {into}: in Minecraft the "
                       "current would carry it where the model cannot say")
        notes.append(f"known difference: the water at {water} would flow into {into} in Minecraft "
                     "(this server, like the model, has no flowing water)")
    names = [world.mc_name(n) for n in g.value_names]
    for yy in range(1, g.height):
        for zz in range(g.depth):
            for xx in range(g.width):
                if names[g.cell(state, xx, yy, zz)] in FALLING and g.cell(state, xx, yy - 1, zz) == g.default:
                    notes.append(f"known difference: the {g.value_names[g.cell(state, xx, yy, zz)]} at "
                                 f"{(xx, yy, zz)} stands on nothing and would fall in Minecraft")
    return notes, refusal
