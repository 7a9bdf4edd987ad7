"""The answer with python-fcl on both sides, read from docs/results.md's section of that run (review r19a)."""

from __future__ import annotations

import dataclasses
import re

import pytest

from toolkit.experiments import paper_numbers
from toolkit.teaching import chapter04, chapter04_paper, checker_scope, costs, recorded

TABLE3 = (
    "`strong --planner paper --baseline paper-fcl-alike`, Table 3: time improvement ratio (without − with) / without"
)
OWN = (
    "`strong --planner paper --baseline paper-fcl-alike`, Time with prediction / Table 3's baseline, "
    "each query's own ratio"
)
RECORDED = {  # the section as tools.recorded_results reads it: 3DC-7 as measured on 5 December, and a made-up 3DC-9
    checker_scope.SLOW: {
        TABLE3: {
            "without": None,
            "columns": ["", "Sampling BS", "Sampling OB", "Total BS", "Total OB"],
            "rows": [
                ["3dc7", "**78%** / 49%", "**78%** / 58%", "**9%** / -2%", "**-12%** / 14%"],
                ["3dc9", "**40%** / 39%", "**5%** / 60%", "**20%** / 18%", "**-30%** / 20%"],
            ],
        },
        OWN: {
            "without": None,
            "columns": ["", "Total BS", "Total OB"],
            "rows": [["3dc7", "0.94 (0.81–1.03)", "1.06 (0.97–1.17)"], ["3dc9", "0.85 (0.8–0.9)", "1.30 (1.1–1.4)"]],
        },
    }
}
ONE = checker_scope.SlowChecker(  # 3DC-7 as recorded on 5 December: Table 3's cells and each query's own ratio
    scenarios=("3DC-7",),
    sampling=(0.78, 0.78, 0.72, 0.67),
    papers_sampling=(0.49, 0.58, 0.51, 0.61),
    totals=(0.09, -0.12, -0.03, 0.01),
    papers_totals=(-0.02, 0.14, -0.09, 0.54),
    own=(0.94, 1.06, 0.99, 1.02),
)


def test_it_reads_whatever_scenarios_the_section_holds():
    read = checker_scope.slow_checker(RECORDED)
    assert read == checker_scope.SlowChecker(
        scenarios=("3DC-7", "3DC-9"),
        sampling=(0.78, 0.78, 0.40, 0.05),
        papers_sampling=(0.49, 0.58, 0.39, 0.60),
        totals=(0.09, -0.12, 0.20, -0.30),
        papers_totals=(-0.02, 0.14, 0.18, 0.20),
        own=(0.94, 1.06, 0.85, 1.30),
        edge=1,  # 0.85 saves, within the record's noise edge (0.18) of 1
    )
    packaged = checker_scope.slow_checker()  # docs/results.md, as the package carries it: a row per scenario
    ratios = recorded.query_ratios(checker_scope.SLOW)
    assert packaged.scenarios == tuple(checker_scope.NAMES[key] for key in ratios)
    assert packaged.own == tuple(r for row in ratios.values() for r in row.values())


def test_a_tie_in_every_sampler_is_said_as_one():
    assert checker_scope.slow_sentence(ONE) == (
        "With a slow exact checker on both sides (python-fcl, 3DC-7; 100 recorded queries a scenario), our accurate "
        "network saved 67–78 % of the sampling time by Table 3's means (the paper's Table 3: 49–61 %), but each "
        "query's total time was a tie for every sampler (the median of each query's own ratio 0.94–1.06; Table 3's "
        "totals from −12 to +9 %, the paper's from −9 to +54 %)."
    )


def test_the_answer_leaves_the_ranges_out():
    """Review r24a: the answer's second item in one sentence, without the ranges of the totals."""
    short = checker_scope.slow_sentence(ONE, ranges=False)
    assert short == checker_scope.slow_sentence(ONE).split(" (the median of each query's own ratio")[0] + "."
    assert "Table 3's totals" not in short


