"""The learned checker: the paper's predictor (§III-B, Algorithm 1 lines 1 and 3) behind the checker interface.

:class:`LearnedChecker` encodes its workspace with the CAE once, at construction,
and then answers ``are_valid(Q)`` for whole batches with one MLP pass, exactly like
the exact checkers of :mod:`toolkit.geometry.collision` do, so a planner swaps one for the
other in one argument. ``probability(Q)`` gives P(valid); ``threshold`` trades
false-valid (lower it: more samples accepted) against false-invalid (raise it).
Configurations outside the robot's bounds are invalid, whatever the network says.

On a device (``device="cuda"``, or the device the models are on): ``are_valid`` of a
torch tensor answers with a bool tensor on the same device, without a round trip
(:mod:`toolkit.geometry.device`); a numpy batch travels through pinned buffers, in
chunks, as float32 (the network's type), and only its answers come back. The bounds
are compared in the batch's own type, exactly (float32 bounds rounded inwards).
``graph_sizes``: batch sizes whose calls are recorded once and replayed as a CUDA graph
(:class:`~toolkit.learning.inference.Replay`): a small call's launches cost more than its
arithmetic. ``docs/gpu.md`` has what each path measured.

>>> checker = load_checker("runs/2ds-strong", workspace)  # doctest: +SKIP
>>> checker.are_valid(Q), checker.probability(Q)  # doctest: +SKIP
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import torch
from scipy.special import expit, logit

from toolkit.geometry.collision import CollisionChecker
from toolkit.geometry.device import Stager, checked_array, checked_tensor, is_tensor
from toolkit.geometry.workspace import Workspace
from toolkit.learning.checkpoints import load_models
from toolkit.learning.inference import Replay, WorkspaceMLP
from toolkit.learning.training import TrainedModels


class LearnedChecker(CollisionChecker):
    """Predicted validity in one workspace: P(valid) >= ``threshold`` (default: the model's own, 0.5 or calibrated)."""

    # on a CPU a call's fixed cost is worth hundreds of configurations ("The learned checker's fast path" in
    # docs/benchmarks.md): better one call too many configurations than several calls
    few_calls = True

    def __init__(
        self,
        workspace: Workspace,
        models: TrainedModels,
        threshold: float | None = None,
        *,
        device: torch.device | str | None = None,
        graph_sizes: tuple[int, ...] = (),
    ):
        scenario = models.scenario
        if workspace.grid_shape != scenario.grid_shape:
            raise ValueError(
                f"workspace grid {workspace.grid_shape} does not fit scenario {scenario.name!r}'s {scenario.grid_shape}"
            )
        super().__init__(scenario.robot)
        self.workspace, self.models = workspace, models
        self.threshold = models.threshold if threshold is None else threshold
        home = models.predictor.threshold.device
        self.device = home if device is None else torch.device(device)
        grid = torch.as_tensor(workspace.occupancy(), device=home)  # (*grid)
        # the workspace, encoded once
        self.workspace_mlp = WorkspaceMLP(models.predictor.eval(), grid, device=self.device)
        self._bounds = {  # by the batch's type: bounds that compare exactly in it
            dtype: tuple(torch.as_tensor(b, device=self.device) for b in inward_bounds(self.robot, dtype))
            for dtype in (torch.float32, torch.float64)
        }
        self._stager = Stager(self.device, self.robot.dof, torch.float32)
        self.workspace_mlp(self.robot.lower[None])  # a first call's one-off costs (lazy set-up) belong here
        fill = torch.tensor(self.robot.lower, dtype=torch.float32, device=self.device)  # (dof,)
        self._replays = [Replay(self._decide, fill.expand(n, -1)) for n in sorted(graph_sizes)]

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

    def are_valid(self, Q):
        """``(N,)`` bool of ``Q (N, dof)``: numpy for numpy (float32 or float64, not copied to either), a tensor
        on ``Q``'s device for a tensor (non-finite rows invalid, :mod:`toolkit.geometry.device`)."""
        if is_tensor(Q):
            Q = checked_tensor(self.robot, Q)
            self.n_checked += len(Q)
            return self.validity_tensor(Q)
        Q = checked_array(self.robot, Q)
        self.n_checked += len(Q)
        if self.device.type == "cpu":
            if not np.isfinite(Q).all():
                raise ValueError("Q contains NaN or infinite values")
            return self.validity(Q)
        finite = torch.ones((), dtype=torch.bool, device=self.device)  # read once, after the last chunk

        def decide(chunk: torch.Tensor) -> torch.Tensor:
            finite.logical_and_(torch.isfinite(chunk).all())
            return self._decide(chunk)

        valid = self._stager(decide, Q)
        if not finite.item():
            raise ValueError("Q contains NaN or infinite values")
        return valid

    def validity(self, Q: np.ndarray) -> np.ndarray:
        # the margin logit(valid) - logit(invalid) (N,) of every row, in or out of bounds (cheaper than selecting)
        return self.robot.in_bounds(Q) & (self.workspace_mlp(Q) >= self._margin_threshold)

    def validity_tensor(self, Q: torch.Tensor) -> torch.Tensor:
        """On the checker's device, replayed where a recorded size fits a float32 batch; answered on ``Q``'s."""
        on_device = Q.to(self.device)
        replay = next((r for r in self._replays if r.capacity >= len(Q)), None)
        if replay is not None and Q.dtype == torch.float32:
            return replay(on_device).to(Q.device)
        return self._decide(on_device).to(Q.device)

    def _decide(self, Q: torch.Tensor) -> torch.Tensor:
        """``(N,)`` bool of a float tensor ``Q (N, dof)`` on the checker's device: in bounds, margin >= threshold."""
        lower, upper = self._bounds[torch.float32 if Q.dtype == torch.float32 else torch.float64]
        inside = ((Q >= lower) & (Q <= upper)).all(dim=1)  # (N,); NaN compares False
        finite = torch.nan_to_num(Q.float(), nan=0.0, posinf=0.0, neginf=0.0)  # NaN would index no grid cell
        return inside & (self.workspace_mlp.margins(finite) >= self._margin_threshold)


def inward_bounds(robot, dtype: torch.dtype) -> tuple[np.ndarray, np.ndarray]:
    """The robot's bounds in ``dtype``, rounded inwards: for ``q`` of that type, ``lower <= q`` in float64 exactly
    when ``lower' <= q`` in it (the least representable number >= lower; likewise for upper)."""
    kind = torch.empty(0, dtype=dtype).numpy().dtype
    lower, upper = robot.lower.astype(kind), robot.upper.astype(kind)
    lower = np.where(lower < robot.lower, np.nextafter(lower, kind.type(np.inf)), lower)
    upper = np.where(upper > robot.upper, np.nextafter(upper, kind.type(-np.inf)), upper)
    return lower, upper


def load_checker(checkpoint_dir: str | Path, workspace: Workspace, threshold: float | None = None) -> LearnedChecker:
    """A :class:`LearnedChecker` for ``workspace`` from a folder written by ``toolkit train``."""
    models = load_models(checkpoint_dir)
    return LearnedChecker(workspace, models, threshold)
