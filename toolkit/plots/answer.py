"""Chapter 04's answer in a figure (review r25a: the panel that carried it was third of five, and half the answer,
the python-fcl runs, and two of four scenarios were not drawn).

:func:`answer_ratios` draws, for every scenario and sampler, total time with / without prediction inside the paper's
Algorithm 1 for each series of ``{"<scenario>, <series>": {sampler: ratio}}`` (the rows of
:func:`toolkit.teaching.checker_scope.compact`: the paper's Table 3, our accurate network with our fast checker
(compiled in 3D, numpy in 2DS) and with python-fcl on both sides), on a log axis against the line at 1 and the tie
band. With ``means`` (our series' ratios of mean times, Table 3's statistic) it draws two panels (reader r33d: the
large markers compared our medians with the paper's means): above, like for like, the paper's squares beside our
means, filled, with ``floor`` (how far timing alone moved a ratio of means) hatched round the tie band (reader r34d:
0.86 read as a clear saving); below, our medians of each query's own ratio, hollow, each with its middle half, with
``median_floor`` (the median's noise band) hatched (reader r36d), in a legend of their own under the figure.
"""

from __future__ import annotations

import dataclasses

import numpy as np
from matplotlib.figure import Figure
from matplotlib.ticker import NullLocator

from toolkit.planning.sampling import PAPER_SAMPLERS
from toolkit.plots.alt import Part, describe
from toolkit.plots.palette import COLORS, LINE_COLORS, OKABE_ITO, PAGE_WIDTH, halo
from toolkit.plots.query_ratios import NOISE_HATCH, hatch_round
from toolkit.plots.timings import band_words, log_ticks

CHECKERS = {  # reader r44d, item 3: one colour and marker per checker on chapter 04's whole page, none of them a
    # verdict look of the home page's Figure 1 (its circle, square and triangle; its blue, vermillion and black)
    "paper": (LINE_COLORS[5], "D"),  # grey diamonds: the paper's Table 3 (as the results page draws it)
    "fast exact": (LINE_COLORS[3], "X"),  # bluish green crosses: our fast exact checker
    "python-fcl": (LINE_COLORS[4], "h"),  # reddish purple hexagons: python-fcl
    "network": (OKABE_ITO["sky blue"], "P"),  # sky-blue pluses, outlined in ink: the network (section 4 only)
}
SHAPES = {"D": "diamonds", "X": "crosses", "h": "hexagons", "P": "pluses"}  # each marker in words, for a legend
SERIES_CHECKERS = ("paper", "fast exact", "python-fcl")  # the answer figures' series in turn: whose look each takes
MARKERS = tuple(CHECKERS[c][1] for c in SERIES_CHECKERS)  # a series' marker, beside its colour
SPREAD = 0.36  # the distance between two series' points at one sampler, centred on its tick (reader r44d, item 7: at
# 0.25 a circle hid behind a triangle); three series stand :data:`WIDEST` / 2 apart, so the outer ones keep a
# marker's width inside the sampler's slot (reader r33d)
WIDEST = 0.6  # the most a sampler's series span, first to last
SIZE = 6.0  # points, a marker: series at 0.3 stand apart (about 6.3 points at the page's width)
MEANS_TITLE = "Means, Table 3's statistic: the paper's diamonds beside ours"
MEDIANS_TITLE = "Ours, each query's own ratio: its median (hollow), whiskers its middle half"  # r45d: one name