def test_mixed_verdicts_are_counted_never_called_a_tie():
    said = checker_scope.slow_sentence(checker_scope.slow_checker(RECORDED))
    assert "(python-fcl, 3DC-7 and 3DC-9;" in said
    assert "saved sampling time (Table 3's means) in 3 of 4 cells" in said  # 5 % is a tie
    assert (
        "by the median own ratio, total time was 10 % or more shorter in 1 of the 4 cells, a tie in 2 and 10 % or "
        "more longer in 1" in said  # reader r49d, item 2: "shorter" is a change of 10 % or more, said so
    )
    assert "for every sampler" not in said


@pytest.mark.parametrize("own, words", [((0.8, 0.85), "shorter"), ((1.1, 1.5), "longer"), ((0.91, 1.09), "a tie")])
def test_each_unanimous_verdict_has_its_words(own, words):
    said = checker_scope.slow_sentence(dataclasses.replace(ONE, own=own))
    assert f"each query's total time was {words} for every sampler (the median of each query's own ratio" in said


def test_like_for_like_counts_savings_of_ten_percent_or_more_by_means_with_our_tie_band():
    """Review r23a: the page printed Table 3's range of totals, never the count the paper's own reader makes."""
    assert checker_scope.like_for_like(ONE) == (
        "Read by our 10 % tie band, by means (Table 3's statistic), that run saved 10 % or more of the total time in "
        "none of its 4 cells, the paper's Table 3 in 2 of the same 4."
    )
    edge = dataclasses.replace(ONE, totals=(0.10, 0.09, 0.5, -0.2))  # 10 % is a saving (0.90 as printed)
    assert "saved 10 % or more of the total time in 2 of its 4 cells" in checker_scope.like_for_like(edge)
    assert "as the paper counts" not in checker_scope.like_for_like(edge)  # reader r47d: the tie band is ours


