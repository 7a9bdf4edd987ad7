"""Figures of the contractive autoencoder (paper §III-A, Eq. 1; notebook 02): every function returns a Figure.

- :func:`training_curves` — the loss of Eq. (1) per epoch, one line per model;
- :func:`reconstructions` — input, decoded grid and wrong cells of 2D workspaces, titled with accuracy and "all free";
- :func:`accuracy_vs_all_free` — each workspace's reconstruction accuracy against answering "all free" (Table 1);
- :func:`contraction` — the encoder Jacobian's norm, and how far ``z`` and the decoded grid move when a few cells are
  flipped (the latent codes themselves: :mod:`toolkit.plots.latent`).

Grids hold -1 (free) and +1 (occupied), as :meth:`toolkit.geometry.workspace.Workspace.occupancy` returns them; a
decoded cell counts as occupied where the decoder's output is positive, as in
:func:`toolkit.learning.metrics.reconstruction_accuracy`. Nothing here calls ``show()``.
"""

from __future__ import annotations

import re
from dataclasses import replace
from functools import partial
from typing import Any

import numpy as np
from matplotlib import colormaps
from matplotlib.figure import Figure
from matplotlib.legend_handler import HandlerTuple
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.ticker import FuncFormatter, LogLocator, NullLocator

from toolkit.learning.metrics import reconstruction_accuracy
from toolkit.plots.accuracy_panels import CROSS_HAIR, MEAN_SAID, mean_handle
from toolkit.plots.alt import Part, describe, lines_part
from toolkit.plots.box_names import NAME_POINTS, fitted, slot_points, tick_names
from toolkit.plots.palette import COLORS, GREYS_CMAP, LINE_COLORS, LINE_STYLES, PAGE_WIDTH, halo, series_style
from toolkit.plots.wrong_cells import draw_wrong_cells, grid_part, legend_handles, wrong_in_words, wrong_kinds


def training_curves(
    histories: dict[str, list[float]],
    *,
    ylabel: str = "loss of Eq. (1), mean per epoch",
    log: bool = True,
    panels: bool = False,
    series: tuple[int, ...] | None = None,
) -> Figure:
    """One line per named history (e.g. ``TrainedModels.history["cae"]``), epochs 1, 2, ... on x. Two curves that
    coincide stay visible: each later line is drawn thinner over the earlier ones, and their markers take turns; or,
    with ``panels``, each line in a panel of its own, all on one y axis (reader r39b: λ = 0 hid under λ = 1e-3), in
    colour and line style only, the colour of series ``series[k]`` (reader r50b: no marker, which meant groups of
    grids elsewhere on the page)."""
    n = len(histories)
    series = tuple(range(n)) if series is None else tuple(series)
    fig = Figure(figsize=(PAGE_WIDTH, 3.2 if panels else 3.6))
    axes = list(fig.subplots(1, n if panels else 1, sharey=True, squeeze=False)[0])
    for k, (name, history) in enumerate(histories.items()):
        every = max(1, len(history) // 8)  # about 8 markers a line, each line's shifted off the others'
        marks = dict(markevery=(k * every // n, every), markersize=6)
        style = _line(k, series[k]) if panels else _stacked(k, n) | marks
        axes[k if panels else 0].plot(np.arange(1, len(history) + 1), history, label=name, **style)
        if panels:
            axes[k].set_title(name, fontsize=10)
    for ax in axes:
        if log:  # reader r33b: 10² and 10³ alone on an axis from 40 to 4,000; r36b: no tick above a start at 3,830
            ax.set_yscale("log")
            ax.yaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 4.0)))
            ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:,.0f}" if v >= 1 else f"{v:g}"))
            ax.yaxis.set_minor_locator(NullLocator())
        ax.set_xlabel("epoch")
    axes[0].set_ylabel(ylabel)
    values = np.concatenate([np.asarray(h, dtype=float) for h in histories.values()])
    if log and values.min() > 0:  # reader r41b: λ = 0.961's first point, the highest, sat clipped on the top frame
        pad = max(1.3, (values.max() / values.min()) ** 0.1)  # r49b: a tenth of the range each side, its ends clear
        axes[0].set_ylim(values.min() / pad, values.max() * pad)
    if panels:
        fig.suptitle("CAE training curves", fontsize=10)
    else:
        axes[0].legend(fontsize=9)
        axes[0].set_title("CAE training curves", fontsize=10)  # r26b: how lines are drawn is not a title's to say
    fig.tight_layout()
    said = "; ".join(
        f"{name}: {len(h)} epochs, from {h[0]:.3g} to {h[-1]:.3g} (lowest {min(h):.3g})"
        for name, h in histories.items()
    )
    text = f"Training curves, epoch across and {ylabel} up{' on a log scale' if log else ''}. {said}."
    parts = [replace(lines_part(ax), text=f"{ylabel} against epoch") for ax in axes] if panels else []
    return describe(fig, text, parts)  # several panels: each one's line as a table under the figure


