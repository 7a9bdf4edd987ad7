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
from tools.results_findings import DETAIL_BEGIN, DETAIL_END, cae_unseen, summary
from tools.results_noise import at_noise_edge, own_intervals
from tools.results_words import change, counted, percent, span

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
    """The summary's Markdown, without its markers: the verdict on the paper's claim in one sentence, with the counts
    Figure 1 draws (review r27f, item 1), then the same network with python-fcl, the paper's statistic and the paper's
    own network, each count said here only (item 2); the findings say why."""
    ratios = recorded.query_ratios(recorded.ALGORITHM_1, tables)
    own = counted([change(r) for row in ratios.values() for r in row.values()])
    facts = checker_scope.slow_checker(tables)
    whole = whole_query(facts)
    slow = facts.total_verdicts()
    sampling = facts.sampling_verdicts()
    stage = (
        f"cuts sampling time by {span(list(facts.sampling))} %"
        if sampling[findings.SAVES] == len(facts.sampling)
        else f"cuts sampling time in {sampling[findings.SAVES]} of {len(facts.sampling)} cells"
    )
    _, _, better = cae_unseen(tables)
    cae_said = (
        "no better than answering “all free” on unseen workspaces"
        if round(better * 100) <= 0
        else f"at most {percent(better)} points better than answering “all free” on unseen workspaces"
    )
    fast_edge, slow_edge = (
        edges(own_intervals(tables, key), tables) for key in (recorded.ALGORITHM_1, checker_scope.SLOW)
    )
    lead = (
        "**In short: does an accurate network inside the paper's Algorithm 1 save planning time? "
        f"{ANSWERS[findings.claim_verdict(ratios)]}, against our fast compiled checker.** By the median of each "
        f"query's own ratio (Figure 1) the `strong` network's whole query saved time in {own[0]} of {sum(own)} "
        f"cells{robust(own[0], fast_edge[0], 'savings')}, tied in {own[1]} and cost time in "
        f"{own[2]}{robust(own[2], fast_edge[1], 'costs')}."
    )
    rest = (  # review r30f, item 1: three plain sentences, no bullets; the counts by means are Table 3's section's
        f"With python-fcl, a slow exact checker, on both sides, the same network {stage}, as the paper's did "
        f"({span(list(facts.papers_sampling))} %), but its whole query saved time by the median query in only "
        f"{slow[findings.SAVES]} of {len(facts.own)} cells{robust(slow[findings.SAVES], slow_edge[0], 'savings')}, "
        f"tied in {slow[findings.TIES]} and cost time in {slow[findings.COSTS]}"
        f"{robust(slow[findings.COSTS], slow_edge[1], 'costs')}; {whole.verdict}. The paper's own network cannot "
        f"test the claim: its CAE is {cae_said} and its MLP is at chance on balanced unseen samples "
        "([What reproduces](#what-reproduces-and-what-does-not) gives the figures)."
    )
    return f"{lead} {rest}"


def edges(medians: dict[str, dict[str, tuple[float, float, float]]], tables: Tables) -> tuple[int, int]:
    """How many of the savings and of the costs among ``medians`` lie at the noise edge (:func:`at_noise_edge`)."""
    cells = [float(cell.split()[-1]) for cell in at_noise_edge(medians, tables)]
    return sum(r < 1 for r in cells), sum(r > 1 for r in cells)


def robust(count: int, edge: int, what: str) -> str:
    """Review r28f, contradiction 3: ``" (5 clear costs, 4 at the noise edge)"``, the cells of a count that lie at the
    noise edge (:func:`edges`) told apart from those clear of it; empty for none."""
    if not count:
        return ""
    return f" ({count - edge} clear {what}, {edge} at the noise edge)" if edge else " (all clear of the noise edge)"


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
