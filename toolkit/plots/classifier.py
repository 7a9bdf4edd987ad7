"""Figures of the collision MLP (paper §III-B, Table 2): where it says "valid", and where it is wrong (notebook 03).

The MLP answers P(valid) for a configuration; the learned checker calls it valid when P(valid) >= a threshold.
Against the exact checker each answer is one of four kinds (:mod:`toolkit.plots.answers` codes, counts and sweeps them):

- *valid kept* and *invalid rejected*: right (TPR and TNR count them: :func:`toolkit.learning.metrics.classification`);
- *valid rejected* (a false invalid): a **conservative** mistake, it only costs a sample;
- *invalid kept* (a false valid): a **dangerous** mistake, a configuration in collision that the planner would trust,
  unless it checks its path exactly (``toolkit.planning.prm`` does).

The maps here sweep two degrees of freedom over their bounds (:func:`toolkit.plots.slices.slice_grid`; the point
robot's whole C-space, or a 2-DoF slice of a 3D robot with the other joints fixed), show P(valid) as an image, draw the
true C-obstacle boundary over it and mark every mistake at its cell: dangerous ones as squares, conservative ones as
circles, a mark per block of cells holding any where the map is fine, spaced so that the grey between them is P(valid)
(review r18b: a hatch of dots hid it on the `paper` preset's map) and the squares can be counted; each map's title
counts both kinds.

>>> grid = slice_grid(robot, dofs=(0, 1), n=80)  # doctest: +SKIP
>>> probability = grid.image(checker.probability(grid.configs))  # (80, 80)  # doctest: +SKIP
>>> probability_map(probability, grid.image(exact.are_valid(grid.configs)), grid, threshold=0.5)  # doctest: +SKIP
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.colors import ListedColormap, to_rgb
from matplotlib.figure import Figure
from matplotlib.legend_handler import HandlerLine2D
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from toolkit.learning import metrics
from toolkit.plots import answers, cell_marks
from toolkit.plots.alt import Part, describe
from toolkit.plots.answers import ANSWERS, answer_codes, confusion_counts, roc_points
from toolkit.plots.cell_marks import draw_cell_hatch, draw_cell_marks, draw_cell_outline, fit_cell_marks
from toolkit.plots.mark_sides import fit_on_cells, labels_clear_of, marks_counted, on_cells, place_on_cells
from toolkit.plots.palette import COLORS, GREY_CMAP, PAGE_WIDTH, halo
from toolkit.plots.robot_drawing import POSITION_NAMES, dof_label
from toolkit.plots.slices import CSpaceSlice

DANGEROUS, CONSERVATIVE, BOUNDARY = COLORS["dangerous"], COLORS["conservative"], COLORS["boundary"]
ANSWER_COLORS = (COLORS["free"], CONSERVATIVE, COLORS["occupied"], DANGEROUS)  # free white, obstacles dark
MISTAKE_MARKERS = {1: "o", 3: "s"}  # conservative circles, dangerous squares: the mistakes told without colour
CUT = 2.5  # points: the path map's dotted line at the model's threshold, bold enough to follow across the map (r15c)
END_CLEAR = 0.06  # of a map's width: a path's diamond nearer an end than this is left out, the end's mark beside it
OUTLINE = 1.2  # points: the true C-obstacle boundary's line, its black and white rings 1.6 points wider each
CUT_MAP = OUTLINE + 1.6  # a map's line: under the outline, as wide as it with its dark ring, so that where the model
# is right it hides under the outline and shows only where it leaves it (r44c: wider, its dots stuck out a cell on
# each side and read as running through the cells beside the outline; r31c: drawn over the outline, it beaded)
ZORDER = {1: 2.8, 3: 3.0}  # over the lines (2: the boundary), squares over circles (r29c: circles under the outlines
# were half hidden; r10b, r11: a square under its ringed line was cut in two)
PITCH = {1: 40.0, 3: 14.0}  # points between two marks' centres, at least: conservative circles sparse (the grey between
# them is P(valid)), dangerous squares apart, a gap between their rings (r18b: a pile of them could not be counted)
HATCH = COLORS["c_obstacle"]  # the C-obstacles' hatch on a P(valid) map: light, seen on its black and its greys
TINT = {1: 0.08, 3: 0.6}  # wrong cells tinted in their colour: conservative light, its grey read (r41c, r44c)
DARK = 0.25  # P(valid) under which a conservative cell is filled sky blue, its light tint unseen on the dark grey
UNDER = f"its cell filled\nsky blue if P(valid) < {DARK}"  # the circles' legend (r60c: not the circle's fill)
BLOCKS = {1: 5, 3: 10}  # tiles a side on every map: a 100-cell map's circles one per 20 x 20 cells, squares 10 x 10


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
    side, the one bar read as the right map's), its mistakes counted in its title."""
    cut = {name: thresholds[name] if isinstance(thresholds, Mapping) else thresholds for name in probabilities}
    fig = Figure(figsize=(PAGE_WIDTH, 4.8 * len(cut) + 1.0))  # r15c: at 230 px, a strip a pixel
    fig.set_layout_engine("constrained", hspace=0.12)  # r26c: the first map's "x" met the second's title; r27c: an
    # h_pad that kept them apart left a blank band between a map and its legend
    axes = fig.subplots(len(cut), 1, squeeze=False)[:, 0]
    said, parts = [], []
    for ax, (name, probability), t in zip(axes, probabilities.items(), cut.values()):
        image = _draw_probability(ax, probability, valid, grid, t)
        ax.set_box_aspect(1)  # square, as section 4's decision map (reader r33c: 2DS's square drawn 32 % wide)
        bar = fig.colorbar(image, ax=ax, label=f"P(valid); the line: threshold {t:.2f}", shrink=0.9)
        bar.ax.axhline(t, linewidth=2.5, color=COLORS["free"], path_effects=halo(2.5, ("ink",)))  # r41c: white dots
        said.append(f"{name}, threshold {t:.2f}: " + answers.answers_in_words(np.asarray(probability) >= t, valid))
        parts.append(answers.map_in_regions(name, said[-1], probability, valid, grid, t))
    blocks = fit_on_cells(fig, grid)  # laid out: each kind's marks one per k x k cells holding any, on one of them
    k = {code: blocks.get(ANSWERS[code], 1) for code in MISTAKE_MARKERS}
    for ax, (name, probability), t in zip(axes, probabilities.items(), cut.values()):  # the marks counted (r34c)
        tiles = marks_counted(confusion_counts(np.asarray(probability) >= t, valid), ax, k)
        ax.set_title(f"{name}: P(valid), threshold {t:.2f}, {tiles}", fontsize=10)  # r36c: "64% of the map wrong"
    _legend(fig, _mistake_handles(k))  # under the maps, read after them (r37c: above, a screen from the maps)
    place_on_cells(fig, grid, blocks)  # again, the maps as the legend left them (r34c)
    per = {code: f" (one per {n} x {n} cells holding any)" if n > 1 else "" for code, n in k.items()}
    text = f"Map of P(valid) over {grid.names[0]} and {grid.names[1]} ({grid.shape[0]} x {grid.shape[1]} "
    text += "configurations; grey, 0 black to 1 white; obstacle cells kept tinted vermillion, their squares' colour; "
    text += f"free cells rejected marked by circles, filled sky blue below P(valid) {DARK}) with the true C-obstacles "
    text += "outlined and hatched, the threshold's contour dotted (hidden under an outline where it runs along one), "
    text += "dangerous mistakes as squares"
    text += f"{per[3]} and conservative ones as circles"
    rule = f"a square per {k[3]} x {k[3]}-cell tile holding dangerous cells, a circle per {k[1]} x {k[1]}-cell tile "
    rule += "holding conservative ones, each drawn on one of its tile's mistake cells (the one nearest their centroid)"
    return describe(fig, text + f"{per[1]}. " + "; ".join(said) + ".", [Part("marks", rule), *parts])