def _stacked(k: int, n: int, s: int | None = None) -> dict[str, Any]:
    """The ``k``-th of ``n`` lines that may coincide, series ``k``'s style (given ``s``, :func:`_line`'s), each later
    line thinner, its markers smaller, drawn over the earlier ones (a line under another shows at its edges)."""
    under = (n - 1 - k) / max(n - 1, 1)  # 1 for the first line (the lowest), 0 for the last (on top)
    style = series_style(k) if s is None else _line(k, s)
    return style | dict(linewidth=1.2 + 3.0 * under, markersize=5 + 5 * under, zorder=2 + k)


def _line(k: int, s: int) -> dict[str, Any]:
    """The ``k``-th line of a figure in series ``s``'s colour and the ``k``-th line style, no marker."""
    return dict(color=LINE_COLORS[s % len(LINE_COLORS)], linestyle=LINE_STYLES[k % len(LINE_STYLES)], marker="")


def reconstructions(
    grids: np.ndarray, decoded: np.ndarray, names: list[str], flipped: np.ndarray | None = None
) -> Figure:
    """One row per 2D workspace: input, decoded sign, and the wrong cells over the input.

    ``grids``, ``decoded``: ``(W, nx, ny)``. Wrong cells are marked by kind (:mod:`toolkit.plots.wrong_cells`): a
    missed cell (input occupied, decoded free) or an invented one; given ``flipped (W, nx, ny)``, the cells flipped
    in a perturbed input, those are a kind of their own (flip ignored, flip copied) and the rest "other wrong".
    A legend above the first row names the kinds (review r27b), in the figure's first subfigure; the rows are the
    others. Each row's title gives the reconstruction accuracy next to the share of free cells, the accuracy of
    answering "all free". Given ``flipped``, both are of the *clean* grid, the input with its flips undone (review
    r29b: against the noisy input, a decoder that ignored every flip read as 30 cells wrong).
    """
    grids, decoded = np.asarray(grids), np.asarray(decoded)
    if grids.ndim != 3 or decoded.shape != grids.shape or len(names) != len(grids):
        raise ValueError(
            f"need grids, decoded of one shape (W, nx, ny), W names; got {grids.shape}, {decoded.shape}, {len(names)}"
        )
    if flipped is not None and np.shape(flipped) != grids.shape:
        raise ValueError(f"flipped has shape {np.shape(flipped)}, the grids {grids.shape}")
    clean = grids if flipped is None else np.where(flipped, -grids, grids)  # the flips undone
    accuracy = reconstruction_accuracy(decoded, clean)  # (W,)
    right = "of cells right" if flipped is None else "of cells as in the clean grid"
    fig = Figure(figsize=(PAGE_WIDTH, 4.3 * len(grids) + 0.65), layout="constrained")
    # a strip for the legend, then one row per workspace: a figure's "outside" legend would overlap the rows' titles
    key, *rows = fig.subfigures(len(grids) + 1, 1, height_ratios=(0.65, *[4.3] * len(grids)), squeeze=False)[:, 0]
    said, parts = [], []
    drawn: dict[str, np.ndarray] = {}  # the kinds of wrong cell drawn in any row, for the legend
    for k, (row, grid, out, name, acc, target) in enumerate(zip(rows, grids, decoded, names, accuracy, clean)):
        kinds = wrong_kinds(grid, out, None if flipped is None else flipped[k])
        drawn |= kinds
        layout = row.add_gridspec(2, 2, width_ratios=(1, WRONG))  # input over decoded; r19b: marks 8 px wide
        axes = [row.add_subplot(layout[0, 0]), row.add_subplot(layout[1, 0]), row.add_subplot(layout[:, 1])]
        _image(axes[0], grid, "input")
        _image(axes[1], np.where(out > 0, 1.0, -1.0), "decoded (sign)")
        wrong = wrong_in_words(kinds)
        _image(axes[2], grid, wrong_in_words(kinds, marks=True), alpha=FADED, axes=True)  # x, y: the thumbnails'
        draw_wrong_cells(axes[2], grid, kinds, cell=72 * 0.62 * fig.get_figwidth() / max(grid.shape))
        all_free = np.mean(target < 0)
        row.suptitle(f"{name}: {acc:.1%} {right} (all free: {all_free:.1%})", fontsize=10)
        scored = f"{acc:.1%} {right} against {all_free:.1%} for answering all free; {wrong}"
        said.append(f"{name}: {scored}")  # reader r45b: the part has its name as title, not again ("seen 0: seen 0:")
        parts.append(_cells(grid_part(name, scored, grid, out, None if flipped is None else flipped[k])))
    handles, labels = legend_handles(list(drawn))  # "missed cell", not "block": mostly single cells (r29b)
    handles.append(Patch(facecolor=colormaps[GREYS_CMAP](1.0), alpha=FADED, edgecolor=COLORS["ink"], linewidth=0.5))
    labels.append("occupied in the input (faded)")  # reader r31b: a seen grid's panel, all grey, read as empty
    colours = "the colours here: kinds of cell, not models or groups of grids"  # r50b; r51b: an ignored flip is right
    key.legend(handles, labels, loc="center", ncols=2, fontsize=9, frameon=False, title=colours, title_fontsize=9)
    grids_said = f"{len(grids)} occupancy grid{'s' if len(grids) > 1 else ''}"
    text = f"{grids_said}, each beside its reconstruction and its wrong cells. " + "; ".join(said)
    return describe(fig, text + ".", parts)


