"""What a small call costs the compiled box checker per configuration, against one batch (docs/benchmarks.md,
"For maintainers", "Inside the compiled checker").

    python docs/scripts/small_call_cost.py [SCENARIOS [ROUNDS]]

Per scenario (default ``3dc7,3dc9,3do``), on the first query workspace, 20,000 uniform configurations: each round
times by the thread's CPU clock one call of all of them, 20,000 calls of none, and the same configurations cut in
calls of 16, 32 and 64. Prints the medians over the rounds (default 7): the batch's cost per configuration, an empty
call's cost, per call size a configuration's cost over its batched cost, and what a call of 16 costs beyond checking
its configurations at the batch's rate (the fixed cost of a call: the target, calls of 16 within twice the batched
cost, needs it below 16 batched checks). Run it several times, in turns with the code it is compared with, and take
the median of the runs: on a shared machine one run moves by several per cent.
"""

import sys
import time

import numpy as np

from toolkit.geometry.collision import exact_checker
from toolkit.scenarios import get

SIZES = (16, 32, 64)
N = 20_000


def rounds(name: str, n_rounds: int) -> dict:
    """Per round, ns: the batch's cost per configuration, an empty call's, and per size a configuration's."""
    scenario = get(name)
    checker = exact_checker(scenario.workspaces("query", 1, 0)[0], scenario.robot)
    Q = scenario.robot.sample(np.random.default_rng(0), N)  # (N, dof)
    checker.are_valid(Q)  # compiled, or loaded from the cache, before anything is timed
    empty, times = Q[:0], {key: [] for key in ("batch", 0, *SIZES)}
    for _ in range(n_rounds):
        start = time.thread_time_ns()
        checker.are_valid(Q)
        times["batch"].append((time.thread_time_ns() - start) / N)
        start = time.thread_time_ns()
        for _ in range(N):
            checker.are_valid(empty)
        times[0].append((time.thread_time_ns() - start) / N)
        for size in SIZES:
            pieces = [Q[i : i + size] for i in range(0, N - size + 1, size)]
            start = time.thread_time_ns()
            for piece in pieces:
                checker.are_valid(piece)
            times[size].append((time.thread_time_ns() - start) / (len(pieces) * size))
    return {key: float(np.median(values)) for key, values in times.items()}


if __name__ == "__main__":
    names = sys.argv[1].split(",") if len(sys.argv) > 1 else ["3dc7", "3dc9", "3do"]
    n_rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 7
    for name in names:
        cost = rounds(name, n_rounds)
        ratios = "  ".join(f"{size}: {cost[size] / cost['batch']:.2f}x" for size in SIZES)
        fixed = 16 * (cost[16] - cost["batch"])  # ns a call of 16 costs beyond 16 batched checks
        line = f"{name}: batch {cost['batch']:.1f} ns/cfg  empty {cost[0]:.0f} ns  {ratios}  fixed(16) {fixed:.0f} ns"
        print(line, flush=True)