def test_the_answer_is_three_plain_sentences_read_from_the_record():
    """Reader r44d, item 1: the answer in two sentences a student can repeat, by one statistic (the median of each
    query's own ratio, named so: reader r45d, item 3):
    both checkers counted by the one rule, then the paper's Table 3 in one clause; the counts by means are section
    6's, which says plainly that by means almost nothing of ours is beyond the noise band (0.52-1.48)."""
    said = chapter04.answer()
    sentences, _, rest = said.partition("\n\n")
    box, _, table = rest.partition("\n\n")
    assert sentences == (  # reader r59d, lifts 1-2: one statistic's count, both halves of the why; r61d, item 4:
        "**No.** With an accurate network inside the paper's own planner (Algorithm 1), prediction saved 10 % or more "
        "of a typical query's time in none of 16 settings against our fast exact checker and in 3 of 16 against slow "
        "python-fcl. Sample checks are at most 18 % of a query (34 % with python-fcl), and a network call costs more "
        "than the fast check, so sampling itself got slower; what else grew in the slower settings is left open "
        "(section 6)."
    )  # r62d, item 1: what the two reasons leave open is the growth after sampling, not costs beyond sampling's share
    assert len(sentences.split()) < 85 and "Table 3" not in sentences  # r59d item 1: like with like, in the fold
    for word in ("own ratio", "noise band", "cell", "borrow", "preset", "\\*", "†"):  # r59d item 3: terms after the box
        assert word not in sentences
    lines = box.splitlines()  # common57: a visible box of at most four lines, each term defined
    assert lines[0] == "> **How to read the ratios**" and len([line for line in lines if line.startswith("> -")]) == 4
    for term in ("*ratio*", "*cell*", "*median own ratio*", "0.90–1.10 is a *tie*", "0.82–1.18 is the median own"):
        assert term in box
    assert "<details>" not in box
    assert costs.clear_mean_savings(recorded.ALGORITHM_1) == []
    assert costs.mean_verdicts(recorded.ALGORITHM_1)[chapter04_paper.SAVES] == 3  # the record as of r51d
    ours, folded = table.split("\n\n", 1)
    assert ours.splitlines()[2:] == [
        "| our fast exact checker | none | 7 | 9 (5 beyond the noise band) |",
        "| python-fcl on both sides (not timed twice: it borrows the fast checker's noise band) "
        "| 3 (2 beyond the noise band) | 13 | none |",
    ]
    head, lead, papers, band, end = folded.split("\n\n")  # reader r49d, item 3: the by-means table folded
    assert head.startswith("<details><summary>The same 16 cells by mean times") and end == "</details>"
    assert lead == (  # reader r54d, item 3: the run names, the counts by means, the sampling claim, in the fold
        "From the recorded run `strong --planner paper` (100 queries a scenario, `docs/results.md`; python-fcl's row: "
        "the same run with `--baseline paper-fcl-alike`). By means, Table 3's statistic, 3 of 16 cells took 10 % or "
        "more less time with our fast checker, none beyond that statistic's noise band; the paper's Table 3 takes "
        "less time in 13 of its 16 cells, 10 % or more less in 10. The two statistics lie furthest apart in 3DC-9 OB: "
        "by its median own ratio it costs time (1.24), by means it saves time (0.72); a mean follows a few slow "
        "queries."
    )  # reader r58d, item 2: the sampling claim moved up into the answer's second sentence
    assert papers.splitlines() == [  # its own header: Table 3 is by means; one count a column (r49d, items 2-3)
        "| 16 cells, by mean times | less / more time | faster | tie | slower |",
        "| --- | --- | --- | --- | --- |",
        "| the paper's Table 3 | 13 / 3 | 10 | 6 | none |",
        "| ours, fast checker | 5 / 11 | 3 (none beyond the noise band) | 7 | 6 (2 beyond the noise band) |",
        "| ours, python-fcl (noise band borrowed) | 11 / 4, 1 equal (2DS BS) | 2 (none beyond the noise band) | 12 "
        "| 2 (none beyond the noise band) |",
    ]
    for row in papers.splitlines()[2:]:  # each row adds up to its 16 cells, both ways (reader r49d, item 3)
        counts = [
            int(w)
            for c in row.replace("none", "0").replace(",", " ").split(" | ")[1:]
            for w in c.split("(")[0].split()
            if w.isdigit()
        ]
        assert sum(counts[:-3]) == 16 and sum(counts[-3:]) == 16, row
    assert band == (  # reader r48d, item 2: one line on why each query's own ratio decides; r49d: the words
        "*Less time* and *more time* count any ratio of mean times below or above 1 (*equal*: 1.00 as printed); "
        'Table 3\'s 3 cells with more time are 2–9 % more, and of 3DO BT the paper says "a slow-down". *Faster* '
        "counts only 0.90 or less, *slower* only 1.10 or more: our 10 % tie band, not the paper's; we read the "
        "paper's cells and ours with it alike. Why each query's own ratio decides: a ratio of means divides two sums "
        "over the same 100 queries, and a few slow queries weigh on a mean, so its noise band is wide (0.52–1.48); "
        "each query's own ratio divides one query's two times, taken in turn (0.82–1.18)."
    )  # reader r61d, item 4: python-fcl's borrowed band is said by its rows, so this line no longer repeats it
    assert sentences.count(". ") == 1 and "By mean times" not in said  # two sentences (r59d); no by-means tally
    assert chapter04.by_means() == (
        "**By mean times**, the paper's statistic, prediction saved 10 % or more in 3 cells with our fast checker and "
        "2 with python-fcl, none beyond the noise band of a ratio of means (0.52–1.48). So by means our runs cannot "
        "tell savings of Table 3's size from timing noise: a ratio of means divides two sums over the same 100 "
        "queries, and a few slow queries weigh on a mean. That is why this page judges by each query's own ratio, "
        "whose noise band is 0.82–1.18."
    )
    line = chapter04.mark_line()  # reader r44d, item 2: one visible sentence, the one rule folded under it
    visible, _, folded = line.partition("<details>")
    assert visible.strip() == (
        'The hatched band is the noise band of "How to read the ratios", 0.82–1.18; a tie never carries \\*.'
    )
    assert "take 2 times that, both ways, because a single repeat understates timing noise" in folded
    assert "0.82–1.18 = 1 ± 2 × 0.09 (timing alone: 0.96–1.09)" in folded
    assert "A ratio of mean times: 0.52–1.48; a ratio of medians: 0.40–1.60." in folded
    assert "as measured" not in line and "doubled" not in line  # one rule for every band (common46)
    assert line.count("† means one thing") == 1 and line.count("†") == 1  # reader r44d, item 5: one meaning
    assert (  # reader r55d, item 3: one plain sentence why the recorded runs carry no †
        "The recorded runs carry none, because a middle half shows how the queries spread, not how sure their median "
        "is" in folded
    )
    assert "3 of these 4 cells" in costs.cost_table()  # the same count, under the table it comes from
    facts = checker_scope.slow_checker()
    full = chapter04.full_answer()
    assert "(a tie in 7, a cost in 9)" in full  # the same counts, in full
    assert checker_scope.slow_sentence(facts, ranges=False) in full and checker_scope.like_for_like(facts) in full
    assert (  # reader r49d, item 2: "saved" is 10 % or more, said so; cells, not pairs
        "saved 10 % or more in 3 of the 16 cells with our fast checker (7 tied, 6 took 10 % or more longer) and in 2 "
        "with python-fcl" in full
    )
    assert "those clear of the noise band: none with our fast checker, none with python-fcl" in full  # folded


