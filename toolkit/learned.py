"""The learned checker: the paper's online phase (§III-B, Algorithm 1 lines 1-6) behind the checker interface.

:class:`LearnedChecker` encodes its workspace with the CAE once, at construction,
and then answers ``are_valid(Q)`` for whole batches with one MLP pass, exactly like
the exact checkers of :mod:`toolkit.collision` do, so a planner swaps one for the
other in one argument. ``probability(Q)`` gives P(valid); ``threshold`` trades
false-valid (lower it: more samples accepted) against false-invalid (raise it).
Configurations outside the robot's bounds are invalid without asking the network.

>>> checker = load_checker("runs/2ds-strong", workspace)  # doctest: +SKIP
>>> checker.are_valid(Q), checker.probability(Q)  # doctest: +SKIP
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import torch
from scipy.special import expit, logit

from .checkpoints import load_models
from .collision import CollisionChecker
from .models import VALID
from .training import TrainedModels
from .workspace import Workspace


class LearnedChecker(CollisionChecker):
    """Predicted validity in one workspace: P(valid) >= ``threshold`` (default: the model's own, 0.5 or calibrated)."""

    def __init__(self, workspace: Workspace, models: TrainedModels, threshold: float | None = None):
        scenario = models.scenario
        if workspace.grid_shape != scenario.grid_shape:
            raise ValueError(f"workspace grid {workspace.grid_shape} does not fit scenario {scenario.name!r}'s "
                             f"{scenario.grid_shape}")
        super().__init__(scenario.robot)
        self.workspace, self.models = workspace, models
        self.threshold = models.threshold if threshold is None else threshold
        self._predictor = models.predictor.eval()
        self._device = models.predictor.threshold.device
        grid = torch.as_tensor(workspace.occupancy(), device=self._device)[None]  # (1, *grid)
        with torch.no_grad():
            self._context = self._predictor.context(grid)  # the workspace, encoded once

    @property
    def threshold(self) -> float:
        return self._threshold

    @threshold.setter
    def threshold(self, value: float) -> None:
        value = float(value)
        if not 0.0 <= value <= 1.0:
            raise ValueError(f"threshold must lie in [0, 1], got {value}")
        self._threshold = value

    def probability(self, Q) -> np.ndarray:
        """``(N,)`` P(valid) of configurations ``Q (N, dof)``; 0 outside the robot's bounds."""
        Q = self.robot.check_configs(Q)
        return expit(self._margin(Q, self.robot.in_bounds(Q)))

    def _are_valid(self, Q: np.ndarray) -> np.ndarray:
        inside = self.robot.in_bounds(Q)
        return inside & (self._margin(Q, inside) >= logit(self._threshold))  # P >= t  <=>  margin >= logit(t)

    def _margin(self, Q: np.ndarray, inside: np.ndarray) -> np.ndarray:
        """``(N,)`` logit(valid) - logit(invalid), so P(valid) = sigmoid(margin); -inf outside the bounds."""
        margin = np.full(len(Q), -np.inf)
        if inside.any():
            with torch.inference_mode():
                Qt = torch.as_tensor(Q[inside], dtype=torch.float32, device=self._device)
                ws_index = torch.zeros(len(Qt), dtype=torch.long, device=self._device)
                logits = self._predictor.logits(self._context, ws_index, Qt)  # (n, 2)
                margin[inside] = (logits[:, VALID] - logits[:, 1 - VALID]).cpu().numpy()
        return margin


def load_checker(checkpoint_dir: str | Path, workspace: Workspace, threshold: float | None = None) -> LearnedChecker:
    """A :class:`LearnedChecker` for ``workspace`` from a folder written by ``toolkit train``."""
    models = load_models(checkpoint_dir)
    return LearnedChecker(workspace, models, threshold)
