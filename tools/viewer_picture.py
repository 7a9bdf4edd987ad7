"""The viewer's picture on the home page and in ``docs/viewer.md`` (``docs/viewer.png``), made to read at a web page's
width::

    python -m tools.viewer_picture docs/viewer.png

It is what ``toolkit view --scenario 3do --samples 300 --screenshot PNG`` photographs (the office, seed 0, 300 uniform
samples marked at the robot's base), in a narrower window at twice the pixels: the course site shows a picture in a
column of about 690 px, where an 800 px window left the panel's slider labels about 8 px high (reader r18c). The
panel is narrowed to :data:`PANEL_WIDTH` and two of its folders are folded (:data:`FOLD`), so that it ends above the
window's foot and covers under a third of the scene (reader r25b: at its full 340 px, cut off at "Layers", it hid the
blocks behind it); the camera is moved sideways (:data:`SHIFT`) so that the scene and the youBot stand in the window's
left part, beside the panel, not under it (reader r23b). The workspace's outline keeps its floor's four edges
(:func:`floor_outline`): an upright edge of the office's far corner, its foot behind the panel, poked out above it as
a stray stroke (reader r23b).

``docs/office.png`` (linked from the home page's row for chapter 05) is chapter 05's office as section 2 draws it
(seed 0, 2000 uniform samples), the overview of its still alone (:func:`office_still`): the whole office, every kind
of mark and a legend (reader r27e: a JupyterLab screenshot showed a dozen marks close to the robot and no outline)::

    python -m tools.viewer_picture --office docs/office.png
"""

from __future__ import annotations

import argparse
import sys

import numpy as np

from toolkit import viewer
from toolkit.viewer import drawing
from toolkit.viewer.browser import screenshot

WINDOW = (680, 860)  # (width, height) in CSS px: the panel whole, its "Plan" section included (reader r24b; viser
#   docks the panel at the bottom of a window under 576 px), and beside it a wider scene; under the site's 688 px column
SCALE = 2.0  # pixels per CSS px: sharp where the page shows the picture larger than its window
PANEL_WIDTH = 250  # CSS px (viser's own: 340): the sliders' labels and ends still whole
FOLD = ("Workspace", "Samples")  # folded, as a click on their titles folds them: the panel ends above the window's foot
SHIFT = np.array([2.8, 0.0, 0.0])  # workspace units the camera moves to the robot's right: the robot left of the panel
SCENARIO, SEED, SAMPLES = "3do", 0, 300
OFFICE_SAMPLES = 2000  # chapter 05's N_SAMPLES at full size: its section 2's scene, drawn from the same seed
OFFICE_DPI = 150  # about 820 px wide: the site's 688 px column shows its 10 pt text at about 17 px


def office_samples() -> np.ndarray:
    """``(OFFICE_SAMPLES, 8)``: chapter 05's uniform configurations of the youBot (its ``office_samples``)."""
    from toolkit import scenarios

    return scenarios.get(SCENARIO).robot.sample(np.random.default_rng(SEED), OFFICE_SAMPLES)


def office_still(png: str) -> str:
    """Write ``png``: the overview of chapter 05's office still (:meth:`toolkit.viewer.Viewer.still`), its close-ups
    cropped off, its title, the robot's name and the legend kept."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.transforms import Bbox

    with viewer.Viewer(SCENARIO, seed=SEED, port=0) as shown:
        shown.show_samples(office_samples())
        fig = shown.still()
    renderer = FigureCanvasAgg(fig).get_renderer()
    fig.canvas.draw()
    overview = next(ax for ax in fig.axes if ax.get_title().startswith("the whole workspace"))
    parts = [overview.get_tightbbox(renderer) or overview.bbox]
    parts += [text.get_window_extent(renderer) for text in overview.texts]
    parts += [legend.get_window_extent(renderer) for legend in fig.legends]  # the robot's name lies outside the layout
    crop = Bbox.union(parts).transformed(fig.dpi_scale_trans.inverted()).padded(0.1)
    fig.savefig(png, dpi=OFFICE_DPI, bbox_inches=crop)
    return png


def floor_outline(edges: np.ndarray) -> np.ndarray:
    """Of the region's outline ``edges (12, 2, 3)`` (:func:`toolkit.viewer.drawing.region_edges`), the ``(4, 2, 3)``
    that lie on its floor (both ends at its lowest height)."""
    floor = edges[..., 2].min()
    return edges[np.all(edges[..., 2] == floor, axis=1)]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Photograph the viewer on the 3D office for the docs.")
    parser.add_argument("png", help="where the picture goes (docs/viewer.png, or docs/office.png with --office)")
    parser.add_argument("--office", action="store_true", help="chapter 05's still of the office instead")
    args = parser.parse_args(argv)
    if args.office:
        print(f"wrote {office_still(args.png)}")
        return 0
    shown = viewer.launch(SCENARIO, seed=SEED, quiet=True)
    try:
        shown.sample("raw", SAMPLES, seed=SEED)
        region = floor_outline(drawing.region_edges(shown.workspace))  # the node of the same name, replaced
        shown.server.scene.add_line_segments("/workspace/region", region, drawing.REGION, thickness=0.05)
        camera = shown.server.initial_camera
        camera.look_at, camera.position = camera.look_at + SHIFT, camera.position + SHIFT
        shown.server.gui.main_panel.set_width(PANEL_WIDTH)
        print(f"wrote {screenshot(shown.url, args.png, size=WINDOW, scale=SCALE, fold=FOLD)}")
    finally:
        shown.stop()
    return 0


if __name__ == "__main__":
    sys.exit(main())
