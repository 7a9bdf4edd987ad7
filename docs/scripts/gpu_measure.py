"""The GPU measurements of docs/gpu.md (issue 50), in one short run that installs nothing.

    PYTHONPATH=. python docs/scripts/gpu_measure.py [--device cuda] [--out DIR] [--quick]

From the repository's root, on a machine with a CUDA device and the toolkit's dependencies
(torch with CUDA, numpy, numba, scipy, trimesh; python-fcl where present). In an estimated five
minutes on an H200 it prints one JSON line per measurement, and writes them to
``DIR/gpu_measure.jsonl`` with ``--out``:

1. ``environment``: the device, its driver's CUDA version, torch, the CPU count, the load;
2. ``agreement``: per scenario, the exact check in torch on the device against the compiled
   kernel on 1M uniform configurations and on pairs within 1e-6 of contact, and against
   python-fcl on 20,000 of them (where python-fcl is installed);
3. ``throughput``: per scenario, ``toolkit bench --device`` (``bench.throughput``): the CPU
   checkers at their defaults, the learned (``strong``, untrained: speed does not depend on the
   weights) and the exact check on the device at 1M, numpy in/out and resident; and both
   resident at 4M;
4. ``latency``: a call of 256 configurations already on the device, learned direct,
   learned replayed from a CUDA graph, exact (milliseconds a call, the median of 200 calls);
5. ``crossover``: ``toolkit bench --crossover --device`` (``on_device.sweep``) in 3DC-7 and
   3DO, batches 256 ... 4M, the CPU pair beside.

``--quick`` shrinks every size (a test of the script on any machine, with ``--device cpu``).
"""

import argparse
import json
import os
import platform
import time
from pathlib import Path

import numpy as np
import torch

from toolkit import scenarios
from toolkit.experiments import bench, on_device
from toolkit.geometry.collision import CompiledChecker, FCLChecker
from toolkit.geometry.torch_kernels import TorchChecker
from toolkit.learning import presets
from toolkit.learning.learned import LearnedChecker

SCENARIOS = ("2ds", "3do", "3dc7", "3dc9")


def near_contact(checker, rng, n: int, tol: float = 1e-6) -> np.ndarray:
    """``(2M, dof)``: valid and invalid configurations less than ``tol`` apart, found by bisection from valid
    uniform ones towards invalid ones (as tests/test_compiled_checker.py's straddle_the_boundary)."""
    robot = checker.robot
    Q = robot.sample(rng, 4 * n)
    valid = checker.are_valid(Q)
    start = Q[valid][:n]
    end = Q[~valid][rng.integers((~valid).sum(), size=len(start))]
    step = robot.difference(start, end)  # (M, dof)
    lo, hi = np.zeros(len(start)), np.ones(len(start))  # valid at lo, invalid at hi
    for _ in range(int(np.ceil(np.log2(np.linalg.norm(step, axis=1).max() / tol)))):
        mid = (lo + hi) / 2
        ok = checker.are_valid(robot.wrap(start + mid[:, None] * step))
        lo, hi = np.where(ok, mid, lo), np.where(ok, hi, mid)
    return np.concatenate([robot.wrap(start + lo[:, None] * step), robot.wrap(start + hi[:, None] * step)])


