"""Memory probes and the address-space cap that makes a memory budget hard.

A memory budget is about resident memory, but the kernel can only cap address space
(RLIMIT_AS). The two differ by mappings that are not resident -- shared libraries
imported after the cap was set, reserved but untouched pages -- so the cap is anchored
to the address space *now* plus what the budget still allows resident memory to grow by,
and re-anchored at each budget check of a search: imports and compiling before the
search then never count against it, and between two checks the process can grow by no
more than the budget left.
"""
from __future__ import annotations

import os
import resource

_PAGE = os.sysconf("SC_PAGE_SIZE") if hasattr(os, "sysconf") else 4096
_budget_mb: float | None = None   # the memory budget the cap enforces, while one is armed


def physical_memory_mb() -> float:
    try:
        return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2**20
    except (ValueError, OSError, AttributeError):
        return 8192.0


def _statm() -> tuple[int, int] | None:
    """(address space, resident) in bytes, from Linux /proc."""
    try:
        with open("/proc/self/statm") as f:
            fields = f.read().split()
        return int(fields[0]) * _PAGE, int(fields[1]) * _PAGE
    except (OSError, ValueError, IndexError):
        return None


def current_rss_mb() -> float:
    """Resident memory now (Linux /proc), else the peak so far."""
    statm = _statm()
    if statm is None:
        return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    return statm[1] / 2**20


def peak_rss_mb() -> float:
    """The process's peak resident memory so far: the `peak_mb` of a result, which a
    sampled maximum would understate. Linux's VmHWM is this process's own high-water
    mark; ru_maxrss is not, since it starts from the parent's resident size at fork (a
    solve started by a 400 MB process would report 400 MB), so it is only the fallback."""
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024
    except (OSError, ValueError, IndexError):
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def cap_growth(extra_mb: float, lock: bool = False, statm: tuple[int, int] | None = None) -> bool:
    """Cap the address space at what the process maps now plus `extra_mb` (never above
    the hard limit); with `lock`, the hard limit too, so the process cannot lift it (a
    sandboxed job). `statm` is a reading the caller already made. False when this system
    has no /proc or rlimits to do it with."""
    statm = statm or _statm()
    if statm is None:
        return False
    try:
        hard = resource.getrlimit(resource.RLIMIT_AS)[1]
        cap = int(statm[0] + max(extra_mb, 1) * 2**20)
        if hard != resource.RLIM_INFINITY:
            cap = min(cap, hard)
        resource.setrlimit(resource.RLIMIT_AS, (cap, cap if lock else hard))
    except (OSError, ValueError):
        return False
    return True


def arm_cap(max_memory_mb: float):
    """Cap the address space for `max_memory_mb` of resident memory; returns what
    `disarm_cap` restores, or None when this system has no cap to set."""
    global _budget_mb
    outer = _budget_mb
    try:
        old = resource.getrlimit(resource.RLIMIT_AS)
    except (OSError, ValueError):
        return None
    _budget_mb = max_memory_mb if outer is None else min(outer, max_memory_mb)
    if not cap_growth(_budget_mb - current_rss_mb()):
        _budget_mb = outer
        return None
    return old, outer


def disarm_cap(armed) -> None:
    """Undo `arm_cap` (nested caps restore the outer one)."""
    global _budget_mb
    if armed is None:
        return
    old, _budget_mb = armed
    try:
        resource.setrlimit(resource.RLIMIT_AS, old)
    except (OSError, ValueError):
        pass


def memory_check(max_memory_mb: float | None, reserve_mb: float) -> tuple[float, bool]:
    """A search's memory check, from one reading of /proc: (resident MB now, whether the
    process may grow by `reserve_mb` more). It first moves an armed cap to the address
    space now plus the budget left, so mappings added since the last check (imports, a
    heuristic's tables) do not count; then the growth must fit both the budget and the
    cap, since a growth the cap refuses is a MemoryError with nothing left to handle it."""
    statm = _statm()
    if statm is None:
        resident = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
        return resident, max_memory_mb is None or resident + reserve_mb <= max_memory_mb
    space, resident = statm[0], statm[1] / 2**20
    if max_memory_mb is None:
        return resident, True
    if _budget_mb is not None:
        cap_growth(_budget_mb - resident, statm=statm)
    try:
        cap = resource.getrlimit(resource.RLIMIT_AS)[0]
    except (OSError, ValueError):
        cap = resource.RLIM_INFINITY
    room = cap == resource.RLIM_INFINITY or space + (reserve_mb + 16) * 2**20 <= cap
    return resident, room and resident + reserve_mb <= max_memory_mb
