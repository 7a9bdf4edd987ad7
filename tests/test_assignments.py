"""The course assignments grade honestly (tutorials/assignments/, toolkit.teaching.grading, otter-grader).

The slow tests build every master with ``otter assign`` and grade, all at once in threads
(each ``otter run`` is a subprocess with its own kernel): the master's solutions, the untouched
student notebook, a plausible wrong answer per assignment, a submission that never ends and a
file that is not a notebook; and they follow ``tutorials/instructors.md`` on a folder of three
submissions.
"""

from __future__ import annotations

import csv
import json
import os
import subprocess
import sys
import zipfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from toolkit import cli
from toolkit.cli import commands
from toolkit.teaching import grading

ASSIGNMENTS = ["bridge_test", "verify_and_repair", "evaluating_a_checker", "cae_loss"]
# Plausible wrong answers: (assignment, the solution's line, its replacement, the questions it breaks).
WRONG = {
    "bridge_keeps_invalid_midpoints": (
        "bridge_test",
        "keep = free(checker, middles)",
        "keep = np.ones(len(middles), dtype=bool)",
        {"q1"},
    ),
    "repair_trusts_the_liar": (
        "verify_and_repair",
        "path = roadmap.shortest_path(start, goal)  # (P,) node indices",
        "return roadmap.shortest_path(start, goal)",
        {"q1"},
    ),
    "tpr_and_tnr_swapped": (
        "evaluating_a_checker",
        '"tpr": float(np.mean(predicted_valid[valid])) if valid.any() else float("nan"),\n        "tnr"',
        '"tnr": float(np.mean(predicted_valid[valid])) if valid.any() else float("nan"),\n        "tpr"',
        {"q1"},
    ),
    "threshold_ignores_invalid_paths": (
        "evaluating_a_checker",
        'if all(r["success"] and r["path_valid"] for r in records)',
        'if all(r["success"] for r in records)',
        {"q2"},
    ),
    "loss_without_the_penalty": (
        "cae_loss",
        "return reconstruction + lam * contractive_penalty(cae, grids)",
        "return reconstruction",
        {"q2"},
    ),
    "penalty_without_gradient": ("cae_loss", "create_graph=True)[0]", "retain_graph=True)[0]", {"q1"}),
}
HANG_TIMEOUT_S = 30


def _edited(source: Path, target: Path, old: str, new: str) -> Path:
    """A copy of notebook ``source`` at ``target`` with ``old`` replaced by ``new`` (which must occur once)."""
    notebook = json.loads(source.read_text())
    hits = 0
    for cell in notebook["cells"]:
        text = "".join(cell["source"])
        hits += text.count(old)
        cell["source"] = text.replace(old, new)
    assert hits == 1, f"{old!r} occurs {hits} times in {source}"
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(json.dumps(notebook))
    return target


@pytest.fixture(scope="module")
def graded(tmp_path_factory) -> dict[str, dict]:
    """Build every assignment, then grade all the notebooks below concurrently.

    Building runs each master's solutions against every public and hidden test and fails
    when one fails (``otter assign``), so a built assignment's solutions score full marks.
    """
    with ThreadPoolExecutor() as pool:
        zips = dict(zip(grading.assignment_names(), pool.map(grading.build, grading.assignment_names())))
    root = tmp_path_factory.mktemp("submissions")
    jobs: dict[str, tuple[Path, str, float | None]] = {}  # label -> (notebook, assignment, timeout in s)
    for name, zip_path in zips.items():
        dist = zip_path.parent.parent
        jobs[f"{name}/blank"] = (dist / "student" / f"{name}.ipynb", name, None)
    for label, (name, old, new, _) in WRONG.items():
        solution = zips[name].parent / f"{name}.ipynb"
        jobs[label] = (_edited(solution, root / label / f"{name}.ipynb", old, new), name, None)
    jobs["broken"] = (root / "broken" / "bridge_test.ipynb", "bridge_test", None)
    jobs["broken"][0].parent.mkdir()
    jobs["broken"][0].write_text("this is not a notebook")
    solution = zips["verify_and_repair"].parent / "verify_and_repair.ipynb"
    jobs["hangs"] = (
        _edited(
            solution,
            root / "hangs" / "verify_and_repair.ipynb",
            "path = roadmap.shortest_path(start, goal)  # (P,) node indices",
            "path = None\n        while True:\n            pass",
        ),
        "verify_and_repair",
        HANG_TIMEOUT_S,
    )
    with ThreadPoolExecutor(max_workers=5) as pool:
        results = pool.map(lambda job: grading.grade(*job), jobs.values())
        return dict(zip(jobs, results))


