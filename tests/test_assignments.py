"""The course assignments grade honestly (tutorials/assignments/, toolkit.teaching.grading, otter-grader).

The slow tests build every master with ``otter assign`` and grade as ``toolkit grade`` does (each
notebook in its sandbox, the hidden tests in the grader's process), in threads: each master's
solutions, its untouched student notebook, a submission that never ends and a file that is not a
notebook, and every answer of ``tests/assignment_variants.py``, each of which must lose points on
the questions it breaks only (a correct one: full marks). otter's own test runner, in the
submission's process as Gradescope runs it, must give every variant the same scores. Then they
follow ``tutorials/instructors.md`` on a folder of three submissions.
"""

from __future__ import annotations

import csv
import json
import os
import re
import subprocess
import sys
import zipfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
from assignment_variants import VARIANTS, Variant
from otter.test_files import OKTestFile

from toolkit import cli
from toolkit.cli import commands
from toolkit.teaching import classroom, grading, unavailable
from tools import handout

ASSIGNMENTS = ["bridge_test", "verify_and_repair", "evaluating_a_checker", "cae_loss"]
THROUGH_OTTER_RUN = {  # one wrong answer per assignment whose whole report is read
    "bridge_test": "bridge_sigma_squared",
    "verify_and_repair": "repair_checks_nodes_only",
    "evaluating_a_checker": "threshold_upper_median",
    "cae_loss": "loss_sign_error",
}
HANG_TIMEOUT_S = 30


def _solved(name: str) -> Path:
    """The master's notebook with its solutions, as ``otter assign`` wrote it beside the autograder."""
    return grading.autograder(name).parent / f"{name}.ipynb"


def _with_variant(variant: Variant, target: Path) -> Path:
    """A copy of the solved notebook at ``target`` with the cell defining the variant's function replaced by it."""
    notebook = json.loads(_solved(variant.assignment).read_text())
    cells = [
        c for c in notebook["cells"] if c["cell_type"] == "code" and f"def {variant.function}(" in "".join(c["source"])
    ]
    assert len(cells) == 1, f"{len(cells)} cells define {variant.function} in {variant.assignment}"
    cells[0]["source"] = variant.code
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(json.dumps(notebook))
    return target


def _scores_in_process(notebook: Path) -> dict[str, float]:
    """Each autograded question's score as otter computes it in the submission's process (Gradescope): the
    student's cells that grading runs (``otter_ignore`` ones skipped, IPython magics dropped) in one namespace,
    then otter's test runner on every test of the autograder, public and hidden. The toolkit functions the
    hidden tests make unavailable are restored afterwards."""
    cells = json.loads(notebook.read_text())["cells"]
    namespace: dict = {"__name__": "__main__"}
    for cell in cells:  # otter's own cells (its set-up, the grader.check calls) are not editable: not the student's
        meta = cell["metadata"]
        if cell["cell_type"] == "code" and "otter_ignore" not in meta.get("tags", []) and meta.get("editable", True):
            source = "".join(line for line in cell["source"] if not line.lstrip().startswith("%"))
            exec(compile(source, str(notebook), "exec"), namespace)
    tests = json.loads(notebook.read_text())["metadata"]["otter"]["tests"]
    scores = {}
    try:
        for question, spec in tests.items():
            test_file = OKTestFile.from_spec(spec)
            test_file.run(namespace)
            scores[question] = round(float(test_file.score), 4)  # as grading.grade rounds
    finally:
        unavailable.restore()
    return scores


@pytest.fixture(scope="module")
def built(assignment_zip) -> dict[str, Path]:
    """Build every assignment, once a test session (``otter assign`` runs each master's solutions against all its
    tests first and fails when one fails: a built assignment's solutions pass them all)."""
    with ThreadPoolExecutor() as pool:
        return dict(zip(grading.assignment_names(), pool.map(assignment_zip, grading.assignment_names())))


