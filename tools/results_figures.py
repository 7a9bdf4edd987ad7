"""The results page's three figures and their text. Figure 1, :data:`CLAIM_FIGURE`, is the statistic the verdict on
the paper's claim reads: the strong network inside Algorithm 1, the median of each query's own ratio with its middle
half, with our compiled checker (filled) and with python-fcl on both sides (hollow; :data:`CLAIM_SERIES`), drawn by
:func:`toolkit.plots.query_ratios.own_ratios`. Figures 2 and 3, :data:`FIGURES`, are Table 3's total and sampling
columns by means, ours beside the paper's (:func:`table3_figure`, :func:`toolkit.plots.query_ratios.means_grid`).
Each one's text alternative is written between its markers; each PNG carries the same text (its ``Description``), so
``tests/test_results_figure.py`` fails while the picture or its words no longer match the tables."""

from __future__ import annotations

import html
import math

import numpy as np
from matplotlib import patheffects
from matplotlib.colors import to_rgb
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Rectangle
from matplotlib.ticker import NullFormatter, NullLocator

from toolkit.experiments.paper_numbers import IMPROVEMENT
from toolkit.plots import alt, query_ratios
from toolkit.plots.palette import COLORS, LINE_COLORS, OKABE_ITO
from toolkit.teaching import checker_scope, costs, findings, recorded
from toolkit.teaching.recorded import Tables
from tools.recorded_results import RESULTS, parse
from tools.results_noise import noise, own_intervals
from tools.results_rings import beyond, ring
from tools.results_words import NAMES, change

FIGURES = {kind: RESULTS.parent / f"results_table3_{kind}.png" for kind in ("total", "sampling")}  # Table 3's columns
LEADS = {  # what each figure shows, over it
    "total": "**Figure 2: a whole query's time, by means** (Table 3's *Total* columns), each against Algorithm 1 "
    "without prediction, ours beside the paper's.",
    "sampling": "**Figure 3: the sampling stage's time, by means** (Table 3's *Sampling* columns), each against "
    "Algorithm 1 without prediction, ours beside the paper's.",
}
TICKS = {"total": (), "sampling": (3.0,)}  # labelled beside each figure's 1-2-5 steps, with the floor's edges
MARGINS = {"total": 1.15, "sampling": 1.25}  # each figure's range: its points', widened by this factor
ROW_HEIGHTS = {"total": 3.3, "sampling": 3.2}  # inches a row of panels: each band is read to 0.9 and 1.1 (r27f)
KEY = (  # under Figure 2 (reader r31f, item 3): its marks are not Figure 1's verdicts; r39f, item 7: one colour each;
    # reader r44f, item 9: each series named by its shape; reader r47f, item 5: its crosses yellow, not orange;
    # reader r50f, item 5: a fill colour (black outlines every mark)
    " Here colour and shape name a series, not a verdict as in Figure 1: grey diamonds, the paper; yellow bold "
    "crosses (×) edged in black, the paper-recipe network; reddish-purple stars, the strong network with our "
    "compiled checker; "
    "bluish-green pentagons, the strong network with python-fcl."
)
CLAIM_FIGURE = RESULTS.parent / "results_claim.png"  # Figure 1: the statistic the verdict on the paper's claim reads
CLAIM_BEGIN = "<!-- figure of the claim: drawn by `python -m tools.results_summary` from the tables below -->"
CLAIM_END = "<!-- end of the figure of the claim -->"
CLAIM_TITLE = "strong network inside Algorithm 1: total time, each query's own ratio"
CLAIM_SERIES = ("our compiled checker on both sides", "python-fcl on both sides")  # Figure 1's filled and hollow points
FIGURE_BEGIN = "<!-- figure of {kind} times: drawn by `python -m tools.results_summary` from the tables below -->"
FIGURE_END = "<!-- end of the figure of {kind} times -->"
FIGURE_DPI = 110  # as docs/crossover.png: the site's column shows it at about its size
CLAIM_WIDTH = 6.3  # inches, Figure 1: with its edges' labels on the right, the column's width (reader r41f: 570 px)
WIDTH = 6.35  # inches, Figures 2-3: at FIGURE_DPI, cropped, the site's column (688 px at 1280), shown at its size
SOURCES = {  # a series of the figure: its preset in the tables (None: the paper's own numbers) and its name; the
    # 1-2 December run with python-fcl is history, left out (review r27f, item 5: five series were 80 markers)
    "the paper's reported results (Table 3)": None,
    "ours, paper-recipe network, compiled checker of 2 December": "paper",
    "ours, strong network, compiled checker of 5 December": recorded.ALGORITHM_1,
    "ours, strong network, python-fcl on both sides": checker_scope.SLOW,
}