def agreement(name: str, device: str, n_uniform: int, n_near: int, n_fcl: int) -> dict:
    scenario = scenarios.get(name)
    robot, rng = scenario.robot, np.random.default_rng(50)
    ws = scenario.make_workspace(rng)
    on_device, compiled = TorchChecker(ws, robot, device), CompiledChecker(ws, robot)
    uniform, near = robot.sample(rng, n_uniform), near_contact(compiled, rng, n_near)
    row = {"scenario": name, "uniform": n_uniform, "near_contact": len(near)}
    for label, Q in (("uniform", uniform), ("near_contact", near)):
        row[f"{label}_disagree_compiled"] = int((on_device.are_valid(Q) != compiled.are_valid(Q)).sum())
    try:
        fcl = FCLChecker(ws, robot)
    except ImportError:
        row["fcl"] = "python-fcl not installed"
        return row
    Q = np.concatenate([uniform[:n_fcl], near[: n_fcl // 2], near[-n_fcl // 2 :]])
    row["fcl_checked"], row["disagree_fcl"] = len(Q), int((on_device.are_valid(Q) != fcl.are_valid(Q)).sum())
    return row


def throughput(name: str, device: str, big: int, repeats: int, quick: bool) -> dict:
    scenario = scenarios.get(name)
    models = bench.untrained_models(scenario, presets.get("strong"))
    row = {"scenario": name, "preset": "strong", **bench.throughput(scenario, models, device=device, repeats=repeats)}
    if quick:  # the CPU checkers' default batches are the script's largest cost on a CPU
        row["note"] = "quick: nothing at the large batch"
        return row
    calls = bench.device_calls(scenario, models, big, device)
    rates = bench.in_turns({k: calls[k] for k in ("learned_resident", "exact_device_resident")}, repeats)
    row.update({f"{k}_cfg_per_s_at_{big}": v for k, v in rates.items()})
    return row


def latency(name: str, device: str, calls: int) -> dict:
    """Milliseconds per resident call of 256: the learned checker direct and replayed, the exact one."""
    scenario = scenarios.get(name)
    ws, models = scenario.workspaces("query", 1, 0)[0], bench.untrained_models(scenario, presets.get("strong"))
    Q = torch.as_tensor(scenario.robot.sample(np.random.default_rng(0), 256), dtype=torch.float32, device=device)
    row: dict = {"scenario": name, "batch": 256}
    checkers = {
        "learned_direct": LearnedChecker(ws, models, device=device),
        "exact_device": TorchChecker(ws, scenario.robot, device),
    }
    try:  # a failed capture is a finding, not the end of the run
        checkers["learned_graph"] = LearnedChecker(ws, models, device=device, graph_sizes=(256,))
    except RuntimeError as err:
        row["graph_error"] = str(err)[:300]
    wait = torch.cuda.synchronize if torch.device(device).type == "cuda" else (lambda: None)
    for key, checker in checkers.items():
        times = []
        for _ in range(calls + 10):  # 10 warm-up calls
            wait()
            start = time.perf_counter()
            checker.are_valid(Q).cpu()  # the answer read on the host, as a planner reads it
            times.append(time.perf_counter() - start)
        row[f"{key}_ms"] = 1e3 * float(np.median(times[10:]))
    if "learned_graph" in checkers:
        same = checkers["learned_graph"].are_valid(Q).cpu() == checkers["learned_direct"].are_valid(Q).cpu()
        row["graph_equals_direct"] = bool(same.all())
    return row


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--device", default="cuda")
    parser.add_argument("--out", type=Path)
    parser.add_argument("--quick", action="store_true", help="small sizes: a test of the script")
    args = parser.parse_args()
    bench.usable_device(args.device)
    q = args.quick
    lines = []

    def report(kind: str, row: dict) -> None:
        line = json.dumps({"measure": kind, **row})
        print(line, flush=True)
        lines.append(line)

    props = torch.cuda.get_device_properties(args.device) if torch.device(args.device).type == "cuda" else None
    report(
        "environment",
        {
            "device": props.name if props else platform.processor() or "cpu",
            "cuda": torch.version.cuda,
            "torch": torch.__version__,
            "cpus": os.cpu_count(),
            "load": os.getloadavg(),
            "quick": q,
        },
    )
    for name in SCENARIOS:
        report(
            "agreement",
            agreement(name, args.device, 2_000 if q else 1 << 20, 100 if q else 20_000, 500 if q else 20_000),
        )
    for name in SCENARIOS if not q else ("3dc7",):
        report("throughput", throughput(name, args.device, 1 << 22, 2 if q else 5, q))
    for name in ("3dc7", "3do"):
        report("latency", latency(name, args.device, 20 if q else 200))
    preset = presets.get("strong")
    for name in ("3dc7",) if q else ("3dc7", "3do"):
        batches = on_device.QUICK_BATCHES if q else on_device.BATCHES
        found = on_device.sweep(scenarios.get(name), preset, device=args.device, batches=batches, repeats=2 if q else 5)
        report("crossover", found)
        print(on_device.markdown(found), flush=True)
    if args.out:
        args.out.mkdir(parents=True, exist_ok=True)
        (args.out / "gpu_measure.jsonl").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