def _cells(part: Part) -> Part:
    """A region table's ranges of cells, both ends said (reader r53b: "x cell 0 to 8 | 8 to 16" read as overlapping
    ends): "x cells 0–7 | 8–15"."""
    said = partial(re.sub, r"([xy]) cell (\d+) to (\d+)", lambda m: f"{m[1]} cells {m[2]}–{int(m[3]) - 1}")
    return replace(part, columns=tuple(map(said, part.columns)), rows=tuple((said(r[0]), *r[1:]) for r in part.rows))


FADED = 0.25  # the input's opacity under the wrong cells' marks: its obstacles light grey
WRONG = 2.2  # the wrong cells' panel's width against the input's column: 0.62 of the figure's, laid out
FEW = 50  # a group of at most this many workspaces is drawn larger and on top: hundreds of points would bury it
GREY = {True: dict(s=28, alpha=1.0, linewidths=0.8, zorder=3), False: dict(s=10, alpha=0.5, linewidths=0, zorder=1)}
AREA = {"^": 1.7, "v": 1.7, "o": 1.2}  # marker area factors: a triangle of the same size looks half a square's
LAYERS = 10  # slices of a large group drawn in turns with the other large groups' (accuracy_vs_all_free)
MEAN_SIZE = 1000  # the first group's mean cross-hair (points squared); each later group's is smaller, drawn over it
POINT_SIZE = 45  # a point of a small group; its mean's cross-hair 10 times its area at least (r47b)