def path_map(
    probability, valid, grid: CSpaceSlice, *, threshold: float, path, nodes, nodes_valid, title: str = "", edges=None
) -> Figure:
    """A planner's roadmap ``nodes (M, dof)`` and returned ``path (P, dof)`` over a P(valid) map of the grid's two DoFs.

    Nodes in collision (``nodes_valid`` False, by the exact checker) are the dangerous mistakes the planner accepted:
    vermillion plus signs, labelled (w41c: not a map's square, a tile of dangerous cells); the start a triangle.
    The path, checked exactly, avoids them; it is dashed with a diamond per configuration (none beside an
    end), to stand apart from the solid C-obstacle boundary. The model's threshold is a bold dotted line (P(valid) =
    threshold): the roadmap's dots on its dark side are nodes the model rejected, which the exact checker drew. The
    map's mistakes are not marked: no square of theirs passes for a node. ``edges (E, 2)``, node indices: the roadmap's
    edges, thin ink lines.
    """
    nodes, nodes_valid, path = np.asarray(nodes), np.asarray(nodes_valid, dtype=bool), np.asarray(path)
    fig = Figure(figsize=(6, 6.2), layout="constrained")
    ax = fig.subplots()
    image = _draw_probability(ax, probability, valid, grid, threshold, mistakes=False, cut=CUT)
    bar = fig.colorbar(image, ax=ax, label=f"P(valid); the line: threshold {threshold:.2f}", shrink=0.8)  # r40c
    bar.ax.axhline(threshold, lw=CUT, color=COLORS["free"], path_effects=halo(CUT, ("ink",)))  # as the maps' (r34c)
    cut = _dots(f"P(valid) = {threshold:.2f}")  # r42c: as the maps' legends
    x, y = grid.dofs
    _draw_roadmap(ax, nodes, nodes_valid, path, (x, y), edges)
    ax.set_title(title or f"P(valid) at threshold {threshold:.2f}, roadmap and path", fontsize=10, wrap=True)
    _legend(fig, [(line, line.get_label()) for line in [cut, *ax.get_lines()] if line.get_label() != "_hair"])
    fit_cell_marks(fig, grid)
    labels_clear_of(ax, grid, grid.on_grid(valid, "valid") & (np.asarray(probability) < threshold), "in collision")
    text = f"Map of the model's P(valid) over {grid.names[0]} and {grid.names[1]} (grey, 0 black to 1 white) with a"
    text += f" roadmap of {len(nodes)} nodes, {int(np.sum(~nodes_valid))} in collision (a plus sign each), and the"
    text += f" returned path through {len(path)} configurations (yellow, dashed, diamonds), checked exactly."
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


