"""What a call of the default exact checker costs by its size (issue 51): a planner asks tens of configurations at
a time, and every call has a fixed cost that a batch of thousands hides. ``toolkit bench`` prints it as
``exact_small_call_cost``, ``docs/scripts/small_call_cost.py`` in full (docs/benchmarks.md, "Small calls")."""

from __future__ import annotations

import time

import numpy as np

from toolkit.geometry.collision import exact_checker
from toolkit.scenarios import Scenario

__all__ = ["SMALL_CALLS", "small_call_cost"]

SMALL_CALLS = (16, 32, 64)  # configurations a call, as a planner makes them


def small_call_cost(
    scenario: Scenario, *, batch: int = 20_000, seed: int = 0, repeats: int = 7, sizes: tuple[int, ...] = SMALL_CALLS
) -> dict:
    """What the default exact checker's calls cost by their size, on ``batch`` uniform configurations in a query
    workspace: each of ``repeats`` rounds times, by the thread's CPU clock, one call of all of them, ``batch`` calls
    of none, and the same configurations cut in calls of each of ``sizes``, every call's answers dropped as a
    planner drops them; medians over the rounds, in ns: ``batch_ns`` (a configuration in the batch), ``empty_ns``
    (a call of none), per size ``call_ns`` (a configuration in calls of that size) and ``ratios`` (that over
    ``batch_ns``, keyed by the size as a string), and ``fixed_16_ns``: what a call of 16 costs beyond checking 16
    configurations at the batch's rate (below 16 ``batch_ns``, calls of 16 cost under twice the batch's).

    ``toolkit bench`` (:func:`throughput`'s ``exact_small_call_cost``) and ``docs/scripts/small_call_cost.py``
    both print this. The CPU clock counts what the call computed, not a wait for a core beside other work."""
    ws = scenario.workspaces("query", 1, seed)[0]
    checker, batch = exact_checker(ws, scenario.robot), max(batch, *sizes)  # a call of each size at least
    Q = scenario.robot.sample(np.random.default_rng(seed), batch)  # (batch, dof)
    checker.are_valid(Q)  # compiled, or loaded from the cache, before anything is timed
    empty, pieces = Q[:0], {size: [Q[i : i + size] for i in range(0, batch - size + 1, size)] for size in sizes}
    times: dict = {key: [] for key in ("batch", 0, *sizes)}
    for _ in range(repeats):
        start = time.thread_time_ns()
        checker.are_valid(Q)
        times["batch"].append((time.thread_time_ns() - start) / batch)
        start = time.thread_time_ns()
        for _ in range(batch):
            checker.are_valid(empty)
        times[0].append((time.thread_time_ns() - start) / batch)
        for size in sizes:
            start = time.thread_time_ns()
            for piece in pieces[size]:
                checker.are_valid(piece)
            times[size].append((time.thread_time_ns() - start) / (len(pieces[size]) * size))
    cost = {key: float(np.median(values)) for key, values in times.items()}
    return {
        "batch_ns": cost["batch"],
        "empty_ns": cost[0],
        "call_ns": {str(size): cost[size] for size in sizes},
        "ratios": {str(size): cost[size] / cost["batch"] for size in sizes},
        "fixed_16_ns": 16 * (cost[16] - cost["batch"]) if 16 in sizes else None,
    }
