"""Figure 1's verdict as the page reads it (reader r57f, lift item 4): a ring round every point beyond the noise band
of each query's own ratio (the page's "clearly"), and a fill key in words with no glyph (reader r60e: a key glyph
no point takes reads as a missing point). :func:`ring` takes the figure
:func:`toolkit.plots.query_ratios.own_ratios` draws and adds both, its legend rebuilt and its text alternative and
longer description told which points are ringed, from the data."""

from __future__ import annotations

import dataclasses
from typing import Any

from matplotlib.figure import Figure
from matplotlib.legend_handler import HandlerTuple
from matplotlib.transforms import blended_transform_factory

from toolkit.plots import alt, query_ratios
from toolkit.plots.palette import COLORS
from toolkit.plots.query_ratios import Cells
from tools.results_words import NAMES

RING_SIZE = 2.15  # a ring's diameter over a marker's: it clears a hollow triangle's wider edge
RING_WIDTH = 1.4  # points, the ring's line
RING_LABEL = "ringed: beyond the noise band (clearly)"
FILL_GLYPH = "None"  # the fill key's entries are words only: every glyph in the key is one the figure draws
FILL_KEYS = ("filled:", "hollow:")
RIGHT_PAD = 0.3  # x units added on the right: the last hollow point's ring (2.15 markers wide) clears the frame
TIE_EDGES = (0.9, 1.1)  # the tie band's edges, labelled on the left axis (findings.TIE either side of 1)


def beyond(cells: Cells, band: tuple[float, float]) -> list[tuple[str, str, float]]:
    """The cells whose median lies on an edge of ``band`` or beyond it: ``[("3dc7", "OB", 1.50), ...]``."""
    low, high = band
    return [(s, sampler, m) for s, by in cells.items() for sampler, (m, _, _) in by.items() if not low < m < high]


def _drawn_beyond(ax, band: tuple[float, float]) -> list[tuple[float, float]]:
    """Where :func:`toolkit.plots.query_ratios.own_ratios` drew each median on an edge of ``band`` or beyond it, read
    from the figure itself (a median is a one-point marker line): ``[(x, median), ...]``."""
    low, high = band
    medians = [line for line in ax.lines if len(line.get_xdata()) == 1 and line.get_marker() not in ("None", "")]
    return [(line.get_xdata()[0], line.get_ydata()[0]) for line in medians if not low < line.get_ydata()[0] < high]


def ring(fig: Figure, fast: Cells, slow: Cells, band: tuple[float, float], title: str) -> Figure:
    """``fig`` (Figure 1, ``fast`` filled and ``slow`` hollow) with a ring round each point beyond ``band``, the fill
    key as words, its legend rebuilt with the ring's entry (:func:`_legend`), and its words told which points are
    ringed (:func:`_words`)."""
    ax = fig.axes[0]
    for x, median in _drawn_beyond(ax, band):
        ax.plot([x], [median], **_ring_look(), zorder=4)
    ax.plot([], [], **_ring_look(), label=RING_LABEL)
    for line in ax.lines:
        if str(line.get_label()).startswith(FILL_KEYS):
            line.set_marker(FILL_GLYPH)
    _tie_edges(ax)
    _legend(fig, ax, title)
    return _words(fig, fast, slow, band)


def _tie_edges(ax) -> None:
    """Reader r59f, item 5: the right limit moved out so the last point's ring clears the frame, and the tie band's
    edges labelled on the left beside the "1", set apart from it (above and below, smaller), as the home page shows
    this figure too."""
    low, high = ax.get_xlim()
    ax.set_xlim(low, high + RIGHT_PAD)
    ticks = [float(t) for t in ax.get_yticks()]
    names = {t: label.get_text() for t, label in zip(ticks, ax.get_yticklabels())}
    names.update({TIE_EDGES[0]: f"{TIE_EDGES[0]:.2f}", TIE_EDGES[1]: f"{TIE_EDGES[1]:.2f}"})
    shown = sorted(names)
    ax.set_yticks(shown, [names[t] for t in shown])
    for t, label in zip(shown, ax.get_yticklabels()):
        if t in TIE_EDGES:
            label.set_fontsize(7.5)
            label.set_verticalalignment("top" if t < 1 else "bottom")


