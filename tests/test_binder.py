"""Binder: the repo2docker configuration in binder/ installs a toolkit that runs a chapter.

There is no Docker here, so the test does what repo2docker's Python build does with ``binder/requirements.txt``:
``pip install -r binder/requirements.txt`` from the repository's root, here into a clean virtual environment
(from the test session's wheelhouse, filled from the registries: tests/conftest.py's ``fresh_environment``),
then adds what repo2docker's base environment brings (a Jupyter kernel) and runs chapter 01 in quick mode under
``binder/start``, with that environment's kernel.
"""

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BINDER = ROOT / "binder"
CHAPTER = ROOT / "notebooks" / "01_workspaces_and_collision.ipynb"
KERNEL = ["ipykernel", "nbclient"]  # repo2docker's base environment: JupyterLab, its kernel and nbclient


def clean_environment() -> dict[str, str]:
    """This process's environment without the variables that would put this checkout's toolkit on the path."""
    return {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV", "TOOLKIT_QUICK")}


def test_binder_starts_in_quick_mode_unless_told_otherwise():
    env = clean_environment()
    assert (
        "TOOLKIT_QUICK=1" in subprocess.run([BINDER / "start", "env"], env=env, capture_output=True, text=True).stdout
    )
    env["TOOLKIT_QUICK"] = "0"
    assert (
        "TOOLKIT_QUICK=0" in subprocess.run([BINDER / "start", "env"], env=env, capture_output=True, text=True).stdout
    )


def test_binder_builds_with_the_python_this_test_installs_into():
    assert (BINDER / "runtime.txt").read_text().strip() == "python-{}.{}".format(*sys.version_info[:2])


def test_the_requirements_pin_the_cpu_torch_and_install_the_toolkit_for_a_hub():
    lines = [line.split("#")[0].strip() for line in (BINDER / "requirements.txt").read_text().splitlines()]
    lines = [line for line in lines if line]
    pinned = next(line for line in (ROOT / "constraints.txt").read_text().splitlines() if line.startswith("torch=="))
    assert f"{pinned}+cpu" in lines  # the constraints' version, CPU build
    assert "-c ../constraints.txt" in lines and ".[hub]" in lines
    assert "--extra-index-url https://download.pytorch.org/whl/cpu" in lines


def test_the_guides_hub_config_runs_each_students_server_from_the_course_environment():
    """tutorials/instructors_jupyterhub_config.py, read as JupyterHub reads it, sets what the guide says it sets."""
    from traitlets.config import Config

    config, path = Config(), ROOT / "tutorials" / "instructors_jupyterhub_config.py"
    exec(compile(path.read_text(), str(path), "exec"), {"get_config": lambda: config})
    assert config.Spawner.cmd == ["/opt/course/bin/jupyterhub-singleuser"]
    assert config.Spawner.environment == {"TOOLKIT_QUICK": "1", "TOOLKIT_CACHE": "/srv/course/models"}
    assert config.JupyterHub.public_url.endswith("/") and config.JupyterHub.bind_url.startswith("http://127.0.0.1:")
    guide = (ROOT / "tutorials" / "instructors_jupyterhub.md").read_text()
    for line in ('c.Spawner.cmd = ["/opt/course/bin/jupyterhub-singleuser"]', 'c.Spawner.mem_limit = "3G"'):
        assert line in guide and line in path.read_text(), line  # the guide quotes the file


@pytest.mark.slow
@pytest.mark.binder
def test_an_install_from_the_binder_files_runs_a_chapter(fresh_environment, tmp_path):
    venv, env = tmp_path / "binder-venv", clean_environment()
    python = str(fresh_environment(venv, ["-r", "binder/requirements.txt"], KERNEL, cwd=ROOT, env=env))

    where = [python, "-c", "import toolkit, torch; print(toolkit.__file__, torch.__version__)"]
    shown = subprocess.run(where, cwd=tmp_path, env=env, capture_output=True, text=True, check=True).stdout.split()
    assert Path(shown[0]).is_relative_to(venv) and shown[1].endswith("+cpu")  # installed, not this checkout
    assert subprocess.run([python, "-c", "import jupyter_server_proxy"], env=env).returncode == 0

    run = [str(BINDER / "start"), python, "-m", "tools.notebook_runner", str(CHAPTER)]  # start sets quick mode
    done = subprocess.run(run, cwd=ROOT, env=env, capture_output=True, text=True, timeout=1200)
    assert done.returncode == 0 and "FAILED" not in done.stdout, done.stdout + done.stderr[-3000:]
    assert f"{CHAPTER}: wall" in done.stdout
