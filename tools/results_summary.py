"""The summary at the top of ``docs/results.md`` ("In short"): its sentences written here, every number in them
computed from the tables the page prints (read as :mod:`tools.recorded_results` reads them)::

    python -m tools.results_summary        # after editing docs/results.md's tables

It rewrites the lines between :data:`BEGIN` and :data:`END` in ``docs/results.md``, the findings ("What
reproduces and what does not", :mod:`tools.results_findings`) and the three figures' text
(:mod:`tools.results_figures`), and draws the figures; ``tests/test_results_page.py`` fails while the page differs
from what the tables give, so a new run's tables cannot leave an old summary behind. Time ratios are read with the
page's rule, chapter 04's (:mod:`tools.results_words`), and single cells against the noise floor
(:mod:`tools.results_noise`). It also shows the page's wide tables in parts (:mod:`tools.results_layout`).
"""

from __future__ import annotations

import sys
from typing import NamedTuple

from toolkit.experiments.paper_numbers import IMPROVEMENT, table3_against_text
from toolkit.plots import alt
from toolkit.teaching import checker_scope, costs, findings, recorded
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
    LAZY_BEGIN,
    LAZY_END,
    causes,
    lazy_said,
    network_costs,
    not_from_sampling,
    summary,
)
from tools.results_layout import narrow
from tools.results_networks import cae_unseen, mlp_unseen, reproduces_said
from tools.results_noise import bands, noise, own_intervals
from tools.results_words import NAMES, change, counted, percent, span

BEGIN = "<!-- summary: written by `python -m tools.results_summary` from the tables below; edit it there -->"
END = "<!-- end of the summary -->"
BANDS_BEGIN = (
    "<!-- the table of bands: written by `python -m tools.results_summary` from the tables below; edit it there -->"
)
BANDS_END = "<!-- end of the table of bands -->"
COUNTS_BEGIN = "<!-- the counts: written by `python -m tools.results_summary` from the tables below; edit it there -->"
COUNTS_END = "<!-- end of the counts -->"


class Whole(NamedTuple):
    """The whole query with python-fcl on both sides, read by our 10 % tie band by means (Table 3's statistic)."""

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


# reader r54f, item 1: the question the answer answers, stated before it
QUESTION = "*The question: does screening samples with a learned collision checker make the paper's planner faster?*"
ANSWERS = {findings.HOLDS: "Yes", findings.IN_PART: "In part", findings.DOES_NOT_HOLD: "No"}


