"""The summary at the top of ``docs/results.md``: its sentences written here, every number in them computed from the
tables the page prints (read as :mod:`tools.recorded_results` reads them)::

    python -m tools.results_summary        # after editing docs/results.md's tables

It rewrites the lines between :data:`BEGIN` and :data:`END` in ``docs/results.md``; ``tests/test_results_page.py``
fails while they differ from what the tables give, so a new run's tables cannot leave an old summary behind.
Time ratios are read with the page's rule, chapter 04's (:data:`RULE`, :func:`toolkit.teaching.findings.time_verdict`).

It also draws the page's three figures. Figure 1, :data:`CLAIM_FIGURE`, is the statistic the verdict on the paper's
claim reads: the `strong` network inside Algorithm 1, the median of each query's own ratio with its middle half,
with our compiled checker (filled) and, beside it, with python-fcl on both sides (hollow; :data:`CLAIM_SERIES`)
(:func:`claim_figure`, drawn by :func:`toolkit.plots.query_ratios.own_ratios`). Figures 2 and 3, :data:`FIGURES`, are
Table 3's total and sampling columns by means, ours beside the paper's, per scenario and sampler
(:func:`table3_figure`, drawn by :func:`toolkit.plots.query_ratios.means_grid`). Each one's text alternative is
written between its markers (:data:`CLAIM_BEGIN`, :data:`FIGURE_BEGIN` and their ends); each PNG carries the same text
(its ``Description``), so
``tests/test_results_figure.py`` fails while the picture or its words no longer match the tables.

Table 2's accuracy, TPR and TNR imply the share of valid samples in the paper's tests (:func:`implied_valid_share`),
which the paper does not report; docs/fidelity.md, §7, sets the paper's accuracies against answering "valid" to all of
them (tests/test_results_page.py checks its figures against :func:`above_always_valid`).
"""

from __future__ import annotations

import html
import itertools
import math
import re
import sys
from typing import NamedTuple

from matplotlib.figure import Figure

from toolkit.experiments.paper_numbers import IMPROVEMENT
from toolkit.plots import alt, query_ratios
from toolkit.teaching import checker_scope, findings, recorded
from toolkit.teaching.recorded import Tables
from tools.recorded_results import RESULTS, parse

BEGIN = "<!-- summary: written by `python -m tools.results_summary` from the tables below; edit it there -->"
END = "<!-- end of the summary -->"
DETAIL_BEGIN = "<!-- findings: written by `python -m tools.results_summary` from the tables below; edit them there -->"
DETAIL_END = "<!-- end of the findings -->"
RULE = (  # chapter 04's rule for a time ratio with / without, in the page's words
    "a gain of 10 % or more, on the ratio as shown to two decimals (0.90 or less), is a saving, a loss of 10 % or "
    "more (1.10 or more) a loss, anything between a tie"
)
CHAPTER_04 = ("2ds", "3dc7")  # the scenarios whose lazy-PRM cells chapter 04 shows
NAMES = {"2ds": "2DS", "3dc7": "3DC-7", "3dc9": "3DC-9", "3do": "3DO"}
FIGURES = {kind: RESULTS.parent / f"results_table3_{kind}.png" for kind in ("total", "sampling")}  # Table 3's columns
LEADS = {  # what each figure shows, over it
    "total": "**Figure 2: a whole query's time, by means** (Table 3's *Total* columns), each against Algorithm 1 "
    "without prediction, ours beside the paper's.",
    "sampling": "**Figure 3: the sampling stage's time, by means** (Table 3's *Sampling* columns), each against "
    "Algorithm 1 without prediction, ours beside the paper's.",
}
TICKS = {"total": (0.9, 1.1), "sampling": (0.9, 1.1, 3.0)}  # labelled beside each figure's 1-2-5 steps
MARGINS = {"total": 1.15, "sampling": 1.25}  # each figure's range: its points', widened by this factor
ROW_HEIGHTS = {"total": 2.9, "sampling": 3.2}  # inches a row of panels: each band is read to 0.9 and 1.1 (r27f)
NOISE_EDGE = 2  # a median within this many times timing's own reach of 1 reads "at the noise edge"
CLAIM_FIGURE = RESULTS.parent / "results_claim.png"  # Figure 1: the statistic the verdict on the paper's claim reads
CLAIM_BEGIN = "<!-- figure of the claim: drawn by `python -m tools.results_summary` from the tables below -->"
CLAIM_END = "<!-- end of the figure of the claim -->"
CLAIM_TITLE = "strong network inside Algorithm 1: total time, each query's own ratio"
CLAIM_SERIES = ("our compiled checker on both sides", "python-fcl on both sides")  # Figure 1's filled and hollow points
INTERVAL = re.compile(r"(\d+\.\d+) \((\d+\.\d+)–(\d+\.\d+)\)")  # "1.24 (1.12–1.36)": a median (middle half)
FIGURE_BEGIN = "<!-- figure of {kind} times: drawn by `python -m tools.results_summary` from the tables below -->"
FIGURE_END = "<!-- end of the figure of {kind} times -->"
COLUMNS = 5  # the widest table the page shows: wider ones are cut off, or scroll, at 1280 px (chapter 04's rule)
KEYS = ("", "sampler")  # a table's leading columns that name its rows: every part of a split table repeats them
FIGURE_DPI = 110  # as docs/crossover.png: the site's column shows it at about its size
SOURCES = {  # a series of the figure: its preset in the tables (None: the paper's own numbers) and its name; the
    # 1-2 December run with python-fcl is history, left out (review r27f, item 5: five series were 80 markers)
    "the paper (Table 3)": None,
    "ours, paper network, compiled checker": "paper",
    "ours, accurate strong network, compiled checker": recorded.ALGORITHM_1,
    "ours, accurate strong network, python-fcl on both sides": checker_scope.SLOW,
}


