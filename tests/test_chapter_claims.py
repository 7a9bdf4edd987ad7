"""The chapters' prose says only what holds at quick and full size; what it measured, it prints (issue 37).

Fast checks on the committed notebooks (no typed run times, no sentence that a page was found to contradict, every
`toolkit.` name in the prose exists), and the checks of ``tests/chapter_claims.py`` held against crafted outputs:
they pass a chapter whose sentences agree with its tables and fail one whose sentences do not. The executed
chapters themselves are checked where the site's build runs them (``tests/test_site.py``).
"""

from __future__ import annotations

import dataclasses
import importlib
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import chapter_claims
import numpy as np
import pytest
from chapter_claims import problems

from toolkit.experiments import paper_numbers
from toolkit.learning import metrics
from toolkit.teaching import (
    chapter04,
    chapter04_paper,
    chapter05,
    chapter05_accuracy,
    checker_scope,
    costs,
    findings,
    recorded,
)

ROOT = Path(__file__).resolve().parents[1]
CHAPTERS = sorted((ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))
SAMPLERS = ("BS", "OB", "G", "BT")
SCENARIOS_4 = (("2DS", "2ds"), ("3DC-7", "3dc7"), ("3DC-9", "3dc9"), ("3DO", "3do"))
CH03, CH04 = "03_mlp_decision_boundaries.ipynb", "04_prm_with_and_without_prediction.ipynb"


def markdown_of(path: Path) -> str:
    cells = json.loads(path.read_text())["cells"]
    return "\n\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "markdown")


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.stem)
def test_no_chapter_types_a_run_time(path):
    """Run times are printed by the cells that take them (or read from docs/benchmarks.md), never typed."""
    typed = re.findall(r"[^\n]{0,40}\b\d+(?:[.,]\d+)? ?(?:s|seconds?|minutes?)\b", markdown_of(path))
    assert not typed, f"{path.name} types run times: {typed}"


CONTRADICTED = (  # sentences that executed pages contradicted (issue 37), in the words they used
    "are the taller",
    "in means and medians",
    "at a few hundred blocks",
    "chains of about the paper's longest",
    "batches of thousands",
    "the second ratio, above 1",
    "the one that makes prediction pay",
    "tens of thousands of configurations",
    "the grey line",
    "in proportion to how many cells",
    "compare the counts in the two titles",
    "86–87 %",
    "brighter towards the region's corners",
    "threshold of about 0.4",
    "breathe the same way",
    "most of the time goes into drawing figures",
    "an order of magnitude or more faster than FCL",
    "bars look equally wide at every yaw",
    "Now a column of cells is partly covered",
    "Ours is the last column",
    "All three error terms fall to a few tens",
    "The further below it a CAE stays",
    "the triangles 500 unseen ones",
    "Two directions hold under half",
    "About 88 % of the cells are free",
    "with 20× the labelled data",
    "is close to the table's median ratio, not equal to it",  # issue 45: opposite sides of 1 in a quick run
    "exactly — costs about the same in both modes",  # the bars showed connection and query taller with prediction
    "almost all inside the grown blocks",  # 4 of 9 in a quick run
    "every curve is piecewise straight, with kinks at the nodes",  # the sampled frames cut the kinks short
    "the sky-blue trace of its base",
    "are about three 3D scenarios",  # Tables 2 and 3 include 2DS
    "over a few queries its range is wide",  # it printed 0.88-0.90
    "So they are close",  # issue 45, review r3b: the table said "network dearer (2.42)"
    "close to the network per configuration",
    "costs about what a network call costs",
    "its cost hardly grows with the triangles",  # the mesh rows grew 0.63 to 1.7 us
    "saves time almost everywhere",  # the paper's 3DC-7 totals 1.02 and 1.09
    "that share moves from run to run",
    "no PyTorch needed",
    "4.4 units",  # the slider's default is computed: 10 % of the diagonal
    "a quick run's few queries may show",  # on a full-size page
    "even where the model doubts it",  # the model called no frame colliding
    "tens of times more through python-fcl than",  # issue 45, review r7b: in 2D it printed 218x
    "a few times to tens of times faster",  # the ratios it printed were 22-34x
    "costs about as much per configuration as the compiled one",  # chapter 04 measured 2.25x and 18x dearer
    "orientation and joints matter everywhere",  # the chain9 slice was free over most of joint2's range
    "identical unit cubes",  # the paper says "same shape and size", never "unit"
    "rebuild the 2DS (2D simple) rows",  # chapter 03 rebuilds only Table 2's unseen columns
    "Its CAE memorizes its training grids",  # the `paper` preset's CAE: 89.2 % seen, "all free" 88.6 %
    "drawn as the paper draws its unseen test",  # a reading, and the paper's own rates imply 60 % valid
    "The task itself is learnable: our `strong` preset",  # its MLP does not read z
    "furniture types (desks, shelves",  # the paper names no furniture: "small box, big box, .."
    "against the best exact planner here, on 3DC-7, with no sampler.",  # chapter 05's closing, a fragment
    # issue 45, review r8b:
    "The time per call grows only from about a hundred",  # 12.6, 15.2, 23.4 µs at 1, 10, 100
    "Keep the 3D ratio in mind",  # which ratio?
    "as after a short training (quick mode)",  # full size: 1.07 decoded cells at 1 flip, above the copy line
    "The same holds for all three λ",  # λ = 0.961 scored unseen 88.1 % against "all free" 87.6 %
    "the unseen codes crowd",  # both groups' centres near the middle, the same range
    "however long it trains",  # two lengths measured
    "their blocks look like blocks of **training**",  # decoded unseen 1 was speckle
    "optimizer, with weight decay)",  # train_cae passes no weight decay
    "(Adam with weight decay)",
    "the share of collisions the network spares the exact checker",  # Algorithm 1 checks kept nodes neither
    "a smooth ramp",  # P 0.46-0.50 in 12 of 16 regions
    "faint pattern of grey dots",  # not visible at page size
    "costs time (a repair)",  # "repairs: 0": the node was a dead end
    "where its P(valid) is highest",  # the cross sat in a region of mean P 0.54, the highest 0.71
    "count the MLP's dangerous",  # the `strong` model, not the paper's MLP
    # issue 45, review r13a:
    "and on 2DS no sampler saved time.",  # which network? The `paper` preset's medians saved with BT (0.88)
    "the recorded 100 queries of `docs/results.md`, section 6's figure, have",  # its `paper` panel saved sampling
    "the median of the queries' own ratios, time with / time without.",  # no warning: not a ratio of the bars
    # issue 45, review r17a (chapter 04):
    "roadmap sometimes never joins start and goal, with or without prediction",  # 2DS BT 100 % / 100 %
    "The paper says the same of its bridge test",  # the paper: BT "perform the worst", and BT saves most in 3DC
    "means, the paper's statistic,",  # the paper says "Average"; means are our reading
    # issue 45, the lead's reading of r13a and r13b:
    "and on 3DC-7 for no sampler",  # awkward: "on 3DC-7 it saved time for none of the four samplers"
    "Read the last two columns",  # chapter 01's speed table, six columns, was cut at the page's width: two tables
    # issue 45, review r14b (chapter 05):
    "Algorithm 1 with the model screening",  # the lazy PRM is ours; Algorithm 1 is the paper's eager PRM
    "- Algorithm 1 stays safe because",  # said of the path the lazy PRM found
    "the paper's four samplers keep only valid samples",  # §IV-A: S is drawn "regardless of their validity"
    "and repair it when a node or edge fails",  # the paper only verifies the path; the repair is ours
    # issue 45, reader r19c (chapter 05):
    "both verify a path exactly",  # the paper: "the path is extracted and verified", no checker named
    "(unit cubes here)",  # the paper gives no size; the reader took "unit" for the paper's
    "A mark far from the camera is drawn larger than a near one",  # a far mark is grown to 9 px, not larger
    "arm are six boxes",  # six boxes: the platform, a turret and four arm links
    "pokes through a wall counts",  # no wall in view: the office's collisions are counted by kind instead
    "We read that as Table 2's unseen test",  # Table 2's own rates imply a set 42 % valid, uniform gives 76 %
    # issue 45, reader r27e (chapter 05):
    "a planner trusting the model alone would have lost an edge there",  # the lazy PRM trusts it and kept the edge
    "Only the sampling stage depends on the checker",  # a query's total time depends on it too
    "The panel on the right has five folders",  # six: "The scene in words" too (toolkit.viewer.panel)
    "those diamonds line the region's black outline",  # the still draws no black outline
)


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.stem)
def test_no_chapter_repeats_a_sentence_its_page_contradicted(path):
    text = " ".join(markdown_of(path).split())
    assert not [s for s in CONTRADICTED if s in text], path.name


def resolves(dotted: str) -> bool:
    """Whether ``toolkit.a.b.C.d`` names a module, or an attribute chain of the longest module prefix."""
    parts = dotted.split(".")
    for cut in range(len(parts), 0, -1):
        try:
            found = importlib.import_module(".".join(parts[:cut]))
        except ImportError:
            continue
        for name in parts[cut:]:
            if not hasattr(found, name):
                return False
            found = getattr(found, name)
        return True
    return False


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.stem)
def test_every_toolkit_name_in_the_prose_exists(path):
    names = set(re.findall(r"`(toolkit(?:\.\w+)+)", markdown_of(path)))
    assert names, f"{path.name} names no library code"
    assert not [n for n in sorted(names) if not resolves(n)], path.name


def test_resolves_tells_a_missing_name():
    assert resolves("toolkit.scenarios.Scenario.workspaces") and resolves("toolkit.teaching.findings")
    assert not resolves("toolkit.scenario.workspaces") and not resolves("toolkit.scenarios.Scenario.no_such")


# ---- the executed-chapter checks, on crafted outputs ----


def executed(*printed: str | tuple[str, ...]) -> dict:
    """A notebook whose code cells printed ``printed`` (one cell each, a tuple for several outputs of one cell;
    ``MD:`` starts displayed Markdown)."""

    def output(text):
        if text.startswith("MD:"):
            return {"output_type": "display_data", "data": {"text/markdown": text[3:]}, "metadata": {}}
        return {"output_type": "stream", "name": "stdout", "text": text}

    return {
        "cells": [
            {"cell_type": "code", "source": [], "outputs": [output(t) for t in (p if isinstance(p, tuple) else (p,))]}
            for p in printed
        ]
    }


def row(without: list[float], with_: list[float]) -> dict:
    def summary(totals):
        return {"n_queries": len(totals), "total_s_median": float(np.median(totals)), "total_s_per_query": totals}

    return {"without": summary(without), "with": summary(with_)}


NAMES = {key: name for name, key in SCENARIOS_4}
CLAIM_STATUS = findings.claim_status(  # the paper's claim from the recorded runs, as the chapter states it
    {NAMES[key]: ratios for key, ratios in recorded.query_ratios(recorded.ALGORITHM_1).items()},
    {NAMES[key]: recorded.median_ratios("strong")[key]["total"] for key in ("2ds", "3dc7")},
)  # the noise edge's count is section 6's line's (chapter04.edge_line), not this sentence's

SLOW = checker_scope.slow_sentence(
    checker_scope.slow_checker(), ranges=False
)  # python-fcl on both sides, as the chapter prints it


def slow_unsaid(facts: checker_scope.SlowChecker) -> list[str]:
    """The checks of the prose on python-fcl on both sides, where the prose is missing, for the record ``facts``: none
    (review r28d: the numbers stand in the first code cell's bullets; the prose must not contradict them)."""
    return []


SLOW_UNSAID = slow_unsaid(checker_scope.slow_checker())


ACROSS_SAID = f"\n\n{findings.ACROSS} marks no clear evidence: {findings.ACROSS_REASON}."


def chapter_04() -> dict:
    """A chapter 04 whose tables carry the verdicts their numbers give."""
    planning = {
        name: {"BS": row([1, 1, 1], [2, 2, 2.5]), "OB": row([1, 1, 1], [0.5, 0.6, 1.4])} for name in ("2DS", "3DC-7")
    }
    sweep = {"label": "links", "values": [2, 4], "exact_us": [0.3, 0.4], "fcl_us": [3.0, 4.0], "learned_us": [1, 0.5]}
    rates = {"ratio": 0.4, "exact_cfg_per_s": 5e6, "fcl_cfg_per_s": 2e5, "learned_cfg_per_s": 2e6}
    crossed = {"variables": {"links": sweep}}
    nb = executed(
        (
            "MD:" + chapter04.answer(),  # the answer in two sentences, one statistic (reader r40d)
            "MD:" + findings.planning_table(planning) + ACROSS_SAID,  # section 3: its † said under it (reader r45d)
            "MD:" + chapter04.full_answer(),  # ... in full, as section 6 folds it
            "MD:" + chapter04.mark_line(),  # beside the answer figure: the page's one mark and its noise bands
            "MD:" + chapter04.by_means(),  # section 6, beside the means figure: the counts by means
            "MD:" + chapter04.edge_line(),  # section 6: what to take from its table
            "MD:" + chapter04_paper.why(),  # under the answer figure: where the why is measured, what stays open
        ),
        "MD:" + costs.throughput_table({"2DS": rates, "3DC-7": rates}, 10_000),
        (
            "MD:"
            + findings.crossover_table(crossed, tie=costs.CLOSE)
            + "\n\n"
            + findings.crossover_counts(crossed, tie=costs.CLOSE),
            "MD:" + costs.cost_table(),  # section 6: where the recorded costs' extra time went
        ),
        eager_counts(),
        recorded_ratios(),
        "MD:" + paper_mlp(),
        "MD:This run took 49 s from the first cell to this one, at a load average of 2.1 on 2 cores.",
    )
    nb["cells"].insert(-1, {"cell_type": "markdown", "source": PROSE_04})  # the chapter's own prose, as written
    return nb


PROSE_04 = markdown_of(ROOT / "notebooks" / CH04)  # its opening first


