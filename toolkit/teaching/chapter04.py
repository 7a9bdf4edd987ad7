"""Chapter 04's tables of its own small runs (sections 2, 3 and 5), and the answer read from ``docs/results.md``:
:func:`answer`, :func:`mark_line` at the top; :func:`full_answer`, :func:`edge_line` in 6 (its figures:
:mod:`toolkit.teaching.chapter04_figures`)."""

from __future__ import annotations

import os
from collections import Counter
from collections.abc import Mapping

import numpy as np

from toolkit.experiments.queries import solve_query
from toolkit.geometry.collision import exact_checker
from toolkit.learning.learned import LearnedChecker
from toolkit.planning.local_planner import path_is_valid
from toolkit.planning.sampling import PAPER_SAMPLERS
from toolkit.teaching import chapter04_encoding, checker_scope, costs, findings, recorded
from toolkit.teaching.chapter04_paper import RUNS, how_to_read, means_sentence, papers_table, plain
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
    """``compare_prediction``'s tables as one Markdown table, and a line naming each cell below 100 % success."""
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
    """Section 2's repairs with prediction, ``{(query, sampler): repairs}``: a line, the table folded under it."""
    queries = sorted({i for i, _ in repairs})
    rows = ["| query | " + " | ".join(PAPER_SAMPLERS) + " |", "| --- |" + " --- |" * len(PAPER_SAMPLERS)]
    rows += [f"| {i} | " + " | ".join(str(repairs[i, s]) for s in PAPER_SAMPLERS) + " |" for i in queries]
    total = {s: sum(repairs[i, s] for i in queries) for s in PAPER_SAMPLERS}
    most, fewest = max(total.values()), min(total.values())
    named = {n: ", ".join(s for s, m in total.items() if m == n) for n in (most, fewest)}
    return (
        f"With prediction, {sum(n == 0 for n in repairs.values())} of {len(repairs)} runs needed no repair; the most "
        f"repairs in all: {named[most]} ({most}), the fewest: {named[fewest]} ({fewest}).\n\n<details><summary>"
        "Repairs per query and sampler, with prediction</summary>\n\n" + "\n".join(rows) + "\n\n</details>"
    )


def audit(scenario, queries, models, seed: int = 0) -> dict[str, str]:
    """Per sampler, ``"valid of returned"``: re-plan each query with prediction (seeded ``[seed, n]`` as
    ``compare_prediction`` does: the same paths) and check each path with a fresh exact checker, 10x finer."""
    counts = {}
    for s in PAPER_SAMPLERS:
        returned = valid = 0
        for n, q in enumerate(queries):
            found = solve_query(scenario, q, s, checker=LearnedChecker(q.workspace, models), seed=[seed, n])
            if found.success:
                returned += 1
                fine = found.stats["resolution"] / 10
                valid += path_is_valid(exact_checker(q.workspace, scenario.robot), found.path, fine)
        counts[s] = f"{valid} of {returned}"
    return counts


def path_checks(
    tables: Mapping[str, Mapping[str, Mapping[str, Mapping]]], audited: Mapping[str, Mapping[str, str]]
) -> str:
    """Section 3's fold: :func:`success_table` and the paths :func:`audit` accepts (``audited``)."""
    head = "| scenario | " + " | ".join(PAPER_SAMPLERS) + " |\n| --- |" + " ---: |" * len(PAPER_SAMPLERS)
    body = "\n".join(f"| {name} | " + " | ".join(c[s] for s in PAPER_SAMPLERS) + " |" for name, c in audited.items())
    return (
        "<details><summary>Success and path validity: every returned path checked again</summary>\n\n"
        "`path_valid_rate` is the share of returned paths that a fresh exact checker accepts at 10× finer resolution. "
        "A query can fail (no path within `max_rounds` = 20 rounds), most likely with the bridge test (few samples in "
        'open 2DS) or the obstacle-based sampler (samples crowded along the C-obstacles): an honest "no path found", '
        "never a path the exact check rejects. Repairs fall unevenly (a query or two can carry most), so this "
        "section's and section 2's repairs per query can differ many times over.\n\n"
        f"{success_table(tables)}\n\nDon't take the summary's word for it: `chapter04.audit` re-plans every query "
        "with prediction (the same seeds give the same paths) and checks each returned path with a fresh exact "
        "checker at 10× finer resolution. Returned paths it accepts:\n\n"
        f"{head}\n{body}\n\n</details>"
    )


