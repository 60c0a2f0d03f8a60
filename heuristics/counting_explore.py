"""The counting abstraction's forward exploration (`Builder.run`, counting_build.py): the
abstract states met from the start's, a layer at a time, then their distances to the
goal by a backward search by cost.

Apart from the builder, which decides what the abstraction keeps (exact cells, counted
classes, each action's touched cells) and answers for one abstract state; this module is
the loop over all of them and the tables it fills. Each step here is called once a layer;
the per-state work stays in `cell_edges`' one loop.
"""
from __future__ import annotations

import array
import time

from .backward import backward_distances, ranges, unique
from .counting_data import SHIFT, TOUCH_CAP, CountingDatabase, TooBig, as_numbers, getter


class Exploration:
    """One exploration. A state is numbered by its variables' id and its cell part's id
    (the exact cells, then the counts, 2 bytes each): `vid << SHIFT | rid`.

    Actions that touch no mutable cell (turning, looking) move from variables to
    variables whatever the cells hold: their successors are a table by variables id,
    applied to a whole layer at once in numpy. What the other actions do depends on the
    variables and, of the cell part, only on the bytes their touched cells' values are
    read from (the *view*, `Builder._seen`): memoized by (variables id, view); what a
    change does to the cells depends on the cell part only, memoized by id."""

    def __init__(self, builder):
        import numpy as np
        from ..model import cell_entries
        b = self.b = builder
        self.np, self.cell_entries = np, cell_entries
        variables = self.variables = {b.initial: 0}
        var_list = self.var_list = [b.initial]
        self.parts = {b.start_exact + bytes(2 * b.n_slots): 0}
        self.part_list = list(self.parts)
        # by cell part id, what the touched cells may hold: counts capped at 1 (for plans
        # whose actions touch one cell each) and at TOUCH_CAP
        self.seen_one, self.seen_more = [b._seen(self.part_list[0], 1)], [b._seen(self.part_list[0], TOUCH_CAP)]
        self.views: list = []         # by variables id: (view function, its actions that touch cells, seen list)
        self.free_ptr, self.free_dst, self.free_cost = [0], [], []   # by variables id: successors of the others
        self.successors: dict = {}    # (variables id, view) -> ((next variables id, changes, cost), ...)
        self.choices_of: dict = {}    # (cell part id, kinds) -> the value choices of the touched cells
        self.outcomes: dict = {}      # (action, variables id, values of the touched cells) -> ((next variables id, changes), ...)
        self.moved: dict = {}         # (cell part id, changes) -> next cell part id
        self.goal_memo: dict = {}
        self.goal_class: list = []    # by variables id: the id of the goal's variables' values
        self.goal_classes: dict = {}
        self.goal_vars: list = []     # by goal class: a variables id of that class
        self.gclass = np.zeros(0, dtype=np.int64)
        goal_idx = sorted(b.L.by_var[v].index for v in b.goal_vars if v in b.L.by_var)
        self.goal_of = getter(goal_idx)
        self.costs = [a.cost for a in b.actions]
        self.uniform = len({self.costs[i] for i in b.search}) <= 1
        self.mask = (1 << SHIFT) - 1
        self.fptr, self.fdst, self.fcost = np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64), np.zeros(0)

        def var_id(vb: bytes) -> int:
            found = variables.get(vb)
            if found is None:
                found = variables[vb] = len(var_list)
                var_list.append(vb)
            return found
        self.var_id = var_id

    def run(self) -> CountingDatabase:
        np = self.np
        known = np.zeros(1, dtype=np.int64)          # every state met, sorted
        frontier = known
        edge_src, edge_dst, edge_cost, goals = [], [], [], []
        while len(frontier):
            keys = frontier.tolist()
            self.add_views(int(frontier.max()) >> SHIFT)
            src, dst, cost = self.cell_edges(keys)
            vids, rids = frontier >> SHIFT, frontier & self.mask
            goals.append(self.goal_states(frontier, vids, rids))
            # the actions that touch no cell, for the whole layer
            idx, total = ranges(self.fptr[vids], self.fptr[vids + 1])
            layer_dst = np.concatenate((self.fdst[idx] | np.repeat(rids, total), np.frombuffer(dst, dtype=np.int64)))
            edge_src.append(np.concatenate((np.repeat(frontier, total), np.frombuffer(src, dtype=np.int64))))
            edge_dst.append(layer_dst)
            if not self.uniform:
                edge_cost.append(np.concatenate((self.fcost[idx], np.frombuffer(cost, dtype=np.float64))))
            frontier, known = self.new_states(known, layer_dst)
        return self.database(known, edge_src, edge_dst, edge_cost, goals)

    def add_views(self, vmax: int) -> None:
        """The view, the actions that touch cells and the free successors of every
        variables id up to `vmax` not yet planned, and its goal class; once each."""
        b, np, views, var_list = self.b, self.np, self.views, self.var_list
        while vmax >= len(views):
            vb = var_list[len(views)]
            view_of, cell_plan, free, cap = b._view(b._plan(vb, self.cell_entries, b.failure_reads_cells),
                                                    self.var_id, self.costs)
            views.append((view_of, cell_plan, self.seen_one if cap == 1 else self.seen_more))
            self.free_dst.extend(nvid for nvid, _ in free)
            self.free_cost.extend(c for _, c in free)
            self.free_ptr.append(len(self.free_dst))
            gk = self.goal_of(vb)
            if gk not in self.goal_classes:
                self.goal_classes[gk] = len(self.goal_classes)
                self.goal_vars.append(len(views) - 1)   # a variables id with these goal values
            self.goal_class.append(self.goal_classes[gk])
        if len(self.fptr) != len(self.free_ptr):   # the new variables' rows
            self.fptr = np.concatenate((self.fptr, np.array(self.free_ptr[len(self.fptr):], dtype=np.int64)))
            self.fdst = np.concatenate((self.fdst, np.array(self.free_dst[len(self.fdst):], dtype=np.int64) << SHIFT))
            self.fcost = np.concatenate((self.fcost, np.array(self.free_cost[len(self.fcost):], dtype=np.float64)))

    def cell_edges(self, keys: list):
        """The edges (sources, destinations, costs unless uniform) of the actions that
        touch cells, from each state of a layer; a move back to the same state is left out."""
        b = self.b
        deadline, mask, uniform, views, successors = b.deadline, self.mask, self.uniform, self.views, self.successors
        var_list, part_list, parts, moved = self.var_list, self.part_list, self.parts, self.moved
        seen_one, seen_more = self.seen_one, self.seen_more
        var_id, costs, cell_entries = self.var_id, self.costs, self.cell_entries
        choices_of, outcomes = self.choices_of, self.outcomes
        src, dst, cost = array.array("q"), array.array("q"), array.array("d")
        for n, key in enumerate(keys):
            if n & 8191 == 8191 and time.process_time() > deadline:
                raise TooBig("the time limit ran out", timed_out=True)
            vid, rid = key >> SHIFT, key & mask
            view_of, cell_plan, seen_of = views[vid]
            if not cell_plan:
                continue
            skey = (vid, view_of(seen_of[rid])) if view_of is not None else (vid, None, rid)
            succ = successors.get(skey)
            if succ is None:
                succ = successors[skey] = b._cell_successors(vid, var_list[vid], rid, part_list[rid], cell_plan,
                                                             var_id, costs, cell_entries, choices_of, outcomes)
            for nvid, changes, c in succ:
                if changes:
                    mkey = (rid, changes)
                    nrid = moved.get(mkey)
                    if nrid is None:
                        nb = b._moved(part_list[rid], changes)
                        nrid = parts.get(nb)
                        if nrid is None:
                            nrid = parts[nb] = len(part_list)
                            part_list.append(nb)
                            seen_one.append(b._seen(nb, 1))
                            seen_more.append(b._seen(nb, TOUCH_CAP))
                        moved[mkey] = nrid
                else:
                    nrid = rid
                nkey = nvid << SHIFT | nrid
                if nkey != key:
                    src.append(key)
                    dst.append(nkey)
                    if not uniform:
                        cost.append(c)
        return src, dst, cost

    def goal_states(self, frontier, vids, rids):
        """The states of `frontier` that meet the goal: tested once per (the goal's
        variables' values, cell part)."""
        np, b, mask, goal_memo = self.np, self.b, self.mask, self.goal_memo
        if len(self.gclass) != len(self.goal_class):
            self.gclass = np.concatenate((self.gclass, np.array(self.goal_class[len(self.gclass):], dtype=np.int64)))
        gkeys = self.gclass[vids] << SHIFT | rids
        distinct = unique(gkeys)
        for gkey in distinct.tolist():
            if gkey not in goal_memo:
                goal_memo[gkey] = bool(b._goal(self.var_list[self.goal_vars[gkey >> SHIFT]], self.part_list[gkey & mask]))
        met_goal = np.array([goal_memo[g] for g in distinct.tolist()], dtype=bool)
        return frontier[met_goal[np.searchsorted(distinct, gkeys)]]

    def new_states(self, known, layer_dst):
        """The next frontier (the destinations not met before) and `known` with them;
        TooBig past the state or time limit."""
        np, b = self.np, self.b
        met = unique(layer_dst)
        pos = np.searchsorted(known, met)
        fresh = (pos >= len(known)) | (known[np.minimum(pos, len(known) - 1)] != met)
        frontier = met[fresh]
        known = np.insert(known, pos[fresh], frontier)
        if len(known) > b.max_states or len(self.part_list) > self.mask:
            raise TooBig(f"more than {b.max_states:,} abstract states")
        if time.process_time() > b.deadline:
            raise TooBig("the time limit ran out", timed_out=True)
        return frontier, known

    def database(self, known, edge_src, edge_dst, edge_cost, goals) -> CountingDatabase:
        """Every known state's distance to the goal, by a backward search by cost."""
        np, b = self.np, self.b
        s_idx = np.searchsorted(known, np.concatenate(edge_src)).astype(np.int32)
        d_idx = np.searchsorted(known, np.concatenate(edge_dst)).astype(np.int32)
        if self.uniform:
            c_all = np.full(len(s_idx), float(self.costs[b.search[0]] if b.search else 1))
        else:
            c_all = np.concatenate(edge_cost)
        dist = backward_distances(len(known), s_idx, d_idx, c_all, np.searchsorted(known, np.concatenate(goals)))
        table = dict(zip(known.tolist(), as_numbers(dist)))
        return CountingDatabase(b.base, dict(b.exact), b.start_exact, dict(b.tracked), b.n_slots,
                                self.variables, self.parts, table, len(known),
                                tuple((j, b.initial[j]) for j, _ in b.projected))
