"""The paper's four scenarios (§IV-A, §IV-B): workspace family, robot, data counts, model sizes.

>>> from toolkit import scenarios
>>> s = scenarios.get("3dc9")
>>> s.robot.dof, s.grid_shape
(9, (11, 11, 11))
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from toolkit.geometry import robots, workspace
from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace
from toolkit.util import registry

# What a seed's random numbers are drawn for, one stream each.
STREAMS = {
    "seen": 0,
    "unseen": 1,
    "query": 2,
    "train_samples": 3,
    "test_samples": 4,
    "unseen_samples": 5,
    "unseen_uniform": 6,
    "cae_grids": 7,
}


def stream_rng(seed: int, stream: str, index: int) -> np.random.Generator:
    """The generator for item ``index`` of a named stream of ``STREAMS``."""
    if stream not in STREAMS:
        raise ValueError(f"unknown stream {stream!r}; choose one of {sorted(STREAMS)}")
    return np.random.default_rng([int(seed), STREAMS[stream], int(index)])


@dataclass(frozen=True)
class Scenario:
    """One row of the paper's tables; counts and sizes are the paper's."""

    name: str
    title: str
    family: str  # workspace family: '2ds', '3do' or '3dc'
    robot: BoxRobot
    grid_shape: tuple[int, ...]
    n_seen: int  # workspaces the CAE and MLP train on (§IV-A)
    n_seen_test: int  # of those, how many are re-tested as "seen"
    n_unseen: int  # workspaces never trained on
    samples_per_workspace: int  # labelled configurations per workspace, about 50/50 (§IV-A)
    cae_hidden: tuple[int, ...]  # encoder widths after the input; the last is the latent size (§IV-B1)
    mlp_hidden: tuple[int, ...]  # MLP hidden widths (§IV-B2)
    plan_samples: int  # |S| in Algorithm 1 (§IV-A): samples drawn before prediction
    query_workspaces: int  # planning queries: workspaces x pairs (§IV-A)
    queries_per_workspace: int
    plan_resolution: float | None = None  # local planner: no robot point moves farther between checks
    #   (None: half the thinnest link, see toolkit.planning.local_planner.default_resolution)
    cae_max_steps: int | None = None  # caps CAE training where a step is slow (None: the preset's cap)
    cae_max_batch: int | None = None  # caps the CAE's batch where a step is slow (None: the preset's batch)
    cae_max_lr: float | None = None  # caps the CAE's learning rate where a higher one diverges (None: the preset's)

    def make_workspace(self, rng: np.random.Generator) -> Workspace:
        """A new random workspace of this scenario's family."""
        return workspace.generate(self.family, rng)

    def workspaces(self, stream: str, count: int, seed: int) -> list[Workspace]:
        """``count`` workspaces of a named stream of ``STREAMS``: 'seen' (training), 'unseen' or 'query' (planning).

        Workspace ``i`` is drawn from its own generator, :func:`stream_rng`, so growing a
        stream keeps the workspaces it already had.
        """
        return [self.make_workspace(stream_rng(seed, stream, i)) for i in range(count)]

    @property
    def latent_dim(self) -> int:
        return self.cae_hidden[-1]

    @property
    def grid_size(self) -> int:
        return int(np.prod(self.grid_shape))


MLP_3D = (50, 40, 30, 20, 10, 5)
CAE_3DC = (1000, 800, 600, 400, 200, 100, 50)


# The table: one scenario a block, its fields in the dataclass's order. The 3D clutter scenarios differ
# only in their robot; clutter() holds what they share.
# fmt: off
def clutter(name: str, title: str, robot: BoxRobot) -> Scenario:
    """A 3D clutter scenario (3DC): the paper's counts and sizes, the same for both box chains (§IV-A, §IV-B)."""
    return Scenario(name, title, "3dc", robot, (11, 11, 11),
                    n_seen=50, n_seen_test=30, n_unseen=10, samples_per_workspace=200,
                    cae_hidden=CAE_3DC, mlp_hidden=MLP_3D,
                    plan_samples=400, query_workspaces=100, queries_per_workspace=1,
                    cae_max_lr=1e-4)  # at 1e-3 the CAE diverges on 2000 grids (docs/fidelity.md)


SCENARIOS: dict[str, Scenario] = {s.name: s for s in [
    Scenario("2ds", "2D simple, point robot",       "2ds", robots.point_robot(), (31, 31),
             n_seen=30,  n_seen_test=30,  n_unseen=10, samples_per_workspace=100,
             cae_hidden=(512, 256, 128, 64, 32, 12),                mlp_hidden=(6, 4),
             plan_samples=200,  query_workspaces=10,  queries_per_workspace=10),
    Scenario("3do", "3D office, youBot-like 8-DoF", "3do", robots.youbot(),      (41, 41, 6),
             n_seen=100, n_seen_test=100, n_unseen=20, samples_per_workspace=200,
             cae_hidden=(5043, 3125, 1600, 800, 400, 200, 100, 50), mlp_hidden=MLP_3D,
             plan_samples=2000, query_workspaces=10,  queries_per_workspace=10,
             plan_resolution=0.1,  # half the thinnest link (0.03) would make every query far slower, and
                                   # the office's blocks are >= 1 thick (docs/design.md, "Local planner resolution")
             cae_max_steps=300, cae_max_batch=10,  # 147M parameters: each step is slow (docs/fidelity.md §3)
             cae_max_lr=1e-4),                     # at 1e-3 its CAE diverges
    clutter("3dc7", "3D clutter, 7-DoF box chain", robots.box_chain(1)),
    clutter("3dc9", "3D clutter, 9-DoF box chain", robots.box_chain(3)),
]}
# fmt: on


def register(scenario: Scenario, *, replace: bool = False) -> Scenario:
    """Make ``get(scenario.name)`` return ``scenario`` (a robot of your own, say), so that everything that takes a
    scenario's name accepts it: training, checkpoints, queries, ``toolkit.teaching.notebook.trained_models``.

    The robot must fit the family's workspaces (its dimension is the grid's); a name
    already taken (the paper's four among them) is refused unless ``replace``.
    Registration lasts for the Python process: register again before loading a checkpoint.
    """
    if scenario.family not in workspace.GENERATORS:
        raise ValueError(f"unknown workspace family {scenario.family!r}; choose one of {sorted(workspace.GENERATORS)}")
    if len(scenario.grid_shape) != scenario.robot.dim:
        raise ValueError(
            f"a {scenario.robot.dim}D robot cannot move in the {len(scenario.grid_shape)}D grid {scenario.grid_shape}"
        )
    family_grid = scenario.make_workspace(np.random.default_rng(0)).grid_shape
    if family_grid != tuple(scenario.grid_shape):
        raise ValueError(f"{scenario.family!r} workspaces have the grid {family_grid}, not {scenario.grid_shape}")
    return registry.bind(SCENARIOS, scenario.name, scenario, kind="scenario", replace=replace)


def get(name: str) -> Scenario:
    """The scenario called ``name`` ('2ds', '3do', '3dc7', '3dc9' or a registered one)."""
    return registry.lookup(SCENARIOS, name, kind="scenario")