def key(tables: Tables) -> str:
    """The Key under the answer (reader r44f, item 3): the six terms the answer and its table use, one a line, each
    defined before the page leans on it. The strong network said not to be the paper's CAE+MLP, and why it is the
    fair test (its balanced accuracy, computed)."""
    balanced = [
        recorded.ours(row["Balanced unseen Acc"])
        for row in recorded.table(recorded.ALGORITHM_1, "MLP accuracy", tables).values()
    ]
    differ = table3_against_text()
    low, high = costs.floors(tables)["own"]
    entries = sum(len(row) for kinds in IMPROVEMENT.values() for row in kinds.values())
    items = (
        "*scenarios*, *samplers*: 2DS, the 2D point robot; 3DC-7 and 3DC-9, the 7- and 9-DoF box chains in 3D clutter; "
        "3DO, the 8-DoF KUKA youBot in the 3D office. The samplers: BS, OB, G and BT, the paper's Basic PRM (uniform), "
        "Obstacle-Based PRM, Gaussian and Bridge Test",
        "*Algorithm 1*: the paper's planner as we read it, a PRM that checks every candidate edge as it adds it (the "
        "*lazy PRM* checks only a candidate path's edges)",
        # reader r45f, item 5; reader r57f, lift item 2: one name per network, each defined once, here
        "*strong network*: the answer's accurate network, our `strong` preset (a preset names a network and its "
        "planner's settings). With a configuration, its MLP reads the occupancy around the robot's base cell and "
        "where its link boxes are, not the CAE's code (a `strong` CAE is trained only for Table 1). It is accurate "
        f"enough for a fair timing test: right {span(balanced)} % of the time on unseen workspaces' balanced samples "
        "(the MLP's finding, in the next section, and the last row of its table, “Tables 1 and 2 on unseen "
        "workspaces”), where the paper-recipe network is at chance. On cost, see the finding “Why, in the runs of 5 "
        "December”",
        "*paper-recipe network*: the paper's recipe, rebuilt as our `paper` preset: a CAE, which compresses a "
        "workspace's occupancy grid into a short code, and an MLP, which reads that code and a configuration and "
        "answers “valid” (collision-free) or “invalid”",
        # reader r46f, item 5: the third network the findings name, defined before they lean on it
        "*lazy-PRM network*: a second strong network, trained in the run of 3 December for the lazy PRM, where it "
        "screens samples and edges (the `strong` section)",
        "*compiled checker*, *python-fcl*: our fast exact check, and the FCL library's Python binding, a far slower "
        "one (in 2DS our exact check is numpy point checks)",
        "*3DC-9 OB*, a cell's name: the 9-DoF chain with Obstacle-Based sampling",
        "*ratio of means*: Table 3's statistic, the two modes' mean times divided, our reading of the paper "
        f"({entries - len(differ)} of its {entries} entries agree); a *ratio of medians* divides their median times",
        f"*noise band*: twice how far timing alone moved a ratio; each ratio has its own (the table of bands, in the "
        f"fold under Figure 1), the median own ratio's {low:.2f}–{high:.2f}. A cell inside it is no clear evidence",
    )
    # reader r47f, item 4: folded, so the answer stands next to Figure 1; its three terms are said under the answer
    listed = "\n".join(f"- {item}" for item in items)
    runs = "\n".join(f"- {run}" for run in RUNS)  # reader r51f, item 3: the run map folded with the terms
    return (
        '<details markdown="1"><summary>Key: every term the page uses, and the runs behind the figures</summary>'
        f"\n\n{listed}\n\n{RUNS_LEAD}\n\n{runs}\n\n</details>"
    )


RUNS_LEAD = (
    "*The runs behind the figures* (each a section under [How these results were made](#how-these-results-were-made)):"
)
RUNS = (  # reader r50f, item 5: which network and checker each series is, and which run
    "Figure 1, filled points: the strong network inside Algorithm 1, our compiled checker on both sides, the run of "
    "5 December (`strong --planner paper`), which also timed Algorithm 1 twice for the noise bands.",
    "Figure 1, hollow points: the same network, python-fcl on both sides, a second run of 5 December (`strong "
    "--planner paper --baseline paper-fcl-alike`).",
    "Figures 2 and 3, and Tables 1 and 2, add the paper-recipe network, the run of 2 December (`paper`); the lazy-PRM "
    "finding reads the lazy-PRM network, the run of 3 December (`strong`).",
)


def short(tables: Tables) -> str:
    """The summary's Markdown, without its markers (reader r57f, lift item 1): the question, then three plain
    sentences with no term the page has not yet defined (:func:`answer`), then the visible box "How to read the
    ratios" (:func:`ratios_box`, lift item 2), then the Key folded (:func:`key`). The counts table and the table of
    bands are a fold under Figure 1 (:func:`counted_said`); the arithmetic, the findings' (:func:`table_3_said`)."""
    return f"{QUESTION}\n\n{answer(tables)}\n\n{ratios_box(tables)}\n\n{key(tables)}"