def test_the_assignments_exist():
    assert set(ASSIGNMENTS) <= set(grading.assignment_names())


@pytest.mark.slow
@pytest.mark.parametrize("name", ASSIGNMENTS)
def test_the_untouched_student_notebook_runs_and_scores_zero(graded, name):
    blank = graded[f"{name}/blank"]
    assert not blank["timed_out"] and blank["max_score"] > 0
    assert blank["score"] == 0, grading.report(blank)


@pytest.mark.slow
@pytest.mark.parametrize("label", sorted(WRONG))
def test_a_wrong_answer_loses_the_points_of_its_parts_only(graded, label):
    broken = WRONG[label][3]
    result = graded[label]
    for question in result["questions"]:
        lost = question["score"] < question["max_score"]
        assert lost == (question["name"] in broken), grading.report(result)


@pytest.mark.slow
def test_a_submission_that_never_ends_is_stopped_and_scored_zero(graded):
    result = graded["hangs"]
    assert result["timed_out"] and result["score"] == 0 and result["max_score"] > 0
    assert "stopped after" in result["questions"][0]["feedback"]


@pytest.mark.slow
def test_a_file_otter_cannot_grade_scores_zero_with_the_reason(graded):
    result = graded["broken"]
    assert not result["timed_out"] and result["score"] == 0 and result["max_score"] > 0
    assert "otter could not grade" in result["error"] and "JSON" in result["error"]


def test_the_report_ends_with_the_score_and_shows_feedback_where_points_were_lost():
    result = {
        "assignment": "a",
        "timed_out": False,
        "score": 2.0,
        "max_score": 5.0,
        "questions": [
            {"name": "q1", "score": 2.0, "max_score": 2.0, "feedback": "all passed"},
            {
                "name": "q2",
                "score": 0.0,
                "max_score": 3.0,
                "feedback": "AssertionError: a returned sample is in collision",
            },
        ],
    }
    lines = grading.report(result).splitlines()
    assert lines[-1] == "score: 2/5"
    assert "q2: 0/3" in lines and any("a returned sample is in collision" in line for line in lines)
    assert not any("all passed" in line for line in lines)


def test_a_folder_of_submissions_becomes_one_csv_row_each(tmp_path):
    for stem in ("b", "a"):
        (tmp_path / f"{stem}.ipynb").write_text("{}")
    (tmp_path / "notes.txt").write_text("")
    found = grading.submissions([tmp_path])
    assert [p.name for p in found] == ["a.ipynb", "b.ipynb"]
    results = {
        p: {
            "assignment": "x",
            "timed_out": False,
            "error": None,
            "score": float(i),
            "max_score": 2.0,
            "questions": [{"name": "q1", "score": float(i), "max_score": 2.0, "feedback": ""}],
        }
        for i, p in enumerate(found)
    }
    grading.write_csv(results, tmp_path / "scores.csv")
    with open(tmp_path / "scores.csv") as scores:
        rows = list(csv.DictReader(scores))
    assert [(Path(r["submission"]).name, r["q1"], r["score"], r["max_score"]) for r in rows] == [
        ("a.ipynb", "0.0", "0.0", "2.0"),
        ("b.ipynb", "1.0", "1.0", "2.0"),
    ]
    assert list(rows[0])[-3:] == ["max_score", "timed_out", "error"] and rows[0]["error"] == ""