def test_the_noise_band_is_a_mark_on_the_tables_verdicts_explained_once():
    """Review r32d: the noise band in numbers, from the record; reader r33d: a verdict inside it keeps its word and
    carries a mark, explained once (reader r40d: beside the answer figure); section 6 takes one new fact from its
    table (r40d, lift 6)."""
    assert chapter04.edge_line() == (  # reader r42d: the answer's 3, the 2 here; r47d: 10 % or more is our band's
        "**Take from it:** in the 10 cells where the paper's Table 3 saves 10 % or more, our median own ratio saved in "
        "none with our fast checker and in 2 with python-fcl (2DS OB\\*, 3DC-9 OB; \\* inside the noise band; the "
        "third python-fcl saving, 3DO BT, is a cell where Table 3 does not save 10 % or more)."
    )
    table, more = checker_scope.section_6({"2DS": 5.0})
    assert "| costs time\\*<br>(1.13) | costs time\\*<br>(1.17) | a tie<br>(1.07) | costs time\\*<br>(1.10) |" in table
    assert "| a tie<br>(1.00) | saves time\\*<br>(0.87) | a tie<br>(0.94) |" in table  # python-fcl 2DS OB
    assert "saves time<br>(0.83)" in table  # the paper's row is never marked: we cannot time it
    assert "| saves time\\*<br>(0.88) |" in more  # the `paper` preset's one saving against the lazy PRM (2DS BT)
    # a ratio of means by the means band, 0.52-1.48 (common46: one rule; 1.22 and 0.72 inside it, 1.53 not)
    assert "| 3DO, ours (`strong` preset), means<br>saves / tie / costs: 1 / 2 / 1 | saves time\\*<br>(0.86) " in more
    assert "| costs time\\*<br>(1.22) | a tie<br>(0.99) |" in more and "| saves time\\*<br>(0.72) |" in more
    assert "| costs time<br>(1.53) |" in more
    assert "(1 of the 3 savings marked \\*)" in chapter04.full_answer()


