"""Shared test set-up: headless plotting, few threads, a fixed seed, no JupyterHub's variables; the assignments, the
toolkit's wheel and the wheels that fresh environments install from, each made once a session."""

import os

os.environ.setdefault("MPLBACKEND", "Agg")

import subprocess
import sys
import threading
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]

for _where in ("JUPYTERHUB_SERVICE_PREFIX", "JUPYTERHUB_PUBLIC_URL", "JUPYTERHUB_HOST", "TOOLKIT_VIEWER_BASE_URL"):
    os.environ.pop(_where, None)  # run on a hub, the viewer's tests still expect its local address


@pytest.fixture
def rng():
    return np.random.default_rng(0)


@pytest.fixture
def make_viewer():
    """Viewers on free ports (``port=0``), always stopped afterwards."""
    from toolkit import viewer

    started = []

    def make(scenario, **kwargs):
        v = viewer.Viewer(scenario, port=0, **kwargs)
        started.append(v)
        return v

    yield make
    for v in started:
        v.stop()


@pytest.fixture(scope="session")
def checkpoint_2ds(tmp_path_factory):
    """A checkpoint folder of a quick 2DS ``strong`` model (seconds to train)."""
    from toolkit.experiments import pipeline
    from toolkit.experiments.config import RunConfig

    config = RunConfig.create("2ds", "strong", quick=True, progress=False, device="cpu")
    return pipeline.train_and_save(config, tmp_path_factory.mktemp("ckpt") / "ckpt")[2]


@pytest.fixture(scope="session")
def notebook_cache(tmp_path_factory):
    """Trained models shared by the notebooks of one test session (``TOOLKIT_CACHE``), not the user's cache."""
    return tmp_path_factory.mktemp("notebook-cache")


@pytest.fixture
def quick_notebooks(monkeypatch, notebook_cache):
    """Notebooks run as the test suite runs them: quick mode, the session's model cache, inline figures."""
    monkeypatch.setenv("TOOLKIT_QUICK", "1")
    monkeypatch.setenv("TOOLKIT_CACHE", str(notebook_cache))
    monkeypatch.setenv("MPLBACKEND", "module://matplotlib_inline.backend_inline")


@pytest.fixture(autouse=True)
def library_restored():
    """Each test ends with the library whole: grading in this process runs hidden tests that make an assignment's
    library functions unavailable (``toolkit.teaching.unavailable.apply``), and a later test would meet them so."""
    yield
    from toolkit.teaching import unavailable

    unavailable.restore()


@pytest.fixture(scope="module")
def chromium():
    """A headless Chromium (Debian's, driven by Playwright), one for a test module's browser tests."""
    from playwright.sync_api import sync_playwright

    from toolkit.viewer import browser

    with sync_playwright() as pw:
        launched = pw.chromium.launch(executable_path=browser.find_chromium(), args=browser.CHROMIUM_ARGS)
        try:
            yield launched
        finally:
            launched.close()


@pytest.fixture(scope="session")
def assignment_zip() -> Callable[[str], Path]:
    """``build(name)``: :func:`grading.build` of assignment ``name`` (``otter assign``, which runs the master's
    solutions against every test first, and the toolkit's wheel added), once a session; its autograder zip.
    Threads may ask at once."""
    from toolkit.teaching import grading

    built: dict[str, Path] = {}
    locks: dict[str, threading.Lock] = {}
    guard = threading.Lock()

    def build(name: str) -> Path:
        with guard:
            lock = locks.setdefault(name, threading.Lock())
        with lock:
            if name not in built:
                built[name] = grading.build(name)
        return built[name]

    return build


@pytest.fixture(scope="session")
def toolkit_wheel(tmp_path_factory) -> Path:
    """The toolkit's wheel built from this checkout (:func:`gradescope.build_wheel`), once a session."""
    from toolkit.teaching import gradescope

    return gradescope.build_wheel(tmp_path_factory.mktemp("wheel"), ROOT)


def _wheelhouse_seed(wheel: Path) -> list[str]:
    """What the tests that install into fresh environments ask pip for, together (a plain install's, Binder's and an
    autograder's requirements, and the build backend Binder's ``.[hub]`` needs): downloaded at once, then each install
    resolves without an index."""
    import otter
    import tomllib  # Python 3.11's

    from toolkit.teaching import gradescope

    backend = tomllib.loads((ROOT / "pyproject.toml").read_text())["build-system"]["requires"]
    torch = [f"--extra-index-url={gradescope.TORCH_INDEX}", gradescope.torch_pin(ROOT)]
    kernels = ["nbclient", "ipykernel", "jupyter_server", f"otter-grader[grading,plugins]=={otter.__version__}"]
    return [*torch, f"{wheel}[hub,grading,ompl]", *kernels, *backend]


@pytest.fixture(scope="session")
def fresh_environment(tmp_path_factory, toolkit_wheel) -> Callable[..., Path]:
    """``make(venv, *installs, cwd, env)``: a new virtual environment at ``venv`` and, one after another, each
    ``pip install`` of ``installs`` (a test's install command's arguments) run in it; returns its Python.

    pip resolves every install from one wheelhouse of this session, filled from the registries the first time (one
    download of what all those tests ask for, instead of each install reading the indexes again); what it lacks for
    an install is downloaded into it from the registries first, so each environment holds what the registries give
    its requirements. pip byte-compiles nothing (Python compiles a module when it is first imported)."""
    house = tmp_path_factory.mktemp("wheelhouse")
    downloaded: list[bool] = []

    def download(requirements: list, cwd: Path, env: dict[str, str]) -> None:
        fetch = [sys.executable, "-m", "pip", "download", "--quiet", "--retries", "0", "--dest", house, *requirements]
        subprocess.run(fetch, cwd=cwd, env=env, check=True, timeout=1800)  # no retrying the CPU index where none is

    def make(venv: Path, *installs: list, cwd: Path, env: dict[str, str]) -> Path:
        if not downloaded:
            download(_wheelhouse_seed(toolkit_wheel), ROOT, env)
            downloaded.append(True)
        subprocess.run([sys.executable, "-m", "venv", venv], check=True)
        python = venv / "bin" / "python"
        for requirements in installs:
            pip = [python, "-m", "pip", "install", "--quiet", "--no-compile", "--no-index", "--find-links", house]
            if subprocess.run([*pip, *requirements], cwd=cwd, env=env, capture_output=True).returncode != 0:
                download(requirements, cwd, env)  # what the wheelhouse lacked
                subprocess.run([*pip, *requirements], cwd=cwd, env=env, check=True, timeout=1800)
        return python

    return make