def percent(fraction: float) -> str:
    """``0.855`` as ``"86"``: a fraction in whole percent, as the tables write them."""
    return f"{round(fraction * 100)}"


def span(values: list[float], show=percent) -> str:
    """``"86–97"``: the range of ``values`` as ``show`` writes them; one figure where they agree."""
    low, high = show(min(values)), show(max(values))
    return low if low == high else f"{low}–{high}"


WORDS = {findings.SAVES: "less time", findings.TIES: "about the same time", findings.COSTS: "more time"}


def change(ratio: float) -> str:
    """A time ratio with / without read with chapter 04's rule (:func:`toolkit.teaching.findings.time_verdict`):
    ``"more time"``, ``"about the same time"`` or ``"less time"``."""
    return WORDS[findings.time_verdict(ratio)]


def grouped(ratios: dict[str, dict[str, float]]) -> dict[str, list[tuple[str, float]]]:
    """The scenario-sampler cells of ``{scenario: {sampler: ratio}}`` by :func:`change`: ``[(name, ratio), ...]``."""
    groups: dict[str, list[tuple[str, float]]] = {"more time": [], "about the same time": [], "less time": []}
    for scenario, row in ratios.items():
        for sampler, ratio in row.items():
            groups[change(ratio)].append((f"{NAMES.get(scenario, scenario)} {sampler}", ratio))
    return groups


def told(groups: dict[str, list[tuple[str, float]]]) -> str:
    """``"more time in 14 of 16 scenario–sampler cells (1.37–2.58 times as much) and about the same time in 2 (2DS BS
    1.07, 2DS OB 1.00)"``: the largest group first; a group of up to three cells named with its ratios, a larger one
    as the range of its ratios."""
    total = sum(map(len, groups.values()))
    parts: list[str] = []
    for word, cells in sorted(groups.items(), key=lambda group: -len(group[1])):  # the largest group first
        if not cells:
            continue
        ratios = [r for _, r in cells]
        count = f"{len(cells)} of {total} scenario–sampler cells" if not parts else f"{len(cells)}"
        if len(cells) <= 3:
            parts.append(f"{word} in {count} ({', '.join(f'{name} {r:.2f}' for name, r in cells)})")
        else:
            parts.append(f"{word} in {count} ({span(ratios, lambda r: f'{r:.2f}')} times as much)")
    return ", ".join(parts[:-1]) + (" and " if len(parts) > 1 else "") + parts[-1]


