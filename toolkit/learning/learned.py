"""The learned checker: the paper's predictor (§III-B, Algorithm 1 lines 1 and 3) behind the checker interface.

:class:`LearnedChecker` encodes its workspace with the CAE once, at construction,
and then answers ``are_valid(Q)`` for whole batches with one MLP pass, exactly like
the exact checkers of :mod:`toolkit.geometry.collision` do, so a planner swaps one for the
other in one argument. ``probability(Q)`` gives P(valid); ``threshold`` trades
false-valid (lower it: more samples accepted) against false-invalid (raise it).
Configurations outside the robot's bounds are invalid, whatever the network says.

>>> checker = load_checker("runs/2ds-strong", workspace)  # doctest: +SKIP
>>> checker.are_valid(Q), checker.probability(Q)  # doctest: +SKIP
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import torch
from scipy.special import expit, logit

from toolkit.geometry.collision import CollisionChecker
from toolkit.geometry.workspace import Workspace
from toolkit.learning.checkpoints import load_models
from toolkit.learning.inference import WorkspaceMLP
from toolkit.learning.training import TrainedModels


class LearnedChecker(CollisionChecker):
    """Predicted validity in one workspace: P(valid) >= ``threshold`` (default: the model's own, 0.5 or calibrated)."""

    # on a CPU a call's fixed cost is worth hundreds of configurations ("The learned checker's fast path" in
    # docs/benchmarks.md): better one call too many configurations than several calls
    few_calls = True

    def __init__(self, workspace: Workspace, models: TrainedModels, threshold: float | None = None):
        scenario = models.scenario
        if workspace.grid_shape != scenario.grid_shape:
            raise ValueError(
                f"workspace grid {workspace.grid_shape} does not fit scenario {scenario.name!r}'s {scenario.grid_shape}"
            )
        super().__init__(scenario.robot)
        self.workspace, self.models = workspace, models
        self.threshold = models.threshold if threshold is None else threshold
        device = models.predictor.threshold.device
        grid = torch.as_tensor(workspace.occupancy(), device=device)  # (*grid)
        self.workspace_mlp = WorkspaceMLP(models.predictor.eval(), grid)  # the workspace, encoded once
        self.workspace_mlp(self.robot.lower[None])  # a first call's one-off costs (lazy set-up) belong here

    @property
    def threshold(self) -> float:
        return self._threshold

    @threshold.setter
    def threshold(self, value: float) -> None:
        value = float(value)
        if not 0.0 <= value <= 1.0:
            raise ValueError(f"threshold must lie in [0, 1], got {value}")
        self._threshold = value
        self._margin_threshold = logit(value)  # P >= t  <=>  margin >= logit(t)

    def probability(self, Q) -> np.ndarray:
        """``(N,)`` P(valid) of configurations ``Q (N, dof)``; 0 outside the robot's bounds."""
        Q = self.robot.check_configs(Q)
        return np.where(self.robot.in_bounds(Q), expit(self.workspace_mlp(Q).astype(float)), 0.0)

    def validity(self, Q: np.ndarray) -> np.ndarray:
        # the margin logit(valid) - logit(invalid) (N,) of every row, in or out of bounds (cheaper than selecting)
        return self.robot.in_bounds(Q) & (self.workspace_mlp(Q) >= self._margin_threshold)


def load_checker(checkpoint_dir: str | Path, workspace: Workspace, threshold: float | None = None) -> LearnedChecker:
    """A :class:`LearnedChecker` for ``workspace`` from a folder written by ``toolkit train``."""
    models = load_models(checkpoint_dir)
    return LearnedChecker(workspace, models, threshold)
