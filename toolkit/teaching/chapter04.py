"""Chapter 04's tables of its own small runs, built here so that the page shows the tables, not their formatting
(review r25a: the page ran to 25 screens).

- :func:`success_table`: section 3's success, valid paths, rounds and repairs per query, and the queries that found no
  path;
- :func:`repairs_table`: section 2's repairs per query and sampler, with prediction;
- :func:`audited_table`: section 3's returned paths that a fresh exact checker accepts at 10x finer resolution;
- :func:`eager_tables`: section 5's stage times and counts of Algorithm 1 with and without the network, medians over
  the queries;
- :func:`answer`: the answer at the top, three short bullets read from ``docs/results.md``, :func:`answer_figure`,
  its evidence under it, and :func:`full_answer`, the counts in full sentences and by means for section 6.
"""

from __future__ import annotations

import os
from collections import Counter
from collections.abc import Mapping

import numpy as np
from matplotlib.figure import Figure

from toolkit.experiments.paper_numbers import TIMES, saved_beyond_sampling
from toolkit.planning.sampling import PAPER_SAMPLERS
from toolkit.plots.answer import answer_ratios
from toolkit.teaching import checker_scope, costs, findings, recorded
from toolkit.teaching.recorded import Tables
from toolkit.util.verdicts import COSTS, SAVES, TIES, time_verdict

STAGE_MS = {
    "sampling_s": "sampling",
    "connection_s": "connection (edges)",
    "query_s": "query",
    "other_s": "other (encoding, set-up)",  # the total less the three stages (review r27d: the stages must sum)
    "total_s": "total",
}
COUNTS = {  # what each mode checked, per query
    "nodes": "roadmap nodes",
    "samples_exact": "samples, exact",
    "predicted_checks": "samples, network",
    "edge_checks": "edge points, exact",
}


def success_table(tables: Mapping[str, Mapping[str, Mapping[str, Mapping]]]) -> str:
    """``{scenario: {sampler: {"without" | "with": summary}}}`` (``compare_prediction``'s) as a five-column Markdown
    table, and a line naming each sampler, scenario and mode whose success was below 100 %."""
    rows = [
        "| scenario | sampler | success<br>without / with | paths valid<br>without / with "
        "| rounds / repairs per query, with prediction (means) |",
        "| --- | --- | --- | --- | --- |",
    ]
    failed = []
    for name, table in tables.items():
        for s in PAPER_SAMPLERS:
            without, with_ = table[s]["without"], table[s]["with"]
            rows.append(
                f"| {name} | {s} | {without['success_rate']:.0%} / {with_['success_rate']:.0%} "
                f"| {without['path_valid_rate']:.0%} / {with_['path_valid_rate']:.0%} "
                f"| {with_['rounds']:.2f} / {with_['repairs']:.2f} |"
            )
            failed += [
                f"{name} {s} {mode} prediction ({table[s][mode]['success_rate']:.0%} found a path)"
                for mode in ("without", "with")
                if table[s][mode]["success_rate"] < 1
            ]
    said = "; ".join(failed) if failed else "none, in either mode"
    return "\n".join(rows) + f"\n\nQueries that found no path, in this run: {said}."


def repairs_table(repairs: Mapping[tuple[int, str], int]) -> str:
    """Section 2's repairs with prediction, ``{(query, sampler): repairs}``, as a Markdown table (a row a query, a
    column a sampler) under its title, and a line: how many runs needed none, and the samplers with the most and the
    fewest in all (review r30d: the table's code was on the page)."""
    queries = sorted({i for i, _ in repairs})
    rows = ["| query | " + " | ".join(PAPER_SAMPLERS) + " |", "| --- |" + " --- |" * len(PAPER_SAMPLERS)]
    rows += [f"| {i} | " + " | ".join(str(repairs[i, s]) for s in PAPER_SAMPLERS) + " |" for i in queries]
    total = {s: sum(repairs[i, s] for i in queries) for s in PAPER_SAMPLERS}
    most, fewest = max(total.values()), min(total.values())
    named = {n: ", ".join(s for s, m in total.items() if m == n) for n in (most, fewest)}
    return (
        "Repairs per query and sampler, with prediction:\n\n" + "\n".join(rows) + f"\n\n"
        f"{sum(n == 0 for n in repairs.values())} of {len(repairs)} runs needed no repair; the most repairs in all: "
        f"{named[most]} ({most}), the fewest: {named[fewest]} ({fewest})."
    )


