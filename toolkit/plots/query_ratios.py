"""Each query's own time ratio with / without prediction, read as a verdict reads it (paper §V, Table 3's claim).

A planning verdict over many queries reads the median of each query's own ratio (its time with prediction over its
own time without), not a ratio of means: a few slow queries move a mean. :func:`own_ratios` draws that median for
every scenario and sampler in one panel, the middle half of the ratios as a whisker, against the line at 1 and the
tie band; each point's colour and marker say what its median reads as (saves, a tie, costs). A second series (the same
network with another exact checker, ``slow``) sits beside the first in each sampler's slot, its markers hollow, so the
two are told apart without colour. ``docs/results.md`` shows it first, for the accurate network inside Algorithm 1,
with our compiled checker (filled) and with python-fcl on both sides (hollow).

:func:`means_grid` draws the page's Figures 2 and 3: mean time ratios (Table 3's statistic) of several series, one
panel per scenario in a grid of two columns, one legend over them all, one log axis shared by every panel. Its series
take a hue and a marker each (:data:`MEANS_STYLES`), no pair of them one of the three verdict looks of
:func:`own_ratios`, so a reader who carries Figure 1's key into Figure 2 cannot misread it. Each returns a
matplotlib ``Figure``; never calls ``show()``.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
from matplotlib.figure import Figure
from matplotlib.legend_handler import HandlerTuple
from matplotlib.ticker import NullLocator
from matplotlib.transforms import blended_transform_factory

from toolkit.plots.alt import Part, describe
from toolkit.plots.palette import COLORS, LINE_COLORS, OKABE_ITO, PAGE_WIDTH, halo, series_style
from toolkit.plots.ratio_bands import (  # noqa: F401  (re-exported: answer.py and the tests read them here)
    EDGE_HATCH,
    EDGE_WORDS,
    NOISE_HATCH,
    NOISE_WORDS,
    band_edges,
    edge_band,
    edge_labels,
    hatch_round,
    noise_bands,
)
from toolkit.plots.timings import band_words, legend_above, log_ticks, ratio_parts, tie_band
from toolkit.util.verdicts import COSTS, SAVES, TIE, TIES, time_verdict

READS = (COSTS, TIES, SAVES)  # what a median reads as, in the legend's order; each its own colour and marker
GAP = 0.4  # the room between two scenarios' groups of samplers, beyond a sampler's own (reader r42f: the width it
# took is the pairs' now)
APART = 0.22  # where a scenario has two series: each point this far from its sampler's tick, the first to the left, so
# a pair stands closer than two samplers' points (reader r42f: at 0.27 a hollow point touched the next sampler's)
SIZE = 6.5  # points, a marker (a hollow triangle 2 more): a pair at :data:`APART` clears its twin (reader r42f)
BELOW_1 = (0.7,)  # labelled on :func:`own_ratios`' axis, where savings lie, beside its 1-2-5 steps (r27f: no 0.8); the
# tie band's edges on the right (:func:`band_edges`; r30f: "0.9" crowded the "1")
NEAR_1 = 1.25  # :func:`means_grid`'s extra ticks this close to 1 are labelled on the right, away from the "1"
Cells = Mapping[str, Mapping[str, tuple[float, float, float]]]  # {scenario: {sampler: (median, q1, q3)}}
MEANS_STYLES = (  # :func:`means_grid`'s series in turn: colour, marker, hollow; no verdict look of own_ratios
    (LINE_COLORS[5], "D", False),  # grey diamonds: the paper's own numbers (r28f: its cross read as the pluses)
    (LINE_COLORS[3], "X", False),  # bluish green crosses: a network with our compiled checker
    (LINE_COLORS[4], "*", False),  # reddish purple stars: another network with our compiled checker
    (OKABE_ITO["sky blue"], "h", False),  # sky-blue hexagons, outlined in black: that network with python-fcl (reader
    # r39f: the stars' hue, hollow, could not be told from the stars; r33f: orange, Figure 1's "tie", meant two things;
    # sky blue is under 3:1 on white, so the halo's black ring carries it)
    (LINE_COLORS[3], "P", True),  # bluish green, hollow pluses: the first network with python-fcl
)
"""Reader r31f: Figure 1's blue, vermillion and black are its verdicts, its circle, square and triangle too, so no
series here takes any of them; each series its own colour (reader r39f: a shared hue could not be told apart)."""
EDGE_NAME, TIE_EDGE_NAME = "noise band's edges", "tie band's edges"  # what the labels on the right are
Y_LABEL = "time with / without\n(log axis; below 1: saves)"  # reader r31f: the axis is log, and says so
MEANS_SIZE = 5.5  # points (r28f asked 1.5 times 5; r32f 1.5 times more, but then neighbouring markers would touch)
STAR_SCALE = 1.35  # a star fills less of its box than the other markers: drawn this much larger, it reads as large
MEANS_SPREAD = 1.0  # of the space between two samplers, what a sampler's points spread over: evenly spaced, so
# neighbours within and across samplers stand as far apart (reader r39f: a star and a hexagon touched)


def own_ratios(
    cells: Cells,
    *,
    title: str,
    tie: float = TIE,
    slow: Cells | None = None,
    series: tuple[str, str] = ("", ""),
    edge: float | None = None,
    width: float = PAGE_WIDTH,
) -> Figure:
    """``{scenario: {sampler: (median, q1, q3)}}`` of each query's own ratio, with / without prediction: a point per
    scenario and sampler at its median, a whisker over its middle half (``q1`` to ``q3``), on a log axis with the
    line at 1 and the shaded tie band from ``1 - tie`` to ``1 + tie``. A point's colour and marker give the verdict
    its median reads as (:func:`toolkit.util.verdicts.time_verdict`), named in a legend over the panel; each point's
    sampler is written under it, each scenario under its samplers. ``slow``, where given, is a second series of the
    same form (any of the scenarios), drawn hollow beside the first; ``series`` names the two in the legend. ``edge``,
    where given, hatches the band from ``1 - edge`` to ``1 + edge`` round the tie band (:func:`edge_band`): a cost or
    saving there lies in the noise band (review r30f, item 2); its edges are labelled outside the axes, on the right
    (:func:`edge_labels`; without it, the tie band's). The legend stands between the title and the axes. ``width``:
    inches (a page's column may be wider than a chapter's)."""
    slow = {} if slow is None else slow
    fig = Figure(figsize=(width, 3.9))
    ax = fig.subplots()
    names: list[str] = []  # tick labels: the samplers
    ticks: list[float] = []  # their x
    centres: list[float] = []  # each scenario's middle
    for k, (scenario, by_sampler) in enumerate(cells.items()):
        start = len(names) + k * GAP
        x = start + np.arange(len(by_sampler))  # (samplers,)
        second = slow.get(scenario, {})
        _points(ax, x - APART * bool(second), by_sampler, tie, hollow=False)
        at = [i for i, sampler in enumerate(by_sampler) if sampler in second]
        _points(ax, x[at] + APART, {s: second[s] for s in by_sampler if s in second}, tie, hollow=True)
        names += list(by_sampler)
        ticks += list(x)
        centres.append(float(x.mean()))
    pairs = _legend_entries(ax, series if slow else None, None if edge is None else (edge, tie))
    ax.axhline(1.0, color=COLORS["ink"], linewidth=1.0, zorder=1)
    tie_band(ax, tie)
    _sampler_axis(ax, cells, names, ticks, centres)
    drawn = [v for table in (cells, slow) for by in table.values() for value in by.values() for v in value]
    _own_axis(ax, drawn, tie, [] if edge is None else [1 - edge, 1 + edge])
    ax.set_ylabel(Y_LABEL, fontsize=9)
    _legend_under_title(fig, ax, pairs, title)
    words = _words(cells, title, tie, series[0] if slow else "")
    words += f" Hollow points beside them, {series[1]}. {_counts(slow, tie)}" if slow else ""
    words += f" Hatched round the tie band, {EDGE_WORDS.format(low=1 - edge, high=1 + edge)}." if edge else ""
    words += (
        " The noise band's edges are labelled on the right." if edge else " The band's edges are labelled on the right."
    )
    if not slow:
        return describe(fig, words, [_part(cells, title)])
    return describe(
        fig, words, [_part(cells, f"{title}, {series[0]} (filled)"), _part(slow, f"{title}, {series[1]} (hollow)")]
    )


def _sampler_axis(ax, cells: Cells, names: list[str], ticks: list[float], centres: list[float]) -> None:
    """:func:`own_ratios`' x axis: each sampler's name under its ``ticks``, each scenario's under its ``centres``, a
    line between two scenarios."""
    ax.set_xticks(ticks, names)
    ax.set_xticks([c + (len(cells[s]) + GAP) / 2 for c, s in zip(centres[:-1], cells)], minor=True)
    ax.grid(True, axis="x", which="minor", color=COLORS["shade"], linewidth=0.8)
    ax.tick_params(axis="x", which="minor", length=0)
    ax.tick_params(labelsize=9)
    groups = ax.secondary_xaxis("bottom")
    groups.set_xticks(centres, list(cells))
    groups.tick_params(length=0, pad=16, labelsize=10)
    ax.set_xlabel("sampler, by scenario", labelpad=16)  # under the scenarios' names
    ax.set_xlim(-0.55, ticks[-1] + 0.55)  # reader r33f: the last hollow point clears the frame


def _own_axis(ax, drawn: list[float], tie: float, edges: list[float]) -> None:
    """:func:`own_ratios`' log axis over every ``drawn`` value, the tie band and the noise band's ``edges``, labelled at
    its 1-2-5 steps and :data:`BELOW_1` on the left, the noise band's edges on the right (:func:`edge_labels`; reader
    r39f: on the left "1.18", "1" and "0.82" crowded)."""
    ax.set_yscale("log")
    ax.set_ylim(min(*drawn, *edges, 1 - tie) / 1.15, max(*drawn, *edges, 1 + tie) * 1.15)
    log_ticks(ax)
    low, high = ax.get_ylim()
    every = (*ax.get_yticks(), *BELOW_1)  # r25c: 0.7 alone below 1; r39f: the band's edges in the legend only
    shown = sorted({round(s, 2) for s in every if low <= s <= high})
    ax.set_yticks(shown, [f"{s:g}" for s in shown])
    ax.yaxis.set_minor_locator(NullLocator())  # review r27f: an unlabelled tick under 0.7 read as a missing label
    # reader r41f: the edges a verdict turns on, on the right; reader r42f: 1.18 and 1.10 crowded there, so where the
    # noise band is drawn only its edges are, the tie band's in the legend's words ("1.10 or more")
    # reader r44e, home 3: the edges named beside them, so 0.82 and 1.18 are not read as the tie band's 0.90 and 1.10
    edge_labels(ax, sorted(edges) if edges else [1 - tie, 1 + tie], EDGE_NAME if edges else TIE_EDGE_NAME)


def _legend_under_title(fig: Figure, ax, pairs: dict, title: str) -> None:
    """:func:`own_ratios`' legend between its title and its axes (reader r42e, home figure 1: over the title it read as
    a separate figure), each verdict's entry its ``pairs`` of markers (filled and hollow, as the plot draws them) side
    by side; the title raised over it."""
    handles, labels = ax.get_legend_handles_labels()
    handles = [pairs.get(label, handle) for handle, label in zip(handles, labels)]
    legend = fig.legend(
        handles,
        labels,
        loc="lower center",
        bbox_to_anchor=(0.5, 1.0),
        bbox_transform=blended_transform_factory(fig.transFigure, ax.transAxes),  # centred on the figure, as before
        ncol=2,
        fontsize=9,
        frameon=False,
        borderaxespad=0.2,
        handler_map={tuple: HandlerTuple(ndivide=None, pad=0.6)},
    )
    height = legend.get_window_extent().height * 72 / fig.dpi  # points
    ax.set_title(title, fontsize=10, pad=height + 6)
    fig.tight_layout()


def _legend_entries(ax, series: tuple[str, str] | None, edge: tuple[float, float] | None = None) -> dict:
    """The legend's entries: each verdict once, by its colour and shape, drawn as the plot draws its points, filled
    and, where there are two ``series``, hollow beside it (reader r41f: a verdict's hollow look was in no entry);
    and which series a point's fill names, on a plain circle (reader r40e, home figure 1: no half-filled icon, a
    marker the plot never draws); the caption counts which checker's points read as each verdict. Returns each
    verdict's words and its icons, for :func:`_legend_above`."""
    pairs = {}
    for k, reads in enumerate(READS):
        look = series_style(k)
        icons = [
            ax.plot(
                [],
                [],
                linestyle="none",
                marker=look["marker"],
                markersize=SIZE + 2 * (look["marker"] == "^" and hollow),
                label=None if hollow else _read(reads),
                **_fill(look["color"], hollow),
            )[0]
            for hollow in ((False, True) if series else (False,))
        ]
        pairs[_read(reads)] = tuple(icons)
    if edge:  # drawn here, so the legend lists it under the verdicts (:func:`edge_band`, ``(edge, tie)``)
        edge_band(ax, *edge)
    for hollow, name in zip((False, True), series or ()):
        label = f"{'hollow' if hollow else 'filled'}: {name}"
        ax.plot([], [], linestyle="none", marker="o", markersize=SIZE, label=label, **_fill(LINE_COLORS[5], hollow))
    return pairs