def live_line(tables: Mapping[str, Mapping[str, Mapping]]) -> str:
    """Section 3's visible result (reader r48d, item 3): the live cells' verdicts by the median of each query's own
    ratio, their range, and how many are no clear evidence (marked in the folded table)."""
    found = [findings.planning_verdict(row) for table in tables.values() for row in table.values()]
    medians = [median for median, *_ in found]
    said = Counter(time_verdict(median) for median in medians)
    unsure = sum(v == findings.UNSURE for *_, v in found)  # r62d: every verdict the table marks, ties included
    words = {COSTS: "cost time in", SAVES: "saved time in", TIES: "tied in"}
    parts = [f"{words[v]} {said[v]}" for v in (COSTS, SAVES, TIES) if said[v]]
    only = next((words[v] for v in said if said[v] == len(found)), "")
    cells = f"{only} all {len(found)} cells" if only else f"{', '.join(parts)} of the {len(found)} cells"
    return (
        f"**In these live queries** prediction {cells} (the median of each query's own ratio, "
        f"{min(medians):.2f} to {max(medians):.2f})"
        + f"; {unsure} of the {len(found)} verdicts {'is' if unsure == 1 else 'are'} no clear evidence" * bool(unsure)
        + ". A handful of queries illustrate; section 6's recorded runs decide."
    )


def counted(runs: Mapping[str, tuple[list[dict], dict]]) -> dict[str, list[dict]]:
    """``run_interleaved``'s records with ``samples_exact`` (nodes less the network's) and ``other_s`` (the rest)."""
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


def _median_of(records: list[dict], key: str) -> str:
    value = float(np.median([r[key] for r in records]))
    return f"{1000 * value:.1f}" if key.endswith("_s") else f"{value:,.0f}"


def _stage_ms(records: list[dict], key: str) -> str:
    """A stage's ms a query as section 3's bars draw it (reader r36d): its mean share times the median total."""
    total = float(np.median([r["total_s"] for r in records]))
    share = np.mean([r[key] for r in records]) / max(float(np.mean([r["total_s"] for r in records])), 1e-12)
    return f"{1000 * total * float(share):.1f}"


def eager_tables(records: Mapping[str, list[dict]]) -> list[str]:
    """Section 5's two tables (``records``: :func:`counted`'s): each stage's ms a query, and what each mode checked."""
    modes = list(records)
    head = "| stage, ms a query | " + " | ".join(modes) + " |\n| --- |" + " ---: |" * len(modes)
    body = "\n".join(
        f"| {name} | " + " | ".join(_stage_ms(records[m], key) for m in modes) + " |" for key, name in STAGE_MS.items()
    )
    stages = (
        "This run's times, ms a query, as section 3's bars: one run on a machine others share, whose load can "
        f"reorder them:\n\n{head}\n{body}"
    )
    counts_head = "| mode | " + " | ".join(COUNTS.values()) + " |\n| --- |" + " ---: |" * len(COUNTS)
    counts_body = "\n".join(
        f"| {m} | " + " | ".join(_median_of(rs, k) for k in COUNTS) + " |" for m, rs in records.items()
    )
    counted_title = f"What each mode checked, per query (medians of {len(records[modes[0]])} queries):"
    return [stages + "\n\n" + other_line(records), f"{counted_title}\n\n{counts_head}\n{counts_body}"]


def roadmap_line(records: Mapping[str, list[dict]]) -> str:
    """Under section 5's counts (reader r61d, item 1: counts only, which a busy machine cannot move): the median
    roadmap's nodes and exact edge points in each mode, and the least share of edge points among the exact checks."""
    med = {m: {k: float(np.median([r[k] for r in records[m]])) for k in COUNTS} for m in ("without", "with")}
    share = min(v["edge_checks"] / max(v["edge_checks"] + v["samples_exact"], 1.0) for v in med.values())
    return (
        f"With prediction the median roadmap had {med['with']['nodes']:,.0f} nodes against "
        f"{med['without']['nodes']:,.0f} without, and its exact checker checked {med['with']['edge_checks']:,.0f} "
        f"edge points against {med['without']['edge_checks']:,.0f}: in both modes at least {int(100 * share)} % of "
        "the exact checks are edge points. Prediction can change that work only through the roadmap it leaves."
    )


def other_line(records: Mapping[str, list[dict]]) -> str:
    """What section 5's *other* row holds (with prediction the workspace's encoding), and how rows are built."""
    said = (
        "*Other* is each query's time outside the three stages: setting the query up in both modes, and, with "
        "prediction, encoding the workspace for the network"
    )
    encoded = [r.get("encode_s", 0.0) for r in records.get("with", [])]
    if encoded and max(encoded) > 0:
        said += f" ({1000 * float(np.median(encoded)):.1f} ms a query, median)"
    return said + (
        ". Each row is that stage's share of the mean query times the median total, as section 3's bars, so the rows "
        "add up to the total."
    )


SLOW_ROW = "python-fcl on both sides (not timed twice: it borrows the fast checker's noise band)"  # common rule 4