def metrics_bars(scores: Mapping[str, Mapping[str, float]], title: str = "") -> Figure:
    """Accuracy, TPR and TNR of several models or baselines (``{name: {"acc", "tpr", "tnr"}}``), grouped, each group's
    balanced accuracy, (TPR + TNR) / 2, printed under it (reader r29c: the measure to read; r41c: a dashed line at it
    ran through the bars' values)."""
    fig = Figure(figsize=(min(PAGE_WIDTH, 1.6 + 1.6 * len(scores)), 3.4), layout="constrained")
    answers.draw_rates(ax := fig.subplots(), scores)
    balanced = [(s["tpr"] + s["tnr"]) / 2 for s in scores.values()]
    if any(scores):  # each group's balanced accuracy named under it (r30c)
        ax.set_xticks(
            np.arange(len(scores)), [f"{name}\nbal. acc. {b:.2f}" for name, b in zip(scores, balanced)], fontsize=8
        )
        ax.set_ylim(0, 1.32)  # r41c: a third of the frame was legend room; the values upright over 1.00, one legend row
    ax.legend(fontsize=8, loc="upper center", ncols=3, frameon=False)  # the rates' legend
    fig.suptitle(title or "Accuracy, TPR (valid kept), TNR (invalid rejected)")
    said = "; ".join(
        f"{name}: accuracy {s['acc']:.2f}, TPR {s['tpr']:.2f}, TNR {s['tnr']:.2f}, balanced accuracy {b:.2f}"
        for (name, s), b in zip(scores.items(), balanced)
    )
    text = f"{title + '. ' if title else ''}Bars of accuracy, TPR (the share of valid configurations kept) and TNR"
    return describe(fig, f"{text} (the share in collision rejected), balanced accuracy under each group. {said}.")


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
    fig = Figure(figsize=(6.2, 8.4), layout="constrained")  # two rows, as wide as a chapter page's column
    grid_spec = fig.add_gridspec(2, 2, height_ratios=(2, 1), width_ratios=(1.5, 1))  # the map the page's width (r30c:
    ax_map, ax_counts, ax_roc = (fig.add_subplot(grid_spec[where]) for where in ((0, slice(None)), (1, 0), (1, 1)))
    ax_map.set_box_aspect(1)  # a third of it, its vermillion patch hid under its two squares), the ROC by the counts
    _draw_decision(ax_map, predicted, valid, grid)
    _draw_counts(ax_counts, predicted, valid)
    roc = answers.draw_roc(ax_roc, {"": (probability, valid, threshold)})
    _, fpr, tpr = roc_points(probability, valid)  # r39c: the legend lower right hid a curve near the diagonal there
    ax_roc.legend(fontsize=8, loc="upper left" if np.trapezoid(tpr[::-1], fpr[::-1]) < 0.8 else "lower right")
    fig.suptitle(title)
    cells = [Patch(facecolor=c, edgecolor=COLORS["ink"]) for c in ANSWER_COLORS]
    handles: list[Any] = [  # a mistake's cell with its mark on it
        (cell, Line2D([], [], linestyle="", **_mistake_mark(code, legend=True))) if code in MISTAKE_MARKERS else cell
        for code, cell in enumerate(cells)
    ]
    boundary = Line2D([], [], color=BOUNDARY, path_effects=halo(1.2))
    blocks = fit_on_cells(fig, grid)  # the mistakes' marks as large as one sees, the circles sparse, on their cells
    per = {code: blocks.get(ANSWERS[code], 1) for code in MISTAKE_MARKERS}
    block = {code: f" (one per {k} x {k} cells holding any)" if k > 1 else "" for code, k in per.items()}
    per_block = f"\nsquares 1 per {per[3]} x {per[3]}-cell tile, circles 1 per {per[1]} x {per[1]}"  # marks < mistakes
    ax_map.set_title(
        f"decision at threshold {threshold:.2f}" + (per_block if max(per.values()) > 1 else ""), fontsize=9
    )
    labels = ["true C-obstacle boundary", ANSWERS[0], f"{ANSWERS[1]}: conservative\nmistake (circles)", ANSWERS[2]]
    labels.append("invalid kept: dangerous\nmistake (squares)")  # r39c: section 1's table's names
    fig.legend([boundary, *handles], labels, loc="outside lower center", ncols=3, fontsize=8, frameon=False)
    place_on_cells(fig, grid, blocks)  # again, the map as its title and legend left it (r34c)
    text = f"{title + ': ' if title else ''}the model's decision at threshold {threshold:.2f} over {grid.names[0]} and "
    text += f"{grid.names[1]}, each cell by its kind of answer, over the boundary; the mistakes marked on their "
    text += f"cells: dangerous ones with squares{block[3]} and conservative ones with sparse "
    text += f"circles{block[1]}; their counts, and the ROC curve. "
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


