"""Chapter 01's tables (toolkit.experiments.survey): ours beside §IV-A with the free share."""

from __future__ import annotations

from toolkit.experiments import survey


def test_the_closing_table_sets_ours_beside_the_paper_and_the_free_share_last():
    shapes = survey.paper_comparison(n_workspaces=3, n_checked=1, n_samples=200)
    rows = {line.split(" | ")[0].strip("| "): line.strip("|").split("|") for line in shapes.splitlines()[2:]}
    assert set(rows) == set(survey.PAPER) and shapes.startswith(survey.SHAPE_HEADER)
    assert all(0 < float(row[4].strip().rstrip("%")) <= 100 for row in rows.values())
    assert "| 3do | **" in shapes and "/ 25–30 |" in shapes
    assert "checks / s" not in shapes  # speeds stay in section 3's table (review r30a)
