"""The viewer's picture on the home page and in ``docs/viewer.md`` (``docs/viewer.png``), made to read at a web page's
width::

    python -m tools.viewer_picture docs/viewer.png

It is what ``toolkit view --scenario 3do --samples 300 --screenshot PNG`` photographs (the office, seed 0, 300 uniform
samples marked at the robot's base), in a narrower window: that command's 1280 px, in the course site's column of
about 690 px, left the panel's text about 6 px high. In a window :data:`WINDOW` wide the panel keeps its 340 px, the
scene fills the rest, and the site shows the whole at about 0.85 of its size.
"""

from __future__ import annotations

import argparse
import sys

from toolkit import viewer
from toolkit.viewer.browser import screenshot

WINDOW = (800, 800)  # (width, height) in px: the panel down to the heading of its "Plan" section
SCENARIO, SEED, SAMPLES = "3do", 0, 300


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Photograph the viewer on the 3D office for the docs.")
    parser.add_argument("png", help="where the picture goes (docs/viewer.png)")
    args = parser.parse_args(argv)
    shown = viewer.launch(SCENARIO, seed=SEED, quiet=True)
    try:
        shown.sample("raw", SAMPLES, seed=SEED)
        print(f"wrote {screenshot(shown.url, args.png, size=WINDOW)}")
    finally:
        shown.stop()
    return 0


if __name__ == "__main__":
    sys.exit(main())