def audited_table(audited: Mapping[str, Mapping[str, str]]) -> str:
    """``{scenario: {sampler: "valid of returned"}}`` as a Markdown table under its title."""
    head = "| scenario | " + " | ".join(PAPER_SAMPLERS) + " |\n| --- |" + " ---: |" * len(PAPER_SAMPLERS)
    body = "\n".join(f"| {name} | " + " | ".join(c[s] for s in PAPER_SAMPLERS) + " |" for name, c in audited.items())
    return (
        f"Returned paths with prediction that a fresh exact checker accepts at 10× finer resolution:\n\n{head}\n{body}"
    )


def counted(runs: Mapping[str, tuple[list[dict], dict]]) -> dict[str, list[dict]]:
    """Each mode's per-query records of ``run_interleaved`` with ``samples_exact``: the samples the exact checker
    decided (the nodes checked less those the network decided), and ``other_s``: the total less the three stages
    (the workspace's encoding, with prediction, and the query's set-up)."""
    return {
        mode: [
            dict(
                r,
                samples_exact=r["node_checks"] - r["predicted_checks"],
                other_s=r["total_s"] - r["sampling_s"] - r["connection_s"] - r["query_s"],
            )
            for r in records
        ]
        for mode, (records, _) in runs.items()
    }


def per_point(records: Mapping[str, list[dict]]) -> dict[str, float]:
    """Each mode's median connection time per exact edge point, in seconds: the same exact check in both modes."""
    return {
        m: float(np.median([r["connection_s"] / max(r["edge_checks"], 1) for r in rs])) for m, rs in records.items()
    }


def _median_of(records: list[dict], key: str) -> str:
    value = float(np.median([r[key] for r in records]))
    return f"{1000 * value:.1f}" if key.endswith("_s") else f"{value:,.0f}"


def eager_tables(records: Mapping[str, list[dict]]) -> list[str]:
    """Section 5's two tables, each under its title: each stage's time (ms a query; a row a stage, a column a mode)
    and what each mode checked per query, medians over the queries (``records``: :func:`counted`'s), and a line on
    what the *other* row holds."""
    modes = list(records)
    head = "| stage, ms a query | " + " | ".join(modes) + " |\n| --- |" + " ---: |" * len(modes)
    body = "\n".join(
        f"| {name} | " + " | ".join(_median_of(records[m], key) for m in modes) + " |" for key, name in STAGE_MS.items()
    )
    stages = f"Algorithm 1, 3DC-7, BS: each stage's time, ms a query (medians over the queries):\n\n{head}\n{body}"
    counts_head = "| mode | " + " | ".join(COUNTS.values()) + " |\n| --- |" + " ---: |" * len(COUNTS)
    counts_body = "\n".join(
        f"| {m} | " + " | ".join(_median_of(rs, k) for k in COUNTS) + " |" for m, rs in records.items()
    )
    counted_title = (
        "What each mode checked, per query (medians): the roadmap's nodes, the samples the exact checker and the "
        "network decided, and the edge points the exact checker checked:"
    )
    return [stages + "\n\n" + other_line(records), f"{counted_title}\n\n{counts_head}\n{counts_body}"]


def other_line(records: Mapping[str, list[dict]]) -> str:
    """What section 5's *other* row holds: the time outside the three stages, with prediction the workspace's encoding
    (its median, ms a query), and that each row is its own median, so the rows add up to the total only roughly."""
    said = (
        "*Other* is each query's time outside the three stages: setting the query up in both modes, and, with "
        "prediction, encoding the workspace for the network"
    )
    encoded = [r.get("encode_s", 0.0) for r in records.get("with", [])]
    if encoded and max(encoded) > 0:
        said += f" ({1000 * float(np.median(encoded)):.1f} ms a query, median)"
    return said + ". Each row is its own median over the queries, so the rows add up to the total only roughly."


