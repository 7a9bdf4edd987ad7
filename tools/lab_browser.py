"""A notebook as a student sees it: opened in a real JupyterLab, run in headless Chromium (Playwright).

Used by ``tests/test_jupyterlab.py``, to make the README's screenshot, and to look at a
whole rendered notebook, screen by screen (``--full-page``: ``lab_01.png``, ``lab_02.png``, ...)::

    TOOLKIT_QUICK=1 python -m tools.lab_browser notebooks/05_3d_scenes.ipynb \\
        --view-only --screenshot docs/jupyterlab.png
    TOOLKIT_QUICK=1 python -m tools.lab_browser notebooks/02_cae_reconstruction.ipynb \\
        --screenshot lab.png --full-page

The notebook is copied into a temporary folder first (JupyterLab saves what it
runs; the original stays without outputs), a JupyterLab server starts on
127.0.0.1 with a one-time token, Chromium opens the notebook and clicks
*Run → Run All Cells*, and waits until every code cell has run. What the page then
shows is counted: ipywidgets sliders, images (matplotlib figures), iframes (the
embedded viewer), "Error displaying widget" messages and tracebacks. Playwright
drives Debian's Chromium (``executable_path``); it never downloads a browser.

JupyterLab scrolls a notebook inside its own element, not the page, so a page
screenshot (even Playwright's ``full_page=True``) holds one screen. ``full_page``
scrolls that element a screen at a time and saves each, the notebook panel only, the
last one ending where the notebook ends. Lab's windowing is off
(``"windowingMode": "none"``: every cell in the page): ``"full"`` attaches only the cells
in view, ``"defer"`` the others later, and the default, ``"contentVisibility"``, lets the
browser skip drawing those off screen, any of which could hide cells from the counts
above or leave a screen half drawn.
"""

from __future__ import annotations

import argparse
import json
import os
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request
from collections.abc import Iterator
from contextlib import contextmanager, suppress
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import IO

from toolkit.viewer.browser import CHROMIUM_ARGS, find_chromium

WINDOW = (1400, 1000)  # (width, height) of the page
SHOT_WINDOW, SHOT_SCALE = (860, 1000), 2  # the page for one screenshot: narrower, at twice the pixels (see below)
SHOT_HEIGHT = 2400  # CSS px: the tallest cell a screenshot shows whole (the page grows to hold it)
SETTINGS = {  # JupyterLab settings for the run: no news pop-up; every cell in the page, also those scrolled away;
    # no empty screen below the last cell; a code line longer than the cell is wide wraps (reader r23b: a comment
    # ran off the screenshot's right edge)
    "@jupyterlab/apputils-extension/notification": {"fetchNews": "false", "checkForUpdates": False},
    "@jupyterlab/notebook-extension/tracker": {
        "windowingMode": "none",
        "scrollPastEnd": False,
        "codeCellConfig": {"lineNumbers": False, "lineWrap": True},
    },
}
STDERR = '.jp-OutputArea-output[data-mime-type="application/vnd.jupyter.stderr"]'  # errors and warnings render so
PROMPTS = "[...document.querySelectorAll('.jp-CodeCell .jp-InputArea-prompt')]"  # JavaScript: each code cell's prompt
CELLS_RUN = PROMPTS + ".filter(p => /\\[\\d+\\]/.test(p.textContent)).length"  # JavaScript: prompts with a number
SCROLLER = "lab-browser-scroller"  # attribute marking the element the notebook scrolls in
FIND_SCROLLER = f"""() => {{  // the nearest ancestor of the first cell that scrolls, else (it fits) the notebook
    const first = document.querySelector('.jp-NotebookPanel .jp-Cell');
    let node = first;
    while (node && !(['auto', 'scroll'].includes(getComputedStyle(node).overflowY)
                     && node.scrollHeight > node.clientHeight)) node = node.parentElement;
    node = node ?? first.closest('.jp-Notebook');
    node.setAttribute('{SCROLLER}', '');
    return [node.scrollHeight, node.clientHeight];  // the notebook's height and a screen's, in px
}}"""
SCROLL_TO = f"""top => {{  // scroll there; the cells (by index) now in view, and whether an iframe is
    const box = document.querySelector('[{SCROLLER}]');
    box.scrollTop = top;
    const view = box.getBoundingClientRect(), overlaps = r => r.bottom > view.top && r.top < view.bottom;
    const cells = [...box.querySelectorAll('.jp-Cell')];
    return [box.scrollTop, cells.flatMap((c, i) => overlaps(c.getBoundingClientRect()) ? [i] : []),
            [...box.querySelectorAll('iframe')].some(f => overlaps(f.getBoundingClientRect()))];
}}"""


