"""The GPU measurements of docs/gpu.md (issue 50), in one short run that installs nothing.

    PYTHONPATH=. PYTHONUNBUFFERED=1 python docs/scripts/gpu_measure.py [--device cuda] [--out DIR] [--quick]

From the repository's root, on a machine with a CUDA device and the toolkit's dependencies
(torch with CUDA, numpy, numba, scipy, trimesh; python-fcl where present). On an H200 it is
sized to finish in under eight minutes (an estimate until a GPU has run it: each section prints
its seconds). It prints one JSON line per measurement as it goes, and with ``--out`` writes
``DIR/gpu_measure.jsonl`` (those lines), ``DIR/gpu_measure.md`` (the same as tables),
``DIR/gpu_record.json`` (what chapter 04 reads: copy it to ``toolkit/teaching/gpu_record.json``)
and the reproduction's folder ``DIR/table3_3dc7``:

1. ``environment``: the device, its CUDA version, torch, the CPU count, the load;
2. ``agreement``: per scenario, the exact check in torch on the device against the compiled
   kernel on 1M uniform configurations and on pairs within 1e-6 of contact, and against
   python-fcl on 20,000 of them (where python-fcl is installed);
3. ``throughput``: per scenario, ``toolkit bench --device`` (``bench.throughput``): the CPU
   checkers at their defaults, the learned (``strong``, untrained: speed does not depend on the
   weights) and the exact check on the device at 1M, numpy in/out and resident; and both
   resident at 4M;
4. ``latency``: a call of 256 configurations already on the device, learned direct,
   learned replayed from a CUDA graph, exact (milliseconds a call, the median of 200 calls);
5. ``crossover``: ``toolkit bench --crossover --device`` (``on_device.one_device``): in 3DC-7 the
   batch (256 ... 4M), the obstacles and the links; in 3DO the batch; the CPU pair beside;
6. ``table3``: ``toolkit reproduce --scenario 3dc7 --preset strong --quick --planner batched
   --device D``: Table 3 with and without prediction, the batched PRM both ways, the network
   trained on the device and deciding samples there, every returned path verified exactly.

``--quick`` shrinks every size (a test of the script on any machine, with ``--device cpu``: a
test runs it so in CI).
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
from toolkit.experiments import bench, on_device, reproduce
from toolkit.experiments.config import RunConfig
from toolkit.geometry.collision import CompiledChecker, FCLChecker
from toolkit.geometry.torch_kernels import TorchChecker
from toolkit.learning import presets
from toolkit.learning.learned import LearnedChecker
from toolkit.planning.sampling import PAPER_SAMPLERS

SCENARIOS = ("2ds", "3do", "3dc7", "3dc9")
COMMAND = "PYTHONPATH=. PYTHONUNBUFFERED=1 python docs/scripts/gpu_measure.py --device cuda --out $OUT"


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
    on_device_, compiled = TorchChecker(ws, robot, device), CompiledChecker(ws, robot)
    uniform, near = robot.sample(rng, n_uniform), near_contact(compiled, rng, n_near)
    row = {"scenario": name, "uniform": n_uniform, "near_contact": len(near)}
    for label, Q in (("uniform", uniform), ("near_contact", near)):
        row[f"{label}_disagree_compiled"] = int((on_device_.are_valid(Q) != compiled.are_valid(Q)).sum())
    try:
        fcl = FCLChecker(ws, robot)
    except ImportError:
        row["fcl"] = "python-fcl not installed"
        return row
    Q = np.concatenate([uniform[:n_fcl], near[: n_fcl // 2], near[-n_fcl // 2 :]])
    row["fcl_checked"], row["disagree_fcl"] = len(Q), int((on_device_.are_valid(Q) != fcl.are_valid(Q)).sum())
    return row


def throughput(name: str, device: str, big: int, repeats: int, quick: bool) -> dict:
    scenario = scenarios.get(name)
    models = bench.untrained_models(scenario, presets.get("strong"))
    batch = 2048 if quick else None  # None: 1M on a GPU
    row = {"scenario": name, "preset": "strong", **bench.throughput(scenario, models, batch=batch, device=device)}
    row["device_batch"] = batch or (1 << 20 if torch.device(device).type == "cuda" else 10_000)
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


def table_3(device: str, out: Path, quick: bool) -> dict:
    """Table 3 in 3DC-7, quick, the batched PRM with and without prediction (``toolkit reproduce --planner batched
    --device``); ``--quick``: the uniform sampler only, and two small steps of the CAE (Table 1's, which a CPU
    trains slowest)."""
    config = RunConfig.create(
        "3dc7",
        "strong",
        quick=True,
        device=device,
        planner="batched",
        workers=1,
        progress=False,
        samplers=("BS",) if quick else PAPER_SAMPLERS,
        **({"cae_max_steps": 2, "cae_batch": 8} if quick else {}),
    )
    results = reproduce.reproduce(config, out)
    keys = ("sampling_s_median", "total_s_median", "success_rate", "path_valid_rate", "n_queries", "planner")
    planning = {
        sampler: {mode: {k: row[mode][k] for k in keys} for mode in ("without", "with")}
        for sampler, row in results["planning"].items()
    }
    return {"scenario": "3dc7", "preset": "strong", "planner": "batched", "device": device, "planning": planning}


def record(rows: dict[str, list[dict]]) -> dict:
    """What chapter 04 reads (``toolkit.teaching.gpu_record``): the environment, per scenario the throughput and
    the latency of a call of 256, 3DC-7's batch sweep on one device, and Table 3 with the batched PRM."""
    env = rows["environment"][0]
    batch = next(r for r in rows["crossover"] if r["scenario"] == "3dc7")["variables"]["batch"]
    return {
        "measured": env["device_type"] == "cuda" and not env["quick"],
        "environment": {k: env[k] for k in ("device", "cuda", "torch", "cpus", "load", "quick")},
        "command": COMMAND,
        "throughput": {
            r["scenario"]: {k: r[k] for k in r if k.endswith("cfg_per_s") or k == "device_batch"}
            for r in rows["throughput"]
        },
        "latency_ms": {r["scenario"]: {k: v for k, v in r.items() if k.endswith("_ms")} for r in rows["latency"]},
        "crossover_3dc7": {k: batch[k] for k in batch if k in ("values", "fastest") or k.endswith("_us")},
        "table3_3dc7": rows["table3"][0]["planning"],
    }