@pytest.fixture(scope="module")
def graded(built, tmp_path_factory) -> dict[str, dict]:
    """``otter run`` (through :func:`grading.grade`) on the solutions, the blank student notebooks, one wrong answer
    per assignment, a file that is not a notebook and a notebook that never ends, concurrently."""
    root = tmp_path_factory.mktemp("submissions")
    jobs: dict[str, tuple[Path, str, float | None]] = {}  # label -> (notebook, assignment, timeout in s)
    for name in built:
        jobs[f"{name}/solution"] = (_solved(name), name, None)
        jobs[f"{name}/blank"] = (grading.student_notebook(name), name, None)
    for name, label in THROUGH_OTTER_RUN.items():
        jobs[label] = (_with_variant(VARIANTS[label], root / label / f"{name}.ipynb"), name, None)
    jobs["broken"] = (root / "broken" / "bridge_test.ipynb", "bridge_test", None)  # not a notebook
    jobs["broken"][0].parent.mkdir()
    jobs["broken"][0].write_text("this is not a notebook")
    hangs = Variant(
        "verify_and_repair",
        frozenset({"q1"}),
        "def verify_and_repair(*args):\n    while True:\n        pass\n",
        "never ends",
    )
    jobs["hangs"] = (
        _with_variant(hangs, root / "hangs" / "verify_and_repair.ipynb"),
        "verify_and_repair",
        HANG_TIMEOUT_S,
    )
    with ThreadPoolExecutor(max_workers=4) as pool:
        return dict(zip(jobs, pool.map(lambda job: grading.grade(*job), jobs.values())))


def test_the_assignments_exist():
    assert set(ASSIGNMENTS) <= set(grading.assignment_names())


@pytest.mark.parametrize(
    ("printed", "runs", "built"),
    [
        ([grading.KERNEL_LOST_PORT, ""], 2, True),  # a kernel lost its ports once: the second run builds
        ([grading.KERNEL_LOST_PORT] * 3, 3, False),  # every time: the error, after three runs
        (["NameError: name 'x' is not defined"], 1, False),  # a master's own fault: not run again
    ],
)
def test_otter_assign_runs_again_only_when_its_kernel_lost_its_ports(monkeypatch, printed, runs, built):
    outcomes = iter(printed)
    calls = []

    def otter_assign(command, **kwargs):
        calls.append(command)
        message = next(outcomes)
        return subprocess.CompletedProcess(command, 1 if message else 0, stdout="", stderr=message)

    monkeypatch.setattr(grading.subprocess, "run", otter_assign)
    monkeypatch.setattr(grading, "autograder", lambda name, build_missing: Path("made.zip"))
    monkeypatch.setattr(grading.gradescope, "ship_toolkit", lambda zip_path, source: None)
    monkeypatch.setattr(grading.shutil, "rmtree", lambda path, ignore_errors: None)  # the real dist/ stays
    if built:
        assert grading.build("bridge_test") == Path("made.zip")
    else:
        with pytest.raises(RuntimeError, match=f"otter assign failed for bridge_test:\n\n{re.escape(printed[-1])}"):
            grading.build("bridge_test")
    assert len(calls) == runs


def _sentences(name: str) -> set[str]:
    """Every sentence of the master's specifications that a hidden test checks: "q1 sentence 4", ..."""
    found, question = set(), None
    for cell in json.loads(grading.master(name).read_text())["cells"]:
        source = "".join(cell["source"])
        if source.startswith("# BEGIN QUESTION"):
            question = source.split("name: ")[1].split()[0]
        label = re.search(r'^_checks = "(sentence \d+) \(', source, re.MULTILINE)
        if label:
            found.add(f"{question} {label[1]}")
    return found


def test_every_variant_replaces_a_solution_of_its_assignment():
    for label, variant in VARIANTS.items():
        assert variant.assignment in ASSIGNMENTS and bool(variant.loses) == bool(variant.breaks), label
        assert f"def {variant.function}(" in grading.master(variant.assignment).read_text(), label
    assert {v.assignment for v in VARIANTS.values()} == set(ASSIGNMENTS)
    assert all(THROUGH_OTTER_RUN[name] in VARIANTS for name in ASSIGNMENTS)


@pytest.mark.parametrize("name", ASSIGNMENTS)
def test_every_sentence_has_a_wrong_variant_and_every_assignment_two_correct_ones(name):
    sentences = _sentences(name)
    assert len(sentences) >= 4, sentences
    broken = {v.breaks for v in VARIANTS.values() if v.assignment == name}
    assert sentences <= broken, f"{name}: no wrong variant for {sorted(sentences - broken)}"
    assert broken - {""} <= sentences | {"library"}, f"{name}: variants break sentences the master lacks"
    assert sum(not v.loses for v in VARIANTS.values() if v.assignment == name) >= 2


@pytest.mark.slow
@pytest.mark.parametrize("name", ASSIGNMENTS)
def test_the_solution_scores_full_marks_and_the_blank_notebook_zero(graded, name):
    solution, blank = graded[f"{name}/solution"], graded[f"{name}/blank"]
    assert solution["score"] == solution["max_score"] > 0, grading.report(solution)
    assert not blank["timed_out"] and blank["max_score"] == solution["max_score"]
    assert blank["score"] == 0, grading.report(blank)


