"""Course assignments: written and handed out with otter-grader, graded where the submission cannot reach.

Each assignment is one otter master notebook, ``tutorials/assignments/<name>/<name>.ipynb``,
with its solutions inside otter's markers, public tests (students run them with
``grader.check("q1")``) and hidden tests (only grading runs them). :func:`build` runs
``otter assign`` on a master and writes ``dist/student/<name>.ipynb`` (what a course hands out)
and ``dist/autograder/`` (the zip Gradescope grades with) beside it. Questions marked ``manual``
(prose) are graded by hand; cells tagged ``otter_ignore`` (exploration: training, figures) are
skipped.

:func:`grade` keeps the submission and its judge apart. The student's notebook runs in a
process of its own inside a :mod:`~toolkit.teaching.sandbox`, which holds the notebook and the
library, never the tests (:mod:`~toolkit.teaching.submission`); the hidden tests run here, in the
grader's process, and call the notebook's functions through :mod:`~toolkit.teaching.remote`, which
lets only plain values come back (:mod:`~toolkit.teaching.wire`). So the comparisons, the
references, the score and the report are out of the submission's reach: it cannot patch the test
runner or ``numpy.isclose``, write the results, or read the tests. A question's points are split
among its hidden tests (public tests carry none; they are the student's own check).

The feedback of a question that lost points names each failed hidden test by the sentence it
checks and says why: the test's assertion message, or what the submission's function raised, on
one line and cut short, never a test's code nor anything the notebook printed.

A submission that runs longer than ``timeout`` seconds is stopped and scores 0 on every
autograded question (a loop that never ends must not hold up a whole class's grading); a file
that is not a notebook scores 0 with the reason in its ``error``. Which assignment a submission
answers is read from the notebook (``otter assign`` writes its name into the student version's
metadata), so students may rename their files.

The assignments are the course's, not the library's: they are found in ``$TOOLKIT_ASSIGNMENTS``, else in
``tutorials/assignments/`` under the current folder (the course's repository or handout, where ``make assignments``
and ``toolkit grade`` run), never beside the installed package (:func:`folder`).
"""

from __future__ import annotations

import doctest
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Collection
from pathlib import Path

from toolkit.teaching import gradescope, remote, sandbox

FOLDER_VARIABLE = "TOOLKIT_ASSIGNMENTS"  # the folder of the assignments, when not ./tutorials/assignments
TIMEOUT_S = 600  # seconds a submission may run before it is stopped and scored 0


def folder() -> Path:
    """The folder of the course's assignments (one ``<name>/<name>.ipynb`` master each): ``$TOOLKIT_ASSIGNMENTS``,
    else ``tutorials/assignments`` under the current folder."""
    return Path(os.environ.get(FOLDER_VARIABLE) or Path("tutorials", "assignments")).resolve()


def assignment_names() -> list[str]:
    """The assignments whose master ``<name>/<name>.ipynb`` exists in :func:`folder`, sorted."""
    return sorted(p.parent.name for p in folder().glob("*/*.ipynb") if p.stem == p.parent.name)


def master(name: str) -> Path:
    """The master notebook of assignment ``name``."""
    path = folder() / name / f"{name}.ipynb"
    if not path.is_file():
        known = assignment_names()
        raise ValueError(
            f"unknown assignment {name!r}; choose one of {known}"
            if known
            else f"no assignments in {folder()}: run from the course's folder (the one holding tutorials/assignments/)"
            f" or set ${FOLDER_VARIABLE} to the folder of the assignments"
        )
    return path


# A kernel that dies before it answers has usually lost a race for its ports: Jupyter picks free ports, closes them
# and starts the kernel, and a kernel starting beside it may take one first (jupyter_client issue 154). Builds run
# side by side (the test suite builds every assignment at once) meet it now and then; the same build then passes.
KERNEL_LOST_PORT = "Kernel died before replying to kernel_info"
ASSIGN_ATTEMPTS = 3


def _otter(*args: str) -> list[str]:
    return [sys.executable, "-m", "otter", *args]


