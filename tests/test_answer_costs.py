"""Chapter 04's answer figure (one panel, review r25a) and the split of the recorded costs (toolkit.teaching.costs)."""

from __future__ import annotations

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg

from toolkit.planning.sampling import PAPER_SAMPLERS
from toolkit.plots import answer, query_ratios
from toolkit.plots.alt import alt_text
from toolkit.plots.answer import answer_ratios
from toolkit.teaching import (
    chapter04,
    chapter04_encoding,
    chapter04_figures,
    checker_scope,
    costs,
    findings,
    recorded,
)
from toolkit.teaching.chapter04_figures import SERIES


def test_answer_ratios_draws_every_scenario_sampler_and_series_in_one_panel():
    rows = checker_scope.compact()
    fig = answer_ratios(rows, tie=findings.TIE)
    assert len(fig.axes) == 1
    drawn = sum(len(line.get_xdata()) for line in fig.axes[0].lines if line.get_marker() not in ("None", None, ""))
    assert drawn == sum(len(r) for r in rows.values()) == 48  # 4 scenarios x 4 samplers x 3 series
    assert "tie band, above 0.90 and below 1.10" in alt_text(fig)


def test_answer_ratios_puts_our_means_beside_the_papers_and_our_medians_under_them():
    """Reader r33d, figure 1: the large markers compared our medians with the paper's means. With ``means`` the figure
    has two panels on one scale: above, the paper's diamonds beside our means, filled (like for like); below, our
    medians, hollow, each with its whisker; a legend of three lines, one a series. Reader r34d: the means floor
    hatched above (named first in the legend), and the hollow markers in a legend of their own under the figure."""
    rows, means = checker_scope.compact(), checker_scope.our_means()
    fig = answer_ratios(rows, tie=findings.TIE, means=means, spans=checker_scope.spans(), names=SERIES)
    top, low = fig.axes
    assert top.get_ylim() == low.get_ylim()

    def marks(ax) -> dict[str, list]:
        return {line.get_marker(): line for line in ax.lines if line.get_marker() in answer.MARKERS}

    def values(ax, marker: str) -> list[float]:
        return sorted(v for line in ax.lines if line.get_marker() == marker for v in line.get_ydata())

    assert set(marks(top)) == {"D", "X", "h"} and set(marks(low)) == {"X", "h"}  # no diamond below: the paper's means
    assert values(top, "X") == sorted(v for label, r in means.items() if "python-fcl" not in label for v in r.values())
    assert values(top, "h") == sorted(v for label, r in means.items() if "python-fcl" in label for v in r.values())
    assert values(low, "X") == sorted(
        v for label, r in rows.items() if label.endswith("(`strong` preset), medians") for v in r.values()
    )
    assert all(line.get_markerfacecolor() == "none" for line in marks(low).values())  # hollow: the second statistic
    assert all(line.get_markerfacecolor() != "none" for line in marks(top).values())
    assert len(low.collections) == 32 and not top.collections  # a whisker a median, none above
    labels = [[t.get_text() for t in legend.get_texts()] for legend in fig.legends]
    assert labels[0] == ["a tie, 0.90–1.10", *SERIES.values()]  # r39d: the band named there, a line a series
    assert labels[1] == list(SERIES.values())[1:]  # the hollow markers, under the figure
    hatched = answer_ratios(rows, tie=findings.TIE, means=means, names=SERIES, floor=(0.84, 1.24))
    top = hatched.axes[0]
    hatches = [p for p in top.patches if p.get_hatch() == query_ratios.NOISE_HATCH]
    # reader r61d, item 5: one band below and one above the tie band, across the axis, not strips that read as error
    # bars (reader r57d's strips over our series only, gone); the legend and alt text say it is ours, not the paper's
    assert len(hatches) == 2
    assert all(line.get_markeredgewidth() >= 1.2 for line in top.lines if line.get_marker() == "D")  # outlined
    assert "hatched round the tie band, noise band of our ratios" in alt_text(hatched)
    # reader r45d, item 4: the legend says whose band it is
    assert (
        hatched.legends[0].get_texts()[0].get_text() == "noise band of our ratios of means (not the paper's), 0.84–1.24"
    )
    assert "round the tie band, noise band of our ratios of means (not the paper's), 0.84–1.24: twice" in (
        alt_text(hatched)
    )
    both = answer_ratios(  # reader r36d: the lower panel draws the median's band too
        rows, tie=findings.TIE, means=means, names=SERIES, floor=(0.84, 1.24), median_floor=(0.82, 1.18)
    )
    assert [p.get_hatch() for p in both.axes[1].patches].count(query_ratios.NOISE_HATCH) == 2
    # reader r45d, item 3: one name for the statistic, never "(medians)", the name of a ratio of medians' band
    assert both.legends[1].get_texts()[0].get_text() == "noise band of each query's own ratio, 0.82–1.18"
    assert "Hatched round the tie band below, noise band of each query's own ratio, 0.82–1.18" in alt_text(both)
    assert "medians)" not in alt_text(both) + " ".join(t.get_text() for g in both.legends for t in g.get_texts())
    assert [ax.get_title() for ax in both.axes][
        1
    ] == "Ours, each query's own ratio: its median (hollow), whiskers its middle half"
    said = alt_text(fig)
    assert "Above, means, Table 3's statistic: the paper's diamonds beside our two series' means, 48 points" in said
    assert "Below, our medians of each query's own ratio, hollow" in said and "32 points, 3 of them at or below" in said