def _points(ax, x: np.ndarray, by_sampler: Mapping[str, tuple[float, float, float]], tie: float, hollow: bool) -> None:
    """One series' points of a scenario at ``x`` (samplers,): a whisker over each middle half, a marker at each median
    in the colour and shape of what it reads as, hollow for the second series."""
    if not by_sampler:
        return
    values = np.array(list(by_sampler.values()))  # (samplers, 3): median, q1, q3
    ax.errorbar(
        x,
        values[:, 0],
        yerr=[values[:, 0] - values[:, 1], values[:, 2] - values[:, 0]],
        fmt="none",
        ecolor=COLORS["ink"],
        capsize=3,
        linewidth=1,
        zorder=2,
    )
    for xi, median in zip(x, values[:, 0]):
        look = series_style(READS.index(time_verdict(median, tie=tie)))
        wide = look["marker"] == "^"  # reader r39f: a hollow triangle's small centre read as filled: drawn larger,
        (point,) = ax.plot(  # its white centre reads, as the hollow circles' and squares' do
            [xi],
            [median],
            linestyle="none",
            marker=look["marker"],
            markersize=SIZE + 2 * (wide and hollow),
            zorder=3,
            **_fill(look["color"], hollow),
        )
        point.set_path_effects(halo(1.0))