@pytest.mark.slow
@pytest.mark.parametrize("name", ASSIGNMENTS)
def test_public_tests_carry_no_points(built, name):
    tests = json.loads(_solved(name).read_text())["metadata"]["otter"]["tests"]
    for question, spec in tests.items():
        cases = OKTestFile.from_spec(spec).test_cases
        assert any(case.hidden for case in cases), f"{name} {question} has no hidden test"
        assert all(case.points == 0 for case in cases if not case.hidden), f"{name} {question}: a public test scores"


@pytest.fixture(scope="module")
def variants_graded(built, tmp_path_factory) -> dict[str, dict]:
    """Every variant graded as ``toolkit grade`` grades (its notebook in the sandbox, the tests here), two at once."""
    root = tmp_path_factory.mktemp("variants")
    notebooks = {
        label: _with_variant(variant, root / label / f"{variant.assignment}.ipynb")
        for label, variant in VARIANTS.items()
    }
    with ThreadPoolExecutor(max_workers=2) as pool:
        graded = pool.map(lambda label: grading.grade(notebooks[label], VARIANTS[label].assignment), notebooks)
        return dict(zip(notebooks, graded))


def _failed(result: dict) -> set[str]:
    """The hidden tests a graded submission failed: {"q1 sentence 4", ...}."""
    return {
        f"{q['name']} {line.split(' (')[0]}"
        for q in result["questions"]
        for line in q["feedback"].splitlines()
        if line.startswith("sentence ")
    }


@pytest.mark.slow
@pytest.mark.parametrize("label", sorted(VARIANTS))
def test_a_variant_loses_points_on_the_questions_it_breaks_only(variants_graded, label):
    """A wrong variant fails the hidden test of the sentence it breaks and scores below full marks on its
    questions, full marks on the others; a correct variant scores full marks."""
    variant, result = VARIANTS[label], variants_graded[label]
    scores = {q["name"]: q["score"] for q in result["questions"]}
    full = grading.points(variant.assignment)
    assert {q: scores[q] < full[q] for q in full} == {q: q in variant.loses for q in full}, (
        f"{label}: {grading.report(result)}"
    )
    if variant.breaks and variant.breaks != "library":
        assert variant.breaks in _failed(result), (
            f"{label}: the test of {variant.breaks} passed: {grading.report(result)}"
        )


PARITY = sorted({label for label, v in VARIANTS.items() if not v.loses} | set(THROUGH_OTTER_RUN.values()))


@pytest.mark.slow
@pytest.mark.parametrize("label", PARITY)
def test_otter_in_one_process_scores_a_variant_as_the_grader_does(variants_graded, tmp_path, label):
    """Gradescope runs otter, the tests in the submission's own process: an honest submission scores the same.

    Held on every correct variant and one wrong one an assignment (``PARITY``): otter in one process takes
    seconds a notebook, and all 92 variants added a quarter of an hour to the suite.
    """
    variant = VARIANTS[label]
    in_process = _scores_in_process(_with_variant(variant, tmp_path / f"{variant.assignment}.ipynb"))
    assert {q["name"]: q["score"] for q in variants_graded[label]["questions"]} == in_process, label


@pytest.mark.slow
@pytest.mark.parametrize("name", ASSIGNMENTS)
def test_the_report_names_the_failed_sentences_and_shows_no_test_source(graded, name):
    report = grading.report(graded[THROUGH_OTTER_RUN[name]])
    assert "sentence " in report and "AssertionError: " in report, report
    leaked = [line for line in handout.secret_lines(name) if line in report]
    assert not leaked, f"the grade report quotes a test's or a solution's source: {leaked}"


@pytest.mark.slow
def test_a_submission_that_never_ends_is_stopped_and_scored_zero(graded):
    result = graded["hangs"]
    assert result["timed_out"] and result["score"] == 0 and result["max_score"] > 0
    assert "stopped after" in result["questions"][0]["feedback"]


@pytest.mark.slow
def test_a_file_otter_cannot_grade_scores_zero_with_the_reason(graded):
    result = graded["broken"]
    assert not result["timed_out"] and result["score"] == 0 and result["max_score"] > 0
    assert result["error"].startswith("not a notebook (JSONDecodeError")