def _draw_probability(ax, probability, valid, grid: CSpaceSlice, threshold: float, *, mistakes=True, cut=CUT_MAP):
    """P(valid) ``(nx, ny)`` in gray (0 black, 1 white), the boundary, the threshold's line (on the cells' edges
    between those kept and rejected, as the boundary: r42c, interpolated it ran outside it) dotted ``cut`` points
    wide (:data:`CUT_MAP`: under the boundary and wider, both show where they meet; the path map's over it) and, with
    ``mistakes``, dangerous cells as squares and conservative ones as circles, sparse enough that the grey between
    them is P(valid) (review r18b: a hatch of dots over the `paper` map's rejected free space hid its grey)."""
    probability = grid.on_grid(probability, "probability")
    image = ax.imshow(probability.T, cmap=GREY_CMAP, vmin=0, vmax=1, **_cells(grid))
    if probability.min() < threshold <= probability.max():
        line = draw_cell_outline(ax, grid, probability >= threshold, colors=COLORS["free"], linestyles=":")  # r42c
        line.set_linewidth(cut)
        line.set_path_effects(halo(cut, ("ink",)))  # a black ring: it shows on the light side too
        line.set_zorder(1.9 if cut >= CUT_MAP else 2.5)  # a map's wide line under the boundary (2), the path map's over
    _draw_boundary(ax, valid, grid)
    draw_cell_hatch(ax, grid, ~grid.on_grid(valid, "valid"), color=HATCH)  # the truth without reading the grey
    codes = answer_codes(probability >= threshold, grid.on_grid(valid, "valid"))
    if mistakes:  # fit_cell_marks sizes them, no two closer than their pitch
        tint = np.zeros((*codes.shape, 4))  # (nx, ny, RGBA) each wrong cell in its kind's colour, the grey showing
        for code in MISTAKE_MARKERS:  # through (reader r36c: 22 circles on a flat grey hid 64 % of the map wrong)
            tint[codes == code] = (*to_rgb(ANSWER_COLORS[code]), TINT[code])
        tint[(codes == 1) & (probability < DARK), 3] = 1.0  # r59c: on a dark grey the light tint was unseen: filled
        ax.imshow(tint.transpose(1, 0, 2), **_cells(grid))
        _draw_mistakes(ax, grid, codes)
    return image