def _cae_unseen(tables: Tables) -> tuple[list[float], list[float], float]:
    """The `paper` CAE's accuracy on unseen grids and a CAE answering "free" everywhere's, per scenario (Table 1),
    and the most the first beats the second by (0 or less: no better)."""
    rows = recorded.table("paper", "CAE reconstruction", tables)
    ours = [recorded.ours(row["Unseen"]) for row in rows.values()]
    free = [recorded.ours(row["all free: Seen / Unseen"].split("/")[-1]) for row in rows.values()]
    return ours, free, max(o - f for o, f in zip(ours, free))


def cae(tables: Tables) -> str:
    rows = recorded.table("paper", "CAE reconstruction", tables)
    papers = [recorded.ours(row["Unseen"].split("/")[-1]) for row in rows.values()]
    ours, free, gain = _cae_unseen(tables)
    than_free = (
        "no better, scenario by scenario, than a CAE that answers “free” everywhere"
        if round(gain * 100) <= 0
        else f"at most {percent(gain)} points better than a CAE that answers “free” everywhere"
    )
    return (
        f"**The CAE (Table 1).** The `paper` CAE reconstructs unseen workspaces at {span(ours)} % of their cells "
        f"(the paper: {span(papers)} %), {than_free} ({span(free)} %)."
    )


def implied_valid_share(acc: float, tpr: float, tnr: float) -> float:
    """The share ``p`` of valid samples in a test that a classifier's accuracy, TPR and TNR on it imply:
    Acc = TPR·p + TNR·(1 − p). The paper gives no share for its unseen tests (its seen ones: "approximately
    distributed 50/50"); its Table 2 gives the three scores."""
    if tpr == tnr:
        raise ValueError(f"TPR and TNR are equal ({tpr}): the accuracy is the same for every share of valid samples")
    return (acc - tnr) / (tpr - tnr)


class Implied(NamedTuple):
    """A test's valid share as a classifier's printed scores imply it, and the accuracy above "always valid"."""

    share: float  # at the printed scores
    gap: float  # the accuracy minus the share
    low: float  # the least share any scores that round to the printed ones give
    high: float  # the largest
    least_gap: float  # the least gap they give


def above_always_valid(scores: dict[str, float], rounded: float = 0.005) -> Implied:
    """``scores`` (``{"acc", "tpr", "tnr"}`` as Table 2 prints them, to whole percent) against answering "valid" to
    every sample of the same test (:func:`implied_valid_share`), at the printed scores and over every scores within
    ``rounded`` of them (share and gap are monotone in each score, so the corners bound them)."""
    acc, tpr, tnr = scores["acc"], scores["tpr"], scores["tnr"]
    corners = [
        (acc + a, implied_valid_share(acc + a, tpr + t, tnr + n))
        for a, t, n in itertools.product((-rounded, rounded), repeat=3)
    ]
    share = implied_valid_share(acc, tpr, tnr)
    shares = [p for _, p in corners]
    return Implied(share, acc - share, min(shares), max(shares), min(a - p for a, p in corners))


def mlp(tables: Tables) -> str:
    def balanced(preset: str) -> list[float]:
        return [
            recorded.ours(row["Balanced unseen Acc"]) for row in recorded.table(preset, "MLP accuracy", tables).values()
        ]

    rows = recorded.table("paper", "MLP accuracy", tables)
    one_answer = [
        NAMES.get(name, name)
        for name, row in rows.items()
        if min(recorded.ours(row["Unseen TPR"]), recorded.ours(row["Unseen TNR"])) == 0
    ]
    listed = ", ".join(one_answer[:-1]) + " and " * (len(one_answer) > 1) + "".join(one_answer[-1:])
    trivial = (
        f" In {listed} the `paper` MLP gives one answer to every sample (a TPR or TNR of 0 %)." if one_answer else ""
    )
    blind = [recorded.ours(row["Unseen Acc"]) for row in rows.values()]
    always = [recorded.ours(row["Unseen always valid"]) for row in rows.values()]
    return (
        f"**The MLP (Table 2).** On unseen workspaces' balanced samples (half of them valid) the `paper` MLP is right "
        f"{span(balanced('paper'))} % of the time, where a coin flip is right 50 %; the `strong` MLP "
        f"{span(balanced('strong'))} %. On the validity-blind samples the paper describes, which chapter 04 quotes, "
        f"the `paper` MLP is right {span(blind)} %, answering “valid” to every sample {span(always)} %.{trivial}"
    )


