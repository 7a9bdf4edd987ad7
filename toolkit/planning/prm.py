"""PRM with and without prediction: ``plan(exact, start, goal, ...)``, one entry to either planner.

The options' class chooses the planner (:mod:`toolkit.planning.options`; :data:`PLANNERS`, and
:func:`register_planner` for one of your own):

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
    "PLANNERS",
    "PRM",
    "STAGES",
    "START",
    "LazyPRM",
    "LazyPRMOptions",
    "PRMOptions",
    "PlanResult",
    "PlanStep",
    "plan",
    "register_planner",
]

PLANNERS: dict[type[PRMOptions], type[PRM]] = {PRMOptions: PRM, LazyPRMOptions: LazyPRM}  # options -> the planner


def register_planner(planner: type[PRM], *, replace: bool = False) -> type[PRM]:
    """Make :func:`plan` run ``planner`` (a subclass of :class:`PRM` with a ``name`` and an ``Options`` class of its
    own) for options of its ``Options`` class, and offer it by name (``toolkit bench --planner``)."""
    if not (isinstance(planner, type) and issubclass(planner, PRM)):
        raise TypeError(f"a planner is a subclass of toolkit.planning.paper_prm.PRM, got {planner!r}")
    known = PLANNERS.get(planner.Options)
    if known not in (None, planner) and not replace:
        raise ValueError(
            f"planner {known.name!r} reads {planner.Options.__name__} already: give yours an Options class"
        )
    PLANNERS[planner.Options] = planner
    return planner


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
    """Solve one query ``start -> goal`` (``(dof,)`` each) with the planner that reads the ``options``' class (default:
    the lazy PRM); ``checker`` decides samples (default: ``exact``); a ``trace`` list receives a :class:`PlanStep` at
    every stage."""
    options = LazyPRMOptions() if options is None else options
    if (planner := PLANNERS.get(type(options))) is None:  # the options' class says which planner runs
        raise TypeError(f"no planner reads {type(options).__name__}; see toolkit.planning.prm.register_planner")
    return planner(exact, checker, options=options, sampler=sampler).solve(start, goal, rng=rng, trace=trace)
