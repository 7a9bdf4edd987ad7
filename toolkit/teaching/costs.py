"""Where the extra time went in the recorded cells where our accurate network cost the most inside Algorithm 1.

Chapter 04's answer table gives, for each scenario and sampler, the median of each query's own ratio (time with
prediction / time without) of our accurate `strong` network inside the paper's Algorithm 1 (``docs/results.md``,
"Preset `strong` with `--planner paper`"). Where that ratio is :data:`DEAR` or more, the time with prediction was 25 %
or more above the time without (review r25a: "the recorded costs of 1.5-1.75x are never explained"). The record times
two things a query, sampling and the total, by means: :func:`cost_table` splits each such cell's mean time into the
sampling stage and everything after it (connecting the roadmap's edges, extracting and verifying the path), with
and without prediction. The record keeps no finer split and no counts (rounds, auxiliary samples, roadmap nodes,
edge points) for these runs; chapter 04's section 5 counts them live for one sampler.
"""

from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass

from toolkit.teaching import recorded
from toolkit.teaching.recorded import Tables
from toolkit.util.verdicts import COSTS, SAVES, time_verdict

DEAR = 1.25  # a median ratio at or above this: with prediction 25 % or more above the time without
NAMES = {"2ds": "2DS", "3dc7": "3DC-7", "3dc9": "3DC-9", "3do": "3DO"}


@dataclass(frozen=True)
class Cost:
    """One recorded cell: its median ratio and its mean times in seconds, without and with prediction."""

    scenario: str
    sampler: str
    ratio: float
    sampling: tuple[float, float]  # mean sampling time: without, with
    total: tuple[float, float]  # mean total time: without, with

    @property
    def after(self) -> tuple[float, float]:
        """The mean time after sampling (the total less sampling), without and with."""
        return self.total[0] - self.sampling[0], self.total[1] - self.sampling[1]

    @property
    def sampling_share(self) -> float:
        """The share of the extra mean time (with less without) that the slower sampling stage explains."""
        extra = self.total[1] - self.total[0]
        return (self.sampling[1] - self.sampling[0]) / extra if extra else 0.0

    @property
    def after_share(self) -> float:
        """The share of the extra mean time (with less without) that came after sampling."""
        extra = self.total[1] - self.total[0]
        return (self.after[1] - self.after[0]) / extra if extra else 0.0


def _mean_times(preset: str, tables: Tables | None = None) -> dict[tuple[str, str], dict[str, str]]:
    """``preset``'s table "Times behind Table 3": ``{(scenario, sampler): {column: cell}}``."""
    times = recorded.packaged() if tables is None else tables
    heading = next(name for name in times[preset] if "times behind table 3" in name.lower())
    found = times[preset][heading]
    return {(row[0], row[1]): dict(zip(found["columns"], row)) for row in found["rows"]}


def sampling_shares(preset: str, tables: Tables | None = None) -> list[float]:
    """Per recorded cell of ``preset``, the sampling stage's share of a mean query without prediction: the most that
    skipping the samples' checks can save (review r30d: the "why" in a number)."""
    return list(shares_by_cell(preset, tables).values())


def shares_by_cell(preset: str, tables: Tables | None = None) -> dict[tuple[str, str], float]:
    """:func:`sampling_shares` by cell: ``{(scenario, sampler): share}``."""
    return {
        key: recorded.ours(row["sampling without"]) / recorded.ours(row["total without"])
        for key, row in _mean_times(preset, tables).items()
    }


def dear_cells(tables: Tables | None = None) -> list[Cost]:
    """The cells whose median ratio is :data:`DEAR` or more, with their mean times from "Times behind Table 3"."""
    ratios = recorded.query_ratios(recorded.ALGORITHM_1, tables)
    rows = _mean_times(recorded.ALGORITHM_1, tables)
    cells = []
    for scenario, by_sampler in ratios.items():
        for sampler, ratio in by_sampler.items():
            if ratio >= DEAR:
                row = rows[scenario, sampler]
                means = {k: recorded.ours(row[k]) for k in ("sampling without", "sampling with", "total without")}
                cells.append(
                    Cost(
                        NAMES.get(scenario, scenario),
                        sampler,
                        ratio,
                        (means["sampling without"], means["sampling with"]),
                        (means["total without"], recorded.ours(row["total with"])),
                    )
                )
    return cells


def cost_table(tables: Tables | None = None) -> str:
    """The dear cells as a Markdown table (five columns, ms a query by means, without → with), and a line that counts
    in how many the larger part of the extra mean time came after sampling."""
    cells = dear_cells(tables)
    rows = [
        "| cell | median ratio | sampling, ms | after sampling, ms | share of the extra from sampling |",
        "| --- | ---: | ---: | ---: | ---: |",
    ]
    for c in cells:
        rows.append(
            f"| {c.scenario} {c.sampler} | {c.ratio:.2f} | {1000 * c.sampling[0]:.1f} → {1000 * c.sampling[1]:.1f} "
            f"| {1000 * c.after[0]:.1f} → {1000 * c.after[1]:.1f} | {c.sampling_share:.0%} |"
        )
    mostly = [c for c in cells if c.after_share > 0.5]
    rest = [f"{c.scenario} {c.sampler}" for c in cells if c not in mostly]
    others = f"the other: {rest[0]}" if len(rest) == 1 else f"the others: {', '.join(rest) or 'none'}"
    return (
        "\n".join(rows) + f"\n\nThe larger part of the extra mean time came after sampling in {len(mostly)} of these "
        f"{len(cells)} cells ({others})."
    )