def answer(tables: Tables) -> str:
    """Reader r57f, lift item 1; reader r59f, lift items 1-2: three short lines. (a) The verdict, each checker's count
    of settings faster by each query's own ratio and how many clearly (beyond that ratio's noise band); (b) why: the
    network's cost in fast exact checks, so sampling got no cheaper in 3D, the larger slowdowns after sampling, and
    sampling's largest share of a query with the slow checker; (c) the paper's own recipe against the trivial
    answers. Reader r60f, item 1: (a) says what the strong network is where it first names it, before (b) reads its
    cost. Every number computed; the borrowed band is Figure 1's caption's."""
    ratios = recorded.query_ratios(recorded.ALGORITHM_1, tables)
    band = costs.floors(tables)["own"]
    said = {}
    for name, run in OWN_RUNS.items():
        medians = [m for _, m in own_medians(tables, run)]
        fast = sum(change(m) == "less time" for m in medians)
        clear = sum(change(m) == "less time" and not costs.inside(m, band) for m in medians)
        of = f"{fast} of {len(medians)}" if fast else f"none of the {len(medians)} settings"
        said[name] = of + ("" if clear == fast else f" ({clear} clearly)" if clear else " (none clearly)")
    cost = network_costs(tables)
    cost_3d = span([c for s, c in cost.items() if s != "2ds"], lambda c: f"{c:.2g}")
    share = causes(tables).share
    verdict = ANSWERS[findings.claim_verdict(ratios)]
    return "\n\n".join(  # reader r59f, lift items 1-2: three short lines, verdict, why, the paper's network
        (
            f"**In short: {verdict.lower()}.** In the paper's planner, our accurate *strong network*, reading the "
            "occupancy grid round the robot (not the paper's CAE+MLP), made "
            f"{said['compiled']} faster with our fast exact checker, and "
            f"{said['python-fcl']} with the slow python-fcl checker.",
            f"**Why:** one network answer costs as much as {cost_3d} fast exact checks in 3D, so sampling "
            f"{'took longer in most 3D settings' if sampling_dearer(tables) else 'saved little there'}, and the "
            f"larger slowdowns come after sampling; with the slow checker, sampling is at most {percent(share)} % of "
            "a query.",
            f"**The paper's CAE+MLP:** {tables_said(tables)}.",
        )
    )


def sampling_dearer(tables: Tables) -> bool:
    """Reader r59f, item 1; r62f-r63f: whether, with our compiled checker, most 3D cells' sampling took 10 % more
    time by means (the answer's "sampling took longer in most 3D settings"; Figure 3 draws them)."""
    said = [
        change(1 - s)
        for scenario in recorded.table(recorded.ALGORITHM_1, "time improvement", tables)
        if scenario != "2ds"
        for s in recorded.improvements(recorded.ALGORITHM_1, scenario, "sampling", recorded=tables).values()
    ]
    return 2 * said.count("more time") > len(said)


def ratios_box(tables: Tables) -> str:
    """Reader r57f, lift item 2 (common rule of wave 37): a visible box of four lines, above Figure 1, defining the
    cell, the median own ratio, the tie band and that statistic's noise band; no other band before Figure 1."""
    low, high = costs.floors(tables)["own"]
    lines = (
        "*ratio*: time with prediction / time without, for one setting, a *cell* (one scenario and one sampler, 100 "
        "queries); "
        "below 1, prediction saved time.",
        "*median own ratio*: each query is timed with and without prediction in turn; a cell's median own ratio is "
        "the median of its queries' ratios (Figure 1).",
        "*tie band*, 0.90–1.10: strictly inside it, a tie; at or below 0.90, *faster*; at or above 1.10, *slower* "
        "(our 10 % rule, not the paper's).",
        f"*noise band* of the median own ratio, {low:.2f}–{high:.2f}: a verdict inside it is no clear evidence; "
        "on its edge or beyond, *clearly* faster or slower.",
    )
    listed = "\n".join(f"    - {line}" for line in lines)
    return f'!!! note "How to read the ratios"\n\n{listed}'