def test_the_assignment_is_read_from_the_notebook_then_its_file_name(tmp_path):
    renamed = tmp_path / "alice.ipynb"  # a student version as otter assign writes it, renamed by its student
    renamed.write_text(json.dumps({"cells": [], "metadata": {"otter": {"assignment_name": "cae_loss"}}}))
    assert grading.assignment_of(renamed) == "cae_loss"
    (tmp_path / "bridge_test.ipynb").write_text("{}")  # no metadata: the file name
    assert grading.assignment_of(tmp_path / "bridge_test.ipynb") == "bridge_test"
    (tmp_path / "bob.ipynb").write_text("not a notebook")
    with pytest.raises(ValueError, match=r"bob\.ipynb: cannot tell which assignment.*--assignment"):
        grading.assignment_of(tmp_path / "bob.ipynb")


def test_missing_or_empty_submissions_are_named(tmp_path):
    with pytest.raises(ValueError, match=r"no such file or folder: .*missing"):
        grading.submissions([tmp_path / "missing"])
    with pytest.raises(ValueError, match="no notebooks"):
        grading.submissions([tmp_path])


def test_the_grade_command_is_wired():
    args = cli.build_parser().parse_args(["grade", "x.ipynb", "--csv", "s.csv", "--timeout", "5"])
    assert args.func is commands.cmd_grade and args.notebooks == ["x.ipynb"] and args.timeout == 5.0
    with pytest.raises(ValueError, match="unknown assignment"):
        grading.master("no_such_assignment")


GUIDE = Path(__file__).resolve().parent.parent / "tutorials" / "instructors.md"


def _guide_command(word: str) -> list[str]:
    """The command line of ``tutorials/instructors.md`` that contains ``word`` (in a fenced bash block), split."""
    blocks = GUIDE.read_text().split("```bash\n")[1:]
    lines = [line.split("#")[0].split() for block in blocks for line in block.split("```")[0].splitlines()]
    found = [line for line in lines if word in line]
    assert len(found) == 1, f"{GUIDE.name} should hold one command with {word!r}, found {found}"
    return found[0]


@pytest.mark.slow
def test_the_instructors_guide_grades_a_folder_of_three_submissions_into_a_csv(tmp_path):
    """Follow tutorials/instructors.md: collect three renamed submissions in one folder, run its grading command."""
    solution = grading.autograder("bridge_test").parent / "bridge_test.ipynb"
    blank = grading.autograder("verify_and_repair").parent.parent / "student" / "verify_and_repair.ipynb"
    folder = tmp_path / "submissions"
    folder.mkdir()
    (folder / "alice.ipynb").write_text(solution.read_text())
    (folder / "bob.ipynb").write_text(blank.read_text())
    _edited(solution, folder / "carol.ipynb", *WRONG["bridge_keeps_invalid_midpoints"][1:3])
    command = _guide_command("grade")
    assert command[:2] == [".venv/bin/toolkit", "grade"] and "submissions/" in command, command
    root = Path(__file__).resolve().parent.parent
    done = subprocess.run(
        [sys.executable, "-m", "toolkit", *command[1:]],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        env={**os.environ, "PYTHONPATH": str(root)},
        timeout=1500,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    csv_file = tmp_path / command[command.index("--csv") + 1]
    with open(csv_file) as scores:
        rows = {Path(row["submission"]).name: row for row in csv.DictReader(scores)}
    assert sorted(rows) == ["alice.ipynb", "bob.ipynb", "carol.ipynb"]
    assert (rows["alice.ipynb"]["assignment"], rows["alice.ipynb"]["score"], rows["alice.ipynb"]["max_score"]) == (
        "bridge_test",
        "8.0",
        "8.0",
    )
    assert (rows["bob.ipynb"]["assignment"], rows["bob.ipynb"]["score"]) == ("verify_and_repair", "0.0")
    carol = rows["carol.ipynb"]
    assert float(carol["q1"]) < 6 and carol["q2"] == "2.0" and carol["timed_out"] == "False" and carol["error"] == ""
    assert done.stdout.count("score: ") == 3
    with zipfile.ZipFile(
        grading.autograder("bridge_test")
    ) as archive:  # otter's Gradescope autograder, as the guide says
        assert {"run_autograder", "setup.sh", "otter_config.json"} <= set(archive.namelist())
