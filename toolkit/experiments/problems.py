"""One query built once: :func:`build` resolves everything a solve needs and returns a frozen :class:`Task`.

The command line (``toolkit plan``), the experiments (:mod:`toolkit.experiments.queries`), the
viewer and the notebooks build a query here, and nowhere else:

- the scenario (a name is looked up once), the query (the seed's first of the paper's set unless
  one is given: its workspace, start and goal), the sampler (checked by name);
- the exact checker, the truth for edges and paths (default: ``exact_checker``, the fastest), and
  the checker that decides samples (default: the exact one, so no prediction; a learned checker
  predicts because it is not exact, ``CollisionChecker.is_exact``);
- the planner (:func:`planner`): the one named, else the one paired with ``preset`` when a run
  trains that recipe (:mod:`toolkit.experiments.planners`), else ``toolkit.planning.prm.DEFAULT``;
  its parameters: its own defaults, the scenario's |S| (``Scenario.plan_samples``), the pairing's,
  then ``changes``. The local planner's resolution is the scenario's (:func:`scenario_resolution`).

So a reader of one :class:`Task` can say which planner, checkers and parameters a query ran with:
``task.planner`` (its ``name`` and ``params``) and ``task.problem``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from toolkit import scenarios
from toolkit.experiments import planners
from toolkit.experiments.query_sets import Query, make_queries
from toolkit.geometry.collision import CollisionChecker, exact_checker
from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace
from toolkit.learning.presets import Preset
from toolkit.planning import prm
from toolkit.planning.local_planner import default_resolution
from toolkit.planning.planner import Planner, PlanResult, Problem, replace_fields
from toolkit.scenarios import Scenario

CheckerSource = CollisionChecker | Callable[[Workspace], CollisionChecker] | None  # a checker, or how to build one
ExactSource = CollisionChecker | Callable[[Workspace, BoxRobot], CollisionChecker] | None


@dataclass(frozen=True)
class Task:
    """One query ready to solve: the ``scenario``, the ``query`` (its workspace), the ``planner`` that runs (a name and
    its parameters) and the ``problem`` it solves."""

    scenario: Scenario
    query: Query
    planner: Planner
    problem: Problem

    def solve(self, rng: np.random.Generator, *, trace: list | None = None) -> PlanResult:
        """The planner's answer; ``trace`` (roadmap planners): a list that receives every stage's snapshot."""
        if trace is None:
            return self.planner.solve(self.problem, rng)
        return self.planner.solve(self.problem, rng, trace=trace)  # type: ignore[call-arg]


def build(
    scenario: str | Scenario,
    query: Query | None = None,
    *,
    seed: int = 0,
    sampler: str = "BS",
    planner: str | Planner | None = None,
    checker: CheckerSource = None,
    exact: ExactSource = None,
    preset: Preset | None = None,
    **changes,
) -> Task:
    """The :class:`Task` of ``query`` (None: the first query of the paper's set for ``seed``) in ``scenario``.

    ``checker`` and ``exact``: a checker, or a function of the query's workspace (``exact``: of the workspace and
    the robot) that builds one; ``planner``: a name, or a planner already made; ``preset``: the recipe whose pairing
    names the planner when none is; ``changes``: to the planner's parameters."""
    scenario = scenarios.get(scenario) if isinstance(scenario, str) else scenario
    if query is None:
        query, truth = first_query(scenario, seed, exact)
    else:
        truth = (
            exact if isinstance(exact, CollisionChecker) else (exact or exact_checker)(query.workspace, scenario.robot)
        )
    checker = checker if checker is None or isinstance(checker, CollisionChecker) else checker(query.workspace)
    problem = Problem.create(
        truth, query.start, query.goal, sampler=sampler, checker=checker, resolution=scenario.plan_resolution
    )  # None: Problem.create's default_resolution(robot), so the resolution is scenario_resolution(scenario)
    if planner is None or isinstance(planner, str):
        solver = make_planner(scenario, planner, preset=preset, **changes)
    elif changes:
        raise ValueError(f"{planner!r} is made already: give it its parameters when you make it")
    else:
        solver = planner
    return Task(scenario, query, solver, problem)


def scenario_resolution(scenario: Scenario) -> float:
    """The local planner's resolution in ``scenario``: its own (``Scenario.plan_resolution``), else
    ``default_resolution(robot)``; returned paths are also checked ``planner.REFINEMENT`` times finer."""
    return scenario.plan_resolution or default_resolution(scenario.robot)


def first_query(scenario: Scenario, seed: int, exact: ExactSource) -> tuple[Query, CollisionChecker]:
    """The first query of the paper's set for ``seed`` and its workspace's exact checker, built once: it accepts the
    start and goal, then checks the plan."""
    kept = [exact] if isinstance(exact, CollisionChecker) else []
    factory = exact_checker if exact is None or isinstance(exact, CollisionChecker) else exact

    def exact_of(workspace: Workspace, robot: BoxRobot) -> CollisionChecker:
        kept[:] = kept or [factory(workspace, robot)]
        return kept[0]

    return make_queries(scenario, seed=seed, n_workspaces=1, per_workspace=1, exact=exact_of)[0], kept[0]


def make_planner(scenario: Scenario, name: str | None = None, *, preset: Preset | None = None, **changes) -> Planner:
    """The planner ``name`` (None: the one paired with ``preset``, :func:`toolkit.experiments.planners.pairing`;
    without a preset, ``toolkit.planning.prm.DEFAULT``) with the scenario's |S| (when it reads ``n_samples``),
    the pairing's parameters when it is the paired planner, then ``changes`` (one it does not read is an error)."""
    paired = planners.OWN_RECIPE if preset is None else planners.pairing(preset)
    cls = prm.get(name or paired.planner)
    defaults = cls.Params()
    settings: dict[str, object] = {"n_samples": scenario.plan_samples} if hasattr(defaults, "n_samples") else {}
    settings.update(paired.params if cls.name == paired.planner else {})
    return cls(replace_fields(defaults, {**settings, **changes}))
