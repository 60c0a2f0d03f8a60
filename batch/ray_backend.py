"""The Ray backend: the same items as Ray tasks, on a local Ray or an existing cluster.

Ray does the scheduling; bcc only keeps at most `workers` tasks in flight (by default
the cluster's CPUs), so a killed sweep loses no more than those. Each task runs its
item through `limits.run_limited`, in a child process of the Ray worker, so hard limits
and crashes behave exactly as in the local backend. Ray is optional: imported here only.
"""
from __future__ import annotations

import os
from typing import Callable, Iterable, Iterator

from ..errors import BccError
from ..extras import install_hint
from ..run.children import Limits, Outcome, one_line, run_limited

INSTALL = f"the ray backend needs Ray: {install_hint('ray')}"


def import_ray():
    try:
        import ray
    except ImportError:
        raise BccError(INSTALL) from None
    return ray


def connect(ray, address: str | None, workers: int | None) -> bool:
    """Join a running Ray (this process's, or the cluster at `address`) or start a local
    one; True when this call started it (and so must shut it down)."""
    if ray.is_initialized():
        return False
    try:
        if address:
            ray.init(address=address, log_to_driver=False)
        else:
            ray.init(num_cpus=workers or os.cpu_count() or 1, include_dashboard=False, log_to_driver=False)
    except (ConnectionError, ValueError, RuntimeError) as exc:
        where = f"the Ray cluster at {address}" if address else "a local Ray"
        raise BccError(f"cannot connect to {where}: {one_line(exc)}") from None
    return True


def map_ray(function, items: Iterable, workers: int | None, limits_of: Callable[[object], Limits],
            address: str | None = None, prepare: Callable | None = None) -> Iterator[Outcome]:
    ray = import_ray()
    started = connect(ray, address, workers)
    task = ray.remote(num_cpus=1, max_retries=0)(run_limited)
    function_ref = ray.put(function)  # shipped once, not with every task
    if not workers:
        workers = max(int(ray.cluster_resources().get("CPU", 1)), 1)
    in_flight: dict = {}
    try:
        for index, item in enumerate(items):
            while len(in_flight) >= workers:
                yield from _collect(ray, in_flight)
            in_flight[task.remote(function_ref, item, limits_of(item), index, prepare)] = index
        while in_flight:
            yield from _collect(ray, in_flight)
    finally:
        for ref in in_flight:
            try:
                ray.cancel(ref, force=True)
            except Exception:  # noqa: BLE001 - best effort on the way out
                pass
        if started:
            ray.shutdown()


def _collect(ray, in_flight: dict) -> Iterator[Outcome]:
    done, _ = ray.wait(list(in_flight), num_returns=1)
    for ref in done:
        index = in_flight.pop(ref)
        try:
            yield ray.get(ref)
        except ray.exceptions.RayError as exc:  # the Ray worker or its node died
            yield Outcome(index, error=f"ray task failed: {one_line(exc)}"[:500])