def test_means_apart_names_where_a_mean_and_the_median_query_part():
    """Review r32d: "while the median query did not save" was false for two of the five bars below the band."""
    assert chapter04.means_apart() == (
        "of the 5 cells (3 fast checker, 2 python-fcl) where a mean saved 10 % or more, the median own ratio did not "
        "in 3 (fast checker 2DS BT, 3DC-9 OB, 3DO BS) and did in 2 (python-fcl 3DC-9 OB, 3DO BT)"
    )
    assert "(*The statistic*, below): where those saved, a mean can save while most queries did not; of the 5 " in (
        chapter04.full_answer()
    )


def test_sampling_words_counts_the_cells_where_not_every_one_saved():
    tied = dataclasses.replace(ONE, sampling=(0.5, 0.05, 0.3, 0.2))  # 5 % saved: a tie
    assert checker_scope.sampling_words(tied) == "shorter in 3 of the 4 cells"
    every = dataclasses.replace(ONE, sampling=(0.5, 0.4, 0.3, 0.2))
    assert checker_scope.sampling_words(every) == "20–50 % shorter"


def test_our_means_are_the_means_rows_by_the_medians_labels():
    means = checker_scope.our_means()
    assert set(means) == {label for label in checker_scope.compact() if "ours" in label}
    rows = checker_scope.against_algorithm_1()
    assert means["3DC-9, ours (`strong` preset), medians"] == rows["3DC-9, ours (`strong` preset), means"]


def test_beyond_sampling_sets_the_papers_own_arithmetic_beside_ours():
    """Review r31d, item 3: the paper's savings exceed its whole sampling time (3DO G 4.1 s against 0.21 s, 3DC-9 BT
    2.6 s against 0.10 s, from its §V mean times), which skipping the samples' checks cannot explain; ours with
    python-fcl has five such cells by means, the fast checker four (reader r54d: any saving, as for the paper)."""
    said = chapter04_paper.beyond_sampling()
    assert "exceeds all the sampling time without prediction in 10 of its 16 cells" in said
    assert "3DO G saves 4.10 s while its sampling took 0.21 s, 3DC-9 BT 2.60 s against 0.10 s." in said
    assert "in 7 of those 10 cells the paper's standard deviation of a query's time exceeds the saving" in said
    # reader r34d, contradiction 1: both our runs, the fast checker's cells too; reader r54d, contradiction 1: one
    # rule for the paper's and ours (any saving larger than all of sampling), so ours are 9, not only the 4 of 10 %+
    assert "We count every saving larger than that, of any size, for the paper and for ours." in said
    assert "By the same rule ours have 9 such savings by means" in said
    assert (
        "fast checker: 2DS BT 13 % against 7.6 %, 3DC-9 OB 28 % against 8.4 %, 3DO BS 14 % against 0.6 %, 3DO G 1 % "
        "against 0.6 %;" in said
    )
    assert "python-fcl: 3DC-7 BS 9 % against 0.5 %, 3DC-9 BS 7 % against 0.3 %, 3DC-9 OB 34 % against 10.6 %," in said
    assert "Counting only savings of 10 % or more, the paper has 8 and ours 4." in said
    # common46: by means each of ours lies inside the means band (0.52-1.48), so no story of a saving beyond sampling
    assert said.endswith(  # reader r51d, item 2: by each query's own ratio one python-fcl saving is, clearly
        "Each of our 9 lies inside the noise band of a ratio of means (0.52–1.48): within timing noise, so no "
        "evidence of a saving larger than sampling. By each query's own ratio python-fcl's 3DC-9 OB and 3DO BT saved "
        "time beyond that statistic's noise band; no table here splits an own ratio into stages (the fold under the "
        "answer's *Why*)."
    )
    assert "did save more than all of sampling" not in said  # reader r56d, item 2: like with like only
    assert "another roadmap can explain it" not in said.split("ours have")[1]


