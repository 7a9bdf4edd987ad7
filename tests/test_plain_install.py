"""A plain install: the toolkit's wheel in a clean environment outside the checkout, as a hub, Binder or a course
has it, and everything a student and an instructor run there.

The wheel is built from this checkout (:func:`toolkit.teaching.gradescope.build_wheel`) and installed with the one
command of ``tutorials/instructors_jupyterhub.md`` (the CPU torch, ``-c constraints.txt``, the ``hub``, ``grading``
and ``ompl`` extras) into a fresh virtual environment, from the registries through the test session's wheelhouse
(tests/conftest.py's ``fresh_environment``). Every chapter and
tutorial then runs in quick mode from a copy of ``notebooks/`` and ``tutorials/`` outside the checkout (nothing the
library reads may come from the repository), and ``toolkit plan`` and ``toolkit grade`` run there too, the latter on
an assignment folder given by ``$TOOLKIT_ASSIGNMENTS``.

Measured (``pytest -s --durations=0 tests/test_plain_install.py`` alone, the project's 2-core machine at a load of 5
to 18): 15 min in all, of which the wheel, the wheelhouse's download and the install about 4 min, the eleven notebooks
8.4 min in one runner process (kernel CPU 231 s; each one's wall and CPU time printed), ``toolkit grade`` 97 s (with
building the assignment, which a whole session has done before), ``toolkit plan`` 14 s.
"""

import json
import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from test_assignments import _solved
from test_binder import clean_environment

from toolkit.geometry.collision import exact_checker
from toolkit.geometry.workspace import Workspace
from toolkit.planning.local_planner import default_resolution, path_is_valid
from toolkit.scenarios import get as scenario
from toolkit.teaching import gradescope, grading, sandbox

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted(ROOT.glob("notebooks/*.ipynb")) + sorted(ROOT.glob("tutorials/*.ipynb"))
EXTRAS = "hub,grading,ompl"
pytestmark = [pytest.mark.slow, pytest.mark.binder]


@pytest.fixture(scope="module")
def installed(toolkit_wheel, fresh_environment, tmp_path_factory) -> tuple[Path, dict[str, str], Path]:
    """The environment's Python, the environment to run it in (quick mode, a model cache of its own) and a folder
    outside the checkout holding copies of ``notebooks/`` and ``tutorials/``."""
    work = tmp_path_factory.mktemp("plain-install")
    env = clean_environment() | {"TOOLKIT_QUICK": "1", "TOOLKIT_CACHE": str(work / "cache")}
    *index, torch, _ = gradescope.requirements(str(toolkit_wheel), ROOT)  # the CPU index and torch, as the guide's
    pip = ["-c", ROOT / "constraints.txt", *index[0].split(), torch, f"{toolkit_wheel}[{EXTRAS}]", "nbclient"]
    python = fresh_environment(work / "venv", pip, cwd=work, env=env)
    course = work / "course"
    for folder in ("notebooks", "tutorials"):
        shutil.copytree(ROOT / folder, course / folder, ignore=shutil.ignore_patterns("dist", ".ipynb_checkpoints"))
    shutil.copy(ROOT / "tools" / "notebook_runner.py", work)  # the runner alone: tools/ is not on its path
    where = [python, "-c", "import toolkit; print(toolkit.__file__)"]
    shown = subprocess.run(where, cwd=course, env=env, capture_output=True, text=True, check=True).stdout.strip()
    assert Path(shown).is_relative_to(work / "venv"), shown  # installed, not this checkout
    return python, env, course


@pytest.fixture(scope="module")
def notebook_runs(installed) -> dict[str, str]:
    """Each chapter's and tutorial's line from the notebook runner, which ran them all from the copy, one per core
    at a time, each worker importing the toolkit once: ``{name: "...: wall ..."}``."""
    python, env, course = installed
    copies = [course / notebook.relative_to(ROOT) for notebook in NOTEBOOKS]
    jobs = str(len(os.sched_getaffinity(0)))  # a quick kernel keeps about one core busy: one at a time per core
    run = [python, course.parent / "notebook_runner.py", "--quick", "--jobs", jobs, *copies]
    done = subprocess.run(run, cwd=course, env=env, capture_output=True, text=True, timeout=3600)
    print(done.stdout.strip())  # each one's wall and CPU time (pytest -s)
    lines = {Path(line.split(": ")[0]).stem: line for line in done.stdout.splitlines() if ".ipynb: " in line}
    return {
        name: lines.get(name, f"no line for {name}:\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
        for name in (notebook.stem for notebook in NOTEBOOKS)
    }


@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=lambda p: p.stem)
def test_every_chapter_and_tutorial_runs_from_the_installed_toolkit(notebook_runs, notebook):
    line = notebook_runs[notebook.stem]
    assert ": wall " in line and "FAILED" not in line, line


def test_toolkit_plan_from_the_installed_toolkit_returns_an_exactly_valid_path(installed):
    python, env, course = installed
    toolkit = python.parent / "toolkit"
    command = [toolkit, "plan", "--scenario", "3dc7", "--sampler", "OB", "--seed", "3", "--json"]
    answer = json.loads(subprocess.run(command, cwd=course, env=env, capture_output=True, text=True, check=True).stdout)
    assert answer["success"]
    robot = scenario("3dc7").robot
    workspace = Workspace(*(np.asarray(answer["workspace"][key]) for key in ("lower", "upper", "boxes")))
    path = np.asarray(answer["path"])  # (P, dof)
    assert path.shape[0] >= 2 and path.shape[1] == robot.dof
    assert path_is_valid(exact_checker(workspace, robot), path, default_resolution(robot))  # checked here, exactly


def test_toolkit_grade_from_the_installed_toolkit_grades_an_assignment_folder(installed, assignment_zip, tmp_path):
    python, env, _ = installed
    name = "bridge_test"
    assignment_zip(name)  # built in the checkout (make assignments); the folder a course keeps, dist/ included
    assignments = tmp_path / "assignments"
    shutil.copytree(grading.master(name).parent, assignments / name)
    submission = tmp_path / "submissions" / f"{name}.ipynb"
    submission.parent.mkdir()
    shutil.copy(_solved(name), submission)  # the master's solutions: every point
    grade = [python.parent / "toolkit", "grade", submission] + (["--unisolated"] if sandbox.unavailable() else [])
    done = subprocess.run(
        grade, cwd=tmp_path, env=env | {grading.FOLDER_VARIABLE: str(assignments)}, capture_output=True, text=True
    )
    points = grading.points(name)
    assert done.stdout.strip().splitlines()[-1] == f"score: {sum(points.values()):g}/{sum(points.values()):g}", (
        done.stdout + done.stderr[-3000:]
    )
    elsewhere = subprocess.run(
        [python.parent / "toolkit", "grade", submission], cwd=tmp_path, env=env, text=True, capture_output=True
    )
    assert f"no assignments in {tmp_path / 'tutorials' / 'assignments'}" in elsewhere.stdout + elsewhere.stderr
