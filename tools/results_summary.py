"""The summary at the top of ``docs/results.md`` ("In short"): its sentences written here, every number in them
computed from the tables the page prints (read as :mod:`tools.recorded_results` reads them)::

    python -m tools.results_summary        # after editing docs/results.md's tables

It rewrites the lines between :data:`BEGIN` and :data:`END` in ``docs/results.md``, the findings ("What
reproduces and what does not", :mod:`tools.results_findings`) and the three figures' text
(:mod:`tools.results_figures`), and draws the figures; ``tests/test_results_page.py`` fails while the page differs
from what the tables give, so a new run's tables cannot leave an old summary behind. Time ratios are read with the
page's rule, chapter 04's (:mod:`tools.results_words`), and single cells against the noise floor
(:mod:`tools.results_noise`). It also shows the page's wide tables in parts of at most :data:`COLUMNS` columns
(:func:`narrow`).
"""

from __future__ import annotations

import sys
from collections.abc import Sequence
from typing import NamedTuple

from toolkit.plots import alt
from toolkit.teaching import checker_scope, findings, recorded
from toolkit.teaching.checker_scope import SLOW
from toolkit.teaching.recorded import Tables
from tools.recorded_results import RESULTS, parse
from tools.results_figures import (
    CLAIM_BEGIN,
    CLAIM_END,
    CLAIM_FIGURE,
    FIGURE_BEGIN,
    FIGURE_DPI,
    FIGURE_END,
    FIGURES,
    claim_figure,
    claim_markdown,
    figure_markdown,
    furthest_apart,
    table3_figure,
)
from tools.results_findings import (
    APART_BEGIN,
    APART_END,
    DETAIL_BEGIN,
    DETAIL_END,
    apart,
    causes,
    not_from_sampling,
    summary,
)
from tools.results_networks import cae_unseen
from tools.results_noise import NOISE_EDGE, own_intervals, reach_of
from tools.results_words import NAMES, change, counted, percent, span

BEGIN = "<!-- summary: written by `python -m tools.results_summary` from the tables below; edit it there -->"
END = "<!-- end of the summary -->"
COLUMNS = 5  # the widest table the page shows: wider ones are cut off, or scroll, at 1280 px (chapter 04's rule)
KEYS = ("", "sampler")  # a table's leading columns that name its rows: every part of a split table repeats them


class Whole(NamedTuple):
    """The whole query with python-fcl on both sides, counted as the paper counts (Table 3's means)."""

    means: int  # our cells that saved 10 % or more by means
    papers: int  # the paper's Table 3's, in the same cells
    verdict: str  # what a slow checker reproduces, in words


def whole_query(facts: checker_scope.SlowChecker) -> Whole:
    """Table 3's total cells that saved 10 % or more, ours with python-fcl on both sides and the paper's, and what that
    says: the sampling savings reproduce with a slow checker (where they do), the whole-query ones where ours save in
    at least half as many cells as the paper's."""
    means = sum(change(1 - saved) == "less time" for saved in facts.totals)
    papers = sum(change(1 - saved) == "less time" for saved in facts.papers_totals)
    sampled = facts.sampling_verdicts()[findings.SAVES] == len(facts.sampling)
    medians = facts.total_verdicts()[findings.SAVES]
    whole = 2 * max(means, medians) >= papers
    if sampled:  # review r29f, contradiction 3: the sizes, cell by cell, are Figure 3's
        verdict = (
            f"the paper's whole-query savings ({papers} of {len(facts.papers_totals)} cells in its Table 3) reproduce "
            + ("with this checker" if whole else "with neither checker")
        )
    else:
        verdict = "neither checker reproduces the paper's savings"
    return Whole(means, papers, verdict)


ANSWERS = {findings.HOLDS: "Yes", findings.IN_PART: "In part", findings.DOES_NOT_HOLD: "No"}