def counted_said(tables: Tables) -> str:
    """The fold under Figure 1 (reader r53f, lift item 1): the table of counts (:func:`counts`) and a line under it,
    python-fcl's borrowed bands said where its counts beyond them are first given (common rule 4)."""
    borrowed = (
        ""
        if timed_twice(tables, SLOW)
        else " The python-fcl run was not timed twice: its “beyond” columns read the compiled run's bands."
    )
    dashes = (  # reader r48f, item 2: by means the result is inconclusive, the verdict rests on each query's own ratio
        "A “—”: no query's own ratio was recorded, and the paper gives no noise band. The columns by means, Table 3's "
        f"statistic, read a wider noise band (tabled below): by means, {told_apart(tables)} would lie inside that "
        f"band, so the verdict rests on each query's own ratio.{borrowed}"
    )
    return f"{counts(tables)}\n\n{dashes}"


def papers_saved(tables: Tables, key: str = SLOW) -> list[tuple[str, float, float, float]]:
    """Reader r51f, item 2 (like with like): the paper's Table 3 cells that save 10 % or more of a query's time, each
    with the paper's ratio of means, ours by means and ours by each query's own ratio in the run ``key``:
    ``[("3DC-7 BT", 0.46, 0.97, 1.02), ...]``."""
    ours = dict(own_medians(tables, key))
    means = by_means(tables, key)
    names = list(by_means(tables, SLOW))
    totals = checker_scope.slow_checker(tables).papers_totals
    if len(names) != len(totals):
        raise ValueError(f"Table 3 with python-fcl: {len(names)} cells, {len(totals)} of the paper's")
    return [
        (cell, round(1 - s, 2), means[cell], ours[cell])
        for cell, s in zip(names, totals)
        if change(1 - s) == "less time"
    ]


def table_3_said(tables: Tables) -> str:
    """Two findings (reader r51f, item 3: one statistic each): the paper's Table 3 by its own statistic (means),
    quoted exactly (common rule 1), beside the strong network's cells by means, both checkers, and in the paper's
    saving cells ours against the noise band of a ratio of means (:func:`means_said`); then the verdict on the
    total-time columns by each query's own ratio (:func:`own_said`). Joined as two bullets of the findings."""
    facts = checker_scope.slow_checker(tables)
    runs = {
        "compiled": (fast_means(tables), [1 - s for s in recorded_sampling(tables)]),
        "python-fcl": ([1 - s for s in facts.totals], [1 - s for s in facts.sampling]),
    }
    faster = {name: counted([change(r) for r in totals])[0] for name, (totals, _) in runs.items()}
    sampled = {name: counted([change(r) for r in sampling])[0] for name, (_, sampling) in runs.items()}
    far = sum(beyond_means(tables, totals)[0] for totals, _ in runs.values())
    papers = counted([change(1 - s) for s in facts.papers_totals])[0]
    some = sum(s > 0 for s in facts.papers_totals)
    papers_sampled = counted([change(1 - s) for s in facts.papers_sampling])[0]
    cells = len(facts.papers_totals)
    return (  # reader r53f, item 2: the sampling columns reproduce by count of cells; the sizes that differ named
        "**The paper's Table 3: its sampling columns reproduce with python-fcl by count of cells"
        f"{'' if sampled['python-fcl'] >= papers_sampled else ' in part'}, not with our compiled checker; by means, "
        "our total-time ratios lie mostly within timing noise.** By means, the strong network saves 10 % or more "
        f"of sampling time in {sampled['compiled']} of {cells} cells with the compiled checker and in "
        f"{sampled['python-fcl']} with python-fcl, where the paper's Table 3 does in "
        f"{'all ' + str(cells) if papers_sampled == cells else f'{papers_sampled} of {cells}'}"
        f"{smaller_sampling(tables)}. The paper's Table 3 saves 10 % or more of a query's time in {papers} of its "
        f"{cells} cells (some time in {some}); ours does in {faster['compiled']} cells with the compiled checker and "
        f"{faster['python-fcl']} with python-fcl ({far or 'none'} beyond the noise band of a ratio of means)."
        f"{means_said(tables)}"
        f"\n- {own_said(tables)}"
    )