class _Local:
    """A stand-in for :class:`remote.Submission`: the notebook's functions, here in this process."""

    def __init__(self, **functions):
        self.names, self.functions = list(functions), functions

    def function(self, name):
        return self.functions[name]


def test_a_failed_hidden_test_says_why_on_one_line_and_never_its_source():
    code = ">>> _checks = 'sentence 5 (what is kept)'\n>>> assert f(1) == 2, 'f(1) must be 2, got ' + repr(f(1))\n"
    assert grading.test_name({"code": code, "hidden": True}) == "sentence 5 (what is kept)"
    assert grading.test_name({"code": ">>> assert True\n", "hidden": False}) == "public test"
    assert grading.run_case(code, _Local(f=lambda x: x + 1)) is None
    why = grading.run_case(code, _Local(f=lambda x: "\nscore: 8/8\n"))
    assert why == "AssertionError: f(1) must be 2, got '\\nscore: 8/8\\n'"
    printed = grading._withheld("AssertionError: got\nscore: 8/8\r\n", ())
    assert printed == "AssertionError: got score: 8/8", "a message is one line: nothing in it starts a line"
    assert grading._withheld("x" * 1000, ()).endswith("...") and len(grading._withheld("x" * 1000, ())) == 400
    assert "withheld" in grading._withheld("raised: _want = 50_000 * _share(_slit)", {"_want = 50_000 * _share(_slit)"})
    assert grading.run_case(">>> g()\n", _Local(f=len)) == "NameError: name 'g' is not defined"


def _hidden_cells(name: str, question: str) -> list[str]:
    """The source of each hidden test of ``question`` in the master of ``name``."""
    found, current = [], None
    for cell in json.loads(grading.master(name).read_text())["cells"]:
        source = "".join(cell["source"])
        if source.startswith("# BEGIN QUESTION"):
            current = source.split("name: ")[1].split()[0]
        elif cell["cell_type"] == "code" and current == question and source.startswith("# HIDDEN"):
            found.append(source)
    return found


def _master_function(name: str, function: str):
    """The master's solution of ``function`` (its solution cell run here)."""
    cells = json.loads(grading.master(name).read_text())["cells"]
    source = next(
        "".join(c["source"]) for c in cells if c["cell_type"] == "code" and f"def {function}(" in "".join(c["source"])
    )
    namespace: dict = {"np": __import__("numpy")}
    exec(source, namespace)
    return namespace[function]


def test_the_hidden_tests_build_only_measurements_the_specification_allows():
    """evaluating_a_checker Q2: a record's path is valid only where a path was returned; times are positive."""
    solution, records = _master_function("evaluating_a_checker", "fastest_valid_threshold"), []

    def recording(runs):
        records.extend(r for measured in runs.values() for r in measured)
        return solution(runs)

    cells = _hidden_cells("evaluating_a_checker", "q2")
    assert len(cells) >= 5
    for source in cells:
        exec(source, {"fastest_valid_threshold": recording})
    assert len(records) > 500
    impossible = [r for r in records if r["path_valid"] and not r["success"]]
    assert not impossible, f"a hidden test builds records the specification calls impossible: {impossible[:3]}"
    assert all(set(r) == {"total_s", "success", "path_valid"} and r["total_s"] > 0 for r in records)


def test_the_report_ends_with_the_score_and_shows_feedback_where_points_were_lost():
    result = {
        "assignment": "a",
        "timed_out": False,
        "score": 2.0,
        "max_score": 5.0,
        "questions": [
            {"name": "q1", "score": 2.0, "max_score": 2.0, "feedback": "all tests passed"},
            {
                "name": "q2",
                "score": 0.0,
                "max_score": 3.0,
                "feedback": "sentence 5 (what is kept) failed: AssertionError: a returned sample is in collision",
            },
        ],
    }
    lines = grading.report(result).splitlines()
    assert lines[-1] == "score: 2/5"
    assert "q2: 0/3" in lines and any("a returned sample is in collision" in line for line in lines)
    assert not any("all tests passed" in line for line in lines)


def test_a_folder_of_submissions_becomes_one_csv_row_each(tmp_path):
    for stem in ("b", "a"):
        (tmp_path / f"{stem}.ipynb").write_text("{}")
    (tmp_path / "notes.txt").write_text("")
    found = classroom.submissions([tmp_path])
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
    classroom.write_csv(results, tmp_path / "scores.csv")
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
        classroom.submissions([tmp_path / "missing"])
    with pytest.raises(ValueError, match="no notebooks"):
        classroom.submissions([tmp_path])


