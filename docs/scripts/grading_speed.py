"""Seconds per submission for ``toolkit grade FOLDER`` (docs/benchmarks.md, "Grading a course").

Puts ``--copies`` copies of every assignment's solved notebook (as ``make assignments`` writes it)
in one folder and grades it as an instructor would (each notebook in its sandbox, the hidden
tests in this process), ``--workers`` at once; prints the wall-clock seconds per submission and
the machine's load average before and after (all full marks, else it fails).

    .venv/bin/python docs/scripts/grading_speed.py --copies 2 --workers 2
"""

from __future__ import annotations

import argparse
import os
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
        load = os.getloadavg()[0]
        began = time.perf_counter()
        results = classroom.grade_all(notebooks, workers=args.workers)
        seconds = time.perf_counter() - began
    short = [
        f"{n.name}:\n{grading.report(r)}"
        for n, r in results.items()
        if r["score"] != r["max_score"] or not r["max_score"]
    ]
    if short:
        raise SystemExit("a solution did not score full marks: " + "\n".join(short))
    print(
        f"{len(notebooks)} submissions, {args.workers or 'all'} workers: {seconds:.0f} s in all, "
        f"{seconds / len(notebooks):.1f} s a submission; load average {load:.1f} before, {os.getloadavg()[0]:.1f} after"
    )


if __name__ == "__main__":
    main()