def smaller_sampling(tables: Tables) -> str:
    """Reader r53f, item 2: the cells where python-fcl's sampling saving (by means) is smaller than the paper's, each
    with both sizes: ``"; python-fcl saves as much as the paper or more in 13 and less in 3: 2DS OB 23 % (the paper:
    57 %)"`` and the rest."""
    facts = checker_scope.slow_checker(tables)
    names = list(by_means(tables, SLOW))
    less = [
        f"{name} {round(ours * 100)} % (the paper: {round(papers * 100)} %)"
        for name, ours, papers in zip(names, facts.sampling, facts.papers_sampling)
        if round(ours * 100) < round(papers * 100)
    ]
    if not less:
        return "; python-fcl saves as much as the paper or more in every cell"
    said = ", ".join(less)
    return (
        f"; python-fcl saves as much as the paper or more in {len(names) - len(less)} and less in {len(less)}: {said}"
    )


def verdict_table(tables: Tables) -> str:
    """Reader r54f, item 3: the findings open with four lines, the paper's Tables 1 and 2 and Table 3's two halves,
    each: does it reproduce, and with which network and checker; every number computed."""
    cae_said, mlp_said = reproduces_said(tables)
    facts = checker_scope.slow_checker(tables)
    sampled = {
        "compiled": counted([change(1 - s) for s in recorded_sampling(tables)])[0],
        "python-fcl": counted([change(1 - s) for s in facts.sampling])[0],
    }
    papers_sampled = counted([change(1 - s) for s in facts.papers_sampling])[0]
    own = {name: counted([change(m) for _, m in own_medians(tables, key)])[0] for name, key in OWN_RUNS.items()}
    papers = counted([change(1 - s) for s in facts.papers_totals])[0]
    means = {  # reader r56f, item 3: ours by means too, as the paper's count in the first column
        "compiled": counted([change(1 - s) for s in recorded_totals(tables)])[0],
        "python-fcl": counted([change(1 - s) for s in facts.totals])[0],
    }
    cells = len(facts.papers_totals)
    rows = (  # reader r55f, item 3: one statistic per cell; the paper's by-means counts in the first column
        ("Table 1, the CAE", cae_said, "paper-recipe network; no planner"),
        ("Table 2, the MLP", mlp_said, "paper-recipe network (the strong network's MLP is accurate); no planner"),
        (
            f"Table 3, sampling time (the paper: {papers_sampled} of {cells} cells save 10 % or more, by means as we "
            "read it)",
            f"{'yes' if sampled['python-fcl'] >= papers_sampled else 'in part'}, by count of cells, with python-fcl: "
            f"{sampled['python-fcl']} of {cells} save 10 % or more by means; no with our compiled checker "
            f"({sampled['compiled']} of {cells})",
            "strong network inside Algorithm 1; each checker on both sides",
        ),
        (
            f"Table 3, total time (the paper: {papers} of {cells} cells save 10 % or more, by means as we read it)",
            f"no: by means, {means['compiled']} of {cells} cells save 10 % or more with our compiled checker, "
            f"{means['python-fcl']} with python-fcl; by each query's own ratio, {own['compiled']} of {cells} cells "
            f"faster with our compiled checker, {own['python-fcl']} with python-fcl",
            "strong network inside Algorithm 1; each checker on both sides",
        ),
    )
    lines = [
        "| the paper's table | reproduces? | with which network and checker |",
        "| --- | --- | --- |",
        *(f"| {name} | {said} | {network} |" for name, said, network in rows),
    ]
    return "\n" + "\n".join(lines)  # a blank line after the marker, so the table is a table


