"""Throughput benchmarks: configurations checked per second, exact and learned.

Figures are medians over repeats, and ratios come from one run, since these
machines are noisy. ``toolkit bench --scenario S --json`` prints them.
"""

from __future__ import annotations

import time

import numpy as np
import torch

from . import data
from .collision import exact_checker
from .scenarios import Scenario


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
                       repeats: int = 5) -> float:
    """Predictions per second of a :class:`~toolkit.learned.LearnedChecker` at ``batch``, the workspace encoded once.

    The networks are untrained ones of the preset's sizes: their speed does not depend on the weights.
    """
    from . import presets
    from .learned import LearnedChecker
    from .models import build_predictor
    from .training import TrainedModels

    recipe = presets.get(preset)
    torch.manual_seed(seed)
    predictor = build_predictor(scenario, recipe.encoding, recipe.mlp_hidden, recipe.dropout).eval()
    ws = data.workspaces(scenario, "query", 1, seed)[0]
    checker = LearnedChecker(ws, TrainedModels(scenario, recipe, predictor, seed))
    Q = scenario.robot.sample(np.random.default_rng(seed), batch)
    return median_rate(lambda: checker.are_valid(Q), batch, repeats)