def recorded_ratios(
    paper_3dc7: dict[str, float] | None = None, paper_2ds: dict[str, float] | None = None
) -> tuple[str, str]:
    """Section 6's two tables of recorded ratios as the chapter builds them from docs/results.md and the paper's
    Table 3 (``paper_3dc7``, ``paper_2ds``: other ratios for the `paper` preset's means in that scenario)."""

    def means(preset, key):
        return {s: 1 - r for s, r in recorded.improvements(preset, key).items()}

    eager, lazy = {}, {}
    accurate = recorded.query_ratios(recorded.ALGORITHM_1)
    slow_own = recorded.query_ratios(checker_scope.SLOW)
    for name, key in SCENARIOS_4:
        eager[f"{name}, the paper's Table 3"] = {s: 1 - paper_numbers.IMPROVEMENT[key]["total"][s] for s in SAMPLERS}
        eager[f"{name}, ours (`paper` preset)"] = means("paper", key)
        if key in accurate:
            eager[f"{name}, ours (`strong` preset), means"] = means(recorded.ALGORITHM_1, key)
            eager[f"{name}, ours (`strong` preset), medians"] = accurate[key]
        if key in slow_own:
            eager[f"{name}, ours (`strong`, python-fcl), means"] = means(checker_scope.SLOW, key)
            eager[f"{name}, ours (`strong`, python-fcl), medians"] = slow_own[key]
    for name, key in SCENARIOS_4[:2]:
        lazy[f"{name}, `paper` preset, ratio of medians"] = recorded.median_ratios("paper")[key]["total"]
        lazy[f"{name}, `strong` preset, means"] = means("strong", key)
        lazy[f"{name}, `strong` preset, ratio of medians"] = recorded.median_ratios("strong")[key]["total"]
    if paper_3dc7 is not None:
        eager["3DC-7, ours (`paper` preset)"] = paper_3dc7
    if paper_2ds is not None:
        eager["2DS, ours (`paper` preset)"] = paper_2ds
    eager_table, lazy_table = (  # our verdicts inside timing's own reach marked, as section 6 prints them
        "MD:" + costs.marked(findings.ratio_table(rows, counts=True, narrow=True)) for rows in (eager, lazy)
    )
    return eager_table, lazy_table


def paper_mlp() -> str:
    """Section 6's table of what the `paper` preset's MLP answers on unseen workspaces (docs/results.md, Table 2)."""
    table = recorded.table("paper", "MLP accuracy")
    rates = {name: [recorded.ours(table[key][f"Unseen {r}"]) for r in ("TPR", "TNR")] for name, key in SCENARIOS_4}
    rows = [f"| {name} | {metrics.what_it_answers(*rate)} |" for name, rate in rates.items()]
    return "| scenario | what it answers |\n| --- | --- |\n" + "\n".join(rows)


EAGER_RECORDS = {  # section 5's records as chapter04.counted gives them, a query each (a quick run's numbers)
    mode: [dict(nodes=n, samples_exact=e, predicted_checks=p, edge_checks=c, node_checks=e + p)]
    for mode, n, e, p, c in (("without", 308, 400, 0, 157_612), ("with", 305, 0, 400, 135_922))
}


def eager_counts(with_samples: str = "0", with_connection: str = "122.7") -> tuple[str, ...]:
    """Section 5's tables: Algorithm 1's checks with the line that reads them, then its stages' times, as the chapter
    prints them (a quick run's numbers)."""
    return (
        "MD:| mode | roadmap nodes | samples, exact | samples, network | edge points, exact |\n| --- |"
        + " ---: |" * 4
        + f"\n| without | 308 | 400 | 0 | 157,612 |\n| with | 305 | {with_samples} | 400 | 135,922 |\n\n"
        + chapter04.roadmap_line(EAGER_RECORDS),
        "MD:| stage, ms a query | without | with |\n| --- | ---: | ---: |\n| sampling | 0.2 | 1.0 |\n"
        f"| connection (edges) | 237.6 | {with_connection} |\n| query | 14.8 | 2.9 |\n"
        "| other (encoding, set-up) | 0.2 | 8.5 |\n| total | 252.8 | 135.1 |",
    )


def test_chapter_04_passes_when_every_verdict_agrees_with_its_row():
    assert problems(CH04, chapter_04()) == []


def test_chapter_04_quotes_table_3_exactly():
    """Common47 rule 1 (reader r47d, item 1; r50d: "saves" is ours for 10 % or more): Table 3 takes less time in 13
    of 16 cells, 10 % or more less in 10; the 10 % tie band is ours, so the page never says the paper "reports 10
    of 16 faster" or counts "as the paper counts"."""
    nb = chapter_04()
    answer = nb["cells"][0]["outputs"][0]["data"]
    answer["text/markdown"] = answer["text/markdown"].replace(
        "takes less time in 13 of its 16", "takes less time in 10 of its 16"
    )
    assert problems(CH04, nb) == ["04: the answer says Table 3 takes less time in ['10'] cells; it does in 13"]
    nb = chapter_04()
    nb["cells"].insert(-1, {"cell_type": "markdown", "source": "Counted as the paper counts, Table 3 reports 10."})
    assert problems(CH04, nb) == ["04: the page quotes Table 3 loosely: ['as the paper counts', 'Table 3 reports']"]


def test_chapter_04_says_the_call_cost_moves_only_where_the_recorded_runs_part():
    """Review r28d: section 4 says the network's cost per call moved between the recorded runs only where the `strong`
    network's two recorded runs' 3DC-7 figures (docs/results.md: 1.32 and 6.90) part by more than the tie band; reader
    r37d: the figures themselves are section 6's fold. Without the sentence, the check fails."""
    nb = chapter_04()
    for cell in nb["cells"]:
        if cell["cell_type"] == "markdown":
            cell["source"] = "".join(cell["source"]).replace("The first ratio moves from run to run", "The first ratio")
    assert problems(CH04, nb) == ["04: section 4 on the recorded runs' 3DC-7 costs; the record: ('1.32', '6.90')"]


def test_chapter_04_fails_a_verdict_its_numbers_contradict():
    nb = chapter_04()
    first = nb["cells"][0]["outputs"][1]["data"]  # after the line that states section 5's verdict
    first["text/markdown"] = first["text/markdown"].replace("costs time", "saves time", 1)
    assert problems(CH04, nb) == [
        "04: 2DS BS: says 'saves time (median 2.00; middle half 2.00–2.25)', its numbers say 'costs time'"
    ]
    nb = chapter_04()
    last = nb["cells"][2]["outputs"][0]["data"]
    last["text/markdown"] = last["text/markdown"].replace("network dearer", "network cheaper", 1)
    assert problems(CH04, nb) == ["04: links 2: says 'network cheaper (3.33)', its numbers say 'network dearer'"]


def test_chapter_04_section_5_reads_its_counts_as_printed():
    """Reader r61d, item 1: section 5's sentences read counts only (a busy machine moved its live times), and the line
    under its counts gives the table's nodes and edge points."""
    nb = chapter_04()
    [data] = [o["data"] for c in nb["cells"] for o in c.get("outputs", []) if "roadmap nodes" in str(o.get("data"))]
    data["text/markdown"] = data["text/markdown"].replace("135,922 edge points", "135,923 edge points")
    assert [p[:30] for p in problems(CH04, nb)] == ["04: section 5 says ('305', '30"]


def test_chapter_04_fails_where_the_network_is_the_cheaper_check_its_prose_says_it_is_not():
    nb = chapter_04()
    rates = {"ratio": 1.5, "exact_cfg_per_s": 1e6, "fcl_cfg_per_s": 2e5, "learned_cfg_per_s": 1.5e6}
    table = costs.throughput_table({"2DS": rates, "3DC-7": rates}, 10_000, tie=findings.TIE)
    nb["cells"][1] = executed("MD:" + table)["cells"][0]
    assert problems(CH04, nb) == [
        "04: the prose says a network call costs more than the default exact check: "
        "{'2DS': 'network cheaper (0.67)', '3DC-7': 'network cheaper (0.67)'}"
    ]


def test_chapter_04_fails_without_its_tables_or_with_pre_wrapped_lines():
    nb = chapter_04()
    nb["cells"][2]["outputs"].pop(1)  # the recorded costs' split
    nb["cells"].append(
        executed("3DC-7, total time with / without prediction against the lazy exact\n    planner")["cells"][0]
    )
    assert problems(CH04, nb) == [
        "04: pre-wrapped generated lines",
        "04: section 6 does not show the recorded costs' split (costs.cost_table)",
    ]


def test_chapter_04_says_where_the_recorded_costs_went_only_as_the_record_has_it():
    """Review r25a: the recorded costs of 1.5-1.75x were never explained. Section 6 says both the sampling stage and
    the time after it grew with prediction in every cell where it cost 25 % or more; a record where the time
    after sampling fell in one such cell fails the sentence, and the cells the record has pass it."""
    nb = chapter_04()
    assert chapter_claims._dear_cells(nb) == []
    fell = [costs.Cost("3DC-7", "OB", 1.5, (0.004, 0.010), (0.034, 0.030))]  # after sampling: 30 -> 20 ms
    assert chapter_claims._dear_cells(nb, fell) == [
        f"04: the prose says '{chapter_claims.DEAR_SAID[1]}'; the record: {fell}"
    ]
    sampled = [costs.Cost("3DC-7", "OB", 1.5, (0.004, 0.010), (0.034, 0.041))]  # sampling: 6 of the extra 7 ms
    assert chapter_claims._dear_cells(nb, sampled) == [  # reader r43d, 1: the top's Why says "most" came after
        f"04: the prose says '{chapter_claims.DEAR_SAID[2]}'; the record: {sampled}"
    ]
    assert all(c.sampling[1] > c.sampling[0] and c.after_share > 0 for c in costs.dear_cells())


def test_chapter_04_fails_where_the_2ds_rows_do_not_disagree_as_its_summary_says():
    """Review r16a: the summary said the paper's 2DS row and ours "give opposite verdicts" where the bridge test is a
    tie in one and a saving in the other. It now says how they disagree; a recorded row that reads otherwise fails."""
    nb = chapter_04()
    nb["cells"][4] = executed(recorded_ratios(paper_2ds={"BS": 1.05, "OB": 1.51, "G": 1.27, "BT": 0.81}))["cells"][0]
    (said,) = problems(CH04, nb)
    assert said.startswith("04: the summary says how the paper's 2DS row and ours disagree")


def test_chapter_04_fails_where_section_6s_recorded_verdicts_contradict_its_answer():
    """The answer first: the `paper` preset saves for one sampler of four on 3DC-7 (and three on 3DC-9 and 3DO); a
    count column that disagrees with its row, or a row whose verdicts the answer does not describe, is a problem."""
    nb = chapter_04()
    cell = nb["cells"][4]["outputs"][0]["data"]
    cell["text/markdown"] = cell["text/markdown"].replace(": 1 / 2 / 1 |", ": 3 / 0 / 1 |", 1)
    assert problems(CH04, nb) == [
        "04: 3DC-7, ours (`paper` preset): counted 3 / 0 / 1, its verdicts "
        "['a tie', 'a tie', 'saves time', 'costs time']"
    ]
    nb = chapter_04()
    nb["cells"][4] = executed(recorded_ratios({"BS": 0.8, "OB": 0.8, "G": 0.8, "BT": 1.35}))["cells"][0]
    assert problems(CH04, nb) == [
        "04: the answer says the `paper` preset saves for 1 of 4 on 3DC-7; it shows "
        "['saves time', 'saves time', 'saves time', 'costs time']"
    ]
    nb = chapter_04()
    nb["cells"][5] = executed("MD:" + paper_mlp().replace('"invalid"', '"valid"'))["cells"][0]
    assert problems(CH04, nb)[0].startswith("04: the answer says what the `paper` MLP answers")


def _claim_expected() -> tuple[str | None, ...]:
    """What the first code cell must say of the paper's claim: docs/results.md's
    counts, read by hand (inside Algorithm 1 the accurate network saves in none of 16 cells, ties in 7, costs in 9;
    against the lazy PRM, on 2DS and 3DC-7, it saves in none of 8)."""
    return (findings.DOES_NOT_HOLD, "none", "16", "7", "9", None, "none", "8")  # the noise edge: edge_line's


def _in_full(expected: tuple) -> tuple:
    """Section 6's sentence on the claim: ``expected`` without the noise edge's count, which its own line gives."""
    return (*expected[:5], None, *expected[6:])


def test_chapter_04_fails_where_its_statement_of_the_papers_claim_disagrees_with_the_recorded_runs():
    """Review r15a: the paper's claim (an accurate network inside Algorithm 1) was tested on 4 queries. The first code
    cell states it from the recorded runs of 100 queries a scenario, as section 6's
    rows count them; a statement that disagrees, or a missing one, fails."""
    expected = _claim_expected()
    assert CLAIM_STATUS.startswith(
        f"Against our fast exact checker (compiled in 3D, numpy interval tests in 2DS), "
        f"the paper's claim {expected[0]} for an accurate network: inside the"
    )
    nb = chapter_04()
    full = nb["cells"][0]["outputs"][2]["data"]  # section 6's full sentences
    other = findings.HOLDS if expected[0] != findings.HOLDS else findings.DOES_NOT_HOLD
    full["text/markdown"] = full["text/markdown"].replace(f"claim {expected[0]} for", f"claim {other} for")
    assert problems(CH04, nb) == [
        f"04: the paper's claim is said to be {_in_full((other, *expected[1:]))}; section 6's tables give "
        f"{_in_full(expected)}"
    ]
    nb = chapter_04()
    full = nb["cells"][0]["outputs"][2]["data"]
    full["text/markdown"] = full["text/markdown"].replace(f"a cost in {expected[4]}", "a cost in 99")
    assert problems(CH04, nb) == [
        f"04: the paper's claim is said to be {_in_full((*expected[:4], '99', *expected[5:]))}; section 6's tables "
        f"give {_in_full(expected)}"
    ]
    nb = chapter_04()
    full = nb["cells"][0]["outputs"][2]["data"]
    full["text/markdown"] = full["text/markdown"].replace(CLAIM_STATUS, "")
    assert problems(CH04, nb) == ["04: section 6 does not state the paper's claim from the recorded runs"]


