"""Benchmarks: what prediction is worth in time (§V, Table 3), measured where it is won or lost.

The paper's framework pays when the network answers "is this sample valid?" faster
than the exact checker does (§III-B, "Sample's Validity"), and when those answers
save planning time. So three measurements, one function each:

- :func:`throughput` — configurations per second of the default exact checker (compiled for box
  worlds), of the python-fcl reference and of the learned checker, and what a configuration costs the
  exact checker in the small calls a planner makes (:mod:`toolkit.experiments.small_calls`);
- :func:`edge_checks` — the exact local planner's edge checks, every point against
  clearance certificates (``local_planner.check_edges`` / ``certify_edges``);
- :func:`planning_ratios` — PRM with and without prediction, per sampler, on the paper's
  queries: the time ratios of Table 3, one planner (named; default the lazy PRM) with the default exact
  checker, the two runs differing in the checker that decides samples only.

Figures are medians over repeats, and a ratio's two figures come from one run, timed
in turns (:func:`in_turns`), since a shared machine's speed changes while it runs.
``toolkit bench --scenario S --json`` prints the throughput and the edge checks; with
``--checkpoint DIR`` also the planning ratios. ``toolkit bench --vs-ompl`` races our
planners against OMPL's (:mod:`toolkit.experiments.versus_ompl`), and ``toolkit bench
--crossover`` asks where prediction pays (:mod:`toolkit.experiments.crossover`). Results:
``docs/benchmarks.md``.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager

import numpy as np
import torch

from toolkit.experiments import queries
from toolkit.experiments.problems import make_planner, scenario_resolution
from toolkit.experiments.small_calls import small_call_cost
from toolkit.geometry.collision import CollisionChecker, FCLChecker, exact_checker
from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.torch_kernels import TorchChecker
from toolkit.geometry.workspace import Workspace
from toolkit.learning.learned import LearnedChecker
from toolkit.learning.presets import Preset
from toolkit.learning.training import TrainedModels
from toolkit.planning import prm, sampling
from toolkit.planning.local_planner import certify_edges, check_edges
from toolkit.planning.options import RoadmapParams
from toolkit.planning.planner import REFINEMENT
from toolkit.scenarios import Scenario

__all__ = [
    "cpu_clock",
    "device_calls",
    "edge_checks",
    "edge_checks_at",
    "exact_call",
    "exact_throughput",
    "in_turns",
    "learned_call",
    "learned_throughput",
    "median_rate",
    "median_seconds",
    "planning_ratios",
    "prediction_ratios",
    "short_valid_segments",
    "small_call_cost",
    "throughput",
    "untrained_models",
    "usable_device",
]


def median_seconds(fn, repeats: int = 5) -> float:
    """Seconds of ``fn()``, the median over ``repeats`` timed calls (one warm-up call first)."""
    fn()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return float(np.median(times))


def median_rate(fn, n_items: int, repeats: int = 5) -> float:
    """Items per second of ``fn()``, the median over ``repeats`` timed calls (one warm-up call first)."""
    return in_turns({"": (fn, n_items)}, repeats)[""]


_CLOCK: list[Callable[[], float] | None] = [None]  # what in_turns times with: None, the wall clock; cpu_clock


@contextmanager
def cpu_clock() -> Iterator[None]:
    """Within it, :func:`in_turns` (so :func:`throughput` and the crossover) times the calling thread's CPU time, not
    the wall clock: beside other work a call then costs what it computed, not what it waited for a core. For work
    on one thread (``queries.one_thread``: torch, numba and python-fcl then run in the caller's)."""
    _CLOCK.append(time.thread_time)
    try:
        yield
    finally:
        _CLOCK.pop()


def in_turns(calls: dict[str, tuple[Callable[[], object], int]], repeats: int = 5) -> dict[str, float]:
    """Items per second of each ``name: (fn, n_items)``, the medians of ``repeats`` rounds in which every
    ``fn`` is timed once, in turns (after one warm-up call each).

    Timed one after the other, two measurements see different machines whenever the
    load changes, and their ratio then measures the load as much as the calls; timed in
    turns, every round sees all calls under the same load (``docs/benchmarks.md``, "On a
    busy machine": how far apart two runs' ratios came out without turns).
    """
    for fn, _ in calls.values():
        fn()
    seconds: dict[str, list[float]] = {name: [] for name in calls}
    for _ in range(repeats):
        for name, (fn, _) in calls.items():
            clock = _CLOCK[-1] or time.perf_counter
            start = clock()
            fn()
            seconds[name].append(max(clock() - start, 1e-9))
    return {name: n / float(np.median(seconds[name])) for name, (_, n) in calls.items()}


def throughput(
    scenario: Scenario,
    models: TrainedModels,
    *,
    batch: int | None = None,
    seed: int = 0,
    repeats: int = 5,
    device: str | None = None,
) -> dict[str, float | str | dict[str, float]]:
    """Configurations per second of the default exact checker (``exact_cfg_per_s``: ``exact_checker``, compiled
    for box worlds), of the python-fcl reference (``fcl_cfg_per_s``) and of the learned checker of ``models``
    (``learned_cfg_per_s``; trained, or :func:`untrained_models`: the speed does not depend on the weights), the
    three timed in turns (:func:`in_turns`) at ``batch`` configurations a call (default: 20,000 exact, 10,000
    learned); ``ratio`` is learned / default exact, ``exact_over_fcl`` the compiled checker's speed-up.
    ``exact_small_call_cost``: per size in ``small_calls.SMALL_CALLS``, what a configuration costs the default exact
    checker in calls of that many over what it costs in the batch (:func:`small_call_cost`'s ``ratios``, timed
    apart, by the thread's CPU clock: what ``docs/scripts/small_call_cost.py`` prints).

    With ``device`` (``"cpu"``, ``"cuda"``): the learned checker runs there, and beside it the exact one in torch
    (:class:`~toolkit.geometry.torch_kernels.TorchChecker`), each timed twice: a numpy batch in and out
    (``learned_cfg_per_s``, ``exact_device_cfg_per_s``) and a batch already on the device, answered there
    (``learned_resident_cfg_per_s``, ``exact_device_resident_cfg_per_s``); their ``batch`` defaults to 1M on a
    GPU. ``device_ratio`` is learned / exact, both resident on the device."""
    calls = {
        "exact": exact_call(scenario, batch or 20_000, seed),
        "fcl": exact_call(scenario, batch or 20_000, seed, make=FCLChecker),
    }
    if device is None:
        calls["learned"] = learned_call(scenario, models, batch or 10_000, seed)
    else:
        on_gpu = torch.device(device).type != "cpu"
        calls.update(device_calls(scenario, models, batch or (1 << 20 if on_gpu else 10_000), device, seed))
    rates = in_turns(calls, repeats)
    result: dict[str, float | str | dict[str, float]] = {
        "exact_cfg_per_s": rates["exact"],
        "fcl_cfg_per_s": rates["fcl"],
        "learned_cfg_per_s": rates["learned"],
        "ratio": rates["learned"] / rates["exact"],
        "exact_over_fcl": rates["exact"] / rates["fcl"],
        "exact_small_call_cost": small_call_cost(scenario, batch=batch or 20_000, seed=seed)["ratios"],
    }
    if device is not None:
        result.update(
            device=str(device),
            learned_resident_cfg_per_s=rates["learned_resident"],
            exact_device_cfg_per_s=rates["exact_device"],
            exact_device_resident_cfg_per_s=rates["exact_device_resident"],
            device_ratio=rates["learned_resident"] / rates["exact_device_resident"],
        )
    return result


def usable_device(name: str | None) -> str | None:
    """``name`` checked as a torch device this machine has (None stays None); a clear error otherwise."""
    if name is None:
        return None
    try:
        device = torch.device(name)
    except (RuntimeError, ValueError):
        raise ValueError(f"--device {name!r} is not a torch device; use cpu or cuda") from None
    if device.type == "cuda" and not torch.cuda.is_available():
        raise ValueError(f"--device {name}: this machine has no CUDA device (torch {torch.__version__})")
    if device.type not in ("cpu", "cuda"):
        raise ValueError(f"--device {name}: only cpu and cuda are measured here")
    return name


def device_calls(
    scenario: Scenario,
    models: TrainedModels,
    batch: int,
    device: str,
    seed: int = 0,
    *,
    graph_sizes=(),
    calls=1,
    workspace: Workspace | None = None,
) -> dict[str, tuple[Callable[[], object], int]]:
    """The learned checker on ``device`` and the exact one in torch there, asked about ``batch`` uniform samples of
    ``workspace`` (default: a query workspace) ``calls`` times a round: ``learned`` and ``exact_device`` take and
    return numpy, ``learned_resident`` and ``exact_device_resident`` a float32 tensor on the device (each call waits
    for the device's answer, as a caller reading it would). Each numpy batch is in its checker's own type: float32
    for the network (a float64 one is converted on the way, a pass over the host's memory), float64 for the exact
    check. ``graph_sizes``: the learned checker's replayed sizes."""
    ws = scenario.workspaces("query", 1, seed)[0] if workspace is None else workspace
    Q = scenario.robot.sample(np.random.default_rng(seed), batch)  # (batch, dof)
    on_device = torch.as_tensor(Q, dtype=torch.float32, device=device)
    learned = LearnedChecker(ws, models, device=device, graph_sizes=graph_sizes)
    exact = TorchChecker(ws, scenario.robot, device=device)
    wait = torch.cuda.synchronize if torch.device(device).type == "cuda" else (lambda: None)

    def timed(checker, batch_):
        def call():
            for _ in range(calls):
                checker.are_valid(batch_)
            wait()

        return call, calls * batch

    return {
        "learned": timed(learned, Q.astype(np.float32)),
        "learned_resident": timed(learned, on_device),
        "exact_device": timed(exact, Q),
        "exact_device_resident": timed(exact, on_device),
    }


def exact_throughput(scenario: Scenario, *, batch: int = 20_000, seed: int = 0, repeats: int = 5) -> float:
    """Configurations per second of the default exact checker on uniform samples in one workspace."""
    return median_rate(*exact_call(scenario, batch, seed), repeats)


def learned_throughput(
    scenario: Scenario, models: TrainedModels, *, batch: int = 10_000, seed: int = 0, repeats: int = 5
) -> float:
    """Predictions per second of a :class:`~toolkit.learning.learned.LearnedChecker` of ``models`` at ``batch``, the
    workspace encoded once (:func:`untrained_models` time as well as trained ones: the weights do not matter)."""
    return median_rate(*learned_call(scenario, models, batch, seed), repeats)


def exact_call(
    scenario: Scenario,
    batch: int = 20_000,
    seed: int = 0,
    make: Callable[[Workspace, BoxRobot], CollisionChecker] = exact_checker,
    workspace: Workspace | None = None,
) -> tuple[Callable[[], object], int]:
    """An exact checker (``make(workspace, robot)``, default the fastest) asked about ``batch`` uniform samples in
    ``workspace`` (default: a query workspace) in one call; and ``batch``."""
    ws = scenario.workspaces("query", 1, seed)[0] if workspace is None else workspace
    checker = make(ws, scenario.robot)
    Q = scenario.robot.sample(np.random.default_rng(seed), batch)  # (batch, dof)
    return (lambda: checker.are_valid(Q)), batch


def learned_call(
    scenario: Scenario, models: TrainedModels, batch: int = 10_000, seed: int = 0, workspace: Workspace | None = None
) -> tuple[Callable[[], object], int]:
    """A learned checker of ``models`` asked about ``batch`` uniform samples in ``workspace`` (default: a query
    workspace), and ``batch``."""
    ws = scenario.workspaces("query", 1, seed)[0] if workspace is None else workspace
    checker = LearnedChecker(ws, models)
    Q = scenario.robot.sample(np.random.default_rng(seed), batch)
    return (lambda: checker.are_valid(Q)), batch


def untrained_models(scenario: Scenario, preset: Preset, seed: int = 0) -> TrainedModels:
    """Networks of ``preset``'s recipe with random weights (torch seeded by ``seed``), in eval mode: a learned
    checker's speed does not depend on its weights, so timing needs no training."""
    torch.manual_seed(seed)
    return TrainedModels(scenario, preset, preset.build_predictor(scenario).eval(), seed)


def edge_checks(scenario: Scenario, *, n_segments: int = 300, seed: int = 0, repeats: int = 5) -> dict[str, dict]:
    """``check_edges`` against ``certify_edges`` (same answers) at the planner's resolution and ``REFINEMENT`` times
    finer (where returned paths are checked).

    On ``n_segments`` segments between valid configurations of a query workspace, 3 %
    of the bounds apart (normal steps: some valid, some grazing, some through a block;
    a path's edges look like these). Per resolution: median seconds of each, and the
    configurations each checked (``certify_edges`` also bounds clearances).
    """
    ws = scenario.workspaces("query", 1, seed)[0]
    exact = exact_checker(ws, scenario.robot)
    Q0, Q1 = short_valid_segments(exact, n_segments, np.random.default_rng(seed))  # (E, dof) each
    resolution = scenario_resolution(scenario)
    spacing = resolution * RoadmapParams().certify_spacing
    return {
        name: edge_checks_at(exact, Q0, Q1, r, spacing=spacing, repeats=repeats)
        for name, r in (("resolution", resolution), ("finer", resolution / REFINEMENT))
    }


def edge_checks_at(
    exact: CollisionChecker, Q0: np.ndarray, Q1: np.ndarray, resolution: float, *, spacing: float, repeats: int = 5
) -> dict[str, float]:
    """:func:`edge_checks`' row at one ``resolution``: configurations checked (and clearances bounded) and median
    seconds of ``check_edges`` and of ``certify_edges`` (certificates ``spacing`` apart) on ``Q0 -> Q1``."""
    exact.reset_count()
    valid = check_edges(exact, Q0, Q1, resolution)  # (E,)
    row = {
        "resolution": resolution,
        "segments": len(Q0),
        "valid": float(valid.mean()),
        "check_edges_checked": exact.n_checked,
    }
    exact.reset_count()
    certify_edges(exact, Q0, Q1, resolution, spacing=spacing)
    row.update(
        certify_edges_checked=exact.n_checked,
        certify_edges_bounded=exact.n_bounded,
        check_edges_s=median_seconds(lambda: check_edges(exact, Q0, Q1, resolution), repeats),
        certify_edges_s=median_seconds(lambda: certify_edges(exact, Q0, Q1, resolution, spacing=spacing), repeats),
    )
    row["speedup"] = row["check_edges_s"] / row["certify_edges_s"]
    return row


def short_valid_segments(
    exact: CollisionChecker, n_segments: int, rng: np.random.Generator, step: float = 0.03
) -> tuple[np.ndarray, np.ndarray]:
    """Up to ``n_segments`` segments ``(Q0, Q1)``, ``(E, dof)`` each: valid uniform starts, ends a normal step of
    ``step`` x the bounds away (clipped to them) and valid too; what is between them may not be."""
    robot = exact.robot
    Q0 = robot.sample(rng, 20 * n_segments)  # (20 E, dof): enough valid starts in a cluttered workspace
    Q0 = Q0[exact.are_valid(Q0)]
    Q1 = np.clip(Q0 + rng.normal(0, step, Q0.shape) * (robot.upper - robot.lower), robot.lower, robot.upper)
    keep = exact.are_valid(Q1)
    return Q0[keep][:n_segments], Q1[keep][:n_segments]


def planning_ratios(
    scenario: Scenario,
    models: TrainedModels,
    *,
    n_workspaces: int = 2,
    per_workspace: int = 2,
    seed: int = 0,
    samplers: tuple[str, ...] = sampling.PAPER_SAMPLERS,
    overrides: dict | None = None,
    planner: str | None = None,
) -> dict[str, dict]:
    """Per sampler, one planner on the first queries of the paper's set, with ``models`` and without, in turns:
    ``{"sampling_ratio", "total_ratio"}`` (with / without, mean times), the same of the medians, both
    success rates and the sampling rounds and repairs a query each mode needed (means), and ``planner``, the name
    of the planner that ran.

    Both modes run ``planner`` (a name; None: ``toolkit.planning.prm.DEFAULT``, the lazy PRM) with the same
    parameters and the default exact checker (compiled): only the checker that decides samples differs.
    ``overrides`` change the planner's parameters (one it does not read is an error): the same queries with one
    option changed measure what that option does. ``samplers``: the paper's four by default, or any registered
    ones (``sampling.register_sampler``).
    """
    samplers = sampling.check_names(samplers)
    solver = make_planner(scenario, planner or prm.DEFAULT, **(overrides or {}))
    per_workspace = min(per_workspace, scenario.queries_per_workspace)
    query_set = queries.make_queries(scenario, seed=seed, n_workspaces=n_workspaces, per_workspace=per_workspace)
    table = queries.compare_prediction(
        scenario, query_set, lambda ws: LearnedChecker(ws, models), samplers=samplers, planner=solver, seed=seed
    )
    return {sampler: dict(prediction_ratios(row), planner=solver.name) for sampler, row in table.items()}


def prediction_ratios(row: dict) -> dict[str, float]:
    """One sampler's row of ``queries.compare_prediction``, as :func:`planning_ratios` reports it."""
    with_, without = row["with"], row["without"]
    return {
        "sampling_ratio": row["sampling_ratio"],
        "total_ratio": row["total_ratio"],
        "sampling_ratio_median": with_["sampling_s_median"] / without["sampling_s_median"],
        "total_ratio_median": with_["total_s_median"] / without["total_s_median"],
        "success_without": without["success_rate"],
        "success_with": with_["success_rate"],
        **{f"{key}_{mode}": row[mode][key] for key in ("rounds", "repairs") for mode in ("without", "with")},
    }