def answer(tables: Tables | None = None) -> str:
    """Chapter 04's answer in numbers, three short bullets read from ``docs/results.md`` (100 recorded queries a
    scenario), each a student can repeat (reader r33d): how often our accurate network saved time by the statistic
    the page reads, the median of each query's own ratio (reader r35d: the answer led with means, section 6 said it
    reads medians), with how many python-fcl savings lie inside timing noise, then by means like for like with the
    paper; the most that skipping the samples' checks can save, and the cells whose means saved more; what a network
    call cost against our fast check. The rest is section 6's (:func:`edge_line`, :func:`full_answer`)."""
    facts = checker_scope.slow_checker(tables)
    papers = sum(time_verdict(1 - saved) == SAVES for saved in facts.papers_totals)
    share = max(costs.sampling_shares(recorded.ALGORITHM_1, tables))
    fast, slow = (costs.saved_counts(preset, tables) for preset, _ in RUNS)
    noise = slow["medians"][1]  # python-fcl's median savings inside timing noise (reader r35d: cells, not pairs)
    beyond = costs.over_sampling(recorded.ALGORITHM_1, tables)
    whose = "cells'" if len(beyond) != 1 else "cell's"
    why = (
        f" With our fast checker, {len(beyond)} {whose} means saved more than their sampling, "
        + ", ".join(f"{c} {1 - a:.2f}" for c, a, _ in beyond)
        + ": a few slow queries moved those means, not prediction."
        if beyond
        else ""
    )
    return (
        "- **Saved time**: by the median of each query's own ratio, the statistic this page reads, our accurate "
        f"network saved time in {_of_16(fast['medians'][0])} scenario–sampler pairs with our fast checker and in "
        f"{_of_16(slow['medians'][0])} with python-fcl on both sides"
        + (f", {noise} of them inside timing noise (section 6's {costs.MARK})" if noise else "")
        + f"; by mean times, Table 3's statistic, in {fast['means'][0] or 'none'} and {_of_16(slow['means'][0])}, "
        f"the paper's Table 3 in {papers} of {len(facts.own)}.\n"
        f"- **Why**: prediction only skips the samples' checks, at most {100 * share:.0f} % of a mean query with our "
        "fast checker, all a free network saves. The rest is exact checks along the roadmap's edges, never the "
        f"network's in Algorithm 1 (section 5).{why}\n"
        f"- **Cost**: {_adds(tables)}."
    )


def _of_16(n: int) -> str:
    return f"{n or 'none'} of 16"


def edge_line(tables: Tables | None = None) -> str:
    """The footnote under section 6's tables (reader r33d: the noise edge a mark in the table): what the mark
    :data:`toolkit.teaching.costs.MARK` on a verdict means, and the band each statistic is marked by
    (:func:`toolkit.teaching.costs.floors`, reader r34d: a mean was marked by the median's band)."""
    bands = costs.floors(tables)

    def band(kind: str) -> str:
        return f"{bands[kind][0]:.2f}–{bands[kind][1]:.2f}"

    return (
        f"{costs.MARK} inside timing noise: no clear evidence. The band depends on the statistic: for the median "
        f"of each query's own ratio {band('own')} (twice the {costs.timing_reach(tables):.2f} by which timing one "
        f"computation twice moved it), for a ratio of means {band('means')} and for a ratio of medians "
        f"{band('medians')} (as far as that timing moved them; `docs/results.md`, its table of bands)."
    )


def means_apart(tables: Tables | None = None) -> str:
    """Of the pairs where the ratio of mean times saves (the answer figure's bars below the band), those where the
    median query did not save and those where it did (review r32d: "while the median query did not save" was false
    for two of them)."""
    cells: dict[bool, dict[str, list[str]]] = {False: {}, True: {}}
    for preset, who in ((recorded.ALGORITHM_1, "fast checker"), (checker_scope.SLOW, "python-fcl")):
        medians = costs.middle_halves(preset, tables)
        for key in medians:
            for s, saved in recorded.improvements(preset, key, "total", tables).items():
                if time_verdict(1 - saved) == SAVES:
                    both = time_verdict(medians[key][s][0]) == SAVES
                    cells[both].setdefault(who, []).append(f"{checker_scope.NAMES[key]} {s}")

    def named(group: dict[str, list[str]]) -> str:
        count = sum(len(c) for c in group.values())
        return f"in {count or 'none'}" + (
            " (" + "; ".join(f"{w} {', '.join(c)}" for w, c in group.items()) + ")" if count else ""
        )

    total = sum(len(c) for group in cells.values() for c in group.values())
    said = f"of the {total} pairs where a mean saved, the median query did not {named(cells[False])}"
    return f"{said} and did {named(cells[True])}"