def _cells(grid: CSpaceSlice) -> dict[str, Any]:
    """imshow's options for an image of one value per cell of ``grid`` (its array transposed: y up)."""
    return dict(origin="lower", extent=grid.extent, aspect="auto", interpolation="nearest")


def _draw_mistakes(ax, grid: CSpaceSlice, codes) -> None:
    """Every map's mistakes alike: circles, then squares over them, one per block of ``BLOCKS`` a side, each on one of
    its block's mistakes of its kind (r42c: moved towards the truth's side, squares sat where the model rejects)."""
    for code in MISTAKE_MARKERS:
        style: dict[str, Any] = dict(pitch=PITCH[code], blocks=BLOCKS[code], label=ANSWERS[code], zorder=ZORDER[code])
        on_cells(draw_cell_marks(ax, grid, codes == code, **style, **_mistake_mark(code)), codes == code)


def _draw_roadmap(ax, nodes: np.ndarray, nodes_valid, path: np.ndarray, dofs: tuple[int, int], edges=None) -> None:
    """A roadmap's valid nodes as dots, those in collision as plus signs, its ``edges (E, 2)`` (node indices) as faint
    lines, and the path dashed with diamonds, over a map of the two ``dofs``."""
    x, y = dofs
    scale = np.abs(np.diff([ax.get_xlim(), ax.get_ylim()]).ravel())  # (2,) the map's width and height
    apart = np.abs(path[:, None, [x, y]] - path[None, [0, -1]][..., [x, y]]) / scale  # (P, 2 ends, 2) map widths
    near = apart.max(axis=2).min(axis=1) < END_CLEAR  # (P,) beside an end: no diamond (r20b: one sat on the start)
    dots = dict(color=COLORS["node"], markersize=4, label="roadmap node, valid", path_effects=halo(0.5, ("free",)))
    ax.plot(nodes[nodes_valid, x], nodes[nodes_valid, y], ".", **dots)
    if edges is not None and len(edges):  # thin, under the nodes: a node in collision visibly has none (r29c); ink,
        ends = nodes[np.asarray(edges)][..., [x, y]]  # (E, 2, 2)  seen on the light and the mid greys (r30c)
        ax.add_collection(LineCollection(ends, colors=COLORS["ink"], linewidths=0.5, alpha=0.2, zorder=2.2))  # r41c
    mark = dict(markersize=10, label=COLLIDING, zorder=7, **_mistake_mark(3, legend=True) | dict(marker=NODE))  # filled
    ax.plot(nodes[~nodes_valid, x], nodes[~nodes_valid, y], linestyle="", **mark)  # r40c: no hair; its label: where
    box = dict(boxstyle="round,pad=0.2", fc=COLORS["free"], ec=COLORS["ink"], lw=0.6)
    label = dict(textcoords="offset points", va="center", fontsize=9, zorder=7, bbox=box)
    arrow = dict(arrowstyle="-", color=ANSWER_COLORS[3], lw=1.5, ls="--", shrinkB=8, path_effects=halo(1.5, ("free",)))
    for node in nodes[~nodes_valid][:3]:  # a few named in words too, placed on free cells once laid out (path_map)
        name = f"in collision\n({node[x]:.1f}, {node[y]:.1f})"  # r40c: where, in numbers
        ax.annotate(name, node[[x, y]], xytext=(30, -30), arrowprops=arrow, **label)
    ax.plot(
        path[:, x],
        path[:, y],
        "--D",  # dashed, a diamond per configuration, yellow: apart from the solid blue C-obstacle boundary (r46c)
        markevery=[k for k in range(1, len(path) - 1) if not near[k]],  # the ends have marks, and room around them
        color=COLORS["returned_path"],
        linewidth=3,
        markersize=7,
        label="returned path (checked exactly)",
        path_effects=halo(2.5),
        clip_on=False,  # whole where it ends on the map's edge
    )
    # the ends black, a white edge, a black ring: their whole shape shows on the map's dark side, on its light side
    # and, drawn whole on the map's edge over the frame, on the white beyond it
    end = dict(color=COLORS["endpoint"], markeredgecolor=COLORS["free"], clip_on=False, zorder=5)
    for at, marker, size, name in ((0, "^", 12, "start"), (-1, "*", 20, "goal")):  # no square: that is a mistake
        ax.plot(*path[at, [x, y]], marker, markersize=size, label=name, path_effects=halo(0.0, ("ink",)), **end)