def test_the_papers_squares_sit_inside_their_samplers_slot():
    """Reader r33d, figure 1: the squares sat on the dotted lines between samplers, so it was unclear whose they were.
    Every point lies at least a marker's width inside its sampler's slot (half a unit either side of its tick)."""
    fig = answer_ratios(checker_scope.compact(), tie=findings.TIE, means=checker_scope.our_means())
    for ax in fig.axes:
        ticks = ax.get_xticks()
        for line in ax.lines:
            if line.get_marker() in answer.MARKERS:
                for x in line.get_xdata():
                    assert min(abs(x - t) for t in ticks) <= 0.5 - 0.2 + 1e-9  # a marker inside (r44d: 0.30 apart)


def test_each_checker_keeps_one_look_and_no_marker_hides_another():
    """Reader r44d, items 3 and 7: one colour and marker per checker on the whole page, none a verdict shape of the
    home page's Figure 1 (circle, square, triangle), named in each legend; at one sampler the series stand at least a
    marker apart, centred on its tick."""
    shapes = {marker for _, marker in answer.CHECKERS.values()}
    assert len(shapes) == len(answer.CHECKERS) and not shapes & {"o", "s", "^", "v"}
    fig = chapter04_figures.answer_figure()
    ax = fig.axes[0]
    lines = [line for line in ax.lines if line.get_marker() in answer.MARKERS]
    assert sorted({line.get_marker() for line in lines}) == ["X", "h"]  # a line a scenario and series
    fast, slow = (np.concatenate([line.get_xdata() for line in lines if line.get_marker() == m]) for m in "Xh")
    assert np.allclose(slow - fast, answer.SPREAD) and np.allclose((slow + fast) / 2, ax.get_xticks())
    labels = [t.get_text() for t in fig.legends[0].get_texts()]
    assert labels[-2:] == [
        "ours, our fast checker (compiled in 3D, numpy in 2DS): crosses",
        "ours, python-fcl on both sides: hexagons",
    ]
    rates = chapter04_figures.rates_figure({"2DS": {"fast exact": 5e6, "python-fcl": 2e5, "network": 1e6}})
    drawn = {line.get_label(): (line.get_marker(), line.get_color()) for line in rates.axes[0].lines}
    assert drawn == {
        f"{c} ({answer.SHAPES[m]})": (m, color) for c, (color, m) in answer.CHECKERS.items() if c != "paper"
    }
    assert [t.get_text() for t in rates.legends[0].get_texts()] == list(drawn)
    assert answer.CHECKERS["fast exact"] == (lines[0].get_color(), lines[0].get_marker())  # one look in both figures


def test_cost_table_splits_the_cells_where_both_statistics_cost_time():
    """Reader r38d, item 8: the median query beyond timing noise and the mean time longer, not a cut-off of 1.25 that
    left out 3DC-9 OB (1.24, beyond noise; its mean time fell, so it has no extra time to split)."""
    cells = costs.dear_cells()
    assert {f"{c.scenario} {c.sampler}" for c in cells} == {"3DC-7 OB", "3DC-7 BT", "3DC-9 BT", "3DO OB"}
    for c in cells:
        assert c.ratio > costs.floors()["own"][1] and c.total[1] > c.total[0]
        assert abs(sum(c.after) + sum(c.sampling) - sum(c.total)) < 1e-12  # the two parts make the total
    table = costs.cost_table()
    assert table.count("\n| 3D") == len(cells) and f"in 3 of these {len(cells)} cells (the other: 3DO OB)." in table
    # reader r41d, 7: the cell beyond the noise band that the table leaves out is named under it, with why
    assert set(costs.left_out()) == {"3DC-9 OB"} and costs.left_out()["3DC-9 OB"] < 1
    assert "Left out: 3DC-9 OB (ratio of mean times 0.72), beyond the noise band by the median own ratio" in table
    shares = costs.sampling_shares(recorded.ALGORITHM_1)  # reader r45d, item 1: the top's "a small part" in numbers
    assert len(shares) == 16 and 0 < min(shares) < max(shares) < 0.2
    assert f"sampling took {100 * min(shares):.1f}–{100 * max(shares):.0f} % of the mean query in each of" in table
    assert "sampling took 0.3–18 % of the mean query in each of the run's 16 cells" in table  # the record's numbers


