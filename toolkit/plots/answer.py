"""Chapter 04's answer in one panel (review r25a: the panel that carried it was third of five, and half the answer,
the python-fcl runs, and two of four scenarios were not drawn).

:func:`answer_ratios` draws, for every scenario and sampler, total time with / without prediction inside the paper's
Algorithm 1 for each series of ``{"<scenario>, <series>": {sampler: ratio}}`` (the rows of
:func:`toolkit.teaching.checker_scope.compact`: the paper's Table 3, our accurate network with our fast checker
(compiled in 3D, numpy in 2DS) and with python-fcl on both sides), on a log axis against the line at 1 and the tie
band; with ``means``, each of our series' mean-based ratio (Table 3's statistic) as a short bar across its median's
x (reader r31d: rings around the points overlapped them).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure
from matplotlib.legend_handler import HandlerTuple
from matplotlib.lines import Line2D

from toolkit.planning.sampling import PAPER_SAMPLERS
from toolkit.plots.alt import Part, describe
from toolkit.plots.palette import COLORS, PAGE_WIDTH, series_style
from toolkit.plots.timings import band_words, log_ticks

MARKERS = ("s", "o", "^")  # a series' marker, beside its colour
SPREAD = 0.28  # a series' offset from its sampler's tick: a sampler's three series side by side, nearer each other
# than a neighbour's (review r29d: at 0.32 a triangle sat nearer the next sampler's square), a faint line between
MEAN_WORDS = "short level bars, in each series' colour: our ratios of mean times (Table 3's statistic)"
BAR = 190  # a mean's bar, its scatter size (points squared): wider than a marker, so it shows on both sides of one


def answer_ratios(
    rows: dict[str, dict[str, float]],
    *,
    tie: float,
    names: dict[str, str] | None = None,
    spans: dict[str, dict[str, tuple[float, float]]] | None = None,
    means: dict[str, dict[str, float]] | None = None,
) -> Figure:
    """One panel: a group of four samplers per scenario, one point per series in each, the tie band ``1 ± tie``
    shaded darker than the page's other bands, and the series named in a legend above (``names`` renames them);
    ``spans``: a whisker per point of the rows it names (the middle half of the queries' ratios); ``means``: a short
    bar across each point of the rows it names, at that series' ratio of mean times (review r28d: the
    paper's squares are means, our filled markers medians, and our means were not drawn)."""
    scenarios = list(dict.fromkeys(label.split(", ", 1)[0] for label in rows))
    series = list(dict.fromkeys(label.split(", ", 1)[1] for label in rows))
    names = names or {}
    fig = Figure(figsize=(PAGE_WIDTH, 5.5), layout="constrained")  # review r30d: 20 % taller, the groups apart
    ax = fig.subplots()
    ax.axhspan(
        1 - tie,
        1 + tie,
        facecolor=COLORS["shade"],
        edgecolor=COLORS["reference"],
        alpha=0.9,
        zorder=0,
        label=band_words(tie),
    )
    ax.axhline(1.0, color=COLORS["ink"], linewidth=1.0, zorder=1)
    drawn, parts = _series(ax, rows, scenarios, series, names, spans or {})
    rings, ring_handles = _rings(ax, means or {}, scenarios, series)
    drawn += rings
    _groups(ax, scenarios)
    ax.set_ylim(min(*drawn, 1 - tie) / 1.25, max(*drawn, 1 + tie) * 1.25)
    log_ticks(ax)
    ax.set_ylabel("total time with / without\n(log scale; below 1: saves)")
    ax.set_xlabel("sampler, grouped by scenario", labelpad=24)  # under the scenarios' names
    handles: list = ax.get_legend_handles_labels()[0]
    labels = ax.get_legend_handles_labels()[1]
    if ring_handles:  # one entry, a bar in each series' colour (review r30d: the orange one was not shown)
        handles, labels = [*handles, tuple(ring_handles)], [*labels, MEAN_WORDS]
    fig.legend(  # over the panel: long names, a row each
        handles,
        labels,
        loc="outside upper center",
        ncol=1,
        fontsize=9,
        frameon=False,
        handler_map={tuple: HandlerTuple(ndivide=None, pad=0.6)},
    )
    points = [v for row in rows.values() for v in row.values()]
    below = int(np.sum(np.array(points) <= 1 - tie))
    text = (
        "Inside the paper's Algorithm 1, total time with prediction over time without, per scenario and sampler, "
        f"log scale, against the line at 1 and the shaded {band_words(tie)}: {len(points)} points in "
        f"{len(series)} series, {below} of them at or below {1 - tie:.2f}"
        + (", whiskers spanning the middle half of the queries' ratios where a series has them" if spans else "")
        + (", a bar across each of our points at its series' ratio of mean times." if means else ".")
    )
    return describe(fig, text, parts)


def _groups(ax, scenarios: list[str]) -> None:
    """The x axis: a group of :data:`PAPER_SAMPLERS` per scenario, a line between groups, a faint dotted one between a
    group's samplers (which three points belong together), the samplers' names as ticks, the scenario's under them."""
    width = len(PAPER_SAMPLERS) + 1  # a scenario's samplers, and a gap
    for i in range(1, len(scenarios)):
        ax.axvline(i * width - 1, color=COLORS["shade"], linewidth=1.0, zorder=0)
    for i in range(len(scenarios)):
        for j in range(1, len(PAPER_SAMPLERS)):
            ax.axvline(i * width + j - 0.5, color=COLORS["shade"], linewidth=0.6, linestyle=":", zorder=0)
    ticks = [i * width + j for i in range(len(scenarios)) for j in range(len(PAPER_SAMPLERS))]
    ax.set_xticks(ticks, list(PAPER_SAMPLERS) * len(scenarios), fontsize=9)
    ax.set_xlim(-0.7, len(scenarios) * width - 1.3)
    for i, scenario in enumerate(scenarios):  # each group's name under its samplers' names, a fixed distance below
        ax.annotate(
            scenario,
            (i * width + 1.5, 0),
            xycoords=ax.get_xaxis_transform(),
            xytext=(0, -17),
            textcoords="offset points",
            ha="center",
            va="top",
            fontsize=10,
            weight="bold",
        )


def _series(ax, rows, scenarios: list[str], series: list[str], names: dict[str, str], spans) -> tuple[list, list]:
    """Each series' points, its scenarios in groups of :data:`PAPER_SAMPLERS` and a series a little left or right of
    a sampler's tick, with a whisker where ``spans`` gives one; returns every value drawn and one :class:`Part` a
    series (its numbers, for the text alternative)."""
    width = len(PAPER_SAMPLERS) + 1
    drawn: list[float] = []
    parts = []
    for k, name in enumerate(series):
        cells = []
        for i, scenario in enumerate(scenarios):
            ratios = rows.get(f"{scenario}, {name}", {})
            x = [i * width + j + (k - 1) * SPREAD for j, s in enumerate(PAPER_SAMPLERS) if s in ratios]
            y = [ratios[s] for s in PAPER_SAMPLERS if s in ratios]
            whiskers = spans.get(f"{scenario}, {name}", {})
            for xi, s in zip(x, (s for s in PAPER_SAMPLERS if s in ratios)):
                if s in whiskers:
                    ax.vlines(xi, *whiskers[s], color=series_style(k)["color"], linewidth=1.4, zorder=2)
                    drawn += list(whiskers[s])
            ax.plot(
                x,
                y,
                linestyle="none",
                marker=MARKERS[k % len(MARKERS)],
                color=series_style(k)["color"],
                markersize=6,
                markeredgecolor=COLORS["ink"],
                markeredgewidth=0.6,
                zorder=3,
                label=names.get(name, name) if i == 0 else None,
            )
            drawn += y
            cells.append((scenario, *(_cell(ratios.get(s), whiskers.get(s)) for s in PAPER_SAMPLERS)))
        parts.append(
            Part(names.get(name, name), "total time with / without", ("scenario", *PAPER_SAMPLERS), tuple(cells))
        )
    return drawn, parts


def _rings(ax, means: dict[str, dict[str, float]], scenarios: list[str], series: list[str]) -> tuple[list, list]:
    """A short bar at each ratio of ``means``, across the x of the filled point of the same label and sampler (reader
    r31d: rings overlapped the points). Returns the values drawn, and a bar per colour for the legend's one entry."""
    width = len(PAPER_SAMPLERS) + 1
    x, y, colors = [], [], []
    for k, name in enumerate(series):
        for i, scenario in enumerate(scenarios):
            ratios = means.get(f"{scenario}, {name}", {})
            for j, s in enumerate(PAPER_SAMPLERS):
                if s in ratios:
                    x.append(i * width + j + (k - 1) * SPREAD)
                    y.append(ratios[s])
                    colors.append(series_style(k)["color"])
    if x:
        # under the markers (reader r32d: a bar over the next series' square hid which mark was which), each marker
        # whole, the bar's ends on both sides of it (reader r31d: rings hid dots)
        ax.scatter(x, y, s=BAR, marker="_", color=colors, linewidths=2.6, zorder=2.5)
    handles = [
        Line2D([], [], linestyle="none", marker="_", markersize=BAR**0.5, markeredgewidth=2.6, markeredgecolor=c)
        for c in dict.fromkeys(colors)
    ]
    return y, handles


def _cell(ratio: float | None, whisker: tuple[float, float] | None) -> str:
    """A point's number for the text alternative: "1.13", or "1.13 (0.77–1.59)" with its whisker."""
    if ratio is None:
        return ""
    return f"{ratio:.2f}" + (f" ({whisker[0]:.2f}–{whisker[1]:.2f})" if whisker else "")