def told_apart(tables: Tables) -> str:
    """Reader r54f, item 2; reader r55f, item 2 (the paper's numbers are not read against our noise): savings the
    size of which of the paper's Table 3 savings (10 % or more) would lie inside our noise band of a ratio of means,
    ``"savings the size of most of Table 3's (all but 3DC-7 BT's 54 %)"``, the others named with their saving."""
    band = noise(tables).means
    found = papers_saved(tables)
    far = [f"{cell}'s {round((1 - paper) * 100)} %" for cell, paper, _, _ in found if not costs.inside(paper, band)]
    if not far:
        return "savings the size of Table 3's"
    if len(far) == len(found):
        return "savings smaller than Table 3's"  # every one of the paper's lies beyond the band
    most = "most of" if 2 * len(far) < len(found) else "some of"
    return f"savings the size of {most} Table 3's (all but {' and '.join(far)})"


def means_said(tables: Tables) -> str:
    """Reader r51f, item 2: like with like, by means. In the cells where the paper saves 10 % or more, how many of
    our ratios of means lie inside the noise band of a ratio of means, each checker, and those beyond it named."""
    low, high = noise(tables).means
    saved = {name: papers_saved(tables, key) for name, key in OWN_RUNS.items()}
    inside = {name: sum(costs.inside(m, (low, high)) for _, _, m, _ in found) for name, found in saved.items()}
    cells = len(saved["compiled"])
    outside = {
        name: [f"{c} {m:.2f}" for c, _, m, _ in found if not costs.inside(m, (low, high))]
        for name, found in saved.items()
    }
    beyond = "".join(
        f"; the {name} checker's other {len(found)} {'is a cost' if len(found) == 1 else 'are costs'} beyond it "
        f"({', '.join(found)})"
        for name, found in outside.items()
        if found and all(float(f.rsplit(" ", 1)[1]) > 1 for f in found)
    )
    return (
        f" In the {cells} cells where the paper saves 10 % or more, our ratio of means lies inside that band, "
        f"{low:.2f}–{high:.2f}, in {inside['compiled']} with the compiled checker and {inside['python-fcl']} with "
        f"python-fcl{beyond}. By means, {told_apart(tables)} would lie inside that band of our runs."
    )


def own_said(tables: Tables) -> str:
    """Reader r51f, item 2: like with like, by each query's own ratio: in the cells where the paper saves 10 % or
    more, how many of ours are faster too, each checker, counted in the bold claim (reader r60f, item 2: "none"
    where none, not "not observed in most cells"), and which of ours save there."""
    saved = {name: papers_saved(tables, key) for name, key in OWN_RUNS.items()}
    cells = len(saved["compiled"])
    also = {name: [f"{c} {o:.2f}" for c, _, _, o in found if change(o) == "less time"] for name, found in saved.items()}
    own = {name: counted([change(m) for _, m in own_medians(tables, key)])[0] for name, key in OWN_RUNS.items()}
    kept = {name: str(len(found)) if found else "none" for name, found in also.items()}
    lead = (
        f"**By each query's own ratio, of the {cells} cells where the paper saves 10 % or more of total time, ours is "
        f"faster in {kept['compiled']} with the compiled checker and {kept['python-fcl']} with python-fcl.** Of all "
        f"{len(own_medians(tables, recorded.ALGORITHM_1))} (Figure 1): {own['compiled'] or 'none'} faster with the "
        f"compiled checker, {own['python-fcl'] or 'none'} with python-fcl."
    )
    band = costs.floors(tables)["own"]  # the count beyond it said with the count (the page's one rule)
    rest = "".join(
        f" {WHOSE[name]} {len(found)} in the paper's cells: {' and '.join(found)} "
        f"({sum(not costs.inside(float(f.rsplit(' ', 1)[1]), band) for f in found)} beyond the noise band)."
        for name, found in also.items()
        if found
    )
    return f"{lead}{rest}"


OWN_RUNS = {"compiled": recorded.ALGORITHM_1, "python-fcl": SLOW}
WHOSE = {"compiled": "The compiled checker's", "python-fcl": "python-fcl's"}


