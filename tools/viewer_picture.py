"""The viewer's picture on the home page and in ``docs/viewer.md`` (``docs/viewer.png``), made to read at a web page's
width::

    python -m tools.viewer_picture docs/viewer.png

It is what ``toolkit view --scenario 3do --samples 300 --screenshot PNG`` photographs (the office, seed 0, 300 uniform
samples marked at the robot's base), in a narrower window at twice the pixels: the course site shows a picture in a
column of about 690 px, where an 800 px window left the panel's slider labels about 8 px high (reader r18c). In a
window :data:`WINDOW` wide the panel keeps its 340 px and the site shows the whole at about its own size; the
camera is moved sideways (:data:`SHIFT`) so that the scene and the youBot stand in the window's left half, beside the
panel, not under it (reader r23b: the panel covered the right half of the scene). The workspace's outline keeps its
floor's four edges (:func:`floor_outline`): an upright edge of the office's far corner, its foot behind the panel,
poked out above it as a stray stroke (reader r23b).
"""

from __future__ import annotations

import argparse
import sys

import numpy as np

from toolkit import viewer
from toolkit.viewer import drawing
from toolkit.viewer.browser import screenshot

WINDOW = (680, 1000)  # (width, height) in CSS px: the panel down to its "Plan" section, whole (reader r24b: the
#   picture stopped at "Samples", under the section the home page's next paragraph describes; viser docks the panel
#   at the bottom of a window under 576 px), and beside it a scene as wide; under the site's 688 px column
SCALE = 2.0  # pixels per CSS px: sharp where the page shows the picture larger than its window
SHIFT = np.array([3.6, 0.0, 0.0])  # workspace units the camera moves to the robot's right: the robot left of the
#   panel (less than in a shorter window, whose wider view kept it in sight from farther)
SCENARIO, SEED, SAMPLES = "3do", 0, 300


def floor_outline(edges: np.ndarray) -> np.ndarray:
    """Of the region's outline ``edges (12, 2, 3)`` (:func:`toolkit.viewer.drawing.region_edges`), the ``(4, 2, 3)``
    that lie on its floor (both ends at its lowest height)."""
    floor = edges[..., 2].min()
    return edges[np.all(edges[..., 2] == floor, axis=1)]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Photograph the viewer on the 3D office for the docs.")
    parser.add_argument("png", help="where the picture goes (docs/viewer.png)")
    args = parser.parse_args(argv)
    shown = viewer.launch(SCENARIO, seed=SEED, quiet=True)
    try:
        shown.sample("raw", SAMPLES, seed=SEED)
        region = floor_outline(drawing.region_edges(shown.workspace))  # the node of the same name, replaced
        shown.server.scene.add_line_segments("/workspace/region", region, drawing.REGION, thickness=0.05)
        camera = shown.server.initial_camera
        camera.look_at, camera.position = camera.look_at + SHIFT, camera.position + SHIFT
        print(f"wrote {screenshot(shown.url, args.png, size=WINDOW, scale=SCALE)}")
    finally:
        shown.stop()
    return 0


if __name__ == "__main__":
    sys.exit(main())
