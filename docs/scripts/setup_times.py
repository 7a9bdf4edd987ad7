"""How long the README's commands take here, piece by piece, each timed with the machine's load beside it.

    python docs/scripts/setup_times.py [PIECE ...] [--work DIR] [--cold]

Pieces (default: demo site site-again):

- ``setup``: what ``make setup`` does, into a fresh virtual environment under DIR: ``python -m venv``, then
  ``pip install -c constraints.txt -e ".[dev]"`` (pip's cache and the machine's wheels used, as for any install);
- ``demo``: ``make demo``'s reproduction, ``toolkit reproduce --scenario 2ds --preset paper``;
- ``site``: ``make site``'s build at full size (``python -m tools.site``), with a fresh folder of executed
  notebooks (every notebook runs; with ``--cold`` also a fresh model cache, so the chapters train theirs);
- ``site-again``: the same build once more: notebooks whose inputs have not changed are reused;
- ``binder``: ``tests/test_binder.py``'s install of ``binder/requirements.txt`` and its run of chapter 01;
- ``test``: the whole suite, ``python -m pytest -q`` (``make test`` adds the set-up and the lint).

Prints one JSON line per piece (its output goes to DIR/PIECE.log): its wall time in seconds and the load
average (1 min) before and after, on ``os.cpu_count()`` cores. Run it with the project's environment
(``.venv/bin/python``) from the repository's root.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def commands(work: Path, cold: bool) -> dict[str, tuple[list[str], dict[str, str]]]:
    """Each piece's command and the environment variables it adds."""
    python, venv = sys.executable, work / "venv"
    cache = {"TOOLKIT_CACHE": str(work / "model-cache")} if cold else {}
    site = [python, "-c", f"from tools.site import build_site; build_site({str(work / 'site')!r}, work={str(work)!r})"]
    return {
        "setup": (
            [
                "bash",
                "-c",
                f'python3 -m venv {venv} && {venv}/bin/pip install -q -c constraints.txt -e ".[dev]"',
            ],
            {},
        ),
        "demo": (
            [
                python,
                "-m",
                "toolkit",
                "reproduce",
                "--scenario",
                "2ds",
                "--preset",
                "paper",
                "--out",
                str(work / "demo"),
            ],
            {},
        ),
        "site": (site, cache),
        "site-again": (site, cache),
        "binder": ([python, "-m", "pytest", "-q", "tests/test_binder.py", "-k", "runs_a_chapter"], {}),
        "test": ([python, "-m", "pytest", "-q"], {}),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pieces", nargs="*", default=["demo", "site", "site-again"])
    parser.add_argument("--work", type=Path, help="where the pieces write (default: a new temporary folder)")
    parser.add_argument("--cold", action="store_true", help="the site with an empty model cache too")
    args = parser.parse_args()
    work = (args.work or Path(tempfile.mkdtemp(prefix="setup-times-"))).resolve()
    work.mkdir(parents=True, exist_ok=True)
    known = commands(work, args.cold)
    if unknown := [p for p in args.pieces if p not in known]:
        parser.error(f"unknown piece {', '.join(unknown)}; choose from {', '.join(known)}")
    for piece in args.pieces:
        command, extra = known[piece]
        fresh = {"setup": "venv", "demo": "demo", "site": "executed"}  # what a first run finds missing
        if piece in fresh:  # (a reproduction resumes from its cache; a site build reuses executed notebooks)
            shutil.rmtree(work / fresh[piece], ignore_errors=True)
        load_before, began = os.getloadavg()[0], time.perf_counter()
        with (work / f"{piece}.log").open("w") as log:  # its output, for a piece that failed
            done = subprocess.run(command, cwd=ROOT, env={**os.environ, **extra}, stdout=log, stderr=log)
        took = time.perf_counter() - began
        print(
            json.dumps(
                {
                    "piece": piece,
                    "seconds": round(took),
                    "exit": done.returncode,
                    "load_before": round(load_before, 1),
                    "load_after": round(os.getloadavg()[0], 1),
                    "cores": os.cpu_count(),
                }
            ),
            flush=True,
        )


if __name__ == "__main__":
    main()