def short(tables: Tables) -> str:
    """The summary's Markdown, without its markers: the answer, then three one-line verdicts a student can repeat
    (reader r33f, item 1), one a series (our compiled checker, python-fcl on both sides, the paper), each read from
    the counts the table under them gives (:func:`counts`), then the bands near 1 those counts are read with
    (:func:`tools.results_noise.bands`). Why prediction saves so little is the findings' first bullet."""
    ratios = recorded.query_ratios(recorded.ALGORITHM_1, tables)
    facts = checker_scope.slow_checker(tables)
    papers = counted([change(1 - s) for s in facts.papers_totals])
    fast = counted([change(m) for _, m in own_medians(tables, recorded.ALGORITHM_1)])
    edge = NOISE_EDGE * reach_of(tables)
    slow = own_medians(tables, SLOW)
    slow_read = counted([change(m) for _, m in slow])
    beyond = counted([change(m) for _, m in slow if abs(m - 1) >= edge])
    answer = (  # reader r37f, item 1: one sentence, both checkers and the other two tables, every count computed
        "**In short: does an accurate network inside the paper's Algorithm 1 (its PRM planner) save planning time? "
        f"{ANSWERS[findings.claim_verdict(ratios)]}: with our fast compiled checker the network "
        f"{VERBS[max(range(3), key=lambda k: (fast[k], k == 1))]} ({fast[2] or 'none'} of {sum(fast)} cells slower, "
        f"{fast[0] or 'none'} faster); with python-fcl, a slow exact checker, it "
        f"{VERBS[max(range(3), key=lambda k: (slow_read[k], k == 1))]} ({beyond[0] or 'none'} of {sum(slow_read)} "
        f"faster beyond the noise edge); {tables_said(tables)}.** A cell is one scenario with one sampler, say 3DC-9 "
        "OB: the 9-DoF box chain in 3D clutter with the Obstacle-Based sampler (the Key under the table names all "
        "eight). Each bullet counts its cells by each query's own ratio, its time with prediction over its own time "
        "without: saved at 0.90 or less, cost at 1.10 or more (our 10 % rule); the *noise edge*, "
        f"{1 - edge:.2f}–{1 + edge:.2f}, is twice as far from 1 as timing alone moved that ratio, and a saving or "
        "cost inside it is no clear evidence:"
    )
    verdicts = [
        verdict_line(
            "With our fast compiled checker (our exact collision check, compiled with numba)",
            own_medians(tables, recorded.ALGORITHM_1),
            tables,
        ),
        verdict_line(
            "With python-fcl (the FCL library called from Python, a slow exact checker) on both sides",
            own_medians(tables, SLOW),
            tables,
        )
        + not_prediction(tables),
        f"- **The paper's Table 3, by means: {READS[max(range(3), key=lambda k: (papers[k], k == 1))]}.** It gives no "
        f"query's own ratio; {papers[0]} saved 10 % or more, {papers[1]} tied, "
        f"{papers[2] or 'none'} cost 10 % or more{small_costs(facts.papers_totals)} ([how we read its "
        "table](#how-these-results-were-made)).",
    ]
    why = causes(tables)
    why_said = (  # reader r37f, contradiction 1 and item 2: two causes, one per checker
        f"Why, by means: with our compiled checker the network is the dearer check, so sampling got 10 % or more "
        f"slower in {why.slower} of {why.cells} cells, adding at most {percent(-why.grew)} % of a query; with "
        f"python-fcl sampling took at most {percent(why.share)} % of a query, so shortening sampling saved at most "
        f"{percent(why.saved)} % of a query. In {len(apart(tables, recorded.ALGORITHM_1))} cells with our compiled "
        f"checker and {len(apart(tables))} with python-fcl the rest of the query, on the roadmap the screened samples "
        "built, moved the whole query 10 points or more further than sampling did "
        "([the findings](#what-reproduces-and-what-does-not)). The table under them adds the counts by mean times, "
        f"the paper's statistic; a few slow queries pull a mean: {means_apart(tables)}"
    )
    return f"{answer}\n\n" + "\n".join(verdicts) + f"\n\n{networks(tables)}\n\n{why_said}\n\n{counts(tables)}"


def small_costs(totals: Sequence[float]) -> str:
    """Reader r36f, contradiction 5: the paper's whole-query costs under 10 %, which the 10 % rule calls ties, said
    beside "none cost 10 % or more" (``totals``: Table 3's improvements; a cost is a negative one), as
    ``" (three cost 2–9 %)"``; empty where there are none."""
    costs = [-saved for saved in totals if saved < 0 and change(1 - saved) != "more time"]
    if not costs:
        return ""
    words = {1: "one", 2: "two", 3: "three", 4: "four", 5: "five"}
    return f" ({words.get(len(costs), str(len(costs)))} cost {span(costs)} %)"


