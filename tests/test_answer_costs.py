"""Chapter 04's answer figure (one panel, review r25a) and the split of the recorded costs (toolkit.teaching.costs)."""

from __future__ import annotations

from toolkit.plots.alt import alt_text
from toolkit.plots.answer import answer_ratios
from toolkit.teaching import checker_scope, costs, findings


def test_answer_ratios_draws_every_scenario_sampler_and_series_in_one_panel():
    rows = checker_scope.compact()
    fig = answer_ratios(rows, tie=findings.TIE)
    assert len(fig.axes) == 1
    drawn = sum(len(line.get_xdata()) for line in fig.axes[0].lines if line.get_marker() not in ("None", None, ""))
    assert drawn == sum(len(r) for r in rows.values()) == 48  # 4 scenarios x 4 samplers x 3 series
    assert "tie band, 0.90 to 1.10" in alt_text(fig)


def test_cost_table_splits_the_cells_where_prediction_cost_a_quarter_or_more():
    cells = costs.dear_cells()
    assert {f"{c.scenario} {c.sampler}" for c in cells} == {"3DC-7 OB", "3DC-7 BT", "3DC-9 BT", "3DO OB"}
    for c in cells:
        assert c.ratio >= costs.DEAR
        assert abs(sum(c.after) + sum(c.sampling) - sum(c.total)) < 1e-12  # the two parts make the total
    table = costs.cost_table()
    assert table.count("\n| 3D") == len(cells) and f"in 3 of these {len(cells)} cells" in table


def test_after_share_is_the_part_of_the_extra_time_after_sampling():
    cell = costs.Cost("X", "BS", 1.5, (0.001, 0.003), (0.010, 0.016))  # extra 6 ms: 2 sampling, 4 after
    assert all(abs(a - b) < 1e-12 for a, b in zip(cell.after, (0.009, 0.013)))
    assert abs(cell.after_share - 4 / 6) < 1e-12
