"""The crossover on one device: the network against the exact check, both on the GPU (or both on the CPU).

A network on a GPU is usually raced against an exact checker on a CPU, and wins on the
GPU's size alone. Here the exact check runs on the same device too
(:mod:`toolkit.geometry.torch_kernels`, the compiled kernel's algorithm in torch), and each
checker is timed twice: with the batch already on the device (resident: what a planner that
samples there would see) and with numpy in and out (what today's planners see), the CPU pair
(the compiled exact checker, the learned one) beside them, all in turns
(:func:`toolkit.experiments.bench.in_turns`) on one thread. Three things are varied, one at a
time (:data:`VARIABLES`): the batch, from a sampler's 256 configurations a call to 4M; the
obstacles and the robot's links, as :mod:`toolkit.experiments.crossover` varies them on the CPU
(:func:`~toolkit.experiments.crossover.settings`), at :data:`VARIABLE_BATCH` a call. Meshes are
not varied here: the exact check in torch is the box-world check, and a mesh workspace stays on
the CPU (``docs/gpu.md`` says why). The learned checker's calls up to :data:`GRAPHED_UP_TO` are
replayed as CUDA graphs on a GPU. The exact answers on the device are held to the compiled ones
at every point.

``toolkit bench --crossover --device cuda [--variables batch,obstacles,links] [--quick] [--out DIR]``;
``docs/gpu.md`` reads the results.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Iterator

import numpy as np

from toolkit.experiments import bench, crossover
from toolkit.experiments.crossover import CrossoverSizes, Setting
from toolkit.experiments.queries import one_thread
from toolkit.geometry.collision import exact_checker
from toolkit.learning.presets import Preset
from toolkit.learning.training import TrainedModels
from toolkit.scenarios import Scenario

VARIABLES = ("batch", "obstacles", "links")  # what is varied on one device (no meshes: see the docstring)
BATCHES = (256, 4096, 65_536, 1 << 20, 1 << 22)  # a sampler's call to 4M
QUICK_BATCHES = (256, 2048)
VARIABLE_BATCH = 1 << 16  # configurations a call where the obstacles or the links vary (quick: CrossoverSizes')
CALLS_FOR = 1 << 16  # a timed round makes enough calls for this many configurations (quick: QUICK_CALLS_FOR)
QUICK_CALLS_FOR = 1 << 12
GRAPHED_UP_TO = 4096  # the learned checker's calls up to this size are replayed (CUDA graphs)
COLUMNS = {  # sweep's columns -> what they time
    "exact_cpu": "exact, compiled, CPU (1 thread), numpy",
    "learned_cpu": "learned, CPU (1 thread), numpy",
    "exact_device_io": "exact in torch on the device, numpy in/out",
    "exact_device": "exact in torch on the device, resident",
    "learned_device_io": "learned on the device, numpy in/out",
    "learned_device": "learned on the device, resident",
}


def variables_of(scenario: Scenario) -> tuple[str, ...]:
    """The variables that apply: in 2D the batch and the obstacles (a lone point robot has no links to add)."""
    return VARIABLES if scenario.robot.dim == 3 else ("batch", "obstacles")


def points(scenario: Scenario, variable: str, *, quick: bool = False, seed: int = 0) -> Iterator[Setting]:
    """The settings ``variable`` takes: the batch over :data:`BATCHES` (quick: :data:`QUICK_BATCHES`) in the
    scenario's first query workspace; the obstacles and links as :func:`crossover.settings` has them, at
    :data:`VARIABLE_BATCH` a call (quick: :meth:`CrossoverSizes.quick`, two small values and short calls); a timed
    round of a point makes enough calls for :data:`CALLS_FOR` configurations (quick: :data:`QUICK_CALLS_FOR`)."""
    calls_for = QUICK_CALLS_FOR if quick else CALLS_FOR
    if variable == "batch":
        ws = scenario.workspaces("query", 1, seed)[0]
        for batch in QUICK_BATCHES if quick else BATCHES:
            yield Setting(batch, ws, scenario, batch, calls=max(1, calls_for // batch))
        return
    if variable not in VARIABLES:
        raise ValueError(f"unknown variable {variable!r} on one device; choose from {', '.join(VARIABLES)}")
    sizes = CrossoverSizes.quick() if quick else dataclasses.replace(CrossoverSizes(), batch=VARIABLE_BATCH)
    for setting in crossover.settings(scenario, variable, sizes, seed):
        yield dataclasses.replace(setting, calls=max(1, calls_for // setting.batch))


def sweep(
    scenario: Scenario,
    preset: Preset,
    *,
    device: str,
    variable: str = "batch",
    quick: bool = False,
    repeats: int = 5,
    seed: int = 0,
) -> dict:
    """Microseconds per configuration of the checkers of :data:`COLUMNS` at each value of ``variable``
    (:func:`points`), timed in turns on one thread (untrained networks of ``preset``: the weights do not matter):
    ``{"variable", "label", "values", "batch", "<column>_us", "fastest", "disagreements"}``, a list per key but
    the first two. ``disagreements``: configurations the exact check on the device answers differently from the
    compiled one (the float32 batch, widened, for both); ``fastest``: the cheapest column per value."""
    models: dict[str, TrainedModels] = {}  # by scenario name: the chains need networks of their own DoF
    rows = []
    with one_thread():
        for setting in points(scenario, variable, quick=quick, seed=seed):
            robot_scenario, batch, calls = setting.scenario, setting.batch, setting.calls
            if robot_scenario.name not in models:
                models[robot_scenario.name] = bench.untrained_models(robot_scenario, preset, seed)
            model, ws = models[robot_scenario.name], setting.workspace
            graphs = (batch,) if batch <= GRAPHED_UP_TO else ()
            timed = bench.device_calls(
                robot_scenario, model, batch, device, seed, graph_sizes=graphs, calls=calls, workspace=ws
            )
            for name, (fn, n) in (
                ("exact_cpu", bench._exact_call(robot_scenario, batch, seed, workspace=ws)),
                ("learned_cpu", bench._learned_call(robot_scenario, model, batch, seed, workspace=ws)),
            ):
                timed[name] = _repeated(fn, calls), calls * n
            rates = bench.in_turns(timed, repeats)
            agreement = _device_agreement(setting, device, seed)
            rows.append({"value": setting.value, "batch": batch, **_device_row(rates), **agreement})
    columns = {key: [row[key] for row in rows] for key in rows[0]}
    label = crossover.VARIABLES[variable]
    return {"variable": variable, "label": label, "values": columns.pop("value"), **columns}


def one_device(
    scenario: Scenario,
    preset: Preset,
    *,
    device: str,
    variables: tuple[str, ...] = (),
    quick: bool = False,
    repeats: int | None = None,
    seed: int = 0,
) -> dict:
    """Every variable that applies (or those named) swept on ``device``: ``{"scenario", "preset", "device",
    "quick", "seed", "variables": {name: sweep}, "conclusion": [lines]}``; ``repeats``: timed rounds (default 5,
    quick 2)."""
    applicable = variables_of(scenario)
    if unknown := sorted(set(variables) - set(applicable)):
        raise ValueError(
            f"variable(s) {unknown} do not apply to {scenario.name} on one device; choose from {', '.join(applicable)}"
            + (" (meshes stay on the CPU: docs/gpu.md)" if "triangles" in unknown else "")
        )
    rounds = repeats or (2 if quick else 5)
    sweeps = {
        v: sweep(scenario, preset, device=device, variable=v, quick=quick, repeats=rounds, seed=seed)
        for v in variables or applicable
    }
    results = {
        "scenario": scenario.name,
        "preset": preset.name,
        "device": str(device),
        "quick": quick,
        "seed": seed,
        "variables": sweeps,
    }
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


def _device_agreement(setting: Setting, device: str, seed: int) -> dict:
    """The exact check on the device against the compiled one, on the batch :func:`bench.device_calls` times."""
    import torch

    from toolkit.geometry.torch_kernels import TorchChecker

    robot, ws = setting.scenario.robot, setting.workspace
    Q = robot.sample(np.random.default_rng(seed), setting.batch).astype(np.float32).astype(np.float64)
    on_device = TorchChecker(ws, robot, device).are_valid(torch.as_tensor(Q, device=device)).cpu().numpy()
    return {"disagreements": int((on_device != exact_checker(ws, robot).are_valid(Q)).sum())}


def conclusion(results: dict) -> list[str]:
    """Per variable and value, the cheapest checker and, on the device, the network's cost over the exact check's
    (both resident), and the same on the CPU."""
    lines = []
    for found in results["variables"].values():
        for i, value in enumerate(found["values"]):
            ratio = found["learned_device_us"][i] / found["exact_device_us"][i]
            cpu = found["learned_cpu_us"][i] / found["exact_cpu_us"][i]
            where = f"{value:,} a call" if found["variable"] == "batch" else f"{found['label']} {value:,}"
            lines.append(
                f"{where} on {results['device']}: cheapest is {COLUMNS[found['fastest'][i]]}; "
                f"there the network costs {ratio:.2f}x the exact check (both resident), on the CPU {cpu:.2f}x."
            )
    return lines


def markdown(results: dict) -> str:
    """:func:`one_device`'s measurements as markdown tables (microseconds a configuration), then its conclusion."""
    names = list(COLUMNS)
    lines = [f"# One device: {results['scenario']}, preset `{results['preset']}`, device `{results['device']}`"]
    for found in results["variables"].values():
        lines += [
            "",
            f"| {found['label']} | batch | " + " | ".join(COLUMNS[n] for n in names) + " | disagree |",
            "| --- | --- |" + " --- |" * (len(names) + 1),
        ]
        for i, value in enumerate(found["values"]):
            cells = " | ".join(f"{found[f'{n}_us'][i]:.3g}" for n in names)
            lines.append(f"| {value:,} | {found['batch'][i]:,} | {cells} | {found['disagreements'][i]} |")
    return "\n".join(lines + ["", *results["conclusion"], ""])