def split_sentence(tables: Tables | None = None) -> str:
    """One sentence on the dear cells (review r27d: the "why" must cover the costs the page records): how much of the
    extra mean time the slower sampling stage explains, and where the rest came from, said only as far as the record
    splits it."""
    cells = dear_cells(tables)
    if not cells:
        return ""
    shares = [c.sampling_share for c in cells]
    low, high = round(100 * min(shares)), round(100 * max(shares))
    span = f"{low} %" if low == high else f"{low}–{high} %"
    if all(c.after[1] > c.after[0] for c in cells):
        rest = (
            "the rest is work after sampling (connecting and checking the roadmap's edges, extracting and verifying "
            "the path) that grew with prediction, which the record does not break down"
        )
    else:
        rest = "the rest came after sampling, which the record does not break down"
    return (
        f"In the {len(cells)} recorded cells where the time with prediction was 25 % or more above the time without "
        f"(section 6's last table), slower sampling explains {span} of the extra mean time; {rest}."
    )


def middle_halves(preset: str, tables: Tables | None = None) -> dict[str, dict[str, tuple[float, float, float]]]:
    """The table "each query's own ratio" of ``preset`` with its middle halves: ``{scenario: {sampler: (median, lower
    quartile, upper quartile)}}``, from cells like "1.13 (0.77–1.59)"."""
    found = recorded.table(preset, "each query's own ratio", tables)
    out: dict[str, dict[str, tuple[float, float, float]]] = {}
    for scenario, cells in found.items():
        for column, cell in cells.items():
            median, low, high = (float(v) for v in re.findall(r"\d+(?:\.\d+)?", cell)[:3])
            out.setdefault(scenario, {})[column.split()[1]] = (median, low, high)
    return out


NOISE_EDGE = 2  # a median within this many times timing's own reach of 1 is "at the noise edge" (docs/results.md)


def timing_reach(tables: Tables | None = None) -> float:
    """The furthest that timing one computation twice moved a median of each query's own ratio from 1 (the table
    "timed twice" of :data:`toolkit.teaching.recorded.ALGORITHM_1`; ``tables`` without that run borrow the record's,
    as the results page does)."""
    runs = [found for found in (tables or {}, recorded.packaged()) if recorded.ALGORITHM_1 in found]
    run = runs[0][recorded.ALGORITHM_1]
    rows = next(found for heading, found in run.items() if "timed twice" in heading.lower())["rows"]
    return max(abs(float(row[4].split()[0]) - 1) for row in rows)


def noise_edge(tables: Tables | None = None) -> float:
    """How far from 1 the noise edge reaches: :data:`NOISE_EDGE` times :func:`timing_reach` (the results page's)."""
    return NOISE_EDGE * timing_reach(tables)


def edge_cells(preset: str, tables: Tables | None = None) -> list[tuple[str, str, float]]:
    """``preset``'s saves and costs (by the median of each query's own ratio) that lie at the noise edge, less than
    :func:`noise_edge` from 1: ``[(scenario key, sampler, median), ...]``, the results page's cells (review r31d: one
    rule for the page and the record)."""
    reach = noise_edge(tables)
    return [
        (key, sampler, median)
        for key, by_sampler in middle_halves(preset, tables).items()
        for sampler, (median, _, _) in by_sampler.items()
        if time_verdict(median) in (COSTS, SAVES) and abs(median - 1) < reach
    ]


def at_edge(preset: str, tables: Tables | None = None) -> Counter:
    """How many of :func:`edge_cells` are saves and how many costs."""
    return Counter(time_verdict(median) for _, _, median in edge_cells(preset, tables))


MARK = r"\*"  # Markdown for the mark on a verdict inside timing's own reach (reader r33d: one band in prose)
_VERDICT_CELL = re.compile(rf"({SAVES}|{COSTS})<br>\((\d+\.\d+)\)")


def marked(table: str, tables: Tables | None = None) -> str:
    """``table`` (a narrow :func:`toolkit.teaching.findings.ratio_table`) with :data:`MARK` after each "saves time" or
    "costs time" of our rows (not the paper's) whose ratio lies less than :func:`noise_edge` from 1: the verdict word
    stays, the mark says timing alone could have moved it that far."""
    reach = noise_edge(tables)

    def mark(found: re.Match) -> str:
        inside = abs(float(found[2]) - 1) < reach
        return f"{found[1]}{MARK if inside else ''}<br>({found[2]})"

    rows = table.splitlines()
    return "\n".join(row if "the paper" in row.split("|")[1] else _VERDICT_CELL.sub(mark, row) for row in rows)
