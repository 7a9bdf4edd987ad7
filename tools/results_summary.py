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
from tools.results_findings import DETAIL_BEGIN, DETAIL_END, share_word, stage_shares, summary
from tools.results_words import change, counted, span

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
    """The summary's Markdown, without its markers: three plain sentences (reader r31f, item 1). The answer, with the
    counts Figure 1 draws and the two words it needs defined where they are first used (a cell, each query's own
    ratio); what the paper claimed beside what we measured with python-fcl on both sides, by the median query and by
    means (so Figure 2's costs do not contradict it); and where a learned check would pay (:func:`where_it_pays`).
    The noise edge is Figure 1's caption's; the paper's own network, the findings'."""
    ratios = recorded.query_ratios(recorded.ALGORITHM_1, tables)
    own = counted([change(r) for row in ratios.values() for r in row.values()])
    facts = checker_scope.slow_checker(tables)
    whole = whole_query(facts)
    slow = facts.total_verdicts()
    by_means = counted([change(1 - saved) for saved in facts.totals])
    sampling = facts.sampling_verdicts()
    stage = (
        f"cut sampling time by {span(list(facts.sampling))} %"
        if sampling[findings.SAVES] == len(facts.sampling)
        else f"cut sampling time in {sampling[findings.SAVES]} of {len(facts.sampling)} cells"
    )
    answer = (
        "**In short: does an accurate network inside the paper's Algorithm 1 save planning time? "
        f"{ANSWERS[findings.claim_verdict(ratios)]}, against our fast compiled checker.** Of {sum(own)} cells (a cell "
        "is one scenario with one sampler, say 3DC-9 OB), the `strong` network saved a whole query's time in "
        f"{own[0]}, tied in {own[1]} and cost time in {own[2]}, each cell read by the median of each query's own "
        "ratio, that query's time with prediction over its own time without (Figure 1)."
    )
    claimed = (
        f"The paper's network cut sampling time by {span(list(facts.papers_sampling))} % and saved whole-query time "
        f"in {whole.papers} of {len(facts.papers_totals)} cells (its Table 3); with python-fcl, a slow exact checker, "
        f"on both sides, ours {stage} but saved whole-query time in only {slow[findings.SAVES]} of {len(facts.own)} "
        f"cells by the median query, tied in {slow[findings.TIES]} and cost time in {slow[findings.COSTS]} (by mean "
        f"times, as the paper counts: saved in {by_means[0]}, cost time in {by_means[2]}; Figure 2)."
    )
    return f"{answer} {claimed} {where_it_pays(tables)}"


def where_it_pays(tables: Tables) -> str:
    """Where a learned check would pay: where an exact check costs many times the network's and sampling is most of a
    query; here sampling's largest share of a mean query without prediction, with each checker
    (:func:`tools.results_findings.stage_shares`)."""
    fast, _ = stage_shares(tables, recorded.ALGORITHM_1)
    slow, _ = stage_shares(tables, checker_scope.SLOW)
    return (
        "A learned check would pay only where an exact check costs many times the network's and sampling is most of "
        f"a query; here sampling took at most {max(fast) * 100:.2g} % of a mean query with our compiled checker and "
        f"at most about {share_word(max(slow))} with python-fcl ([why](#what-reproduces-and-what-does-not))."
    )


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
