"""Shared test set-up: headless plotting, few threads, a fixed seed, no JupyterHub's variables; the assignments, the
toolkit's wheel and the wheels that fresh environments install from, each made once a session (the assignments and the
notebooks' models once a run, shared by pytest-xdist's workers); which worker runs which test file."""

import fcntl
import os

os.environ.setdefault("MPLBACKEND", "Agg")

import subprocess
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]
GRADING = {"test_assignments.py", "test_grading_sandbox.py", "test_handout.py", "test_plain_install.py"}

for _where in ("JUPYTERHUB_SERVICE_PREFIX", "JUPYTERHUB_PUBLIC_URL", "JUPYTERHUB_HOST", "TOOLKIT_VIEWER_BASE_URL"):
    os.environ.pop(_where, None)  # run on a hub, the viewer's tests still expect its local address


@pytest.hookimpl(tryfirst=True)  # before pytest-xdist's own
def pytest_xdist_make_scheduler(config: pytest.Config, log):
    """``--dist loadgroup`` (``make test``'s slow tests) here: each test file runs whole in one worker, as with
    ``--dist loadfile`` (its module's fixtures made once), and the files of :data:`GRADING` in one worker together,
    each grading in bubblewrap's sandbox: the sandbox numbers its uids per process (two workers' sandboxes would share
    a uid and its process limit), the hostile submissions' test asserts no process of a sandbox uid outlives it, and the
    handout copies the assignments' dist/ that the first of them builds. (pytest-xdist's own loadgroup reads
    ``xdist_group`` marks into node ids, which pytest 9 no longer lets it change.)"""
    if config.getvalue("dist") != "loadgroup":
        return None
    from xdist.scheduler import LoadFileScheduling  # type: ignore[import-untyped]

    class Grouped(LoadFileScheduling):
        def _split_scope(self, nodeid: str) -> str:
            path = nodeid.split("::", 1)[0]
            return "grading" if Path(path).name in GRADING else path

    return Grouped(config, log)


def _shared(tmp_path_factory: pytest.TempPathFactory, name: str) -> Path:
    """A folder ``name`` of this test run, the same for every pytest-xdist worker (their base folders' parent)."""
    base = tmp_path_factory.getbasetemp()
    folder = (base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base) / name
    folder.mkdir(exist_ok=True)
    return folder


@contextmanager
def _locked(path: Path) -> Iterator[None]:
    """Held by one thread of one process at a time (an exclusive ``flock`` on ``path``, each call its own open file)."""
    with open(path, "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        yield


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
    """Trained models shared by the notebooks of one test run, every worker's (``TOOLKIT_CACHE``), not the user's
    cache (a model folder appears by a rename, whole: :func:`toolkit.teaching.notebook.trained_models`)."""
    return _shared(tmp_path_factory, "notebook-cache")


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
def assignment_zip(tmp_path_factory) -> Callable[[str], Path]:
    """``build(name)``: :func:`grading.build` of assignment ``name`` (``otter assign``, which runs the master's
    solutions against every test first, and the toolkit's wheel added), once a test run; its autograder zip.
    Threads and pytest-xdist's workers may ask at once: the first builds (``dist/`` beside the master) under a file
    lock, the others wait and take its zip."""
    from toolkit.teaching import grading

    shared = _shared(tmp_path_factory, "assignments")

    def build(name: str) -> Path:
        with _locked(shared / f"{name}.lock"):
            built = shared / f"{name}.zip-path"
            if not built.exists():
                built.write_text(str(grading.build(name)))
            return Path(built.read_text())

    return build


@pytest.fixture(scope="session")
def toolkit_wheel(tmp_path_factory) -> Path:
    """The toolkit's wheel built from this checkout (:func:`gradescope.build_wheel`), once a test run."""
    from toolkit.teaching import gradescope

    folder = _shared(tmp_path_factory, "wheel")
    with _locked(folder.with_suffix(".lock")):
        if not folder.with_suffix(".built").exists():
            folder.with_suffix(".built").write_text(str(gradescope.build_wheel(folder, ROOT)))
        return Path(folder.with_suffix(".built").read_text())


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

    pip resolves every install from one wheelhouse of this test run (every worker's), filled from the registries the
    first time (one download of what all those tests ask for, instead of each install reading the indexes again); what
    it lacks for an install is downloaded into it from the registries first, one download at a time, so each
    environment holds what the registries give its requirements. pip byte-compiles nothing (Python compiles a module
    when it is first imported)."""
    house = _shared(tmp_path_factory, "wheelhouse")

    def download(requirements: list, cwd: Path, env: dict[str, str]) -> None:
        fetch = [sys.executable, "-m", "pip", "download", "--quiet", "--retries", "0", "--dest", house, *requirements]
        subprocess.run(fetch, cwd=cwd, env=env, check=True, timeout=1800)  # no retrying the CPU index where none is

    def make(venv: Path, *installs: list, cwd: Path, env: dict[str, str]) -> Path:
        with _locked(house.with_suffix(".lock")):  # one download at a time, the first one the seed
            if not house.with_suffix(".seeded").exists():
                download(_wheelhouse_seed(toolkit_wheel), ROOT, env)
                house.with_suffix(".seeded").touch()
        subprocess.run([sys.executable, "-m", "venv", venv], check=True)
        python = venv / "bin" / "python"
        for requirements in installs:
            pip: list[str | Path] = [
                python,
                "-m",
                "pip",
                "install",
                "--quiet",
                "--no-compile",
                "--no-index",
                "--find-links",
                house,
            ]
            if subprocess.run([*pip, *requirements], cwd=cwd, env=env, capture_output=True).returncode != 0:
                with _locked(house.with_suffix(".lock")):
                    download(requirements, cwd, env)  # what the wheelhouse lacked
                subprocess.run([*pip, *requirements], cwd=cwd, env=env, check=True, timeout=1800)
        return python

    return make