def answer(tables: Tables | None = None) -> str:
    """Chapter 04's answer from ``docs/results.md`` (reader r59d, lifts 1-3): two sentences by one statistic, with no
    term the box under them defines, then the box, our table with the ties and the counts beyond the noise band, and
    the paper's Table 3 beside ours by means in a fold (like with like)."""
    facts = checker_scope.slow_checker(tables)
    papers = Counter(time_verdict(1 - saved) for saved in facts.papers_totals)
    fast, slow = (costs.median_counts(preset, tables) for preset, _ in RUNS)
    total = len(facts.own)
    counts = (fast[SAVES][0], fast[COSTS][0], fast[COSTS][0] - fast[COSTS][1], slow[SAVES][0])
    word = "No" if not fast[SAVES][0] else "Rarely" if 4 * fast[SAVES][0] <= total else "In part"

    def n(cells: int, zero: str = "none", of: bool = False) -> str:
        return f"{cells} of {total}" * of * bool(cells) or str(cells or zero)

    def cell(c: tuple[int, int]) -> str:  # (cells, of them inside the noise band)
        return n(c[0]) + f" ({c[0] - c[1]} beyond the noise band)" * bool(c[0])

    rows = [
        (name, [cell(c[SAVES]), n(c[TIES][0]), cell(c[COSTS])])
        for name, c in (("our fast exact checker", fast), (SLOW_ROW, slow))
    ]
    runs = (  # reader r54d, item 3: the run names and the counts by means in the fold (r58d: sampling in the answer)
        "From the recorded run `strong --planner paper` (100 queries a scenario, `docs/results.md`; python-fcl's row: "
        f"the same run with `--baseline paper-fcl-alike`). {means_sentence(tables)} "
        f"{chapter04_encoding.disagreement(tables)}"
    )
    return (
        f"**{word}.** {plain(counts, total, tables, word)}\n\n{how_to_read(tables)}\n\n"
        f"| {total} scenario–sampler cells, by the median of each query's own time ratio (with ÷ without) | faster "
        "| tie | slower |\n| --- | --- | --- | --- |\n"
        + "\n".join(f"| {name} | {' | '.join(c)} |" for name, c in rows)
        + "\n\n"
        + papers_table((papers[SAVES], papers[TIES], papers[COSTS]), tables, runs)
    )


def by_means(tables: Tables | None = None) -> str:
    """Section 6's line beside the means figure (reader r44d, item 1): both runs' savings by mean times, how many lie
    beyond the noise band of a ratio of means, and why the page therefore judges by each query's own ratio."""
    means = [costs.mean_verdicts(preset, tables)[SAVES] for preset, _ in RUNS]
    clear = list(dict.fromkeys(c for preset, _ in RUNS for c, _ in costs.clear_mean_savings(preset, tables)))
    bands = costs.floors(tables)

    def band(kind: str) -> str:
        return f"{bands[kind][0]:.2f}–{bands[kind][1]:.2f}"

    return (
        f"**By mean times**, the paper's statistic, prediction saved 10 % or more in {means[0] or 'none'} cells with "
        "our fast "
        f"checker and {means[1] or 'none'} with python-fcl, {'only ' * bool(clear)}{', '.join(clear) or 'none'} "
        f"beyond the noise band of a ratio of means ({band('means')}). "
        + (
            "So by means our runs cannot tell savings of Table 3's size from timing noise"
            if len(clear) <= 1
            else "By means only these few are clear of timing noise"
        )
        + ": a ratio of means divides two sums over the same 100 queries, and a few slow queries weigh on a mean. "
        f"That is why this page judges by each query's own ratio, whose noise band is {band('own')}."
    )


def mark_line(tables: Tables | None = None) -> str:
    """Under the answer figure (reader r44d, item 2): one visible sentence on the hatched band and its mark, then the
    one rule that builds every noise band, and the page's two marks, each with one meaning (item 5), in a fold."""
    bands, (low, high) = costs.floors(tables), costs.measured_reach(tables)

    def band(kind: str) -> str:
        return f"{bands[kind][0]:.2f}–{bands[kind][1]:.2f}"

    return (
        f'The hatched band is the noise band of "How to read the ratios", {band("own")}; a tie never carries '
        f"{costs.MARK}."
        "\n\n<details><summary>How "
        "every noise band is built, and the page's two marks</summary>\n\n"
        "Every noise band is built one way (`docs/results.md`): time one computation twice, see how far timing alone "
        f"moved the statistic from 1, and take {costs.NOISE_EDGE} times that, both ways, because a single repeat "
        f"understates timing noise. Each query's own ratio: {band('own')} = 1 ± {costs.NOISE_EDGE} × "
        f"{costs.timing_reach(tables):.2f} (timing alone: {low:.2f}–{high:.2f}). A ratio of mean times: "
        f"{band('means')}; a ratio of medians: {band('medians')}. Those two are wider: a few slow queries weigh on a "
        "mean, and the two medians can fall on different queries.\n\n"
        f"{costs.MARK} means one thing on this page: inside the noise band of its statistic, so no clear evidence. "
        f"† means one thing too, on a verdict of section 3's few live queries only: no clear evidence, as "
        f"{findings.ACROSS_REASON}. The recorded runs "
        "carry none, because a middle half shows how the queries spread, not how sure their median is: the median of "
        "100 recorded queries is pinned far more tightly than their spread, the median of a few live queries is not. "
        "Where both hold, "
        f"{costs.MARK} takes precedence: the verdict carries {costs.MARK} alone.\n\n</details>"
    )


