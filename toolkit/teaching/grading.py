"""Course assignments graded with otter-grader (a course's ``tutorials/assignments/``).

Each assignment is one otter master notebook, ``tutorials/assignments/<name>/<name>.ipynb``,
with its solutions inside otter's markers, public tests (students run them with
``grader.check("q1")``) and hidden tests (only grading runs them). :func:`build` runs
``otter assign`` on a master and writes ``dist/student/<name>.ipynb`` (what a course hands out)
and ``dist/autograder/`` (the zip that grades) beside it; :func:`grade` runs ``otter run``
(locally, no Docker) on a filled-in student notebook with that zip and returns the score of
each autograded question. Questions marked ``manual`` (prose) are graded by hand and are not
part of the score; cells tagged ``otter_ignore`` (exploration: training, figures) are skipped.

The feedback of a question that lost points says which tests failed, public or hidden, and why:
the last line of the exception each raised, a test's assertion message (:func:`feedback`). It
never quotes a test's code, which otter's own output does, so it can go back to the student as
it is without revealing the hidden tests.

A submission that runs longer than ``timeout`` seconds is stopped and scores 0 on every
autograded question (a loop that never ends must not hold up a whole class's grading); one that
otter cannot grade at all (a broken file) scores 0 with the reason in its ``error``. Which
assignment a submission answers is read from the notebook (``otter assign`` writes its name into
the student version's metadata), so students may rename their files.

The assignments are the course's, not the library's: they are found in ``$TOOLKIT_ASSIGNMENTS``, else in
``tutorials/assignments/`` under the current folder (the course's repository or handout, where ``make assignments``
and ``toolkit grade`` run), never beside the installed package (:func:`folder`).
"""

from __future__ import annotations

import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import textwrap
from collections.abc import Collection
from pathlib import Path

from toolkit.teaching import gradescope, sandbox

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


def _otter(*args: str) -> list[str]:
    return [sys.executable, "-m", "otter", *args]


def build(name: str) -> Path:
    """Run ``otter assign`` on the master (which also checks that its solutions pass every test);
    return the autograder zip, which carries the toolkit (:func:`gradescope.ship_toolkit`). Replaces ``dist/``
    beside the master."""
    source = master(name)
    if "# ASSIGNMENT CONFIG" not in source.read_text():
        raise ValueError(
            f"{source} is a student version, not a master (it has no ASSIGNMENT CONFIG cell): a handout cannot build "
            "the autograder, which holds the hidden tests; the instructor grades with the masters"
        )
    dist = source.parent / "dist"
    shutil.rmtree(dist, ignore_errors=True)
    done = subprocess.run(
        _otter("assign", "--no-pdfs", source.name, "dist"), cwd=source.parent, capture_output=True, text=True
    )
    if done.returncode != 0:
        raise RuntimeError(f"otter assign failed for {name}:\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}")
    zip_path = autograder(name, build_missing=False)
    gradescope.ship_toolkit(zip_path, source=folder().parents[1])  # the course's repository: the toolkit's source
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


CASE = re.compile(r"^\s*\S+ - (\d+) result:\n(.*?)(?=^\s*\S+ - \d+ result:|\Z)", re.MULTILINE | re.DOTALL)


def _secrets(zip_path: Path, question: str) -> set[str]:
    """The lines of ``question``'s hidden tests long enough to recognize (a message that quotes one is withheld)."""
    notebook = json.loads((zip_path.parent / f"{zip_path.name.split('-autograder_')[0]}.ipynb").read_text())
    cases = [c for s in notebook["metadata"]["otter"]["tests"][question]["suites"] for c in s["cases"] if c["hidden"]]
    lines = (line[4:].strip() for case in cases for line in case["code"].splitlines())
    return {line for line in lines if len(line) >= 24}


MESSAGE_CHARS = 400  # the longest message a failed test passes on


def feedback(output: str, names: list[str], secrets: Collection[str] = ()) -> str:
    """What a student may see of otter's output for one question: which tests failed, each named as the notebook
    lists it (``names``, test by test: the sentence it checks, or "public test"), and why, the last line of the
    exception each raised (a test's assertion message); never a test's source, which otter's own output quotes."""
    if "All test cases passed" in output:
        return "all tests passed"
    failed = [
        f"{names[int(n) - 1]} failed: {_withheld(_why(body), secrets)}"
        for n, body in CASE.findall(output)
        if "Test case passed" not in body and 0 < int(n) <= len(names)
    ]
    return "\n".join(failed) or "the tests did not run"