def accuracy_vs_all_free(
    groups: dict[str, tuple[np.ndarray, np.ndarray]], *, series: tuple[int, ...] | None = None
) -> Figure:
    """Reconstruction accuracy (y) against the share of free cells (x), one point per workspace, per named group.

    ``groups[name] = (all_free (W,), accuracy (W,))``. Points above the diagonal beat a CAE that answers "all free";
    on it, the CAE has learned nothing about that workspace. A small group (a few dozen workspaces) has larger, filled
    markers ringed in white, drawn on top, the first over the next. Large groups are hollow markers of their own
    shapes, drawn in turns, a slice of each at a time (:data:`LAYERS`): where clouds overlap every group shows (review
    r14c). Each group's mean is a thin cross-hair open at its centre, behind every point (review r27b; as section 7's
    panels draw it): a point at the mean shows whole; each later one smaller and on top: means that coincide nest.
    ``series[k]``: group ``k``'s :func:`~toolkit.plots.palette.series_style` (by default ``k``): a page keeps one
    code across figures (r45b).
    """
    series = tuple(range(len(groups))) if series is None else tuple(series)  # (len(groups),)
    fig = Figure(figsize=(6, 5.2), layout="constrained")
    ax = fig.subplots()
    said = []
    for k, (name, (all_free, accuracy)) in enumerate(groups.items()):
        style = series_style(series[k])
        all_free, accuracy = np.asarray(all_free), np.asarray(accuracy)
        above = int(np.sum(accuracy > all_free))
        few = len(accuracy) <= FEW
        layers = 1 if few else LAYERS
        # a few: filled, an ink rim; hundreds: hollow, so that where clouds overlap each shows, by its shape
        marks = (
            dict(c=style["color"], edgecolors=COLORS["ink"])
            if few
            else dict(facecolors="none", edgecolors=style["color"])
        )
        for j in range(layers):  # layer j of every large group, then layer j + 1: the groups interleave
            ax.scatter(
                all_free[j::layers],
                accuracy[j::layers],
                label=f"{name}: mean {np.mean(accuracy):.1%} vs {np.mean(all_free):.1%}" if j == 0 else None,
                alpha=0.9 if few else 0.8,
                s=(POINT_SIZE if few else 14) * AREA.get(style["marker"], 1.0),
                marker=style["marker"],
                **marks,
                linewidths=0.9,
                path_effects=halo(0.9, ("free",)) if few else None,  # r50b: a point on a mean's outline stands out
                zorder=3 + len(groups) - k if few else 2 + (j * len(groups) + k) / (layers * len(groups)),
                gid=name,
            )
        _draw_mean(ax, name, (np.mean(all_free), np.mean(accuracy)), k, len(groups), series[k], few)
        said.append(
            f"{name}: {len(accuracy)} workspaces, mean accuracy {np.mean(accuracy):.1%} against {np.mean(all_free):.1%}"
            f" for all free, {above} of them above the diagonal"
        )
    low = min(min(np.min(f), np.min(a)) for f, a in groups.values())
    ax.plot([low, 1], [low, 1], color=COLORS["reference"], linestyle="--", label='"all free" (diagonal)')
    ax.set_xlabel('share of free cells = accuracy of answering "all free"')
    ax.set_ylabel("reconstruction accuracy")
    ax.set_title("Above the diagonal: better than all free", fontsize=10)
    _key(fig, ax, series)
    text = "Reconstruction accuracy against the accuracy of answering all free, one point per workspace. "
    return describe(fig, text + "; ".join(said) + ".")


def _key(fig: Figure, ax, series: tuple[int, ...]) -> None:
    """The scatter's legend below it, the means one entry: a cross-hair in each group's colour, drawn as
    :mod:`toolkit.plots.accuracy_panels` draws its means (r45b; reader r51b: one style on the page)."""
    handles, labels = ax.get_legend_handles_labels()
    mean = tuple(mean_handle(series_style(s)["color"]) for s in series)
    handles, labels = [*handles, mean], [*labels, MEAN_SAID.format("group")]  # r29b: not in
    key: dict[str, Any] = dict(loc="outside lower center", fontsize=9, frameon=False)
    fig.legend(handles, labels, handler_map={tuple: HandlerTuple(None)}, **key)


def _draw_mean(ax, name: str, mean: tuple[float, float], k: int, n: int, s: int, few: bool) -> None:
    """Group ``k`` of ``n``'s mean, a thin cross-hair open at its centre in series ``s``'s colour (as section 7's
    panels draw theirs; reader r51b), behind every cloud (points zorder 2 and up), each later group's smaller and on
    top of the earlier: two means at one spot both show; a ``few`` group's arms reach well past a point of its own
    at the mean (reader r47b), which shows whole in the open centre (a hollow mark around it read as one mark)."""
    least = 10 * POINT_SIZE * AREA.get(series_style(s)["marker"], 1.0) * few  # arms well past a point at the mean
    ax.scatter(
        *mean,
        s=max(MEAN_SIZE * (1 - 0.6 * k / max(n - 1, 1)), least),
        marker=CROSS_HAIR,
        facecolors="none",
        edgecolors=series_style(s)["color"],
        linewidths=1.4,
        zorder=1 + k / (n + 1),
        path_effects=halo(1.4, ("free",)),
        gid=f"{name}: mean",
    )


LINES_KEY: dict[str, Any] = dict(loc="outside upper center", ncols=2, fontsize=9, title_fontsize=9, frameon=False)


def _plain_log_ticks(ax, values: np.ndarray) -> None:
    """``ax``'s log y axis ticked at 1, 2, 3 and 5 times a power of ten in the range of ``values``, plain numbers."""
    moved = values[values > 0]
    if moved.size:
        steps = [m * 10.0**e for e in range(-4, 2) for m in (1, 2, 3, 5)]
        ticks = [t for t in steps if moved.min() / 1.5 <= t <= moved.max() * 1.5] or [moved.min()]
        ax.set_yticks(ticks, [f"{t:g}" for t in ticks])
        ax.set_yticks([], minor=True)