def lazy_prm(tables: Tables) -> str:
    """Against the lazy PRM, one answer per scope, each scope named (reader r18a: chapter 04's "none of 8" and this
    page's "Rarely" read as disagreeing): the accurate `strong` network alone, then both networks together."""
    groups = {
        preset: grouped({s: kinds["total"] for s, kinds in recorded.median_ratios(preset, tables).items()})
        for preset in ("strong", "paper")
    }
    cells = {preset: sum(map(len, g.values())) for preset, g in groups.items()}
    saved = {preset: g["less time"] for preset, g in groups.items()}
    chapter = sum(len(row["total"]) for s, row in recorded.median_ratios("strong", tables).items() if s in CHAPTER_04)

    def answer(count: int, total: int) -> str:
        return "no" if count == 0 else "rarely" if count < total / 2 else "mostly"

    floor = medians_floor(tables)
    beyond = [(name, r) for g in groups.values() for name, r in g["less time"] if floor is None or r < floor[0]]
    named = f" ({', '.join(f'{name} {r:.2f}' for name, r in beyond)})" if beyond else ""
    floor_said = f" beyond this ratio's noise floor ({floor[0]:.2f}–{floor[1]:.2f})," if floor else ""
    return (  # review r28f, items 2 and 3: four lines, the count read by its own noise floor
        "**Does prediction save planning time against the lazy PRM, the fastest exact planner a network can "
        "drive?** By the ratio of the two modes' median times (the medians tables of “Preset `strong`” and “Preset "
        f"`paper`”), for the accurate `strong` network {answer(len(saved['strong']), cells['strong'])} (chapter 04 "
        f"shows {chapter} of its cells): it took {told(groups['strong'])}. Counting the `paper` network's cells too "
        f"(its planner with prediction is Algorithm 1, so planner and prediction both change), "
        f"{answer(len(beyond), sum(cells.values()))}:{floor_said} {len(beyond) or 'none'} of {sum(cells.values())}"
        f"{named}."
    )


def medians_floor(tables: Tables) -> tuple[float, float] | None:
    """How far timing alone moved a ratio of the two medians (:func:`noise`); ``None`` where ``tables`` hold no run
    timed twice."""
    try:
        return noise(tables).medians
    except (KeyError, StopIteration):
        return None


def algorithm_1(tables: Tables) -> str:
    """The `paper` network against the paper's Algorithm 1, Table 3's means counted (the page's section on the
    `paper` preset points here rather than count again)."""
    ours = {
        s: recorded.improvements("paper", s, recorded=tables)
        for s in recorded.table("paper", "time improvement", tables)
    }
    verdicts = [change(1 - saved) for row in ours.values() for saved in row.values()]
    papers = [
        recorded.ours(cell.split("/")[-1])
        for row in recorded.table("paper", "time improvement", tables).values()
        for column, cell in row.items()
        if column.startswith("Total")
    ]
    return (
        "**Against the paper's Algorithm 1** (the `paper` section's Table 3, of means), the `paper` network "
        f"saved 10 % or more of a query's time in {verdicts.count('less time')} of {len(verdicts)} cells, "
        f"lost 10 % or more in {verdicts.count('more time')} and tied in {verdicts.count('about the same time')} "
        f"(the paper: savings of up to {percent(max(papers))} %). With the MLP above, those savings are not the "
        "method working (below: “Savings against Algorithm 1 that are not the method”)."
    )


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
    if sampled and not whole:
        verdict = (
            "a slow checker reproduces the paper's savings in sampling time for the strong network, in the paper's "
            "direction; its savings in a whole query's time reproduce with neither checker"
        )
    elif sampled:
        verdict = (
            "a slow checker reproduces the paper's savings for the strong network, in the paper's direction, in "
            "sampling time and in a whole query's time"
        )
    else:
        verdict = "neither checker reproduces the paper's savings"
    return Whole(means, papers, verdict)


