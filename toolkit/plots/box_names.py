"""The names under a row of boxes (:func:`toolkit.plots.cae.contraction`'s Jacobian norms): models all named "λ = ..."
ticked by their λ alone (:func:`tick_names`), each name wrapped to fit its slot (:func:`slot_points`, :func:`fitted`),
so that names side by side never run into each other. Nothing here calls ``show()``.
"""

from __future__ import annotations

import re
import textwrap

from matplotlib.font_manager import FontProperties
from matplotlib.textpath import TextToPath

NAME_POINTS = 9.0  # the boxes' names, in points


def tick_names(names: list[str]) -> tuple[list[str], str]:
    """The boxes' tick labels and the axis's name: models all named "λ = ..." ticked by their λ alone, a trailing
    "(...)" left to the legend (reader r31b: "λ = 0.961 (mean reading)" wrapped to four lines under its box); other
    names whole, under "model"."""
    if not all(name.startswith("λ = ") for name in names):
        return names, "model"
    return [re.sub(r" \(.*\)$", "", name.removeprefix("λ = ")) for name in names], "λ"


def slot_points(ax, n: int) -> float:
    """The width in points of one of ``n`` equal slots across ``ax`` once its figure is laid out, less a gap."""
    root = ax.get_figure(root=True)  # the figure itself, where ax sits in one of its subfigures
    root.draw_without_rendering()  # the axes take their width
    return 0.85 * ax.bbox.width * 72 / root.dpi / n


def fitted(names: list[str], width: float, size: float) -> list[str]:
    """Each name wrapped at its spaces into the fewest lines each at most ``width`` points wide at ``size`` points
    (a single word wider stays whole): names side by side never run into each other."""
    measure = TextToPath()
    font = FontProperties(size=size)

    def fits(lines: list[str]) -> bool:
        return all(measure.get_text_width_height_descent(line, font, ismath=False)[0] <= width for line in lines)

    wrapped = []
    for name in names:
        ways = [textwrap.wrap(name, k, break_long_words=False) for k in range(len(name), 0, -1)]
        wrapped.append("\n".join(next((lines for lines in ways if fits(lines)), ways[-1])))
    return wrapped