@dataclass
class Screen:
    """One PNG of a notebook saved screen by screen: which stretch of it, which cells it shows."""

    path: str
    top: int  # px from the notebook's top to the screen's top
    bottom: int  # px from the notebook's top to the screen's bottom
    cells: list[int]  # the cells (0-based, markdown cells included) of which some part is in view


@dataclass
class RenderedNotebook:
    """What the page shows once every cell has run."""

    code_cells: int
    cells_run: int
    sliders: int  # ipywidgets sliders rendered
    images: int  # images in output areas (matplotlib figures)
    iframes: int  # iframes in output areas (the embedded viewer)
    widget_errors: int  # "Error displaying widget" messages
    tracebacks: int  # error outputs
    seconds: float  # from "Run All Cells" to the last cell's end
    screens: list[Screen] = field(default_factory=list)  # the PNGs saved, top to bottom


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@contextmanager
def jupyterlab(root: Path, env: dict[str, str] | None = None, timeout_s: float = 120.0) -> Iterator[str]:
    """A JupyterLab server on ``root``, bound to 127.0.0.1; yields its URL with the token, stops it afterwards."""
    port, token = _free_port(), secrets.token_hex(16)
    settings = root / ".lab-settings"
    for plugin, value in SETTINGS.items():
        path = settings / f"{plugin}.jupyterlab-settings"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(value))
    env = {**os.environ, "JUPYTERLAB_SETTINGS_DIR": str(settings), **(env or {})}
    command = [
        sys.executable,
        "-m",
        "jupyterlab",
        "--no-browser",
        "--ServerApp.ip=127.0.0.1",
        f"--ServerApp.port={port}",
        "--ServerApp.port_retries=0",
        f"--IdentityProvider.token={token}",
        f"--ServerApp.root_dir={root}",
        "--LabApp.news_url=",
        "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
    ]
    if os.geteuid() == 0:  # CI machines run as root, which JupyterLab refuses unless told
        command.append("--allow-root")
    url = f"http://127.0.0.1:{port}"
    with tempfile.TemporaryFile() as log:
        # start_new_session: its kernels share its process group, so one signal stops all
        server = subprocess.Popen(command, env=env, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
        try:
            yield _wait_until_up(server, log, url, token, timeout_s)
        finally:
            _stop(server)


def _wait_until_up(server: subprocess.Popen, log: IO[bytes], url: str, token: str, timeout_s: float) -> str:
    """Wait until the server at ``url`` answers; its notebook URL pattern (with ``{path}`` and the token)."""
    deadline = time.monotonic() + timeout_s
    while True:
        try:
            urllib.request.urlopen(f"{url}/api/status?token={token}", timeout=5).close()
            return f"{url}/lab/tree/{{path}}?token={token}"
        except OSError:
            if server.poll() is not None or time.monotonic() > deadline:
                log.seek(0)
                raise RuntimeError(f"JupyterLab did not start on {url}: {log.read().decode()[-2000:]}") from None
            time.sleep(0.5)


def _stop(server: subprocess.Popen) -> None:
    """Stop the server and its kernels (one process group): SIGTERM, then SIGKILL after 20 s."""
    for sig, wait_s in ((signal.SIGTERM, 20), (signal.SIGKILL, None)):
        with suppress(ProcessLookupError):
            os.killpg(server.pid, sig)
        try:
            server.wait(timeout=wait_s)
            return
        except subprocess.TimeoutExpired:
            continue


def run_all(
    notebook: str | Path,
    *,
    env: dict[str, str] | None = None,
    screenshot: str | Path | None = None,
    full_page: bool = False,
    view_only: bool = False,
    timeout_s: float = 900.0,
) -> RenderedNotebook:
    """Open ``notebook`` in JupyterLab, run all cells, and count what the page shows.

    With ``screenshot``, save a PNG there of the cell that shows the first embedded viewer (of the page where
    there is none); with ``view_only``, of that cell from the viewer down (the 3D view, its caption and what the
    cell prints below); with ``full_page`` too, the whole notebook instead, a screen per PNG named after it
    (``lab.png``: ``lab_01.png``, ...)."""
    from playwright.sync_api import sync_playwright

    chromium = find_chromium()
    if chromium is None:
        raise FileNotFoundError("no Chromium found; install it with `make browser` or `apt-get install chromium`")
    notebook = Path(notebook).resolve()
    n_code = sum(cell["cell_type"] == "code" for cell in json.loads(notebook.read_text())["cells"])
    with tempfile.TemporaryDirectory(prefix="toolkit-lab-") as root, sync_playwright() as pw:
        shutil.copy(notebook, Path(root) / notebook.name)
        with jupyterlab(Path(root), env) as url:
            browser = pw.chromium.launch(executable_path=chromium, args=CHROMIUM_ARGS)
            try:
                one_shot = screenshot is not None and not full_page
                width, height = SHOT_WINDOW if one_shot else WINDOW
                page = browser.new_page(
                    viewport={"width": width, "height": height}, device_scale_factor=SHOT_SCALE if one_shot else 1
                )
                page.set_default_timeout(timeout_s * 1000)
                page.goto(url.format(path=notebook.name))
                seconds = _run_every_cell(page, n_code)
                page.wait_for_timeout(2000)  # widgets and iframes finish rendering
                rendered = _count_outputs(page, n_code, seconds)
                if screenshot is not None:
                    _close_side_panel(page)
                    if full_page:
                        rendered.screens = _save_screens(page, Path(screenshot))
                    else:
                        _save_screenshot(page, rendered, Path(screenshot), view_only=view_only)
            finally:
                browser.close()
    return rendered


def _run_every_cell(page, n_code: int) -> float:
    """Click *Run → Run All Cells* once the kernel has started and wait until every one of the ``n_code`` code
    cells has run, or one failed and the rest were skipped; the seconds that took. Folded code cells (the course
    site's fold, ``source_hidden`` in a cell's metadata) are opened first with *View → Expand All Code*: a folded
    cell shows no prompt, so its run could not be counted."""
    page.wait_for_selector(".jp-Notebook .jp-CodeCell")
    _wait_idle(page)  # the kernel has started
    page.locator("#jp-menu-panel").get_by_text("View", exact=True).click()
    page.get_by_text("Expand All Code", exact=True).click()
    began = time.monotonic()
    page.locator("#jp-menu-panel").get_by_text("Run", exact=True).click()
    page.get_by_text("Run All Cells", exact=True).click()
    page.wait_for_function(f"""() => {{
        const failed = [...document.querySelectorAll('{STDERR}')].some(o => o.textContent.includes('Traceback'));
        return {CELLS_RUN} === {n_code} || (failed && !{PROMPTS}.some(p => p.textContent.includes('*')));
    }}""")
    _wait_idle(page)
    return time.monotonic() - began


def _count_outputs(page, n_code: int, seconds: float) -> RenderedNotebook:
    """What the page shows now, counted."""
    outputs = page.locator(".jp-OutputArea-output")
    return RenderedNotebook(
        code_cells=n_code,
        cells_run=page.evaluate(CELLS_RUN),
        sliders=page.locator(".jp-OutputArea .widget-slider").count(),
        images=outputs.locator("img").count(),
        iframes=outputs.locator("iframe").count(),
        widget_errors=page.get_by_text("Error displaying widget").count(),
        tracebacks=page.locator(STDERR, has_text="Traceback").count(),
        seconds=seconds,
    )


def _close_side_panel(page) -> None:
    """Close the file browser (or whichever left panel is open): room for the notebook."""
    open_panel = page.locator(".jp-SideBar.jp-mod-left .lm-TabBar-tab.lm-mod-current")
    if open_panel.count():
        open_panel.click()
        page.wait_for_timeout(500)  # the notebook widens, its outputs reflow


def _save_screenshot(page, rendered: RenderedNotebook, path: Path, *, view_only: bool = False) -> None:
    """A PNG of the cell that shows the first embedded viewer, its code and its output (of the page where there is
    none). The page is :data:`SHOT_WINDOW` wide, about a web page's column (the course site's home page shows the
    picture about 700 px wide), at :data:`SHOT_SCALE` times the pixels: a picture of the whole 1400 px window, so
    shrunk, left its text 6-8 px high. A cell taller than the window is shown whole, the window made as tall (up to
    :data:`SHOT_HEIGHT`). ``view_only`` leaves out the cell's code and the outputs above the viewer's (reader r25b:
    on the home page the code filled a third of the picture and the still repeated, small, what the view shows)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    if not rendered.iframes:
        page.screenshot(path=str(path))
        return
    cell = page.locator(".jp-CodeCell", has=page.locator(".jp-OutputArea-output iframe")).first
    tall = cell.bounding_box()["height"]  # a cell taller than the window: the window grows to hold it whole
    if tall + 40 > page.viewport_size["height"]:  # (a clip past the window's edge is cut off there)
        page.set_viewport_size({"width": page.viewport_size["width"], "height": min(int(tall) + 120, SHOT_HEIGHT)})
        page.wait_for_timeout(1000)  # the notebook reflows
    cell.scroll_into_view_if_needed()
    page.wait_for_timeout(3000)  # its WebGL scene draws
    clip = cell.bounding_box()
    if view_only:  # from the top left of the output holding the viewer (its empty prompt left out) to the cell's foot
        view = cell.locator(".jp-OutputArea-output", has=page.locator("iframe")).first.bounding_box()
        right, bottom = clip["x"] + clip["width"], clip["y"] + clip["height"]
        left = view["x"] - 12  # a margin, so that the caption's text does not touch the picture's edge
        clip = {"x": left, "y": view["y"], "width": right - left, "height": bottom - view["y"]}
    page.screenshot(path=str(path), clip=clip)


def _save_screens(page, path: Path) -> list[Screen]:
    """PNGs of the notebook panel from its top to its end, a screen each (the last one overlaps the one before
    so that it ends where the notebook ends), named ``path``'s stem + ``_01``, ``_02``, ...; what each shows."""
    total, height = page.evaluate(FIND_SCROLLER)
    box = page.locator(f"[{SCROLLER}]").bounding_box()
    tops = [*range(0, total - height, height), max(total - height, 0)]  # scroll offsets, the last one at the end
    digits = max(2, len(str(len(tops))))
    path.parent.mkdir(parents=True, exist_ok=True)
    screens = []
    for i, wanted in enumerate(tops, start=1):
        top, cells, iframe = page.evaluate(SCROLL_TO, wanted)
        page.wait_for_timeout(3000 if iframe else 300)  # outputs in view draw (a viewer's WebGL scene: seconds)
        shot = path.with_name(f"{path.stem}_{i:0{digits}d}{path.suffix}")
        page.screenshot(path=str(shot), clip=box)
        screens.append(Screen(str(shot), top, top + height, cells))
    return screens


def _wait_idle(page) -> None:
    """Wait until the status bar says the kernel is idle ("Python 3 (ipykernel) | Idle")."""
    page.wait_for_function("(document.querySelector('#jp-main-statusbar')?.innerText ?? '').includes('| Idle')")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description="Run a notebook in JupyterLab in headless Chromium and report what "
        "the page shows (quick mode: TOOLKIT_QUICK=1)."
    )
    parser.add_argument("notebook")
    parser.add_argument(
        "--screenshot",
        metavar="PNG",
        help="save a PNG here of the cell that shows the first embedded viewer (of the page where there is none)",
    )
    parser.add_argument(
        "--view-only",
        action="store_true",
        help="with --screenshot: that cell from the embedded viewer down (the view, its caption, what follows)",
    )
    parser.add_argument(
        "--full-page",
        action="store_true",
        help="with --screenshot: the whole notebook, a screen per PNG (PNG's name + _01, _02, ...)",
    )
    args = parser.parse_args(argv)
    if args.full_page and not args.screenshot:
        parser.error("--full-page needs --screenshot PNG (the series is named after it)")
    shown = run_all(args.notebook, screenshot=args.screenshot, full_page=args.full_page, view_only=args.view_only)
    print(asdict(shown))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
