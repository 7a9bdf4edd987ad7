"""Screenshots of the viewer in a real headless Chromium, taken once the page shows the scene.

Used by the browser test, by ``toolkit view --screenshot PNG``, and to make ``docs/viewer.png``
(in a window narrow enough to read at a web page's width)::

    python -m tools.viewer_picture docs/viewer.png

Playwright drives Debian's Chromium (``make browser``). WebGL renders in software
there (``--disable-gpu``; ``--use-gl=swiftshader`` would turn WebGL off), and on a
busy machine the first frame can be long in coming (``docs/viewer.md``). So the picture is not
taken after a fixed time: the page is photographed every second until ``ready(png)``
says it shows what is expected (by default, the workspace's obstacles), within a
total budget after which a ``TimeoutError`` names the last picture. (The earlier
way, ``chromium --screenshot`` with a fixed ``--virtual-time-budget``, took its one
picture blind and, beside busy processes, timed out.)
"""

from __future__ import annotations

import shutil
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np
from matplotlib import image as mpimg
from matplotlib.colors import rgb_to_hsv

from toolkit.viewer import drawing as draw

CHROMIUM_NAMES = ("chromium", "chromium-browser", "google-chrome")
CANVAS_ROWS = (0.2, 0.95)  # fractions of the height clear of the top-left notice and the bottom edge
CANVAS_LEFT = 0.02  # fraction of the width left out on the left
PANEL_PX = 340  # the GUI panel's width on the right, in pixels
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",  # no network besides the page
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]


def find_chromium() -> str | None:
    """Path of an installed Chromium, or None."""
    return next((path for path in map(shutil.which, CHROMIUM_NAMES) if path), None)


def shows_obstacles(png: str | Path) -> bool:
    """Whether a screenshot shows the workspace's obstacles (every scene has some): the scene has arrived."""
    return color_share(png, draw.OBSTACLE) > 0.001


def screenshot(
    url: str,
    path: str | Path,
    *,
    size: tuple[int, int] = (1280, 800),
    scale: float = 1.0,
    ready: Callable[[Path], bool] = shows_obstacles,
    budget_s: float = 300.0,
    every_s: float = 1.0,
    fold: tuple[str, ...] = (),
) -> Path:
    """Load ``url`` in headless Chromium and save a PNG of ``size`` (width, height; ``scale`` times as many pixels,
    the page's text as sharp as a high-density screen shows it) to ``path`` once
    ``ready(path)`` holds, photographing the page every ``every_s`` seconds for at most ``budget_s``. ``fold`` names
    folders of the panel to fold first (their titles clicked, as a student would), so that the scene shows below."""
    chromium = find_chromium()
    if chromium is None:
        raise FileNotFoundError(
            f"no Chromium found (looked for {', '.join(CHROMIUM_NAMES)}); "
            "install it with `make browser` or `apt-get install chromium`"
        )
    try:
        from playwright.sync_api import TimeoutError as PageTimeout
        from playwright.sync_api import sync_playwright
    except ImportError:
        raise FileNotFoundError(
            "screenshots need Playwright: pip install playwright (it is in the dev extras, pip install -e '.[dev]')"
        ) from None
    path = Path(path).resolve()
    path.parent.mkdir(parents=True, exist_ok=True)
    path.unlink(missing_ok=True)
    deadline = time.monotonic() + budget_s

    def left_ms() -> float:
        return max(1.0, deadline - time.monotonic()) * 1000

    with sync_playwright() as playwright:
        try:
            browser = playwright.chromium.launch(executable_path=chromium, args=CHROMIUM_ARGS, timeout=left_ms())
            page = browser.new_page(viewport={"width": size[0], "height": size[1]}, device_scale_factor=scale)
            page.goto(url, timeout=left_ms())
            # viser's pop-up notices (e.g. "Software WebGL rendering detected" in a headless browser) are about the
            # browser, not the scene: hidden, so that a picture shows what a student's browser shows.
            page.add_style_tag(content=".mantine-Notifications-root { display: none !important; }")
            for title in fold:
                page.get_by_text(title, exact=True).first.click(timeout=left_ms())
                page.wait_for_timeout(1000)  # the folder's closing animation, over before the picture
            while True:
                page.screenshot(path=str(path), timeout=left_ms())
                if ready(path):
                    return path
                if time.monotonic() + every_s > deadline:
                    break
                time.sleep(every_s)
        except PageTimeout:
            pass
    raise TimeoutError(
        f"{url} did not show what was expected within {budget_s:.0f} s; the last screenshot: "
        f"{path if path.exists() else 'none'}"
    )


def color_share(
    png: str | Path, rgb: tuple[int, int, int], *, hue_tolerance: float = 15.0, min_saturation: float = 0.1
) -> float:
    """Share of the canvas's pixels whose hue is within ``hue_tolerance`` degrees of ``rgb``'s.

    Shading scales a face's color and lighting adds white to it; neither moves its hue
    much, so lit, shadowed and see-through faces of one color all count. Grey and
    white (background, grid, text) have no saturation and never count. Only the
    canvas clear of the GUI panel and the top-left notice is looked at.
    """
    pixels = mpimg.imread(str(png))[..., :3].astype(float)  # (H, W, 3) in [0, 1]
    height, width = pixels.shape[:2]
    top, bottom = (int(f * height) for f in CANVAS_ROWS)
    pixels = pixels[top:bottom, int(CANVAS_LEFT * width) : width - PANEL_PX]
    hsv = rgb_to_hsv(pixels)  # (h, w, 3), hue in [0, 1)
    target = rgb_to_hsv(np.asarray(rgb, dtype=float) / 255)[0] * 360
    gap = np.abs((hsv[..., 0] * 360 - target + 180) % 360 - 180)  # circular hue distance, degrees
    return float(np.mean((gap <= hue_tolerance) & (hsv[..., 1] >= min_saturation) & (hsv[..., 2] >= 0.15)))