def _draw_decision(ax, predicted_valid, valid, grid: CSpaceSlice):
    """Each cell coloured by its kind of answer (``ANSWER_COLORS``), and the boundary."""
    codes = answer_codes(grid.on_grid(predicted_valid, "predictions"), grid.on_grid(valid, "valid"))
    image = ax.imshow(codes.T, cmap=ListedColormap(ANSWER_COLORS), vmin=-0.5, vmax=len(ANSWERS) - 0.5, **_cells(grid))
    _draw_boundary(ax, valid, grid)
    _draw_mistakes(ax, grid, codes)  # as on a P(valid) map (r27c: a circle a cell hid the sky blue under a carpet)
    return image


def _mistake_mark(code: int, *, legend: bool = False) -> dict[str, Any]:
    """The mark of a mistake of answer ``code`` (1 conservative, 3 dangerous): its colour in a black, then a white
    ring (:data:`MARK_RING`: it stands out on white, on the obstacles' dark grey, on any grey of P(valid) between
    and on its own cell's colour); scatter's options, or a legend line's."""
    color = ANSWER_COLORS[code]
    if legend:
        return dict(marker=MISTAKE_MARKERS[code], color=color, markeredgecolor=COLORS["ink"], path_effects=halo(0.0))
    return dict(c=color, marker=MISTAKE_MARKERS[code], linewidths=0, path_effects=halo(MARK_RING), clip_on=False)


COLLIDING, NODE = "roadmap node in collision\n(a dangerous mistake kept)", "P"  # the path map's mark: no tile's square
MARK_RING = 1.0  # points: a mistake's black ring 1.3 points wide (2 pixels on the site), its white one 0.8 beyond


