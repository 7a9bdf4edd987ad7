"""Chapter 04's two figures: the answer (our median own ratio per cell, or Table 3 beside our ratios of means) and
section 4's checker rates, each checker in one colour and marker across the page (reader r44d, item 3)."""

from __future__ import annotations

from matplotlib.figure import Figure

from toolkit.plots.answer import CHECKERS, SHAPES, answer_ratios
from toolkit.plots.palette import COLORS
from toolkit.plots.timings import throughputs
from toolkit.teaching import checker_scope, costs, findings
from toolkit.teaching.recorded import Tables

SERIES = {  # the answer figure's legend, a line a series (reader r33d: five lines for three marker kinds)
    "the paper's Table 3": "the paper's Table 3 (its means): diamonds",
    "ours (`strong` preset), medians": "ours, our fast checker (compiled in 3D, numpy in 2DS): crosses",
    "ours (`strong`, python-fcl), medians": "ours, python-fcl on both sides: hexagons",
}


def answer_figure(tables: Tables | None = None, means: bool = False) -> Figure:
    """Our median own ratio per cell, its middle half and band; with ``means``, Table 3 beside our ratios of means."""
    rows = checker_scope.compact(tables)
    papers = {label: r for label, r in rows.items() if "the paper's" in label}
    return answer_ratios(
        papers | checker_scope.our_means(tables) if means else {k: r for k, r in rows.items() if k not in papers},
        tie=findings.TIE,
        spans=None if means else checker_scope.spans(tables),
        names=SERIES,
        order=list(SERIES),  # each series its marker in both figures
        floor=costs.floors(tables)["means"],
        median_floor=costs.floors(tables)["own"],
    )


def rates_figure(rates: dict[str, dict[str, float]]) -> Figure:
    """Section 4's figure, :func:`toolkit.plots.timings.throughputs` (``{scenario: {checker: rate}}``, checkers named
    as :data:`toolkit.plots.answer.CHECKERS`), each checker in chapter 04's one colour and marker (reader r44d, item
    3: the network's triangle meant "saves time" elsewhere), its marker named in the legend."""
    fig = throughputs(rates)  # then restyled
    ax = fig.axes[0]
    for line in ax.lines:
        name = str(line.get_label())
        if name in CHECKERS:
            color, marker = CHECKERS[name]
            line.set(marker=marker, color=color, markerfacecolor=color, markeredgecolor=COLORS["ink"])
            line.set_markeredgewidth(0.6)
            line.set_label(f"{name} ({SHAPES[marker]})")
    for legend in list(fig.legends):
        legend.remove()
    fig.legend(loc="outside lower center", ncol=len(ax.lines), fontsize=9, frameon=False)
    return fig