def fast_means(tables: Tables) -> list[float]:
    """Table 3's whole-query ratios of means of the `strong` network inside Algorithm 1, our compiled checker."""
    return [
        1 - saved
        for scenario in recorded.table(recorded.ALGORITHM_1, "time improvement", tables)
        for saved in recorded.improvements(recorded.ALGORITHM_1, scenario, recorded=tables).values()
    ]


def means_apart(tables: Tables) -> str:
    """The lead's example of a mean pulled by a few slow queries (reader r34f, item 2), Figure 2's
    (:func:`tools.results_figures.furthest_apart`)."""
    name, sampler, mean, median = furthest_apart(tables)
    return (
        f"with our compiled checker, {name} {sampler} is {mean:.2f} by means and {median:.2f} by each query's own "
        "ratio."
    )


def above_paper(rows: list[str], ours: list[float], papers: list[float]) -> list[str]:
    """The scenarios where our figure beats the paper's, as ``"3DO, 97 / 94 %"`` (reader r35f, contradictions 2-3)."""
    return [
        f"{NAMES.get(s, s.upper())}, {percent(o)} / {percent(p)} %"
        for s, o, p in zip(rows, ours, papers)
        if int(percent(o)) > int(percent(p))
    ]


def networks(tables: Tables) -> str:
    """Reader r34f, item 1: the verdicts on the paper's Tables 1 and 2, one line each, read from the record; reader
    r35f, contradictions 2-3: each leads with the paper's own statistic and the trivial answer beside it."""
    ours, free, gain = cae_unseen(tables)
    cae = recorded.table("paper", "CAE reconstruction", tables)
    papers = [recorded.ours(row["Unseen"].split("/")[-1]) for row in cae.values()]
    mlp = recorded.table("paper", "MLP accuracy", tables)
    blind, valid, papers_mlp = (
        [recorded.ours(row[column].split("/")[side]) for row in mlp.values()]
        for column, side in (("Unseen Acc", 0), ("Unseen always valid", 0), ("Unseen Acc", -1))
    )
    balanced = {
        preset: [
            recorded.ours(row["Balanced unseen Acc"]) for row in recorded.table(preset, "MLP accuracy", tables).values()
        ]
        for preset in ("paper", recorded.ALGORITHM_1)
    }
    cae_said = "no better than" if round(gain * 100) <= 0 else "barely better than"
    chance = max(balanced["paper"]) < 0.6
    cae_above = above_paper(list(cae), ours, papers)
    mlp_above = above_paper(list(mlp), blind, papers_mlp)
    always = above_paper(list(mlp), [o if percent(o) == percent(v) else 0.0 for o, v in zip(blind, valid)], papers_mlp)
    return (
        "The paper's other two tables, on unseen workspaces:\n\n"
        f"- **Table 1 (the CAE): not reproduced.** Ours reconstructs {span(ours)} % of their cells, {cae_said} "
        f"answering “free” everywhere ({span(free)} %); the paper's CAE, {span(papers)} %"
        + (f" (ours higher in {'; '.join(cae_above)})" if cae_above else "")
        + f".\n- **Table 2 (the MLP): {'not reproduced' if chance else 'in part'}.** On validity-blind samples "
        "(drawn without regard to collisions, as the paper measures), the paper's recipe is right "
        f"{span(blind)} % of the time (the paper's: "
        f"{span(papers_mlp)} %), answering “valid” to every sample {span(valid)} %"
        + (
            f"; where it beats the paper ({'; '.join(mlp_above)}), it answers “valid” to every sample"
            if mlp_above == always != []
            else ""
        )
        + f"; on balanced samples, half valid, it is right {span(balanced['paper'])} % "
        f"({'chance' if chance else 'above chance'}: a coin flip is right 50 %), our `strong` MLP "
        f"{span(balanced[recorded.ALGORITHM_1])} %."
    )


READS = ("prediction saves time", "mostly a tie", "prediction costs time")  # a series' verdict: its largest count
VERBS = ("saves time", "mostly ties", "costs time")  # the same, in the answer's sentence


