"""Benchmarks: configurations checked per second, exact and learned; exact edge checks, plain and certified;
PRM time with and without prediction.

Figures are medians over repeats, and ratios come from one run, since these
machines are noisy; :func:`throughput` times the two checkers in turns, so that
both see the same machine however its load changes. ``toolkit bench --scenario S
--json`` prints the throughput and the edge checks; with ``--checkpoint DIR`` it
also plans a few of the paper's queries with each sampler, with and without that
model, and prints the time ratios.
"""

from __future__ import annotations

import dataclasses
import time
from typing import Callable

import numpy as np
import torch

from . import data, presets, queries
from .collision import exact_checker
from .learned import LearnedChecker
from .local_planner import certify_edges, check_edges, default_resolution
from .models import build_predictor
from .prm import PRMOptions
from .scenarios import Scenario
from .training import TrainedModels


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


def in_turns(calls: dict[str, tuple[Callable[[], object], int]], repeats: int = 5) -> dict[str, float]:
    """Items per second of each ``name: (fn, n_items)``, the medians of ``repeats`` rounds in which every
    ``fn`` is timed once, in turns (after one warm-up call each).

    Timed one after the other, two measurements see different machines when the load
    changes: on 2 cores beside two busy processes (and other work), 3DC-7's learned /
    exact ratio came out 20.9 in one run and 5.2 in another, 3DO's 27.4 and 151; timed
    in turns, both see the same machine.
    """
    for fn, _ in calls.values():
        fn()
    seconds: dict[str, list[float]] = {name: [] for name in calls}
    for _ in range(repeats):
        for name, (fn, _) in calls.items():
            start = time.perf_counter()
            fn()
            seconds[name].append(time.perf_counter() - start)
    return {name: n / float(np.median(seconds[name])) for name, (_, n) in calls.items()}


def throughput(scenario: Scenario, preset: str = "paper", batch: int | None = None, seed: int = 0, repeats: int = 5,
               models: TrainedModels | None = None) -> dict[str, float]:
    """``{"exact_cfg_per_s", "learned_cfg_per_s", "ratio"}``: both checkers timed in turns (:func:`in_turns`),
    at ``batch`` configurations a call (default: 20,000 exact, 10,000 learned)."""
    batches = {"batch": batch} if batch else {}
    rates = in_turns({"exact": _exact_call(scenario, seed=seed, **batches),
                      "learned": _learned_call(scenario, preset, seed=seed, models=models, **batches)}, repeats)
    return {"exact_cfg_per_s": rates["exact"], "learned_cfg_per_s": rates["learned"],
            "ratio": rates["learned"] / rates["exact"]}


def exact_throughput(scenario: Scenario, batch: int = 20_000, seed: int = 0, repeats: int = 5) -> float:
    """Configurations per second of the exact checker on uniform samples in one workspace."""
    return median_rate(*_exact_call(scenario, batch, seed), repeats)


def learned_throughput(scenario: Scenario, preset: str = "paper", batch: int = 10_000, seed: int = 0,
                       repeats: int = 5, models: TrainedModels | None = None) -> float:
    """Predictions per second of a :class:`~toolkit.learned.LearnedChecker` at ``batch``, the workspace encoded once.

    The networks are ``models`` or, by default, untrained ones of the preset's sizes: their speed
    does not depend on the weights.
    """
    return median_rate(*_learned_call(scenario, preset, batch, seed, models), repeats)


def _exact_call(scenario: Scenario, batch: int = 20_000, seed: int = 0) -> tuple[Callable[[], object], int]:
    """The exact checker asked about ``batch`` uniform samples in a query workspace, and ``batch``."""
    ws = data.workspaces(scenario, "query", 1, seed)[0]
    checker = exact_checker(ws, scenario.robot)
    Q = scenario.robot.sample(np.random.default_rng(seed), batch)
    return (lambda: checker.are_valid(Q)), batch


def _learned_call(scenario: Scenario, preset: str = "paper", batch: int = 10_000, seed: int = 0,
                  models: TrainedModels | None = None) -> tuple[Callable[[], object], int]:
    """A learned checker (``models``, or untrained networks of the preset's sizes) asked about ``batch``
    uniform samples in a query workspace, and ``batch``."""
    if models is None:
        recipe = presets.get(preset)
        torch.manual_seed(seed)
        predictor = build_predictor(scenario, recipe.encoding, recipe.mlp_hidden, recipe.dropout, recipe.latent_input).eval()
        models = TrainedModels(scenario, recipe, predictor, seed)
    ws = data.workspaces(scenario, "query", 1, seed)[0]
    checker = LearnedChecker(ws, models)
    Q = scenario.robot.sample(np.random.default_rng(seed), batch)
    return (lambda: checker.are_valid(Q)), batch