def answer_ratios(
    rows: dict[str, dict[str, float]],
    *,
    tie: float,
    names: dict[str, str] | None = None,
    spans: dict[str, dict[str, tuple[float, float]]] | None = None,
    means: dict[str, dict[str, float]] | None = None,
    floor: tuple[float, float] | None = None,
    median_floor: tuple[float, float] | None = None,
    order: list[str] | None = None,
) -> Figure:
    """A group of four samplers per scenario, one point per series in each, the tie band ``1 ± tie`` shaded, and the
    series named in a legend above, a line each (``names`` renames them); ``spans``: a whisker per point of the rows
    it names (the middle half of the queries' ratios). Without ``means``, one panel of ``rows``; with ``means`` (by
    the labels of the rows they stand beside), two: the rows that ``means`` does not name (the paper's) beside
    ``means``, filled, with ``floor`` hatched round the tie band, and under them the rows it names, hollow, with their
    whiskers, ``median_floor`` hatched (reader r36d: 1.13 read as a clear cost) and their own legend."""
    scenarios = list(dict.fromkeys(label.split(", ", 1)[0] for label in rows))
    series = order or list(dict.fromkeys(label.split(", ", 1)[1] for label in rows))  # a series' style: its place
    names = names or {}
    if means:
        panels = [
            ({label: r for label, r in rows.items() if label not in means} | means, {}, False),
            ({label: rows[label] for label in means if label in rows}, spans or {}, True),
        ]
    else:
        panels = [(rows, spans or {}, False)]
    fig = Figure(figsize=(PAGE_WIDTH, 3.8 * len(panels) + 1.2), layout="constrained")
    axes = fig.subplots(len(panels), 1, squeeze=False)[:, 0]  # each panel its own ticks: read without the other
    one = MEDIANS_TITLE.replace(" (hollow)", "") if spans else MEANS_TITLE  # r39d: each panel names its statistic
    for ax, title in zip(axes, [MEANS_TITLE, MEDIANS_TITLE] if means else [one]):
        ax.set_title(title, fontsize=10)
    parts, counted, every = [], [], []
    for ax, (shown, whiskers, hollow) in zip(axes, panels):
        ax.axhline(1.0, color=COLORS["ink"], linewidth=1.0, zorder=1)
        if median_floor and ax is axes[-1] and (means or spans):  # a panel of medians (r37d: the answer's one)
            _floor(ax, median_floor, tie, MEDIAN_NOISE)
        _tie_band(ax, tie, named=ax is axes[0])
        drawn, found = _series(ax, shown, scenarios, series, names, whiskers, hollow)
        if floor and ax is axes[0] and (means or not spans):  # a panel of means (reader r37d: one, in section 6)
            _floor(ax, floor, tie)  # r61d, item 5: one band across the axis, not strips that read as error bars
        _groups(ax, scenarios)
        every += drawn
        ax.set_ylabel("time with / without (log axis)")
        points = [v for row in shown.values() for v in row.values()]
        counted.append((len(points), int(np.sum(np.array(points) <= 1 - tie))))
        parts += [dataclasses.replace(p, name=f"{_title(ax, means)}{p.name}") for p in found]
    for ax in axes:  # one scale for both panels: a point above reads against one below
        ax.set_ylim(min(*every, 1 - tie) / 1.25, max(*every, 1 + tie) * 1.25)
        log_ticks(ax)
        _near_ticks(ax, not (ax is axes[0] and (means or not spans)), median_floor)  # r48d: not on a panel of means
        ax.set_xlabel("sampler, grouped by scenario", labelpad=24)  # under the scenarios' names
    fig.legend(*_band_first(axes[0]), loc="outside upper center", ncol=1, fontsize=9, frameon=False)  # a line a series
    if means:  # reader r34d: the hollow markers had no legend
        handles, labels = axes[1].get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=1, fontsize=9, frameon=False)
    drawn_series = sum(any(label.endswith(f", {name}") for label in rows) for name in series)
    said = _text(tie, drawn_series, counted, spans, means, None if spans and not means else floor)
    return describe(fig, said + _median_words(median_floor if means or spans else None, bool(means)), parts)


