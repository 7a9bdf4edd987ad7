"""Reconstruction accuracy against "all free", one panel per group of workspaces (paper Table 1; notebook 02, §8).

:func:`toolkit.plots.cae.accuracy_vs_all_free` draws every group on one axes; where two groups of hundreds of
workspaces fall on the same cloud (a CAE's training grids and the unseen ones, once it generalizes), the one drawn
later hides the other, however the marks are layered (review r15c). :func:`accuracy_panels` draws each group in a
panel of its own, on the same axes, the diagonal ("all free") and the group's mean in each: the clouds compare side
by side, none under another.
"""

from __future__ import annotations

import textwrap

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.path import Path
from matplotlib.ticker import MaxNLocator

from toolkit.plots.alt import Part, describe
from toolkit.plots.palette import COLORS, PAGE_WIDTH, halo, series_style

GAP = 0.4  # the cross-hair's open centre, a share of its half-width: a point at the mean shows whole in it
CROSS_HAIR = Path(  # a group's mean (a point at the mean read as part of a hollow mark around it)
    [(-1, 0), (-GAP, 0), (GAP, 0), (1, 0), (0, -1), (0, -GAP), (0, GAP), (0, 1)], [Path.MOVETO, Path.LINETO] * 4
)
MEAN_SAID = "thin cross-hair, open at its centre, in the {0}'s colour: the {0}'s mean"


def mean_handle(color: str, label: str | None = None) -> Line2D:
    """The legend's icon of a mean drawn in ``color``: the cross-hair, as the figures draw it."""
    return Line2D(
        [],
        [],
        label=label,
        marker=CROSS_HAIR,
        linestyle="",
        markersize=14,
        markerfacecolor="none",
        markeredgecolor=color,
        markeredgewidth=1.4,
    )


def accuracy_panels(groups: dict[str, tuple[np.ndarray, np.ndarray]]) -> Figure:
    """One panel per group ``{name: (all_free (W,), accuracy (W,))}``: each workspace a point, its reconstruction
    accuracy (y) against its share of free cells (x, the accuracy of answering "all free"), above the dashed
    diagonal when the CAE beats that answer; the group's mean a large mark. The panels share both axes."""
    # review r29b: two a row left the legend in a spare slot, half out of it; r30b: three a row left each panel 150 px
    # wide at the site's width, its 500 points one blob. Two a row, as tall as wide, the legend filling the spare slot
    # (centred in it, whole); two groups or fewer side by side, the legend below them
    cols = 2 if len(groups) > 2 else len(groups)
    rows_of = -(-len(groups) // cols)
    fig = Figure(figsize=(PAGE_WIDTH, rows_of * PAGE_WIDTH / cols + 0.8), layout="constrained")
    grid = np.atleast_2d(fig.subplots(rows_of, cols, sharex=True, sharey=True, squeeze=False))
    for spare in grid.flat[len(groups) :]:
        spare.set_axis_off()
    axes = grid.flat
    values = [np.asarray(v, dtype=float) for pair in groups.values() for v in pair]
    low = min(float(v.min()) for v in values)
    said, rows = [], []
    for k, (ax, (name, (all_free, accuracy))) in enumerate(zip(axes, groups.items())):
        style = series_style(k)
        all_free, accuracy = np.asarray(all_free, dtype=float), np.asarray(accuracy, dtype=float)  # (W,) each
        # review r28b: the diagonal over the points (a dense cloud hid it), under the mean
        ax.plot([low, 1], [low, 1], color=COLORS["reference"], linestyle="--", zorder=4)
        ax.scatter(
            all_free, accuracy, s=16, marker=style["marker"], c=style["color"], alpha=0.3, lw=0, gid=name
        )  # r19b; r30b: light enough that 500 points show where they crowd
        mean = (float(np.mean(all_free)), float(np.mean(accuracy)))
        ax.scatter(  # as the section 5 scatter's: thin, open at its centre, so it hides no point
            *mean,
            s=400,
            marker=CROSS_HAIR,
            facecolors="none",
            edgecolors=style["color"],
            linewidths=1.4,
            zorder=5,
            path_effects=halo(1.4, ("free",)),
            gid=f"{name}: mean",
        )
        above = int(np.sum(accuracy > all_free))
        ax.set_title(  # review r28b: the count the text reads, in the title, not only in "Figure described"
            "\n".join(textwrap.wrap(name, 40))  # half the page wide: the counts on a line of their own
            + f"\nmean {mean[1]:.1%} vs {mean[0]:.1%}; {above} of {len(accuracy)} above",
            fontsize=9,
        )
        ax.set_xlabel("share of free cells")
        ax.xaxis.set_major_locator(MaxNLocator(5))  # half the page wide: five ticks, never touching
        ax.xaxis.set_tick_params(labelbottom=True)  # every panel's own x axis read, the one over the spare slot too
        ax.tick_params(labelsize=9)
        said.append(
            f"{name}: {len(accuracy)} workspaces, mean accuracy {mean[1]:.1%} against {mean[0]:.1%} for all free, "
            f"{above} of them above the diagonal"
        )
        rows.append((name, str(len(accuracy)), f"{mean[1]:.1%}", f"{mean[0]:.1%}", f"{above} of {len(accuracy)}"))
    for ax in grid[:, 0]:
        ax.set_ylabel("reconstruction accuracy")
    spare = grid.flat[len(groups) :]
    _legend(fig, spare[0] if len(spare) else None)
    text = "Reconstruction accuracy against the accuracy of answering all free, one panel per group, one point per "
    columns = ("panel", "workspaces", "mean accuracy", "mean all free", "above the diagonal")
    return describe(fig, text + "workspace. " + "; ".join(said) + ".", [Part("the panels", "", columns, tuple(rows))])


def _legend(fig: Figure, spare=None) -> None:
    """The diagonal and the mean marker named, in the ``spare`` (empty) axes if given, else under the panels: where it
    covers nothing."""
    handles = [
        Line2D([], [], color=COLORS["reference"], linestyle="--", label='"all free" (diagonal): above it, better'),
        mean_handle(COLORS["reference"], MEAN_SAID.format("panel")),  # in a neutral grey for the panel's colour
    ]
    if spare is not None:  # wrapped to the slot, and out of the layout: a wide legend there squeezed every column
        for handle in handles:
            handle.set_label("\n".join(textwrap.wrap(str(handle.get_label()), 26)))
        spare.legend(handles=handles, loc="center", fontsize=9, frameon=False).set_in_layout(False)
    else:
        fig.legend(handles=handles, loc="outside lower center", ncols=2, fontsize=9, frameon=False)
