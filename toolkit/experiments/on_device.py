"""The crossover on one device: the network against the exact check, both on the GPU (or both on the CPU).

A network on a GPU is usually raced against an exact checker on a CPU, and wins on the
GPU's size alone. Here the exact check runs on the same device too
(:mod:`toolkit.geometry.torch_kernels`, the compiled kernel's algorithm in torch), and over
batch sizes from a sampler's 256 configurations a call to 4M each checker is timed twice:
with the batch already on the device (resident: what a planner that samples there would
see) and with numpy in and out (what today's planners see), the CPU pair (the compiled
exact checker, the learned one) beside them, all in turns (:func:`toolkit.experiments.bench.in_turns`)
on one thread. The learned checker's calls up to :data:`GRAPHED_UP_TO` are replayed as CUDA
graphs on a GPU. The exact answers on the device are held to the compiled ones at every batch.

``toolkit bench --crossover --device cuda [--quick] [--out DIR]``; ``docs/gpu.md`` reads the results.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from toolkit.experiments import bench
from toolkit.experiments.queries import one_thread
from toolkit.geometry.collision import exact_checker
from toolkit.learning.presets import Preset
from toolkit.scenarios import Scenario

BATCHES = (256, 4096, 65_536, 1 << 20, 1 << 22)  # a sampler's call to 4M
QUICK_BATCHES = (256, 2048)
GRAPHED_UP_TO = 4096  # the learned checker's calls up to this size are replayed (CUDA graphs)
COLUMNS = {  # sweep's columns -> what they time
    "exact_cpu": "exact, compiled, CPU (1 thread), numpy",
    "learned_cpu": "learned, CPU (1 thread), numpy",
    "exact_device_io": "exact in torch on the device, numpy in/out",
    "exact_device": "exact in torch on the device, resident",
    "learned_device_io": "learned on the device, numpy in/out",
    "learned_device": "learned on the device, resident",
}


def sweep(
    scenario: Scenario,
    preset: Preset,
    *,
    device: str,
    batches: tuple[int, ...] = BATCHES,
    repeats: int = 5,
    seed: int = 0,
) -> dict:
    """Microseconds per configuration of the checkers of :data:`COLUMNS` at each of ``batches``, timed in turns
    on one thread, in the scenario's first query workspace (untrained networks of ``preset``: the weights do not
    matter); a round makes enough calls for 65,536 configurations. ``disagreements``: configurations the exact
    check on the device answers differently from the compiled one (the float32 batch, widened, for both);
    ``fastest``: the cheapest column per batch; ``conclusion``: in words."""
    models = bench.untrained_models(scenario, preset, seed)
    rows = []
    with one_thread():
        for batch in batches:
            calls = max(1, (1 << 16) // batch)
            graphs = (batch,) if batch <= GRAPHED_UP_TO else ()
            timed = bench.device_calls(scenario, models, batch, device, seed, graph_sizes=graphs, calls=calls)
            for name, (fn, n) in (
                ("exact_cpu", bench.exact_call(scenario, batch, seed)),
                ("learned_cpu", bench.learned_call(scenario, models, batch, seed)),
            ):
                timed[name] = _repeated(fn, calls), calls * n
            rates = bench.in_turns(timed, repeats)
            rows.append({"batch": batch, **_device_row(rates), **_device_agreement(scenario, batch, device, seed)})
    columns = {key: [row[key] for row in rows] for key in rows[0]}
    results = {"scenario": scenario.name, "preset": preset.name, "device": str(device), "seed": seed, **columns}
    results["conclusion"] = conclusion(results)
    return results


def _repeated(fn: Callable[[], object], calls: int) -> Callable[[], object]:
    """``fn`` called ``calls`` times in one call."""
    return lambda: [fn() for _ in range(calls)]


def _device_row(rates: dict[str, float]) -> dict:
    """:func:`sweep`'s columns from :func:`bench.device_calls`' rates and the CPU pair's."""
    names = {
        "learned": "learned_device_io",
        "learned_resident": "learned_device",
        "exact_device": "exact_device_io",
        "exact_device_resident": "exact_device",
    }
    us = {f"{names.get(name, name)}_us": 1e6 / rate for name, rate in rates.items()}
    return {**us, "fastest": min(COLUMNS, key=lambda name: us[f"{name}_us"])}


def _device_agreement(scenario: Scenario, batch: int, device: str, seed: int) -> dict:
    """The exact check on the device against the compiled one, on the batch :func:`bench.device_calls` times."""
    import torch

    from toolkit.geometry.torch_kernels import TorchChecker

    ws = scenario.workspaces("query", 1, seed)[0]
    Q = scenario.robot.sample(np.random.default_rng(seed), batch).astype(np.float32).astype(np.float64)
    on_device = TorchChecker(ws, scenario.robot, device).are_valid(torch.as_tensor(Q, device=device)).cpu().numpy()
    return {"disagreements": int((on_device != exact_checker(ws, scenario.robot).are_valid(Q)).sum())}


def conclusion(results: dict) -> list[str]:
    """Per batch, the cheapest checker and, on the device, the network's cost over the exact check's (resident)."""
    lines = []
    for i, batch in enumerate(results["batch"]):
        ratio = results["learned_device_us"][i] / results["exact_device_us"][i]
        cpu = results["learned_cpu_us"][i] / results["exact_cpu_us"][i]
        lines.append(
            f"{batch:,} a call on {results['device']}: cheapest is {COLUMNS[results['fastest'][i]]}; "
            f"there the network costs {ratio:.2f}x the exact check (both resident), on the CPU {cpu:.2f}x."
        )
    return lines


def markdown(results: dict) -> str:
    """:func:`sweep`'s measurements as a markdown table (microseconds a configuration), then its conclusion."""
    names = list(COLUMNS)
    lines = [
        f"# One device: {results['scenario']}, preset `{results['preset']}`, device `{results['device']}`",
        "",
        "| batch | " + " | ".join(COLUMNS[n] for n in names) + " | disagree |",
        "| --- |" + " --- |" * (len(names) + 1),
    ]
    for i, batch in enumerate(results["batch"]):
        cells = " | ".join(f"{results[f'{n}_us'][i]:.3g}" for n in names)
        lines.append(f"| {batch:,} | {cells} | {results['disagreements'][i]} |")
    return "\n".join(lines + ["", *results["conclusion"], ""])
