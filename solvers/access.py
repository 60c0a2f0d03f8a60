"""Access for the build solver: an atom is not written where it takes the last place from
which a pending atom can still be written.

An achiever that does not move the agent writes its cell from a *standing place* whose
*body cells* (heuristics/goal_cells.footing: the cells the agent takes there) must be
free. When the goal puts blocks into every body cell of every standing place of an atom
q (a cell walled in by other atoms, the middle of a slab), q must be written before the
last of those blocks, or never: the support levels and orders do not say so, since they
read only what an achiever needs on its own cells. `Access.kills(state-free view, p)`
tells the serialiser that writing p now would leave some pending atom without a place.
Nothing here knows what the cells or values mean.
"""
from __future__ import annotations


def _add(p, o):
    return (p[0] + o[0], p[1] + o[1], p[2] + o[2])


class Access:
    """The standing places of the goal's atoms and the goal cells in their bodies."""

    def __init__(self, cells, body_offsets, default):
        self.default = default
        self.places = {}        # atom position -> [standing place]
        self.body = {}          # standing place -> [its body cells]
        self.blocks = {}        # cell -> [atom positions with a place whose body holds it]
        goal = {pos for pos, v in cells.atoms if v != default}
        for pos, v in cells.atoms:
            achievers = [a for a in cells.achievers.get(v, ()) if not a.moves]
            for a in achievers:
                st = (pos[0] - a.write[0], pos[1] - a.write[1], pos[2] - a.write[2])
                self.places.setdefault(pos, []).append(st)
                body = [_add(st, o) for o in body_offsets]
                self.body[st] = body
                for cell in body:
                    if cell in goal and cell != pos:
                        self.blocks.setdefault(cell, []).append(pos)

    def _live(self, q, filled, extra=None) -> bool:
        """Some standing place of q has no filled body cell (nor `extra`)."""
        default = self.default
        for st in self.places.get(q, ()):
            if all(c != extra and filled.get(c, default) == default for c in self.body[st]):
                return True
        return False

    def kills(self, p, todo, filled) -> bool:
        """Writing the atom at p (a non-default value) takes the last place of a pending
        atom that has one now. `filled`: the written atoms (position -> value)."""
        if todo.get(p, self.default) == self.default:
            return False
        for q in self.blocks.get(p, ()):
            if q != p and q in todo and self._live(q, filled) and not self._live(q, filled, p):
                return True
        return False
