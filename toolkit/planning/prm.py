"""The planners by name, and ``plan(exact, start, goal, ...)``: one entry to any of them.

Planners are registered by name (:data:`PLANNERS`; :func:`register`, :func:`get`, :func:`names`), each
with its own parameters (:mod:`toolkit.planning.planner`):

- ``paper``: the paper's Algorithm 1 (§III-B), on one page in :mod:`toolkit.planning.paper_prm`:
  rounds of |S|, every candidate edge checked exactly as it is added;
- ``lazy`` (:data:`DEFAULT`): the lazy PRM, :mod:`toolkit.planning.lazy_prm`: the best exact
  planner, and with prediction learned edge screening (the paper's future work);
- ``batched``: the lazy PRM with each round's samples decided in one checker call (a device call when
  the checker is on a device), :mod:`toolkit.planning.batched_prm`;
- ``rrt-connect``: RRT-Connect, :mod:`toolkit.planning.rrt_connect`: two trees, for a single query
  the fastest exact planner (no prediction);
- any class with a ``name``, a ``Params`` class and ``solve(problem, rng)``: a tree planner too.

**The rule for which planner runs**, the one place it is applied: the one the caller names;
none named, :data:`DEFAULT`, with or without prediction. "With" and "without prediction" differ in
the problem's ``checker`` only; the planner stays the same unless you name another. Every returned
path is valid under the exact checker.
"""

from __future__ import annotations

from dataclasses import is_dataclass

import numpy as np

from toolkit.geometry.collision import CollisionChecker
from toolkit.planning.batched_prm import BatchedPRM
from toolkit.planning.lazy_prm import LazyPRM
from toolkit.planning.options import AUXILIARY, BatchedParams, LazyParams, PaperParams
from toolkit.planning.paper_prm import PRM
from toolkit.planning.planner import Planner, PlanResult, Problem
from toolkit.planning.query_roadmap import GOAL, STAGES, START, PlanStep
from toolkit.planning.rrt_connect import RRTConnect
from toolkit.util import registry

__all__ = [
    "AUXILIARY",
    "DEFAULT",
    "GOAL",
    "PLANNERS",
    "PRM",
    "STAGES",
    "START",
    "BatchedPRM",
    "BatchedParams",
    "LazyPRM",
    "LazyParams",
    "PaperParams",
    "PlanResult",
    "PlanStep",
    "Planner",
    "Problem",
    "get",
    "make",
    "names",
    "plan",
    "register",
]

DEFAULT = "lazy"  # the planner that runs when none is named: the best exact planner, with or without prediction
# name -> planner class
PLANNERS: dict[str, type[Planner]] = {p.name: p for p in (PRM, LazyPRM, BatchedPRM, RRTConnect)}


def register(planner: type[Planner], *, replace: bool = False) -> type[Planner]:
    """Offer ``planner`` by its ``name`` (:func:`get`, ``plan(..., planner=NAME)``, ``toolkit plan --planner``):
    any class with a ``name``, a dataclass ``Params`` of its own and ``solve(problem, rng)``."""
    if not isinstance(planner, type):
        raise TypeError(f"a planner is a class, got {planner!r}")
    for attribute, ok in (
        ("name", isinstance(getattr(planner, "name", None), str)),
        ("Params", is_dataclass(getattr(planner, "Params", None))),
        ("solve", callable(getattr(planner, "solve", None))),
    ):
        if not ok:
            raise TypeError(f"planner {planner.__name__} needs {attribute} (a name, a dataclass Params, solve)")
    owner = next((p for p in PLANNERS.values() if p.Params is planner.Params and p is not planner), None)
    if owner is not None and not (replace and owner.name == planner.name):
        raise ValueError(f"planner {owner.name!r} reads {planner.Params.__name__} already: give yours a Params class")
    return registry.bind(PLANNERS, planner.name, planner, kind="planner", replace=replace)


def get(name: str) -> type[Planner]:
    """The planner class registered as ``name`` (an unknown name: a one-line error listing the known)."""
    return registry.lookup(PLANNERS, name, kind="planner")


def names() -> list[str]:
    """The registered planners' names, in the order they were registered."""
    return list(PLANNERS)


def make(planner: str | Planner | None = None, params=None, **changes) -> Planner:
    """A planner ready to solve: ``planner`` (a name, None: :data:`DEFAULT`, or one already made) with ``params``
    (default: its ``Params()``) and ``changes`` to them."""
    if planner is not None and not isinstance(planner, str):
        if params is not None or changes:
            raise ValueError(f"{planner!r} is made already: pass its parameters when you make it")
        return planner
    return get(planner or DEFAULT)(params, **changes)


def plan(
    exact: CollisionChecker,
    start,
    goal,
    *,
    sampler: str = "BS",
    checker: CollisionChecker | None = None,
    planner: str | Planner | None = None,
    resolution: float | None = None,
    rng: np.random.Generator,
    trace: list | None = None,
) -> PlanResult:
    """Solve one query ``start -> goal`` (``(dof,)`` each) with ``planner`` (a name, None: :data:`DEFAULT`, or one made
    with its parameters, e.g. ``LazyPRM(n_samples=200)``); ``checker`` decides samples (None: ``exact``: no
    prediction); ``resolution``: the local planner's (None: ``default_resolution``); a ``trace`` list receives a
    :class:`PlanStep` at every stage (roadmap planners)."""
    problem = Problem.create(exact, start, goal, sampler=sampler, checker=checker, resolution=resolution)
    solver = make(planner)
    return solver.solve(problem, rng) if trace is None else solver.solve(problem, rng, trace=trace)  # type: ignore[call-arg]
