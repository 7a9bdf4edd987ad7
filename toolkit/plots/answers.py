"""The collision MLP's answers against the exact checker's: four kinds, their counts, where the mistakes lie and
the ROC curve (paper §III-B, Table 2; notebook 03).

The learned checker calls a configuration valid when P(valid) >= a threshold; against the truth each answer is
one of the four kinds of ``ANSWERS`` (:func:`answer_codes`): valid kept and invalid rejected are right, a valid
configuration rejected is a conservative mistake (it costs a sample), an invalid one kept a dangerous one (a
configuration in collision that a planner would trust). :func:`confusion_counts` counts them,
:func:`mistakes_near_boundary` says how many mistakes lie beside the true C-obstacle's boundary on a map of a
slice, and :func:`roc_points` sweeps the threshold. The figures of :mod:`toolkit.plots.classifier` draw them.
"""

from __future__ import annotations

import numpy as np

ANSWERS = ("valid kept", "valid rejected", "invalid rejected", "invalid kept (dangerous)")  # answer_codes 0-3


def answer_codes(predicted_valid, valid) -> np.ndarray:
    """Each answer's index in ``ANSWERS``: 0 valid kept, 1 valid rejected, 2 invalid rejected, 3 invalid kept."""
    pred, truth = np.asarray(predicted_valid, dtype=bool), np.asarray(valid, dtype=bool)
    if pred.shape != truth.shape:
        raise ValueError(f"predictions {pred.shape} and truth {truth.shape} must have the same shape")
    return np.where(truth, np.where(pred, 0, 1), np.where(pred, 3, 2))


def confusion_counts(predicted_valid, valid) -> dict[str, int]:
    """How many answers of each kind in ``ANSWERS``: valid kept, valid rejected, invalid rejected, invalid kept."""
    counts = np.bincount(answer_codes(predicted_valid, valid).ravel(), minlength=len(ANSWERS))
    return dict(zip(ANSWERS, counts.tolist()))


def mistakes_near_boundary(predicted_valid, valid, cells: int = 1) -> tuple[int, float]:
    """Wrong answers on a map ``(nx, ny)``, and the share of them near a boundary of the true C-obstacle: within
    ``cells`` steps (left, right, down, up) of a cell of the other truth, or of the map's edge (the swept bounds,
    where a robot placed in the region meets its walls). A model that has learned the obstacles errs there only,
    where a configuration is a hair's breadth from a block or a wall; mistakes elsewhere mean it has not."""
    truth = np.asarray(valid, dtype=bool)
    if truth.ndim != 2 or np.shape(predicted_valid) != truth.shape:
        raise ValueError(f"a map of predictions {np.shape(predicted_valid)} and one of truth {truth.shape} (nx, ny)")
    if cells < 1:
        raise ValueError(f"cells must be 1 or more, got {cells}")
    wrong = np.asarray(predicted_valid, dtype=bool) != truth  # (nx, ny) valid rejected or invalid kept
    padded = np.pad(truth, 1, mode="edge")  # (nx + 2, ny + 2): the map's edge counts as a boundary below
    inside = padded[1:-1, 1:-1]
    near = (padded[:-2, 1:-1] != inside) | (padded[2:, 1:-1] != inside)
    near |= (padded[1:-1, :-2] != inside) | (padded[1:-1, 2:] != inside)
    near[[0, -1], :] = near[:, [0, -1]] = True  # (nx, ny) beside the other truth, or on the map's edge
    for _ in range(cells - 1):  # grow by one step a round
        grown = np.pad(near, 1)
        near = near | grown[:-2, 1:-1] | grown[2:, 1:-1] | grown[1:-1, :-2] | grown[1:-1, 2:]
    return int(wrong.sum()), float((wrong & near).sum() / max(1, wrong.sum()))


def roc_points(probability, valid, thresholds=None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(thresholds, FPR, TPR)`` of "valid when P(valid) >= t": FPR = invalid kept share = 1 - TNR.

    Default thresholds: every distinct probability and +inf, so the curve runs from
    (1, 1) to (0, 0) through every point a threshold can reach.
    """
    p, truth = np.asarray(probability, dtype=float).ravel(), np.asarray(valid, dtype=bool).ravel()
    if not truth.any() or truth.all():
        raise ValueError("an ROC curve needs both valid and invalid configurations")
    ts = np.append(np.unique(p), np.inf) if thresholds is None else np.asarray(thresholds, dtype=float)

    def kept(q):  # how many of q are >= each threshold
        return len(q) - np.searchsorted(np.sort(q), ts, side="left")

    return ts, kept(p[~truth]) / (~truth).sum(), kept(p[truth]) / truth.sum()