def ratios(text: str, kind: str = "total") -> dict[str, dict[str, dict[str, float]]]:
    """Table 3's ``kind`` columns ("total" or "sampling") as time ratios with / without (``1 - improvement``, means,
    against Algorithm 1), from the paper and from the page ``text``'s runs of the `paper` recipe:
    ``{scenario: {series: {sampler: ratio}}}``."""
    tables = parse(text)
    found: dict[str, dict[str, dict[str, float]]] = {}
    for scenario in NAMES:  # the paper's order
        for name, preset in SOURCES.items():
            if preset is not None and scenario not in recorded.table(preset, "time improvement", tables):
                continue  # a run that did not plan this scenario
            saved = (
                IMPROVEMENT[scenario][kind]
                if preset is None
                else recorded.improvements(preset, scenario, kind, recorded=tables)
            )
            found.setdefault(scenario, {})[name] = {s: round(1 - v, 6) for s, v in saved.items()}
    return found


def table3_figure(text: str, kind: str = "total") -> Figure:
    """One of the page's figures: per scenario, each sampler's mean ``kind`` time ("total" or "sampling") with /
    without prediction against Algorithm 1, the paper's beside ours (:func:`ratios`), the tie band of :data:`RULE`
    shaded; a grid of two columns, one legend, and one log axis for its panels, so the same ratio stands at the same
    height in every panel (:func:`toolkit.plots.query_ratios.means_grid`); each figure its own range, so the tie band of
    the total times is not squeezed by the sampling stage's wider one, the band's edges labelled (:data:`TICKS`)."""
    floor = noise(parse(text)).means  # reader r31f, item 3: the noise band the text under the figure reads by
    banded = kind in BANDED  # reader r48f, figures: Figure 3 draws no band (none was measured for sampling times)
    every = [r for series in ratios(text, kind).values() for by in series.values() for r in by.values()]
    drawn = [*every, *floor] if banded else every
    margin = MARGINS[kind]  # room between the outermost points and the frame
    ylim = (min(drawn) / margin, max(drawn) * margin)
    fig = query_ratios.means_grid(
        {f"{NAMES[s]}: {kind} time, means": series for s, series in ratios(text, kind).items()},
        tie=findings.TIE,
        ylim=ylim,
        ticks=TICKS[kind],  # reader r44f, item 9: the hatch's edges labelled on the right only, clear of 0.5 and 1.5
        row_height=ROW_HEIGHTS[kind],
        noise=floor if banded else None,
        width=WIDTH,
    )
    fig = readable(fig, floor if banded else None, kind)
    return worded(fig, kind) if banded else sampled_words(fig)


BANDED = ("total",)  # the figures that draw the noise band of a ratio of means: it was measured on total times only


BAND_WORDS = "twice how far timing alone moved a ratio of means"  # ratio_bands.NOISE_WORDS' words for the hatch
BAND_SAID = {  # reader r45f, item 5: the band is our timing's, not the paper's; Figure 3's is built on total times;
    # reader r47f, item 2 (common rule 3): twice how far timing alone moved the ratio, not how far
    "total": BAND_WORDS + " on our machine, hatched over our series only (the paper's points are not read against it)",
}


def sampled_words(fig: Figure) -> Figure:
    """Figure 3's text alternative: it shows sampling time, not planning time, and draws no noise band."""
    text = alt.alt_text(fig).replace("Mean planning time with prediction", "Mean sampling time with prediction", 1)
    return alt.describe(fig, text, getattr(fig, alt.DETAILS, ()))