def edge_checks(scenario: Scenario, n_segments: int = 300, seed: int = 0, repeats: int = 5) -> dict[str, dict]:
    """``check_edges`` against ``certify_edges`` (same answers) at the planner's resolution and 10x finer.

    On ``n_segments`` segments between valid configurations of a query workspace, 3 %
    of the bounds apart (normal steps: some valid, some grazing, some through a block;
    a path's edges look like these). Per resolution: median seconds of each, and the
    configurations each checked (``certify_edges`` also bounds clearances).
    """
    ws = data.workspaces(scenario, "query", 1, seed)[0]
    exact, robot, rng = exact_checker(ws, scenario.robot), scenario.robot, np.random.default_rng(seed)
    Q0 = robot.sample(rng, 20 * n_segments)
    Q0 = Q0[exact.are_valid(Q0)]
    Q1 = np.clip(Q0 + rng.normal(0, 0.03, Q0.shape) * (robot.upper - robot.lower), robot.lower, robot.upper)
    keep = exact.are_valid(Q1)
    Q0, Q1 = Q0[keep][:n_segments], Q1[keep][:n_segments]  # (E, dof) each
    resolution = scenario.plan_resolution or default_resolution(robot)
    spacing = resolution * PRMOptions().certify_spacing
    result = {}
    for name, r in (("resolution", resolution), ("finer", resolution / 10)):
        exact.reset_count()
        valid = check_edges(exact, Q0, Q1, r)
        row = {"resolution": r, "segments": len(Q0), "valid": float(valid.mean()), "check_edges_checked": exact.n_checked}
        exact.reset_count()
        certify_edges(exact, Q0, Q1, r, spacing)
        row.update(certify_edges_checked=exact.n_checked, certify_edges_bounded=exact.n_bounded,
                   check_edges_s=median_seconds(lambda: check_edges(exact, Q0, Q1, r), repeats),
                   certify_edges_s=median_seconds(lambda: certify_edges(exact, Q0, Q1, r, spacing), repeats))
        row["speedup"] = row["check_edges_s"] / row["certify_edges_s"]
        result[name] = row
    return result


def planning_ratios(scenario: Scenario, models: TrainedModels, n_workspaces: int = 2, per_workspace: int = 2,
                    seed: int = 0, samplers=("BS", "OB", "G", "BT"), overrides: dict | None = None) -> dict[str, dict]:
    """Per sampler, PRM on the first queries of the paper's set, with ``models`` and without, in turns:
    ``{"sampling_ratio", "total_ratio"}`` (with / without, mean times), the same of the medians, both
    success rates and the sampling rounds and repairs a query each mode needed (means).

    ``overrides`` (PRMOptions fields) apply to both modes, over the scenario's settings and the
    preset's: the same queries with one option changed measure what that option does.
    """
    fields = {f.name for f in dataclasses.fields(PRMOptions)}
    if unknown := sorted(set(overrides or {}) - fields):
        raise ValueError(f"unknown planner option(s) {unknown}; PRMOptions has {sorted(fields)}")
    options = queries.default_options(scenario, None, **{**models.preset.planner_options(), **(overrides or {})})
    per_workspace = min(per_workspace, scenario.queries_per_workspace)
    query_set = queries.make_queries(scenario, seed, n_workspaces, per_workspace)
    table = queries.compare_prediction(scenario, query_set, lambda ws: LearnedChecker(ws, models), samplers,
                                       options, seed)
    return {sampler: {"sampling_ratio": row["sampling_ratio"], "total_ratio": row["total_ratio"],
                      "sampling_ratio_median": row["with"]["sampling_s_median"] / row["without"]["sampling_s_median"],
                      "total_ratio_median": row["with"]["total_s_median"] / row["without"]["total_s_median"],
                      "success_without": row["without"]["success_rate"], "success_with": row["with"]["success_rate"],
                      **{f"{key}_{mode}": row[mode][key] for key in ("rounds", "repairs") for mode in ("without", "with")}}
            for sampler, row in table.items()}