def test_chapter_04_holds_the_answers_bullet_on_our_fast_checker_to_section_6():
    """Reader r34d: the answer gives our fast checker's count by the median query (none of 16), section 6's; reader
    r40d: in two plain sentences, the costs beyond the noise band counted (9 costs, 4 inside it), the counts by means
    beside section 6's means figure. Another count, or a missing answer, fails."""
    expected = _claim_expected()
    nb = chapter_04()
    first = nb["cells"][0]["outputs"][0]["data"]
    said = first["text/markdown"]
    first["text/markdown"] = said.replace("| our fast exact checker | none |", "| our fast exact checker | 8 |")
    assert problems(CH04, nb) == [
        "04: the answer's first sentence counts [('none', '3')]; its table [('8', '3')]",  # r54d
        f"04: the first code cell's bullet on our fast checker says [('8', '16', '7', '9', '5')]; section 6's: "
        f"{expected}",
    ]
    nb = chapter_04()  # reader r39d: the count by means, the paper's statistic, in one sentence (r40d: section 6)
    means = nb["cells"][0]["outputs"][4]["data"]
    means["text/markdown"] = means["text/markdown"].replace("more in 3 cells", "more in 5 cells")
    assert problems(CH04, nb) == [
        f"04: the first code cell's bullet on our fast checker says [('none', '16', '7', '9', '5')]; section "
        f"6's: {expected}"
    ]  # reader r44d, item 1: the answer's two sentences carry no count by means; section 6's line does
    nb = chapter_04()  # reader r36d: the costs are counted in the answer too, with those beyond the noise band
    first = nb["cells"][0]["outputs"][0]["data"]
    first["text/markdown"] = first["text/markdown"].replace("| 9 (5 beyond", "| 5 (3 beyond", 1)
    assert problems(CH04, nb) == [
        f"04: the first code cell's bullet on our fast checker says [('none', '16', '7', '5', '3')]; section "
        f"6's: {expected}",
    ]
    nb = chapter_04()  # reader r50d, items 1 and 2: sampling's share of a query, in plain words, from the record
    first = nb["cells"][0]["outputs"][0]["data"]
    first["text/markdown"] = first["text/markdown"].replace("(34 % with python-fcl)", "(9 % with python-fcl)")
    assert problems(CH04, nb) == [  # reader r54d, item 3: the largest share with each checker
        "04: the answer gives sampling's share of a query as [('18', '9')]; the record: ('18', '34')"
    ]
    nb = chapter_04()  # reader r33d: the noise band is a mark on the table's verdicts, explained once
    for cell in nb["cells"]:
        for output in cell.get("outputs", []):
            said = output.get("data", {}).get("text/markdown", "")
            output.get("data", {})["text/markdown"] = said.replace("costs time\\*<br>(1.13)", "costs time<br>(1.13)")
    assert problems(CH04, nb) == [
        "04: section 6's noise edge counts our fast checker's cells as ('2', '0'); the record: ('4', '0')"
    ]
    nb = chapter_04()
    edge = nb["cells"][0]["outputs"][3]["data"]
    edge["text/markdown"] = edge["text/markdown"].replace("inside the noise band of its statistic", "near 1")
    assert problems(CH04, nb) == [
        "04: section 6's noise edge counts our fast checker's cells as ('', ''); the record: ('4', '0')",
        "04: section 6's noise edge counts python-fcl's cells as ('', ''); the record: ('0', '1')",
    ]
    nb = chapter_04()
    full = nb["cells"][0]["outputs"][2]["data"]
    full["text/markdown"] = full["text/markdown"].replace("more in 3 of the 16 cells", "more in none", 1)
    assert problems(CH04, nb) == [
        "04: section 6's fold counts our fast checker's means as []; its table: ('3', '7', '6')",
        "04: section 6's fold counts python-fcl's means as []; the record: ('2', '12', '2')",
    ]
    nb = chapter_04()
    nb["cells"][0]["outputs"].pop(0)
    said = problems(CH04, nb)
    assert said[0] == f"04: the first code cell's bullet on our fast checker says []; section 6's: {expected}"
    assert said[1].startswith(f"04: the answer on '{chapter_claims.ANSWER_NO}'; the recorded runs: ")
    nb = chapter_04()  # reader r51d, item 1: the answer's count by means, Table 3's statistic, from the record
    first = nb["cells"][0]["outputs"][0]["data"]
    first["text/markdown"] = first["text/markdown"].replace("statistic, 3 of 16 cells", "statistic, 5 of 16 cells")
    assert problems(CH04, nb) == ["04: the answer counts our fast checker by means as [('5', 'none')]; the record: 3"]


def test_chapter_04_fails_prose_that_answers_the_papers_claim_otherwise_than_the_recorded_runs():
    """The written answer says the claim's verdict once, "The answer: no.", only where the recorded runs give it,
    and the prose never says another verdict's fixed words."""
    verdict = _claim_expected()[0]
    nb = chapter_04()
    other = next(v for v in chapter_claims.PLAIN if v != verdict)
    nb["cells"][-2]["source"] += f" So {chapter_claims.PLAIN[other]}."
    assert problems(CH04, nb) == [f"04: the prose says '{chapter_claims.PLAIN[other]}'; the recorded runs: {verdict}"]
    nb = chapter_04()
    first = nb["cells"][0]["outputs"][0]["data"]
    first["text/markdown"] = first["text/markdown"].replace("**No.**", "**Rarely.**")
    assert problems(CH04, nb) == [f"04: the answer on '{chapter_claims.ANSWER_NO}'; the recorded runs: {verdict}"]


def test_claim_status_reads_the_accurate_network_inside_algorithm_1():
    lazy = {"2DS": {"BS": 0.85, "OB": 1.0}, "3DC-7": {"BS": 2.0, "OB": 0.9}}  # 0.90 saves 10 %: it counts
    some = findings.claim_status({"2DS": {"BS": 0.8, "OB": 1.05}, "3DC-9": {"BS": 1.5, "OB": 1.2}}, lazy)
    assert some == (
        "Against our fast exact checker (compiled in 3D, numpy interval tests in 2DS), the paper's claim holds here "
        "only in part for an accurate network: inside the paper's Algorithm 1 the median own ratio of our accurate "
        "`strong` network saved time in 1 of the 4 scenario–sampler pairs (2DS BS) (a tie in 1, a cost in 2), and "
        "against the lazy PRM (on 2DS and 3DC-7, by the median time with over the median without) in 2 of the 4 "
        "scenario–sampler pairs (2DS BS, 3DC-7 OB) "
        "(recorded runs, 100 queries a scenario)."
    )
    none = findings.claim_status({"2DS": {"BS": 0.91, "OB": 1.1}}, lazy)
    assert (
        none.startswith(
            "Against our fast exact checker (compiled in 3D, numpy interval tests in 2DS), "
            "the paper's claim does not hold here for an accurate network"
        )
        and "in none of the 2" in none
    )
    every = findings.claim_status({"2DS": {"BS": 0.9, "OB": 0.5}}, lazy)
    assert every.startswith(
        "Against our fast exact checker (compiled in 3D, numpy interval tests in 2DS), "
        "the paper's claim holds here for an"
    )
    with pytest.raises(ValueError, match="no time ratios"):
        findings.claim_verdict({})


def test_ratio_table_counts_each_rows_verdicts():
    table = findings.ratio_table({"a": {"BS": 0.5, "OB": 1.0, "G": 1.05, "BT": 1.2}}, counts=True)
    assert table.splitlines()[0].endswith(f"| {findings.COUNT_COLUMN} |")
    assert table.splitlines()[2].endswith("| costs time (1.20) | 1 / 2 / 1 |")
    assert "saves /" not in findings.ratio_table({"a": {"BS": 0.5}})  # no count unless asked
    narrow = findings.ratio_table({"a": {"BS": 0.5, "OB": 1.2}}, counts=True, narrow=True).splitlines()
    assert narrow[0] == "| measured | BS | OB |"  # five columns for four samplers fit a page's column; six do not
    assert narrow[2] == f"| a<br>{findings.COUNT_COLUMN}: 1 / 0 / 1 | saves time<br>(0.50) | costs time<br>(1.20) |"


def test_what_it_answers_reads_whole_percents():
    assert metrics.what_it_answers(1.0, 0.0) == '"valid" to every sample'
    assert metrics.what_it_answers(0.004, 0.996) == '"invalid" to every sample'
    assert metrics.what_it_answers(0.28, 0.83) == metrics.what_it_answers(0.99, 0.0) == "some of each"


def test_chapter_04_fails_where_section_5s_counts_contradict_its_prose():
    nb = chapter_04()
    nb["cells"][3] = executed(eager_counts(with_samples="9,000", with_connection="50.0"))["cells"][0]
    assert problems(CH04, nb) == [
        "04: Algorithm 1 with: the sample checks are no small fraction of the edge points",
        "04: Algorithm 1 with: edge points are not 99 % of the exact checks",
        "04: Algorithm 1 with: the stages' medians sum to 62.4, far from the total",
    ]
    nb = chapter_04()
    del nb["cells"][3:]
    assert (
        problems(CH04, nb)
        == [
            "04: section 5's counts of Algorithm 1's checks, their line or its times are not displayed once",
            "04: section 6's tables of recorded ratios, with their counts, are not displayed",
            *SLOW_UNSAID,
            "04: section 6's noise edge counts python-fcl's cells as ('0', '0'); the record: ('0', '1')",  # no table
            *(f"04: section 6 does not say '{words}'" for words in chapter_claims.DEAR_SAID[:2]),  # [2]: the top's Why
            "04: section 4 on the recorded runs' 3DC-7 costs; the record: ('1.32', '6.90')",
            "04: the run's time is not printed with its load",
        ]
    )


def test_chapter_04_names_the_network_whose_lazy_medians_it_reports():
    """Review r13a: "on 2DS no sampler saved time" beside the `paper` preset's row "saves time (0.88)" with the bridge
    test. The opening names the `strong` network for that, and the `paper` network's savers; a row that gives
    either otherwise fails."""
    nb = chapter_04()
    cell = nb["cells"][4]["outputs"][1]["data"]
    text = cell["text/markdown"].replace(": 1 / 0 / 3 |", ": 0 / 1 / 3 |", 1)
    cell["text/markdown"] = text.replace("saves time\\*<br>(0.88)", "a tie<br>(0.95)", 1)
    assert problems(CH04, nb) == [
        "04: section 6 says 'the bridge test alone' saved time (2DS, `paper` preset, ratio of medians); its row saves "
        "for []"
    ]
    nb = chapter_04()
    cell = nb["cells"][4]["outputs"][1]["data"]
    cell["text/markdown"] = cell["text/markdown"].replace(
        "ratio of medians<br>saves / tie / costs: 0 / 2 / 2 | a tie<br>(1.07)",
        "ratio of medians<br>saves / tie / costs: 1 / 1 / 2 | saves time<br>(0.70)",
    )
    stated = _claim_expected()
    counted = (
        f"04: the paper's claim is said to be {_in_full(stated)}; section 6's tables give "
        f"{_in_full((*stated[:6], '1', stated[7]))}"
    )
    assert problems(CH04, nb) == [
        "04: section 6 says 'none of the four samplers' saved time (2DS, `strong` preset, ratio of medians); its row "
        "saves for ['BS']",
        counted,  # ... and the first code cell: none of eight, lazy PRM
    ]


def test_chapter_04_holds_its_plain_answer_to_the_table_it_summarises():
    """The opening's answer against the lazy PRM, reworded for a student (issue 45: "on 3DC-7 for no sampler" read
    awkwardly), is read back and compared with section 6's second table: the range of the `strong` network's 3DC-7
    medians, and the samplers named for each network and scenario; a sentence the check cannot read fails too."""
    assert chapter_claims._named("none of the four samplers") == chapter_claims._named("no sampler") == []
    assert chapter_claims._named("the bridge test alone") == ["BT"]
    assert chapter_claims._named("the uniform and Gaussian samplers") == ["BS", "G"]
    assert chapter_claims._named("every sampler") == list(SAMPLERS)
    nb = chapter_04()
    opening = nb["cells"][-2]
    assert 'on 3DC-7 for none of the four samplers (the table "Against the lazy PRM")' in " ".join(
        opening["source"].split()
    )
    opening["source"] = opening["source"].replace("took 1.8 to 2.2 times", "took 1.5 to 2.2 times")
    assert problems(CH04, nb) == [
        "04: section 6 says 3DC-7 took 1.5 to 2.2 times as long; its medians are [2.13, 2.24, 2.14, 1.77]"
    ]
    nb = chapter_04()
    opening = nb["cells"][-2]
    opening["source"] = opening["source"].replace("on 3DC-7 for none of the four", "on 3DC-7 for the Gaussian and four")
    assert problems(CH04, nb) == [
        "04: section 6 says 'the Gaussian and four samplers' saved time (3DC-7, `paper` preset, ratio of medians); its "
        "row saves for []"
    ]
    nb = chapter_04()
    nb["cells"].pop(-2)
    assert problems(CH04, nb) == [
        "04: section 6 does not give its answer against the lazy PRM in the words the check reads",
        *SLOW_UNSAID,
        *(f"04: section 6 does not say '{words}'" for words in chapter_claims.DEAR_SAID[:2]),  # [2]: the top's Why
        "04: section 4 on the recorded runs' 3DC-7 costs; the record: ('1.32', '6.90')",
    ]


def test_chapter_04_holds_section_3s_sampling_sentence_to_the_recorded_runs(monkeypatch):
    """Review r13a: "the recorded 100 queries ... no faster for any sampler" while the `paper` panel saved sampling
    time. The sentence now speaks of each run apart; recorded figures that would contradict either half fail."""
    strong, medians = recorded.median_ratios("strong"), recorded.median_ratios
    faster = {**strong, "2ds": {**strong["2ds"], "sampling": {**strong["2ds"]["sampling"], "OB": 0.8}}}
    monkeypatch.setattr(recorded, "median_ratios", lambda preset: faster if preset == "strong" else medians(preset))
    assert chapter_claims._recorded_sampling() == [
        "04: the `strong` run's sampling is faster with prediction for ['OB'] on 2ds"
    ]
    monkeypatch.undo()
    means = recorded.improvements
    monkeypatch.setattr(
        recorded,
        "improvements",
        lambda p, k, kind="total": {**means(p, k, kind), **({"G": 0.0} if p == "paper" else {})},
    )
    assert chapter_claims._recorded_sampling() == [
        "04: the `paper` run's means save sampling time for "
        "{'2ds': ['BT'], '3dc7': ['BS'], '3dc9': ['OB'], '3do': []}, not as the prose says"
    ]
    monkeypatch.undo()  # reader r54d, item 3: by means only 3DO OB's sampling saved (26 %, inside the means band)
    monkeypatch.setattr(
        recorded,
        "improvements",
        lambda p, k, kind="total": {**means(p, k, kind), **({"BT": 0.05} if p == "strong" and k == "2ds" else {})},
    )
    assert chapter_claims._recorded_sampling() == [
        "04: by means the `strong` run's sampling saves {('2ds', 'BT'): 0.05, ('3do', 'OB'): 0.26}, not 3DO OB's 26 % "
        "inside the band"
    ]