def _fill(colour: str, hollow: bool) -> dict:
    """A marker's colours: filled in ``colour``, or hollow (white inside, ``colour`` round it, a thicker edge)."""
    if hollow:
        return dict(color=colour, markerfacecolor=COLORS["free"], markeredgecolor=colour, markeredgewidth=1.8)
    return dict(color=colour)


def _read(reads: str) -> str:
    """A legend's entry: where a median that reads as ``reads`` lies (reader r51e: not "costs" or "saves", which a
    point inside the noise band does not show); the fill key's circles are grey, as black is a verdict's colour."""
    return {COSTS: "median 1.10 or more", TIES: "median in the tie band", SAVES: "median 0.90 or less"}[reads]


def _words(cells: Cells, title: str, tie: float, label: str = "") -> str:
    """The text alternative: what is drawn (``label``: the series, where there are two), then :func:`_counts`."""
    which = f" ({label}: filled)" if label else ""
    return (
        f"{title}: the median of each query's own time ratio with prediction over without, a point per scenario and "
        f"sampler{which}, a whisker over the middle half of the ratios, log scale, read against the line at 1 and the "
        f"shaded {band_words(tie)}. {_counts(cells, tie)}"
    )


def _counts(cells: Cells, tie: float) -> str:
    """How many medians read as each verdict, and their range."""
    medians = [value[0] for by in cells.values() for value in by.values()]
    said = [time_verdict(m, tie=tie) for m in medians]
    counts = ", ".join(f"{said.count(r)} read as “{r}”" for r in READS)
    return f"Of {len(medians)} medians, from {min(medians):.2f} to {max(medians):.2f}: {counts}."