def _draw_boundary(ax, valid, grid: CSpaceSlice) -> None:
    """The true C-obstacle boundary: the 0.5 contour of the exact checker's answers; axis names."""
    valid = grid.on_grid(valid, "valid")
    if valid.any() and not valid.all():
        draw_cell_outline(ax, grid, valid, colors=BOUNDARY, linewidths=OUTLINE).set_path_effects(halo(OUTLINE))
        walls = [name in POSITION_NAMES for name in grid.names]  # (2,) each axis's ends are walls (an angle's: none)
        frame = cell_marks.draw_frame_runs(ax, grid, valid, walls, colors=BOUNDARY, linewidths=OUTLINE)
        frame.set_path_effects(halo(OUTLINE))  # r44c: a block against the map's edge read as cut off by the frame
    ax.set_xlabel(dof_label(grid.names[0]))  # an angle with its unit, radians
    ax.set_ylabel(dof_label(grid.names[1]))


def _mistake_handles(blocks: Mapping[int, int]) -> list:
    """The P(valid) maps' legend: the threshold's line, and each mistake's mark, said to be one (``blocks[code]`` 1) or
    one per ``k x k`` cells holding any (review r18b: the conservative circles along the blocks read as a border)."""
    per = {code: f"\none per {k} x {k}-cell tile holding any" if k > 1 else "" for code, k in blocks.items()}
    return [
        (_dots(), "P(valid) = threshold: white dots\nringed dark, the lighter side kept;\nhidden under an outline"),
        (_mistake_line(3), f"dangerous mistake: kept, in\ncollision (squares){per[3]}"),
        (_mistake_line(1), f"conservative mistake: rejected,\nfree (circles; {UNDER}){per[1]}"),
    ]


def _dots(label: str = "") -> Line2D:
    """The threshold's line in a legend: three ringed white dots (:func:`_legend`; r42c: dotted, it read as "⊐ ]")."""
    dots = Line2D([], [], linestyle="", marker="s", markersize=3.5, color=COLORS["free"], gid="dots", label=label)
    dots.set_markeredgecolor(COLORS["ink"])
    return dots


def _mistake_line(code: int) -> Line2D:
    return Line2D([], [], linestyle="", markersize=7, **_mistake_mark(code, legend=True))


def _legend(fig: Figure, handles: list) -> None:
    """The boundary, then ``handles`` (``(handle, label)`` pairs), under the figure."""
    boundary = Patch(facecolor=COLORS["occupied"], edgecolor=BOUNDARY, hatch="//", hatchcolor=HATCH, linewidth=1.5)
    pairs = [(boundary, "true C-obstacle (outlined, hatched)"), *handles]
    ncols = len(pairs) if fig.get_figwidth() >= 9 else 2
    dots = {h: HandlerLine2D(numpoints=3) for h, _ in pairs if h.get_gid() == "dots"}  # the threshold's (r42c)
    fig.legend(*zip(*pairs), loc="outside lower center", ncols=ncols, fontsize=9, frameon=False, handler_map=dots)


BAR_NAMES = ("valid\nkept", "conservative\nmistake", "invalid\nrejected", "dangerous\nmistake")  # section 1's (r39c)


def _draw_counts(ax, predicted_valid, valid) -> None:
    counts = confusion_counts(predicted_valid, valid)
    bars = ax.bar(range(len(counts)), list(counts.values()), color=ANSWER_COLORS, edgecolor=COLORS["ink"])
    for code in MISTAKE_MARKERS:  # a mistake's mark on its bar: a bar of a few cells shows (r19b: 35 and 4 did not)
        ax.plot(code, counts[ANSWERS[code]], linestyle="", clip_on=False, **_mistake_mark(code, legend=True))
    ax.bar_label(bars, fontsize=9, padding=6)
    ax.set_ylim(0, 1.18 * max(max(counts.values()), 1))  # room above the tallest bar for its count, inside the frame
    ax.set_xticks(range(len(counts)), BAR_NAMES, fontsize=9)
    for tick in ax.xaxis.get_major_ticks()[1::2]:  # every other name lower down (r51c: two names touched)
        tick.set_pad(tick.get_pad() + 22)
    ax.set(xlabel="answer", ylabel="configurations")
    rates = metrics.classification(np.ravel(predicted_valid), np.ravel(valid))
    ax.set_title(f"accuracy {rates['acc']:.2f}, TPR {rates['tpr']:.2f}, TNR {rates['tnr']:.2f}", fontsize=9)
