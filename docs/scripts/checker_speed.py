"""Throughput of the exact checkers, timed in turns in one run: the python-fcl reference and the compiled default.

    python docs/scripts/checker_speed.py [SCENARIO ...] [--configs N] [--turns T]

For each scenario (default 2ds 3dc7 3dc9 3do): the seed-0 workspace, ``N`` (20,000)
uniform configurations, then ``T`` (5) turns, each timing ``FCLChecker``, ``CompiledChecker``
and, for the 2D point robot, ``PointRobotChecker`` on the same batch. Prints one JSON line
per scenario: median configurations per second of each, the compiled / FCL ratio, whether
their answers agree, and each one's first call in seconds, paid before the turns (the
compiled checker's loads numba's code, or compiles it: with ``NUMBA_CACHE_DIR`` set to an
empty folder it shows a cold start).
"""

import argparse
import json
import time

import numpy as np

from toolkit import scenarios
from toolkit.geometry.collision import CompiledChecker, FCLChecker, PointRobotChecker


def rate(checker, Q) -> float:
    start = time.perf_counter()
    checker.are_valid(Q)
    return len(Q) / (time.perf_counter() - start)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenarios", nargs="*", default=["2ds", "3dc7", "3dc9", "3do"])
    parser.add_argument("--configs", type=int, default=20_000)
    parser.add_argument("--turns", type=int, default=5)
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
        rates: dict[str, list[float]] = {key: [] for key in checkers}
        for _ in range(args.turns):
            for key, checker in checkers.items():
                rates[key].append(rate(checker, Q))
        median = {f"{key}_cfg_per_s": float(np.median(r)) for key, r in rates.items()}
        line = {"scenario": name, "configs": len(Q), "turns": args.turns, **median}
        line["compiled_over_fcl"] = median["compiled_cfg_per_s"] / median["fcl_cfg_per_s"]
        line["agree"] = all(np.array_equal(answers["fcl"], a) for a in answers.values())
        line["first_call_s"] = first_call
        print(json.dumps(line), flush=True)


if __name__ == "__main__":
    main()