def _ring_look() -> dict:
    size = query_ratios.SIZE * RING_SIZE
    return dict(
        linestyle="none",
        marker="o",
        markersize=size,
        markerfacecolor="none",
        markeredgecolor=COLORS["ink"],
        markeredgewidth=RING_WIDTH,
    )


def _legend(fig: Figure, ax, title: str) -> None:
    """Figure 1's legend again, between its title and its axes as :func:`toolkit.plots.query_ratios.own_ratios` sets
    it: each verdict's filled and hollow icons side by side, then the bands, the ring and the fill key."""
    for old in list(fig.legends):
        old.remove()
    empty = [line for line in ax.lines if len(line.get_xdata()) == 0]
    pairs: dict[str, Any] = {}  # an artist, or a pair of them
    for k, line in enumerate(empty):
        label = str(line.get_label())
        if label.startswith("_"):
            continue
        partner = empty[k + 1] if k + 1 < len(empty) and empty[k + 1].get_label().startswith("_") else None
        pairs[label] = (line, partner) if partner is not None else line
    for handle, label in zip(*ax.get_legend_handles_labels()):  # the bands
        pairs.setdefault(label, handle)
    verdicts = [label for label in pairs if label.startswith("median")]
    tie = [label for label in pairs if label.startswith("tie band")]
    noise = [label for label in pairs if label.startswith("noise band")]
    keys = [label for label in pairs if label.startswith(FILL_KEYS)]
    order = [*verdicts, *noise, *tie, RING_LABEL, *keys]  # column 1: verdicts, noise band; 2: the rest (the width)
    legend = fig.legend(
        [pairs[label] for label in order],
        order,
        loc="lower center",
        bbox_to_anchor=(0.5, 1.0),
        bbox_transform=blended_transform_factory(fig.transFigure, ax.transAxes),
        ncol=2,
        fontsize=9,
        frameon=False,
        borderaxespad=0.2,
        handler_map={tuple: HandlerTuple(ndivide=None, pad=0.6)},
    )
    fig.canvas.draw()  # the legend's height, known once drawn
    height = legend.get_window_extent().height * 72 / fig.dpi  # points
    ax.set_title(title, fontsize=10, pad=height + 6)
    fig.tight_layout()


def _words(fig: Figure, fast: Cells, slow: Cells, band: tuple[float, float]) -> Figure:
    """The text alternative and the longer description told the ringed points, from the data."""
    low, high = band

    def said(cells: Cells) -> str:
        return ", ".join(f"{NAMES.get(s, s)} {sampler} {m:.2f}" for s, sampler, m in beyond(cells, band))

    far = {False: beyond(fast, band), True: beyond(slow, band)}
    words = (
        f" Ringed, beyond the noise band ({low:.2f}–{high:.2f}) and so clear: "
        f"{alt.many(len(far[False]), 'filled point')}"
        f"{' (' + said(fast) + ')' if far[False] else ''} and {alt.many(len(far[True]), 'hollow point')}"
        f"{' (' + said(slow) + ')' if far[True] else ''}."
    )
    parts = []
    for part, cells in zip(alt.parts_of(fig), (fast, slow)):
        ringed = {(NAMES.get(s, s), sampler) for s, sampler, _ in beyond(cells, band)}
        rows = tuple(
            (row[0], *(f"{c}, ringed" if (row[0], col) in ringed else c for col, c in zip(part.columns[1:], row[1:])))
            for row in part.rows
        )
        text = f"{part.text}; “ringed”: beyond the noise band, {low:.2f}–{high:.2f}"
        parts.append(dataclasses.replace(part, text=text, rows=rows))
    return alt.describe(fig, alt.alt_text(fig) + words, parts)