def markdown(rows: dict[str, list[dict]]) -> str:
    """The run's measurements as tables: one per kind, one row per line it printed (crossovers as their own)."""
    lines = ["# GPU measurements (docs/scripts/gpu_measure.py)", ""]
    for kind, found in rows.items():
        if kind == "crossover":
            lines += [on_device.markdown(r) for r in found]
            continue
        flat = [{k: v for k, v in r.items() if not isinstance(v, dict)} for r in found]
        keys = list(dict.fromkeys(k for r in flat for k in r))
        lines += [f"## {kind}", "", "| " + " | ".join(keys) + " |", "|" + " --- |" * len(keys)]
        lines += ["| " + " | ".join(_cell(r.get(k)) for k in keys) + " |" for r in flat]
        if kind == "table3":
            lines += ["", "| sampler | mode | " + " | ".join(_TABLE3_KEYS) + " |", "|" + " --- |" * 7]
            for sampler, modes in found[0]["planning"].items():
                for mode, summary in modes.items():
                    lines.append(
                        f"| {sampler} | {mode} | " + " | ".join(_cell(summary[k]) for k in _TABLE3_KEYS) + " |"
                    )
        lines.append("")
    return "\n".join(lines)


_TABLE3_KEYS = ("sampling_s_median", "total_s_median", "success_rate", "path_valid_rate", "n_queries")


def _cell(value) -> str:
    if isinstance(value, float):
        return f"{value:.4g}"
    return "" if value is None else str(value)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--device", default="cuda")
    parser.add_argument("--out", type=Path)
    parser.add_argument("--quick", action="store_true", help="small sizes: a test of the script")
    args = parser.parse_args()
    device = bench.usable_device(args.device)
    assert device is not None
    q, began = args.quick, time.perf_counter()
    rows: dict[str, list[dict]] = {}
    lines = []

    def report(kind: str, row: dict) -> None:
        line = json.dumps({"measure": kind, **row, "elapsed_s": round(time.perf_counter() - began, 1)})
        print(line, flush=True)
        lines.append(line)
        rows.setdefault(kind, []).append(row)

    cuda = torch.device(device).type == "cuda"
    props = torch.cuda.get_device_properties(device) if cuda else None
    report(
        "environment",
        {
            "device": props.name if props else platform.processor() or "cpu",
            "device_type": torch.device(device).type,
            "cuda": torch.version.cuda,
            "torch": torch.__version__,
            "cpus": os.cpu_count(),
            "load": os.getloadavg(),
            "quick": q,
        },
    )
    for name in SCENARIOS:
        report("agreement", agreement(name, device, 500 if q else 1 << 20, 50 if q else 20_000, 200 if q else 20_000))
    for name in ("3dc7",) if q else SCENARIOS:
        report("throughput", throughput(name, device, 1 << 22, 2 if q else 5, q))
    for name in ("3dc7", "3do"):
        report("latency", latency(name, device, 5 if q else 200))
    preset = presets.get("strong")
    for name, variables in (("3dc7", ("batch",) if q else on_device.VARIABLES), ("3do", ("batch",))):
        if q and name != "3dc7":
            continue
        found = on_device.one_device(scenarios.get(name), preset, device=device, variables=variables, quick=q)
        report("crossover", found)
    out = args.out or Path("runs/gpu_measure")
    report("table3", table_3(device, out / "table3_3dc7", q))
    text = markdown(rows)
    print(text, flush=True)
    if args.out:
        args.out.mkdir(parents=True, exist_ok=True)
        (args.out / "gpu_measure.jsonl").write_text("\n".join(lines) + "\n")
        (args.out / "gpu_measure.md").write_text(text)
        (args.out / "gpu_record.json").write_text(json.dumps(record(rows), indent=1) + "\n")
    print(f"gpu_measure: {time.perf_counter() - began:.0f} s in all", flush=True)


if __name__ == "__main__":
    main()