ANSWERS = {findings.HOLDS: "Yes", findings.IN_PART: "In part", findings.DOES_NOT_HOLD: "No"}


def counted(verdicts: list[str]) -> tuple[int, int, int]:
    """How many of ``verdicts`` (:func:`change`'s words) save time, tie and cost time."""
    return verdicts.count("less time"), verdicts.count("about the same time"), verdicts.count("more time")


def stage_shares(tables: Tables, preset: str) -> tuple[list[float], list[float]]:
    """A run's times behind Table 3 (means, a row per scenario and sampler): per cell the sampling stage's share of a
    query without prediction, and the sampling time prediction saved as a share of that query's time (negative where
    sampling grew)."""
    times = next(t for heading, t in tables[preset].items() if "Times behind Table 3" in heading)
    columns = times["columns"]

    def mean(row: list[str], column: str) -> float:
        return recorded.ours(row[columns.index(column)].split("/")[0].replace("*", ""))

    shares, saved = [], []
    for row in times["rows"]:
        total = mean(row, "total without")
        shares.append(mean(row, "sampling without") / total)
        saved.append((mean(row, "sampling without") - mean(row, "sampling with")) / total)
    return shares, saved


def why_no_saving(tables: Tables) -> str:
    """The arithmetic behind the verdict (review r27f, item 7): prediction shortens only the sampling stage, a small
    share of a query; with a fast checker the network costs more than the check it replaces; with a slow one the
    sampling it saves is a small share of the query. Every number from the two runs inside Algorithm 1."""
    fast, _ = stage_shares(tables, recorded.ALGORITHM_1)
    slow, saved = stage_shares(tables, checker_scope.SLOW)
    rates = recorded.table(recorded.ALGORITHM_1, "Checker throughput", tables)
    costs = [1 / recorded.ours(row["learned / exact"]) for row in rates.values()]
    means = counted(
        [
            change(1 - s)
            for scenario in recorded.table(recorded.ALGORITHM_1, "time improvement", tables)
            for s in recorded.improvements(recorded.ALGORITHM_1, scenario, "sampling", recorded=tables).values()
        ]
    )
    return (  # review r28f, item 2: three sentences
        "**Why a fast checker erases the saving.** Prediction shortens only sampling, which took "
        f"{span(fast, lambda f: f'{f * 100:.2g}')} % of a mean query without it with our compiled checker "
        f"({span(slow, lambda f: f'{f * 100:.2g}')} % with python-fcl), and there the network cost "
        f"{span(costs, lambda c: f'{c:.2g}')} times an exact check per configuration, so by means sampling lost 10 % "
        f"or more in {means[2]} of {sum(means)} cells. python-fcl is tens of times slower than today's compiled "
        "checker ([Benchmarks](benchmarks.md)), so with it the network is the cheaper check, yet the sampling time it "
        f"saved came to {span(saved, lambda f: f'{f * 100:.2g}')} % of a mean query's time.{not_from_sampling(tables)}"
    )


class Apart(NamedTuple):
    """A cell of the run with python-fcl on both sides whose whole query, by means, moved further than the sampling
    time prediction saved there could move it (review r28f, contradiction 2)."""

    name: str  # "3DC-9 OB"
    total: float  # Table 3's total improvement (negative: a loss)
    sampling: float  # the sampling time saved, as a share of a mean query without prediction


def apart(tables: Tables) -> list[Apart]:
    """The cells of the run with python-fcl on both sides whose total improvement by means lies 10 points or more from
    the sampling time saved as a share of the query (:func:`stage_shares`): the rest of the query, which prediction
    does not shorten, moved them."""
    _, saved = stage_shares(tables, checker_scope.SLOW)
    times = next(t for heading, t in tables[checker_scope.SLOW].items() if "Times behind Table 3" in heading)
    cells = [(row[0], row[1]) for row in times["rows"]]  # scenario, sampler, in the order of ``saved``
    found = []
    for (scenario, sampler), share in zip(cells, saved):
        total = recorded.improvements(checker_scope.SLOW, scenario, recorded=tables)[sampler]
        if round(abs(total - share) * 100) >= round(findings.TIE * 100):
            found.append(Apart(f"{NAMES.get(scenario, scenario)} {sampler}", total, share))
    return found