def _adds(tables: Tables | None = None) -> str:
    """What a network call cost against the fast exact check, per configuration, in the recorded Algorithm 1 run
    (Checker throughput), a range over the scenarios, and how far the same network's 2DS cost moved between its two
    recorded runs (reader r34d: the range read as fixed)."""
    dearer = {
        preset: {key: 1 / recorded.ours(row["learned / exact"]) for key, row in rows.items()}
        for preset in ("strong", recorded.ALGORITHM_1)
        for rows in [recorded.table(preset, "Checker throughput", tables)]
    }
    now = list(dearer[recorded.ALGORITHM_1].values())
    low, high = (f"{v:.2g}" for v in (min(now), max(now)))
    moved = sorted(f"{d['2ds']:.2g}" for d in dearer.values())
    return (
        f"our network cost {low if low == high else f'{low}–{high}'} times an exact check per configuration with our "
        "fast checker in the recorded Algorithm 1 run (`--planner paper`), so there prediction adds time; in 2DS the "
        f"same network cost {' times in one recorded run and '.join(moved)} in another, so the why rests on what "
        "Algorithm 1 checks, not on this cost"
    )


def _counts(preset: str, tables: Tables | None = None, means: bool = False) -> Counter:
    """The verdicts of a recorded run inside Algorithm 1, every scenario and sampler: of the median of each query's own
    ratio, or with ``means`` of the ratio of mean times (Table 3's statistic as we read it)."""
    if means:
        keys = recorded.query_ratios(preset, tables)
        return Counter(
            time_verdict(1 - saved)
            for key in keys
            for saved in recorded.improvements(preset, key, "total", tables).values()
        )
    return Counter(time_verdict(r) for row in recorded.query_ratios(preset, tables).values() for r in row.values())


def _rest(counted: Counter) -> str:
    """``"7 tied, 9 longer"``."""
    return f"{counted[TIES]} tied, {counted[COSTS]} longer"


def full_answer(tables: Tables | None = None) -> str:
    """:func:`answer`'s counts in full sentences, for the fold under it: the compiled checker
    (:func:`toolkit.teaching.findings.claim_status`, with the lazy PRM beside it) and python-fcl on both sides
    (:func:`~toolkit.teaching.checker_scope.slow_sentence`, :func:`~toolkit.teaching.checker_scope.like_for_like`)."""
    eager = {
        checker_scope.NAMES[key]: ratios for key, ratios in recorded.query_ratios(recorded.ALGORITHM_1, tables).items()
    }
    strong = recorded.median_ratios("strong", tables)
    lazy = {checker_scope.NAMES[key]: strong[key]["total"] for key in ("2ds", "3dc7") if key in strong}
    facts = checker_scope.slow_checker(tables)
    fast, slow = _counts(recorded.ALGORITHM_1, tables, means=True), _counts(checker_scope.SLOW, tables, means=True)
    return (
        f"{findings.claim_status(eager, lazy)}\n\n"
        f"{checker_scope.slow_sentence(facts, ranges=False)} {checker_scope.like_for_like(facts)}\n\n"
        f"By mean times, the paper's statistic, prediction saved time in {fast[SAVES] or 'none'} of the "
        f"{fast.total()} pairs with our fast checker ({_rest(fast)}) and in {slow[SAVES] or 'none'} with python-fcl "
        f"on both sides ({_rest(slow)}). A mean follows the few slowest queries (*The statistic*, below): where those "
        f"saved, a mean can save while most queries did not; {means_apart(tables)}."
    )


