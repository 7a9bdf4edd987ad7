"""The exact mesh checkers timed in turns on the tutorials' room, subdivided: compiled against the reference.

    python docs/scripts/mesh_checker_speed.py [SCENARIO ...] [--subdivisions S] [--configs N] [--turns T]

The demo room (``toolkit.geometry.meshes.room``, 288 triangles, as ``tutorials/data/room.stl``)
subdivided ``S`` (3) times (18,432 triangles), each scenario's robot (default 3dc7 3dc9 3do), ``N``
(20,000) uniform configurations, then ``T`` (15: a compiled turn lasts milliseconds, and a busy
machine slows some of them) turns, each timing ``CompiledMeshChecker`` (the default, ``exact_checker``),
``MeshChecker`` (python-fcl's BVH and numpy winding numbers, the
reference) and the compiled box checker on the same furniture given as boxes, on the same batch.
Prints one JSON line per scenario: median configurations per second of each, the speed-up over the
reference, disagreements (must be 0; the box checker's too), the share valid, and the compiled mesh
checker's set-up seconds.
"""

import argparse
import json
import time

import numpy as np

from toolkit import scenarios
from toolkit.experiments import bench
from toolkit.geometry import meshes
from toolkit.geometry.collision import CompiledChecker, CompiledMeshChecker, MeshChecker
from toolkit.geometry.workspace import Workspace, from_mesh


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenarios", nargs="*", default=["3dc7", "3dc9", "3do"])
    parser.add_argument("--subdivisions", type=int, default=3)
    parser.add_argument("--configs", type=int, default=20_000)
    parser.add_argument("--turns", type=int, default=15)
    args = parser.parse_args()
    mesh = meshes.room()
    for _ in range(args.subdivisions):
        mesh = mesh.subdivide()
    ws = from_mesh(mesh, lower=np.zeros(3), upper=np.full(3, 11.0))
    furniture = np.concatenate([meshes.furniture_boxes(*piece) for piece in meshes.DEMO_LAYOUT])  # (K, 2, 3)
    boxes = Workspace(ws.lower, ws.upper, furniture)
    for name in args.scenarios:
        robot = scenarios.get(name).robot
        Q = robot.sample(np.random.default_rng(0), args.configs)
        began = time.perf_counter()
        compiled = CompiledMeshChecker(ws, robot)
        setup = time.perf_counter() - began
        reference, box = MeshChecker(ws, robot), CompiledChecker(boxes, robot)
        fast, truth = compiled.are_valid(Q), reference.are_valid(Q)  # first calls: numba loads, caches warm
        rates = bench.in_turns(
            {
                "compiled": (lambda c=compiled, Q=Q: c.are_valid(Q), len(Q)),
                "reference": (lambda c=reference, Q=Q: c.are_valid(Q), len(Q)),
                "box": (lambda c=box, Q=Q: c.are_valid(Q), len(Q)),
            },
            args.turns,
        )
        print(
            json.dumps(
                {
                    "scenario": name,
                    "triangles": len(mesh.faces),
                    "compiled_cfg_per_s": round(rates["compiled"]),
                    "reference_cfg_per_s": round(rates["reference"]),
                    "box_cfg_per_s": round(rates["box"]),
                    "speed_up": round(rates["compiled"] / rates["reference"], 1),
                    "disagree": int((fast != truth).sum()),
                    "box_disagree": int((box.are_valid(Q) != truth).sum()),
                    "valid": round(float(truth.mean()), 3),
                    "setup_s": round(setup, 3),
                }
            )
        )


if __name__ == "__main__":
    main()