def recorded_sampling(tables: Tables) -> list[float]:
    """Table 3's sampling improvements of the strong network inside Algorithm 1, our compiled checker."""
    return [
        saved
        for scenario in recorded.table(recorded.ALGORITHM_1, "time improvement", tables)
        for saved in recorded.improvements(recorded.ALGORITHM_1, scenario, "sampling", recorded=tables).values()
    ]


def recorded_totals(tables: Tables) -> list[float]:
    """Table 3's total-time improvements of the strong network inside Algorithm 1, our compiled checker."""
    return [
        saved
        for scenario in recorded.table(recorded.ALGORITHM_1, "time improvement", tables)
        for saved in recorded.improvements(recorded.ALGORITHM_1, scenario, "total", recorded=tables).values()
    ]


def tally(
    tied: int, far: int, verb: str, cells: int | None = None, named: list[str] | None = None, band: str = ""
) -> str:
    """ONE RULE of issue #45 (reader r42f, contradiction 1): a count read against the tie band, then how many of those
    lie beyond the noise band: ``"9 of 16 cells slower (5 beyond the noise band)"``; ``"none slower"`` where none.
    ``named``: those beyond it, each with its ratio (reader r45f, item 1), after the count; ``band``: words after
    "the noise band" (reader r47f, item 3: a borrowed one said so)."""
    if not tied:
        return f"none {verb}"
    of = f" of {cells} cells" if cells is not None else ""
    them = f": {(', and ' if any(',' in n for n in named) else ' and ').join(named)}" if named else ""
    return f"{tied}{of} {verb} ({far} beyond the noise band{band}{them})"


def by_means(tables: Tables, key: str) -> dict[str, float]:
    """Table 3's whole-query ratios of means of the run ``key``: ``{"3DC-9 OB": 0.72, ...}``."""
    return {
        f"{NAMES.get(s, s)} {sampler}": round(1 - saved, 2)
        for s in recorded.table(key, "time improvement", tables)
        for sampler, saved in recorded.improvements(key, s, recorded=tables).items()
    }


def beyond_means(tables: Tables, ratios: list[float]) -> tuple[int, int]:
    """Reader r41f, item 9: of ``ratios`` (ratios of means), the savings and costs beyond the noise band of a ratio of
    means (:func:`tools.results_noise.noise`)."""
    band = noise(tables).means  # read strictly (reader r44f, item 8): on an edge counts as beyond it
    far = [r for r in ratios if not costs.inside(r, band) and change(r) != "about the same time"]
    return sum(r < 1 for r in far), sum(r > 1 for r in far)


def timed_twice(tables: Tables, key: str) -> bool:
    """Whether the run ``key`` holds its own table "timed twice" (else its noise band is borrowed)."""
    return any("timed twice" in heading for heading in tables[key])


def fast_means(tables: Tables) -> list[float]:
    """Table 3's whole-query ratios of means of the strong network inside Algorithm 1, our compiled checker."""
    return [
        1 - saved
        for scenario in recorded.table(recorded.ALGORITHM_1, "time improvement", tables)
        for saved in recorded.improvements(recorded.ALGORITHM_1, scenario, recorded=tables).values()
    ]


def tables_said(tables: Tables) -> str:
    """The answer's last sentence: whether our rebuild of the paper's Tables 1 and 2 beats a trivial answer on unseen
    workspaces (reader r48f, item 3: the ranges, each beside the paper's, are the findings')."""
    gain = cae_unseen(tables)[2]
    blind, always, _ = mlp_unseen(tables)
    trivial = round(gain * 100) <= 0 and all(round(b, 2) <= round(a, 2) for b, a in zip(blind, always))
    if not trivial:
        return "on unseen workspaces, our rebuild reproduces the paper's Tables 1 and 2 in part"
    # reader r57f, lift item 1 c: the paper's CAE+MLP against the trivial answers, and its one name on the page
    return (
        "rebuilt as our *paper-recipe network*, it does no better on new workspaces than answering “always free” "
        "(the CAE) or “always valid” (the MLP)"
    )


