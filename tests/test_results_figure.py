"""docs/results.md's figure, Table 3's totals ours beside the paper's, against the tables on the same page: the
picture (docs/results_table3.png), its text alternative on the page and the text the PNG carries are what
tools/results_summary.py draws from the tables now, and its points are the tables' cells, read here on their own."""

import re

import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from PIL import Image

from toolkit.experiments.paper_numbers import IMPROVEMENT
from toolkit.plots import alt
from tools import recorded_results, results_summary

TEXT = recorded_results.RESULTS.read_text()
AGAIN = "docs/results.md's tables changed: run python -m tools.results_summary"
COLUMN = 688  # px: the site's column at 1280 px (tests/test_doc_pictures.py): the picture is shown at its size


@pytest.fixture(scope="module")
def fig():
    drawn = results_summary.table3_figure(TEXT)
    FigureCanvasAgg(drawn).draw()
    return drawn


def test_the_picture_carries_the_description_of_the_figure_the_tables_give(fig):
    with Image.open(results_summary.FIGURE) as image:
        said, width = image.info.get("Description"), image.size[0]
    assert said == alt.alt_text(fig), AGAIN
    assert width <= COLUMN


def test_the_page_shows_the_picture_with_that_description_and_its_table_of_values():
    block = TEXT.partition(results_summary.FIGURE_BEGIN)[2].partition(results_summary.FIGURE_END)[0].strip()
    assert block == results_summary.figure_markdown(TEXT), AGAIN
    assert f"]({results_summary.FIGURE.name})" in block and "Figure described" in block


def _cell(table: str, scenario: str, sampler: str, text: str) -> float:
    """Our total improvement of ``sampler`` in the Table 3 under the heading ``table``, read from the page's
    Markdown: the cell ``**-25%** / 17%`` gives -0.25."""
    section = text.partition(f"### {table}")[2].partition("\n###")[0]
    row = re.search(rf"(?m)^\| {scenario} \| (.*)$", section.partition(f"Total {sampler}")[2])
    header = section.partition(f"Total {sampler}")[0].rpartition("\n")[2] + f"Total {sampler}"
    assert row, f"no row {scenario} under the column Total {sampler} of {table}"
    cell = re.match(r"\*\*(-?\d+)%\*\*", row[1].split("|")[header.count("|") - 2].strip())
    assert cell, f"{table}, {scenario}, Total {sampler}: no **ours** / paper's cell"
    return int(cell[1]) / 100


def test_each_point_is_a_cell_of_table_3_or_the_papers(fig):
    tables = {
        "ours, compiled exact checker": "`paper`, Table 3: time improvement ratio",
        "ours, python-fcl (before issue 25)": "`paper` before issue 25, Table 3: time improvement ratio",
    }
    panels = dict(zip(results_summary.NAMES, fig.axes))
    assert len(fig.axes) == 4
    for scenario, ax in panels.items():
        assert ax.get_title().startswith(results_summary.NAMES[scenario])
        points = {line.get_label(): list(line.get_ydata()) for line in ax.get_lines() if line.get_marker() != "None"}
        samplers = ("BS", "OB", "G", "BT")
        assert points["the paper (Table 3)"] == pytest.approx([1 - IMPROVEMENT[scenario]["total"][s] for s in samplers])
        for name, table in tables.items():
            assert points[name] == pytest.approx([1 - _cell(table, scenario, s, TEXT) for s in samplers]), name


def test_a_changed_cell_changes_the_figure_and_its_words():
    changed = TEXT.replace("| 2ds | **-25%** / 17% |", "| 2ds | **30%** / 17% |", 1)
    assert changed != TEXT, "the `paper` Table 3's 2DS total BS cell is no longer -25 %: pick another cell here"
    redrawn = results_summary.table3_figure(changed)
    assert alt.alt_text(redrawn) != alt.alt_text(results_summary.table3_figure(TEXT))
    assert results_summary.with_summary(changed) != changed


def test_the_sentence_over_the_figure_counts_the_papers_cells_by_the_tie_rule():
    totals = [v for row in IMPROVEMENT.values() for v in row["total"].values()]  # the paper's Table 3, total columns
    saved, lost = sum(v >= 0.10 for v in totals), sum(v <= -0.10 for v in totals)
    said = re.search(
        r"the paper \(Table 3\) saved 10 % or more in (\d+) of 16 cells, lost 10 % or more in (\d+) "
        r"and tied in (\d+)",
        TEXT,
    )
    assert said and [int(n) for n in said.groups()] == [saved, lost, 16 - saved - lost]
