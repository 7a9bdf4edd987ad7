"""The checker interface (paper §II-B's "black box"): ``are_valid(Q (N, dof)) -> (N,) bool``.

As in OMPL's ``StateValidityChecker``, everything that needs validity asks a
:class:`CollisionChecker` for whole batches. The exact checkers
(:mod:`toolkit.geometry.collision`) and the learned one (:mod:`toolkit.learning.learned`)
share it, so planning with or without prediction differs in one argument.
"""

from __future__ import annotations

import numpy as np

from toolkit.geometry.robots import BoxRobot


class CollisionChecker:
    """Answers "is this configuration valid?" for batches; counts configurations checked.

    Callers ask :meth:`are_valid` and :meth:`clearances`, which check and count the batch; a
    checker of your own overrides :meth:`validity` (and :meth:`clearance_bounds`), which count nothing.

    ``few_calls``: a call's fixed cost outweighs its cost per configuration (a neural
    network on CPU): callers then ask about configurations they may not need in one
    call rather than in several dependent ones (same answers, fewer calls).
    ``certificates_pay``: bounding a clearance costs less than the checks it can spare
    (``local_planner.certify_edges``); False where a check is a few comparisons.
    ``is_exact``: its answers are the geometry's, the truth (the box-world checkers); False, the
    default, for a predictor or any checker that does not say so. A planner given a checker that is
    not exact to decide samples plans "with prediction", whatever other checker it holds.
    All three say what the checker *is*, like OMPL's validity-checker specs; how a planner uses
    it is the planner's business.
    """

    few_calls = False
    certificates_pay = True
    is_exact = False

    def __init__(self, robot: BoxRobot):
        self.robot = robot
        self.n_checked = 0  # configurations asked about since construction or reset_count()
        self.n_bounded = 0  # configurations whose clearance was bounded, likewise

    def are_valid(self, Q) -> np.ndarray:
        """``(N,)`` bool: whether each configuration of ``Q (N, dof)`` is valid."""
        Q = self.robot.check_configs(Q)
        self.n_checked += len(Q)
        return self.validity(Q)

    def is_valid(self, q) -> bool:
        """Whether the single configuration ``q (dof,)`` is valid."""
        q = np.asarray(q, dtype=float)
        if q.ndim != 1:
            raise ValueError(f"q must have shape ({self.robot.dof},), got {q.shape}")
        return bool(self.are_valid(q[None])[0])

    def reset_count(self) -> None:
        self.n_checked = self.n_bounded = 0

    def clearances(self, Q, cap: float) -> np.ndarray:
        """``(N,)`` a lower bound on each configuration's clearance, in ``[0, cap]``.

        The clearance is how far some point of the robot must move before the robot
        touches an obstacle or leaves the region (its distance to them, leaving out walls
        it never moves towards); > 0 proves the configuration valid.
        """
        Q = self.robot.check_configs(Q)
        if not (np.isfinite(cap) and cap > 0):
            raise ValueError(f"cap must be positive and finite, got {cap!r}")
        self.n_bounded += len(Q)
        return self.clearance_bounds(Q, float(cap))

    def clearance_bounds(self, Q: np.ndarray, cap: float) -> np.ndarray:
        """``(N,)`` clearance lower bounds of a checked batch; knowing no geometry, 0 (box-world checkers know more)."""
        return np.zeros(len(Q))

    def validity(self, Q: np.ndarray) -> np.ndarray:
        """``(N,)`` bool for a checked batch ``Q (N, dof)``: what a subclass decides (:meth:`are_valid` counts it)."""
        raise NotImplementedError(f"{type(self).__name__} must override validity(Q)")
