"""Where the extra time went in the recorded cells where our accurate network cost the most inside Algorithm 1.

Chapter 04's answer table gives, for each scenario and sampler, the median of each query's own ratio (time with
prediction / time without) of our accurate `strong` network inside the paper's Algorithm 1 (``docs/results.md``,
"Preset `strong` with `--planner paper`"). Where that ratio costs time beyond the noise band and the mean time grew too
(:func:`dear_cells`; reader r38d: not a cut-off of 1.25), the costs need explaining (review r25a). The record times
two things a query, sampling and the total, by means: :func:`cost_table` splits each such cell's mean time into the
sampling stage and everything after it (connecting the roadmap's edges, extracting and verifying the path), with
and without prediction. The record keeps no finer split and no counts (rounds, auxiliary samples, roadmap nodes,
edge points) for these runs; chapter 04's section 5 counts them live for one sampler.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from toolkit.teaching import recorded
from toolkit.teaching.recorded import Tables
from toolkit.util.verdicts import CLOSE, COSTS, NEAR, SAVES, TIES, cost_verdict, time_verdict

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


def mean_times(preset: str, tables: Tables | None = None) -> dict[tuple[str, str], dict[str, str]]:
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
        for key, row in mean_times(preset, tables).items()
    }


def dear_cells(tables: Tables | None = None) -> list[Cost]:
    """The cells whose median ratio costs time beyond the noise band (above :func:`floors`' band) and whose ratio of
    mean times costs time too, with their mean times from "Times behind Table 3" (a cell whose mean time fell has no
    extra time to split)."""
    ratios = recorded.query_ratios(recorded.ALGORITHM_1, tables)
    edge = floors(tables)["own"][1]
    rows = mean_times(recorded.ALGORITHM_1, tables)
    cells = []
    for scenario, by_sampler in ratios.items():
        for sampler, ratio in by_sampler.items():
            mean = 1 - recorded.improvements(recorded.ALGORITHM_1, scenario, "total", tables)[sampler]
            if ratio > edge and time_verdict(mean) == COSTS:
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


def left_out(tables: Tables | None = None) -> dict[str, float]:
    """The cells whose median ratio costs time beyond the noise band but whose mean time did not grow, so
    :func:`dear_cells` leaves them out (reader r41d, 7): ``{"3DC-9 OB": ratio of mean times}``."""
    ratios = recorded.query_ratios(recorded.ALGORITHM_1, tables)
    edge = floors(tables)["own"][1]
    out = {}
    for scenario, by_sampler in ratios.items():
        means = recorded.improvements(recorded.ALGORITHM_1, scenario, "total", tables)
        for sampler, ratio in by_sampler.items():
            if ratio > edge and time_verdict(1 - means[sampler]) != COSTS:
                out[f"{NAMES.get(scenario, scenario)} {sampler}"] = 1 - means[sampler]
    return out


def cost_table(tables: Tables | None = None) -> str:
    """The dear cells as a Markdown table (five columns, ms a query by means, without → with), and a line that counts
    in how many the larger part of the extra mean time came after sampling."""
    cells = dear_cells(tables)
    rows = [
        "| cell | median own ratio | sampling, ms | after sampling, ms | share of the extra from sampling |",
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
    skipped = left_out(tables)
    named = ", ".join(f"{name} (ratio of mean times {mean:.2f})" for name, mean in skipped.items())
    gone = (
        f" Left out: {named}, beyond the noise band by the median own ratio but with no extra mean time to split."
        if skipped
        else ""
    )
    shares = sampling_shares(recorded.ALGORITHM_1, tables)  # reader r45d, item 1: the top's Why in a number
    return (
        "\n".join(rows) + f"\n\nThe larger part of the extra mean time came after sampling in {len(mostly)} of these "
        f"{len(cells)} cells ({others}).{gone} Without prediction, sampling took {100 * min(shares):.1f}–"
        f"{100 * max(shares):.0f} % of the mean query in each of the run's {len(shares)} cells: the most that "
        "skipping the samples' exact checks could save."
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
        f"In the {len(cells)} recorded cells where the median own ratio cost time beyond the noise band and the mean "
        f"time grew too (section 6's last table), slower sampling explains {span} of the extra mean time; {rest}."
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


NOISE_EDGE = 2  # every noise band reaches this many times timing's own reach from 1, both ways (docs/results.md)


def _timed_twice(tables: Tables | None = None) -> list[list[str]]:
    """The rows of the table "timed twice" of :data:`toolkit.teaching.recorded.ALGORITHM_1` (scenario, sampler, ratio
    of the means, ratio of the medians, each query's own ratio); ``tables`` without that run borrow the record's, as
    the results page does."""
    runs = [found for found in (tables or {}, recorded.packaged()) if recorded.ALGORITHM_1 in found]
    run = runs[0][recorded.ALGORITHM_1]
    return next(found for heading, found in run.items() if "timed twice" in heading.lower())["rows"]


COLUMNS = {"means": 2, "medians": 3, "own": 4}  # each statistic's column of the table "timed twice"


def measured_reach(tables: Tables | None = None, kind: str = "own") -> tuple[float, float]:
    """The lowest and highest value of statistic ``kind`` (:data:`COLUMNS`) that timing one computation twice gave:
    how far timing alone moved it, as measured."""
    values = [float(row[COLUMNS[kind]].split()[0]) for row in _timed_twice(tables)]
    return min(values), max(values)


def timing_reach(tables: Tables | None = None, kind: str = "own") -> float:
    """The furthest that timing one computation twice moved statistic ``kind`` from 1, on its larger side."""
    return max(abs(v - 1) for v in measured_reach(tables, kind))


def noise_edge(tables: Tables | None = None, kind: str = "own") -> float:
    """How far from 1 the noise band of ``kind`` reaches: :data:`NOISE_EDGE` times :func:`timing_reach`."""
    return NOISE_EDGE * timing_reach(tables, kind)


def floors(tables: Tables | None = None) -> dict[str, tuple[float, float]]:
    """The band inside which a ratio is no clear evidence, per statistic, as the results page draws them (its table of
    bands), all built by one rule: 1 ± :data:`NOISE_EDGE` times the furthest timing one computation twice moved that
    statistic (its larger side, both ways; a single repeat understates timing noise). ``"own"``, the median of each
    query's own ratio; ``"means"`` and ``"medians"``, a ratio of the two modes' mean or median times."""
    return {kind: (1 - noise_edge(tables, kind), 1 + noise_edge(tables, kind)) for kind in COLUMNS}


def inside(ratio: float, band: tuple[float, float]) -> bool:
    """Whether ``ratio`` lies inside ``band`` (strictly: a ratio on an edge is beyond it), the one test every page
    marks with."""
    return band[0] < ratio < band[1]


def statistic(label: str) -> str:
    """Which of :func:`floors` judges a table row labelled ``label``: "ratio of medians" rows a ratio of the two
    medians, other "medians" rows the median of each query's own ratio, every other row of ours a ratio of means."""
    return "medians" if "ratio of medians" in label else "own" if "medians" in label else "means"


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
    "costs time" of our rows (not the paper's) whose ratio lies inside its statistic's band of :func:`floors`
    (:func:`statistic` of the row's label): the verdict word stays, the mark says timing alone could have moved it
    that far."""
    bands = floors(tables)

    def marker(kind: str) -> Callable[[re.Match], str]:
        low, high = bands[kind]

        def mark(found: re.Match) -> str:
            return f"{found[1]}{MARK if inside(float(found[2]), (low, high)) else ''}<br>({found[2]})"

        return mark

    rows = table.splitlines()
    return "\n".join(
        row
        if row.count("|") < 3 or "the paper" in row.split("|")[1]
        else _VERDICT_CELL.sub(marker(statistic(row.split("|")[1])), row)
        for row in rows
    )


def over_sampling(preset: str, tables: Tables | None = None) -> list[tuple[str, float, float]]:
    """``preset``'s cells (inside Algorithm 1) whose total time by means saved more than all their sampling took
    without prediction, which is all that skipping the samples' checks can save (review r34d: the fast-checker run
    has such cells too); any saving counts, the rule the paper's cells are counted by (reader r54d, contradiction 1):
    ``[("3DC-9 OB", share of the mean query saved, sampling's share of it), ...]``."""
    shares = shares_by_cell(preset, tables)
    return [
        (f"{NAMES[key]} {s}", saved, shares[key, s])
        for key in dict.fromkeys(k for k, _ in shares)
        for s, saved in recorded.improvements(preset, key, "total", tables).items()
        if saved > shares[key, s]
    ]


ABOUT = "too close to tell"  # chapter 04's words inside its 25 % cost band, as docs/results.md's (reader r43d)


def cost_word(ratio: float, tie: float = CLOSE) -> str:
    """:func:`cost_verdict`, with :data:`ABOUT` for a ratio inside the band: chapter 04 keeps "can't tell" for one
    meaning, a few queries that cannot decide."""
    verdict = cost_verdict(ratio, tie)
    return ABOUT if verdict == NEAR else verdict


def throughput_table(measured: Mapping[str, Mapping[str, float]], batch: int, tie: float = CLOSE) -> str:
    """Markdown: per scenario of ``{scenario: bench.throughput result}``, the network's cost per configuration
    against each exact checker's (network / exact) with its verdict, then the three checkers' configurations a
    second."""
    rows = [
        f"| scenario, {batch:,} a call | cost, network / fast exact | cost, network / python-fcl "
        "| configurations a second: fast exact / python-fcl / network |",
        "| --- | --- | --- | --- |",
    ]
    for name, m in measured.items():
        exact, fcl = 1 / m["ratio"], m["fcl_cfg_per_s"] / m["learned_cfg_per_s"]  # cost ratios, network / exact
        rows.append(
            f"| {name} | {cost_word(exact, tie)} ({exact:.2f}) | {cost_word(fcl, tie)} ({fcl:.2f}) "
            f"| {m['exact_cfg_per_s']:,.0f} / {m['fcl_cfg_per_s']:,.0f} / {m['learned_cfg_per_s']:,.0f} |"
        )
    return "\n".join(rows)


def call_cost_table(runs: Mapping[str, Mapping[str, float | None]], tie: float = CLOSE) -> str:
    """Markdown: one column per run of ``{run: {scenario: cost per configuration, network / default exact}}`` (None:
    not timed in that run), one row per scenario, each ratio with its verdict (:func:`cost_word`)."""
    scenarios = list(dict.fromkeys(name for ratios in runs.values() for name in ratios))
    rows = ["| scenario | " + " | ".join(runs) + " |", "| --- |" + " --- |" * len(runs)]
    for name in scenarios:
        cells = [ratios.get(name) for ratios in runs.values()]
        rows.append(
            f"| {name} | "
            + " | ".join("not timed" if r is None else f"{cost_word(r, tie)} ({r:.2f})" for r in cells)
            + " |"
        )
    return "\n".join(rows)


def median_counts(preset: str, tables: Tables | None = None) -> dict[str, tuple[int, int]]:
    """``preset``'s 16 cells inside Algorithm 1 by the median of each query's own ratio: ``{verdict: (how many, how
    many of them inside the noise band)}`` for saves, ties and costs (reader r36d: the costs counted too)."""
    verdicts = Counter(time_verdict(m) for row in middle_halves(preset, tables).values() for m, _, _ in row.values())
    edge = at_edge(preset, tables)
    return {v: (verdicts[v], edge[v] if v != TIES else 0) for v in (SAVES, TIES, COSTS)}


def clear_mean_savings(preset: str, tables: Tables | None = None) -> list[tuple[str, float]]:
    """``preset``'s cells whose ratio of mean times saves time outside the means' band of :func:`floors`:
    ``[("3DC-9 OB", 0.72), ...]`` (reader r36d: the means' savings with their noise)."""
    low, high = floors(tables)["means"]
    return [
        (f"{NAMES[key]} {s}", r)
        for key in recorded.query_ratios(preset, tables)
        for s, saved in recorded.improvements(preset, key, "total", tables).items()
        for r in [round(1 - saved, 2)]
        if time_verdict(r) == SAVES and not inside(r, (low, high))
    ]


def counted(counts: Mapping[str, tuple[int, int]], total: int = 0) -> str:
    """``"saved time in none of the 16 cells, tied in 7 and cost time in 9 (4 of them inside the noise band)"``."""

    def noise(verdict: str) -> str:
        n = counts[verdict][1]
        return f" ({n} of them inside the noise band)" if n else ""

    of = f" of the {total} cells (4 scenarios × 4 samplers)" if total else ""
    return (
        f"saved time in {counts[SAVES][0] or 'none'}{of}{noise(SAVES)}, tied in {counts[TIES][0] or 'none'} and cost "
        f"time in {counts[COSTS][0] or 'none'}{noise(COSTS)}"
    )


def clear(clear: list[list[tuple[str, float]]]) -> str:
    """Which savings by means clear the noise band, per checker (:func:`clear_mean_savings`)."""
    names = [[c for c, _ in cells] for cells in clear]
    if names[0] == names[1] and names[0]:
        ratios = " and ".join(", ".join(f"{r:.2f}" for _, r in cells) for cells in clear)
        return (
            f"only {', '.join(names[0])} clear{'s' * (len(names[0]) == 1)} the noise band, with each checker ({ratios})"
        )
    said = [", ".join(f"{c} {r:.2f}" for c, r in cells) or "none" for cells in clear]
    return f"those clear of the noise band: {said[0]} with our fast checker, {said[1]} with python-fcl"


def mean_verdicts(preset: str, tables: Tables | None = None) -> Counter:
    """The verdicts of ``preset``'s ratios of mean times inside Algorithm 1 (Table 3's statistic as we read it), every
    scenario and sampler."""
    return Counter(
        time_verdict(1 - saved)
        for key in recorded.query_ratios(preset, tables)
        for saved in recorded.improvements(preset, key, "total", tables).values()
    )