def tables_said(tables: Tables) -> str:
    """The answer's last clause: whether the paper's Tables 1 and 2 reproduce (:func:`networks` reads them)."""
    _, _, gain = cae_unseen(tables)
    balanced = [
        recorded.ours(row["Balanced unseen Acc"]) for row in recorded.table("paper", "MLP accuracy", tables).values()
    ]
    if round(gain * 100) <= 0 and max(balanced) < 0.6:
        return "and the paper's Tables 1 and 2 do not reproduce either"
    return "the paper's Tables 1 and 2 reproduce in part"


def own_medians(tables: Tables, key: str) -> list[tuple[str, float]]:
    """The medians of each query's own ratio of the run ``key``: ``[("3DC-9 OB", 0.79), ...]``."""
    return [(f"{s} {sampler}", m) for s, by in own_intervals(tables, key).items() for sampler, (m, _, _) in by.items()]


def not_prediction(tables: Tables) -> str:
    """Reader r38f, contradiction 2: python-fcl's savings beyond the noise edge whose whole query, by means, saved 10
    points or more beyond what sampling saved (:func:`apart`), said as not prediction's doing; empty where none."""
    edge = NOISE_EDGE * reach_of(tables)
    far = {cell for cell, m in own_medians(tables, SLOW) if change(m) == "less time" and abs(m - 1) >= edge}
    rest = [cell.name for cell in apart(tables) if cell.total > cell.sampling and cell.name in far]
    return (
        f" Of those, {' and '.join(rest)} saved through the rest of the query, not sampling (by means; this run was "
        "not timed twice: its noise edge is borrowed from the run with our compiled checker)."
        if rest
        else ""
    )


def verdict_line(series: str, cells: list[tuple[str, float]], tables: Tables) -> str:
    """One of the summary's verdicts: the series' largest count by each query's own ratio (:data:`READS`, a tie where
    two are equal), then its cells saved, tied and cost by that ratio alone (reader r36f, item 2: one statistic a
    line; the counts by means are the table's), those beyond the noise edge counted and, up to three, named."""
    read = counted([change(m) for _, m in cells])
    edge = NOISE_EDGE * reach_of(tables)
    parts = []
    for k, name, word in ((0, "saved", "less time"), (2, "cost", "more time")):
        far = [f"{cell} {m:.2f}" for cell, m in cells if change(m) == word and abs(m - 1) >= edge]
        named = f": {', '.join(far)}" if 0 < len(far) <= 3 else ""
        parts.append(f"{read[k] or 'none'} {name}" + (f" ({len(far)} beyond the noise edge{named})" if read[k] else ""))
    said = READS[max(range(3), key=lambda k: (read[k], k == 1))]
    return f"- **{series}: {said}.** {parts[0][0].upper()}{parts[0][1:]}, {read[1]} tied, {parts[1]}."


def counts(tables: Tables) -> str:
    """The summary's table (reader r32f, item 1): each series' cells that saved, tied and cost time, by the median of
    each query's own ratio (Figure 1, the verdict's statistic), those of them beyond the noise edge, and by means
    (Table 3's statistic, Figure 2), the paper's by means alone."""
    facts = checker_scope.slow_checker(tables)
    edge = NOISE_EDGE * reach_of(tables)

    def row(name: str, own: dict[str, dict[str, tuple[float, float, float]]] | None, means: list[float]) -> str:
        by_means = "{} / {} / {}".format(*counted([change(r) for r in means]))
        if own is None:
            return f"| {name} | {by_means} | — | — |"
        medians = [m for by in own.values() for m, _, _ in by.values()]
        read = counted([change(m) for m in medians])
        beyond = counted([change(m) for m in medians if abs(m - 1) >= edge])
        return f"| {name} | {by_means} | {read[0]} / {read[1]} / {read[2]} | {beyond[0]} / {beyond[2]} |"

    lines = [
        f"| whole query, {len(facts.papers_totals)} cells | by means (Table 3, Figure 2): saved / tied / cost "
        "| by each query's own ratio (Figure 1): saved / tied / cost | of those, beyond the noise edge: saved / cost |",
        "| --- | --- | --- | --- |",
        row("the paper's reported results (its Table 3)", None, [1 - s for s in facts.papers_totals]),
        row(  # reader r35f, item 1: the closest copy of the paper's recipe, its savings explained where they are told
            "ours, `paper`-preset network, our compiled checker of 2 December",
            None,
            [
                1 - saved
                for s in recorded.table("paper", "time improvement", tables)
                for saved in recorded.improvements("paper", s, recorded=tables).values()
            ],
        ),
        row("ours, `strong` network, our compiled checker", own_intervals(tables), fast_means(tables)),
        row(
            "ours, `strong` network, python-fcl on both sides",
            own_intervals(tables, checker_scope.SLOW),
            [1 - s for s in facts.totals],
        ),
    ]
    return "\n".join(lines)