def own_medians(tables: Tables, key: str) -> list[tuple[str, float]]:
    """The medians of each query's own ratio of the run ``key``: ``[("3DC-9 OB", 0.79), ...]``."""
    return [(f"{s} {sampler}", m) for s, by in own_intervals(tables, key).items() for sampler, (m, _, _) in by.items()]


def counts(tables: Tables) -> str:
    """The summary's table (reader r32f, item 1): each series' cells that saved, tied and cost time, by the median of
    each query's own ratio (Figure 1, the verdict's statistic), those of them beyond the noise edge, and by means
    (Table 3's statistic, Figure 2), the paper's by means alone."""
    facts = checker_scope.slow_checker(tables)
    edge = costs.noise_edge(tables)

    def row(
        name: str, own: dict[str, dict[str, tuple[float, float, float]]] | None, means: list[float], ours: bool = True
    ) -> str:
        said = "{} / {} / {}".format(*counted([change(r) for r in means]))
        far = "{} / {}".format(*beyond_means(tables, means)) if ours else "—"
        if own is None:
            return f"| {name} | {said} | {far} | — | — |"
        medians = [m for by in own.values() for m, _, _ in by.values()]
        read = counted([change(m) for m in medians])
        beyond = counted([change(m) for m in medians if abs(m - 1) >= edge])
        return f"| {name} | {said} | {far} | {read[0]} / {read[1]} / {read[2]} | {beyond[0]} / {beyond[2]} |"

    lines = [  # reader r41f, item 9: beyond the noise band by means too, every run of ours
        # reader r52f, item 3: a caption, and each "beyond" column named by its band (common rule 6: no band's
        # numbers here but the Key's, before Figure 1)
        f"*The counts*: of the {len(facts.papers_totals)} cells, how many saved, tied or cost time by each statistic, "
        "read against the tie band, and how many of those lie beyond that statistic's own noise band (the table of "
        "bands, below).",
        "",
        f"| whole query, {len(facts.papers_totals)} cells | by means: saved / tied / cost "
        "| beyond the noise band of a ratio of means: saved / cost | by own ratio: saved / tied / cost "
        "| beyond the noise band of each query's own ratio: saved / cost |",
        "| --- | --- | --- | --- | --- |",
        row("the paper (its Table 3)", None, [1 - s for s in facts.papers_totals], ours=False),
        row(  # reader r35f, item 1: the closest copy of the paper's recipe, its savings explained where they are told
            "paper-recipe network, compiled checker, 2 December (skipped work or timing noise: see below)",
            None,
            [
                1 - saved
                for s in recorded.table("paper", "time improvement", tables)
                for saved in recorded.improvements("paper", s, recorded=tables).values()
            ],
        ),
        row("strong network, compiled checker, 5 December", own_intervals(tables), fast_means(tables)),
        row(
            "strong network, python-fcl on both sides",
            own_intervals(tables, checker_scope.SLOW),
            [1 - s for s in facts.totals],
        ),
    ]
    return "\n".join(lines)


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
    text = between(
        text,
        DETAIL_BEGIN,
        DETAIL_END,
        f"{verdict_table(parse(text))}\n\n{summary(parse(text), table_3_said(parse(text)))}",
    )
    text = between(text, LAZY_BEGIN, LAZY_END, lazy_said(parse(text)))  # reader r54f, item 3: its own heading
    text = between(text, APART_BEGIN, APART_END, not_from_sampling(parse(text)))
    text = between(text, CLAIM_BEGIN, CLAIM_END, claim_markdown(text))
    text = between(text, COUNTS_BEGIN, COUNTS_END, counted_said(parse(text)))  # reader r53f, item 1: a fold
    text = between(text, BANDS_BEGIN, BANDS_END, bands(parse(text)))  # reader r46f, item 8: under Figure 1
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