def test_the_lazy_prm_fold_explains_a_mean_that_saved_where_the_ratio_of_medians_did_not():
    """Reader r38d, item 6: the lazy-PRM table's 2DS OB saved by means (0.26) beside "in none of the 8" by the ratio
    of medians; the line under it gives the spread of the time without prediction behind that mean."""
    assert checker_scope._lazy_means() == (
        "\n\n2DS OB saved by means (0.26), not by the ratio of medians (1.00): without prediction its query took 103 "
        "± 330 ms (mean ± std), a few slow queries."
    )
    assert checker_scope._lazy_means() in checker_scope.section_6({})[1]


def test_the_answers_why_gives_sampling_s_share_and_the_papers_savings_beyond_sampling_inline():
    """Reader r47d, item 3: the share of sampling in a query inline (not a pointer to section 6), and, lifted out of
    section 6's fold, that in 10 of the paper's 16 cells the total saving exceeds the whole sampling time."""
    said = chapter04_paper.why()
    shares = costs.sampling_shares(recorded.ALGORITHM_1)
    # reader r59d, lift 1: the answer gives the largest share; the fold under the why gives every cell's
    assert f"Sample checks are at most {100 * max(shares):.0f} % of a query" in chapter04.answer()
    assert f"| 3DC-7 | {100 * min(shares):.1f} / " in said  # the record as of r59d: 3DC-7 BS, 0.3 %
    assert (
        "in 10 of its 16 cells the total time saved exceeds the whole sampling time without prediction (e.g. 3DO G "
        "saves 4.10 s; its sampling took 0.21 s)." in said
    )
    assert said.startswith(  # reader r59d, lift 4: where the answer's two reasons are measured, in one paragraph
        "**Why, measured:** the answer's shares are of mean times without prediction (the fold below); a network "
        "call's cost against each checker is measured in [section 4](#4-is-the-network-a-cheaper-check)"
    )
    # reader r59d, lift 4 and item 3: what stays open said once, section 5's live cell said for what it shows
    assert chapter04_paper.roadmap() in said
    assert chapter04_paper.roadmap() == (
        "**What stays open:** by changing which samples are kept, prediction can change the roadmap, and so the time "
        'after sampling, which also holds the encoding. In 3 of the 4 costly cells section 6 splits ("Where the '
        'extra time went": 3DC-7 OB, 3DC-7 BT, 3DC-9 BT, 3DO OB), most of the extra mean time came after sampling. '
        "The recorded runs keep no node counts and do not time the encoding, so they cannot say what grew. "
        "[Section 5](#5-where-a-querys-work-goes-in-one-tie-cell-3dc-7-bs)'s live queries count the roadmap's "
        "nodes and edge points in both modes, in a cell whose recorded time ties."
    )
    assert sum(c.after_share > 0.5 for c in costs.dear_cells()) == 3 and len(costs.dear_cells()) == 4
    # reader r55d, item 2: the two sets of 10 cells named apart (the record as of r55d)
    assert (
        "These are not the 10 cells that save 10 % or more: 3DO BS and 3DO OB are only here, 2DS G and 3DC-7 OB "
        "only there." in said
    )
    why = said.split("\n\n")[0]
    assert why.endswith(  # r50d item 2: fcl's ties; r60d item 1: share × cut by means, computed from the record
        "yet 13 of 16 cells tie: by means, the sampling time it saves is under 10 % of a query in 14 of 16."
    )
    assert "Table 2" not in said  # reader r50d, item 4: the paper's Table 2 is another table
    assert "and for all four in the results page's checker throughputs. Against python-fcl the network is" in why
    # reader r53d, item 2: the accurate network's accuracy on the page, a one-line table from the record, chapter 03
    assert said.endswith(
        "[notebook 03](03_mlp_decision_boundaries.ipynb) trains and tests it):\n\n"
        "| right this often | 2DS | 3DC-7 | 3DC-9 | 3DO |\n| --- | ---: | ---: | ---: | ---: |\n"
        "| the `strong` network | 100 % | 95 % | 93 % | 99 % |"
    )
    # reader r53d, item 4: both runs' sampling shares by cell, folded, so the Why's ranges can be checked
    fold = chapter04_paper.shares_fold()
    assert fold in said and "| 3DC-9 | 0.3 / 0.3 | 8.4 / 10.6 | 1.2 / 0.4 | 8.3 / 6.5 |" in fold
    assert "| 3DO | 0.6 / 0.4 | 11.2 / 6.7 | 0.6 / 0.4 | 17.9 / 33.8 |" in fold
    # reader r51d, item 2: python-fcl's clear savings put to the paper's test; r56d, item 2: one treatment for both,
    # like with like (by means), read against the means band
    assert (
        "- **3DC-9 OB**: by each query's own ratio, its median query took 21 % less time; no table here splits that "
        "statistic into stages. Sampling is 11 % of its mean query without prediction. By means, its sampling took "
        "77 % less time, about 8 % of a mean query, and its total 34 % less time, more than all of sampling, but "
        "inside that statistic's noise band (0.52–1.48): no clear evidence of a saving larger than sampling." in fold
    )
    assert (
        "- **3DO BT**: by each query's own ratio, its median query took 28 % less time; no table here splits that "
        "statistic into stages. Sampling is 34 % of its mean query without prediction (the table's largest share). By "
        "means, its sampling took 49 % less time, about 17 % of a mean query, and its total 16 % less time, so skipped "
        "checks can explain it." in fold
    )
    assert "cannot explain it" not in fold and "another statistic" not in fold
    shares = costs.shares_by_cell(checker_scope.SLOW)
    assert round(100 * shares["3dc9", "OB"]) == 11 and max(shares, key=shares.__getitem__) == ("3do", "BT")


