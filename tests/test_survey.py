"""Chapter 01's tables (toolkit.experiments.survey): ours beside §IV-A with the free share; section 3's speeds."""

from __future__ import annotations

from toolkit.experiments import survey

SECTION_3 = {  # checks a second as section 3's table gives them, per scenario and checker
    "2ds": {"FCLChecker": 1e6, "CompiledChecker": 5e7, "PointRobotChecker": 1e8},
    "3do": {"FCLChecker": 1e5, "CompiledChecker": 8e6},
    "3dc7": {"FCLChecker": 3e5, "CompiledChecker": 1.5e7},
    "3dc9": {"FCLChecker": 2e5, "CompiledChecker": 1e7},
}
NAMES = {"FCLChecker": "FCL", "CompiledChecker": "compiled", "PointRobotChecker": "point robot"}


def test_the_closing_table_sets_ours_beside_the_paper_and_the_free_share_last():
    shapes = survey.paper_comparison(n_workspaces=3, n_checked=1, n_samples=200)
    rows = {line.split(" | ")[0].strip("| "): line.strip("|").split("|") for line in shapes.splitlines()[2:]}
    assert set(rows) == set(survey.PAPER) and shapes.startswith(survey.SHAPE_HEADER)
    assert all(0 < float(row[4].strip().rstrip("%")) <= 100 for row in rows.values())
    assert "| 3do | **" in shapes and "/ 25–30 |" in shapes
    assert "checks / s" not in shapes  # speeds stay in section 3's table (review r30a)


def test_the_speed_summary_gives_the_3d_range_and_the_fastest_2d_check():
    text = survey.speed_summary(SECTION_3, NAMES)
    assert "3D FCL took **50–80x** the compiled checker's time per check in this run" in text
    assert "about" not in text  # review r36a: "about 59x" beside a row of 53x
    assert "in 2D **100x** the point robot check's" in text