def worded(fig: Figure, kind: str) -> Figure:
    """Reader r45f, item 5: the text alternative says which time the figure shows (Figure 3's is sampling time, not
    planning time) and what its hatched band is: our timing noise (Figure 2's only: :data:`BANDED`)."""
    text = alt.alt_text(fig)
    if BAND_WORDS not in text:  # the hatch's words come from ratio_bands.NOISE_WORDS: the two change together
        raise ValueError(f"the figure's text alternative no longer says {BAND_WORDS!r}; update BAND_WORDS")
    text = text.replace(BAND_WORDS, BAND_SAID[kind])
    if kind == "sampling":
        text = text.replace("Mean planning time with prediction", "Mean sampling time with prediction", 1)
    return alt.describe(fig, text, getattr(fig, alt.DETAILS, ()))


MARKER_SCALE = {"total": 0.78, "sampling": 0.75}  # Figures 2-3's markers, smaller than means_grid draws them, so
# neighbours stand apart (reader r47f, item 5: Figure 3's 2DS BT trio nearly touched)
SPREAD = {"total": 1.0, "sampling": 1.07}  # a sampler's points spread this much wider than means_grid's
PENTAGON_IN = {"total": 0.9, "sampling": 1.0}  # reader r54f, item 4: Figure 2's 2DS G pentagon sat against the G/BT
# divider, beside BT's diamond; the rightmost series (python-fcl's pentagons) drawn this much nearer its column's middle
LOOKS = {  # reader r42f, figures: no blue (Figure 1's "costs time") and no square-like plus (its "tie" square)
    # reader r43f, figures: python-fcl's orange downward triangle read as Figure 1's black "saves" triangle, its orange
    # as Figure 1's vermillion "tie": now a colour and a shape Figure 1 never uses, bluish green pentagons; the
    # paper-recipe series takes the orange, as a thin cross, a shape no Figure 1 square or triangle resembles
    # reader r47f, item 5: orange still read as Figure 1's vermillion "tie"; now yellow, edged in black
    "ours, paper-recipe network, compiled checker of 2 December": (OKABE_ITO["yellow"], "x"),  # yellow, bold cross
    "ours, strong network, python-fcl on both sides": (LINE_COLORS[3], "p"),  # bluish green, pentagon
}  # the other two keep means_grid's look: the paper's grey diamonds, the strong network's reddish purple stars
CROSS_WIDTH = 2.4  # points: a cross is all edge, drawn this thick (bold, as the key says) beside the filled markers
CROSS_SCALE = 1.5  # a bold cross's arms fill less of its box than a filled marker: drawn this much larger (reader
# r48f, figures: at 1.15 the crosses read as yellow blobs at 1280 px)
CROSS_EDGE = 0.7  # points: the yellow cross's black edge, so it stands 3:1 on white (yellow alone is 1.2:1)
STAR_SCALE = 1.3  # reader r53f, figures: the strong network's stars were the smallest marks, the verdict's series
PENTAGON_SCALE = 1.1  # reader r57f, Figure 2: python-fcl's pentagons read smaller than the other marks
MARKER_Z = 4  # over every band and hatch (reader r42f: Figure 3's hatching read as covering the markers inside it)
TIE_TICKS = {"total": False, "sampling": False}  # reader r42f: 0.9 and 1.1 crowd the "1"; the legend names them