def test_chapter_04_holds_its_sampling_inside_algorithm_1_to_the_recorded_run(monkeypatch):
    """Review r16a: the chapter says the accurate network's median sampling time inside Algorithm 1 was longer in
    every cell, because the network was the dearer check in every scenario of that run; a recorded tie, or a network
    too close to tell, fails."""
    assert chapter_claims._sampling_in_algorithm_1() == []
    medians, table = recorded.median_ratios, recorded.table
    inside = medians(recorded.ALGORITHM_1)
    tied = {**inside, "3do": {**inside["3do"], "sampling": {**inside["3do"]["sampling"], "BT": 1.05}}}
    monkeypatch.setattr(recorded, "median_ratios", lambda p: tied if p == recorded.ALGORITHM_1 else medians(p))
    said, unclear = chapter_claims._sampling_in_algorithm_1()
    assert said.startswith("04: Algorithm 1's sampling with the network reads") and findings.TIES in said
    assert unclear == (  # reader r54d, item 2: "clearly in 15" holds only while 2DS BT alone is inside the band
        "04: Algorithm 1's sampling by medians is inside the noise band in {('2ds', 'BT'): 1.56, ('3do', 'BT'): 1.05}, "
        "not 2DS BT 1.56"
    )
    monkeypatch.undo()
    rates = table(recorded.ALGORITHM_1, "Checker throughput")
    close = {**rates, "3do": {**rates["3do"], "learned / exact": "0.9"}}

    def patched(preset, heading, recorded_tables=None):
        return close if preset == recorded.ALGORITHM_1 and "throughput" in heading else table(preset, heading)

    monkeypatch.setattr(recorded, "table", patched)
    (said,) = chapter_claims._sampling_in_algorithm_1()
    assert said.startswith("04: in the Algorithm 1 run the network was not the dearer check everywhere")
    monkeypatch.undo()  # review r28d: section 6 names the cells whose means do not cost, 2DS BT 19 % faster
    means = recorded.improvements
    for bt in (0.1, 0.15):  # a tie, then a saving of 15 %
        faster = {"BS": -1.0, "OB": -1.0, "G": -1.0, "BT": bt}
        monkeypatch.setattr(
            recorded, "improvements", lambda p, k, kind, f=faster: f if k == "2ds" else means(p, k, kind)
        )
        (said,) = chapter_claims._sampling_in_algorithm_1()
        assert said.startswith("04: by means, section 6 says 2DS BT 19 % faster")


def test_chapter_04_fails_a_table_or_a_picture_wider_than_the_page():
    """Review r13a: Algorithm 1's picture and the stage table's sixth column were cut off at the site's width."""
    nb = chapter_04()
    nb["cells"].append({"cell_type": "markdown", "source": ["```\n", "a" * 79 + "\n", "b" * 78 + "\n", "```\n"]})
    nb["cells"].append(
        executed("MD:| a | b | c | d | e | f |\n|" + " --- |" * 6 + "\n| 1 | 2 | 3 | 4 | 5 | 6 |")["cells"][0]
    )
    assert problems(CH04, nb) == [
        "04: a table of 6 columns, more than 5: ['a', 'b', 'c', 'd', 'e', 'f']",
        f"04: a code block's line of 79 characters, more than 78: {'a' * 40}...",
    ]


def test_a_second_table_in_one_output_is_read_apart_and_held_to_the_page_width():
    """Chapter 04's path table and, under it in the same output, a six-column table of `result.stats` were read as one
    table of three columns, and the wide one escaped the width check."""
    nb = chapter_04()
    nb["cells"].append(
        executed(
            "MD:| a | b |\n| --- | ---: |\n| 1 | 2 |\n\nThe statistics:\n\n| c | d | e | f | g | h |\n|"
            + " ---: |" * 6
            + "\n| 1 | 2 | 3 | 4 | 5 | 6 |"
        )["cells"][0]
    )
    assert chapter_claims.tables(nb)[-2:] == [(["a", "b"], [["1", "2"]]), (list("cdefgh"), [list("123456")])]
    assert problems(CH04, nb) == ["04: a table of 6 columns, more than 5: ['c', 'd', 'e', 'f', 'g', 'h']"]
    three = chapter_03(0.25, 0.25)
    three["cells"].append(nb["cells"][-1])
    assert problems(CH03, three) == ["03: a table of 6 columns, more than 5: ['c', 'd', 'e', 'f', 'g', 'h']"]


def test_the_answer_chapter_04_and_05_state_holds_in_docs_results():
    """The written verdict (04's opening and section 6, 05's closing section) against the recorded 100 queries:
    3DC-7 about twice as long with prediction for every sampler (1.8 to 2.2 times), no 2DS sampler saving time; the
    `paper` preset's means against Algorithm 1 saving for one sampler on 3DC-7 and three on 3DC-9 and 3DO, where its
    MLP answers "valid" or "invalid" to every sample; means and medians agreeing on 3DC-7 and parting on 2DS OB."""
    strong = recorded.median_ratios("strong")
    assert all(1.75 <= r < 2.25 for r in strong["3dc7"]["total"].values()), strong["3dc7"]["total"]  # 1.8 to 2.2
    assert not [s for s, r in strong["2ds"]["total"].items() if findings.time_verdict(r) == findings.SAVES]
    mlp = recorded.table("paper", "MLP accuracy")["3dc7"]
    assert recorded.ours(mlp["Seen TNR"]) == 0 and recorded.ours(mlp["Seen TPR"]) == 1
    unseen = (recorded.ours(mlp["Unseen TNR"]), recorded.ours(mlp["Unseen TPR"]))
    assert unseen == (0, 1), unseen  # 05's closing: the `paper` preset's 3DC-7 MLP "calls every sample valid"

    def means(preset, key):  # Table 3's improvement as time with / without, per sampler
        table = recorded.table(preset, "time improvement")[key]
        return {c.split()[1]: 1 - recorded.ours(v) for c, v in table.items() if c.startswith("Total")}

    # "saves time on average for one sampler of four on 3DC-7, where it answers "valid" to every sample, and for three
    # of four on 3DC-9 and 3DO, where it answers "invalid" to every sample"
    for key, saved, answers in (("3dc7", 1, (1, 0)), ("3dc9", 3, (0, 1)), ("3do", 3, (0, 1))):
        said = [findings.time_verdict(r) for r in means("paper", key).values()]
        assert said.count(findings.SAVES) == saved, (key, said)
        row = recorded.table("paper", "MLP accuracy")[key]
        assert (recorded.ours(row["Unseen TPR"]), recorded.ours(row["Unseen TNR"])) == answers, key
    # "on 2DS, for the bridge test alone": its MLP keeps fewer than a third of the valid samples
    assert [s for s, r in means("paper", "2ds").items() if findings.time_verdict(r) == findings.SAVES] == ["BT"]
    # "on 3DC-7 the means and medians give the same verdict for every sampler; they part on 2DS with OB"
    assert [findings.time_verdict(r) for r in means("strong", "3dc7").values()] == [
        findings.time_verdict(r) for r in strong["3dc7"]["total"].values()
    ]
    # "on the same recorded 100 queries, the mean can say prediction saves most of the time while the median says
    # it is a tie" (and docs/results.md's 2DS OB example)
    strong_means, strong_medians = means("strong", "2ds"), strong["2ds"]["total"]
    assert strong_means["OB"] < 0.5 and findings.time_verdict(strong_medians["OB"]) == findings.TIES
    paper_medians = recorded.median_ratios("paper")["3dc7"]["total"]
    assert all(findings.time_verdict(r) == findings.COSTS for r in paper_medians.values())
    # 04, section 6: the paper's means saved for three 2DS samplers of four and two 3DC-7 ones (five of eight, three
    # ties); means and Algorithm 1 without its checker save less; medians vs the lazy PRM cost in all but one of eight
    table3 = {
        key: [findings.time_verdict(1 - paper_numbers.IMPROVEMENT[key]["total"][s]) for s in SAMPLERS]
        for key in ("2ds", "3dc7")
    }
    assert (table3["2ds"].count(findings.SAVES), table3["3dc7"].count(findings.SAVES)) == (3, 2), table3
    assert sum(v.count(findings.TIES) for v in table3.values()) == 3, table3
    # 04's answer: with the same planner and statistic the paper's Table 3 and our `paper` run disagree, so the checker
    # and the network differ too: 2DS saves for three samplers (paper) and costs for three (ours); 3DC-7's bridge test
    # takes under half the time with prediction in the paper's, more than without in ours
    ours_2ds = [findings.time_verdict(r) for r in means("paper", "2ds").values()]
    assert ours_2ds.count(findings.COSTS) == 3, ours_2ds
    assert 1 - paper_numbers.IMPROVEMENT["3dc7"]["total"]["BT"] < 0.5 < 1 < means("paper", "3dc7")["BT"]

    assert all(1 - paper_numbers.IMPROVEMENT[k]["sampling"][s] < 1 for k in table3 for s in SAMPLERS)
    both = [r for key in ("2ds", "3dc7") for r in recorded.median_ratios("paper")[key]["total"].values()]
    assert sum(findings.time_verdict(r) == findings.COSTS for r in both) == 7, both
    mlp_2ds = recorded.table("paper", "MLP accuracy")["2ds"]  # "keeps fewer than a third of the valid samples"
    assert recorded.ours(mlp_2ds["Unseen TPR"]) < 1 / 3
    tpr = f"keeps fewer than a third of the valid samples (TPR {recorded.ours(mlp_2ds['Unseen TPR']):.0%}"
    assert tpr.replace("%", " %") in " ".join(PROSE_04.split())  # 04's opening, as the other pages word it
    assert "turns most" not in PROSE_04  # review r19a: the same measured wording on every page
    assert recorded.ours(mlp_2ds["Unseen Acc"]) < recorded.ours(mlp_2ds["Unseen always valid"])
    text = " ".join(markdown_of(ROOT / "notebooks" / CH04).split())
    verdicts = ("prediction saved time with none of them", "did not save planning time", "neither network we")
    assert any(verdict in text for verdict in verdicts), CH04
    # 05's opening, scoped (review r21c): no saving by medians in the lazy PRM for either preset on 3DC-7, nor by each
    # query's own ratio for `strong` in Algorithm 1; the "More" table's two savings are other statistics
    lazy = [r for key in ("strong", "paper") for r in recorded.median_ratios(key)["3dc7"]["total"].values()]
    own = list(recorded.query_ratios("strong --planner paper")["3dc7"].values())
    assert findings.SAVES not in [findings.time_verdict(r) for r in lazy + own]
    # reader r24b: 05's answer, printed once under its first code cell, says "No" for both checkers
    first = next(c for c in json.loads((ROOT / "notebooks" / CH05).read_text())["cells"] if c["cell_type"] == "code")
    assert "display(Markdown(chapter05.answer(models.threshold, trainings)))" in "".join(first["source"])  # r58e
    answer = chapter05.answer()
    assert (
        answer.startswith("**No.** On 3DC-7 no sampler's whole query saved 10 % or more with the timed network (an")
        and "depends" not in answer
    )
    opening = " ".join("".join(json.loads((ROOT / "notebooks" / CH05).read_text())["cells"][0]["source"]).split())
    # reader r27e; reader r37e, 05 item 3: the recorded run's timing, none of this notebook's
    assert (  # reader r43e, 05 contradiction 1: the median, as the answer's table (quartiles reach past 10 %); r46e:
        # the median of each query's own ratio, not "the median query" (a ratio of two medians reads BS 0.83)
        # reader r48e, 05 item 7: "no sampler's query" read as no single query; the median own ratio said
        "**No**: in our recorded run, with an accurate network, no sampler's median own ratio (each query's time with "
        "the network ÷ its time without, the median over 100 queries) was 10 % or more below 1" in opening
    ) and "median query" not in opening
    assert "This notebook times nothing" in opening
    assert "against our compiled exact checker" in answer and "never" not in answer  # reader r25b: 0.94 is shorter
    # 05's headline (reader r20c): with python-fcl on both sides the `strong` network saves "most of the sampling
    # time" of 3DC-7 but each query's total "is a tie"
    fcl = "strong --planner paper --baseline paper-fcl-alike"
    assert all(saved > 0.5 for saved in recorded.improvements(fcl, "3dc7", "sampling").values())
    assert {findings.time_verdict(r) for r in recorded.query_ratios(fcl)["3dc7"].values()} == {findings.TIES}


SLICES_03 = (  # section 5's two verdicts at full size, as slice_verdict words them (r34c: a count beside each share;
    # r53c: the z = 5.5 slice's mistakes by the walls apart from those beside an obstacle)
    "402 of 10000 cells wrong, 401 of them near a boundary; 30 (2%) of the C-obstacle's cells called valid, 372 (4%) "
    "of the free ones rejected: it finds the obstacles and errs mostly along the walls or the obstacles' edges: 260 "
    "within 4 cells of the map's edge, 141 beside an obstacle elsewhere; away from any boundary it makes 1 "
    "conservative and 0 dangerous mistakes",
    "737 of 10000 cells wrong, 524 of them near a boundary; 9 (0.3%) of the C-obstacle's cells called valid, 728 (10%) "
    "of the free ones rejected: it finds the obstacles and errs mostly at their edges; away from any boundary it makes "
    "213 conservative and 0 dangerous mistakes",
)
OPENING_03 = (("paper", "2DS", 55), ("strong", "2DS", 100), ("strong", "3DC-7", 96))  # the record, docs/results.md
POCKETS_03 = (  # section 5's yaw x joint slice at full size, as chapter03.pockets words it (wrap=True, reader r47c)
    "free regions cut off only as drawn, joined to the rest where alpha wraps round: 148 cells at alpha -3.11 to "
    "-2.23, joint1 -1.98 to -1.22 (the bottom left corner); 148 cells at alpha 2.23 to "
    "3.11, joint1 1.22 to 1.98 (the top right corner)"
)
PLANNED_03 = "roadmap: 203 nodes, 1 of them in collision (dangerous mistakes the planner accepted); repairs: 0"


