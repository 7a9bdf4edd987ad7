"""Grading a course's folder of submissions: in parallel, with a progress bar, one CSV row each.

Each submission is one :func:`~toolkit.teaching.grading.grade` (its notebook in a sandboxed
process of its own, its hidden tests in a thread here); ``workers`` of them run at once, by
default one per core. A submission that cannot be graded (not a notebook, an assignment that
cannot be told, a notebook that never ends) gets a row that says why, and the others are graded
as usual.
"""

from __future__ import annotations

import csv
import os
from concurrent.futures import ThreadPoolExecutor, as_completed
from pathlib import Path

from tqdm.auto import tqdm

from toolkit.teaching import grading


def submissions(paths: list[str | Path]) -> list[Path]:
    """The notebooks among ``paths``: files as given, folders expanded to their ``*.ipynb`` (sorted)."""
    found = []
    for path in map(Path, paths):
        if not path.exists():
            raise ValueError(f"no such file or folder: {path}")
        found += sorted(path.glob("*.ipynb")) if path.is_dir() else [path]
    if not found:
        raise ValueError(f"no notebooks (*.ipynb) in {', '.join(map(str, paths))}")
    return found


def grade_all(
    notebooks: list[Path],
    assignment: str | None = None,
    timeout: float | None = None,
    workers: int | None = None,
    isolate: bool = True,
    progress: bool = True,
) -> dict[Path, dict]:
    """:func:`grading.grade` every notebook, ``workers`` at once (default: one per core), in the order given."""
    workers = (os.cpu_count() or 1) if workers is None else workers
    if workers <= 0:
        raise ValueError(f"workers must be a positive number, got {workers}")
    if timeout is not None and not timeout > 0:
        raise ValueError(f"timeout must be a positive number of seconds, got {timeout}")
    if isolate:
        grading.sandbox.require()
    results: dict[Path, dict] = {}
    with (
        ThreadPoolExecutor(max_workers=workers) as pool,  # each grade mostly waits on its notebook's process
        tqdm(total=len(notebooks), desc="grading", unit="notebook", disable=not progress) as bar,
    ):
        jobs = {pool.submit(_grade_one, notebook, assignment, timeout, isolate): notebook for notebook in notebooks}
        for job in as_completed(jobs):
            results[jobs[job]] = job.result()
            bar.update()
    return {notebook: results[notebook] for notebook in notebooks}


def _grade_one(notebook: Path, assignment: str | None, timeout: float | None, isolate: bool) -> dict:
    """One submission's result; a row that says why where it cannot be graded."""
    try:
        name = assignment or grading.assignment_of(notebook)
    except ValueError as error:
        return _failed("", str(error))
    try:
        return grading.grade(notebook, name, timeout=timeout, isolate=isolate)
    except Exception as error:  # one submission's failure must not stop the class's grading
        return _failed(name, f"{type(error).__name__}: {error}")


def _failed(assignment: str, why: str) -> dict:
    return {"assignment": assignment, "questions": [], "timed_out": False, "error": why, "score": 0.0, "max_score": 0.0}


def write_csv(results: dict[Path, dict], path: str | Path) -> None:
    """One row per submission: ``submission, assignment, <question>..., score, max_score, timed_out, error``
    (``error``: empty, or why the notebook could not be graded or what was wrong with it)."""
    questions = list(dict.fromkeys(q["name"] for r in results.values() for q in r["questions"]))
    with open(path, "w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(["submission", "assignment", *questions, "score", "max_score", "timed_out", "error"])
        for notebook, result in results.items():
            scores = {q["name"]: q["score"] for q in result["questions"]}
            writer.writerow(
                [
                    str(notebook),
                    result["assignment"],
                    *(scores.get(q, "") for q in questions),
                    result["score"],
                    result["max_score"],
                    result["timed_out"],
                    result.get("error") or "",
                ]
            )
