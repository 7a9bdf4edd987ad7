"""Figures of the collision MLP (paper §III-B, Table 2): where it says "valid", and where it is wrong (notebook 03).

The MLP answers P(valid) for a configuration; the learned checker calls it valid when
P(valid) >= a threshold. Against the exact checker each answer is one of four kinds
(:mod:`toolkit.plots.answers` codes, counts and sweeps them):

- *valid kept* and *invalid rejected*: right (TPR and TNR count them, as
  :func:`toolkit.learning.metrics.classification` does);
- *valid rejected* (a false invalid): a **conservative** mistake, it only costs a sample;
- *invalid kept* (a false valid): a **dangerous** mistake, a configuration in collision
  that the planner would trust, unless it checks its path exactly (``toolkit.planning.prm`` does).

The maps here sweep two degrees of freedom over their bounds (:func:`toolkit.plots.slices.slice_grid`;
the point robot's whole C-space, or a 2-DoF slice of a 3D robot with the other joints
fixed), show P(valid) as an image, draw the true C-obstacle boundary over it and mark
every mistake at its cell: dangerous ones as squares, conservative ones with a dotted hatch and no tint (review r14c:
a denser one hid P(valid) on the `paper` preset's map), circled where they lie in a strip too narrow for its dots.

>>> grid = slice_grid(robot, dofs=(0, 1), n=80)  # doctest: +SKIP
>>> probability = grid.image(checker.probability(grid.configs))  # (80, 80)  # doctest: +SKIP
>>> valid = grid.image(exact.are_valid(grid.configs))  # (80, 80)  # doctest: +SKIP
>>> probability_map(probability, valid, grid, threshold=checker.threshold)  # doctest: +SKIP
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.colors import ListedColormap
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from toolkit.learning import metrics
from toolkit.plots import answers
from toolkit.plots.alt import Part, describe
from toolkit.plots.answers import ANSWERS, answer_codes, confusion_counts, roc_points
from toolkit.plots.cell_marks import draw_cell_marks, draw_narrow_cells, fit_cell_marks
from toolkit.plots.palette import COLORS, GREY_CMAP, PAGE_WIDTH, halo
from toolkit.plots.robot_drawing import dof_label
from toolkit.plots.slices import CSpaceSlice

DANGEROUS, CONSERVATIVE, BOUNDARY = COLORS["dangerous"], COLORS["conservative"], COLORS["boundary"]
ANSWER_COLORS = (COLORS["free"], CONSERVATIVE, COLORS["occupied"], DANGEROUS)  # free white, obstacles dark
MISTAKE_MARKERS = {1: "o", 3: "s"}  # conservative dots, dangerous squares: the mistakes told without colour


def probability_map(
    probability, valid, grid: CSpaceSlice, *, threshold: float = 0.5, title: str = "P(valid)"
) -> Figure:
    """P(valid) over a 2-DoF grid ``(nx, ny)``, the true C-obstacle boundary, the mistakes at ``threshold`` marked
    (:func:`probability_maps` of one map)."""
    return probability_maps({title: probability}, valid, grid, thresholds=threshold)


def probability_maps(
    probabilities: Mapping[str, np.ndarray], valid, grid: CSpaceSlice, *, thresholds: float | Mapping[str, float] = 0.5
) -> Figure:
    """Several models' P(valid) maps, same grid and truth (e.g. the ``paper`` and ``strong`` presets), one above the
    other, each as wide as the page with a colour bar of its own, its threshold a line across it (review r16b: side by
    side, the one bar read as the right map's, and a one-cell strip of mistakes showed no dot)."""
    cut = {name: thresholds[name] if isinstance(thresholds, Mapping) else thresholds for name in probabilities}
    fig = Figure(figsize=(PAGE_WIDTH, 4.7 * len(cut) + 0.9), layout="constrained")  # r15c: at 230 px, a strip a pixel
    axes = fig.subplots(len(cut), 1, squeeze=False)[:, 0]
    said, parts = [], []
    for ax, (name, probability), t in zip(axes, probabilities.items(), cut.values()):
        image = _draw_probability(ax, probability, valid, grid, t)
        bar = fig.colorbar(image, ax=ax, label=f"P(valid); the line: threshold {t:.2f}", shrink=0.9)
        bar.ax.axhline(t, color=COLORS["ink"], linewidth=2.5, path_effects=halo(2.5, ("free",)))
        ax.set_title(f"{name}: P(valid), threshold {t:.2f}", fontsize=10)
        said.append(f"{name}, threshold {t:.2f}: " + answers.answers_in_words(np.asarray(probability) >= t, valid))
        parts.append(answers.map_in_regions(name, said[-1], probability, valid, grid, t))
    _legend(fig, _mistake_handles())
    fig.draw_without_rendering()  # laid out: a cell's size on the page, for the strips the dots would miss
    spacing, style = 72 / DOTS_PER_INCH, dict(label=f"{ANSWERS[1]}, narrow", zorder=3, **_mistake_mark(1))
    rejected = [(np.asarray(p) < cut[name]) & np.asarray(valid) for name, p in probabilities.items()]  # (nx, ny) each
    narrow = [draw_narrow_cells(ax, grid, mask, spacing, **style) for ax, mask in zip(axes, rejected)]
    k = fit_cell_marks(fig, grid)
    text = f"Map of P(valid) over {grid.names[0]} and {grid.names[1]} ({grid.shape[0]} x {grid.shape[1]} "
    text += "configurations; grey, 0 black to 1 white) with the true C-obstacle boundary outlined, dangerous "
    text += f"mistakes as squares{f' (one per {k} x {k} cells holding any)' if k > 1 else ''} and conservative ones "
    text += "hatched with dots" + (", circled in strips too narrow for the dots. " if any(narrow) else ". ")
    return describe(fig, text + "; ".join(said) + ".", parts)


def path_map(
    probability, valid, grid: CSpaceSlice, *, threshold: float, path, nodes, nodes_valid, title: str = ""
) -> Figure:
    """A planner's roadmap ``nodes (M, dof)`` and returned ``path (P, dof)`` over a P(valid) map of the grid's two DoFs.

    Nodes in collision (``nodes_valid`` False, by the exact checker) are the dangerous mistakes the planner accepted:
    large ink crosses ringed white, labelled. The path, checked exactly, avoids them; it is dashed with a
    diamond per configuration, so that it stands apart from the solid C-obstacle boundary. The model's threshold is a
    bold dotted line (P(valid) = threshold): the roadmap's dots on its dark side are nodes the model rejected, which
    the exact checker drew. The map's mistakes are not marked: no hatch dot passes for a node, no square buries a cross.
    """
    nodes, nodes_valid, path = np.asarray(nodes), np.asarray(nodes_valid, dtype=bool), np.asarray(path)
    fig = Figure(figsize=(6, 6.2), layout="constrained")
    ax = fig.subplots()
    image = _draw_probability(ax, probability, valid, grid, threshold, mistakes=False)
    fig.colorbar(image, ax=ax, label="P(valid)", shrink=0.8)
    p = _on_grid(probability, grid, "probability")
    if p.min() < threshold <= p.max():
        cut_line = ax.contour(*grid.axes, p.T, levels=[threshold], colors=COLORS["ink"], linestyles=":", linewidths=CUT)
        cut_line.set_path_effects(halo(CUT, ("free",)))  # a white ring: it shows on the dark side too
    cut = Line2D([], [], color=COLORS["ink"], linestyle=":", linewidth=CUT, label=f"P(valid) = {threshold:.2f}")
    x, y = grid.dofs
    _draw_roadmap(ax, nodes, nodes_valid, path, (x, y))
    ax.set_title(title or f"P(valid) at threshold {threshold:.2f}, roadmap and path", fontsize=10, wrap=True)
    _legend(fig, [cut] + ax.get_lines())
    fit_cell_marks(fig, grid)
    text = f"Map of the model's P(valid) over {grid.names[0]} and {grid.names[1]} (grey, 0 black to 1 white) with a"
    text += f" roadmap of {len(nodes)} nodes, {int(np.sum(~nodes_valid))} of them in collision (crosses), and the"
    text += f" returned path through {len(path)} configurations, checked exactly."
    per_cell = answers.per_cell(nodes[:, [x, y]], grid)  # (nx, ny) roadmap nodes in each cell of the map
    parts = [
        answers.map_in_regions(
            "P(valid) map",
            f"threshold {threshold:.2f}: " + answers.answers_in_words(np.asarray(probability) >= threshold, valid),
            probability,
            valid,
            grid,
            threshold,
            extra=lambda cells: f"; {int(per_cell[cells].sum())} roadmap nodes",
        ),
        Part(
            "returned path",
            f"its {len(path)} configurations in order, from start to goal",
            ("configuration", *grid.names),
            tuple((str(k), f"{q[x]:.3g}", f"{q[y]:.3g}") for k, q in enumerate(path)),
        ),
    ]
    return describe(fig, text, parts)


def confusion_bars(predicted_valid, valid, title: str = "") -> Figure:
    """The four kinds of answer as bars (dangerous ones in the invalid colour, last) and accuracy / TPR / TNR."""
    fig = Figure(figsize=(PAGE_WIDTH, 5.6), layout="constrained")
    ax_counts, ax_rates = fig.subplots(2, 1, height_ratios=(1.2, 1))  # one above the other: the page's width each
    _draw_counts(ax_counts, predicted_valid, valid)
    answers.draw_rates(ax_rates, {"": metrics.classification(np.ravel(predicted_valid), np.ravel(valid))})
    fig.suptitle(title or "Predictions against the exact checker")
    text = f"{title or 'Predictions against the exact checker'}: " + answers.answers_in_words(predicted_valid, valid)
    return describe(fig, text + ".", answers.answer_tables(predicted_valid, valid))


def metrics_bars(scores: Mapping[str, Mapping[str, float]], title: str = "") -> Figure:
    """Accuracy, TPR and TNR of several models or baselines (``{name: {"acc", "tpr", "tnr"}}``), grouped."""
    fig = Figure(figsize=(min(PAGE_WIDTH, 1.6 + 1.6 * len(scores)), 3.8), layout="constrained")
    answers.draw_rates(fig.subplots(), scores)
    fig.suptitle(title or "Accuracy, TPR (valid kept), TNR (invalid rejected)")
    said = "; ".join(
        f"{name}: accuracy {s['acc']:.2f}, TPR {s['tpr']:.2f}, TNR {s['tnr']:.2f}" for name, s in scores.items()
    )
    text = f"{title + '. ' if title else ''}Bars of accuracy, TPR (the share of valid configurations kept) and TNR"
    return describe(fig, f"{text} (the share in collision rejected). {said}.")


def roc_curve(curves: Mapping[str, tuple[np.ndarray, np.ndarray, float]], title: str = "") -> Figure:
    """ROC curves of ``{name: (P(valid), valid, threshold)}``, each with its operating point at ``threshold``."""
    fig = Figure(figsize=(4.2, 4.2), layout="constrained")
    said = answers.draw_roc(fig.subplots(), curves)
    fig.suptitle(title or "ROC: valid kept against invalid kept", fontsize=10)
    text = "ROC curves: the share of valid configurations kept against the share in collision kept, as the threshold"
    return describe(fig, f"{text} moves; the diagonal is chance. {said}.")


def threshold_view(probability, valid, grid: CSpaceSlice, *, threshold: float, title: str = "") -> Figure:
    """One threshold three ways: the decision map (each cell coloured by its kind of answer), the counts, the ROC."""
    predicted = np.asarray(probability) >= threshold
    fig = Figure(figsize=(6.2, 6.8), layout="constrained")  # two rows, as wide as a chapter page's column
    grid_spec = fig.add_gridspec(2, 2, height_ratios=(1.4, 1), width_ratios=(1.6, 1))  # the map large: its marks small
    ax_map, ax_counts, ax_roc = (fig.add_subplot(grid_spec[where]) for where in ((0, 0), (1, slice(None)), (0, 1)))
    _draw_decision(ax_map, predicted, valid, grid)
    ax_map.set_title(f"decision at threshold {threshold:.2f}\na mark per cell holding a mistake", fontsize=9)
    _draw_counts(ax_counts, predicted, valid)
    roc = answers.draw_roc(ax_roc, {"": (probability, valid, threshold)})
    fig.suptitle(title)
    cells = [Patch(facecolor=c, edgecolor=COLORS["ink"]) for c in ANSWER_COLORS]
    handles: list[Any] = [  # a mistake's cell with its mark on it
        (cell, Line2D([], [], linestyle="", **_mistake_mark(code, legend=True))) if code in MISTAKE_MARKERS else cell
        for code, cell in enumerate(cells)
    ]
    boundary = Line2D([], [], color=BOUNDARY, path_effects=halo(1.2))
    k = fit_cell_marks(fig, grid)  # the mistakes' marks as large as one sees, over their cells and the boundary
    block = f" (one per {k} x {k} cells holding any)" if k > 1 else ""
    if k > 1:  # the marks are fewer than the mistakes the bars count: the map says why (as tall a title: same layout)
        ax_map.set_title(
            f"decision at threshold {threshold:.2f}\na mark per {k} x {k} cells holding a mistake", fontsize=9
        )
    labels = [
        "true C-obstacle boundary",
        ANSWERS[0],
        f"{ANSWERS[1]} (dots)",
        ANSWERS[2],
        "invalid kept (dangerous, squares)",
    ]
    fig.legend([boundary, *handles], labels, loc="outside lower center", ncols=3, fontsize=8, frameon=False)
    text = f"{title + ': ' if title else ''}the model's decision at threshold {threshold:.2f} over {grid.names[0]} and "
    text += f"{grid.names[1]}, each cell by its kind of answer, the mistakes marked over their cells and the boundary"
    text += f"{block}: dangerous ones with squares, conservative ones with dots; their counts, and the ROC curve. "
    text += f"{answers.answers_in_words(predicted, valid)}; {roc}."
    cut, fpr, tpr = roc_points(probability, valid, np.linspace(0.0, 1.0, 11))  # (11,) each
    curve = Part(
        "ROC curve",
        roc,
        ("threshold", "valid kept (TPR)", "in collision kept (1 - TNR)"),
        tuple((f"{t:.1f}", f"{a:.2f}", f"{b:.2f}") for t, a, b in zip(cut, tpr, fpr)),
    )
    decision = answers.map_in_regions(
        "decision map", answers.answers_in_words(predicted, valid), probability, valid, grid, threshold
    )
    return describe(fig, text, [decision, *answers.answer_tables(predicted, valid)[:1], curve])


# -- the panels ----------------------------------------------------------------


def _draw_probability(ax, probability, valid, grid: CSpaceSlice, threshold: float, *, mistakes=True):
    """P(valid) ``(nx, ny)`` in gray (0 black, 1 white), the boundary and, with ``mistakes``, dangerous cells as squares
    and conservative cells hatched with dots (:func:`_cells`; :data:`DOTS_PER_INCH`, on a map as wide as the page: a
    strip narrower than their spacing :func:`probability_maps` circles)."""
    probability = _on_grid(probability, grid, "probability")
    image = ax.imshow(
        probability.T,
        origin="lower",
        extent=grid.extent,
        cmap=GREY_CMAP,
        vmin=0,
        vmax=1,
        aspect="auto",
        interpolation="nearest",
    )
    _draw_boundary(ax, valid, grid)
    codes = answer_codes(probability >= threshold, _on_grid(valid, grid, "valid"))
    if mistakes:
        ax.add_collection(_cells(grid, codes == 1, **UNDER_HATCH))
        ax.add_collection(_cells(grid, codes == 1, label=ANSWERS[1], **CONSERVATIVE_CELLS))
        draw_cell_marks(ax, grid, codes == 3, label=ANSWERS[3], zorder=3, **_mistake_mark(3))  # fit_cell_marks sizes
    return image


CUT = 2.5  # points: the path map's dotted line at the model's threshold, bold enough to follow across the map
DOTS_PER_INCH = 12  # the conservative hatch "..": sparse enough that the grey between the dots is P(valid) (r14c)
CONSERVATIVE_CELLS: dict[str, Any] = dict(  # ink dots, no tint: the grey between them is P(valid)
    facecolor="none", hatch="..", hatchcolor=COLORS["ink"], edgecolor="none"
)
UNDER_HATCH: dict[str, Any] = dict(  # the same dots in white, wider, under the ink ones: they show on the darkest grey
    facecolor="none", hatch="..", hatchcolor=COLORS["free"], hatch_linewidth=2.0, edgecolor="none"
)


def _cells(grid: CSpaceSlice, mask, **style) -> PolyCollection:
    """One square per cell of ``grid`` where ``mask (nx, ny)`` holds, drawn as one collection (adjacent cells' hatches
    join into one pattern)."""
    i, j = np.nonzero(mask)
    half = [(axis[1] - axis[0]) / 2 if len(axis) > 1 else 0.5 for axis in grid.axes]
    corners = np.array([(-1, -1), (1, -1), (1, 1), (-1, 1)]) * half  # (4, 2)
    centres = np.column_stack([grid.axes[0][i], grid.axes[1][j]])  # (n, 2)
    return PolyCollection(centres[:, None, :] + corners[None], linewidths=0, **style)  # (n, 4, 2) squares


def _draw_roadmap(ax, nodes: np.ndarray, nodes_valid: np.ndarray, path: np.ndarray, dofs: tuple[int, int]) -> None:
    """A roadmap's valid nodes as dots, those in collision as crosses, and the path dashed with diamonds, over a map
    of the two ``dofs``."""
    x, y = dofs
    dots = dict(color=COLORS["node"], markersize=4, label="roadmap node, valid", path_effects=halo(0.5, ("free",)))
    ax.plot(nodes[nodes_valid, x], nodes[nodes_valid, y], ".", **dots)
    ax.plot(
        nodes[~nodes_valid, x],
        nodes[~nodes_valid, y],
        "X",
        color=COLORS["ink"],  # not the dangerous squares' colour: on another map it would sit among them
        markersize=14,
        label="roadmap node in collision",
        path_effects=halo(1.0, ("free",)),  # a white ring: it shows on the dark side of the map too
        zorder=7,  # over the path (5): the one mark that must not be missed
    )
    for node in nodes[~nodes_valid][:3]:  # a few named in words as well
        ax.annotate(
            "in collision",
            node[[x, y]],
            xytext=(12, 12),
            textcoords="offset points",
            fontsize=9,
            zorder=7,
            bbox=dict(boxstyle="round,pad=0.2", fc=COLORS["free"], ec=COLORS["ink"], lw=0.6),
        )
    ax.plot(
        path[:, x],
        path[:, y],
        "--D",  # dashed, a diamond per configuration: apart from the solid C-obstacle boundary, same blue
        markevery=slice(1, -1),  # the ends have marks of their own: no diamond's corners peek out from under them
        color=COLORS["path"],
        linewidth=3,
        markersize=7,
        label="returned path (checked exactly)",
        path_effects=halo(2.5),
        clip_on=False,  # whole where it ends on the map's edge
    )
    for end, marker, size, name in ((0, "s", 11, "start"), (-1, "*", 20, "goal")):  # as chapter 04's roadmaps
        ax.plot(
            path[end, x],
            path[end, y],
            marker,
            color=COLORS["endpoint"],
            markeredgecolor=COLORS["free"],
            markersize=size,
            label=name,
            clip_on=False,  # whole on the map's edge, over the frame
            zorder=5,
            path_effects=halo(0.0, ("ink",)),  # black, a white edge, a black ring: its whole shape shows on the
        )  # map's dark side, on its light side and on the white beyond the frame


def _draw_decision(ax, predicted_valid, valid, grid: CSpaceSlice):
    """Each cell coloured by its kind of answer (``ANSWER_COLORS``), and the boundary."""
    codes = answer_codes(_on_grid(predicted_valid, grid, "predictions"), _on_grid(valid, grid, "valid"))
    image = ax.imshow(
        codes.T,
        origin="lower",
        extent=grid.extent,
        cmap=ListedColormap(ANSWER_COLORS),
        vmin=-0.5,
        vmax=len(ANSWERS) - 0.5,
        aspect="auto",
        interpolation="nearest",
    )
    _draw_boundary(ax, valid, grid)
    for code in MISTAKE_MARKERS:  # each mistake marked in its colour and shape, over the boundary's ringed line
        draw_cell_marks(ax, grid, codes == code, label=ANSWERS[code], zorder=3, **_mistake_mark(code))
    return image


def _mistake_mark(code: int, *, legend: bool = False) -> dict[str, Any]:
    """The mark of a mistake of answer ``code`` (1 conservative, 3 dangerous): its colour in a black, then a white
    ring (:data:`MARK_RING`: it stands out on white, on the obstacles' dark grey, on any grey of P(valid) between
    and on its own cell's colour); scatter's options, or a legend line's."""
    color = ANSWER_COLORS[code]
    if legend:
        return dict(marker=MISTAKE_MARKERS[code], color=color, markeredgecolor=COLORS["ink"], path_effects=halo(0.0))
    return dict(c=color, marker=MISTAKE_MARKERS[code], linewidths=0, path_effects=halo(MARK_RING), clip_on=False)


MARK_RING = 1.0  # points: a mistake's black ring 1.3 points wide (2 pixels on the site), its white one 0.8 beyond


def _draw_boundary(ax, valid, grid: CSpaceSlice) -> None:
    """The true C-obstacle boundary: the 0.5 contour of the exact checker's answers; axis names."""
    valid = _on_grid(valid, grid, "valid")
    if valid.any() and not valid.all():
        contour = ax.contour(*grid.axes, valid.T.astype(float), levels=[0.5], colors=BOUNDARY, linewidths=1.2)
        contour.set_path_effects(halo(1.2))
    ax.set_xlabel(dof_label(grid.names[0]))  # an angle with its unit, radians
    ax.set_ylabel(dof_label(grid.names[1]))


def _on_grid(values, grid: CSpaceSlice, name: str) -> np.ndarray:
    values = np.asarray(values, dtype=bool if name != "probability" else float)
    if values.shape != grid.shape:
        raise ValueError(f"{name} has shape {values.shape}, the grid {grid.shape}")
    return values


def _mistake_handles() -> list:
    dangerous: dict[str, Any] = dict(color=DANGEROUS, marker="s", markeredgecolor=COLORS["ink"], linestyle="")
    return [
        Line2D([], [], label="dangerous: kept, in collision (squares)", **dangerous),
        Patch(label="conservative: rejected, free (dotted;\nright answers carry no dots)", **CONSERVATIVE_CELLS),
        Line2D(
            [],
            [],
            linestyle="",
            label="conservative, in a strip too\nnarrow for dots (circles)",
            **_mistake_mark(1, legend=True),
        ),
    ]


def _legend(fig: Figure, handles: list) -> None:
    handles = [Line2D([], [], color=BOUNDARY, label="true C-obstacle boundary", path_effects=halo(1.2)), *handles]
    ncols = len(handles) if fig.get_figwidth() >= 9 else 2
    fig.legend(handles=handles, loc="outside lower center", ncols=ncols, fontsize=9, frameon=False)


def _draw_counts(ax, predicted_valid, valid) -> None:
    counts = confusion_counts(predicted_valid, valid)
    bars = ax.bar(range(len(counts)), list(counts.values()), color=ANSWER_COLORS, edgecolor=COLORS["ink"])
    ax.bar_label(bars, fontsize=9, padding=2)
    ax.set_ylim(0, 1.18 * max(max(counts.values()), 1))  # room above the tallest bar for its count, inside the frame
    ax.set_xticks(range(len(counts)), [a.replace(" ", "\n", 1) for a in ANSWERS], fontsize=9)
    ax.set_xlabel("answer")
    ax.set_ylabel("configurations")
    rates = metrics.classification(np.ravel(predicted_valid), np.ravel(valid))
    ax.set_title(f"accuracy {rates['acc']:.2f}, TPR {rates['tpr']:.2f}, TNR {rates['tnr']:.2f}", fontsize=9)
