"""Throughput of the exact checkers, timed in turns in one run: the python-fcl reference and the compiled default.

    python docs/scripts/checker_speed.py [SCENARIO ...] [--configs N] [--turns T] [--small S]

For each scenario (default 2ds 3dc7 3dc9 3do): the seed-0 workspace, ``N`` (20,000)
uniform configurations, then ``T`` (5) rounds timed in turns
(:func:`toolkit.experiments.bench.in_turns`), each timing ``FCLChecker``, ``CompiledChecker``
and, for the 2D point robot, ``PointRobotChecker`` on the same batch, and the compiled checker
on the batch in calls of ``S`` (30) configurations, as a planner makes them. Prints one JSON
line per scenario: median configurations per second of each, the compiled / FCL ratio, the
small calls' rate over the batched one, the load average, whether the answers agree, and each
checker's first call in seconds, paid before the turns (the compiled checker's loads numba's
code, or compiles it: with ``NUMBA_CACHE_DIR`` set to an empty folder it shows a cold start).
"""

import argparse
import json
import os
import time

import numpy as np

from toolkit import scenarios
from toolkit.experiments.bench import in_turns
from toolkit.geometry.collision import CompiledChecker, FCLChecker, PointRobotChecker


def timed_calls(checkers: dict, Q: np.ndarray, small: int) -> dict:
    """For :func:`in_turns`: each checker on the batch ``Q (N, dof)``, and the compiled one in calls of ``small``."""
    pieces = np.array_split(Q, max(len(Q) // small, 1))  # (small, dof) each
    calls = {key: (lambda c=checker: c.are_valid(Q), len(Q)) for key, checker in checkers.items()}
    calls["compiled_small"] = (lambda: [checkers["compiled"].are_valid(piece) for piece in pieces], len(Q))
    return calls


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenarios", nargs="*", default=["2ds", "3dc7", "3dc9", "3do"])
    parser.add_argument("--configs", type=int, default=20_000)
    parser.add_argument("--turns", type=int, default=5)
    parser.add_argument("--small", type=int, default=30)
    args = parser.parse_args()
    for name in args.scenarios:
        scenario = scenarios.get(name)
        ws, robot = scenario.make_workspace(np.random.default_rng(0)), scenario.robot
        Q = robot.sample(np.random.default_rng(1), args.configs)
        checkers = {"fcl": FCLChecker(ws, robot), "compiled": CompiledChecker(ws, robot)}
        if robot.base == "point2d" and robot.dof == 2:
            checkers["point"] = PointRobotChecker(ws, robot)
        answers, first_call = {}, {}
        for key, checker in checkers.items():
            start = time.perf_counter()
            answers[key] = checker.are_valid(Q)
            first_call[key] = round(time.perf_counter() - start, 3)
        rates = in_turns(timed_calls(checkers, Q, args.small), args.turns)
        line = {"scenario": name, "configs": len(Q), "turns": args.turns, "small": args.small}
        line |= {f"{key}_cfg_per_s": rate for key, rate in rates.items()}
        line["compiled_over_fcl"] = rates["compiled"] / rates["fcl"]
        line["batched_over_small"] = rates["compiled"] / rates["compiled_small"]
        line["load"] = os.getloadavg()[0]
        line["agree"] = all(np.array_equal(answers["fcl"], a) for a in answers.values())
        line["first_call_s"] = first_call
        print(json.dumps(line), flush=True)


if __name__ == "__main__":
    main()