def not_from_sampling(tables: Tables) -> str:
    """One sentence on :func:`apart`'s cells, a saving larger than its sampling saving with both shares (review r28f,
    item 4); empty where there are none."""
    cells = apart(tables)
    if not cells:
        return ""

    def said(cell: Apart) -> str:
        if cell.total > cell.sampling and change(1 - cell.total) == "less time":
            return f"{cell.name}, {percent(cell.total)} % saved against {percent(cell.sampling)} %"
        return cell.name

    return (
        f" The totals that moved 10 points or more further ({'; '.join(map(said, cells))}) moved with the rest of "
        "the query, which prediction does not shorten."
    )


def short(tables: Tables) -> str:
    """The summary's Markdown, without its markers: the verdict on the paper's claim in one sentence, with the counts
    Figure 1 draws (review r27f, item 1), then the same network with python-fcl, the paper's statistic and the paper's
    own network, each count said here only (item 2); the findings under Figure 1 say why."""
    ratios = recorded.query_ratios(recorded.ALGORITHM_1, tables)
    own = counted([change(r) for row in ratios.values() for r in row.values()])
    means = counted(
        [
            change(1 - saved)
            for s in ratios
            for saved in recorded.improvements(recorded.ALGORITHM_1, s, recorded=tables).values()
        ]
    )
    facts = checker_scope.slow_checker(tables)
    whole = whole_query(facts)
    slow = facts.total_verdicts()
    slow_means = counted([change(1 - saved) for saved in facts.totals])
    sampling = facts.sampling_verdicts()
    stage = (
        f"cuts sampling time by {span(list(facts.sampling))} %"
        if sampling[findings.SAVES] == len(facts.sampling)
        else f"cuts sampling time in {sampling[findings.SAVES]} of {len(facts.sampling)} cells"
    )
    _, _, better = _cae_unseen(tables)
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
    items = [
        f"**With python-fcl, a slow exact checker, on both sides**, the same network {stage} (the paper: "
        f"{span(list(facts.papers_sampling))} %), and its whole query saved time in {slow[findings.SAVES]} of "
        f"{len(facts.own)} cells by the median query{robust(slow[findings.SAVES], slow_edge[0], 'savings')}, "
        f"tied in {slow[findings.TIES]} and cost time in {slow[findings.COSTS]}"
        f"{robust(slow[findings.COSTS], slow_edge[1], 'costs')}. By Table 3's means: {slow_means[0]} saved / "
        f"{slow_means[1]} tied / {slow_means[2]} lost, where the paper's Table 3 saves in {whole.papers} of "
        f"{len(facts.papers_totals)}{more_than_sampling(tables)}.",
        f"**By Table 3's means**, the paper's statistic, the compiled checker's run gives {means[0]} saved / "
        f"{means[1]} tied / {means[2]} lost; timing alone moves a mean further than the tie band (the noise floor "
        "under Figure 1), so the verdict reads the medians.",
        f"**The paper's own network** cannot test the claim: its CAE is {cae_said} and its MLP is at chance on "
        "balanced unseen samples (“What reproduces” below gives the figures).",
        f"**So** {whole.verdict}.",
    ]
    return lead + "\n\n" + "\n".join(f"- {item}" for item in items)


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


def more_than_sampling(tables: Tables) -> str:
    """Review r28f, contradiction 2: of the run with python-fcl, the savings by means larger than the sampling time it
    saved could give (:func:`apart`), named with both shares; empty for none."""
    cells = [c for c in apart(tables) if change(1 - c.total) == "less time" and c.total > c.sampling]
    if not cells:
        return ""
    named = "; ".join(f"{c.name}, {percent(c.total)} % against {percent(c.sampling)} %" for c in cells)
    return (
        f"; {len(cells)} of those savings is more than the sampling time prediction saved there could give ({named}; "
        "“What reproduces” below says why)"
    )