def contraction(
    jacobian_norms: dict[str, np.ndarray],
    *,
    flips: np.ndarray,
    latent_shift: dict[str, np.ndarray],
    decoded_change: dict[str, np.ndarray],
    series: tuple[int, ...] | None = None,
) -> Figure:
    """Two (or more) CAEs side by side: how strongly the encoder reacts to its input; model ``k``'s lines in
    :func:`_line` ``(k, series[k])``'s style, no marker (reader r50b: markers meant groups of grids on the page).

    For each named model: ``jacobian_norms (W,)``, the Frobenius norm of dz/dx at each workspace; ``latent_shift (F,
    T)``, ``||z' - z|| / ||z||`` after flipping ``flips[f]`` random cells, in ``T`` trials; ``decoded_change (F, T)``,
    how many decoded cells change sign then, anywhere in the grid. Lines are the means over trials. The dotted line
    of the last panel marks as many changed cells as flipped ones.
    """
    flips = np.asarray(flips)
    fig = Figure(figsize=(PAGE_WIDTH, 6.6), layout="constrained")  # the page's width: text at its size, 9 pt or more
    # reader r33b: the norms a short row of their own, the two responses side by side under them, their legend between
    boxes, responses = fig.subfigures(2, 1, height_ratios=(2.3, 4.3), squeeze=False)[:, 0]
    ax_j = boxes.subplots()
    ax_z, ax_x = responses.subplots(1, 2)
    names = list(jacobian_norms)
    _draw_norms(ax_j, jacobian_norms)
    series = tuple(range(len(names))) if series is None else tuple(series)
    for k, name in enumerate(names):  # two models that respond alike: the first line wide under the next, thinner
        ax_z.plot(flips, np.mean(latent_shift[name], axis=1), label=name, **_stacked(k, len(names), series[k]))
        ax_x.plot(flips, np.mean(decoded_change[name], axis=1), label=name, **_stacked(k, len(names), series[k]))
    ax_x.plot(flips, flips, color=COLORS["reference"], linestyle=":", label="as many as flipped", zorder=1)
    ax_z.set_yscale("log")  # reader r44b: log-log, as the right panel; a power of the flips reads as a straight line
    ax_z.set_ylabel("||z' - z|| / ||z|| (log scale)")  # review r30b: the long label was cramped; the title says what
    _plain_log_ticks(ax_z, np.concatenate([np.mean(latent_shift[name], axis=1) for name in names]))
    ax_z.set_title("Latent code moves", fontsize=10)  # its axis says relative to what
    ax_x.set_title("Reconstruction changes", fontsize=10)
    changes = np.concatenate([flips, *(np.mean(decoded_change[name], axis=1) for name in names)])  # the counts drawn
    _counts_axis(ax_x, "y", _count_ticks(changes.min(), changes.max(), end=flips[-1]))  # 1 reads as 30 does
    ax_x.set_ylabel("decoded cells that change sign")
    for ax in (ax_z, ax_x):
        _counts_axis(ax, "x", flips)  # the numbers of flips measured
        ax.set_xlabel("cells flipped (log scale)")
    # r31b: above the line panels, not a screen below them; r41b: titled, so that it is not read as the boxes' key
    responses.legend(handles=ax_x.get_lines(), title="the lines of the two panels below", **LINES_KEY)
    for ax in (ax_j, ax_z, ax_x):  # review r16b: the legends and ticks at 8 pt, shrunk to the page, read as 8 px
        ax.tick_params(labelsize=9)
    said = "; ".join(
        f"{name}: median Jacobian norm {np.median(jacobian_norms[name]):.3g}; flipping {flips[-1]:g} cells moves z by "
        f"{np.mean(latent_shift[name][-1]):.1%} of its length and changes {np.mean(decoded_change[name][-1]):.3g} "
        "decoded cells"
        for name in names
    )
    parts = [_norms_part(jacobian_norms), *(lines_part(ax, text="mean over the trials") for ax in (ax_z, ax_x))]
    text = "How strongly each encoder reacts to its input: the norm of its Jacobian (a box per model, the median a"
    text += " thick line, the mean a star), and how far the latent code and the reconstruction move when cells of"
    text += " the input are flipped (both panels log-log: the flips, the code's move and the decoded cells that change)"
    return describe(fig, f"{text}. {said}.", parts)


