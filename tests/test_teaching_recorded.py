"""toolkit.teaching.recorded: the tables of docs/results.md, read cell by cell as the notebooks quote them, from the
copy the package carries (tools/recorded_results.py writes it; it must say what docs/results.md says)."""

import json

import pytest

from toolkit.planning.sampling import PAPER_SAMPLERS
from toolkit.teaching import recorded
from tools import recorded_results

RESULTS = """# Results

## Preset `paper`

### Table 2: MLP accuracy, TPR, TNR

|  | Seen Acc | Seen TPR |
| --- | --- | --- |
| 2ds | **61%** / 92% | **36%** / 96% |
| 3dc7 | **50%** / 75% | **100%** / 87% |

*Seen*: balanced samples.

### Time with / without prediction, medians over the queries

|  | Sampling BS | Total BS |
| --- | --- | --- |
| 3dc7 | 0.05 | 0.88 |

## Preset `strong`

### Time with / without prediction, medians over the queries

*Without prediction*: the best exact planner (the lazy PRM).

|  | Sampling BS | Total BS |
| --- | --- | --- |
| 3dc7 | 0.28 | 0.08 |
"""


@pytest.fixture
def results():
    return recorded_results.parse(RESULTS)


def test_a_table_is_read_by_preset_and_heading(results):
    assert recorded.table("paper", "mlp accuracy", results) == {
        "2ds": {"Seen Acc": "**61%** / 92%", "Seen TPR": "**36%** / 96%"},
        "3dc7": {"Seen Acc": "**50%** / 75%", "Seen TPR": "**100%** / 87%"},
    }
    assert recorded.median_ratios("paper", results) == {"3dc7": {"sampling": {"BS": 0.05}, "total": {"BS": 0.88}}}
    assert recorded.median_ratios("strong", results) == {"3dc7": {"sampling": {"BS": 0.28}, "total": {"BS": 0.08}}}
    assert recorded.without("strong", "medians", results) == "the best exact planner (the lazy PRM)."
    assert recorded.without("paper", "medians", results) is None  # no line says


@pytest.mark.parametrize(
    "cell, number",
    [("**61%** / 92%", 0.61), ("0.28", 0.28), ("43,049,544", 43049544.0), ("**-40%** / 53%", -0.40), ("1.5 %", 0.015)],
)
def test_ours_is_the_first_figure_of_a_cell(cell, number):
    assert recorded.ours(cell) == pytest.approx(number)


def test_a_missing_preset_heading_or_number_is_named(results):
    with pytest.raises(ValueError, match=r"no section '## Preset `ablation`'; recorded presets: \['paper', 'strong'\]"):
        recorded.table("ablation", "medians", results)
    with pytest.raises(ValueError, match="no table under a heading with 'Table 9'"):
        recorded.table("paper", "Table 9", results)
    with pytest.raises(ValueError, match="no number in the cell 'n/a'"):
        recorded.ours("n/a")


def test_the_projects_results_hold_the_tables_the_notebooks_read():
    for preset in ("paper", "strong"):
        medians = recorded.median_ratios(preset)
        assert set(medians) == {"2ds", "3dc7", "3dc9", "3do"}
        for kinds in medians.values():
            assert {kind: set(ratios) for kind, ratios in kinds.items()} == {
                "sampling": set(PAPER_SAMPLERS),
                "total": set(PAPER_SAMPLERS),
            }
            assert all(0 < r < 100 for ratios in kinds.values() for r in ratios.values())
    mlp = recorded.table("paper", "MLP accuracy")["3dc7"]
    assert 0 <= recorded.ours(mlp["Seen TPR"]) <= 1 and 0 <= recorded.ours(mlp["Seen TNR"]) <= 1


def test_the_packaged_tables_are_what_docs_results_md_says():
    packaged = recorded_results.PACKAGED.read_text()
    assert packaged == recorded_results.packaged_text(), "docs/results.md changed: run python -m tools.recorded_results"
    assert recorded.packaged() == json.loads(packaged)  # what an installed toolkit reads (tests/test_plain_install.py)


def test_the_parse_keeps_every_row_and_only_the_first_table_under_a_heading():
    text = RESULTS.replace(
        "*Seen*: balanced samples.", "*Seen*: balanced samples.\n\n|  | other |\n| --- | --- |\n| 2ds | 1 |"
    )
    parsed = recorded_results.parse(text)
    assert parsed["paper"]["Table 2: MLP accuracy, TPR, TNR"]["rows"] == [
        ["2ds", "**61%** / 92%", "**36%** / 96%"],
        ["3dc7", "**50%** / 75%", "**100%** / 87%"],
    ]
    assert list(parsed) == ["paper", "strong"]
    assert recorded_results.parse("## Preset `paper` on 1–2 December\n\n### T\n\n| a |\n| - |\n| b |\n") == {}


def test_a_table_shown_in_parts_is_read_as_one():
    """docs/results.md shows a wide table in parts of at most five columns, each repeating the key columns."""
    one = "|  | sampler | a | b |\n| --- | --- | --- | --- |\n| 2ds | BS | 1 | 2 |\n| 2ds | OB | 3 | 4 |\n"
    parts = "|  | sampler | a |\n| --- | --- | --- |\n| 2ds | BS | 1 |\n| 2ds | OB | 3 |\n\n"
    parts += "|  | sampler | b |\n| --- | --- | --- |\n| 2ds | BS | 2 |\n| 2ds | OB | 4 |\n"
    whole, split = (recorded_results.parse(f"## Preset `paper`\n\n### T\n\n{t}\n*Note*\n") for t in (one, parts))
    assert split == whole and whole["paper"]["T"]["columns"] == ["", "sampler", "a", "b"]
    with pytest.raises(ValueError, match="does not repeat the rows"):
        recorded_results.parse(f"## Preset `paper`\n\n### T\n\n{parts.replace('| 2ds | OB | 4 |', '| 3do | OB | 4 |')}")


def test_a_runs_decision_thresholds_travel_with_its_table_2():
    """Chapter 05 names each `strong` training by its threshold (reader r29e); an installed toolkit has no docs/, so
    the line under Table 2 is carried in the packaged record, and a line that follows a table directly ends it."""
    table = "| a | b |\n| - | - |\n| 3dc7 | 1 |\n"
    text = f"## Preset `paper`\n\n### MLP accuracy\n\n{table}Decision threshold on P(valid): 2ds 0.41, 3dc7 0.63.\n"
    parsed = recorded_results.parse(text)
    assert recorded.thresholds("paper", parsed) == {"2ds": 0.41, "3dc7": 0.63}
    assert recorded.thresholds("strong --planner paper")["3dc7"] == 0.63  # the record's timed run (docs/results.md)
    assert recorded.thresholds("strong")["3dc7"] != recorded.thresholds("strong --planner paper")["3dc7"]
