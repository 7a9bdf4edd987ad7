"""PRM with and without prediction: ``plan(exact, start, goal, ...)``, one entry to either planner.

The options' class chooses the planner (:mod:`toolkit.planning.options`):

- :class:`~toolkit.planning.options.PRMOptions`: the paper's Algorithm 1 (§III-B), on one page in
  :mod:`toolkit.planning.paper_prm`: rounds of |S|, every candidate edge checked exactly as it
  is added;
- :class:`~toolkit.planning.options.LazyPRMOptions` (the default): the lazy PRM,
  :mod:`toolkit.planning.lazy_prm`: the best exact planner, and with prediction learned edge
  screening (the paper's future work).

Both share one query's machinery (:mod:`toolkit.planning.query_roadmap`): connecting, bridging,
and the exact verification and repair of the candidate path, so every returned path is valid
under the exact checker; "with" and "without prediction" differ in the ``checker`` argument only.
"""

from __future__ import annotations

import numpy as np

from toolkit.geometry.collision import CollisionChecker
from toolkit.planning.lazy_prm import LazyPRM
from toolkit.planning.options import AUXILIARY, LazyPRMOptions, PRMOptions
from toolkit.planning.paper_prm import PRM
from toolkit.planning.query_roadmap import GOAL, STAGES, START, PlanResult, PlanStep

__all__ = [
    "AUXILIARY",
    "GOAL",
    "PRM",
    "STAGES",
    "START",
    "LazyPRM",
    "LazyPRMOptions",
    "PRMOptions",
    "PlanResult",
    "PlanStep",
    "plan",
]


def plan(
    exact: CollisionChecker,
    start,
    goal,
    *,
    sampler: str = "BS",
    checker: CollisionChecker | None = None,
    options: PRMOptions | None = None,
    rng: np.random.Generator,
    trace: list | None = None,
) -> PlanResult:
    """Solve one query ``start -> goal`` (``(dof,)`` each) with the planner of the ``options``' class (default: the
    lazy PRM); ``checker`` decides samples (default: ``exact``); a ``trace`` list receives a :class:`PlanStep` at
    every stage."""
    options = LazyPRMOptions() if options is None else options
    planner = LazyPRM if isinstance(options, LazyPRMOptions) else PRM  # the options' class says which
    return planner(exact, checker, options=options, sampler=sampler).solve(start, goal, rng=rng, trace=trace)