def readable(fig: Figure, floor: tuple[float, float] | None, kind: str = "total") -> Figure:
    """Reader r40f, figures: Figures 2-3 with y tick labels on every panel (the right-hand ones had none) and the
    markers a little smaller, so that neighbouring ones (Figure 2's 2DS BS, Figure 3's 2DS BT) stand apart. Reader
    r41f, figures: the noise band's edges outside the axes, on the right of the right-hand panels only (in the gutter
    they read as the next panel's ticks; inside they crowded the points), the tie band's edges 0.9 and 1.1 on the left
    where they stand apart (:data:`TIE_TICKS`), and the paper-recipe series a shape of its own (:data:`SHAPES`)."""
    for ax in (ax for ax in fig.axes if ax.get_visible()):
        for child in list(ax.child_axes):  # means_grid's labels of the band's edges, redrawn below
            child.remove()
        ax.tick_params(axis="y", labelleft=True)
        for line in ax.lines:
            if line.get_marker() not in ("None", None, ""):
                star = STAR_SCALE if line.get_marker() == "*" else 1.0  # reader r53f: the verdict's series
                pentagon = LOOKS.get(str(line.get_label()), ("", ""))[1] == "p"  # before restyle draws it so
                scale = MARKER_SCALE[kind] * star * (PENTAGON_SCALE if pentagon else 1.0)
                line.set_markersize(line.get_markersize() * scale)
                x = [float(v) for v in np.asarray(line.get_xdata())]
                spread = SPREAD[kind] * (PENTAGON_IN[kind] if pentagon else 1.0)
                line.set_xdata([round(v) + (v - round(v)) * spread for v in x])
                line.set_zorder(MARKER_Z)
                restyle(line)
        if TIE_TICKS[kind]:
            ticks = sorted({*ax.get_yticks(), 0.9, 1.1})
            low, high = ax.get_ylim()
            ticks = [t for t in ticks if low <= t <= high]
            ax.set_yticks(ticks, [f"{t:g}" for t in ticks])
            ax.yaxis.set_minor_formatter(NullFormatter())
        if floor is None:
            continue
        clear_of_paper(ax, floor)
        spec = ax.get_subplotspec()
        if spec is not None and spec.colspan.start == 1:  # a right-hand panel: the band's edges beside it, outside
            edges = ax.secondary_yaxis("right")
            edges.set_yticks(list(floor), [f"{edge:.2f}" for edge in floor])
            edges.yaxis.set_minor_locator(NullLocator())
            edges.tick_params(labelsize=9, length=3, pad=1)
    legend = fig.legends[0]
    for handle, label in zip(legend.legend_handles, legend.texts):
        if isinstance(handle, Line2D):
            restyle(handle, label.get_text())
            if handle.get_marker() == "*":  # the key's star as large as the panels' (reader r53f, figures)
                handle.set_markersize(handle.get_markersize() * STAR_SCALE)
            if handle.get_marker() == "p":  # the key's pentagon as the panels' (reader r57f, Figure 2)
                handle.set_markersize(handle.get_markersize() * PENTAGON_SCALE)
        if floor is not None and label.get_text().startswith("noise band"):  # reader r48f, figures: said once
            handle.set_edgecolor(HATCHED["edgecolor"])  # type: ignore[union-attr]  # as the panels' hatch
            label.set_text(f"{label.get_text()} in every panel")
    room = (0.1 + 0.2 * len(fig.legends[0].texts)) / fig.get_figheight()  # as legend_above leaves for the legend
    fig.tight_layout(rect=(0, 0, 1, 1 - room))
    return fig


def clear_of_paper(ax, floor: tuple[float, float]) -> None:
    """Reader r47f, item 5: the noise band of a ratio of means is our machine's, so it is hatched over our series'
    columns only, not behind the paper's diamonds: means_grid's hatch and dotted edges across the panel are drawn
    again from halfway between each sampler's diamond and our first point to the sampler's right-hand edge, the edges
    dashed (:data:`NOISE_EDGE`), as Figure 1's noise band's."""
    for patch in [p for p in ax.patches if p.get_hatch()]:
        patch.remove()
    for line in [line for line in ax.lines if line.get_linestyle() == ":"]:
        line.remove()
    paper = next(line for line in ax.lines if line.get_label() == PAPER)
    ours = sorted({float(v) for line in ax.lines if line.get_label() in SOURCES for v in line.get_xdata()})
    for x in paper.get_xdata():
        start = (x + min(v for v in ours if v > x)) / 2
        end = round(x) + 0.5
        for low, high in ((floor[0], 1 - findings.TIE), (1 + findings.TIE, floor[1])):
            ax.add_patch(Rectangle((start, low), end - start, high - low, **HATCHED))  # type: ignore[arg-type]
        ax.hlines(list(floor), start, end, colors=COLORS["reference"], linestyles=NOISE_EDGE, linewidth=1.0, zorder=0.5)


PAPER = next(name for name, preset in SOURCES.items() if preset is None)  # the paper's own series
NOISE_EDGE = "--"  # reader r51f, item 5: a noise band's edges dashed, as Figure 1's; dotted means the tie band only
HATCH_ALPHA = 0.6  # reader r53f, figures: at 1 the hatch drowned the points; reader r57f: at 0.4 it was faint
HATCHED = dict(
    facecolor="none",
    edgecolor=(*to_rgb(COLORS["reference"]), HATCH_ALPHA),
    hatch=query_ratios.NOISE_HATCH,
    linewidth=0,
    zorder=0,
)