def test_the_grade_command_is_wired():
    args = cli.build_parser().parse_args(["grade", "x.ipynb", "--csv", "s.csv", "--timeout", "5", "--workers", "3"])
    assert args.func is commands.cmd_grade and args.notebooks == ["x.ipynb"] and args.timeout == 5.0
    assert args.workers == 3 and not args.unisolated
    with pytest.raises(ValueError, match="unknown assignment"):
        grading.master("no_such_assignment")


@pytest.mark.parametrize(
    "flag, value", [("--timeout", "0"), ("--timeout", "-5"), ("--workers", "0"), ("--workers", "-1")]
)
def test_grade_refuses_a_timeout_or_workers_of_zero_or_below(capsys, flag, value):
    with pytest.raises(SystemExit):
        cli.build_parser().parse_args(["grade", "x.ipynb", flag, value])
    assert f"argument {flag}: must be" in capsys.readouterr().err
    with pytest.raises(ValueError, match="must be a positive number"):
        classroom.grade_all([Path("x.ipynb")], **{flag[2:]: float(value)}, isolate=False)


def test_a_syntax_error_is_named_with_its_cell(tmp_path):
    notebook = tmp_path / "n.ipynb"
    cells = [
        {"cell_type": "code", "source": ["%matplotlib inline\n", "x = 1\n"]},
        {"cell_type": "code", "source": ["def f(:\n"]},
    ]
    notebook.write_text(json.dumps({"cells": cells}))
    assert grading.syntax_errors(notebook) == "code cell 2 has a syntax error (line 1: invalid syntax)"
    assert grading.notebook_problem(notebook) is None
    (tmp_path / "m.ipynb").write_text("[1, 2]")
    assert grading.notebook_problem(tmp_path / "m.ipynb").startswith("not a notebook (TypeError")


GUIDE = Path(__file__).resolve().parent.parent / "tutorials" / "instructors.md"


def _guide_command(word: str) -> list[str]:
    """The command line of ``tutorials/instructors.md`` that contains ``word`` (in a fenced bash block), split."""
    blocks = GUIDE.read_text().split("```bash\n")[1:]
    lines = [line.split("#")[0].split() for block in blocks for line in block.split("```")[0].splitlines()]
    found = [line for line in lines if word in line]
    assert len(found) == 1, f"{GUIDE.name} should hold one command with {word!r}, found {found}"
    return found[0]


@pytest.mark.slow
def test_the_instructors_guide_grades_a_folder_of_three_submissions_into_a_csv(built, tmp_path):
    """Follow tutorials/instructors.md: collect three renamed submissions in one folder, run its grading command."""
    folder = tmp_path / "submissions"
    folder.mkdir()
    (folder / "alice.ipynb").write_text(_solved("bridge_test").read_text())
    (folder / "bob.ipynb").write_text(grading.student_notebook("verify_and_repair").read_text())
    _with_variant(VARIANTS["bridge_keeps_invalid_midpoints"], folder / "carol.ipynb")
    command = _guide_command("grade")
    assert command[:2] == [".venv/bin/toolkit", "grade"] and "submissions/" in command, command
    root = Path(__file__).resolve().parent.parent
    done = subprocess.run(
        [sys.executable, "-m", "toolkit", *command[1:]],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        env={**os.environ, "PYTHONPATH": str(root), grading.FOLDER_VARIABLE: str(grading.folder())},  # as in the course
        timeout=1500,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    csv_file = tmp_path / command[command.index("--csv") + 1]
    with open(csv_file) as scores:
        rows = {Path(row["submission"]).name: row for row in csv.DictReader(scores)}
    assert sorted(rows) == ["alice.ipynb", "bob.ipynb", "carol.ipynb"]
    alice, bob, carol = rows["alice.ipynb"], rows["bob.ipynb"], rows["carol.ipynb"]
    assert (alice["assignment"], alice["score"], alice["max_score"]) == ("bridge_test", "8.0", "8.0")
    assert (bob["assignment"], bob["score"]) == ("verify_and_repair", "0.0")
    assert float(carol["q1"]) < 6 and carol["q2"] == "2.0" and carol["timed_out"] == "False" and carol["error"] == ""
    assert done.stdout.count("score: ") == 3
    with zipfile.ZipFile(grading.autograder("bridge_test")) as archive:  # otter's Gradescope autograder
        assert {"run_autograder", "setup.sh", "otter_config.json"} <= set(archive.namelist())
