"""The run-time helpers that generated successor code calls: reading and writing a grid
cell (`_cell`, `_set_cell`), index, range and division errors (`_index`, `_range`,
`_divide`), and, for compact states, the expansion of a state's changed cells into a
full cell array (`_cells`, `_expand`, `_derive`, cached in `_CC`) and the merging of
cell writes back into a sorted diff (`_merge`).

Apart from emit.py because they run once per state, not once per compile: they are
closures over one layout's constants (grid size, layers, start cells) so each read is a
local lookup, and emit.py only writes the code that calls them.
"""
from __future__ import annotations

from bisect import bisect_left

from ..errors import ModelError
from ..model import cell_entries, pack_entry


def run_time_helpers(L, area: int, GB: int) -> dict:
    """The generated code's namespace entries for layout `L`: `area` cells a layer, cell
    reads and writes at offset `GB` of the state (0 for the expanded cells of a compact
    state)."""
    cell, set_cell = _grid_access(L, area, GB)
    S0 = L.start_cells
    cells, merge, expand, expanded, derive = _cell_expansion(L.grid_base, S0)
    return dict(_cell=cell, _set_cell=set_cell, _index=index, _range=out_of_range, _divide=divide, _cells=cells,
                _merge=merge, _S0=S0, _expand=expand, _CC=expanded, _from_bytes=int.from_bytes,
                _derive=derive)


def _grid_access(L, area: int, GB: int):
    """`cell(s, x, y, z)` (the grid's default outside it, the static grid in a layer no
    action changes) and `set_cell(n, x, y, z, v, action)`."""
    W, D, H, DEF = L.width, L.depth, L.height, L.grid_default
    layer_of = {y: i for i, y in enumerate(L.layers)}

    def cell(s, x, y, z):
        if not (0 <= x < W and 0 <= z < D and 0 <= y < H):
            return DEF
        i = layer_of.get(y)
        if i is None:
            return L.static_grid[y * area + z * W + x]
        return s[GB + i * area + z * W + x]

    def set_cell(n, x, y, z, v, action):
        i = layer_of.get(y)
        if not (0 <= x < W and 0 <= z < D) or i is None:
            raise ModelError(f"action {action} changes the cell ({x}, {y}, {z}), which is outside the grid "
                             "or in a layer no action was found to change")
        n[GB + i * area + z * W + x] = v
    return cell, set_cell


def index(i, n, label):
    if not 0 <= i < n:
        raise ModelError(f"{label}: index {i} is outside 0..{n - 1}")
    return i


def out_of_range(label, v, lo, hi):
    raise ModelError(f"{label} would become {v}, outside its range [{lo}, {hi}]")


def divide(a, b, modulo, label):
    if not b:
        raise ModelError(label)   # "file:line:col: `//` by zero"
    return a % b if modulo else a // b


def one_entry_apart(ds: bytes, dt: bytes, S0: bytes) -> tuple[int, int] | None:
    """(cell, value) when the changed-cell diffs `ds` and `dt` differ by one entry (one
    added, one cell's value changed, or one removed: that cell is back at its start value
    in `S0`), else None. The entries alike from the start are found by a binary search
    over the bytes. An entry replaced by another cell's (one cell back at its start, one
    newly changed: a push that moves a box) is two changes, not one."""
    lo, hi = 0, min(len(ds), len(dt)) // 4
    while lo < hi:
        mid = (lo + hi + 1) // 2
        if ds[:4 * mid] == dt[:4 * mid]:
            lo = mid
        else:
            hi = mid - 1
    p = 4 * lo
    if dt[p + 4:] == ds[p:] or (dt[p + 4:] == ds[p + 4:] and dt[p + 1:p + 4] == ds[p + 1:p + 4]):
        e = int.from_bytes(dt[p:p + 4], "little")            # one entry added, or one cell's value changed
        return e >> 8, e & 255
    if dt[p:] == ds[p + 4:]:                                # one removed: the cell is back at its start
        e = int.from_bytes(ds[p:p + 4], "little")
        return e >> 8, S0[e >> 8]
    return None


def _cell_expansion(NV: int, S0: bytes):
    """The cells of a compact state (`NV` bytes of variables, then its changed cells)
    expanded from the start's `S0` (`cells`, `expand`, `derive`; the cache `expanded`,
    read by generated code first), and cell writes merged into its diff (`merge`)."""
    expanded: dict = {}   # diff -> cells; generated code reads it first (`_CC.get`)
    keep = max(1024, (16 << 20) // max(1, len(S0)))   # about 16 MB of expansions at most

    def expand(diff):
        c = expanded.get(diff)
        if c is None:
            if len(expanded) >= keep:
                expanded.clear()
            c = bytearray(S0)
            for e in cell_entries(diff):
                c[e >> 8] = e & 255
            c = expanded[diff] = bytes(c)
        return c

    def derive(s, t):
        """Cache the expansion of `t`, a successor of `s` whose expansion is cached,
        when their changed cells differ by one entry (an action that writes one
        cell): `s`'s expansion with that cell patched, found by comparing the two
        diffs as bytes. A search that steps along one path (htn) then expands no
        state by a pass over all its changed cells."""
        if len(t) == NV:
            return
        dt, ds = t[NV:], s[NV:]
        if dt in expanded:
            return
        cs = S0 if not ds else expanded.get(ds)
        if cs is None:
            return
        change = one_entry_apart(ds, dt, S0)
        if change is None:
            return
        cell, value = change
        c = bytearray(cs)
        c[cell] = value
        if len(expanded) >= keep:
            expanded.clear()
        expanded[dt] = bytes(c)

    def cells(s):
        """The mutable cells of compact state `s`, expanded: the start's when nothing
        changed, else cached per distinct diff (states that differ only in their
        variables, e.g. the agent's position, share one expansion)."""
        return S0 if len(s) == NV else expand(s[NV:])

    def merge(n, w):
        """`n` (a copy of the old state, variables written) with the cell writes `w` merged
        into its sorted diff; cells back at their start value leave the diff. Each write
        is spliced in where a binary search finds it, so a state with thousands of
        changed cells costs a copy, not a re-encoding of every entry."""
        if len(n) <= NV:
            for k in sorted(w):
                v = w[k]
                if v != S0[k]:
                    n += pack_entry(k, v)
            return bytes(n)
        diff = bytes(n[NV:])
        del n[NV:]
        entries = cell_entries(diff)
        size, pos = len(entries), 0
        for k in sorted(w):
            i = bisect_left(entries, k << 8, pos)
            n += diff[4 * pos:4 * i]
            if i < size and entries[i] >> 8 == k:
                i += 1                 # the old entry of this cell is replaced
            v = w[k]
            if v != S0[k]:
                n += pack_entry(k, v)
            pos = i
        n += diff[4 * pos:]
        return bytes(n)
    return cells, merge, expand, expanded, derive
