"""Screenshots of the viewer in a real headless Chromium, and what their pixels show.

Used by the browser test and to make ``docs/viewer.png``::

    toolkit view --scenario 3do --screenshot docs/viewer.png

Chromium renders WebGL in software here (``--disable-gpu``, no ``--use-gl`` flag:
``--use-gl=swiftshader`` would turn WebGL off). ``--virtual-time-budget`` lets the
page run that many milliseconds of timers (WebSocket connection, first frames)
before the screenshot is taken. Without ``--run-all-compositor-stages-before-draw``
about half of the runs never finish (measured: 6 of 12 hung; with it 12 of 12
finished in 6-16 s on 2 busy cores); a run that still hangs is retried once.
"""

from __future__ import annotations

import shutil
import subprocess
import tempfile
from pathlib import Path

import numpy as np
from matplotlib import image as mpimg
from matplotlib.colors import rgb_to_hsv

CHROMIUM_NAMES = ("chromium", "chromium-browser", "google-chrome")
CANVAS_ROWS = (0.2, 0.95)  # fractions of the height clear of the top-left notice and the bottom edge
CANVAS_LEFT = 0.02  # fraction of the width left out on the left
PANEL_PX = 340  # the GUI panel's width on the right, in pixels


def find_chromium() -> str | None:
    """Path of an installed Chromium, or None."""
    return next((path for path in map(shutil.which, CHROMIUM_NAMES) if path), None)


def screenshot(url: str, path: str | Path, *, size: tuple[int, int] = (1280, 800), budget_ms: int = 5000,
               timeout_s: float = 60.0, attempts: int = 2) -> Path:
    """Load ``url`` in headless Chromium and save a PNG of ``size`` (width, height) to ``path``."""
    chromium = find_chromium()
    if chromium is None:
        raise FileNotFoundError(f"no Chromium found (looked for {', '.join(CHROMIUM_NAMES)}); "
                                "install it with `make browser` or `apt-get install chromium`")
    path = Path(path).resolve()
    path.parent.mkdir(parents=True, exist_ok=True)
    path.unlink(missing_ok=True)
    for attempt in range(attempts):
        with tempfile.TemporaryDirectory(prefix="toolkit-chromium-") as profile:
            command = [
                chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--hide-scrollbars", "--run-all-compositor-stages-before-draw", f"--user-data-dir={profile}",
                f"--window-size={size[0]},{size[1]}", f"--virtual-time-budget={budget_ms}", f"--screenshot={path}",
                url,
            ]
            try:
                done = subprocess.run(command, capture_output=True, text=True, timeout=timeout_s)
            except subprocess.TimeoutExpired:
                continue
        if done.returncode != 0 or not path.exists():
            raise RuntimeError(f"chromium failed ({done.returncode}) to screenshot {url}: {done.stderr[-2000:]}")
        return path
    raise TimeoutError(f"chromium did not finish a screenshot of {url} in {attempts} tries of {timeout_s:.0f} s")


def color_share(png: str | Path, rgb: tuple[int, int, int], *, hue_tolerance: float = 15.0,
                min_saturation: float = 0.1) -> float:
    """Share of the canvas's pixels whose hue is within ``hue_tolerance`` degrees of ``rgb``'s.

    Shading scales a face's color and lighting adds white to it; neither moves its hue
    much, so lit, shadowed and see-through faces of one color all count. Grey and
    white (background, grid, text) have no saturation and never count. Only the
    canvas clear of the GUI panel and the top-left notice is looked at.
    """
    pixels = mpimg.imread(str(png))[..., :3].astype(float)  # (H, W, 3) in [0, 1]
    height, width = pixels.shape[:2]
    top, bottom = (int(f * height) for f in CANVAS_ROWS)
    pixels = pixels[top:bottom, int(CANVAS_LEFT * width): width - PANEL_PX]
    hsv = rgb_to_hsv(pixels)  # (h, w, 3), hue in [0, 1)
    target = rgb_to_hsv(np.asarray(rgb, dtype=float) / 255)[0] * 360
    gap = np.abs((hsv[..., 0] * 360 - target + 180) % 360 - 180)  # circular hue distance, degrees
    return float(np.mean((gap <= hue_tolerance) & (hsv[..., 1] >= min_saturation) & (hsv[..., 2] >= 0.15)))
