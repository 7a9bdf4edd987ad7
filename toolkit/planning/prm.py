"""PRM with and without prediction: ``plan(exact, start, goal, ...)``, one entry to either planner.

``options.planner`` chooses (:class:`~toolkit.planning.options.PRMOptions`):

- ``"paper"`` (``PAPER_BASELINE``): the paper's Algorithm 1 (§III-B), on one page in
  :mod:`toolkit.planning.paper_prm`: rounds of |S|, every candidate edge checked exactly as it
  is added; the ``paper`` preset's planner, with and without its model (Table 3);
- ``"lazy"`` (the default): the lazy PRM, :mod:`toolkit.planning.lazy_prm`: the best exact
  planner, and with prediction learned edge screening (the paper's future work).

Both share one query's machinery (:mod:`toolkit.planning.query_roadmap`): connecting, bridging,
and the exact verification and repair of the candidate path, so every returned path is valid
under the exact checker; "with" and "without prediction" differ in the ``checker`` argument only.
"""

from __future__ import annotations

import numpy as np

from toolkit.geometry.collision import CollisionChecker
from toolkit.planning.lazy_prm import LazyPRM
from toolkit.planning.options import AUXILIARY, PAPER_BASELINE, PRMOptions
from toolkit.planning.paper_prm import PRM
from toolkit.planning.query_roadmap import GOAL, STAGES, START, PlanResult, PlanStep

PLANNER_CLASSES = {"paper": PRM, "lazy": LazyPRM}  # PRMOptions.planner -> the class that runs it

__all__ = [
    "AUXILIARY",
    "GOAL",
    "PAPER_BASELINE",
    "PLANNER_CLASSES",
    "PRM",
    "STAGES",
    "START",
    "LazyPRM",
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
    """Solve one query ``start -> goal`` (``(dof,)`` each) with the planner ``options.planner`` names (default: the
    lazy PRM); ``checker`` decides samples (default: ``exact``); a ``trace`` list receives a :class:`PlanStep` at
    every stage."""
    options = PRMOptions() if options is None else options
    planner = PLANNER_CLASSES[options.planner](exact, checker, options, sampler)
    return planner.solve(start, goal, rng=rng, trace=trace)
