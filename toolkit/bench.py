"""Benchmarks: configurations checked per second, exact and learned; PRM time with and without prediction.

Figures are medians over repeats, and ratios come from one run, since these
machines are noisy. ``toolkit bench --scenario S --json`` prints the throughput;
with ``--checkpoint DIR`` it also plans a few of the paper's queries with each
sampler, with and without that model, and prints the time ratios.
"""

from __future__ import annotations

import time

import numpy as np
import torch

from . import data, presets, queries
from .collision import exact_checker
from .learned import LearnedChecker
from .models import build_predictor
from .scenarios import Scenario
from .training import TrainedModels


def median_rate(fn, n_items: int, repeats: int = 5) -> float:
    """Items per second of ``fn()``, the median over ``repeats`` timed calls (one warm-up call first)."""
    fn()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return n_items / float(np.median(times))


def exact_throughput(scenario: Scenario, batch: int = 20_000, seed: int = 0, repeats: int = 5) -> float:
    """Configurations per second of the exact checker on uniform samples in one workspace."""
    ws = data.workspaces(scenario, "query", 1, seed)[0]
    checker = exact_checker(ws, scenario.robot)
    Q = scenario.robot.sample(np.random.default_rng(seed), batch)
    return median_rate(lambda: checker.are_valid(Q), batch, repeats)


def learned_throughput(scenario: Scenario, preset: str = "paper", batch: int = 10_000, seed: int = 0,
                       repeats: int = 5, models: TrainedModels | None = None) -> float:
    """Predictions per second of a :class:`~toolkit.learned.LearnedChecker` at ``batch``, the workspace encoded once.

    The networks are ``models`` or, by default, untrained ones of the preset's sizes: their speed
    does not depend on the weights.
    """
    if models is None:
        recipe = presets.get(preset)
        torch.manual_seed(seed)
        predictor = build_predictor(scenario, recipe.encoding, recipe.mlp_hidden, recipe.dropout, recipe.latent_input).eval()
        models = TrainedModels(scenario, recipe, predictor, seed)
    ws = data.workspaces(scenario, "query", 1, seed)[0]
    checker = LearnedChecker(ws, models)
    Q = scenario.robot.sample(np.random.default_rng(seed), batch)
    return median_rate(lambda: checker.are_valid(Q), batch, repeats)


def planning_ratios(scenario: Scenario, models: TrainedModels, n_workspaces: int = 2, per_workspace: int = 2,
                    seed: int = 0) -> dict[str, dict]:
    """Per sampler, PRM on the first queries of the paper's set, with ``models`` and without:
    ``{"sampling_ratio", "total_ratio"}`` (with / without, mean times) and both success rates."""
    per_workspace = min(per_workspace, scenario.queries_per_workspace)
    query_set = queries.make_queries(scenario, seed, n_workspaces, per_workspace)
    table = queries.compare_prediction(scenario, query_set, lambda ws: LearnedChecker(ws, models), seed=seed)
    return {sampler: {"sampling_ratio": row["sampling_ratio"], "total_ratio": row["total_ratio"],
                      "success_without": row["without"]["success_rate"], "success_with": row["with"]["success_rate"]}
            for sampler, row in table.items()}