def build(name: str) -> Path:
    """Run ``otter assign`` on the master (which also checks that its solutions pass every test);
    return the autograder zip, which carries the toolkit (:func:`gradescope.ship_toolkit`). Replaces ``dist/``
    beside the master; runs it again when its kernel lost a race for its ports (:data:`KERNEL_LOST_PORT`)."""
    source = master(name)
    if "# ASSIGNMENT CONFIG" not in source.read_text():
        raise ValueError(
            f"{source} is a student version, not a master (it has no ASSIGNMENT CONFIG cell): a handout cannot build "
            "the autograder, which holds the hidden tests; the instructor grades with the masters"
        )
    for attempt in range(1, ASSIGN_ATTEMPTS + 1):
        shutil.rmtree(source.parent / "dist", ignore_errors=True)
        done = subprocess.run(
            _otter("assign", "--no-pdfs", source.name, "dist"), cwd=source.parent, capture_output=True, text=True
        )
        if done.returncode == 0 or KERNEL_LOST_PORT not in done.stdout + done.stderr or attempt == ASSIGN_ATTEMPTS:
            break
    if done.returncode != 0:
        raise RuntimeError(f"otter assign failed for {name}:\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}")
    zip_path = autograder(name, build_missing=False)
    gradescope.ship_toolkit(zip_path, source=folder().parent.parent)  # the course's repository: the toolkit's source
    return zip_path


def build_all() -> dict[str, Path]:
    """:func:`build` every assignment (``make assignments``); returns each one's autograder zip."""
    return {name: build(name) for name in assignment_names()}


def student_notebook(name: str) -> Path:
    """The student version of assignment ``name`` (``dist/student/<name>.ipynb``), built first when missing or older
    than its master: what a course hands out."""
    source = master(name)
    student = source.parent / "dist" / "student" / source.name
    if not student.is_file() or student.stat().st_mtime < source.stat().st_mtime:
        build(name)
    return student


def autograder(name: str, build_missing: bool = True) -> Path:
    """The newest autograder zip of assignment ``name``, built first when missing."""
    zips = sorted((master(name).parent / "dist" / "autograder").glob(f"{name}-autograder_*.zip"))
    if zips:
        return zips[-1]
    if not build_missing:
        raise FileNotFoundError(f"otter assign wrote no autograder zip for {name}")
    return build(name)


LABEL = re.compile(r"^>>> _checks = ['\"](.+?)['\"]$", re.MULTILINE)


def test_name(case: dict) -> str:
    """How the notebook lists the sentence a test case checks (its ``_checks = "sentence 3 (...)"`` line), or
    "public test"/"hidden test" for a case without one."""
    found = LABEL.search(case["code"])
    return found[1] if found else f"{'hidden' if case['hidden'] else 'public'} test"


def _tests(zip_path: Path) -> dict[str, tuple[float, list[str]]]:
    """Each autograded question's points and, test by test, its name (:func:`test_name`); read from the
    autograder notebook beside the zip."""
    notebook = json.loads((zip_path.parent / f"{zip_path.name.split('-autograder_')[0]}.ipynb").read_text())
    return {
        q: (float(test["points"]), [test_name(case) for suite in test["suites"] for case in suite["cases"]])
        for q, test in notebook["metadata"]["otter"]["tests"].items()
    }


def points(name: str) -> dict[str, float]:
    """Each autograded question of assignment ``name`` and its points (the autograder built first when missing)."""
    return {q: p for q, (p, _) in _tests(autograder(name)).items()}


def _secrets(zip_path: Path, question: str) -> set[str]:
    """The lines of ``question``'s hidden tests long enough to recognize (a message that quotes one is withheld)."""
    cases = [case for case in _cases(zip_path)[question] if case["hidden"]]
    lines = (line[4:].strip() for case in cases for line in case["code"].splitlines())
    return {line for line in lines if len(line) >= 24}


