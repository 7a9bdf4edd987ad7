"""The chapters' prose says only what holds at quick and full size; what it measured, it prints (issue 37).

Fast checks on the committed notebooks (no typed run times, no sentence that a page was found to contradict, every
`toolkit.` name in the prose exists), and the checks of ``tests/chapter_claims.py`` held against crafted outputs:
they pass a chapter whose sentences agree with its tables and fail one whose sentences do not. The executed
chapters themselves are checked where the site's build runs them (``tests/test_site.py``).
"""

from __future__ import annotations

import importlib
import json
import re
from pathlib import Path

import pytest
from chapter_claims import problems

from toolkit.teaching import findings

ROOT = Path(__file__).resolve().parents[1]
CHAPTERS = sorted((ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))
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


def executed(*printed: str) -> dict:
    """A notebook whose code cells printed ``printed`` (one cell each; ``MD:`` starts displayed Markdown)."""

    def output(text):
        if text.startswith("MD:"):
            return {"output_type": "display_data", "data": {"text/markdown": text[3:]}, "metadata": {}}
        return {"output_type": "stream", "name": "stdout", "text": text}

    return {"cells": [{"cell_type": "code", "source": [], "outputs": [output(t)]} for t in printed]}


def summary(median: float, n: int = 4) -> dict:
    return {"n_queries": n, "total_s_median": median}


def chapter_04(verdict_ratio: float, table_ratio: float) -> dict:
    """A chapter 04 whose BS verdict says ``verdict_ratio`` and whose comparison table says ``table_ratio``."""
    ratios = dict(zip(("BS", "OB", "G", "BT"), (verdict_ratio, 1.2, 0.5, 1.0)))
    table = {s: {"without": summary(1.0), "with": summary(r)} for s, r in ratios.items()}
    against = "the lazy exact planner with the compiled exact checker"
    verdicts = {name: findings.describe_medians(name, table, against) for name in ("2DS", "3DC-7")}
    conclusion = [f"variable {i}: learning never wins over 1-2: at its best the network costs 2.0x." for i in range(4)]
    row = f"| total | this notebook (medians) | {table_ratio:.2f} | 1.20 | 0.50 | 1.00 |"
    rows = "\n".join(f"| {name} {row}" for name in verdicts)
    lesson = findings.describe_lesson(verdicts, conclusion)
    return executed(*verdicts.values(), "\n".join(conclusion), "MD:" + rows, "MD:" + lesson)


def test_chapter_04_passes_when_its_verdicts_and_lesson_agree_with_its_tables():
    assert problems(CH04, chapter_04(0.8, 0.8)) == []


def test_chapter_04_fails_a_verdict_that_disagrees_with_the_table():
    found = problems(CH04, chapter_04(0.8, 1.3))
    assert found and all("BS" in p for p in found)


def test_chapter_04_fails_without_the_lesson():
    nb = chapter_04(0.8, 0.8)
    nb["cells"].pop()
    assert problems(CH04, nb) == ["04: the lesson (findings.describe_lesson) is not displayed"]


def chapter_03(paper_blind: float, sentence_blind: float) -> dict:
    rows = [
        f"| `{p}` preset, 2DS unseen | {k} | {a:.0%} | 10% | 90% |"
        for p, k, a in (
            ("paper", "balanced", 0.54),
            ("strong", "balanced", 0.93),
            ("paper", "validity-blind", paper_blind),
            ("strong", "validity-blind", 0.92),
        )
    ]
    rows += ["| always valid | balanced | 50% | 100% | 0% |", "| always valid | validity-blind | 86% | 100% | 0% |"]
    said = {
        ("paper", "balanced"): 0.54,
        ("strong", "balanced"): 0.93,
        ("paper", "validity-blind"): sentence_blind,
        ("strong", "validity-blind"): 0.92,
    }
    always = {"balanced": 0.5, "validity-blind": 0.86}
    lines = [findings.describe_accuracy(f"{p}, {k}", a, always[k]) for (p, k), a in said.items()]
    return executed("\n".join(lines), "the model calls every sample valid", "MD:" + "\n".join(rows))


def test_chapter_03_passes_when_its_sentences_carry_the_tables_accuracies():
    assert problems(CH03, chapter_03(0.25, 0.25)) == []


def test_chapter_03_fails_a_sentence_that_disagrees_with_the_table():
    assert problems(CH03, chapter_03(0.25, 0.38)) == [
        "03: paper, validity-blind: the sentence says 38% vs 86%, the table [25] vs [86]"
    ]