def restyle(line: Line2D, name: str | None = None) -> None:
    """A series' point or legend handle in its :data:`LOOKS` colour and marker, by its series' ``name`` (its label)."""
    look = LOOKS.get(name if name is not None else str(line.get_label()))
    if look is None:
        return
    colour, marker = look
    line.set_marker(marker)
    line.set_color(colour)
    line.set_markerfacecolor(colour)
    line.set_markeredgecolor(colour)
    if marker == "x":  # reader r47f, item 5: yellow, bold, edged in black (a ring just wider than the cross's arms)
        line.set_markeredgewidth(CROSS_WIDTH)
        line.set_path_effects(
            [patheffects.Stroke(linewidth=CROSS_WIDTH + 2 * CROSS_EDGE, foreground=COLORS["ink"]), patheffects.Normal()]
        )
        line.set_markersize(line.get_markersize() * CROSS_SCALE)


def claim_figure(text: str) -> Figure:
    """Figure 1: what the verdict on the paper's claim reads (:func:`accurate_in_algorithm_1`), the median of each
    query's own ratio with its middle half, per scenario and sampler (:func:`toolkit.plots.query_ratios.own_ratios`)."""
    tables = parse(text)
    fast, slow = own_intervals(tables), own_intervals(tables, checker_scope.SLOW)
    fig = query_ratios.own_ratios(
        fast,
        title=CLAIM_TITLE,
        tie=findings.TIE,
        slow=slow,
        series=CLAIM_SERIES,
        edge=costs.noise_edge(tables),  # review r30f, item 2: the noise edge drawn, not only named
        width=CLAIM_WIDTH,
    )
    # reader r57f, lift item 4: the points beyond the noise band ringed; the fill key in words (r60e)
    return ring(fig, fast, slow, costs.floors(tables)["own"], CLAIM_TITLE)


def claim_markdown(text: str) -> str:
    """Figure 1 as the page ``text`` shows it: what it shows and that it is the verdict's statistic, then the picture
    with its text alternative and its longer description; its counts are the summary's (review r27f, item 2)."""
    fig = claim_figure(text)
    tables = parse(text)
    lead = (  # review r28f, item 1: the title over the plot, the caption under it, so the figure fits one screen
        "**Figure 1: the paper's claim, as the verdict reads it**: the strong network inside Algorithm 1, "
        "each query's total time with prediction over its own time without."
    )
    tie, (low, high) = findings.TIE, costs.floors(tables)["own"]
    caption = (  # reader r60f, item 3: what a point, a whisker, a ring, the bands and the shapes are; no more
        "Each point is a cell: the median of its 100 queries' ratios; its whisker, their middle half. *Shape and "
        f"colour = verdict, fill = checker, ring = clear*: the verdict read against the shaded tie band, "
        f"{1 - tie:.2f}–{1 + tie:.2f}; filled, our compiled checker; hollow, python-fcl on both sides; ringed, beyond "
        f"the hatched noise band, {low:.2f}–{high:.2f}, inside which a cost or saving is no clear evidence: "
        f"{ringed(tables)}."
    )
    if not any("timed twice" in heading for heading in tables[checker_scope.SLOW]):  # review r30f, contradiction 5
        caption += " The run with python-fcl was not timed twice: its hollow points borrow that band."
    described = alt.details_html(alt.details(fig)).strip()
    picture = f"![{html.escape(alt.alt_text(fig))}]({CLAIM_FIGURE.name})"
    return f"{lead}\n\n{picture}\n\n{caption}\n\n{described}"


def ringed(tables: Tables) -> str:
    """Reader r57f, lift item 4: how many points Figure 1 rings, each checker's: ``"5 filled and 2 hollow"``."""
    band = costs.floors(tables)["own"]
    fast, slow = (len(beyond(own_intervals(tables, key), band)) for key in (recorded.ALGORITHM_1, checker_scope.SLOW))
    return f"{fast} filled and {slow} hollow"


def furthest_apart(tables: Tables) -> tuple[str, str, float, float]:
    """The `strong` cell (compiled checker) whose ratio of means and median of each query's own ratio lie furthest
    apart: ``(scenario, sampler, ratio of means, median ratio)``, the example of how far a mean can stray."""
    medians = recorded.query_ratios(recorded.ALGORITHM_1, tables)
    cells = [
        (NAMES.get(s, s), sampler, 1 - saved, medians[s][sampler])
        for s in medians
        for sampler, saved in recorded.improvements(recorded.ALGORITHM_1, s, recorded=tables).items()
    ]
    return max(cells, key=lambda c: abs(math.log(c[2] / c[3])))