def test_after_share_is_the_part_of_the_extra_time_after_sampling():
    cell = costs.Cost("X", "BS", 1.5, (0.001, 0.003), (0.010, 0.016))  # extra 6 ms: 2 sampling, 4 after
    assert all(abs(a - b) < 1e-12 for a, b in zip(cell.after, (0.009, 0.013)))
    assert abs(cell.after_share - 4 / 6) < 1e-12 and abs(cell.sampling_share - 2 / 6) < 1e-12


def test_encoding_line_sets_the_live_encoding_beside_each_costly_cells_growth_after_sampling():
    """Reader r52d, item 2: "after sampling" includes the encoding; its measured size (section 5's live 3DC-7 queries)
    beside each costly 3DC-7 cell's growth after sampling, from the record: OB +11.7 ms, BT +2.8 ms."""
    said = chapter04_encoding.encoding_line({"with": [{"encode_s": 0.003}, {"encode_s": 0.0031}, {"encode_s": 0.0029}]})
    assert "The time after sampling includes encoding the workspace" in said and "spent 3.0 ms a query" in said
    assert "3DC-7 OB's time after sampling grew 11.7 ms, of which the encoding is about 26 %" in said
    assert "3DC-7 BT's time after sampling grew 2.8 ms, which the encoding alone could cover" in said
    assert "(3DC-9 BT +15.3 ms, 3DO OB +18.0 ms after sampling)" in said  # reader r53d, item 5: named, not counted
    assert "In 3DC-7 OB the encoding is smaller than that growth, so something else after sampling grew too" in said
    covers_neither = chapter04_encoding.encoding_line({"with": [{"encode_s": 0.001}]})
    assert "In 3DC-7 OB and 3DC-7 BT the encoding is smaller than that growth" in covers_neither
    assert "smaller than that growth" not in chapter04_encoding.encoding_line({"with": [{"encode_s": 0.02}]})
    assert chapter04_encoding.encoding_line({"with": [{"encode_s": 0.0}]}) == ""  # no network, no encoding to set


def test_split_sentence_gives_the_sampling_shares_of_the_dear_cells():
    shares = [round(100 * c.sampling_share) for c in costs.dear_cells()]
    said = costs.split_sentence()
    assert f"explains {min(shares)}–{max(shares)} % of the extra mean time" in said
    assert "grew with prediction, which the record does not break down" in said  # after sampling grew in each


def test_middle_halves_count_the_costs_and_savings_at_the_noise_edge():
    halves = costs.middle_halves("strong --planner paper")
    assert halves["2ds"]["BS"] == (1.13, 0.77, 1.59)
    assert abs(costs.noise_edge() - 0.18) < 1e-9  # twice timing's own reach, as docs/results.md's Figure 1
    assert costs.at_edge("strong --planner paper") == {findings.COSTS: 4}  # 2DS BS, OB, BT; 3DO BT (results.md)
    assert costs.at_edge(checker_scope.SLOW) == {findings.SAVES: 1}  # 2DS OB (hollow)


