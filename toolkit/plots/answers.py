"""The collision MLP's answers against the exact checker's: four kinds, their counts, where the mistakes lie and
the ROC curve, and all of these in words for the figures' descriptions (paper §III-B, Table 2; notebook 03).

The learned checker calls a configuration valid when P(valid) >= a threshold; against the truth each answer is
one of the four kinds of ``ANSWERS`` (:func:`answer_codes`): valid kept and invalid rejected are right, a valid
configuration rejected is a conservative mistake (it costs a sample), an invalid one kept a dangerous one (a
configuration in collision that a planner would trust). :func:`confusion_counts` counts them,
:func:`mistakes_near_boundary` says how many mistakes lie beside the true C-obstacle's boundary on a map of a
slice, and :func:`roc_points` sweeps the threshold. :func:`draw_rates` and :func:`draw_roc` draw the rates and
the ROC curve on an axes; the figures of :mod:`toolkit.plots.classifier` are made of them.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from toolkit.learning import metrics
from toolkit.plots.alt import Part, map_part
from toolkit.plots.palette import CATEGORICAL, COLORS, HATCHES, LINE_COLORS
from toolkit.plots.slices import CSpaceSlice

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


def best_balanced(probability, valid) -> tuple[float, float]:
    """``(balanced accuracy, threshold)``: the best (TPR + TNR) / 2 over every threshold :func:`roc_points` reaches
    (reader r49c: "no threshold fixes it" read with the page's own measure)."""
    ts, fpr, tpr = roc_points(probability, valid)
    balanced = (tpr + 1 - fpr) / 2
    best = int(np.argmax(balanced))
    return float(balanced[best]), float(ts[best])


# -- the answers in words: the figures' longer descriptions ------------------------


def answers_in_words(predicted_valid, valid) -> str:
    """The four kinds of answer and the rates, in words (a figure's text alternative)."""
    counts = confusion_counts(predicted_valid, valid)
    rates = metrics.classification(np.ravel(predicted_valid), np.ravel(valid))
    said = ", ".join(f"{kind} {n}" for kind, n in counts.items())
    return f"{said}; accuracy {rates['acc']:.2f}, TPR {rates['tpr']:.2f}, TNR {rates['tnr']:.2f}"


def map_in_regions(name: str, said: str, probability, valid, grid: CSpaceSlice, threshold: float, extra=None) -> Part:
    """A P(valid) map read region by region (a part of a longer description, after ``said``): mean P(valid), the
    share truly in collision, the dangerous and conservative mistakes at ``threshold``; ``extra(region)`` adds to
    each cell."""
    probability, valid = np.asarray(probability), np.asarray(valid, dtype=bool)  # (nx, ny)
    codes = answer_codes(probability >= threshold, valid)  # (nx, ny)

    def region(cells: tuple[slice, slice]) -> str:
        c = codes[cells]
        text = f"P {np.mean(probability[cells]):.2f}, {np.mean(~valid[cells]):.0%} in collision, "
        text += f"{int(np.sum(c == 3))} dangerous, {int(np.sum(c == 1))} conservative"
        return text + (extra(cells) if extra else "")

    x, y = ((name, lo, hi) for name, lo, hi in zip(grid.names, grid.lower, grid.upper))
    text = f"{said}. The map by region, top row first: mean P(valid), the share truly in collision, the mistakes"
    return map_part(name, text, grid.shape, x, y, region)


def per_cell(points, grid: CSpaceSlice) -> np.ndarray:
    """How many of ``points (M, 2)`` (the grid's two DoFs) lie in each cell of its map: ``(nx, ny)``."""
    edges = [np.linspace(lo, hi, n + 1) for lo, hi, n in zip(grid.lower, grid.upper, grid.shape)]
    x, y = np.asarray(points, dtype=float).reshape(-1, 2).T  # (M,) each
    return np.histogram2d(x, y, bins=edges)[0]


def answer_tables(predicted_valid, valid) -> list[Part]:
    """The counts of the four kinds of answer and the rates, as tables (parts of a longer description)."""
    counts = confusion_counts(predicted_valid, valid)
    rates = metrics.classification(np.ravel(predicted_valid), np.ravel(valid))
    return [
        Part(
            "counts",
            "configurations of each kind of answer",
            ("answer", "count"),
            tuple((k, str(n)) for k, n in counts.items()),
        ),
        Part(
            "rates",
            "accuracy, TPR (valid kept) and TNR (in collision rejected)",
            ("rate", "value"),
            tuple(
                (name.upper() if name != "acc" else "accuracy", f"{rates[name]:.2f}") for name in ("acc", "tpr", "tnr")
            ),
        ),
    ]


RATE_SHADES = {"acc": 0, "tpr": 1, "tnr": 4}  # blue, orange, grey: CATEGORICAL's and HATCHES' entries (r47c: a
# sky-blue TNR bar read as the maps' sky blue, a conservative mistake)


def draw_rates(ax, scores: Mapping[str, Mapping[str, float]]) -> None:
    """Accuracy, TPR and TNR of each model in ``scores`` (``metrics.classification``'s keys) as bars, each bar's value
    written on it."""
    keys, labels = ("acc", "tpr", "tnr"), ("accuracy", "TPR (valid kept)", "TNR (invalid rejected)")
    x, width = np.arange(len(scores)), 0.8 / len(keys)
    for k, (key, label) in enumerate(zip(keys, labels)):
        shade = RATE_SHADES[key]
        bars = ax.bar(
            x + (k - 1) * width,
            [s[key] for s in scores.values()],
            width,
            color=CATEGORICAL[shade],
            hatch=HATCHES[shade],
            edgecolor=COLORS["ink"],
            linewidth=0.6,
            label=label,
        )
        ax.bar_label(bars, fmt="%.2f", fontsize=8, rotation=90 if len(scores) > 3 else 0, padding=2)  # upright: apart
    alone = len(scores) == 1 and not any(scores)  # one unnamed model: each bar named under it, no legend needed
    if alone:
        ax.set_xticks(x[0] + (np.arange(len(keys)) - 1) * width, labels, fontsize=9)
        ax.set_xlabel("measure")
    else:
        ax.set_xticks(x, list(scores), fontsize=8)
        ax.set_xlabel("model")
    ax.set_ylim(0, 1.35 if len(scores) <= 3 else 1.55)  # room for the labels and the legend above the bars
    ax.set_yticks(np.linspace(0, 1, 6))
    ax.set_ylabel("share")
    if not alone:
        ax.legend(fontsize=8, loc="upper center", ncols=2, frameon=False)


ROC_STYLES = (  # reader r45c: not the mistakes' marks (vermillion squares: dangerous, sky-blue circles: conservative);
    {"color": LINE_COLORS[2], "linestyle": "-", "marker": "v"},  # ink; r51c: not the threshold sweep's triangle and
    {"color": LINE_COLORS[4], "linestyle": "-.", "marker": "X"},  # reddish purple (r52c: green is the sweep's TPR);
    {"color": LINE_COLORS[3], "linestyle": ":", "marker": "P"},  # bluish green; diamond (TNR, TPR), nor §7's start
)
"""Each ROC curve's colour, line style and operating point's marker, in turn: none a mistake's colour or mark."""


def draw_roc(ax, curves: Mapping[str, tuple[np.ndarray, np.ndarray, float]]) -> str:
    """The ROC curves and their operating points (styles of :data:`ROC_STYLES`, never a mistake's mark); returns them
    in words."""
    ax.plot([0, 1], [0, 1], color=COLORS["reference"], linestyle="--", label="chance")
    said = []
    for i, (name, (probability, valid, threshold)) in enumerate(curves.items()):
        _, fpr, tpr = roc_points(probability, valid)
        auc = np.trapezoid(tpr[::-1], fpr[::-1])  # thresholds rise, so FPR falls: integrate left to right
        style = ROC_STYLES[i % len(ROC_STYLES)]
        label = f"{name + ': ' if name else ''}AUC {auc:.2f}"
        (line,) = ax.plot(fpr, tpr, label=label, **style | dict(marker="", linewidth=2.5))  # r27c: thin, a curve
        # along the frame (FPR 0, then TPR 1: a near-perfect model) could not be seen
        _, fpr_t, tpr_t = roc_points(probability, valid, [threshold])
        ax.plot(
            fpr_t,
            tpr_t,
            style["marker"],
            color=line.get_color(),
            markeredgecolor=COLORS["ink"] if i else COLORS["free"],  # a black mark ringed white on its black line
            markersize=11,  # r52c: at 8 the black mark hid on its black curve at page size
            markeredgewidth=1.5,
            label=f"{name + ' ' if name else ''}threshold {threshold:.2f}",
        )
        said.append(
            f"{name + ': ' if name else ''}area under the curve {auc:.2f}; at threshold {threshold:.2f} it keeps "
            f"{tpr_t[0]:.0%} of the valid configurations and {fpr_t[0]:.0%} of those in collision"
        )
    ax.set_xlabel("FPR: invalid kept\n(dangerous) = 1 - TNR")
    ax.set_ylabel("TPR: valid kept")
    ax.set_xlim(-0.06, 1.02)  # the frame inset from FPR 0 and TPR 1: a curve along them shows apart from it
    ax.set_ylim(-0.02, 1.06)
    ax.set_aspect("equal")
    ax.legend(fontsize=8, loc="lower right", handlelength=4.5)  # r55c: a whole dash-dot period shows in its handle
    return "; ".join(said)
