"""The planner interface: a frozen :class:`Problem`, a :class:`Planner` that solves it, the answer (OMPL's split).

As in OMPL (``ProblemDefinition``, ``Planner::solve``, ``Planner::declareParam``), what a query
*is* and how it is *solved* are apart:

- a :class:`Problem` is one query, frozen: the exact checker (the truth for edges and returned
  paths), start and goal ``(dof,)``, the sampler by name, the checker that decides samples (the
  exact one when nothing predicts), and the local planner's resolution;
- a planner has a ``name``, its own frozen parameters class ``Params`` and
  ``solve(problem, rng) -> PlanResult``. :class:`Planner` is a convenient base (it checks the
  parameters' class), not a requirement: :func:`toolkit.planning.prm.register` takes any class
  with those three, a roadmap planner or a tree (an RRT) alike.

Whether a query is planned *with prediction* is a property of the checker that decides samples
(``CollisionChecker.is_exact``): a learned checker predicts, a second exact checker (an ``FCLChecker``
of the same workspace) does not. Every returned path has passed the exact checker at
``problem.resolution`` and ``problem.fine_resolution`` (§III-B: "the path is extracted and verified").
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, fields, replace
from typing import Any, ClassVar

import numpy as np

from toolkit.geometry.collision import CollisionChecker
from toolkit.planning import sampling
from toolkit.planning.local_planner import default_resolution
from toolkit.util import registry

REFINEMENT = 10  # a returned path's edges are also checked at resolution / this: shortest paths hug obstacles


@dataclass(frozen=True, eq=False)
class Problem:
    """One query ``start -> goal``, frozen and checked; build it with :meth:`create`, which fills in the defaults."""

    exact: CollisionChecker  # the truth: every edge kept and every returned path is checked by it
    start: np.ndarray  # (dof,)
    goal: np.ndarray  # (dof,)
    sampler: str  # a name of toolkit.planning.sampling.SAMPLERS (checked by create)
    checker: CollisionChecker  # decides samples: the exact checker when nothing predicts
    predicts: bool  # samples are decided by prediction: the checker is not exact (CollisionChecker.is_exact)
    resolution: float  # local planner: no robot point moves farther between two checks
    refinement: int = REFINEMENT  # returned paths are also checked at resolution / refinement

    @classmethod
    def create(cls, exact, start, goal, *, sampler="BS", checker=None, resolution=None) -> Problem:
        """``checker`` None: the exact checker decides samples, nothing predicts; else ``predicts`` is what the checker
        says it is (``not checker.is_exact``). ``resolution`` None: ``default_resolution(robot)``."""
        robot = exact.robot
        registry.lookup(sampling.SAMPLERS, sampler, kind="sampler")  # an unknown one: a one-line error, now
        if checker is not None and checker.robot.dof != robot.dof:
            raise ValueError(f"checker is for a {checker.robot.dof}-DoF robot, the exact checker for {robot.dof}")
        resolution = default_resolution(robot) if resolution is None else float(resolution)
        if not (np.isfinite(resolution) and resolution > 0):
            raise ValueError(f"resolution must be positive and finite, got {resolution!r}")
        start, goal = _single(robot, start, "start"), _single(robot, goal, "goal")
        predicts = checker is not None and not checker.is_exact
        return cls(exact, start, goal, sampler, checker or exact, predicts, resolution)

    @property
    def robot(self):
        return self.exact.robot

    @property
    def fine_resolution(self) -> float:
        """The finer of the two resolutions every returned path is checked at."""
        return self.resolution / self.refinement

    def __repr__(self) -> str:
        what = type(self.checker).__name__ if self.predicts else "no prediction"
        return f"Problem({self.robot.name}, {self.sampler}, {type(self.exact).__name__}, {what})"


@dataclass
class PlanResult:
    """``success``; ``path (P, dof)`` (empty on failure); ``stats`` (counts, seconds); ``planner``, the name of the
    planner that ran; its final ``roadmap`` (None for a planner without one)."""

    success: bool
    path: np.ndarray
    stats: dict
    planner: str
    roadmap: Any = None


class Planner:
    """A base for planners: ``Planner(params)`` (default: ``Params()``) or with changed fields
    (``LazyPRM(k=20)``); a subclass sets ``name``, ``Params`` and writes :meth:`solve`."""

    name: ClassVar[str]
    Params: ClassVar[type]

    def __init__(self, params=None, **changes):
        params = self.Params() if params is None else params
        if type(params) is not self.Params:  # another planner's parameters are not this one's
            raise TypeError(f"{type(self).__name__} reads {self.Params.__name__}, got {type(params).__name__}")
        self.params = replace_fields(params, changes)

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.params!r})"

    def solve(self, problem: Problem, rng: np.random.Generator) -> PlanResult:
        """A path for ``problem``, every one returned valid under ``problem.exact``."""
        raise NotImplementedError(f"{type(self).__name__} must write solve(problem, rng)")


def replace_fields(params, changes: Mapping[str, Any]):
    """``params`` with ``changes`` (a field the class lacks is a one-line error naming the fields it has)."""
    if not changes:
        return params
    known = sorted(f.name for f in fields(params))
    if unknown := sorted(set(changes) - set(known)):
        raise ValueError(f"unknown planner option(s) {unknown}; {type(params).__name__} has {known}")
    return replace(params, **changes)


def _single(robot, q, name: str) -> np.ndarray:
    """``q`` as a ``(dof,)`` configuration of ``robot``, or a clear error naming ``name``."""
    q = np.asarray(q, dtype=float)
    if q.shape != (robot.dof,):
        raise ValueError(f"{name} must have shape ({robot.dof},) for robot {robot.name!r}, got {q.shape}")
    return robot.check_configs(q, name)[0]