def _near_ticks(ax, labelled: bool = True, band: tuple[float, float] | None = None) -> None:
    """Labelled minor ticks on the left where ``labelled``, at the own ratios' noise ``band``'s edges (reader r49d:
    "1.2" / "0.8" beside a band of 0.82-1.18), else at 0.8 and 1.2 (reader r48d: a panel of means has another band),
    and the tie band's edges 0.9 and 1.1 on a right-hand axis (reader r41d: a value by a band's edge could not be read
    off; r47d: five labels within 0.8-1.2 were crammed)."""
    lo, hi = ax.get_ylim()
    near = [round(t, 2) for t in (band or (0.8, 1.2)) if lo <= t <= hi and labelled]
    ax.set_yticks(near, [f"{t:g}" for t in near], minor=True)
    ax.tick_params(axis="y", which="minor", labelsize=8)
    edges = [t for t in (0.9, 1.1) if lo <= t <= hi]
    right = ax.secondary_yaxis("right")
    right.set_yticks(edges, [f"{t:.2f}" for t in edges])  # reader r59d: 0.90 and 1.10, as the text and legend
    right.yaxis.set_minor_locator(NullLocator())
    right.tick_params(axis="y", labelsize=8)


def _tie_band(ax, tie: float, named: bool) -> None:
    """The tie band, grey, named in the legend (``named``) beside the noise band (reader r39d: not in the ylabel)."""
    label = f"a tie, {1 - tie:.2f}–{1 + tie:.2f}" if named else None
    ax.axhspan(
        1 - tie, 1 + tie, facecolor=COLORS["shade"], edgecolor=COLORS["reference"], alpha=0.9, zorder=0, label=label
    )


def _median_words(band: tuple[float, float] | None, below: bool) -> str:
    """The text alternative's words on the median's noise band, where a panel hatches it."""
    said = MEDIAN_NOISE.format(low=band[0], high=band[1]) if band else ""
    return f" Hatched round the tie band{' below' if below else ''}, {said}." if band else ""


NOISE_WORDS = (  # common46: one rule for every band; reader r45d, item 4: drawn over the paper's diamonds too
    "noise band of our ratios of means (not the paper's), {low:.2f}–{high:.2f}: twice as far from 1 as timing one "
    "computation twice moved a ratio of means, both ways"
)
MEDIAN_NOISE = (  # reader r45d, item 3: "(medians)" read as the band of a ratio of medians, 0.40-1.60
    "noise band of each query's own ratio, {low:.2f}–{high:.2f}: twice as far from 1 as timing one computation twice "
    "moved each query's own ratio, both ways"
)


def _floor(ax, floor: tuple[float, float], tie: float, words: str = NOISE_WORDS) -> None:
    """``floor`` hatched round the tie band across the axis, its ends dotted
    (:func:`~toolkit.plots.query_ratios.hatch_round`, as the results page's Figures 2-3 draw it), named once in the
    legend as chapter 04 names it (:data:`NOISE_WORDS`; reader r35d: one name for the band)."""
    hatch_round(ax, floor, tie, words.format(low=floor[0], high=floor[1]).split(":")[0], NOISE_HATCH)


def _band_first(ax) -> tuple[list, list]:
    """A panel's legend handles and labels, a noise band's first (as it was named before the series were drawn)."""
    handles, labels = ax.get_legend_handles_labels()
    first = sorted(range(len(labels)), key=lambda i: not labels[i].startswith("noise band"))
    return [handles[i] for i in first], [labels[i] for i in first]


def _title(ax, means) -> str:
    """A panel's name in its figure's description: its title, or none where the figure has one panel (reader r45d:
    "ratios: ours, ...: crosses" said the series' name twice over)."""
    return f"{ax.get_title()}: " if means else ""


