"""The bands of a time-ratio figure (:mod:`toolkit.plots.query_ratios`): the noise band hatched round the tie band, and
the bands' edges labelled outside the axes, where the "1" on the left cannot crowd them."""

from __future__ import annotations

from matplotlib.ticker import NullLocator

from toolkit.plots.palette import COLORS


def edge_labels(ax, edges: list[float], name: str = "") -> None:
    """The bands' ``edges`` (sorted) labelled outside the axes on the right, where the "1" on the left cannot crowd
    them (reader r41f: whether 1.10 was a tie or a cost could not be read off the plot): of each pair of edges on one
    side of 1, the outer label stands beyond its tick and the inner one towards 1, so the two never touch. ``name``,
    where given, says whose edges they are beside them (reader r44e, home 3: 0.82 and 1.18 could be read as the tie
    band's)."""
    right = ax.secondary_yaxis("right")
    right.set_yticks(edges, [f"{e:.2f}" for e in edges])
    right.yaxis.set_minor_locator(NullLocator())
    right.tick_params(labelsize=8, length=3, pad=2)
    if name:
        right.set_ylabel(name, fontsize=8, rotation=-90, va="bottom", labelpad=2)
    below = [e for e in edges if e < 1]
    for label, e in zip(right.get_yticklabels(), edges):
        outer = e == min(below) if e < 1 else e == max(edges)
        label.set_verticalalignment(("top" if e < 1 else "bottom") if outer else ("bottom" if e < 1 else "top"))


NOISE_WORDS = (  # means_grid's hatching, told apart from own_ratios' (reader r32f: one hatch meant two bands)
    "noise band of a ratio of means, {low:.2f}–{high:.2f}: twice how far timing alone moved a ratio of means"
)
EDGE_WORDS = "noise band of this ratio, {low:.2f}–{high:.2f}: a cost or saving there is no clear evidence"
EDGE_HATCH, NOISE_HATCH = "///", "\\\\\\"  # own_ratios' noise band; means_grid's, the other slant


def edge_band(ax, edge: float, tie: float) -> None:
    """Hatch ``[1 - edge, 1 + edge]`` round the tie band (``tie``): the noise band, where a median read as a cost or a
    saving lies within twice timing's own reach of 1, told apart from the clear ones by where it stands."""
    hatch_round(ax, (1 - edge, 1 + edge), tie, EDGE_WORDS.format(low=1 - edge, high=1 + edge).split(":")[0])


def hatch_round(ax, reach: tuple[float, float], tie: float, label: str | None, hatch: str = EDGE_HATCH) -> None:
    """Hatch from ``reach[0]`` to the tie band and from it to ``reach[1]``, each outer edge a line (dashed under
    :data:`EDGE_HATCH`, dotted under any other), so the hatching reads at the page's width (reader r31f: it was
    faint); ``label`` names it once in the legend."""
    for k, (low, high) in enumerate(((reach[0], 1 - tie), (1 + tie, reach[1]))):
        ax.axhspan(
            low,
            high,
            facecolor="none",
            edgecolor=COLORS["reference"],
            hatch=hatch,
            linewidth=0,
            zorder=0,
            label=label if k == 0 else None,
        )
    for y in reach:
        style = "--" if hatch == EDGE_HATCH else ":"
        ax.axhline(y, color=COLORS["reference"], linestyle=style, linewidth=1.0, zorder=0.5)


def noise_bands(axes, noise: tuple[float, float] | None, tie: float) -> list[str]:
    """``noise`` (the noise band of a ratio of means: twice how far timing alone moved one, both ways) hatched round
    the tie band of every panel of ``axes``, named once in the legend; what the text alternative says of it (nothing
    where ``noise`` is ``None``)."""
    if noise is None:
        return []
    words = NOISE_WORDS.format(low=noise[0], high=noise[1])
    for k, ax in enumerate(axes):
        hatch_round(ax, noise, tie, words.split(":")[0] if k == 0 else None, NOISE_HATCH)
    return [f"hatched the other way round the tie band, the {words}"]


def band_edges(ax, ticks: list[float], size: float = 8) -> None:
    """``ticks`` near 1 (a band's edges) labelled on the right of ``ax``, apart from the "1" on the left; those
    above 1 written above their tick, those below under it, so two edges never touch (review r30f: Figure 3's "1.1"
    and "0.9" did)."""
    edges = ax.secondary_yaxis("right")
    edges.set_yticks(ticks, [f"{t:g}" for t in ticks])
    edges.yaxis.set_minor_locator(NullLocator())
    edges.tick_params(labelsize=size, length=2, pad=1)
    for label, t in zip(edges.get_yticklabels(), ticks):
        label.set_verticalalignment("bottom" if t > 1 else "top")