def _cases(zip_path: Path) -> dict[str, list[dict]]:
    """Each autograded question's test cases (``code`` in doctest form, ``hidden``, ``points``) from the autograder
    notebook beside the zip, their points resolved as otter resolves them."""
    from otter.test_files import OKTestFile  # otter: the dev extra, which builds assignments

    notebook = json.loads((zip_path.parent / f"{zip_path.name.split('-autograder_')[0]}.ipynb").read_text())
    found = {}
    for q, spec in notebook["metadata"]["otter"]["tests"].items():
        resolved = OKTestFile.from_spec(spec).test_cases
        cases = [case for suite in spec["suites"] for case in suite["cases"]]
        found[q] = [{**case, "points": float(r.points or 0.0)} for case, r in zip(cases, resolved)]
    return found


MESSAGE_CHARS = 400  # the longest message a failed test passes on


def _withheld(message: str, secrets: Collection[str]) -> str:
    """``message`` on one line (no control characters: nothing a submission put in it starts a line of the report),
    cut to :data:`MESSAGE_CHARS`; withheld when it quotes a line of a hidden test."""
    message = " ".join("".join(c if c.isprintable() else " " for c in message).split())
    if any(secret in message for secret in secrets):
        return "(the message quotes a hidden test and is withheld)"
    return message if len(message) <= MESSAGE_CHARS else message[: MESSAGE_CHARS - 3] + "..."


def run_case(code: str, submission: remote.Submission) -> str | None:
    """Run one hidden test (``code`` in doctest form) here, in the grader's process, on the submission's functions;
    None when it passed, else why it failed: the test's assertion message, the exception a function of the
    submission raised, or that its process ended. :class:`TimeoutError` past the deadline."""
    source = "".join(example.source for example in doctest.DocTestParser().get_examples(code))
    namespace = {"__name__": "__hidden_test__", **{n: submission.function(n) for n in submission.names}}
    try:
        exec(compile(source, "<hidden test>", "exec"), namespace)
    except TimeoutError:
        raise
    except remote.SubmissionRaised as error:
        return f"your code raised {error}"
    except remote.SubmissionEnded as error:
        return str(error)
    except Exception as error:  # the test's own verdict (an AssertionError), or its error on what it was given
        return f"{type(error).__name__}: {error}" if str(error) else type(error).__name__
    return None


def assignment_of(notebook: str | Path) -> str:
    """The assignment a student notebook answers: the name ``otter assign`` wrote into its metadata, else its
    file name (``<name>.ipynb``); a clear error when neither names a known assignment."""
    notebook = Path(notebook)
    try:
        name = json.loads(notebook.read_text())["metadata"]["otter"]["assignment_name"]
    except (OSError, ValueError, KeyError, TypeError):  # unreadable, not JSON, or no otter metadata
        name = notebook.stem
    if not assignment_names():
        master(name)  # raises: the folder holds no assignment
    if name not in assignment_names():
        raise ValueError(
            f"{notebook}: cannot tell which assignment it answers (its metadata and file name give "
            f"{name!r}); pass --assignment, one of {assignment_names()}"
        )
    return name


def grade(
    notebook: str | Path, assignment: str | None = None, timeout: float | None = None, isolate: bool = True
) -> dict:
    """Grade a filled-in student notebook; the assignment defaults to :func:`assignment_of` the notebook.

    The notebook runs inside a :mod:`~toolkit.teaching.sandbox` (``isolate``; a clear error where bubblewrap
    cannot run) or, with ``isolate=False``, as the instructor with the instructor's files in reach; the hidden
    tests run in this process either way.
    Returns ``{"assignment", "questions": [{"name", "score", "max_score", "feedback"}],
    "score", "max_score", "timed_out", "error"}``; ``error`` is None unless the notebook could not be graded
    at all (every question then scores 0) or a cell has a syntax error (graded all the same).
    """
    notebook = Path(notebook).resolve()
    timeout = TIMEOUT_S if timeout is None else timeout
    if not timeout > 0:
        raise ValueError(f"timeout must be a positive number of seconds, got {timeout}")
    if isolate:
        sandbox.require()
    deadline = time.monotonic() + timeout
    name = assignment or assignment_of(notebook)
    zip_path = autograder(name)
    tests = _tests(zip_path)
    full = {q: p for q, (p, _) in tests.items()}
    if problem := notebook_problem(notebook):
        return _zero(name, full, problem)
    cases = _cases(zip_path)
    with tempfile.TemporaryDirectory() as work:
        inbox = Path(work, "in")
        inbox.mkdir(mode=0o755)
        copy = inbox / "submission.ipynb"  # all the sandbox sees: no tests, no references
        shutil.copy(notebook, copy)
        copy.chmod(0o644)
        submission = remote.Submission(copy, name, deadline, isolate, cpu_s=timeout)
        try:
            if not submission.start():
                return _zero(name, full, "the notebook's process ended before its cells had run")
            questions = [
                _question(q, p, names, cases[q], submission, _secrets(zip_path, q)) for q, (p, names) in tests.items()
            ]
        except TimeoutError:
            return _zero(name, full, f"stopped after {timeout:g} s: the notebook did not finish", timed_out=True)
        finally:
            submission.close()
    return _total(name, questions, error=syntax_errors(notebook))


