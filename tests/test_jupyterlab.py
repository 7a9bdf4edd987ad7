"""A student's view: notebook 05 opened in a real JupyterLab, all cells run in headless Chromium (Playwright).

The page must show an ipywidgets slider, a matplotlib figure and the embedded
viewer's iframe, with no "Error displaying widget" and no traceback. Skipped only
where no Chromium is installed (``make test`` installs Debian's).
"""

from pathlib import Path

import pytest

from toolkit.teaching import lab_browser
from toolkit.viewer import browser as viewer_browser

pytestmark = [
    pytest.mark.browser,
    pytest.mark.slow,
    pytest.mark.skipif(
        viewer_browser.find_chromium() is None,
        reason="no Chromium installed (run `make browser` or `apt-get install chromium`)",
    ),
]

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks" / "05_3d_scenes.ipynb"


def test_notebook_05_runs_in_jupyterlab_with_widgets_figures_and_the_viewer(notebook_cache, tmp_path):
    shown = lab_browser.run_all(
        NOTEBOOK, env={"TOOLKIT_QUICK": "1", "TOOLKIT_CACHE": str(notebook_cache)}, screenshot=tmp_path / "lab.png"
    )
    assert shown.cells_run == shown.code_cells > 0, shown
    assert shown.tracebacks == 0, shown
    assert shown.widget_errors == 0, shown
    assert shown.sliders >= 1, shown
    assert shown.images >= 1, shown
    assert shown.iframes >= 1, shown
    assert (tmp_path / "lab.png").stat().st_size > 10_000
