"""The results page's noise floor: how far timing one computation twice moved each of its ratios (the `strong
--planner paper` run's table "timed twice", :func:`noise`), and the cells of Figure 1 that lie at its edge
(:func:`at_noise_edge`), so no single cell inside timing's own reach is read as evidence (review r28f)."""

from __future__ import annotations

import re
from typing import NamedTuple

from toolkit.teaching import findings, recorded
from toolkit.teaching.costs import NOISE_EDGE
from toolkit.teaching.costs import timing_reach as reach_of  # chapter 04 reads the same rule
from toolkit.teaching.recorded import Tables
from tools.results_words import NAMES, change

INTERVAL = re.compile(r"(\d+\.\d+) \((\d+\.\d+)–(\d+\.\d+)\)")  # "1.24 (1.12–1.36)": a median (middle half)


def medians_floor(tables: Tables) -> tuple[float, float] | None:
    """How far timing alone moved a ratio of the two medians (:func:`noise`); ``None`` where ``tables`` hold no run
    timed twice."""
    try:
        return noise(tables).medians
    except (KeyError, StopIteration):
        return None


def own_intervals(tables: Tables, key: str = recorded.ALGORITHM_1) -> dict[str, dict[str, tuple[float, float, float]]]:
    """The `strong` network inside Algorithm 1 (``key``: with our compiled checker, or :data:`checker_scope.SLOW`), its
    table "each query's own ratio": ``{scenario name: {sampler: (median, q1, q3)}}`` of each query's total time with /
    without prediction."""
    found: dict[str, dict[str, tuple[float, float, float]]] = {}
    for scenario, cells in recorded.table(key, "each query's own ratio", tables).items():
        for column, cell in cells.items():  # "Total BS": "1.13 (0.77–1.59)"
            read = INTERVAL.fullmatch(cell)
            if read is None:
                raise ValueError(f"each query's own ratio, {scenario} {column}: {cell!r} is no 'median (q1–q3)'")
            found.setdefault(NAMES.get(scenario, scenario), {})[column.split()[1]] = (
                float(read[1]),
                float(read[2]),
                float(read[3]),
            )
    return found


class Noise(NamedTuple):
    """How far timing alone moved each statistic: the table "timed twice" (one computation, Algorithm 1 without
    prediction, timed twice in turn), its lowest and highest ratio per column."""

    own: tuple[float, float]  # the median of each query's own ratio
    means: tuple[float, float]  # the ratio of the means
    medians: tuple[float, float]  # the ratio of the two medians


def noise(tables: Tables) -> Noise:
    """The noise floor of the `strong --planner paper` run (:class:`Noise`)."""
    twice = next(t for heading, t in tables[recorded.ALGORITHM_1].items() if "timed twice" in heading)
    rows = twice["rows"]  # scenario, sampler, ratio of the means, ratio of the medians, each query's own ratio

    def reach(column: int) -> tuple[float, float]:
        values = [float(row[column].split()[0]) for row in rows]
        return min(values), max(values)

    return Noise(own=reach(4), means=reach(2), medians=reach(3))


def noise_line(tables: Tables) -> str:
    """One line under Figure 1: how far timing alone moved its ratio (reader r37f, contradiction 2: no pointer to a
    row in a fold)."""
    floor = noise(tables).own
    return (
        "*Noise floor* of each query's own ratio: timing alone moved its median to "  # reader r35f, item 7: named
        f"{floor[0]:.2f}–{floor[1]:.2f}; the noise edge doubles that reach."
    )


def at_noise_edge(medians: dict[str, dict[str, tuple[float, float, float]]], tables: Tables) -> list[str]:
    """The cells read as saving or costing time whose median lies less than :data:`NOISE_EDGE` times timing's own
    reach from 1 (:func:`noise`): ``["2DS BS 1.13", ...]``."""
    reach = reach_of(tables)
    return [
        f"{scenario} {sampler} {m:.2f}"
        for scenario, by in medians.items()
        for sampler, (m, _, _) in by.items()
        if change(m) != "about the same time" and abs(m - 1) < NOISE_EDGE * reach
    ]


def bands(tables: Tables) -> str:
    """The page's bands near 1 (reader r33f, item 3; r37f, item 3: every figure reads two of them, both in the
    visible table): the tie band every count reads with, the noise edge Figure 1 hatches and the ratio-of-means floor
    Figures 2-3 hatch; the other two floors, each query's own (which the edge doubles) and the ratio of medians (the
    lazy PRM's), in a fold."""
    floor, edge = noise(tables), NOISE_EDGE * reach_of(tables)
    tie = findings.TIE

    def edges(low: float, high: float) -> str:
        return f"{low:.2f}–{high:.2f}"

    lead = [
        (
            "tie band (our 10 % rule)",
            edges(1 - tie, 1 + tie),
            "a tie; at or past its edges, a saving or a cost",
            "every count; shaded in every figure",
        ),
        (
            "noise edge",
            edges(1 - edge, 1 + edge),
            f"twice as far from 1 as timing alone moved each query's own ratio (2 × {reach_of(tables):.2f}): a "
            "saving or cost inside it is no clear evidence",
            "Figure 1 (hatched, dashed edges); the summary's counts",
        ),
        (
            "ratio-of-means floor",
            edges(*floor.means),
            "how far timing alone moved a ratio of the two modes' mean times",
            "Figures 2–3 (hatched, dotted edges); the `paper` preset against Algorithm 1",
        ),
    ]
    floors = [
        (
            "noise floor, each query's own ratio",
            edges(*floor.own),
            "how far timing one computation twice moved it (the table “timed twice”)",
            "doubled: the noise edge",
        ),
        (
            "noise floor, ratio of medians",
            edges(*floor.medians),
            "the same, for a ratio of the two modes' median times (measured on Figure 1's run, borrowed for the "
            "lazy PRM's)",
            "against the lazy PRM (the medians tables)",
        ),
    ]
    head = ["| band near 1 | from–to | what it judges | where this page uses it |", "| --- | --- | --- | --- |"]
    table = "\n".join(head + [f"| {' | '.join(row)} |" for row in lead])
    folded = "\n".join(head + [f"| {' | '.join(row)} |" for row in floors])
    return (
        f'{table}\n\n<details markdown="1"><summary>The two noise floors behind them: each query\'s own, which the '
        f"noise edge doubles, and the lazy PRM's</summary>\n\n{folded}\n\n</details>"
    )