def summary(tables: Tables) -> str:
    """The findings under Figure 1, without their markers: why the summary's verdict comes out as it does
    (:func:`why_no_saving`), the paper's networks (Tables 1 and 2), and the answers against the lazy PRM and against
    Algorithm 1 with the `paper` network; no count the summary gives is said again (review r27f, item 2)."""
    items = [
        why_no_saving(tables),
        cae(tables),
        mlp(tables),
        lazy_prm(tables),
        algorithm_1(tables),
    ]
    return "\n".join(f"- {item}" for item in items)


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


def ratios(text: str, kind: str = "total") -> dict[str, dict[str, dict[str, float]]]:
    """Table 3's ``kind`` columns ("total" or "sampling") as time ratios with / without (``1 - improvement``, means,
    against Algorithm 1), from the paper and from the page ``text``'s runs of the `paper` recipe:
    ``{scenario: {series: {sampler: ratio}}}``."""
    tables = parse(text)
    found: dict[str, dict[str, dict[str, float]]] = {}
    for scenario in NAMES:  # the paper's order
        for name, preset in SOURCES.items():
            if preset is not None and scenario not in recorded.table(preset, "time improvement", tables):
                continue  # a run that did not plan this scenario
            saved = (
                IMPROVEMENT[scenario][kind]
                if preset is None
                else recorded.improvements(preset, scenario, kind, recorded=tables)
            )
            found.setdefault(scenario, {})[name] = {s: round(1 - v, 6) for s, v in saved.items()}
    return found


def table3_figure(text: str, kind: str = "total") -> Figure:
    """One of the page's figures: per scenario, each sampler's mean ``kind`` time ("total" or "sampling") with /
    without prediction against Algorithm 1, the paper's beside ours (:func:`ratios`), the tie band of :data:`RULE`
    shaded; a grid of two columns, one legend, and one log axis for its panels, so the same ratio stands at the same
    height in every panel (:func:`toolkit.plots.query_ratios.means_grid`); each figure its own range, so the tie band of
    the total times is not squeezed by the sampling stage's wider one, the band's edges labelled (:data:`TICKS`)."""
    every = [r for series in ratios(text, kind).values() for by in series.values() for r in by.values()]
    margin = MARGINS[kind]  # room between the outermost points and the frame
    ylim = (min(*every, 1 - findings.TIE) / margin, max(*every, 1 + findings.TIE) * margin)
    return query_ratios.means_grid(
        {f"{NAMES[s]}: {kind} time, means": series for s, series in ratios(text, kind).items()},
        tie=findings.TIE,
        ylim=ylim,
        ticks=TICKS[kind],
        row_height=ROW_HEIGHTS[kind],
    )


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


def claim_figure(text: str) -> Figure:
    """Figure 1: what the verdict on the paper's claim reads (:func:`accurate_in_algorithm_1`), the median of each
    query's own ratio with its middle half, per scenario and sampler (:func:`toolkit.plots.query_ratios.own_ratios`)."""
    tables = parse(text)
    return query_ratios.own_ratios(
        own_intervals(tables),
        title=CLAIM_TITLE,
        tie=findings.TIE,
        slow=own_intervals(tables, checker_scope.SLOW),
        series=CLAIM_SERIES,
    )


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
    """One line: how far timing alone moved a median query and a ratio of means."""
    floor = noise(tables)
    return (
        f"*Noise floor* (the table “timed twice”: one computation timed twice): timing alone moved a median of each "
        f"query's own ratio to {floor.own[0]:.2f}–{floor.own[1]:.2f} and a ratio of means to "
        f"{floor.means[0]:.2f}–{floor.means[1]:.2f}."
    )


def reach_of(tables: Tables) -> float:
    """How far from 1 timing alone moved a median of each query's own ratio (:func:`noise`)."""
    return max(abs(v - 1) for v in noise(tables).own)


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


