"""The paper's measures (§V): CAE reconstruction accuracy (Table 1); MLP accuracy, TPR, TNR (Table 2).

TPR is the share of truly valid configurations predicted valid, TNR the share of
truly invalid ones predicted invalid (false negative rate = 1 - TPR, false positive
rate = 1 - TNR). :func:`threshold_sweep` scores one model's P(valid) at every threshold of :data:`SWEEP`.
"""

from __future__ import annotations

import numpy as np


def classification(predicted_valid, valid) -> dict[str, float]:
    """``{"acc", "tpr", "tnr"}`` of boolean predictions against boolean truth, both ``(N,)``.

    A rate whose class is absent (no valid, or no invalid, configurations) is NaN.
    """
    pred, truth = np.asarray(predicted_valid, dtype=bool), np.asarray(valid, dtype=bool)
    if pred.shape != truth.shape or pred.ndim != 1 or len(pred) == 0:
        raise ValueError(f"predictions {pred.shape} and labels {truth.shape} must be equal, non-empty 1-D arrays")
    return {
        "acc": float(np.mean(pred == truth)),
        "tpr": float(np.mean(pred[truth])) if truth.any() else float("nan"),
        "tnr": float(np.mean(~pred[~truth])) if (~truth).any() else float("nan"),
    }


SWEEP = np.linspace(0.0, 1.0, 101)  # (101,) the thresholds a sweep tries: 0, 0.01, ..., 1


def threshold_sweep(probability, valid, thresholds: np.ndarray = SWEEP) -> dict[str, np.ndarray]:
    """``{"acc", "tpr", "tnr"}``, each ``(T,)``: :func:`classification` of ``probability (N,) >= t`` against ``valid
    (N,)`` at every threshold ``t`` of ``thresholds (T,)`` (one sweep, drawn and described from the same numbers)."""
    p, truth = np.asarray(probability, dtype=float), np.asarray(valid, dtype=bool)
    if p.shape != truth.shape or p.ndim != 1 or len(p) == 0:
        raise ValueError(f"probability {p.shape} and valid {truth.shape} must be equal, non-empty (N,) arrays")
    predicted = p[None, :] >= np.asarray(thresholds, dtype=float)[:, None]  # (T, N)
    nan = np.full(len(predicted), np.nan)
    return {
        "acc": (predicted == truth).mean(axis=1),
        "tpr": predicted[:, truth].mean(axis=1) if truth.any() else nan,
        "tnr": (~predicted[:, ~truth]).mean(axis=1) if (~truth).any() else nan,
    }


def reconstruction_accuracy(reconstructed, grids) -> np.ndarray:
    """``(W,)`` share of each grid's cells whose sign the reconstruction gets right (grids of -1 / +1)."""
    rec, x = np.asarray(reconstructed), np.asarray(grids)
    if rec.shape != x.shape or rec.ndim < 2:
        raise ValueError(f"reconstructions {rec.shape} and grids {x.shape} must be equal arrays (W, *grid)")
    match = np.sign(rec) == np.sign(x)
    return match.reshape(len(x), -1).mean(axis=1)


def what_it_answers(tpr: float, tnr: float) -> str:
    """What a classifier with these rates on a test amounts to, read at the printed precision (whole percent):
    '"valid" to every sample' (keeps every valid one, rejects no colliding one), '"invalid" to every sample', or
    "some of each"."""
    keeps, rejects = round(100 * tpr), round(100 * tnr)
    if (keeps, rejects) == (100, 0):
        return '"valid" to every sample'
    if (keeps, rejects) == (0, 100):
        return '"invalid" to every sample'
    return "some of each"