def _question(
    q: str, points: float, names: list[str], cases: list[dict], submission: remote.Submission, secrets: set[str]
) -> dict:
    """One question's score (its points less those of each hidden test that failed) and feedback."""
    score, failed = points, []
    for name, case in zip(names, cases):
        if case["hidden"] and (why := run_case(case["code"], submission)) is not None:
            score -= case["points"]
            failed.append(f"{name} failed: {_withheld(why, secrets)}")
    feedback = "\n".join(failed) or "all tests passed"
    return {"name": q, "score": round(max(score, 0.0), 4), "max_score": points, "feedback": feedback}


def notebook_problem(notebook: Path) -> str | None:
    """Why ``notebook`` cannot be graded at all (not a notebook), or None."""
    try:
        cells = json.loads(notebook.read_text())["cells"]
        ["".join(c["source"]) for c in cells if c["cell_type"] == "code"]
    except (OSError, UnicodeDecodeError, ValueError, KeyError, TypeError) as error:
        return f"not a notebook ({type(error).__name__}: {error})"
    return None


def syntax_errors(notebook: Path) -> str | None:
    """The code cells of ``notebook`` that Python cannot parse (IPython's ``%`` and ``!`` lines aside), or None:
    such a notebook is graded (the tests of what the cell defines fail), and its row says why."""
    errors = []
    code = [c for c in json.loads(notebook.read_text())["cells"] if c["cell_type"] == "code"]
    for number, cell in enumerate(code, start=1):
        lines = "".join(cell["source"]).splitlines()
        source = "\n".join("" if line.lstrip()[:1] in ("%", "!") else line for line in lines)
        try:
            compile(source, f"code cell {number}", "exec")
        except SyntaxError as error:
            errors.append(f"code cell {number} has a syntax error (line {error.lineno}: {error.msg})")
    return "; ".join(errors) or None


def _zero(name: str, points: dict[str, float], why: str, timed_out: bool = False) -> dict:
    """Every question scored 0 with feedback ``why``: a notebook stopped by the time limit, or one otter cannot
    grade."""
    questions = [{"name": q, "score": 0.0, "max_score": p, "feedback": why} for q, p in points.items()]
    return _total(name, questions, timed_out=timed_out, error=None if timed_out else why)


def _total(name: str, questions: list[dict], timed_out: bool = False, error: str | None = None) -> dict:
    return {
        "assignment": name,
        "questions": questions,
        "timed_out": timed_out,
        "error": error,
        "score": sum(q["score"] for q in questions),
        "max_score": sum(q["max_score"] for q in questions),
    }


def report(result: dict) -> str:
    """Per-question scores, the feedback of every question that lost points, and a last line ``score: X/Y``."""
    lines = [f"assignment: {result['assignment']}"]
    for q in result["questions"]:
        lines.append(f"{q['name']}: {q['score']:g}/{q['max_score']:g}")
        if q["score"] < q["max_score"]:
            lines += ["    " + line for line in q["feedback"].strip().splitlines()]
    if result.get("error"):
        lines.append(f"error: {result['error']}")
    lines.append(f"score: {result['score']:g}/{result['max_score']:g}")
    return "\n".join(lines)