def claim_markdown(text: str) -> str:
    """Figure 1 as the page ``text`` shows it: what it shows and that it is the verdict's statistic, then the picture
    with its text alternative and its longer description; its counts are the summary's (review r27f, item 2)."""
    fig = claim_figure(text)
    tables = parse(text)
    edge = at_noise_edge(own_intervals(tables), tables) + [
        f"{cell} (hollow)" for cell in at_noise_edge(own_intervals(tables, checker_scope.SLOW), tables)
    ]
    lead = (  # review r28f, item 1: the title over the plot, the caption under it, so the figure fits one screen
        "**Figure 1: the paper's claim, as the verdict reads it**: the accurate `strong` network inside Algorithm 1, "
        "each query's total time with prediction over its own time without."
    )
    caption = (
        "Each point is the median of those ratios over 100 queries a scenario (the same for each sampler); the "
        "whisker spans their middle half. *Shape and colour = verdict, fill = checker*: filled, our compiled "
        "checker; hollow, python-fcl on both sides. The shaded band holds the ties, above 0.90 and below 1.10; a "
        "median of 0.90 or less is a saving, 1.10 or more a cost. The summary above counts the points."
    )
    edge_said = (
        f" Cells that read as costs or savings but lie within {NOISE_EDGE * reach_of(tables):.2f} of 1 (twice "
        f"that reach) are at the noise edge: {', '.join(edge)}."
        if edge
        else ""
    )
    described = alt.details_html(alt.details(fig)).strip()
    picture = f"![{html.escape(alt.alt_text(fig))}]({CLAIM_FIGURE.name})"
    return f"{lead}\n\n{picture}\n\n{caption}\n\n{noise_line(tables)}{edge_said}\n\n{described}"


def means_not_verdict(tables: Tables) -> str:
    """Over Figure 2: its points are means, while the page's verdict on the paper's claim reads each query's own ratio
    (:func:`accurate_in_algorithm_1`); the `strong` cell where the two statistics lie furthest apart shows it."""
    medians = recorded.query_ratios(recorded.ALGORITHM_1, tables)
    cells = [
        (NAMES.get(s, s), sampler, 1 - saved, medians[s][sampler])
        for s in medians
        for sampler, saved in recorded.improvements(recorded.ALGORITHM_1, s, recorded=tables).items()
    ]
    name, sampler, mean, median = max(cells, key=lambda c: abs(math.log(c[2] / c[3])))
    return (
        " Figures 2 and 3 show means, Table 3's statistic; the verdict on the paper's claim reads each query's own "
        f"ratio (Figure 1): the `strong` network's {name} {sampler}, for one, is {mean:.2f} by means here and "
        f"{median:.2f} by its median query there."
    )


def figure_markdown(text: str, kind: str = "total") -> str:
    """The figure of ``kind`` as the page ``text`` shows it: a line that names it, the picture with its text
    alternative and its longer description under it, then a small table that counts each series' points by the tie
    rule."""
    fig = table3_figure(text, kind)
    counts: dict[str, list[str]] = {}
    for series in ratios(text, kind).values():
        for name, by_sampler in series.items():
            counts.setdefault(name, []).extend(change(r) for r in by_sampler.values())
    rows = [
        f"| {name} | {len(words)} | {words.count('less time')} | {words.count('about the same time')} "
        f"| {words.count('more time')} |"
        for name, words in counts.items()
    ]
    head = f"| {kind} time | cells | saved 10 % or more | tied | lost 10 % or more |\n| --- | --- | --- | --- | --- |"
    described = alt.details_html(alt.details(fig)).strip()
    shown = f"![{html.escape(alt.alt_text(fig))}]({FIGURES[kind].name})\n\n{described}"
    floor = noise(parse(text))
    said = (
        f"*{kind.capitalize()} time*, Table 3's cells counted with the 10 % rule (0.90 or less: saved; 1.10 or "
        f"more: lost). Timing alone moved a ratio of means to {floor.means[0]:.2f}–{floor.means[1]:.2f}, wider than "
        "the band: read a row's counts together, never one cell."
    )
    lead = LEADS[kind] + (means_not_verdict(parse(text)) if kind == "total" else "")
    return f"{lead}\n\n{shown}\n\n{said}\n\n{head}\n" + "\n".join(rows)


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