def chapter_03(
    paper_blind: float,
    sentence_blind: float,
    sweep: str = 'no threshold beats "always valid"',
    best: int = 54,
    share: tuple[int, int] = (40, 80),
    slices: tuple[str, ...] = SLICES_03,
    planned: str = PLANNED_03,
    blind_rates: tuple[float, float] = (0.31, 0.77),
    words: str = "",
    corners: str = "the top right, near (α, joint) = (π, 2), and the bottom left, near (−π, −2). They are cut off "
    "only on the drawn map",
) -> dict:
    """A chapter 03 whose `paper` preset scores ``paper_blind`` on validity-blind samples in the table and
    ``sentence_blind`` in section 4's sentence, with TPR and TNR ``blind_rates`` there (review r16b's full-size site:
    31 % and 77 %, a balanced accuracy of 54 %), and ``words`` as its prose."""
    scores = {  # (preset, kind): accuracy, TPR, TNR
        ("paper", "balanced"): (0.54, 0.29, 0.76),
        ("strong", "balanced"): (0.93, 0.91, 0.94),
        ("paper", "validity-blind"): (paper_blind, *blind_rates),
        ("strong", "validity-blind"): (0.92, 0.91, 0.97),
    }
    rows = ["| | samples | accuracy | TPR / TNR | balanced accuracy |", "| --- | --- | --- | --- | --- |"]
    rows += [  # to a tenth, as printed; the share of valid samples its rates imply in its samples cell (r33c)
        f"| the paper's Table 2, 2DS unseen | unclear; its rounded rates fit {share[0]}–{share[1]}% valid | 88% "
        "| 90% / 85% | 87.5% |"
    ]
    rows += [
        f"| `{p}` preset, 2DS unseen, this page's draw (section 4) | {k} | {a:.0%} | {t:.0%} / {n:.0%} "
        f"| {(t + n) / 2:.0%} |"
        for (p, k), (a, t, n) in scores.items()
    ]
    rows += ["| always valid | validity-blind | 86% | 100% / 0% | 50% |"]  # balanced: 50 % by construction (r33c)
    opening = ["| model, unseen workspaces | balanced accuracy | TPR | TNR |", "| --- | --- | --- | --- |"]
    opening += ["| the paper's MLP, its Table 2, 2DS (its accuracy, as reported: 88%) | 87.5% | 90% | 85% |"]
    opening += [f"| our `{p}` preset, {s} | {b}% | {b}% | {b}% |" for p, s, b in OPENING_03]
    scores["paper", "validity-blind"] = (sentence_blind, *blind_rates)
    always = {"balanced": 0.5, "validity-blind": 0.86}
    lines = [
        findings.describe_accuracy(f"{p}, {k}", dict(zip(("acc", "tpr", "tnr"), v)), always[k])
        for (p, k), v in scores.items()
    ]
    nb = executed(
        "share of valid samples: balanced 50%, validity-blind 86%\n" + "\n".join(lines),
        f"the model calls every sample valid ... {sweep}.",
        f"paper preset: best balanced accuracy over all thresholds {best}% (at threshold 0.52)",  # r49c: section 6
        "MD:" + "\n".join(opening),
        "MD:" + "\n".join(rows),
        *slices,
        POCKETS_03,
        planned,
    )
    nb["cells"].append(
        {"cell_type": "markdown", "source": [f"Two corners hold outlined triangles, not hatched: {corners}."]}
    )
    nb["cells"].append({"cell_type": "markdown", "source": [words]})
    return nb


def test_chapter_03_passes_when_its_sentences_carry_the_tables_accuracies():
    assert problems(CH03, chapter_03(0.25, 0.25)) == []


def test_chapter_03_fails_an_opening_bullet_typing_other_numbers_than_its_table():
    verdict = (
        "scores {} % balanced accuracy on unseen 2DS workspaces, within 5 points of a coin flip's 50 % (what this page"
        ' calls "about"); the paper\'s TPR and TNR give {} %.'
    )
    assert problems(CH03, chapter_03(0.25, 0.25, words=verdict.format(55, 87.5))) == []
    assert problems(CH03, chapter_03(0.25, 0.25, words=verdict.format(54, 87.5))) == [  # reader r36c: 55 % beside 87.5
        "03: the verdict types 54 % and 87.5 %; the table gives (55.0, 87.5)"
    ]
    now = "scores {} % balanced accuracy on unseen 2DS workspaces, where the paper's TPR and TNR give {} %. The main"
    assert problems(CH03, chapter_03(0.25, 0.25, words=now.format(55, 87.5))) == []  # the verdict's words (r43c)
    assert problems(CH03, chapter_03(0.25, 0.25, words=now.format(54, 87.5))) == [
        "03: the verdict types 54 % and 87.5 %; the table gives (55.0, 87.5)"
    ]


def test_chapter_03_says_the_z_q_design_comes_close_only_where_its_line_is_close_and_below():
    """Reader r50c item 3, r52c item 2: the opening and the summary say that with all six changes the same [z, q] design
    comes close to the paper's 87.5 % balanced accuracy, below it; the line under the opening table must show it."""
    words = "the same design comes close to the paper's {} % balanced accuracy but stays below it (the line under it)."
    line = "the same `[z, q]` design reaches {}% balanced accuracy on unseen 2DS: close to the paper's 87.5% balanced, "
    line += "still below"  # r52c item 2: the paper's balanced accuracy, typed in the opening as the line prints it
    for ours, typed, caught in ((84, 87.5, False), (87, 87.5, False), (88, 87.5, True), (80, 87.5, True),
                                (None, 87.5, True), (84, 88, True)):  # fmt: skip
        nb = chapter_03(0.25, 0.25, words=words.format(typed))
        nb["cells"] += executed(line.format(ours) + " it.")["cells"] if ours else []
        found = [p for p in problems(CH03, nb) if "comes close" in p]
        assert bool(found) == caught, (ours, typed, found)


def test_chapter_03_reads_the_ablation_of_docs_fidelity_and_types_none_of_it():
    """Reader r43c: the verdict's cause and "Why so poor?" quote docs/fidelity.md section 4's 2DS rows (unseen
    balanced accuracy); reader r46c item 1: read from the table (``chapter03.ablation_steps``), not typed, so the
    prose names no row's number and no row list."""
    fidelity = (ROOT / "docs" / "fidelity.md").read_text()
    table = fidelity[fidelity.index("### 2DS") : fidelity.index("### 3DC-7")]
    balanced = {
        int(m[1]): float(m[2]) for m in re.finditer(r"^\| (\d) \|[^|]*\|[^|]*\|[^|]*\| ([\d.]+) /", table, re.M)
    }
    text = " ".join(markdown_of(ROOT / "notebooks" / CH03).split())
    for k in (2, 3, 6, 7):
        assert f"{balanced[k]:.0f} %" not in text and f"{balanced[k]} %" not in text, k
    assert "rows 1 to 6" not in text and "rows 3 and 6" not in text
    code = (ROOT / "notebooks" / CH03).read_text()
    assert "chapter03.ablation_steps()" in code


def test_chapter_03_fails_a_balanced_accuracy_or_an_opening_verdict_its_numbers_do_not_bear():
    """Review r26c: the closing table carries the balanced accuracy its verdict cites, and the verdict under the title
    a table of the recorded runs: each must bear its words."""
    nb = chapter_03(0.25, 0.25)
    for cell in nb["cells"]:
        for out in cell.get("outputs", []):
            text = out["data"]["text/markdown"] if "data" in out else ""
            if "| always valid | validity-blind | 86% | 100% / 0% | 50% |" in text:
                out["data"]["text/markdown"] = text.replace("86% | 100% / 0% | 50% |", "86% | 100% / 0% | 70% |", 1)
            if "our `strong` preset, 3DC-7 | 96%" in text:
                out["data"]["text/markdown"] = text.replace("3DC-7 | 96%", "3DC-7 | 76%")
            if "our `paper` preset, 2DS | 55%" in text:  # r41c: past the band that the verdict's "about" names
                out["data"]["text/markdown"] = out["data"]["text/markdown"].replace("2DS | 55%", "2DS | 56%")
    assert problems(CH03, nb) == [
        "03: the closing table's balanced accuracy for always valid is not (TPR + TNR) / 2",
        "03: the opening verdict's table gives our `paper` preset, 2DS 56%, not within 50-55%",
        "03: the opening verdict's table gives our `strong` preset, 3DC-7 76%, not within 90-100%",
    ]


def test_chapter_03_fails_a_sentence_that_disagrees_with_the_table():
    assert problems(CH03, chapter_03(0.25, 0.38)) == [
        "03: paper, validity-blind: the sentence says 38% vs 86% (balanced 54%), the table [25, 31, 77] vs 86"
    ]
    said = chapter_03(0.38, 0.38)  # review r16b's site: the old words, below chance at a balanced accuracy of 54 %
    out = said["cells"][0]["outputs"][0]
    out["text"] = out["text"].replace(
        "54%, about a coin flip (50%)", "54%, below a coin flip (50%) (worse than chance)"
    )
    assert problems(CH03, said) == [
        "03: paper, validity-blind: balanced accuracy 54% is not 'below' a coin flip (worse than chance)",
        "03: the `paper` preset is not about a coin flip by balanced accuracy on validity-blind samples",
    ]


def test_chapter_03_fails_where_its_closing_verdict_or_section_6_would_not_hold():
    """The verdict: `paper` about a coin flip by balanced accuracy on both kinds of sample, below "always valid" on
    validity-blind ones, where "always valid" is close to the paper's 88 %; never "worse than chance" in the prose
    unless a balanced accuracy is (review r16b); section 6: no threshold beats "always valid"."""
    assert problems(CH03, chapter_03(0.9, 0.9)) == [
        "03: the `paper` preset is not below 'always valid' on validity-blind samples",
        "03: the `strong` preset does not classify far better than the `paper` preset",
    ]
    assert problems(CH03, chapter_03(0.4, 0.4, blind_rates=(0.7, 0.8))) == [
        "03: the `paper` preset is not about a coin flip by balanced accuracy on validity-blind samples"
    ]
    for old, caught in (
        ("and worse than chance on validity-blind ones", "worse than chance on"),
        ('falls below both a coin flip and "always valid"', "below both a coin flip"),
    ):
        assert problems(CH03, chapter_03(0.38, 0.38, words=f"The `paper` preset {old}.")) == [
            f"03: the prose says '{caught}'; no printed balanced accuracy is below a coin flip"
        ]
    below = chapter_03(0.38, 0.38, blind_rates=(0.3, 0.5), words="worse than chance on validity-blind ones")
    assert "no printed balanced accuracy" not in " ".join(problems(CH03, below))  # 40 %: it is worse than chance
    assert problems(CH03, chapter_03(0.25, 0.25, sweep='2 points above "always valid"')) == [
        '03: section 6 says no threshold beats "always valid"; the sweep\'s sentence says one does'
    ]
    assert problems(CH03, chapter_03(0.25, 0.25, best=69)) == []  # reader r49c: the best threshold, far below 87.5
    assert problems(CH03, chapter_03(0.25, 0.25, best=70)) == [
        "03: the opening says no threshold lifts `paper` near 87.5 %; its best: 70"
    ]
    for share in ((55, 80), (40, 90)):  # reader r45c: the prose, the range fits balanced samples, not validity-blind
        assert problems(CH03, chapter_03(0.25, 0.25, share=share)) == [
            "03: the paper's rounded rates do not fit balanced samples and not validity-blind ones"
        ]


def test_chapter_03_names_the_free_triangles_corners_as_the_data_finds_them():
    """Reader r45c item 2: the yaw x joint figure's free triangles lie top right and bottom left as drawn; the page
    named top left and bottom right (right modulo 2π, wrong for the picture)."""
    wrong = "the top left, near (α, joint) = (−π, 2), and the bottom right, near (π, −2)"
    assert problems(CH03, chapter_03(0.25, 0.25, corners=wrong)) == [
        "03: section 5 names the free triangles' corners ('top left', 'bottom right'); the data: "
        + "['bottom left', 'top right']"
    ]
    apart = "the top right, near (α, joint) = (π, 2), and the bottom left, near (−π, −2), apart from the rest"
    assert problems(CH03, chapter_03(0.25, 0.25, corners=apart)) == [  # reader r47c: α wraps round; they join
        "03: section 5 says whether the free triangles are cut off only as drawn; the printed line disagrees"
    ]


def test_chapter_03_fails_slice_verdicts_their_counts_contradict():
    """Section 5: "only" needs every mistake near a boundary, "mostly" at least half, the mistakes away from a
    boundary must add up, and so must those by the walls and beside an obstacle (r53c); section 7: the paper's planner
    repairs nothing (review r8b: "costs time (a repair)" beside "repairs: 0")."""
    walls, mostly = SLICES_03
    assert problems(CH03, chapter_03(0.25, 0.25)) == []
    only = mostly.replace("it finds the obstacles and errs mostly", "it finds the obstacles, and errs only")
    assert problems(CH03, chapter_03(0.25, 0.25, slices=(walls, only))) == [
        "03: a slice 'errs only' near an edge with 524 of its 737 mistakes near a boundary"
    ]
    assert problems(CH03, chapter_03(0.25, 0.25, slices=(walls, mostly.replace("524 of them", "295 of them")))) == [
        "03: a slice 'errs mostly' near an edge with 295 of its 737 mistakes near a boundary",
        "03: a slice's mistakes away from a boundary (213 + 0) are not 442",
    ]
    assert problems(CH03, chapter_03(0.25, 0.25, slices=(walls.replace("260 within", "250 within"), mostly))) == [
        "03: a slice's mistakes by the walls (250) and beside an obstacle (141) do not add up"
    ]
    assert problems(CH03, chapter_03(0.25, 0.25, slices=(walls,))) == [
        "03: expected two slice verdicts (section 5), found 1"
    ]
    assert problems(CH03, chapter_03(0.25, 0.25, planned=PLANNED_03.replace("repairs: 0", "repairs: 1"))) == [
        "03: section 7 says the paper's planner never puts a node in collision on a path; it repaired"
    ]


# ---- chapter 02: the unseen grids against "all free" ----

CH02 = "02_cae_reconstruction.ipynb"
ERRORS_02 = ((38.4, 38.4, 41.1), (1881, 1880, 1213), (0.0, 1.9, 1165.7))  # section 4: error term, sum W_e^2, λ × sum