def test_chapter04_tables_name_every_sampler_and_each_failure():
    summary = {"success_rate": 1.0, "path_valid_rate": 1.0, "rounds": 1.5, "repairs": 0.25}
    failing = dict(summary, success_rate=0.5)
    tables = {"2DS": {s: {"without": summary, "with": failing if s == "BT" else summary} for s in PAPER_SAMPLERS}}
    said = chapter04.success_table(tables)
    assert said.count("\n| 2DS |") == 4 and "| 2DS | BT | 100% / 50% | 100% / 100% | 1.50 / 0.25 |" in said
    assert said.endswith("Queries that found no path, in this run: 2DS BT with prediction (50% found a path).")
    records = {
        "without": [
            {
                "connection_s": 0.004,
                "edge_checks": 2000,
                "sampling_s": 0.001,
                "query_s": 0.0,
                "total_s": 0.005,
                "nodes": 10,
                "samples_exact": 20,
                "predicted_checks": 0,
                "other_s": 0.0,
            }
        ]
    }
    stages, checks = chapter04.eager_tables(records)
    assert "| sampling | 1.0 |" in stages and "| other (encoding, set-up) | 0.0 |" in stages
    assert "| total | 5.0 |" in stages and "| without | 10 | 20 | 0 | 2,000 |" in checks
    assert "encoding the workspace for the network. Each row" in stages  # no encoding time: none said
    two = {"with": [dict(records["without"][0]), dict(records["without"][0], sampling_s=0.011, total_s=0.015)]}
    stages = chapter04.eager_tables(two)[0]  # reader r36d: section 3's construction, so the rows add up to the total
    rows = {line.split(" | ")[0][2:]: float(line.split(" | ")[1].rstrip(" |")) for line in stages.splitlines()[4:9]}
    assert rows["total"] == 10.0 and abs(sum(v for k, v in rows.items() if k != "total") - 10.0) < 0.2
    modes = {"without": records["without"], "with": [dict(records["without"][0], nodes=8, edge_checks=1500)]}
    assert chapter04.roadmap_line(modes) == (  # reader r61d, item 1: counts only, which a busy machine cannot move
        "With prediction the median roadmap had 8 nodes against 10 without, and its exact checker checked 1,500 edge "
        "points against 2,000: in both modes at least 98 % of the exact checks are edge points. Prediction can "
        "change that work only through the roadmap it leaves."
    )
    assert " ms" not in chapter04.roadmap_line(modes)

    def cell(ratios: list[float]) -> dict:
        return {"without": {"total_s_per_query": [1.0] * len(ratios)}, "with": {"total_s_per_query": ratios}}

    live = {"2DS": {"BS": cell([1.5, 1.6, 1.7]), "OB": cell([1.12, 1.15, 1.2])}}
    assert chapter04.live_line(live) == (  # reader r48d, item 3: section 3's result, visible
        "**In these live queries** prediction cost time in all 2 cells (the median of each query's own ratio, 1.15 "
        "to 1.60); 1 of the 2 verdicts is no clear evidence. A handful of queries illustrate; section 6's recorded "
        "runs decide."
    )
    live["3DC-7"] = {"BS": cell([0.5, 0.6, 0.7]), "G": cell([1.0, 1.0, 1.01])}
    assert "prediction cost time in 2, saved time in 1, tied in 1 of the 4 cells" in chapter04.live_line(live)
    crossing = {"2DS": {"G": cell([0.7, 1.0, 1.3])}}  # r62d: a tie whose middle half crosses a band edge counts
    assert "; 1 of the 1 verdicts is no clear evidence" in chapter04.live_line(crossing)
    folded = chapter04.path_checks(tables, {"2DS": dict.fromkeys(PAPER_SAMPLERS, "2 of 2")})
    assert folded.startswith("<details><summary>Success and path validity") and folded.endswith("</details>")
    assert "| 2DS | 2 of 2 | 2 of 2 | 2 of 2 | 2 of 2 |" in folded and said in folded


def test_repairs_table_gives_a_row_a_query_and_counts_the_runs_without_repairs():
    """Review r30d: section 2's repairs table built in chapter04, not on the page."""
    repairs = {
        (0, "BS"): 0,
        (0, "OB"): 3,
        (0, "G"): 0,
        (0, "BT"): 1,
        (1, "BS"): 0,
        (1, "OB"): 2,
        (1, "G"): 0,
        (1, "BT"): 0,
    }
    said = chapter04.repairs_table(repairs)
    assert "| 0 | 0 | 3 | 0 | 1 |\n| 1 | 0 | 2 | 0 | 0 |" in said
    assert said.startswith(
        "With prediction, 5 of 8 runs needed no repair; the most repairs in all: OB (5), the fewest: BS, G (0)."
    )
    assert "<details><summary>Repairs per query and sampler" in said and said.endswith("</details>")  # r41d: length


def test_the_ratio_figures_spread_their_labels_near_1_over_both_sides():
    """Reader r47d: 0.8, 0.9, 1, 1.1 and 1.2 were crammed within a few pixels on one side. The tie band's edges, 0.9
    and 1.1, are labelled on a right-hand axis; 0.8, 1 and 1.2 on the left (reader r48d: only where they bracket the
    own ratios' noise band, not on the means' figure); no two labels of a side touch."""
    for fig, near in ((chapter04_figures.answer_figure(), True), (chapter04_figures.answer_figure(means=True), False)):
        FigureCanvasAgg(fig).draw()  # the labels take their places when drawn
        renderer = fig.canvas.get_renderer()  # the Agg canvas's
        for ax in fig.axes:
            left = [t for t in ax.get_yticklabels(which="both") if t.get_visible() and t.get_text()]
            said = {t.get_text() for t in left}
            assert ({"0.82", "1.18"} <= said) == near and "1" in said and "0.9" not in said  # r49d: the band's edges
            assert not {"0.8", "1.2"} & said
            (right,) = ax.child_axes
            assert [t.get_text() for t in right.get_yticklabels()] == ["0.90", "1.10"]  # reader r59d: as the legend
            for labels in (left, right.get_yticklabels()):
                boxes = sorted((t.get_window_extent(renderer) for t in labels), key=lambda b: b.y0)
                assert all(b.y0 - a.y1 >= 2 for a, b in zip(boxes, boxes[1:]))  # at least 2 pixels apart
