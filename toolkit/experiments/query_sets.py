"""The paper's planning queries (§IV-A): workspaces from the query stream, and start/goal pairs in each.

2DS and 3DO: 10 workspaces x 10 start/goal pairs; 3DC: 100 workspaces x 1 pair
(``scenario.query_workspaces x scenario.queries_per_workspace``). Workspaces come
from the ``'query'`` stream of :meth:`toolkit.scenarios.Scenario.workspaces`; starts and goals are
uniform configurations the exact checker accepts, drawn from a generator derived
from ``(seed, workspace index)``, and at least a quarter of the region's diagonal
apart (base positions), so every query means travelling.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from toolkit.geometry.collision import CollisionChecker, exact_checker
from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace
from toolkit.scenarios import STREAMS, Scenario

PAIR_STREAM = 1  # appended to the workspace's seed words: the start/goal pairs of query workspace i
PAIR_ATTEMPTS = 1000  # batches of 256 uniform configurations tried before a workspace is given up


@dataclass(frozen=True)
class Query:
    """One start/goal pair in workspace number ``workspace_index`` of the query stream."""

    workspace_index: int
    workspace: Workspace
    start: np.ndarray  # (dof,)
    goal: np.ndarray  # (dof,)


def query_pairs(
    scenario: Scenario, ws: Workspace, count: int, rng: np.random.Generator, *, min_separation: float = 0.25, exact=None
) -> list[tuple[np.ndarray, np.ndarray]]:
    """``count`` (start, goal) pairs valid under ``exact`` (None: ``exact_checker``), base positions ``min_separation``
    x diagonal apart; a workspace too full for them is a one-line ``ValueError``."""
    robot = scenario.robot
    checker = exact_checker(ws, robot) if exact is None else exact
    far = min_separation * float(np.linalg.norm(ws.upper - ws.lower))
    pairs: list[tuple[np.ndarray, np.ndarray]] = []
    for _ in range(PAIR_ATTEMPTS):
        Q = robot.sample(rng, 256)  # (256, dof)
        Q = Q[checker.are_valid(Q)]
        for start, goal in zip(Q[0::2], Q[1::2]):
            if len(pairs) < count and np.linalg.norm(goal[: robot.dim] - start[: robot.dim]) >= far:
                pairs.append((start, goal))
        if len(pairs) == count:
            return pairs
    raise ValueError(f"found no {count} valid start/goal pairs far enough apart in this {scenario.name} workspace")


def make_queries(
    scenario: Scenario,
    *,
    seed: int = 0,
    n_workspaces: int | None = None,
    per_workspace: int | None = None,
    exact: Callable[[Workspace, BoxRobot], CollisionChecker] = exact_checker,
) -> list[Query]:
    """The paper's query set (counts default to the scenario's), reproducible from ``seed``; ``exact(workspace,
    robot)`` builds the checker that accepts starts and goals (any exact checker gives the same set)."""
    n_workspaces = scenario.query_workspaces if n_workspaces is None else n_workspaces
    per_workspace = scenario.queries_per_workspace if per_workspace is None else per_workspace
    queries = []
    for i, ws in enumerate(scenario.workspaces("query", n_workspaces, seed)):
        rng = np.random.default_rng([int(seed), STREAMS["query"], i, PAIR_STREAM])
        pairs = query_pairs(scenario, ws, per_workspace, rng, exact=exact(ws, scenario.robot))
        queries += [Query(i, ws, start, goal) for start, goal in pairs]
    return queries
