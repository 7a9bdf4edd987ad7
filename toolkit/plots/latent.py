"""Where workspaces' latent codes lie (paper §III-A; notebook 02, §7): :func:`latent_scatter` draws ``z`` projected
to 2D, one point per workspace and one panel per group, so that a reader sees whether unseen workspaces land where
the training ones do. Nothing here calls ``show()``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
from matplotlib.figure import Figure

from toolkit.plots.alt import Part, describe
from toolkit.plots.cae import AREA, FEW, GREY
from toolkit.plots.palette import COLORS, MARKER_NAMES, MARKERS, PAGE_WIDTH, SEQUENTIAL_CMAP, series_style


def latent_scatter(
    points: dict[str, np.ndarray],
    *,
    color: dict[str, np.ndarray] | None = None,
    color_label: str = "",
    color_range: tuple[float, float] | None = None,
    highlight: str | None = None,
    markers: Mapping[str, str] | None = None,
    xlabel: str = "PC 1",
    ylabel: str = "PC 2",
    title: str = "Latent codes, projected to 2D",
) -> Figure:
    """One marker per workspace: ``points[group]`` is ``(n, 2)``, e.g. the first two principal components of ``z``.

    One panel per group on shared axes, the others grey (a few dozen larger, on top): whether the groups form one cloud
    reads from where the colour lies on the grey, not from telling hundreds of small markers apart by shape.
    ``color[group]`` ``(n,)`` (optional): a value per workspace shown on one shared colour scale (e.g. its share of
    occupied cells), from ``color_range`` when given (reader r40b: two maps side by side on one scale), else from the
    values' own lowest to highest. ``highlight``: a group drawn with larger, thick black-edged markers (e.g. a few
    training workspaces). ``markers[group]``: its marker shape, grey or not (reader r49b: a chapter's shapes for its
    groups of grids kept from figure to figure); else :data:`MARKERS` in turn.
    """
    fig = Figure(figsize=(PAGE_WIDTH, 3.6 if len(points) > 1 else 5.2), layout="constrained")
    axes = fig.subplots(1, len(points), squeeze=False, sharex=True, sharey=True)[0]
    if color:
        low, high = color_range or (min(np.min(c) for c in color.values()), max(np.max(c) for c in color.values()))
    shape = {name: (markers or {}).get(name, MARKERS[k % len(MARKERS)]) for k, name in enumerate(points)}
    said = []
    for k, (ax, (name, xy)) in enumerate(zip(axes, points.items())):
        xy = np.asarray(xy)
        others = {other: np.asarray(v) for other, v in points.items() if other != name}
        for other, rest in others.items():  # grey: where this group lies among them; a few dozen larger, on top
            grey = dict(GREY[len(rest) <= FEW], marker=shape[other])
            ax.scatter(*rest.T, color=COLORS["reference"], edgecolors=COLORS["ink"], **grey)
        big = name == highlight
        size = (60 if big else 22) * AREA.get(shape[name], 1.0)  # a triangle as large to the eye as a square
        style: dict[str, Any] = dict(s=size, edgecolors=COLORS["ink"], linewidths=1.4 if big else 0.3)
        style.update(marker=shape[name], c=series_style(k)["color"])
        if color:
            style.update(c=color[name], cmap=SEQUENTIAL_CMAP, vmin=low, vmax=high)
        drawn = ax.scatter(xy[:, 0], xy[:, 1], label=f"{name} ({len(xy)})", alpha=0.9, zorder=2, **style)
        shapes = f"{len(xy)} {MARKER_NAMES[shape[name]]}"  # reader r48b: the shapes in the figure, not in prose only
        ax.set_title(f"{name}: {shapes}" + ("\nthe others grey" if others else ""), fontsize=10)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel if k == 0 else "")
        ax.tick_params(labelsize=9)
        where = f"{name}: {len(xy)} workspaces ({MARKER_NAMES[style['marker']]}{', larger' if big else ''}) around "
        where += f"({np.mean(xy[:, 0]):.3g}, {np.mean(xy[:, 1]):.3g})"
        if color:
            where += f", {color_label or 'value'} {np.min(color[name]):.3g} to {np.max(color[name]):.3g}"
        said.append(where)
    if color:
        fig.colorbar(drawn, ax=list(axes), label=color_label)
    fig.suptitle(title, fontsize=11)
    text = f"{title}: {xlabel} across, {ylabel} up, one panel per group, the others grey (over it if {FEW} or fewer). "
    parts = [
        _cloud_part(name, np.asarray(xy), (xlabel, ylabel), color and (color_label, color[name]))
        for name, xy in points.items()
    ]
    return describe(fig, text + "; ".join(said) + ".", parts)


def _cloud_part(name: str, xy: np.ndarray, labels: tuple[str, str], value) -> Part:
    """One group's panel of :func:`latent_scatter`: where its ``xy (n, 2)`` points lie (quartiles along each axis),
    and the range of the ``value`` = ``(label, (n,))`` they are coloured by, if any."""
    stats = ("lowest", "first quartile", "median", "third quartile", "highest")
    columns = ("along", *stats)
    rows = [
        (label, *(f"{v:.3g}" for v in np.quantile(xy[:, k], (0, 0.25, 0.5, 0.75, 1)))) for k, label in enumerate(labels)
    ]
    if value:
        rows.append((value[0] or "value", *(f"{v:.3g}" for v in np.quantile(value[1], (0, 0.25, 0.5, 0.75, 1)))))
    return Part(f"{name} ({len(xy)})", f"where the {len(xy)} points of {name} lie", columns, tuple(rows))
