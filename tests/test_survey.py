"""Chapter 01's closing tables (toolkit.experiments.survey): ours beside §IV-A, and the speeds three ways."""

from __future__ import annotations

from toolkit.experiments import survey

SECTION_3 = {  # checks a second as section 3's table gives them, per scenario and checker
    "2ds": {"FCLChecker": 1e6, "CompiledChecker": 5e7, "PointRobotChecker": 1e8},
    "3do": {"FCLChecker": 1e5, "CompiledChecker": 8e6},
    "3dc7": {"FCLChecker": 3e5, "CompiledChecker": 1.5e7},
    "3dc9": {"FCLChecker": 2e5, "CompiledChecker": 1e7},
}
NAMES = {"FCLChecker": "FCL", "CompiledChecker": "compiled", "PointRobotChecker": "point robot"}


def test_the_speed_table_repeats_section_3s_rate_of_the_default_checker_beside_two_timed_alone():
    shapes, checks = survey.paper_comparison(SECTION_3, n_workspaces=3, n_checked=1, n_samples=200, rounds=1)
    rows = {line.split(" | ")[0].strip("| "): line.strip("|").split("|") for line in checks.splitlines()[2:]}
    assert set(rows) == set(survey.PAPER) and shapes.startswith(survey.SHAPE_HEADER)
    assert rows["2ds"][2].strip() == "100,000,000" and rows["3do"][2].strip() == "8,000,000"
    assert all(float(row[3].replace(",", "")) > 0 and float(row[4].replace(",", "")) > 0 for row in rows.values())
    assert "| 3do | **" in shapes and "/ 25–30 |" in shapes


def test_the_speed_summary_gives_the_3d_median_and_range_and_the_fastest_2d_check():
    text = survey.speed_summary(SECTION_3, NAMES)
    assert "about **50x**" in text and "(50–80x in this run)" in text
    assert "in 2D **100x** the point robot check's" in text
