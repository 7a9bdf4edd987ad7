"""How long planning and checking take, with and without prediction (paper §V, Table 3): notebook 04.

A planner's time per query split into its stages (:func:`stage_times`), checkers' throughputs
(:func:`throughputs`), and the pieces every ratio figure shares (the tie band, log ticks, a legend above). Every
function returns a matplotlib ``Figure`` and never calls ``show()``.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
from matplotlib.figure import Figure
from matplotlib.ticker import NullFormatter
from matplotlib.transforms import offset_copy

from toolkit.plots.alt import Part, describe
from toolkit.plots.palette import CATEGORICAL, COLORS, PAGE_WIDTH, halo, series_style
from toolkit.util.verdicts import TIES, UNSURE, per_query_ratios, time_verdict

MODES = ("without", "with")
STAGE_KEYS = ("sampling_s", "connection_s", "query_s")  # PRM stats, in the order the planner spends them
STAGE_HATCHES = ("", "//", "..", "xx")  # sampling, connection, query, other: told apart without colour
STAGE_COLORS = tuple(CATEGORICAL[k] for k in (0, 1, 5, 3))  # reader r34d: query white, not sky blue beside blue
STAGE_LABELS = {
    "sampling_s": "sampling (S, S')",
    "connection_s": "connection (edges)",
    "query_s": "query (path, verification, repair)",
    "other_s": "other (encoding, set-up)",
}


def stage_times(panels: dict[str, dict], band: tuple[float, float] | None = None) -> Figure:
    """Per panel (e.g. a scenario), a ``planning`` table ``{sampler: {"without": summary, "with": summary}}``
    (``queries.summarize``): one bar per sampler and mode, as tall as the median total over the queries in ms, split
    into the planner's stages in the shares of an average query (``_share``; the rest, encoding and set-up, on top
    as "other"); a whisker from the total's first to third quartile; above each pair the median of the queries' own
    ratios, time with / without (the summaries' ``total_s_per_query``: each query was solved in both modes in turn),
    the number the chapters' tables read their verdicts from. It is not the bars' quotient: where the two fall on
    opposite sides of 1 (the taller bar is the other mode's) the number carries a "‡" that the title explains
    (reader r35d: "*" is chapter 04's timing noise).

    Each panel has its own scale, set by its bars: a whisker reaching past :data:`CUT` times the tallest bar (one
    slow query's spread would flatten every bar) is cut at the panel's top, a triangle there and its end written
    beside it, inside the frame (the pair's ratio above the frame). With ``band`` (chapter 04's noise band of each
    query's own ratio), a saving or cost inside it carries "*", as chapter 04's tables mark it (reader r48d)."""
    fig = Figure(figsize=(PAGE_WIDTH, 3.7 * len(panels) + 0.8))  # one panel a row, as wide as a chapter's column
    axes = fig.subplots(len(panels), 1, squeeze=False)[:, 0]
    said, parts = [], []
    for ax, (title, planning) in zip(axes, panels.items()):
        names = list(planning)  # the samplers planned, in their order
        x = np.arange(len(names))[:, None] + np.array([-0.22, 0.22])  # (samplers, modes) bar centres
        table = _stage_table(planning, names)  # key -> (samplers, modes), in ms
        cut = _draw_stage_bars(ax, x, table)  # (samplers, modes): which whiskers run past the panel's top
        ratio = [float(np.median(per_query_ratios(planning[s]))) for s in names]  # (samplers,)
        bars = table["total_s"][:, 1] / table["total_s"][:, 0]  # (samplers,): the bars' own quotient, with / without
        crossed = (bars - 1) * (np.asarray(ratio) - 1) < 0  # (samplers,): the taller bar says the other way
        across = [_across(per_query_ratios(planning[s])) for s in names]  # reader r49d, item 4: the table's †
        labels, note = _ratio_labels(ratio, crossed, band, across)  # r40d: one ratio a pair; the bars' own in words
        for i, label in enumerate(labels):  # above the frame, over the pair and a cut whisker's end: never on a bar
            where = dict(xycoords=("data", "axes fraction"), xytext=(0, 13), textcoords="offset points")
            ax.annotate(label, (i, 1.0), ha="center", va="bottom", fontsize=9, weight="bold", **where)
        ax.set_xticks(x.ravel(), [f"{s}\n{m}" for s in names for m in MODES], fontsize=9)
        ax.set_xlabel("sampler, without / with prediction")
        ax.set_ylabel("ms per query (median),\neach panel its own scale")
        ax.set_title(
            f"{title}: above a pair, the median of each query's ratio{note}",  # r31d: not three lines; r62d: the
            # marks' note on a line of its own, since one line of both widened the figure past the column (944 px)
            fontsize=9,
            pad=26,
        )
        said.append(_stage_words(title, names, table, ratio, bars, crossed, labels))
        said[-1] += cut_in_words(
            cut, [[f"{s} {m}" for m in MODES] for s in names], table["total_s_q3"], ax.get_ylim()[1]
        )
        keys = ("total_s", "total_s_q1", "total_s_q3", *STAGE_KEYS, "other_s")
        rows = tuple(
            (f"{s}, {m}", *(ms_text(table[key][i, j]) for key in keys))
            for i, s in enumerate(names)
            for j, m in enumerate(MODES)
        )
        columns = ("sampler, prediction", "median total", "first quartile", "third quartile", *STAGE_LABELS.values())
        parts.append(Part(title, f"ms per query; {said[-1]}", columns, rows))
    shown = {label: h for ax in axes for h, label in zip(*ax.get_legend_handles_labels())}  # each entry once
    order = sorted(shown, key=lambda label: label not in STAGE_LABELS.values())  # the stages first, in their order
    fig.legend([shown[k] for k in order], order, loc="upper center", ncol=2, fontsize=9, frameon=False)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.8 / fig.get_figheight()))  # the legend over the panels, where a reader starts
    text = "Median planning time per query in ms without and with prediction, per sampler, split into the planner's"
    text += " stages (each its own colour and fill pattern), with the median of each query's own time ratio,"
    text += " with / without (not a ratio of the bars), above each pair;"
    text += " each panel on its own scale"
    return describe(fig, f"{text}. {'; '.join(said)}.", parts)


def _across(ratios: np.ndarray) -> bool:
    """Whether the queries' middle half includes a tie band edge (or fewer than two queries): chapter 04's table
    then marks its verdict † (:func:`toolkit.teaching.findings.planning_verdict`)."""
    q1, q3 = (float(v) for v in np.percentile(ratios, (25, 75)))
    return len(ratios) < 2 or time_verdict(q1, q3) == UNSURE


def _ratio_labels(
    ratio: list[float], crossed: np.ndarray, band: tuple[float, float] | None, across: Sequence[bool] = ()
) -> tuple[list[str], str]:
    """Each pair's ratio as written over it, "*" inside ``band`` (a saving or cost only), else "†" where ``across``
    (its middle half includes a tie band edge, as chapter 04's table marks it), :data:`CROSSED` where the bars say
    the other way; and the title's note naming the marks drawn (review r30d: none promised where none is)."""
    noisy = [band is not None and band[0] < r < band[1] and time_verdict(r) != TIES for r in ratio]
    wide = [band is not None and bool(across) and across[i] and not noisy[i] for i in range(len(ratio))]
    labels = [f"{r:.2f}x{'*' * noisy[i]}{'†' * wide[i]}{CROSSED if crossed[i] else ''}" for i, r in enumerate(ratio)]
    marks = [NOISY] * any(noisy) + [WIDE] * any(wide) + [STARRED] * bool(crossed.any())
    return labels, f"\n({'; '.join(marks)})" if marks else ""


def _stage_words(
    title: str, names: list[str], table: dict, ratio: list[float], bars, crossed, labels: Sequence[str] = ()
) -> str:
    """:func:`stage_times`' words for one panel: each sampler's median totals without and with prediction and the
    median of its queries' ratios, the bars' own ratio (reader r40d: not over the pair), and which bar is taller where
    the two say opposite things."""
    words = []
    for i, s in enumerate(names):
        taller = ", though the bar with prediction is the " + ("shorter" if bars[i] < 1 else "taller")
        without, with_ = (ms_text(table["total_s"][i, mode]) for mode in (0, 1))
        own = float(with_) / float(without) if float(without) else bars[i]  # r54d: the printed heights' quotient
        words.append(
            f"{s} {without} ms without, {with_} ms with "
            f"(the median of each query's ratio {ratio[i]:.2f}x"
            + ", inside the noise band" * ("*" in (labels[i] if labels else ""))
            + ", its middle half across the tie band" * ("†" in (labels[i] if labels else ""))
            + f"; the bars' own ratio {own:.2f}x"
            f"{taller if crossed[i] else ''})"
        )
    return f"{title}: " + ", ".join(words)


MS = 1000.0  # the figure's unit, ms, per second
CROSSED = "‡"  # not chapter 04's † (no clear evidence, its tables) nor its * (the noise band): reader r48d
STARRED = "‡: the bars say the other way"  # a stage panel's title's end, where a pair is marked so
WIDE = "†: middle half across the tie band"  # chapter 04's table's other mark (reader r49d, item 4)
NOISY = "*: inside the noise band"  # ... and where a pair's ratio is inside ``band``
BAR = 0.3  # a stage bar's width; a pair's centres are 0.44 apart, each bar's whisker stands on its right
CUT = 2.0  # a whisker reaching past CUT times a panel's tallest bar is cut at its top, its end written there


def ms_text(value: float) -> str:
    """A time in ms as the figure writes it: three digits, whole numbers from 100 on (``'4.35'``, ``'178'``)."""
    return f"{value:.0f}" if value >= 100 else f"{value:.3g}"


def _stage_table(planning: dict, names: list[str]) -> dict[str, np.ndarray]:
    """The bars of :func:`stage_times` in ms, key -> ``(samplers, modes)``: the total's median and quartiles, each
    stage's time (its share of an average query times the median total) and "other", the rest."""
    table = {
        key: MS * np.array([[planning[s][m][key] for m in MODES] for s in names])
        for key in [f"total_s_{stat}" for stat in ("median", "q1", "q3")]
    }
    shares = {key: np.array([[planning[s][m][f"{key}_share"] for m in MODES] for s in names]) for key in STAGE_KEYS}
    table["total_s"] = table["total_s_median"]
    table.update({key: table["total_s"] * shares[key] for key in STAGE_KEYS})
    table["other_s"] = np.maximum(table["total_s"] - sum(table[k] for k in STAGE_KEYS), 0.0)
    return table


def cut_in_words(cut: np.ndarray, labels, q3: np.ndarray, top: float) -> str:
    """The whiskers cut at a panel's top ``top`` (ms), in words: ``cut``, ``q3`` and the bars' ``labels``, arrays of
    the bars' shape; "" for none."""
    ends = [f"{labels[i][j]} to {ms_text(q3[i, j])} ms" for i, j in zip(*np.nonzero(cut))]
    return f"; whiskers cut at the top, {ms_text(top)} ms: " + ", ".join(ends) if ends else ""


def _draw_stage_bars(ax, x: np.ndarray, table: dict[str, np.ndarray]) -> np.ndarray:
    """:func:`stage_times`' bars at ``x (samplers, modes)``: the stages of ``table`` (key -> ``(samplers, modes)``)
    stacked, hatched by stage, and a whisker from the total's first to third quartile on the bar's centre (review
    r25a: beside it, it read as the next bar's), with a white ring over the segments, the y axis up to the bars and
    the whiskers within :data:`CUT` times the tallest bar; returns which whiskers run past it ``(samplers, modes)``,
    drawn to the top with a triangle and their end written."""
    bottom = np.zeros_like(table["total_s"])
    for k, key in enumerate(STAGE_KEYS + ("other_s",)):
        ax.bar(
            x.ravel(),
            table[key].ravel(),
            BAR,
            bottom=bottom.ravel(),
            label=STAGE_LABELS[key],
            color=STAGE_COLORS[k],
            hatch=STAGE_HATCHES[k],  # a second cue besides the colour
            edgecolor=COLORS["ink"],
            linewidth=0.5,
        )
        bottom = bottom + table[key]
    quartiles = (table["total_s_q1"], table["total_s_q3"])
    return quartile_whiskers(  # on its own bar's centre (review r25a: beside it, it read as the next bar's)
        ax, x, table["total_s"], *quartiles, tallest=bottom.max(), label="total: quartiles"
    )  # a cut whisker's end beside its triangle, inside the frame (review r24a: above it, it read as the ratio's)


def quartile_whiskers(
    ax,
    x: np.ndarray,
    median: np.ndarray,
    q1: np.ndarray,
    q3: np.ndarray,
    *,
    tallest: float,
    label: str = "quartiles",
    end_above: bool = False,
) -> np.ndarray:
    """Whiskers at ``x`` from the first to the third quartile ``q1``, ``q3`` (arrays of ``x``'s shape, through the
    ``median``), the y axis up to the bars (``tallest``) and every whisker within :data:`CUT` times them; a whisker
    reaching past that is drawn to the top, ends in a triangle there and its end is written beside it (above the
    frame, over the triangle, if ``end_above``: a narrow panel has no room beside). Returns which whiskers were cut
    (``x``'s shape). Times in ms, as the cut ends are written."""
    top = 1.12 * max(tallest, q3[q3 <= CUT * tallest].max(initial=0.0))  # room above for a cut whisker's label
    ax.set_ylim(0, top)
    cut = q3 > top
    whiskers = ax.errorbar(
        x.ravel(),
        median.ravel(),
        yerr=[(median - q1).ravel(), (np.minimum(q3, top) - median).ravel()],
        fmt="none",
        ecolor=COLORS["ink"],
        capsize=5,  # reader r50d: a lower cap seen inside a dark segment too
        capthick=1.5,
        linewidth=1,
        label=label,
    )
    for line in [*whiskers.lines[1], *whiskers.lines[2]]:  # caps and whiskers: a white ring, seen on a dark bar too
        line.set_path_effects(halo(1.0, ("free",)))
    if cut.any():
        ax.plot(
            x[cut],
            np.full(cut.sum(), top),
            "^",
            color=COLORS["ink"],
            markersize=6,
            transform=offset_copy(ax.transData, ax.figure, y=-3.5, units="points"),  # inside the frame, tip at the top
            label="quartile off the scale (its value written)",
        )
        where = (
            dict(xytext=(0, 2), ha="center", va="bottom") if end_above else dict(xytext=(5, -9), ha="left", va="top")
        )
        for xc, end in zip(x[cut], q3[cut]):
            written = ax.annotate(ms_text(end), (xc, top), textcoords="offset points", fontsize=10, **where)  # r23a: 8
            written.set_path_effects(halo(2.0, ("free",)))  # below the ratio labels, readable over a bar (r25a)
    return cut


SPREAD = 0.84  # of the space between two ticks, what a tick's points spread over: no two touch at the page's width


def legend_above(fig: Figure, axes, columns: int) -> None:
    """Each series once in a legend over the first panel, where a reader starts (review r15a: under the last of four
    panels it was far from the first), ``columns`` entries a row; the panels laid out under it."""
    shown = {label: h for ax in axes for h, label in zip(*ax.get_legend_handles_labels())}
    room = (0.1 + 0.2 * -(-len(shown) // columns)) / fig.get_figheight()  # the legend's share of the height
    fig.legend(
        shown.values(), shown.keys(), loc="upper center", ncol=min(len(shown), columns), fontsize=9, frameon=False
    )
    fig.tight_layout(rect=(0, 0, 1, 1 - room))


def band_words(tie: float) -> str:
    """The tie band in words, as every legend and description name it, its edges as the pages count them
    (:func:`toolkit.util.verdicts.time_verdict`: 0.90 or below saves; review r27f): ``"tie band, above 0.90 and
    below 1.10"``."""
    return f"tie band, above {1 - tie:.2f} and below {1 + tie:.2f}"


def tie_band(ax, tie: float) -> None:
    """Shade ``[1 - tie, 1 + tie]`` behind the points of a ratio panel, its edges dotted (seen without the grey)."""
    ax.axhspan(1 - tie, 1 + tie, facecolor=COLORS["shade"], edgecolor="none", zorder=0, label=band_words(tie))
    for edge in (1 - tie, 1 + tie):
        ax.axhline(edge, color=COLORS["reference"], linestyle=":", linewidth=0.8, zorder=0.5)


def log_ticks(ax, text=lambda t: f"{t:g}") -> None:
    """A log y axis labelled at 1-2-5 steps (0.2, 0.5, 1, 2), finer over less than a decade; each label ``text(t)``
    (default a plain number)."""
    ax.set_yscale("log")
    lo, hi = ax.get_ylim()
    steps = (1, 2, 5) if hi / lo >= 10 else (1, 1.5, 2, 3, 5, 7)
    ticks = [m * 10.0**e for e in range(int(np.floor(np.log10(lo))), int(np.ceil(np.log10(hi))) + 1) for m in steps]
    ticks = [t for t in ticks if lo <= t <= hi]
    ax.set_yticks(ticks, [text(t) for t in ticks])
    ax.yaxis.set_minor_formatter(NullFormatter())


def throughputs(rates: dict[str, dict[str, float]]) -> Figure:
    """Configurations checked per second, ``{scenario: {checker: rate}}`` (e.g. exact, learned): a point per scenario
    and checker on a log axis (where a bar's length would mean nothing), a checker's colour and marker the same in
    every scenario, its rate written beside it and the axis labelled at 1-2-5 steps."""
    checkers = list(dict.fromkeys(c for by in rates.values() for c in by))  # every checker, once, in its order
    fig = Figure(figsize=(PAGE_WIDTH, 3.8), layout="constrained")
    ax = fig.subplots()
    for i, checker in enumerate(checkers):
        x = _points(ax, i, len(checkers), [rates[s][checker] for s in rates], checker)
        for xi, rate in zip(x, (rates[s][checker] for s in rates)):
            ax.annotate(
                _per_second(rate),
                (xi, rate),
                xytext=(7, 0),
                textcoords="offset points",
                ha="left",
                va="center",
                fontsize=8,
            )
    drawn = [r for by in rates.values() for r in by.values()]
    ax.set_yscale("log")
    ax.set_ylim(min(drawn) / 1.6, max(drawn) * 1.6)
    log_ticks(ax, _rate_text)
    ax.grid(True, axis="y", color=COLORS["shade"], linewidth=0.8)
    ax.set_axisbelow(True)
    ax.set_xticks(np.arange(len(rates)), list(rates))
    ax.set_xlim(-0.5, len(rates) - 0.5 + 0.15)  # room for the last point's rate inside the frame (review r25a)
    ax.tick_params(labelsize=9)
    ax.set_xlabel("scenario")
    ax.set_ylabel("configurations checked\nper second", fontsize=9)  # whole at the page's width (review r30d)
    ax.set_title("Collision checking in batches: each checker's rate (log scale)", fontsize=10)
    fig.legend(loc="outside lower center", ncol=len(checkers), fontsize=9, frameon=False)
    said = "; ".join(f"{s}: " + ", ".join(f"{c} {_per_second(r[c])}" for c in checkers) for s, r in rates.items())
    text = "Configurations checked per second in batches, a point per scenario and checker, log scale, the rate written"
    return describe(fig, f"{text} beside each point. {said}.")


def _per_second(rate: float) -> str:
    """A rate in thousands or millions: ``'210k/s'``, ``'3.4M/s'``."""
    return f"{_rate_text(rate)}/s"


def _rate_text(rate: float) -> str:
    """A rate in thousands or millions, as an axis and a point write it: ``'210k'``, ``'3.4M'``."""
    return f"{rate / 1e6:.3g}M" if rate >= 999.5e3 else f"{rate / 1e3:.3g}k"


def _points(ax, i: int, n: int, values: list[float], label: str) -> np.ndarray:
    """Point ``i`` of ``n`` beside each tick (``values (ticks,)``: a scenario's rate), in the ``i``-th series' colour
    and marker (:func:`~toolkit.plots.palette.series_style`), without a line: a value is read against the axis,
    never along a line between ticks. Returns the points' ``(ticks,)`` x."""
    look = series_style(i)
    x = np.arange(len(values)) + (i - (n - 1) / 2) * SPREAD / n
    ax.plot(x, values, linestyle="none", marker=look["marker"], color=look["color"], markersize=7, label=label)
    return x


def segment_table(panels: dict[str, dict]) -> str:
    """:func:`stage_times`' bars as a Markdown table, segment by segment, in ms a query, without / with prediction:
    one row per scenario and sampler, a column per stage and "other" (five columns: the page's width)."""
    columns = [STAGE_LABELS[k].split(" (")[0] for k in (*STAGE_KEYS, "other_s")]  # short headers
    rows = ["| scenario, sampler | " + " | ".join(columns) + " |", "| --- |" + " ---: |" * len(columns)]
    for name, planning in panels.items():
        names = list(planning)
        table = _stage_table(planning, names)
        for i, sampler in enumerate(names):
            cells = (f"{table[k][i, 0]:.1f} / {table[k][i, 1]:.1f}" for k in (*STAGE_KEYS, "other_s"))
            rows.append(f"| {name}, {sampler} | " + " | ".join(cells) + " |")
    return "\n".join(rows)


def ratio_parts(panels: Mapping[str, Mapping[str, Mapping[str, float]]], samplers: Sequence[str]) -> list[Part]:
    """A ratio figure's tables for its text alternative: per panel, a row per series, a column per sampler, each
    time with / without prediction to two decimals."""
    return [
        Part(
            title,
            "time with prediction / time without; below 1, prediction saves time",
            ("series", *samplers),
            tuple((name, *(f"{ratios[s]:.2f}" for s in samplers)) for name, ratios in series.items()),
        )
        for title, series in panels.items()
    ]
