"""The results page's noise bands: how far timing one computation twice moved each of its ratios (the `strong
--planner paper` run's table "timed twice", :func:`noise`), the bands near 1 read from it (:func:`bands`), and the cells
of Figure 1 that lie inside the noise band of each query's own ratio (:func:`at_noise_edge`), so no single cell inside
timing's own reach is read as evidence (review r28f)."""

from __future__ import annotations

import re
from typing import NamedTuple

from toolkit.teaching import costs, findings, recorded
from toolkit.teaching.checker_scope import SLOW
from toolkit.teaching.costs import NOISE_EDGE
from toolkit.teaching.recorded import Tables
from tools.results_words import NAMES, change

INTERVAL = re.compile(r"(\d+\.\d+) \((\d+\.\d+)–(\d+\.\d+)\)")  # "1.24 (1.12–1.36)": a median (middle half)


def medians_floor(tables: Tables) -> tuple[float, float] | None:
    """The noise band of a ratio of the two medians (:func:`noise`); ``None`` where ``tables`` hold no run timed
    twice."""
    try:
        return noise(tables).medians
    except (KeyError, StopIteration):
        return None


def own_intervals(tables: Tables, key: str = recorded.ALGORITHM_1) -> dict[str, dict[str, tuple[float, float, float]]]:
    """The strong network inside Algorithm 1 (``key``: with our compiled checker, or :data:`checker_scope.SLOW`), its
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
    """One band near 1 per statistic, ``(low, high)``, from the table "timed twice" (one computation, Algorithm 1
    without prediction, timed twice in turn)."""

    own: tuple[float, float]  # the median of each query's own ratio
    means: tuple[float, float]  # the ratio of the means
    medians: tuple[float, float]  # the ratio of the two medians


def _timed_twice_here(tables: Tables) -> None:
    """Raise ``KeyError`` or ``StopIteration`` unless ``tables`` hold the `strong --planner paper` run with its table
    "timed twice" (:mod:`toolkit.teaching.costs` would borrow the packaged record's; this page reads its own)."""
    next(t for heading, t in tables[recorded.ALGORITHM_1].items() if "timed twice" in heading)


def measured(tables: Tables) -> Noise:
    """How far timing alone moved each ratio in the `strong --planner paper` run: its lowest and highest value."""
    _timed_twice_here(tables)
    return Noise(*(costs.measured_reach(tables, kind) for kind in Noise._fields))


def noise(tables: Tables) -> Noise:
    """The noise band of each ratio (:func:`toolkit.teaching.costs.floors`: twice timing's reach, both ways)."""
    _timed_twice_here(tables)
    bands = costs.floors(tables)
    return Noise(*(bands[kind] for kind in Noise._fields))


def at_noise_edge(medians: dict[str, dict[str, tuple[float, float, float]]], tables: Tables) -> list[str]:
    """The cells read as saving or costing time whose median lies less than :data:`NOISE_EDGE` times timing's own
    reach from 1 (:func:`noise`, each query's own ratio): ``["2DS BS 1.13", ...]``."""
    edge = costs.noise_edge(tables)
    return [
        f"{scenario} {sampler} {m:.2f}"
        for scenario, by in medians.items()
        for sampler, (m, _, _) in by.items()
        if change(m) != "about the same time" and abs(m - 1) < edge
    ]


def bands(tables: Tables) -> str:
    """The bands near 1 the page reads with, one table under the summary: the tie band every count reads with, and
    the noise band of each statistic, all built by one rule (:func:`toolkit.teaching.costs.floors`; readers r43f, r44e:
    one rule for the three, not a doubled band beside two as measured)."""
    band, reach, tie = noise(tables), measured(tables), findings.TIE

    def edges(low: float, high: float) -> str:
        return f"{low:.2f}–{high:.2f}"

    def built(kind: str) -> str:
        low, high = getattr(reach, kind)
        return f"timing alone: {edges(low, high)}; 1 ± {NOISE_EDGE} × {costs.timing_reach(tables, kind):.2f}"

    rows = [  # reader r41f, item 3: every band the page uses, one row each, a column saying how it is built
        (  # reader r43f, contradiction 9: printed as the counts read it (0.90 saves, 1.10 costs)
            "tie band",
            f"{1 - tie:.2f} < r < {1 + tie:.2f}",
            "our 10 % rule: strictly inside, a tie",
            "every count and figure",
        ),
        ("noise band of each query's own ratio", edges(*band.own), built("own"), "own-ratio counts; Figure 1"),
        (  # reader r45f, item 4: every run counted by means borrows it, the 2 December run too (r48f: not Figure 3)
            "noise band of a ratio of means",
            edges(*band.means),
            built("means"),
            "counts by means, the 2 December run's included; Figure 2 (Figure 3 draws none: sampling times were never "
            "timed twice)",
        ),
        (
            "noise band of a ratio of medians",
            edges(*band.medians),
            built("medians"),
            "the lazy-PRM finding: the lazy-PRM run (3 December) and the 2 December run, against the lazy PRM",
        ),
    ]
    head = ["| band near 1 | from–to | how built | used in |", "| --- | --- | --- | --- |"]
    rule = (
        "*The table of bands*: every noise band is built one way: time one computation twice (Algorithm 1 without "
        "prediction, the table "
        "“timed twice”), see how far timing alone moved the statistic from 1 on its larger side, and take "
        f"{NOISE_EDGE} times that, both ways, because a single repeat understates timing noise. A ratio of means or of "
        "medians moves further than each query's own ratio: it divides two sums (or two medians) over the same 100 "
        "queries, where a few slow queries weigh on a mean, while an own ratio divides one query's two times, taken "
        "in turn under the same load."
    )
    said = rule + "\n\n" + "\n".join(head + [f"| {' | '.join(row)} |" for row in rows])
    borrowed = (
        (  # reader r43f, item 9: said once, here; elsewhere a pointer to this table
            ""
            if any("timed twice" in heading for heading in tables[SLOW])
            else " The python-fcl run was not timed twice: its noise bands are borrowed from the compiled run."
        )
        + (  # reader r45f, item 4: the 2 December run borrows two bands, each where its statistic is read
            " Nor was the run of 2 December: it borrows the means band (its Table 3: the top table, Figure 2) and the "
            "medians band (against the lazy PRM)."
            if not any("timed twice" in heading for heading in tables["paper"])
            else ""
        )
        + (  # reader r52f, smaller items: the lazy-PRM run of 3 December borrows one too
            " Nor was the lazy-PRM run of 3 December: it borrows the medians band, timed with Algorithm 1."
            if not any("timed twice" in heading for heading in tables["strong"])
            else ""
        )
    )
    strict = (  # reader r44f, item 8: said once, here (costs.inside)
        "Every band is read strictly: a ratio inside one (low < r < high) is no clear evidence of a saving or a cost; "
        "a ratio on an edge counts as beyond it."
    )
    return f"{said}\n\n{strict}{borrowed}"


def costs_far(groups: dict, floor: tuple[float, float] | None) -> str:
    """Reader r46f, item 6: the strong network's costs against the lazy PRM read against the noise band of a ratio
    of medians too, those inside it named; empty where no band is known."""
    dearer = groups["strong"]["more time"]
    near = [f"{name} {r:.2f}" for name, r in dearer if floor is not None and costs.inside(r, floor)]
    if floor is None or not dearer:
        return ""
    return (
        f" Of the {len(dearer)} that took more time, {len(dearer) - len(near)} lie beyond the noise band of a ratio "
        f"of medians, {floor[0]:.2f}–{floor[1]:.2f}" + (f" ({' and '.join(near)} inside it)." if near else ".")
    )
