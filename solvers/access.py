"""Access for the build solver: an atom is not written where it takes the last place from
which a pending atom can still be written.

An achiever that does not move the agent writes its cell from a *standing place* whose
*body cells* (heuristics/goal_cells.footing: the cells the agent takes there) must be
free. When the goal puts blocks into every body cell of every standing place of an atom
q (a cell walled in by other atoms, the middle of a slab), q must be written before the
last of those blocks, or never: the support levels and orders do not say so, since they
read only what an achiever needs on its own cells. `Access.kills(state-free view, p)`
tells the serialiser that writing p now would leave some pending atom without a place.
`exit_orders` looks further ahead, once at the start: a pending atom all of whose places
have goal cells in their bodies (a floor cell inside walls) must be written before those
cells, which must in turn be written before the cells their own place needs, out to a
place that stays free; the orders it returns say so, so the region fills from the inside
out instead of closing its last cell in.
Nothing here knows what the cells or values mean.
"""
from __future__ import annotations

import heapq


def _add(p, o):
    return (p[0] + o[0], p[1] + o[1], p[2] + o[2])


class Access:
    """The standing places of the goal's atoms and the goal cells in their bodies."""

    def __init__(self, cells, body_offsets, default):
        self.default = default
        self.places = {}        # atom position -> [standing place]
        self.body = {}          # standing place -> [its body cells]
        self.blocks = {}        # cell -> [atom positions with a place whose body holds it]
        self.in_body = {}       # cell -> [(atom position, its standing place whose body holds the cell)]
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
                        self.in_body.setdefault(cell, []).append((pos, st))

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

    def in_the_way(self, p, todo, first, footed) -> bool:
        """Writing the atom at p fills the body of a standing place that a pending atom q
        for which `first(q)` holds may still be written from (`footed(place)`: the place
        has, or will have, something to stand on): a write ahead of the order must not."""
        return any(q in todo and first(q) and footed(st) for q, st in self.in_body.get(p, ()))


def exit_orders(access: Access, todo: dict, holding: set, waits: dict) -> dict:
    """{q: [p, ...]} (q waits for p) for the pending atoms `todo` (position -> value) whose
    every standing place has a pending goal cell in its body. depth(p) is 0 when p has a
    place whose body holds no goal cell (cells that need not stay as they are count as
    free: what is not in the goal may be cleared), else 1 + the least, over its places,
    of the greatest depth of the pending atoms in the body; a place with an atom that
    already holds (`holding`) in its body is closed for good. Each atom of depth > 0 keeps
    the place of least depth, and the pending atoms in its body wait for it; an order
    that would close a cycle with `waits` (the orders the actions imply) is left out."""
    pending = {p for p, v in todo.items() if v != access.default}
    depth, heap = {}, []
    left, worst = {}, {}     # place -> pending body atoms not yet resolved / their greatest depth
    in_body = {}             # pending atom -> the places whose body holds it
    atoms_at = {}            # place -> the atoms it is a place of
    for p in pending:
        for st in access.places.get(p, ()):
            body = access.body[st]
            if any(c in holding for c in body):
                continue
            inside = [c for c in body if c in pending and c != p]
            if not inside:
                heapq.heappush(heap, (0, p, st))
                continue
            if st not in left:
                left[st], worst[st] = len(inside), -1
                for c in inside:
                    in_body.setdefault(c, []).append(st)
            atoms_at.setdefault(st, []).append(p)
    chosen = {}
    while heap:
        d, p, st = heapq.heappop(heap)
        if p in depth:
            continue
        depth[p], chosen[p] = d, st
        for place in in_body.get(p, ()):
            left[place] -= 1
            worst[place] = max(worst[place], d)
            if left[place] == 0:
                for q in atoms_at.get(place, ()):
                    if q not in depth:
                        heapq.heappush(heap, (worst[place] + 1, q, place))
    out: dict = {}
    for p, d in depth.items():
        if d == 0:
            continue
        for c in access.body[chosen[p]]:
            if c in pending and c != p and not _reaches(waits, p, c):
                out.setdefault(c, []).append(p)
    return out


def _reaches(waits: dict, start, goal, limit: int = 10_000) -> bool:
    """`start` waits for `goal`, directly or through other atoms, in `waits`."""
    seen, stack = {start}, [start]
    while stack and len(seen) < limit:
        q = stack.pop()
        for p in waits.get(q, ()):
            if p == goal:
                return True
            if p not in seen:
                seen.add(p)
                stack.append(p)
    return False
