"""Which learned model a scene shows: a checkpoint's or a predictor's checker, kept only if it gives P(valid) for
the scene's robot.

The paper's network (§III) is a checker like the exact one, with one thing more: its probability of validity, which
the viewer draws as a wireframe around the links. A model for another scenario's robot, or a checker without
``probability``, is refused with the reason, which the panel shows; the scene goes on with the exact checker alone.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial
from pathlib import Path
from typing import Protocol, runtime_checkable

import numpy as np

from toolkit.geometry.collision import CollisionChecker
from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace

Predictor = Callable[[Workspace], CollisionChecker]  # workspace -> checker with are_valid(Q), probability(Q)


@runtime_checkable
class Predicts(Protocol):
    """What a model's checker has beyond are_valid: P(valid) ``(N,)`` of configurations ``Q (N, dof)``."""

    def probability(self, Q) -> np.ndarray: ...


def predictor(checkpoint: str | Path | None, predictor: Predictor | None) -> Predictor | None:
    """The function workspace -> learned checker: the given ``predictor``, or one reading ``checkpoint`` (a folder
    from ``toolkit train``), or None; a checkpoint that cannot be read raises here."""
    if checkpoint is not None and predictor is not None:
        raise ValueError("give a checkpoint or a predictor, not both")
    if checkpoint is None:
        return predictor
    from toolkit.learning.checkpoints import load_models  # torch: only when a model is asked for
    from toolkit.learning.learned import LearnedChecker

    return partial(LearnedChecker, models=load_models(checkpoint))


def model_for(
    predictor: Predictor | None, workspace: Workspace, robot: BoxRobot
) -> tuple[CollisionChecker | None, str]:
    """The predictor's checker for ``workspace``, or None and why it does not apply ("" when there is no predictor)."""
    if predictor is None:
        return None, ""
    try:
        model = predictor(workspace)
    except (ValueError, FileNotFoundError) as err:  # e.g. a checkpoint of another scenario
        return None, str(err)
    if not isinstance(model, Predicts):
        return None, f"the predictor's {type(model).__name__} gives no probability(Q)"
    if model.robot.name != robot.name:
        return None, f"the model is for robot {model.robot.name!r}, this scenario's is {robot.name!r}"
    return model, ""