def beyond_sampling(tables: Tables | None = None) -> str:
    """Section 6 (review r31d, item 3): where a recorded saving is larger than the whole sampling stage, which is all
    that skipping the samples' checks can save. The paper's own mean times (its §V text, the times behind Table 3):
    the cells whose total saving exceeds all their sampling time without prediction, the largest two in different
    scenarios, and how many of them save less than a query's time spreads (its standard deviation without); ours
    with python-fcl on both sides: the savings larger than their sampling stage's, as shares of the mean query."""
    over = saved_beyond_sampling()  # the paper's cells: (seconds saved, seconds of sampling without, its spread)
    best = {key: max((c for c in over if c[0] == key), key=lambda c: over[c][0]) for key, _ in over}
    first, second = sorted(best.values(), key=lambda c: -over[c][0])[:2]
    spread = sum(over[c][2] > over[c][0] for c in over)

    def cell(c: tuple[str, str]) -> str:
        return f"{checker_scope.NAMES[c[0]]} {c[1]}"

    return (
        "**Savings larger than all of sampling.** Skipping the samples' checks can save at most the whole sampling "
        "stage. Yet in the paper's own mean times (§V, the times behind Table 3) the total time saved exceeds all the "
        f"sampling time without prediction in {len(over)} of its {sum(len(k['total_s']) for k in TIMES.values())} "
        f"cells: {cell(first)} saves {over[first][0]:.2f} s while its sampling took {over[first][1]:.2f} s, "
        f"{cell(second)} {over[second][0]:.2f} s against {over[second][1]:.2f} s. Prediction of samples alone cannot "
        "explain these. Another roadmap can, and so can the spread of the times: in "
        f"{spread} of those {len(over)} cells the paper's standard deviation of a query's time exceeds the saving."
        + _ours_beyond(tables)
    )


RUNS = ((recorded.ALGORITHM_1, "fast checker"), (checker_scope.SLOW, "python-fcl"))  # our two Algorithm 1 runs


def _ours_beyond(tables: Tables | None = None) -> str:
    """:func:`beyond_sampling`'s sentences on our two runs (:data:`RUNS`): the cells of :func:`over_sampling`, and of
    them those where the median query did not save, where a few slow queries moved the mean (review r34d)."""
    runs = {who: costs.over_sampling(preset, tables) for preset, who in RUNS}
    count = sum(len(cells) for cells in runs.values())
    if not count:
        return " Ours have no such saving, by means or by the median query."
    named = "; ".join(
        f"{who}: " + ", ".join(f"{c} {100 * a:.0f} % against {100 * b:.0f} %" for c, a, b in cells)
        for who, cells in runs.items()
        if cells
    )
    medians = {who: costs.middle_halves(preset, tables) for preset, who in RUNS}
    split: dict[bool, list[str]] = {False: [], True: []}
    for who, cells in runs.items():
        for c, _, _ in cells:
            key = next(k for k, n in checker_scope.NAMES.items() if c.startswith(n + " "))
            split[time_verdict(medians[who][key][c.split()[1]][0]) == SAVES].append(f"{who} {c}")
    said = (
        f" Ours have {count} such saving{'s' * (count > 1)} by means (the share of the mean query saved against "
        f"sampling's share without prediction; {named})."
    )
    if split[False]:
        said += (
            f" In {len(split[False])} of them ({', '.join(split[False])}) the median query did not save: a few slow "
            "queries moved the mean, not prediction."
        )
    if split[True]:
        said += (
            f" Where the median query saved too ({', '.join(split[True])}), another roadmap can explain it; that run "
            "was not timed twice (`docs/results.md`)."
        )
    return said


SERIES = {  # the answer figure's legend, a line a series (reader r33d: five lines for three marker kinds)
    "the paper's Table 3": "the paper's Table 3 (its means)",
    "ours (`strong` preset), medians": "ours, our fast checker (compiled in 3D, numpy in 2DS)",
    "ours (`strong`, python-fcl), medians": "ours, python-fcl on both sides",
}


def answer_figure(tables: Tables | None = None) -> Figure:
    """The answer's evidence, under it (review r28d: it came at screen 15 of 18): above, the paper's Table 3 beside
    our accurate network's ratios of mean times inside Algorithm 1, with the fast checker and with python-fcl on both
    sides; below, ours by the median of each query's own ratio with its middle half
    (:func:`toolkit.plots.answer.answer_ratios` of :func:`toolkit.teaching.checker_scope.compact`)."""
    return answer_ratios(
        checker_scope.compact(tables),
        tie=findings.TIE,
        spans=checker_scope.spans(tables),
        means=checker_scope.our_means(tables),
        names=SERIES,
        floor=costs.floors(tables)["means"],
    )


def load_line() -> str:
    """The machine's load as a live table was timed (review r32d: the load was printed only at the end, and section
    3's and section 5's live verdicts come from wall-clock times): the last minute's load average and the cores."""
    return (
        f"Timed at a load average of {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores (the last minute's, as this "
        "table was finished). Live timings on a shared machine illustrate; section 6's recorded runs decide."
    )
