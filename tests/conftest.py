"""Shared test set-up: headless plotting, few threads, a fixed seed, no JupyterHub's variables."""

import os

os.environ.setdefault("MPLBACKEND", "Agg")

import numpy as np
import pytest

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