MARKS = {  # each series of ours by its mark, as the key names it
    "ours, paper-recipe network, compiled checker of 2 December": "yellow cross",
    "ours, strong network, compiled checker of 5 December": "star",
    "ours, strong network, python-fcl on both sides": "pentagon",
}
NEAR = 1.05  # a point of ours beyond the noise band but within this factor of its edge sits on the dashed line


def just_beyond(text: str) -> str:
    """Reader r59f, item 5: Figure 2's points of ours that lie beyond the noise band of a ratio of means but so close
    to its edge that their marker covers the dashed line, said beyond it in words; empty where there are none."""
    low, high = noise(parse(text)).means
    close = [
        (f"{NAMES[s]} {sampler} {r:.2f} ({MARKS[name]})", high if r > 1 else low)
        for s, series in ratios(text, "total").items()
        for name, by in series.items()
        if name in MARKS
        for sampler, r in by.items()
        if (high <= r < high * NEAR) or (low / NEAR < r <= low)
    ]
    if not close:
        return ""
    edges = sorted({edge for _, edge in close})
    edge = f"edge at {edges[0]:.2f}" if len(edges) == 1 else "edges"
    named = " and ".join(cell for cell, _ in close)
    return f" {named} sit{'s' if len(close) == 1 else ''} on the dashed {edge}, just beyond it."


def inside_means(text: str) -> str:
    """Reader r59f, lift item 3: Figure 2's takeaway first, how many of our points lie inside the noise band of a
    ratio of means, so that by means the figure cannot tell those cells from timing noise."""
    low, high = noise(parse(text)).means
    ours = [
        r
        for series in ratios(text, "total").values()
        for name, by in series.items()
        if name in MARKS
        for r in by.values()
    ]
    inside = sum(costs.inside(r, (low, high)) for r in ours)
    return (
        f" {inside} of our {len(ours)} points lie inside the noise band of a ratio of means, "
        f"{low:.2f}–{high:.2f}, so by means this figure cannot tell those cells from timing noise."
    )


def means_not_verdict(tables: Tables) -> str:
    """Over Figure 2: its points are means, while the page's verdict on the paper's claim reads each query's own ratio
    (:func:`accurate_in_algorithm_1`); the cell :func:`furthest_apart` finds shows it."""
    name, sampler, mean, median = furthest_apart(tables)
    return (
        " Figures 2 and 3 show means, Table 3's statistic; the verdict on the paper's claim reads each query's own "
        f"ratio (Figure 1): the strong network's {name} {sampler}, for one, is {mean:.2f} by means here and "
        f"{median:.2f} by the median of each query's own ratio there."
    )


def spread_without(tables: Tables, key: str) -> dict[tuple[str, str], tuple[float, float]]:
    """``{(scenario, sampler): (mean, std)}`` of a whole query's time without prediction, ``key``'s section's
    "Times behind Table 3" (ours, seconds)."""
    times = next(t for heading, t in tables[key].items() if "Times behind Table 3" in heading)
    column = times["columns"].index("total without")
    found = {}
    for row in times["rows"]:
        mean, std = (float(v) for v in row[column].split("/")[0].replace("*", "").split("±"))
        found[(row[0], row[1])] = (mean, std)
    return found


