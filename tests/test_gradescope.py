"""Gradescope: an assignment's autograder zip installs the toolkit from itself and grades without network.

There is no Gradescope (nor Docker) here, so the test does what the zip's ``setup.sh`` and ``run_autograder`` do,
in a clean virtual environment instead of Gradescope's conda one: it installs exactly what the zip's
``environment.yml`` lists (its Python is this one; conda's packages and the pip part are installed with pip: the
toolkit from the wheel inside the zip, the rest from the registries through the test session's wheelhouse, as in
tests/test_binder.py),
then grades with ``otter run -a <zip>`` in a network namespace of its own (bubblewrap's ``--unshare-net``): the
master's solutions score full marks, the blank student notebook nothing. The seconds of the install and of the
grading are printed (``pytest -s``; tutorials/instructors.md quotes them).
"""

from __future__ import annotations

import json
import shutil
import socket
import subprocess
import sys
import time
import zipfile
from pathlib import Path

import otter
import pytest
import yaml
from test_assignments import _solved
from test_binder import clean_environment

from toolkit.teaching import gradescope, grading, sandbox
from tools import handout

ROOT = Path(__file__).resolve().parents[1]  # the repository

NAME = "bridge_test"
OTTER_FILES = {"run_autograder", "run_otter.py", "setup.sh", "environment.yml", "otter_config.json"}
OFFLINE = ["bwrap", "--dev-bind", "/", "/", "--unshare-net", "--die-with-parent", "--"]  # all of it, but no network


def _requirements(source: Path) -> list[str]:
    """The pip lines that install what the unpacked zip's ``environment.yml`` lists: its conda packages besides
    Python and pip (PyPI has them under the same names), then its pip part, with the zip's root
    (``/autograder/source``, where Gradescope unpacks it) at ``source``."""
    dependencies = yaml.safe_load((source / "environment.yml").read_text())["dependencies"]
    conda = [d for d in dependencies if isinstance(d, str) and d.split("=")[0] not in ("python", "pip")]
    pip = next(d["pip"] for d in dependencies if isinstance(d, dict))
    return [*conda, *(line.replace("/autograder/source/", f"{source}/") for line in pip)]


def _otter_run(python: str, submission: Path, out: Path, env: dict[str, str]) -> dict[str, float]:
    """Each question's score from ``otter run -a`` on ``submission`` with no network (its ``results.json``)."""
    out.mkdir()
    run = [*OFFLINE, python, "-m", "otter", "run", "--no-logo", "-a", str(out.parent / "autograder.zip")]
    done = subprocess.run([*run, "-o", str(out), str(submission)], cwd=out, env=env, capture_output=True, text=True)
    assert (out / "results.json").is_file(), done.stdout[-3000:] + done.stderr[-3000:]
    tests = json.loads((out / "results.json").read_text())["tests"]
    return {t["name"]: t["score"] for t in tests if t.get("max_score") is not None}


@pytest.fixture(scope="module")
def built(assignment_zip) -> Path:
    """The assignment's autograder zip, as ``make assignments`` builds it (once a test session)."""
    return assignment_zip(NAME)


@pytest.mark.slow
def test_the_zip_installs_the_cpu_torch_and_the_toolkit_from_itself_and_no_solution(built, tmp_path):
    source = tmp_path / "source"
    with zipfile.ZipFile(built) as archive:
        archive.extractall(source)
        names = set(archive.namelist())
    wheel = next(source.glob("sample_collision_toolkit-*-py3-none-any.whl"))
    assert {n for n in names if not n.startswith("tests/")} == OTTER_FILES | {wheel.name}
    python = "python={}.{}".format(*sys.version_info[:2])
    torch = next(line for line in (ROOT / "constraints.txt").read_text().splitlines() if "torch==" in line)
    assert _requirements(source) == [
        "jupyter_server",
        f"otter-grader[grading,plugins]=={otter.__version__}",  # otter adds itself
        f"--extra-index-url {gradescope.TORCH_INDEX}",
        f"{torch}+cpu",
        str(wheel),
    ]
    assert python in (source / "environment.yml").read_text()
    with zipfile.ZipFile(wheel) as archive:
        archive.extractall(source / "wheel")
    assert "toolkit" in {p.name for p in (source / "wheel").iterdir()}
    found = [f.split(": ", 1) for f in handout.find_secrets(source, [NAME])]  # solutions' and hidden tests' lines
    assert found, "the hidden tests are in the zip, and find_secrets finds their lines"
    hidden = " ".join(_hidden_tests(built).split())
    leaked = [f"{path}: {line}" for path, line in found if not (path.startswith("tests/") and line in hidden)]
    assert not leaked, f"a solution, or a hidden test outside otter's tests/: {leaked[:3]}"


def _hidden_tests(zip_path: Path) -> str:
    """The code of every hidden test of the assignment (from the notebook otter assign writes beside the zip)."""
    tests = json.loads((zip_path.parent / f"{NAME}.ipynb").read_text())["metadata"]["otter"]["tests"]
    cases = [case for test in tests.values() for suite in test["suites"] for case in suite["cases"] if case["hidden"]]
    return "\n".join(line[4:] for case in cases for line in case["code"].splitlines())  # without ">>> " / "... "


@pytest.mark.slow
@pytest.mark.binder
def test_otter_run_grades_with_the_zip_in_a_clean_environment_without_network(built, fresh_environment, tmp_path):
    if why := sandbox.unavailable():
        pytest.fail(f"bubblewrap must run where the tests run (make sandbox): {why}")
    shutil.copy(built, tmp_path / "autograder.zip")
    source, venv, env = tmp_path / "source", tmp_path / "venv", clean_environment()
    with zipfile.ZipFile(tmp_path / "autograder.zip") as archive:
        archive.extractall(source)
    began = time.perf_counter()
    (tmp_path / "requirements.txt").write_text("\n".join(_requirements(source)) + "\n")  # as conda hands them to pip
    python = str(fresh_environment(venv, ["-r", "requirements.txt"], cwd=tmp_path, env=env))
    installed = time.perf_counter() - began

    where = [python, "-c", "import toolkit, torch; print(toolkit.__file__, torch.__version__)"]
    shown = subprocess.run(where, cwd=tmp_path, env=env, capture_output=True, text=True, check=True).stdout.split()
    assert Path(shown[0]).is_relative_to(venv) and shown[1].endswith("+cpu")  # from the zip's wheel, not this checkout
    kernels = [python, "-m", "jupyter", "kernelspec", "list", "--json"]
    specs = json.loads(subprocess.run(kernels, env=env, capture_output=True, text=True, check=True).stdout)
    assert Path(specs["kernelspecs"]["python3"]["resource_dir"]).is_relative_to(venv)  # the kernel otter starts
    with socket.create_server(("127.0.0.1", 0)) as listener:  # the control: no connection leaves OFFLINE
        reach = f"import socket; socket.create_connection(('127.0.0.1', {listener.getsockname()[1]}), timeout=5)"
        assert subprocess.run([*OFFLINE, python, "-c", reach], env=env, capture_output=True).returncode != 0

    began = time.perf_counter()
    solved = _otter_run(python, _solved(NAME), tmp_path / "solved", env)
    blank = _otter_run(python, grading.student_notebook(NAME), tmp_path / "blank", env)
    graded = time.perf_counter() - began
    print(f"\n{NAME}: install {installed:.0f} s (this session's wheelhouse), otter run on two {graded:.0f} s")
    assert solved == grading.points(NAME) == {"q1": 6.0, "q2": 2.0}
    assert blank == {"q1": 0.0, "q2": 0.0}