def narrow(text: str) -> str:
    """``text`` with every table wider than :data:`COLUMNS` shown in parts (:func:`parts`), a blank line between
    them: :func:`tools.recorded_results.parse` reads them as one table again."""
    lines, out, k = text.splitlines(), [], 0
    while k < len(lines):
        end = k
        while end < len(lines) and lines[end].startswith("|"):
            end += 1
        if end == k:
            out.append(lines[k])
            k += 1
            continue
        rows = [[cell.strip() for cell in line.strip().strip("|").split("|")] for line in lines[k:end]]
        shown = ["\n".join("| " + " | ".join(row) + " |" for row in part) for part in parts(rows)]
        out.append("\n\n".join(shown))
        k = end
    return "\n".join(out) + "\n" * text.endswith("\n")


def parts(rows: list[list[str]]) -> list[list[list[str]]]:
    """A table's ``rows`` (its header first) as parts of at most :data:`COLUMNS` columns, each with its leading
    :data:`KEYS` columns: the other columns grouped by their first word (``Sampling BS``, ``Sampling OB`` ...),
    whole groups packed from the right, so a table's last columns, which its prose cites, keep together."""
    keys = next(k for k, name in enumerate([*rows[0], None]) if name not in KEYS)
    if len(rows[0]) <= COLUMNS:
        return [rows]
    groups: list[list[int]] = []  # column indices, grouped by first word
    for c in range(keys, len(rows[0])):
        word = (rows[0][c].split() or [""])[0].strip(",").lower()
        if groups and word == (rows[0][groups[-1][0]].split() or [""])[0].strip(",").lower():
            groups[-1].append(c)
        else:
            groups.append([c])
    packed: list[list[int]] = []
    for group in reversed(groups):
        if packed and len(packed[0]) + len(group) <= COLUMNS - keys:
            packed[0][:0] = group
        else:
            packed.insert(0, list(group))
    return [[row[:keys] + [row[c] for c in columns] for row in rows] for columns in packed]


def between(text: str, begin: str, end: str, new: str) -> str:
    """``text`` with the lines between the markers ``begin`` and ``end`` replaced by ``new``."""
    head, found, rest = text.partition(begin)
    _, ended, tail = rest.partition(end)
    if not found or not ended:
        raise ValueError(f"docs/results.md has no markers: a line {begin!r} and, after it, {end!r}")
    return f"{head}{begin}\n{new}\n{end}{tail}"


def with_summary(text: str) -> str:
    """``text`` (docs/results.md) with its wide tables in parts (:func:`narrow`), the summary between its markers
    made again from its tables (:func:`summary`) and the figure's text between its own (:func:`figure_markdown`)."""
    text = between(narrow(text), BEGIN, END, short(parse(text)))
    text = between(text, DETAIL_BEGIN, DETAIL_END, summary(parse(text)))
    text = between(text, APART_BEGIN, APART_END, not_from_sampling(parse(text)))
    text = between(text, CLAIM_BEGIN, CLAIM_END, claim_markdown(text))
    for kind in FIGURES:
        text = between(text, FIGURE_BEGIN.format(kind=kind), FIGURE_END.format(kind=kind), figure_markdown(text, kind))
    return text


def main() -> int:
    text = with_summary(RESULTS.read_text())
    RESULTS.write_text(text)
    drawn = {CLAIM_FIGURE: claim_figure(text), **{path: table3_figure(text, kind) for kind, path in FIGURES.items()}}
    for path, fig in drawn.items():
        fig.savefig(path, dpi=FIGURE_DPI, bbox_inches="tight", metadata={"Description": alt.alt_text(fig)})
    print(f"wrote the summary and the figures' text of {RESULTS.name}, and {', '.join(p.name for p in drawn)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
