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
    table3_figure,
)
from tools.results_findings import (
    APART_BEGIN,
    APART_END,
    DETAIL_BEGIN,
    DETAIL_END,
    not_from_sampling,
    summary,
)
from tools.results_noise import NOISE_EDGE, bands, own_intervals, reach_of
from tools.results_words import change, counted

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
    papers = counted([change(1 - s) for s in checker_scope.slow_checker(tables).papers_totals])
    answer = (
        "**In short: does an accurate network inside the paper's Algorithm 1 save planning time? "
        f"{ANSWERS[findings.claim_verdict(ratios)]}, against our fast compiled checker.** Our accurate network is "
        "the `strong` preset's, Algorithm 1 the paper's PRM planner. Each line counts 16 cells, a cell one scenario "
        "with one sampler (say 3DC-9 OB), ours by each query's time with prediction over its own time without, the "
        "paper's by mean times:"
    )
    verdicts = [
        verdict_line("With our fast compiled checker", own_medians(tables, recorded.ALGORITHM_1), tables),
        verdict_line("With python-fcl, a slow exact checker, on both sides", own_medians(tables, SLOW), tables),
        f"- **The paper's Table 3: {READS[max(range(3), key=lambda k: (papers[k], k == 1))]}.** Of {sum(papers)} "
        f"cells, {papers[0]} saved 10 % or more, {papers[1]} tied, {papers[2] or 'none'} cost (read as mean times: "
        "[how we read it](#how-these-results-were-made)).",
    ]
    why = (
        "Why so little is saved: prediction shortens only sampling, a small share of a query ([the findings]"
        "(#what-reproduces-and-what-does-not)). Saved: 0.90 or less; cost: 1.10 or more; the noise edge and the "
        "other bands near 1 are in the second table."
    )
    return f"{answer}\n\n" + "\n".join(verdicts) + f"\n\n{why}\n\n{counts(tables)}\n\n{bands(tables)}"


READS = ("prediction saves time", "mostly a tie", "prediction costs time")  # a series' verdict: its largest count


def own_medians(tables: Tables, key: str) -> list[tuple[str, float]]:
    """The medians of each query's own ratio of the run ``key``: ``[("3DC-9 OB", 0.79), ...]``."""
    return [(f"{s} {sampler}", m) for s, by in own_intervals(tables, key).items() for sampler, (m, _, _) in by.items()]


def verdict_line(series: str, cells: list[tuple[str, float]], tables: Tables) -> str:
    """One of the summary's verdicts: the series' largest count (:data:`READS`, a tie where two are equal), then its
    cells saved, tied and cost, those beyond the noise edge counted and, up to three, named."""
    read = counted([change(m) for _, m in cells])
    edge = NOISE_EDGE * reach_of(tables)
    parts = []
    for k, name, word in ((0, "saved", "less time"), (2, "cost", "more time")):
        far = [f"{cell} {m:.2f}" for cell, m in cells if change(m) == word and abs(m - 1) >= edge]
        named = f": {', '.join(far)}" if 0 < len(far) <= 3 else ""
        parts.append(f"{read[k] or 'none'} {name}" + (f" ({len(far)} beyond the noise edge{named})" if read[k] else ""))
    said = READS[max(range(3), key=lambda k: (read[k], k == 1))]
    return f"- **{series}: {said}.** Of {len(cells)} cells, {parts[0]}, {read[1]} tied, {parts[1]}."


def counts(tables: Tables) -> str:
    """The summary's table (reader r32f, item 1): each series' cells that saved, tied and cost time, by the median of
    each query's own ratio (Figure 1, the verdict's statistic), those of them beyond the noise edge, and by means
    (Table 3's statistic, Figure 2), the paper's by means alone."""
    facts = checker_scope.slow_checker(tables)
    edge = NOISE_EDGE * reach_of(tables)

    def row(name: str, own: dict[str, dict[str, tuple[float, float, float]]] | None, means: list[float]) -> str:
        by_means = "{} / {} / {}".format(*counted([change(r) for r in means]))
        if own is None:
            return f"| {name} | — | — | {by_means} |"
        medians = [m for by in own.values() for m, _, _ in by.values()]
        read = counted([change(m) for m in medians])
        beyond = counted([change(m) for m in medians if abs(m - 1) >= edge])
        return f"| {name} | {read[0]} / {read[1]} / {read[2]} | {beyond[0]} / {beyond[2]} | {by_means} |"

    fast_means = [
        1 - saved
        for scenario in recorded.table(recorded.ALGORITHM_1, "time improvement", tables)
        for saved in recorded.improvements(recorded.ALGORITHM_1, scenario, recorded=tables).values()
    ]
    lines = [
        f"| whole query, {len(facts.papers_totals)} cells | by each query's own ratio (Figure 1): saved / tied / cost "
        "| of those, beyond the noise edge: saved / cost | by means (Table 3, Figure 2): saved / tied / cost |",
        "| --- | --- | --- | --- |",
        row("the paper's reported results (its Table 3)", None, [1 - s for s in facts.papers_totals]),
        row("ours, `strong` network, our compiled checker", own_intervals(tables), fast_means),
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