def _norms_part(jacobian_norms: dict[str, np.ndarray]) -> Part:
    """The box plot's numbers, a row per model, for the figure's description."""
    return Part(
        "Encoder Jacobian norm",
        "the Frobenius norm of dz/dx over the workspaces, per model",
        ("model", "workspaces", "lowest", "median", "mean", "highest"),
        tuple(
            (n, str(len(v)), *(f"{f(v):.3g}" for f in (np.min, np.median, np.mean, np.max)))
            for n, v in ((n, np.asarray(values)) for n, values in jacobian_norms.items())
        ),
    )


COUNT_TICKS = (0, 1, 2, 5, 10, 20, 50, 100, 200, 500, 1000)


def _count_ticks(low: float, high: float, end: float) -> list[float]:
    """The ticks of a count axis from ``low`` to ``high``: from the highest of :data:`COUNT_TICKS` at or below ``low``
    (review r26b), and ``end`` (the copy line's last count, 30) in place of a round tick too close to it."""
    floor = max(t for t in COUNT_TICKS if t <= max(low, 0))
    ticks = [t for t in COUNT_TICKS if floor <= t <= high and not end / 2 < t < 2 * end]
    return sorted(set(ticks) | {end})


def _counts_axis(ax, which: str, ticks) -> None:
    """An axis of counts (``which``: "x" or "y"), "symlog": log from 1 up, linear from 0 to 1 (a count of 0 shows);
    ``ticks`` in plain numbers, no others."""
    (ax.set_xscale if which == "x" else ax.set_yscale)("symlog", linthresh=1, linscale=0.4)
    axis = ax.xaxis if which == "x" else ax.yaxis
    axis.set_ticks(list(ticks), [f"{t:g}" for t in ticks])
    axis.set_minor_locator(NullLocator())
    ax.autoscale_view()  # the limits on the new scale: the data and a margin, no more


NORM_MARKS: dict[str, dict[str, Any]] = {  # a box plot's marks, each named in the panel's legend
    "median": dict(color=COLORS["ink"], linewidth=2),
    "mean": dict(  # reader r48b: a star, no model's marker (a triangle was λ = 0.961's in the panels below)
        marker="*", color=COLORS["ink"], markerfacecolor=COLORS["free"], markeredgecolor=COLORS["ink"], markersize=11
    ),
    "outlier (beyond\n1.5 × IQR)": dict(marker="+", markeredgecolor=COLORS["ink"], markersize=5),  # r50b: no circle
}


def _draw_norms(ax, jacobian_norms: dict[str, np.ndarray]) -> None:
    """A box per model of its encoder's Jacobian norms over the workspaces (the middle half of them, whiskers to the
    farthest within 1.5 interquartile ranges, IQR), the median a thick line, the mean a star: a legend names
    each mark."""
    names = list(jacobian_norms)
    ink = dict(color=COLORS["ink"])
    median, mean, outlier = NORM_MARKS.values()
    props = dict(boxprops=ink, whiskerprops=ink, capprops=ink, medianprops=median, meanprops=mean, flierprops=outlier)
    ax.boxplot([np.asarray(jacobian_norms[n]) for n in names], showmeans=True, **props)
    marks = [Line2D([], [], linestyle="-" if "marker" not in style else "", **style) for style in NORM_MARKS.values()]
    ax.legend(marks, list(NORM_MARKS), fontsize=9, loc="center left", bbox_to_anchor=(1.01, 0.5))  # beside: on none
    ticks, axis_name = tick_names(names)
    ax.set_xticks(range(1, len(names) + 1), fitted(ticks, slot_points(ax, len(names)), NAME_POINTS), fontsize=9)
    ax.set_xlabel(axis_name)
    ax.set_ylabel("||dz/dx|| per workspace")  # r33b: a short panel; its title names it
    ax.set_title("Encoder Jacobian norm", fontsize=10)


def _image(ax, grid: np.ndarray, title: str, alpha: float = 1.0, axes: bool = False) -> None:
    """A 2D grid of -1 / +1, x right and y up, occupied black; ``axes``: named, in workspace units (r19b: none)."""
    ax.imshow(grid.T, origin="lower", cmap=GREYS_CMAP, vmin=-1, vmax=1, alpha=alpha)
    ax.set_title(title, fontsize=9)
    for axis, n, name in zip((ax.xaxis, ax.yaxis), grid.shape, "xy"):
        at = np.arange(0, n + 1, 10) if axes else np.array([], dtype=int)  # workspace units
        axis.set_ticks(at - 0.5, [f"{v}" for v in at])  # the image's pixel i is centred on i
        axis.set_label_text(name if axes else "")