def _part(cells: Cells, title: str) -> Part:
    """The longer description: each scenario's row, each sampler's median and middle half."""
    samplers = tuple(dict.fromkeys(s for by in cells.values() for s in by))
    rows = tuple(
        (scenario, *(f"{by[s][0]:.2f} ({by[s][1]:.2f}–{by[s][2]:.2f})" for s in samplers))
        for scenario, by in cells.items()
    )
    return Part(
        title,
        "median of each query's own ratio (middle half); below 1, prediction saves time",
        ("scenario", *samplers),
        rows,
    )


def means_grid(
    panels: Mapping[str, Mapping[str, Mapping[str, float]]],
    *,
    tie: float = TIE,
    ylim: tuple[float, float] | None = None,
    ticks: tuple[float, ...] = (),
    row_height: float = 2.3,
    samplers: tuple[str, ...] = ("BS", "OB", "G", "BT"),
    noise: tuple[float, float] | None = None,
    width: float = PAGE_WIDTH,
) -> Figure:
    """``{panel title: {series: {sampler: ratio}}}`` of time ratios with / without prediction (below 1: saves), one
    panel per title in a grid of two columns: a point per series and sampler (a series keeps its place, colour and
    marker in every panel, :data:`MEANS_STYLES`), read against the line at 1 and the shaded tie band, on one log axis
    shared by every panel (``ylim``, where given; else every point's range; ``ticks`` labelled beside its 1-2-5 steps,
    those within 25 % of 1, e.g. the tie band's edges, on the right of each row, apart from the "1"; ``row_height``
    inches a row of panels), the legend once, over the grid. ``noise``, where given, is a ratio of means' noise band
    (twice timing's reach, ``costs.floors``): hatched round the tie band in every panel (:func:`hatch_round`; reader
    r31f: single cells were read), named in the legend; pass its edges in ``ticks`` to label them on the right (reader
    r33f: on the left "1.24", "1" and "0.84" crowded; r36f: the tie band's edges there read as its).
    ``width``: inches (a page's column may be wider than a chapter's).
    The text alternative counts each series' points as the page's rule reads them
    (:func:`toolkit.util.verdicts.time_verdict` on the ratio shown to two decimals)."""
    names = list(dict.fromkeys(name for series in panels.values() for name in series))
    if len(names) > len(MEANS_STYLES):
        raise ValueError(f"{len(names)} series: means_grid has looks for {len(MEANS_STYLES)}")
    rows = -(-len(panels) // 2)
    fig = Figure(figsize=(width, row_height * rows + 1.1))
    grid = fig.subplots(rows, 2, squeeze=False, sharey=True)
    axes = list(grid.flat)
    said = [_means_panel(ax, title, series, names, samplers, tie) for ax, (title, series) in zip(axes, panels.items())]
    for ax in axes[len(panels) :]:
        ax.set_visible(False)
    said += noise_bands(axes[: len(panels)], noise, tie)
    for ax in grid[:, 0]:
        ax.set_ylabel(Y_LABEL, fontsize=10)
    for ax in grid[-1, :]:
        ax.set_xlabel("sampler", fontsize=10)
    drawn = [float(r) for series in panels.values() for by in series.values() for r in by.values()]
    drawn += list(noise or ())
    low, high = ylim if ylim is not None else (min(*drawn, 1 - tie) / 1.3, max(*drawn, 1 + tie) * 1.3)
    axes[0].set_yscale("log")
    axes[0].set_ylim(low, high)
    log_ticks(axes[0])  # shared by every panel
    beside = [t for t in ticks if low <= t <= high and 1 / NEAR_1 < t < NEAR_1]  # would crowd the "1"
    if (
        ticks
    ):  # the tie band's edges on the right (r33f: the floor's, on the left, crowded the "1"; the legend names them)
        every = (*axes[0].get_yticks(), *ticks)
        shown = sorted({round(t, 6) for t in every if low <= t <= high and t not in beside})
        axes[0].set_yticks(shown, [f"{t:g}" for t in shown])
    for ax in axes[: len(panels)] if beside else ():  # r25c: 0.9, 1 and 1.1 crammed on the left; r28f: every panel
        band_edges(ax, beside, 9)
    legend_above(fig, axes[:1], 1)  # one column: two of these names side by side overflow the page
    return _means_described(fig, panels, names, samplers, tie, said)


def _means_panel(ax, title: str, series: Mapping[str, Mapping[str, float]], names, samplers, tie: float) -> str:
    """One panel of :func:`means_grid`: a point per series and sampler, the line at 1 and the tie band; its range in
    words."""
    for name, ratios in series.items():
        k = names.index(name)
        colour, marker, hollow = MEANS_STYLES[k]
        x = np.arange(len(samplers)) + (k - (len(names) - 1) / 2) * MEANS_SPREAD / len(names)
        (line,) = ax.plot(
            x,
            [ratios[s] for s in samplers],
            linestyle="none",
            marker=marker,
            markersize=MEANS_SIZE * STAR_SCALE ** (marker == "*"),
            label=name,
            zorder=3,
            **_fill(colour, hollow),
        )
        line.set_path_effects(halo(1.0))
    every = np.array([[ratios[s] for s in samplers] for ratios in series.values()])  # (series, samplers)
    ax.axhline(1.0, color=COLORS["ink"], linewidth=1.0, zorder=1)
    tie_band(ax, tie)
    ax.set_xticks(np.arange(len(samplers) - 1) + 0.5, minor=True)  # a sampler's points between two lines
    ax.grid(True, axis="x", which="minor", color=COLORS["shade"], linewidth=0.8)
    ax.tick_params(axis="x", which="minor", length=0)
    ax.set_xticks(np.arange(len(samplers)), samplers)
    ax.set_xlim(-0.6, len(samplers) - 0.4)  # reader r32f: the outer points clear the spines
    ax.set_title(title, fontsize=11)
    ax.tick_params(labelsize=10)  # reader r33f: 9 px tick text at the page's width
    return f"{title}: ratios from {every.min():.2f} to {every.max():.2f}"


def _means_described(fig: Figure, panels, names, samplers, tie: float, said: list[str]) -> Figure:
    """:func:`means_grid`'s text alternative: each panel's range, each series' points counted as the page's rule
    reads them, and a table per panel."""
    read: dict[str, list[str]] = {name: [] for name in names}  # each series' points, as the page's rule reads them
    for series in panels.values():
        for name, ratios in series.items():
            read[name] += [time_verdict(round(float(ratios[s]), 2), tie=tie) for s in samplers]
    counted = "; ".join(
        f"{name}: {verdicts.count(SAVES)} of {len(verdicts)} save time ({1 - tie:.2f} or less), "
        f"{verdicts.count(TIES)} tie, {verdicts.count(COSTS)} cost time ({1 + tie:.2f} or more)"
        for name, verdicts in read.items()
    )
    text = (
        "Mean planning time with prediction divided by the mean without, a point per sampler and series, one panel "
        f"per scenario on one log scale, read against the line at 1 and the shaded {band_words(tie)}; below 1 "
        f"prediction saves time. {'; '.join(said)}. Counted by series: {counted}."
    )
    return describe(fig, text, ratio_parts(panels, samplers))