def _text(
    tie: float, series: int, counted: list[tuple[int, int]], spans, means, floor: tuple[float, float] | None = None
) -> str:
    """The figure's text alternative, each panel's points counted from its data."""
    said = (
        "Inside the paper's Algorithm 1, total time with prediction over time without, per scenario and sampler, "
        f"log scale, against the line at 1 and the shaded {band_words(tie)}"
    )
    if not means:
        n, below = counted[0]
        return (
            f"{said}: {n} points in {series} series, {below} of them at or below {1 - tie:.2f}"
            + (", whiskers spanning the middle half of the queries' ratios where a series has them." if spans else ".")
            + (f" Hatched round the tie band, {NOISE_WORDS.format(low=floor[0], high=floor[1])}." if floor else "")
        )
    (n_top, below_top), (n_low, below_low) = counted
    return (
        f"{said}, in two panels. Above, means, Table 3's statistic: the paper's diamonds beside our two series' means, "
        f"{n_top} points, {below_top} of them at or below {1 - tie:.2f}"
        + (f"; hatched round the tie band, {NOISE_WORDS.format(low=floor[0], high=floor[1])}" if floor else "")
        + f". Below, our medians of each query's own "
        f"ratio, hollow, with whiskers spanning the middle half of the queries' ratios: {n_low} points, {below_low} of "
        f"them at or below {1 - tie:.2f}."
    )


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


def _series(
    ax, rows, scenarios: list[str], series: list[str], names: dict[str, str], spans, hollow: bool = False
) -> tuple[list, list]:
    """Each series' points, its scenarios in groups of :data:`PAPER_SAMPLERS` and a series a little left or right of
    a sampler's tick, with a whisker where ``spans`` gives one; returns every value drawn and one :class:`Part` a
    series (its numbers, for the text alternative)."""
    width = len(PAPER_SAMPLERS) + 1
    drawn: list[float] = []
    parts = []
    present = [name for name in series if any(f"{scenario}, {name}" in rows for scenario in scenarios)]
    for k, name in enumerate(series):
        if name not in present:
            continue  # not in this panel: its style kept for the series that are
        color, marker = CHECKERS[SERIES_CHECKERS[k % len(SERIES_CHECKERS)]]
        step = min(SPREAD, WIDEST / max(len(present) - 1, 1))
        offset = (present.index(name) - (len(present) - 1) / 2) * step  # the panel's series centred on the tick
        cells = []
        for i, scenario in enumerate(scenarios):
            ratios = rows.get(f"{scenario}, {name}", {})
            x = [i * width + j + offset for j, s in enumerate(PAPER_SAMPLERS) if s in ratios]
            y = [ratios[s] for s in PAPER_SAMPLERS if s in ratios]
            whiskers = spans.get(f"{scenario}, {name}", {})
            for xi, s in zip(x, (s for s in PAPER_SAMPLERS if s in ratios)):
                if s in whiskers:
                    ax.vlines(xi, *whiskers[s], color=color, linewidth=1.0, zorder=2)
                    drawn += list(whiskers[s])
            ax.plot(
                x,
                y,
                linestyle="none",
                marker=marker,
                color=color,
                markersize=SIZE,
                markerfacecolor="none" if hollow else color,
                markeredgecolor=color if hollow else COLORS["ink"],
                markeredgewidth=1.4 if hollow else 1.2 if marker == CHECKERS["paper"][1] else 0.6,  # r57d, 3
                zorder=3,
                label=names.get(name, name) if i == 0 else None,
                path_effects=[] if hollow else halo(0.6, ("free",)),  # r47d: a white ring, clear of the hatching
            )
            drawn += y
            cells.append((scenario, *(_cell(ratios.get(s), whiskers.get(s)) for s in PAPER_SAMPLERS)))
        parts.append(
            Part(names.get(name, name), "total time with / without", ("scenario", *PAPER_SAMPLERS), tuple(cells))
        )
    return drawn, parts


def _cell(ratio: float | None, whisker: tuple[float, float] | None) -> str:
    """A point's number for the text alternative: "1.13", or "1.13 (0.77–1.59)" with its whisker."""
    if ratio is None:
        return ""
    return f"{ratio:.2f}" + (f" ({whisker[0]:.2f}–{whisker[1]:.2f})" if whisker else "")