def test_table_3_is_quoted_exactly_and_our_tie_band_is_named_ours():
    """Common47 rule 1: Table 3 takes less time in 13 of 16 cells, 10 % or more less in 10; 3 are 2-9 % slower."""
    totals = chapter04_paper.table3_totals()
    assert (len(totals["all"]), len(totals["saved"]), len(totals["ten"])) == (16, 13, 10)
    assert sorted(totals["longer"]) == [0.02, 0.08, 0.09]
    assert chapter04_paper.papers_line() == (
        "The paper's Table 3 takes less time in 13 of its 16 cells, 10 % or more less in 10."
    )
    assert "the paper counts" not in checker_scope.papers_longer_sentence()
    assert "a tie by our tie band (the paper has none)" in checker_scope.papers_longer_sentence()


def test_the_paper_networks_table_sets_the_papers_reported_rates_beside_ours():
    """Reader r50d, item 4: "far less accurate than the paper reports (its table in the box)", and the box did not
    show what the paper reports; nor may "Table 2" name the results page's table, which is not the paper's."""
    said = checker_scope._paper_mlp()
    for name, key in checker_scope.SCENARIOS_4:  # in parentheses, each beside ours: five columns at most
        unseen = paper_numbers.MLP[key]["unseen"]
        assert re.search(
            rf"\| {name} \| \d+% \({unseen['tpr']:.0%}\) \| \d+% \({unseen['tnr']:.0%}\) \| \d+% "
            rf"\({unseen['acc']:.0%}\) / \d+% \| [^|]+ \|",
            said,
        )
    assert "| 3DC-7 | 100% (85%) | 0% (61%) | 76% (71%) / 76% |" in said  # the record as of r50d
    assert "in parentheses, its rates (Table 2)" in said
    assert said.startswith("**The `paper` preset's MLP (not the network the answer uses)**")  # reader r53d, item 2
    assert "regardless of their validity" in said and "unstated" not in said  # common53: the paper describes them
    assert "where the paper's rates would be right 72% to 88%" in said  # balanced: (TPR + TNR) / 2
    assert "From the results page's accuracy table (`docs/results.md`" in said and "Table 2's" not in said