def edge_line(tables: Tables | None = None) -> str:
    """Section 6's one new fact: in the cells where Table 3 saves time, our median queries that save, with each
    checker; python-fcl's named, and its savings in cells Table 3 does not save (reader r42d: 3 in the answer)."""
    rows, bands = checker_scope.compact(tables), costs.floors(tables)["own"]
    papers = [(label.split(",")[0], s) for label, row in rows.items() if "paper" in label for s, r in row.items()]
    saved = [(n, s) for n, s in papers if time_verdict(rows[f"{n}, the paper's Table 3"][s]) == SAVES]

    def ours(series: str, cells: list[tuple[str, str]]) -> list[str]:
        r = {c: rows[f"{c[0]}, ours ({series}), medians"][c[1]] for c in cells}
        return [f"{n} {s}{costs.MARK * (bands[0] < v)}" for (n, s), v in r.items() if time_verdict(v) == SAVES]

    fast, fcl = ours("`strong` preset", saved), ours("`strong`, python-fcl", saved)
    other = [c for c in ours("`strong`, python-fcl", papers) if c not in fcl]
    named = ", ".join(fcl) + f"; {costs.MARK} inside the noise band" * any(costs.MARK in c for c in fcl)
    many = len(other) > 1
    named += f"; the {'other' if many else 'third'} python-fcl saving{'s' * many}, {', '.join(other)}, " * bool(other)
    named += f"{'are cells' if many else 'is a cell'} where Table 3 does not save 10 % or more" * bool(other)
    return (
        f"**Take from it:** in the {len(saved)} cells where the paper's Table 3 saves 10 % or more, our median own "
        "ratio saved "
        f"in {len(fast) or 'none'} with our fast checker and in {len(fcl) or 'none'} with python-fcl"
        + f" ({named})" * bool(fcl)
        + "."
    )


def means_apart(tables: Tables | None = None) -> str:
    """Of the pairs where the ratio of mean times saves, those where the median own ratio did not save and did."""
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
    runs = ", ".join(f"{sum(len(c[w]) for c in cells.values() if w in c)} {w}" for _, w in RUNS)
    said = f"of the {total} cells ({runs}) where a mean saved 10 % or more, the median own ratio did not "
    said += named(cells[False])
    return f"{said} and did {named(cells[True])}"


def full_answer(tables: Tables | None = None) -> str:
    """The answer's counts in full sentences, for section 6's fold: our fast checker, the lazy PRM and python-fcl."""
    eager = {
        checker_scope.NAMES[key]: ratios for key, ratios in recorded.query_ratios(recorded.ALGORITHM_1, tables).items()
    }
    strong = recorded.median_ratios("strong", tables)
    lazy = {checker_scope.NAMES[key]: strong[key]["total"] for key in ("2ds", "3dc7") if key in strong}
    facts = checker_scope.slow_checker(tables)
    fast, slow = (costs.mean_verdicts(preset, tables) for preset, _ in RUNS)
    counts = {who: f"{c[SAVES] or 'none'}" for who, c in (("fast", fast), ("slow", slow))}
    rest = {who: f"{c[TIES]} tied, {c[COSTS]} took 10 % or more longer" for who, c in (("fast", fast), ("slow", slow))}
    return (
        f"{findings.claim_status(eager, lazy)}\n\n"
        f"{checker_scope.slow_sentence(facts, ranges=False)} {checker_scope.like_for_like(facts)}\n\n"
        f"By mean times, the paper's statistic, prediction saved 10 % or more in {counts['fast']} of the "
        f"{fast.total()} cells "
        f"with our fast checker ({rest['fast']}) and in {counts['slow']} with python-fcl on both sides "
        f"({rest['slow']}); {costs.clear([costs.clear_mean_savings(p, tables) for p, _ in RUNS])}. "
        "A mean follows the few slowest queries (*The statistic*, below): where those saved, a mean "
        f"can save while most queries did not; {means_apart(tables)}."
    )


def load_line() -> str:
    """The machine's load as a live table was timed (review r32d): the last minute's load average and the cores."""
    return (
        f"Timed at a load average of {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores (the last minute's, as this "
        "table was finished). Live timings on a shared machine illustrate; section 6's recorded runs decide."
    )