def _withheld(message: str, secrets: Collection[str]) -> str:
    """``message``, cut to :data:`MESSAGE_CHARS`; withheld when it quotes a line of a hidden test (a submission
    can raise an exception whose message is the hidden tests' source)."""
    if any(secret in message for secret in secrets):
        return "(the message quotes a hidden test and is withheld)"
    return message if len(message) <= MESSAGE_CHARS else message[: MESSAGE_CHARS - 3] + "..."


def _why(body: str) -> str:
    """Why a failed doctest failed, from its first failing line: the exception it raised (its message lines), or
    the output it printed unasked."""
    lines = body.splitlines()
    for i, line in enumerate(lines):
        if line.strip() in ("Exception raised:", "Got:"):
            indent = len(line) - len(line.lstrip())
            block = []  # the lines indented below the heading: the traceback, or the output
            for after in lines[i + 1 :]:
                if after.strip() and len(after) - len(after.lstrip()) <= indent:
                    break
                block.append(after)
            block = textwrap.dedent("\n".join(block)).strip("\n").splitlines()
            if line.strip() == "Got:":
                return f"a line printed {block[0].strip() if block else 'output'!r} (a test line's value must be None)"
            frames = [j for j, text in enumerate(block) if text.lstrip().startswith('File "')]
            message = [text for text in block[frames[-1] + 1 if frames else 0 :] if text and not text[0].isspace()]
            return " / ".join(message[-5:]) or "an exception without a message"
    return "no reason given"


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

    ``otter run`` runs it inside a :mod:`~toolkit.teaching.sandbox` (``isolate``; a clear error where bubblewrap
    cannot run) or, with ``isolate=False``, as the instructor with the instructor's files in reach.
    Returns ``{"assignment", "questions": [{"name", "score", "max_score", "feedback"}],
    "score", "max_score", "timed_out", "error"}``; ``error`` is None unless otter could not
    grade the notebook at all (every question then scores 0) or a cell has a syntax error (graded all the same).
    """
    notebook = Path(notebook).resolve()
    timeout = TIMEOUT_S if timeout is None else timeout
    if not timeout > 0:
        raise ValueError(f"timeout must be a positive number of seconds, got {timeout}")
    if isolate and (why := sandbox.unavailable()):
        raise RuntimeError(f"cannot isolate the submissions: {why}; grade without isolation only if you trust them")
    name = assignment or assignment_of(notebook)
    zip_path = autograder(name)
    tests = _tests(zip_path)
    full = {q: p for q, (p, _) in tests.items()}
    if problem := notebook_problem(notebook):
        return _zero(name, full, problem)
    with tempfile.TemporaryDirectory() as work:
        inbox, out = Path(work, "in"), Path(work, "out")
        inbox.mkdir(mode=0o755)
        out.mkdir()
        out.chmod(0o777)  # the sandbox's own user writes the results
        shutil.copy(zip_path, inbox / "autograder.zip")
        shutil.copy(notebook, inbox / f"{name}.ipynb")
        for file in inbox.iterdir():
            file.chmod(0o644)
        done = _run(inbox, out, name, timeout, isolate)
        if done is None:
            return _zero(name, full, f"stopped after {timeout:g} s: the notebook did not finish", timed_out=True)
        results_file = out / "results.json"
        if not results_file.is_file():
            last = done.strip().splitlines()[-1] if done.strip() else "no output"
            return _zero(name, full, f"otter could not grade this notebook: {last}")
        results = {t["name"]: t for t in json.loads(results_file.read_text())["tests"]}
    questions = [
        {
            "name": q,
            "score": round(float(results.get(q, {}).get("score") or 0.0), 4),  # otter keeps 5 digits; 6 / 7 * 7 < 6
            "max_score": p,
            "feedback": feedback(results[q]["output"], names, _secrets(zip_path, q))
            if q in results
            else "not graded: its tests did not run",
        }
        for q, (p, names) in tests.items()
    ]
    return _total(name, questions, error=syntax_errors(notebook))


def _run(inbox: Path, out: Path, name: str, timeout: float, isolate: bool) -> str | None:
    """Run ``otter run`` on ``inbox``'s notebook and autograder, results into ``out``; its log, or None when it was
    stopped after ``timeout`` seconds (with everything it started)."""
    inside = {"in": "/grading/in", "out": "/grading/out"} if isolate else {"in": str(inbox), "out": str(out)}
    otter = _otter("run", "--no-logo", "-a", f"{inside['in']}/autograder.zip", "-o", inside["out"])
    otter.append(f"{inside['in']}/{name}.ipynb")
    if isolate:
        otter = sandbox.command(otter, {str(inbox): inside["in"]}, {str(out): inside["out"]}, cpu_s=timeout)
    process = subprocess.Popen(
        otter,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        cwd=out,
        start_new_session=True,  # its own group: a timeout stops the kernel too
    )
    try:
        return process.communicate(timeout=timeout)[0]
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        return None


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
