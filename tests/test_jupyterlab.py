"""A student's view: notebooks opened in a real JupyterLab, all cells run in headless Chromium (Playwright).

Notebook 05's page must show an ipywidgets slider, a matplotlib figure and the
embedded viewer's iframe, with no "Error displaying widget" and no traceback. A
notebook many screens tall, one of its code cells folded, saved screen by screen (``--full-page``), must come back
whole: from its first cell's title to its last cell's red picture, no stretch missed.
Skipped only where no Chromium is installed (``make test`` installs Debian's).
"""

import json
import math
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from toolkit.viewer import browser as viewer_browser
from tools import lab_browser

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
        NOTEBOOK,
        env={"TOOLKIT_QUICK": "1", "TOOLKIT_CACHE": str(notebook_cache)},
        screenshot=tmp_path / "lab.png",
        timeout_s=300,  # quick mode runs in about half a minute; a hang fails in minutes, not a quarter hour
    )
    assert shown.cells_run == shown.code_cells > 0, shown
    assert shown.tracebacks == 0, shown
    assert shown.widget_errors == 0, shown
    assert shown.sliders >= 1, shown
    assert shown.images >= 1, shown
    assert shown.iframes >= 1, shown
    assert (tmp_path / "lab.png").stat().st_size > 10_000


RED = (255, 0, 0)
TALL_NOTEBOOK = [  # (cell type, source): a title, screens of printed lines, a red picture at the very end
    ("markdown", "# The first cell's title"),
    *[("code", f"print('\\n'.join(f'cell {i}, line {{j}}' for j in range(40)))") for i in range(1, 5)],
    ("code", f"from PIL import Image\nImage.new('RGB', (400, 120), {RED})"),
]


FOLDED = 1  # the first code cell's source is folded, as the course site folds helper code: its run counts too


def red_pixels(png: str) -> int:
    return int(np.all(np.asarray(Image.open(png).convert("RGB")) == RED, axis=-1).sum())


def test_a_notebook_many_screens_tall_is_saved_whole_screen_by_screen(tmp_path):
    notebook = tmp_path / "tall.ipynb"
    cells = [
        {"cell_type": kind, "metadata": {"jupyter": {"source_hidden": True}} if i == FOLDED else {}, "source": source}
        | ({"outputs": [], "execution_count": None} if kind == "code" else {})
        for i, (kind, source) in enumerate(TALL_NOTEBOOK)
    ]
    kernel = {"name": "python3", "display_name": "Python 3", "language": "python"}
    notebook.write_text(
        json.dumps({"cells": cells, "metadata": {"kernelspec": kernel}, "nbformat": 4, "nbformat_minor": 5})
    )
    shown = lab_browser.run_all(notebook, screenshot=tmp_path / "shots" / "lab.png", full_page=True, timeout_s=120)
    assert shown.cells_run == shown.code_cells == 5 and shown.tracebacks == 0, shown
    screens = shown.screens
    height, total = screens[0].bottom - screens[0].top, screens[-1].bottom
    assert [Path(s.path).name for s in screens] == [f"lab_{i:02d}.png" for i in range(1, len(screens) + 1)]
    assert sorted(p.name for p in (tmp_path / "shots").iterdir()) == [Path(s.path).name for s in screens]
    assert len(screens) == math.ceil(total / height) >= 3, screens  # 160 printed lines: several screens
    assert screens[0].top == 0 and all(b.top <= a.bottom for a, b in zip(screens, screens[1:])), screens  # no gap
    assert all(s.bottom - s.top == height for s in screens)
    assert all(Image.open(s.path).size[1] == height for s in screens)  # each PNG a whole screen
    assert 0 in screens[0].cells and len(TALL_NOTEBOOK) - 1 in screens[-1].cells, screens
    assert sorted(set().union(*(s.cells for s in screens))) == list(range(len(TALL_NOTEBOOK)))
    assert red_pixels(screens[-1].path) > 0.9 * 400 * 120  # the last cell's picture, whole, on the last screen
    assert red_pixels(screens[0].path) == 0  # not on the first: the screens differ