def chapter_02(
    unseen: tuple[float, float, float] = (86.7, 86.8, 88.1),
    quick: bool = False,
    seen_above: int = 30,
    on_new: tuple[float, float, float] = (86.9, 86.9, 87.6),
) -> dict:
    """A chapter 02 whose three CAEs score ``unseen`` (%) on unseen grids, "all free" 87.6 % (review r8b's site), the
    `paper` preset's 85.9 % and the many-grids CAE's 91.0 % against 87.8 %; quick: nothing memorized; section 5's
    ranges with ``seen_above`` of the 30 seen grids above the diagonal; the three CAEs ``on_new`` (%) on 500 new grids,
    "all free" 87.8 %; section 5's check on 6 held-out training grids."""
    names = ("λ = 0", "λ = 1e-3, CAE-long", "λ = 0.961 (mean reading)")
    section_5 = [
        "| CAE | seen: its 30 training grids (all free 88.6%) | the 10 test grids (all free 87.6%) "
        "| 500 new grids (all free 87.8%) |",
        "| --- | --- | --- | --- |",
    ]
    section_5 += [
        f"| {n} | 99.6% | {u:.1f}% ({u - 87.6:+.1f} points) | {o:.1f}% ({o - 87.8:+.1f} points) |"
        for n, u, o in zip(names, unseen, on_new)
    ]
    section_5.append("| CAE-preset | 89.2% | 85.9% (-1.7 points) | 86.5% (-1.3 points) |")  # not memorized: not checked
    closing = [
        '| 2DS reconstruction accuracy | seen | unseen | "all free" (seen / unseen) |',
        "| --- | --- | --- | --- |",
        "| paper, Table 1 | 100% | 100% | not reported |",
        f"| CAE-preset, {'quick-sized' if quick else '100 epochs'} | 89.2% | 85.9% | 88.6% / 87.6% |",
    ]
    for n, u in zip(names[1:], unseen[1:]):
        closing.append(f"| this notebook, {n}, 30 grids | 99.6% | {u:.1f}% | 88.6% / 87.6% |")
    closing.append("| this notebook, 1000 grids (not the paper's recipe) | 91.7% | 91.0% | 88.2% / 87.8% |")
    verdict = (
        "seen 70.0% (all free 88.6%), unseen 70.0% (all free 87.6%): not memorized yet."
        if quick
        else "seen 99.6% (all free 88.6%), unseen 86.8% (all free 87.6%): memorized. Near perfect on its training "
        "grids, no better than 'all free' on new ones."
    )
    return executed(
        (
            "\n".join(f"{n}: z moves 0.024 at 1 flip, 0.143 at 30 flips: 6.0x as far for 30x the flips" for n in names),
            f"{'':26s} {'error term':>11s} {'sum W_e^2':>10s} {'lambda * sum':>13s}\n"
            + "\n".join(f"{n:26s} {e:11.1f} {w:10.0f} {lw:13.1f}" for n, e, w, lw in zip(names, *ERRORS_02)),
            "1,000 grids, on the 500 new grids: +3.2 points against 'all free' (its code carries something of new "
            "workspaces); 439 of 500 new grids above the diagonal, 61 below",
        ),
        "median Jacobian norm: λ = 0 2.64, λ = 1e-3, CAE-long 2.66, λ = 0.961 (mean reading) 1.75\n"
        "least sensitive in this run: the smallest mean Jacobian norm: λ = 0.961 (mean reading)\n"
        "λ = 0.961 (mean reading) against λ = 0: median ||J|| -31%, median ||J|| / ||z|| -18%, z's move at 30 flips "
        "-16%, decoded cells changed at 30 flips -39%",
        "λ = 0: 30 of the 30 flips ignored, 0 copied, 3 other cells wrong: 3 cells differ from the clean workspace "
        "(99.7% right)\n"
        "λ = 0.961 (mean reading): 30 of the 30 flips ignored, 0 copied, 0 other cells wrong: 0 cells differ from the "
        "clean workspace (100.0% right)",
        "loss of Eq. (1) per epoch: first 4.64e+18, last 3.81e+17, highest 1.39e+22; training grids reconstructed: "
        '56.0% of cells right, "all free": 88.6%',
        "MD:" + "\n".join(section_5),
        "CAE-long (λ = 1e-3): " + verdict,
        "MD:" + "\n".join(closing),
        'MD:| grids | accuracy, lowest – highest | points above "all free", fewest – most | above the diagonal |\n'
        f"| --- | ---: | ---: | ---: |\n| seen | 98.9% – 100.0% | +0.8 – +21.6 | {seen_above} of 30 |\n"
        "| unseen | 80.1% – 94.0% | -5.2 – +1.1 | 3 of 10 |",
        'On the 6 held-out training grids ("all free" 91.3%): 300 steps 90.9% (-0.4 points); 1,500 steps 90.3% '
        '(-1.0 points); 3,000 steps 89.8% (-1.5 points). Best: 300 steps; 0 of 3 lengths above "all free".',
        "MD:Four findings, in this run's numbers:\n\n- CAE-long, the paper's network and λ trained 1,500 steps on 30 "
        f"generated grids (the paper's count), scores {unseen[1]:.1f}% on 500 new grids, "
        f'{abs(unseen[1] - 87.6):.1f} points {"below" if unseen[1] < 87.6 else "above"} answering "all free", '
        'which gets 87.6%: **no better than answering "all free"**.',
    )


def test_chapter_02_passes_unseen_scores_within_a_couple_of_points_of_all_free():
    assert problems(CH02, chapter_02()) == []
    assert problems(CH02, chapter_02((84.0, 70.0, 60.0), quick=True)) == []  # quick mode: its page says so


def test_chapter_02_fails_a_memorized_cae_whose_seen_grid_sits_on_the_diagonal():
    """Review r15c: "Seen workspaces sit ... above the diagonal" beside a seen grid 96 % free that looked on it. The
    page prints how many are above; a memorized CAE with one not above fails (quick mode's prose says it memorized
    nothing, so its count may be anything)."""
    assert problems(CH02, chapter_02(seen_above=29)) == [
        "02: a memorized CAE's seen grids are not all above the diagonal: | seen | 98.9% – 100.0% | +0.8 – +21.6 | 29 "
        "of 30 |"
    ]
    assert problems(CH02, chapter_02((84.0, 70.0, 60.0), quick=True, seen_above=3)) == []


def test_chapter_02_holds_the_three_caes_level_or_below_all_free_on_the_new_grids():
    """Reader r35b: λ = 0.961's +0.6 on the ten test grids read as a win; section 5 prints the three CAEs on the 500
    new grids and says each is level with "all free" or below it there. One a point above fails; quick mode's CAEs
    memorized nothing, its page says the text describes the full-size run."""
    assert problems(CH02, chapter_02(on_new=(86.9, 86.9, 88.9))) == [
        "02: λ = 0.961 (mean reading) is +1.1 points against 'all free' on the new grids: not level or below"
    ]
    assert problems(CH02, chapter_02((84.0, 70.0, 60.0), quick=True, on_new=(86.9, 86.9, 88.9))) == []


def test_chapter_02_fails_a_cae_far_from_all_free_on_unseen_grids():
    """Review r8b: "the same holds for all three λ" beside λ = 0.961 above "all free"; the words are now "within a
    couple of points, above or below", and a CAE beyond that fails."""
    assert problems(CH02, chapter_02((86.7, 86.8, 91.6))) == [
        "02: λ = 0.961 (mean reading) scores +4.0 points against 'all free' on the test grids: not within a couple",
        "02: this notebook, λ = 0.961 (mean reading), 30 grids: unseen 91.6% is not within a couple of points of "
        "'all free' (87.6%)",
    ]
    nb = chapter_02()
    nb["cells"][5]["outputs"][0]["text"] = nb["cells"][5]["outputs"][0]["text"].replace(
        "memorized. Near perfect on its training grids, no better than", "near perfect on its training grids, and above"
    )
    assert problems(CH02, nb) == [
        "02: the paper's CAE rebuilds unseen grids better than 'all free': the prose says it does not"
    ]


def test_chapter_02_states_what_section_6_and_the_closing_measure():
    """Review r29b: "at λ = 0.961 the norm is smaller", and "all three 30-grid CAEs reproduce the seen column"; a
    page whose numbers say otherwise fails."""
    nb = chapter_02()
    nb["cells"][1]["outputs"][0]["text"] = nb["cells"][1]["outputs"][0]["text"].replace("1.75", "2.70")
    assert problems(CH02, nb) == [
        "02: λ = 0.961's median Jacobian norm is not the smallest: median Jacobian norm: λ = 0 2.64, λ = 1e-3, "
        "CAE-long 2.66, λ = 0.961 (mean reading) 2.70"
    ]
    nb = chapter_02()
    table = nb["cells"][4]["outputs"][0]["data"]
    table["text/markdown"] = table["text/markdown"].replace("| λ = 0 | 99.6%", "| λ = 0 | 95.0%")
    assert problems(CH02, nb) == ["02: λ = 0 scores 95.0% on its training grids"]


def test_chapter_02_holds_section_6s_margins_to_its_words():
    """Reader r48b: "the margins are small" beside 40 % fewer decoded cells changing. Section 6 now says the
    scale-free measures fall by under a fifth and the decoded cells by about two fifths; a page whose printed changes
    say otherwise, or that does not print them, fails (full size only)."""
    nb = chapter_02()
    nb["cells"][1]["outputs"][0]["text"] = nb["cells"][1]["outputs"][0]["text"].replace("-39%", "-12%")
    assert problems(CH02, nb) == [
        "02: section 6 says the scale-free measures fall by under a fifth, the decoded cells by about two fifths: "
        "against λ = 0: median ||J|| -31%, median ||J|| / ||z|| -18%, z's move at 30 flips -16%, decoded cells "
        "changed at 30 flips -12%"
    ]
    nb = chapter_02()
    text = nb["cells"][1]["outputs"][0]["text"]
    nb["cells"][1]["outputs"][0]["text"] = text[: text.index("\nλ = 0.961 (mean reading) against")]
    assert problems(CH02, nb) == ["02: section 6 does not print λ = 0.961's change against λ = 0, measure by measure"]


def test_chapter_02_holds_section_6s_error_terms_to_section_4s_table():
    """Reader r55b: "it cost nothing we can measure" beside a higher error term; section 6 now says λ = 0.961 costs
    no accuracy and types its error term against the other two's (41.1 against 38.4 at full size). A page where
    λ = 0.961's error term is not the highest, or whose typed values section 4's table does not print, fails (full
    size only); a page without the table fails."""
    said = "At full size its error term ends a little\nhigher (section 4's table: 41.1 against 38.4 for the other two)"
    nb = chapter_02()
    nb["cells"].append({"cell_type": "markdown", "source": [said]})
    assert problems(CH02, nb) == []
    nb["cells"][0]["outputs"][1]["text"] = nb["cells"][0]["outputs"][1]["text"].replace("41.1", "41.4")
    assert problems(CH02, nb) == [
        "02: section 6 types 'At full size its error term ends a little higher (section 4's table: 41.1 against 38.4 "
        "for the other two)'; section 4 prints "
        "error term sum W_e^2 lambda * sum λ = 0 38.4 1881 0.0 λ = 1e-3, CAE-long 38.4 1880 1.9 λ = 0.961 (mean "
        "reading) 41.4 1213 1165.7"
    ]
    nb["cells"][0]["outputs"][1]["text"] = nb["cells"][0]["outputs"][1]["text"].replace("41.4", "38.0")
    assert problems(CH02, nb) == [
        "02: section 6 says λ = 0.961's error term ends higher than the other two's: error term sum W_e^2 lambda * "
        "sum λ = 0 38.4 1881 0.0 λ = 1e-3, CAE-long 38.4 1880 1.9 λ = 0.961 (mean reading) 38.0 1213 1165.7"
    ]
    nb = chapter_02((84.0, 70.0, 60.0), quick=True)  # quick mode: its page says the text is the full-size run's
    nb["cells"][0]["outputs"][1]["text"] = nb["cells"][0]["outputs"][1]["text"].replace("41.1", "38.0")
    assert problems(CH02, nb) == []
    nb["cells"][0]["outputs"].pop(1)
    assert problems(CH02, nb) == ["02: section 4 does not print the three CAEs' error terms"]
    with open(Path(__file__).parents[1] / "notebooks" / CH02, encoding="utf-8") as f:  # the page types the values
        assert chapter_claims.TYPED_ERROR.search(chapter_claims.prose(json.load(f)))


@pytest.mark.parametrize("below", [0, 250])
def test_chapter_02_holds_section_7s_points_below_the_diagonal_to_its_count(below):
    """Reader r55b: "few of its points lie below the diagonal" beside 61 of 500; reader r60b: "lies mostly above",
    with 439 of 500 above printed. None below, or half or more, fails at full size; quick mode's page says the text is
    the full-size run's."""
    counts = f"{500 - below} of 500 new grids above the diagonal, {below} below"
    nb = chapter_02()
    nb["cells"][0]["outputs"][2]["text"] = nb["cells"][0]["outputs"][2]["text"].replace(
        "439 of 500 new grids above the diagonal, 61 below", counts
    )
    assert problems(CH02, nb) == [f"02: section 7 says its points lie mostly above the diagonal, not all: {counts}"]
    nb = chapter_02((84.0, 70.0, 60.0), quick=True)
    nb["cells"][0]["outputs"][2]["text"] = nb["cells"][0]["outputs"][2]["text"].replace(
        "439 of 500 new grids above the diagonal, 61 below", counts
    )
    assert problems(CH02, nb) == []
    nb["cells"][0]["outputs"].pop(2)
    assert problems(CH02, nb) == [
        "02: section 7 does not count the many-grids CAE's new grids above and below the diagonal"
    ]


def test_chapter_02_holds_both_readings_of_the_error_below_all_free_on_the_new_grids():
    """Reader r48b: the top fold says CAE-long (the sum) and λ = 0.961 (the mean) both score below "all free" on the
    new grids; λ = 0.961 level with it fails (λ = 0 is not named there)."""
    assert problems(CH02, chapter_02(on_new=(87.9, 86.9, 87.8))) == [
        "02: λ = 0.961 (mean reading) is +0.0 points against 'all free' on the new grids: the top fold says below"
    ]


def test_chapter_02_holds_section_5s_held_out_check_to_its_words():
    """Reader r47b: why stopping earlier does not help, on the page: on the held-out training grids the shorter
    training scores higher and no length beats "all free". A longer training scoring higher fails (full size only);
    a page without the line fails."""
    nb = chapter_02()
    nb["cells"][-2]["outputs"][0]["text"] = nb["cells"][-2]["outputs"][0]["text"].replace("90.3%", "91.0%")
    assert problems(CH02, nb) == [
        "02: section 5 says the shorter training scores higher and none beats 'all free': On the 6 held-out training "
        'grids ("all free" 91.3%): 300 steps 90.9% (-0.4 points); 1,500 steps 91.0% (-1.0 points); 3,000 steps 89.8% '
        '(-1.5 points). Best: 300 steps; 0 of 3 lengths above "all free".'
    ]
    nb = chapter_02((84.0, 70.0, 60.0), quick=True)
    nb["cells"][-2]["outputs"][0]["text"] = nb["cells"][-2]["outputs"][0]["text"].replace("90.3%", "91.0%")
    assert problems(CH02, nb) == []  # quick mode memorized nothing: its page says the text is the full-size run's
    nb["cells"][-2]["outputs"] = []
    assert problems(CH02, nb) == ["02: section 5's check on held-out training grids is not printed"]


def test_chapter_02_holds_its_closing_answer_to_its_numbers():
    """Review r26b: the closing answer gives this run's unseen score beside "all free" and the paper's 100 %; "no
    better than answering 'all free'" beside a score more than a couple of points above it fails, and so does a
    page that no longer prints the answer."""
    nb = chapter_02()
    answer = nb["cells"][-1]["outputs"][0]["data"]
    answer["text/markdown"] = answer["text/markdown"].replace("scores 86.8%", "scores 91.0%")
    assert "02: the answer says 'no better than all free' of 91.0% against 87.6%" in problems(CH02, nb)
    answer["text/markdown"] = "**The answer.** the CAE does better."
    assert problems(CH02, nb) == ["02: the closing answer with this run's unseen score and 'all free' is not printed"]


