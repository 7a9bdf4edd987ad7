"""Seconds per submission for ``toolkit grade FOLDER`` (docs/benchmarks.md, "Grading a course").

Puts ``--copies`` copies of every assignment's solved notebook (as ``make assignments`` writes it)
in one folder and grades it as an instructor would, in the sandbox, ``--workers`` at once; prints
the wall-clock seconds per submission and each one's score (all full marks, else it fails).

    .venv/bin/python docs/scripts/grading_speed.py --copies 2 --workers 2
"""

from __future__ import annotations

import argparse
import shutil
import tempfile
import time
from pathlib import Path

from toolkit.teaching import classroom, grading


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--copies", type=int, default=2, help="copies of each assignment's solution (default 2)")
    parser.add_argument("--workers", type=int, default=None, help="notebooks graded at once (default: all cores)")
    args = parser.parse_args()
    names = grading.assignment_names()
    with tempfile.TemporaryDirectory() as folder:
        for name in names:
            solved = grading.autograder(name).parent / f"{name}.ipynb"
            for copy in range(args.copies):
                shutil.copy(solved, Path(folder, f"{name}-{copy}.ipynb"))
        notebooks = classroom.submissions([folder])
        began = time.perf_counter()
        results = classroom.grade_all(notebooks, workers=args.workers)
        seconds = time.perf_counter() - began
    short = [n.name for n, r in results.items() if r["score"] != r["max_score"] or r["max_score"] == 0]
    if short:
        raise SystemExit(f"a solution did not score full marks: {short}")
    print(
        f"{len(notebooks)} submissions, {args.workers or 'all'} workers: {seconds:.0f} s in all, "
        f"{seconds / len(notebooks):.1f} s a submission"
    )


if __name__ == "__main__":
    main()
