"""The calls our planners make to the exact checker, and what they cost against one batch (docs/benchmarks.md,
"For maintainers", "Inside the compiled checker").

    python docs/scripts/planner_call_sizes.py [N_QUERIES [SEED]]

Plans the race's first N_QUERIES queries (default 20, seed 7300: ``versus_ompl.race_queries``) of each 3D scenario
with the lazy PRM and RRT-Connect (sampler BS), recording every configuration array handed to the compiled checker.
Prints per planner: the calls, their median size, the share of calls of 16 or fewer, and then the recorded calls
replayed on one thread against the same configurations checked in one call (thread CPU time, in turns, median of 7
rounds): the planner's checks as a multiple of their batched cost. The replay answers as the planner's calls did.
"""

import sys
import time

import numpy as np

from toolkit import scenarios
from toolkit.experiments import versus_ompl
from toolkit.experiments.queries import make_planner, one_thread
from toolkit.geometry.compiled import CompiledChecker
from toolkit.planning import prm

n_queries, seed = (int(a) for a in (sys.argv[1:3] + ["20", "7300"][len(sys.argv) - 1 :]))
recorded: list[tuple[CompiledChecker, np.ndarray]] = []  # (checker, configurations (n, dof)) per call
original = CompiledChecker.are_valid


def recording(self: CompiledChecker, q: np.ndarray) -> np.ndarray:
    recorded.append((self, np.array(q)))
    return original(self, q)


def replay(calls: list[tuple[CompiledChecker, np.ndarray]]) -> int:
    """Thread CPU time, ns, of every call in turn."""
    start = time.thread_time_ns()
    for checker, q in calls:
        original(checker, q)
    return time.thread_time_ns() - start


CompiledChecker.are_valid = recording  # type: ignore[method-assign]
print("| scenario, planner | calls | median call | calls of <= 16 | the calls' time / one batch's |")
print("| --- | ---: | ---: | ---: | ---: |")
with one_thread():
    for name in ("3dc7", "3dc9", "3do"):
        scenario = scenarios.get(name)
        for label, option in (("lazy PRM", prm.DEFAULT), ("RRT-Connect", "rrt-connect")):
            plan = versus_ompl.our_planner(make_planner(scenario, option), scenario, sampler="BS", seed=seed)
            recorded.clear()
            for n, query in enumerate(versus_ompl.race_queries(scenario, n_queries, seed)):
                plan(query, CompiledChecker(query.workspace, scenario.robot), n)
            sizes = np.array([len(q) for _, q in recorded])  # (calls,)
            batches = {}  # checker -> all its configurations (n, dof)
            for checker, q in recorded:
                batches.setdefault(checker, []).append(q)
            batched = [(checker, np.concatenate(qs)) for checker, qs in batches.items()]
            ratios = [replay(recorded) / replay(batched) for _ in range(7)]
            print(
                f"| {name}, {label} | {len(sizes)} | {np.median(sizes):.0f} | {np.mean(sizes <= 16):.0%} "
                f"| {np.median(ratios):.2f} |"
            )