def test_chapter_02_prints_each_gap_as_the_difference_of_the_values_printed_beside_it():
    """Review r27b: "86.7%, where answering 'all free' gets 87.6% (0.8 points below)", and -0.8 in section 5's table:
    a reader subtracts and gets 0.9. The gaps are now taken from the values as printed; one that is not fails."""
    nb = chapter_02()
    answer = nb["cells"][-1]["outputs"][0]["data"]
    answer["text/markdown"] = answer["text/markdown"].replace("scores 86.8%", "scores 86.7%")
    assert problems(CH02, nb) == ["02: 86.7% against 'all free' 87.6% is printed as -0.8 points"]
    nb = chapter_02()
    table = nb["cells"][4]["outputs"][0]["data"]
    table["text/markdown"] = table["text/markdown"].replace("-0.9 points", "-0.8 points", 1)
    assert problems(CH02, nb) == ["02: 86.7% against 'all free' 87.6% is printed as -0.8 points"]
    nb["cells"][5]["outputs"][0]["text"] += (
        " The `paper` preset's CAE: seen 89.2% (all free 88.6%: +0.7 points, above it)"
    )
    assert "02: 89.2% against 'all free' 88.6% is printed as +0.7 points" in problems(CH02, nb)


def test_chapter_02_holds_the_answers_gap_to_what_it_prints():
    """Reader r33b: the answer at the top reads its verdict from the new grids and prints the gap beside its two
    values: a gap that is not their difference fails."""
    nb = chapter_02()
    answer = nb["cells"][-1]["outputs"][0]["data"]
    answer["text/markdown"] = answer["text/markdown"].replace("0.8 points below", "1.0 points below")
    assert problems(CH02, nb) == ["02: 86.8% against 'all free' 87.6% is printed as -1.0 points"]


def test_chapter_02_holds_the_many_grids_cae_between_all_free_and_the_papers_100_percent():
    """Review r17b: "this notebook's CAEs land near 'all free'" beside the 1,000-grid row's 91.0 % against 87.8 %; the
    closing now says that one beats "all free" but stays short of 100 %, and a row at either bound fails."""
    for unseen in ("100.0%", "87.0%"):
        nb = chapter_02()
        nb["cells"][6]["outputs"][0]["data"]["text/markdown"] = nb["cells"][6]["outputs"][0]["data"][
            "text/markdown"
        ].replace("| 91.7% | 91.0% |", f"| 91.7% | {unseen} |")
        assert problems(CH02, nb) == [
            f"02: this notebook, 1000 grids (not the paper's recipe): unseen {float(unseen[:-1])}% is not between "
            "'all free' (87.8%) and 100 %"
        ]


# ---- chapter 05: the closing answer against what it prints ----

CH05 = "05_3d_scenes.ipynb"


def chapter_05(
    recipe_tpr: str = "100%",
    recipe_medians: dict[str, float] | None = None,
    frames_valid: int = 90,
    recipe_acc: str = "76%",
    tie: str = f'a ratio less than {findings.TIE:.0%} from 1 reads "{findings.TIES}"',
    shares: tuple[str, str] = ("42%", "76%"),
    office: str = "| 2000 | 631 | 186 | 445 |",
    fifth: str = "94.5%",
    answer: str | None = None,
    of_medians: dict[str, float] | None = None,
    question: str = "**No**: not by 10 %.",
    paper_side: str | None = None,
    costs: str | None = None,
    summary: str = "a tie by the median of each query's own ratio (1.06), and within noise by the ratio of its means",
):
    """A chapter 05 that prints docs/results.md's medians and the closing tables (review r8b's numbers), the lazy
    PRM's after ``tie``; the paper's recipe with ``recipe_acc``, ``recipe_tpr`` and ``recipe_medians``, and
    ``frames_valid`` of 90 frames valid; its ``answer`` (``chapter05.answer()``) and the ratio of two medians
    ``of_medians`` in Algorithm 1 read against timing noise (reader r24b); the closing's ``paper_side``
    (``chapter05._paper_side()``) and the answer's ``costs`` (``chapter05.check_costs()``), readers r29e, r30e."""
    strong = recorded.median_ratios("strong")["3dc7"]["total"]
    of_medians = of_medians or strong  # reader r57e, 05 item 1: the fold's ratio of two medians is the lazy PRM's
    band = chapter05.floors()["medians"]  # wave 24: a ratio of two medians reads against 0.40–1.60, one rule for all
    fcl_sampling = recorded.improvements(chapter05.FCL, "3dc7", "sampling")
    paper_sampling = paper_numbers.IMPROVEMENT["3dc7"]["sampling"]
    recipe_medians = recipe_medians or recorded.median_ratios("paper")["3dc7"]["total"]
    timed, timed_share = chapter05.recorded_scores(chapter05.COMPILED)
    scored = "\n".join(
        [
            f"| 3DC-7, unseen | accuracy | TPR | TNR | {chapter05_accuracy.ALWAYS} |",
            "| --- | ---: | ---: | ---: | ---: |",
            "| paper, Table 2 | 71% | 85% | 61% | — |",
            "| ours: the paper's recipe (`paper` preset), balanced unseen samples (half valid) "
            "| 50% | 100% | 0% | 50% |",
            f"| {chapter05_accuracy.TIMED_ROW} (threshold 0.63), uniform unseen samples "
            f"| {timed['acc']:.0%} | {timed['tpr']:.0%} | {timed['tnr']:.0%} | {timed_share:.0%} |",
            "",
            f"| 3DC-7, unseen | accuracy | TPR | TNR | {chapter05_accuracy.ALWAYS} |",
            "| --- | ---: | ---: | ---: | ---: |",
            f"| ours: the same recipe, uniform unseen samples | {recipe_acc} | {recipe_tpr} | 0% | 76% |",
            "| ours: the notebook's network (`strong`, threshold 0.57), §5's 2000 uniform samples, seed 0 "
            f"| {fifth} | 93.5% | 97.5% | 74.5% |",
            "",
            f"On uniform samples the recipe's {recipe_acc} is above Table 2's 71% only because 76% of them are valid.",
        ]
    )
    nb = executed(
        "MD:"
        + (chapter05.answer() if answer is None else answer).replace(
            chapter05.check_costs(), costs or chapter05.check_costs()
        ),
        "MD:| uniform samples | in collision | of those: poking out of the office "
        "| in collision with furniture only (inside the office) |\n"
        "| ---: | ---: | ---: | ---: |\n" + office,
        "MD:| samples | count | share |\n| --- | ---: | ---: |\n| circle | 1392 | 69.6% |\n\n"
        'accuracy **94.5%**, TPR 93.5%, TNR 97.5% (threshold 0.57); answering "valid" to all 2000 of these: 74.5%',
        "MD:| frames | valid (exact checker) | least clearance (frame) | P(valid): lowest / threshold "
        "| frames below the threshold |\n| ---: | ---: | ---: | ---: | ---: |\n"
        f"| 90 | {frames_valid} | 0.012 (41) | 0.61 / 0.54 | 0 |",
        "MD:" + scored,
        "MD:The paper's row: 71% = 85% × share + 61% × (1 − share) gives a valid share of about "
        f"{shares[0]}. On uniform samples, {shares[1]} valid, the same TPR and TNR would give an accuracy of 79%, "
        "not 71%.",
        "MD:On its balanced unseen test the model is more accurate than the paper's MLP (Table 2); on these uniform "
        'samples it is more accurate than answering "valid" to all of them.',
        "MD:"  # reader r34e, lift 1: the total-time table is the answer's, under it (chapter05.total_table)
        + (chapter05._paper_side() if paper_side is None else paper_side)
        + "\n\nThe sampling stage alone:\n\n"
        + findings.ratio_table(
            {
                f"{chapter05.TIMED}, python-fcl on both sides: "
                + " / ".join(f"{v:.0%}" for v in fcl_sampling.values())
                + " less": {k: 1 - v for k, v in fcl_sampling.items()},
                "the paper's Table 3: " + " / ".join(f"{v:.0%}" for v in paper_sampling.values()) + " less": {
                    k: 1 - v for k, v in paper_sampling.items()
                },
            }
        )
        + f"\n\nAgainst the lazy PRM ({tie}):\n\n"
        + findings.ratio_table({"3DC-7, `paper` preset, medians": recipe_medians})
        + "\n"
        + chapter05._noise_row(chapter05.MEDIANS_ROW, of_medians, band),  # the lazy PRM's row (r57e, 05 item 1)
    )
    nb["cells"].append({"cell_type": "markdown", "source": ["the label **model disagrees** appears"]})
    said = f"OB's whole query, where skipping the checks could save most, was {summary} (1.12)."  # the Summary's
    nb["cells"].insert(0, {"cell_type": "markdown", "source": [said]})  # the last cells stay where tests find them
    nb["cells"].insert(0, {"cell_type": "markdown", "source": [f"**The question.** Does it save time? {question}"]})
    return nb


def test_chapter_05_summary_reads_ob_by_two_named_statistics():
    """Reader r54e, 05 contradiction 1: the Summary called OB's whole query "a tie" where the answer, by the ratio of
    the means (1.12), says "within noise"; each clause now names its statistic and its number from the record."""
    unnamed = "a tie, as the answer says, and within noise by the ratio of its means"
    assert problems(CH05, chapter_05(summary=unnamed)) == [
        "05: the Summary's reading of OB's whole query is not the record's: None"
    ]
    wrong = "a tie by the median of each query's own ratio (1.12), and within noise by the ratio of its means"
    assert problems(CH05, chapter_05(summary=wrong)) == [
        "05: the Summary's reading of OB's whole query is not the record's: ('OB', '1.12', '1.12')"
    ]


def test_chapter_05_passes_when_its_closing_tables_carry_its_answer():
    assert problems(CH05, chapter_05()) == []


def test_chapter_05_gives_its_answer_in_the_question_paragraph_and_our_means_beside_the_papers():
    """Reader r27e: the question paragraph pointed to the answer instead of giving it, and the answer set our medians
    of each query's own ratio beside the paper's ratios of the means."""
    assert problems(CH05, chapter_05(question="The answer is under the first code cell.")) == [
        "05: the question paragraph does not give the answer's 'No' (reader r27e)"
    ]
    said = chapter05.answer()  # reader r29e: and names the statistics its "No" holds by
    named = "by the median of each query's own ratio (the table below)"
    assert problems(CH05, chapter_05(answer=said.replace(named, "by the medians")))[0].startswith(
        "05: the answer does not name the statistics of the closing's total-time rows"
    )
    means = "The numbers behind the answer: the ratio of the means"  # r42e: the means named by their fold alone
    assert problems(CH05, chapter_05(answer=said.replace(means, "The numbers behind the answer")))[0].startswith(
        "05: the answer does not name the statistics of the closing's total-time rows"
    )


def test_chapter_05_fails_where_its_closing_answer_would_not_hold():
    """The answer (review r8b asked for one about the paper's idea in 3D): the paper's recipe calls every 3DC-7 sample
    valid and costs time with every sampler; the path found is valid at every frame."""
    assert problems(CH05, chapter_05(recipe_tpr="93%")) == [
        "05: the paper's recipe does not call every 3DC-7 sample valid: "
        '[["ours: the paper\'s recipe (`paper` preset), balanced unseen samples (half valid)", '
        "'50%', '100%', '0%', '50%'], ['ours: the same recipe, uniform unseen samples', '76%', '93%', '0%', '76%']]"
    ]
    assert problems(CH05, chapter_05(recipe_medians={"BS": 2.0, "OB": 0.5, "G": 2.0, "BT": 2.0})) == [
        "05: the paper's recipe did not cost time with every sampler on 3DC-7: [['3DC-7, `paper` preset, medians', "
        "'costs time (2.00)', 'saves time (0.50)', 'costs time (2.00)', 'costs time (2.00)']]"
    ]
    assert problems(CH05, chapter_05(frames_valid=89)) == [
        "05: the path is not valid at every frame: [['90', '89', '0.012 (41)', '0.61 / 0.54', '0']]"
    ]


def test_chapter_05_holds_the_recipe_row_and_the_tie_band_to_its_closing():
    """Review r10b: the recipe's 76 % beside Table 2's 71 % reads as success unless it is "always valid"'s own score,
    and a ratio labelled "a tie" needs its band printed."""
    assert problems(CH05, chapter_05(recipe_acc="80%")) == [
        "05: the paper's recipe against 'always valid' and Table 2 (71.0): "
        "['ours: the same recipe, uniform unseen samples', '80%', '100%', '0%', '76%']",
        "05: the fold does not say why the recipe's uniform accuracy above Table 2's is no win",
    ]
    assert problems(CH05, chapter_05(tie="a ratio near 1 is a tie")) == [
        "05: the tie band is not printed beside every time table"
    ]


def test_chapter_05_gives_section_5s_scores_in_its_accuracy_table_as_section_5_printed_them():
    """Reader r23b: §5 printed accuracy 94.5 %, the accuracy table said 94 % (a student rounds to 95 %)."""
    assert problems(CH05, chapter_05(fifth="94%")) == [
        "05: the accuracy table's §5 row is not what §5 printed: [['94', '93.5', '97.5', '0.57']], "
        "('94.5', '93.5', '97.5', '0.57')"
    ]