def stars_below(tables: Tables) -> str:
    """Reader r56f, item 4: under Figure 2, why the strong network's compiled-checker cells that save 10 % or more
    by means do not contradict the verdict by each query's own ratio: the means band holds them, and a mean weighs a
    few long queries (the cells whose queries without prediction spread wider than their mean); empty where none."""
    key = recorded.ALGORITHM_1
    own = recorded.query_ratios(key, tables)
    means = {
        (s, sampler): 1 - saved
        for s in own
        for sampler, saved in recorded.improvements(key, s, recorded=tables).items()
    }
    below = [cell for cell, r in means.items() if change(r) == "less time"]
    if not below:
        return ""
    band = noise(tables).means
    saved = sum(change(r) == "less time" for by in own.values() for r in by.values())
    inside = all(costs.inside(means[cell], band) for cell in below)
    spread = spread_without(tables, key)
    wide = [cell for cell in below if spread[cell][1] > spread[cell][0]]
    named = ", ".join(f"{NAMES.get(s, s)} {sampler} {means[(s, sampler)]:.2f}" for s, sampler in below)
    owns = ", ".join(f"{own[s][sampler]:.2f}" for s, sampler in below)
    said = (
        f"By means the reddish-purple stars (the strong network, our compiled checker) save 10 % or more in "
        f"{len(below)} cells ({named}), where by each query's "
        f"own ratio the same run saved time in {saved} of {len(means)} (these {len(below)}: {owns}): "
        + (
            f"{'all ' + str(len(below)) + ' lie' if len(below) > 1 else 'it lies'} inside the noise band of a ratio "
            f"of means, {band[0]:.2f}–{band[1]:.2f}, which is wide "
            if inside
            else "a ratio of means strays from each query's own ratio "
        )
        + "because a mean counts a few long queries' time in full"
    )
    if wide:
        said += (
            f" (without prediction, the queries of {len(wide)} of them spread wider than their mean: "
            + ", ".join(
                f"{NAMES.get(s, s)} {sampler} {spread[(s, sampler)][0]:.3g} ± {spread[(s, sampler)][1]:.2g} s"
                for s, sampler in wide
            )
            + ", mean ± standard deviation)"
        )
    return said + "."


def sampling_takeaway(counts: dict[str, list[str]]) -> str:
    """Figure 3's one line on what it shows (reader r37f, item 7): how many cells the strong network's sampling got
    shorter with python-fcl, and longer with our compiled checker, by the 10 % rule."""
    slow = next(words for name, words in counts.items() if "strong" in name and "python-fcl" in name)
    fast = next(words for name, words in counts.items() if "strong" in name and "compiled" in name)
    return (
        f"It shows the strong network shortening sampling in {slow.count('less time')} of {len(slow)} cells with "
        f"python-fcl and lengthening it in {fast.count('more time')} of {len(fast)} with our compiled checker."
    )


def figure_markdown(text: str, kind: str = "total") -> str:
    """The figure of ``kind`` as the page ``text`` shows it: a line that names it, the picture with its text
    alternative and its longer description under it, then a small table that counts each series' points by the tie
    rule."""
    fig = table3_figure(text, kind)
    counts: dict[str, list[str]] = {}
    for series in ratios(text, kind).values():
        for name, by_sampler in series.items():
            counts.setdefault(name, []).extend(change(r) for r in by_sampler.values())
    rows = [
        f"| {name} | {len(words)} | {words.count('less time')} | {words.count('about the same time')} "
        f"| {words.count('more time')} |"
        for name, words in counts.items()
    ]
    head = f"| {kind} time | cells | saved 10 % or more | tied | lost 10 % or more |\n| --- | --- | --- | --- | --- |"
    described = alt.details_html(alt.details(fig)).strip()
    shown = f"![{html.escape(alt.alt_text(fig))}]({FIGURES[kind].name})\n\n{described}"
    floor = noise(parse(text))
    said = (  # reader r39f, item 1: the band by its one name; r46f, item 3: its table under Figure 1
        f"*{kind.capitalize()} time*, Table 3's cells counted with the 10 % rule. The noise band of a ratio of means, "
        f"{floor.means[0]:.2f}–{floor.means[1]:.2f} (hatched the other way from Figure 1's band, its edges "
        "dashed as there; built as the table of bands under Figure 1 says), sets a single cell of ours apart only "
        "beyond it. It is our machine's timing noise, not the paper's: it is hatched over our series only, not "
        "behind the paper's diamonds." + just_beyond(text) + KEY
        if kind == "total"
        else f"*{kind.capitalize()} time*, counted as in Figure 2. {sampling_takeaway(counts)} The dotted lines "
        "are the tie band's edges. No noise band is drawn: the table “timed twice” holds total times only, so "
        "sampling times have no band of their own."
    )
    tables = parse(text)
    lead = LEADS[kind] + (inside_means(text) + means_not_verdict(tables) if kind == "total" else "")
    stars = f"{stars_below(tables)}\n\n" if kind == "total" and stars_below(tables) else ""
    return f"{lead}\n\n{shown}\n\n{stars}{said}\n\n{head}\n" + "\n".join(rows)