def test_chapter_05_holds_its_answer_to_the_closing_tables():
    """Reader r24b: "It depends on the exact checker" misled (no total time was saved with either checker); the
    answer's sampling cut and accuracy pair were in no table; a ratio of two medians within noise read "saves time"."""
    assert problems(CH05, chapter_05()) == []
    said = chapter05.answer()
    wrong = said.replace("**No.** On 3DC-7 no sampler's whole query saved 10 % or more", "It depends on the checker")
    assert problems(CH05, chapter_05(answer=wrong))[0].startswith("05: the answer's 'No' does not match")
    wrong = chapter05._paper_side().replace("gives OB and BT 14% and ", "gives OB ")  # r25b: Table 3's side
    assert problems(CH05, chapter_05(paper_side=wrong)) == [
        "05: the answer's paper side is not its Table 3 row: OB, ['OB', 'BT']"
    ]
    cut = re.search(r"by \d+–\d+ %", said).group()
    assert problems(CH05, chapter_05(answer=said.replace(cut, "by 49–61 %"))) == [
        "05: the answer's sampling cut is not the sampling table's: ('49', '61'), [78, 78, 72, 67]"
    ]
    pair = re.search(r"right on \d+% of uniform", said).group()
    assert problems(CH05, chapter_05(answer=said.replace(pair, "right on 91% of uniform")))[0].startswith(
        "05: the answer's accuracy pair is not a row of the accuracy table"
    )
    saving = {"BS": 0.83, "OB": 1.5, "G": 1.07, "BT": 1.67}  # not the record's: the lazy PRM's row (r57e, 05 item 1)

    def banded(nb: dict) -> list[str]:  # the band's reading alone, not the record's values (checked above)
        return [p for p in problems(CH05, nb) if "medians are not displayed" not in p]

    assert banded(chapter_05(of_medians=saving)) == []
    row = findings.ratio_table({"r": saving}).splitlines()[-1]  # a verdict where timing noise could make one
    nb = chapter_05(of_medians=saving)
    markdown = nb["cells"][-2]["outputs"][0]["data"]["text/markdown"]
    nb["cells"][-2]["outputs"][0]["data"]["text/markdown"] = markdown.replace(
        chapter05._noise_row(chapter05.MEDIANS_ROW, saving, costs.floors()["medians"]),
        row.replace("| r |", f"| {chapter05.MEDIANS_ROW} |"),
    )
    assert banded(nb) == [  # reader r38e: a tie within noise is a tie, a saving within noise says both
        "05: a ratio of two medians is read against timing noise wrongly: saves time (0.83)",
        "05: a ratio of two medians is read against timing noise wrongly: costs time (1.50)",  # inside 0.40–1.60
    ]


def test_chapter_05_holds_table_2s_valid_share_and_the_offices_collisions_to_its_prose():
    """Reader r19c: TPR 85 % and TNR 61 % at 74 % valid give 78 %, not Table 2's 71 %; the prose says the paper's set
    was nearer half valid than uniform samples, and that the office's collisions are of two kinds, both shown."""
    assert problems(CH05, chapter_05(shares=("80%", "76%"))) == [
        "05: Table 2's set is not nearer half valid than uniform samples: ('80', '76')"
    ]
    assert problems(CH05, chapter_05(office="| 2000 | 631 | 0 | 631 |")) == [
        "05: the office's collisions are not the two kinds the prose names: [['2000', '631', '0', '631']]"
    ]
    assert problems(CH05, chapter_05(office="| 2000 | 631 | 186 | 440 |")) == [
        "05: the office's collisions are not the two kinds the prose names: [['2000', '631', '186', '440']]"
    ]


# ---- chapter 01: the checker-cost words against section 3's ratios ----


OPENING_01 = (
    "gives the same answers as FCL (a general-purpose collision library, called from Python here), many times faster\n"
    "  per check: section 3's last line prints how many times in your run."
)


def chapter_01(low: int = 46, high: int = 90, closing: dict[str, str] | None = None, said: str = OPENING_01) -> dict:
    """A chapter 01 whose opening ``said`` how much longer FCL took, whose section 3 printed FCL's time per check as
    ``low``-``high`` times the fast exact checker's, and whose closing table's last column gives the free share, 80%
    unless ``closing`` gives a scenario's."""
    line = f"Same answers, but FCL took {low}–{high}x the fast exact checker's time per check in this run."
    closed = [
        "| scenario | blocks: **ours** / paper | occupied | robot size at q = 0: **ours** / paper | free |",
        "| --- | --- | --- | --- | ---: |",
    ]
    for name in ("2ds", "3do", "3dc7", "3dc9"):
        closed.append(
            f"| {name} | **3–5** / 3–5 | 10% | **0.5×0.5** / 0.5 × 0.5 | {(closing or {}).get(name, '80%')} |"
        )
    key = f"MD:**The key number:** the same answers, but FCL took {low}–{high}x the fast exact checker's time."
    summary = f"MD:- Same answers, but FCL took {low}–{high}x the fast exact checker's time per check in this run."
    nb = executed(key, "2ds   81.9% valid   differ from FCL: {}\n" + line, "MD:" + "\n".join(closed), summary)
    nb["cells"].append({"cell_type": "markdown", "source": [said]})  # the first Markdown cell: the opening
    return nb


CH01 = "01_workspaces_and_collision.ipynb"


def test_chapter_01_passes_the_ratios_its_words_describe():
    assert problems(CH01, chapter_01()) == []  # the full-size site of reader r39a: 48-57x in 3D, 90x in 2D
    assert problems(CH01, chapter_01(9, 127)) == []  # quick, beside load
    assert problems(CH01, chapter_01(33, 58)) == [] and problems(CH01, chapter_01(46, 101)) == []  # quick, full


def test_chapter_01_fails_words_its_ratios_do_not_give():
    """Review r26a: "roughly ten to a hundred times" beside 46, 53 and 54 times. Reader r39a: the table of every
    checker's rates left the chapter; the line it kept must be printed, run low to high, and say "many times"."""
    assert problems(CH01, chapter_01(2, 60)) == ["01: FCL took 2x the fast exact checker's time: not many times"]
    assert problems(CH01, chapter_01(60, 46)) == ["01: the line's range 60–46x runs backwards"]
    nb = chapter_01()
    nb["cells"][1]["outputs"][0]["text"] = "FCL took 46x"
    nb["cells"][-2]["outputs"][0]["data"]["text/markdown"] = "- FCL took 46x"  # the summary repeats section 3's line
    assert problems(CH01, nb) == ["01: section 3 does not print FCL's time against the fast exact checker's"]
    assert problems(CH01, chapter_01(closing={"3do": "40%"})) == [
        "01: 3do: 40% of uniform configurations free, not most"
    ]  # the prose: "Uniform samples are mostly valid (the **free** column)"
    # reader r48a: the opening's typed "30–100 times" beside the run's "50–103x"; it now says "many times" only
    typed = OPENING_01 + " (about 30–100 times in our runs)"
    assert problems(CH01, chapter_01(50, 103, said=typed)) == [
        "01: the opening types a range, '30–100 times', beside section 3's 50–103x"
    ]
    assert problems(CH01, chapter_01(said="in a fraction of its time")) == [
        '01: the opening does not say "(a general-purpose collision library, called from Python here), many times'
        " faster per check: section 3's last line prints how many times\""
    ]
    # reader r51a: the bullet blamed the library, the fold the one Python call per link
    assert problems(
        CH01, chapter_01(said="general-purpose collision library; FCL is the slow one, many times slower per check")
    ) == [
        '01: the opening does not say "(a general-purpose collision library, called from Python here), many times'
        " faster per check: section 3's last line prints how many times\""
    ]
    # reader r54a: the call's detail in the answer, and no pointer to the ratio section 3 prints
    heavy = "FCL as called here (a Python call for each link the pre-filter cannot clear) is the slow one, many times"
    assert problems(CH01, chapter_01(said=heavy + " slower per check")) == [
        '01: the opening does not say "(a general-purpose collision library, called from Python here), many times'
        " faster per check: section 3's last line prints how many times\""
    ]


def test_chapter_01_repeats_section_3_s_ratio_under_the_answer_and_in_the_summary():
    """Reader r58a: the answer said "many times faster" and the number stood 9 screens down; the line under the
    answer and the summary's last bullet now print it, and must print section 3's."""
    nb = chapter_01(46, 90)
    nb["cells"][0]["outputs"][0]["data"]["text/markdown"] = "*The key number appears here once section 3 has run.*"
    nb["cells"][-2]["outputs"][0]["data"]["text/markdown"] = "- Same answers, but FCL took 40–90x the time."
    assert problems(CH01, nb) == [
        "01: the line under the answer does not say '**The key number:** the same answers, but FCL took 46–90x'",
        "01: the summary does not repeat section 3's 46–90x",
    ]


def test_chapter_01_holds_its_code_blocks_to_the_page_width():
    """Review r13b: a table's sixth column was cut off at the page's width; a code block's line too."""
    nb = chapter_01()
    nb["cells"].append({"cell_type": "markdown", "source": ["```\n", "─" * 79 + "\n", "```\n"]})
    assert problems(CH01, nb) == [f"01: a code block's line of 79 characters, more than 78: {'─' * 40}..."]


# ---- run to run: chapter 04's verdicts beside a busy machine ----


@pytest.mark.slow
def test_chapter_04_verdicts_do_not_flip_beside_a_busy_process_per_core(quick_notebooks):
    """Chapter 04 in quick mode twice, the second time beside one busy process per core: no verdict may turn from
    "saves time" / "network cheaper" into "costs time" / "network dearer" or back (a verdict marked \\*, no clear
    evidence, and a tie may come and go: that is what they are for)."""
    from chapter_claims import verdicts

    from tools.notebook_runner import run_notebook

    chapter = ROOT / "notebooks" / CH04
    quiet = run_notebook(chapter)
    busy = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(os.cpu_count() or 1)]
    try:
        loaded = run_notebook(chapter)
    finally:
        for process in busy:
            process.kill()
            process.wait()
    assert quiet.problem() is None and loaded.problem() is None
    first, second = verdicts(quiet.notebook), verdicts(loaded.notebook)
    assert len(first) >= 8 + 2 + 4 and first.keys() == second.keys()  # planning, eager, throughput, crossover rows
    flipped = {
        key: (first[key], second[key])
        for key in first
        if {first[key], second[key]} & set(findings.POSITIVE) and {first[key], second[key]} & set(findings.NEGATIVE)
    }
    assert not flipped, f"verdicts flipped with the machine's load: {flipped}"


def test_chapter_04_holds_its_answer_with_python_fcl_on_both_sides_to_the_record():
    """Review r19a: "the honest answer is 'no, against a fast compiled checker'". The chapter names the checker and
    says what the run with python-fcl on both sides recorded, in the first code cell's bullet (review r28d) and in
    full in section 6; a record that says otherwise fails the bullet, and the prose's words fail where the record
    does not bear them: "mostly a tie" where every median ties, "saved sampling time" where a sampling cell tied,
    "No." where the run saved more than half the paper's count, words of another verdict."""
    nb = chapter_04()
    facts = checker_scope.slow_checker()
    assert chapter_claims._slow_checker(nb, facts) == []
    mostly = chapter_claims.SLOW_MOSTLY_TIES
    nb["cells"][-2]["source"] += f" With python-fcl, {mostly}; it {chapter_claims.SLOW_SAMPLING}."
    assert chapter_claims._slow_checker(nb, facts) == []
    ties = dataclasses.replace(facts, own=(1.0,) * len(facts.own))
    said = chapter_claims._slow_checker(nb, ties)
    assert said[0].startswith("04: section 6 does not print the slow checker's record")
    assert said[1].startswith("04: the first code cell's bullets on python-fcl say ")
    assert said[2:] == [  # reader r40d: the answer's count on python-fcl is computed, so no word of the prose to hold
        f"04: the prose says '{mostly}'; the record: {{'a tie': {len(facts.own)}}}",
    ]
    tied = dataclasses.replace(facts, sampling=(*facts.sampling[:-1], 0.05))
    said = chapter_claims._slow_checker(nb, tied)  # r59d: python-fcl's sampling range left the answer (section 6's)
    assert said[0].startswith("04: section 6 does not print the slow checker's record")
    assert said[1:] == [
        f"04: the prose says '{chapter_claims.SLOW_SAMPLING}'; the record: {dict(tied.sampling_verdicts())}",
    ]
    saving = dataclasses.replace(facts, totals=(0.5,) * len(facts.totals))  # every cell saves, by means
    assert (
        f"04: the answer says '{chapter_claims.ANSWER_NO}'; counted the paper's way: ours {len(facts.totals)}, the "
        "paper's 10" in chapter_claims._slow_checker(nb, saving)
    )
    nb["cells"][-2]["source"] = nb["cells"][-2]["source"].replace(
        f"With python-fcl, {mostly}", "With python-fcl, each query's total time was longer for every sampler measured"
    )
    assert f"04: the prose says '{chapter_claims.SLOW_TOTAL[findings.COSTS][0]}'; the record: " in " ".join(
        chapter_claims._slow_checker(nb, facts)
    )
    nb["cells"][-2]["source"] += " Against a slow checker on both sides (python-fcl): only the sampling stage."  # r21a
    saved = dataclasses.replace(facts, own=(0.5, *facts.own[1:]))  # one pair's total shorter, whatever the record
    assert f"04: the prose says '{chapter_claims.SLOW_ONLY_SAMPLING}'; the record: " in " ".join(
        chapter_claims._slow_checker(nb, saved)
    )


def test_a_cell_that_draws_a_promised_figure_must_show_one():
    """Review r24a: section 3's 3DC-7 figure was drawn but was not its cell's last expression, so the page had none."""
    drawn = {"cell_type": "code", "source": 'planning_times(planning_3d, title="t")\ndisplay(Markdown("line"))\n'}
    picture = {"output_type": "display_data", "data": {"image/png": "", "text/plain": "<Figure>"}}
    callback = {"cell_type": "code", "source": "def show(s):\n    return planning.samplers(ws, s)\n", "outputs": []}
    nb = {"cells": [{**drawn, "outputs": [{"output_type": "display_data", "data": {"text/markdown": "line"}}]}]}
    assert chapter_claims.figures_shown(nb, chapter_claims.FIGURES_04, "04") == [
        "04: a cell draws planning_times( but shows no figure"
    ]
    nb = {"cells": [{**drawn, "outputs": [picture]}, callback]}  # a widget's callback draws on demand: not counted
    assert chapter_claims.figures_shown(nb, chapter_claims.FIGURES_04, "04") == []


def test_chapter_05_holds_section_6s_why_to_the_records_costs():
    """Readers r28e, r29e, r30e: the answer says why prediction did not pay, a network answer dearer than a compiled
    check and cheaper than a python-fcl one; the record's line in the answer must say so."""
    cheaper = "takes as long as 0.5 compiled exact checks, and one python-fcl check as long as 6.0 network answers"
    assert problems(CH05, chapter_05(costs=cheaper)) == [
        "05: the answer's costs do not make the network dearer than a compiled check, cheaper than python-fcl: "
        "('0.5', '6.0')"
    ]


def test_chapter_04_a_dagger_in_a_table_comes_with_its_reason():
    """Reader r45d: section 3's table marked "costs time†" while the line under it gave no reason."""
    table = "| 2DS | BS | costs time†<br>(median 1.20; middle half 0.60–1.44) | 5 / 6 | 4 |"
    cell = {"cell_type": "code", "outputs": [{"output_type": "display_data", "data": {"text/markdown": table}}]}
    assert chapter_claims._dagger_said({"cells": [cell]}) != []
    cell["outputs"][0]["data"]["text/markdown"] += "\n\n† marks no clear evidence: its middle half includes an edge"
    assert chapter_claims._dagger_said({"cells": [cell]}) == []
