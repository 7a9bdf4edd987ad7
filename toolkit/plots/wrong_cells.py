"""The wrong cells of a decoded occupancy grid marked on it (notebook 02; :func:`toolkit.plots.cae.reconstructions`).

A decoded cell is wrong where its sign differs from the input's. Each wrong cell is coloured by its kind and carries
a mark in ink, so that the kind shows without colour: ``x`` a *missed* cell (input occupied, decoded free), ``o`` an
*invented* one (input free, decoded occupied). When the input is a grid with a few cells flipped (section 6 of
notebook 02), a wrong flipped cell is not a missed or invented cell: the decoder drew it as in the clean grid, it
*ignored* the flip. Flipped cells then get a kind of their own, a hollow square, on a green cell where the flip was
ignored; the other wrong cells keep ``x`` and ``o``. A figure's title and its description, region by region
(:func:`grid_part`), count them in the same words (:func:`wrong_in_words`).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.colors import ListedColormap
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from toolkit.plots.alt import Part, map_part
from toolkit.plots.palette import COLORS

ERROR_COLORS = ListedColormap([COLORS["phantom"], COLORS["missed"]])  # -1: invented cell; +1: missed cell
ERROR_MARKERS = {"missed": "x", "phantom": "o", "ignored": "s", "copied": "s"}  # a second cue, in ink
ERROR_INK: dict[str, Any] = dict(fillstyle="none", mew=1.2)  # a ring, not a dot (in the legend too): a visible stroke
LABELS = {
    "missed": "missed cell (x)",
    "phantom": "invented cell (o)",
    "ignored": "flipped cell, flip ignored (square on green)",
    "copied": "flipped cell, flip copied (square)",
}


def error_cells(grid: np.ndarray, decoded: np.ndarray) -> np.ndarray:
    """Boolean mask of the cells whose decoded sign differs from the input's (what reconstruction accuracy counts)."""
    return np.sign(decoded) != np.sign(grid)


def wrong_kinds(grid: np.ndarray, decoded: np.ndarray, flipped: np.ndarray | None = None) -> dict[str, np.ndarray]:
    """``{kind: mask (nx, ny)}`` of one grid's cells: ``missed`` and ``phantom`` (invented) wrong cells, and, given
    the ``flipped`` cells ``(nx, ny)``, ``ignored`` (flipped, wrong) and ``copied`` (flipped, right) ones, which are
    then neither missed nor invented."""
    wrong = error_cells(grid, decoded)
    flipped = np.zeros_like(wrong) if flipped is None else np.asarray(flipped, dtype=bool)
    kinds = {"missed": wrong & ~flipped & (grid > 0), "phantom": wrong & ~flipped & (grid < 0)}
    if flipped.any():
        kinds |= {"ignored": wrong & flipped, "copied": ~wrong & flipped}
    return kinds


def wrong_in_words(
    kinds: dict[str, np.ndarray], where: tuple[slice, slice] = (slice(None), slice(None)), marks: bool = False
) -> str:
    """The wrong cells of ``kinds`` (:func:`wrong_kinds`) inside the region ``where`` (default: all), as a title and a
    region of a figure's description both count them: "2 missed, 0 invented", or, given flipped cells, "1 of 3 flips
    ignored; other cells: 2 missed, 0 invented" (an ignored flip is never counted missed or invented). ``marks``: each
    kind with its mark, "2 missed (x), 0 invented (o)", a title's key (reader r37b: the legend lay screens above)."""
    count = {kind: int(mask[where].sum()) for kind, mask in kinds.items()}
    x, o = (f" ({ERROR_MARKERS['missed']})", f" ({ERROR_MARKERS['phantom']})") if marks else ("", "")
    wrong = f"{count['missed']} missed{x}, {count['phantom']} invented{o}"
    if "ignored" in count:
        wrong = f"{count['ignored']} of {count['ignored'] + count['copied']} flips ignored; other cells: {wrong}"
    return wrong


def draw_wrong_cells(ax, grid: np.ndarray, kinds: dict[str, np.ndarray], cell: float) -> None:
    """The wrong cells of ``kinds`` (:func:`wrong_kinds`) over a faded input already on ``ax``: missed and invented
    cells in their colours, ignored flips green, each with its mark in ink ``cell`` points wide."""
    others = kinds["missed"] | kinds["phantom"]
    ax.imshow(np.ma.masked_array(grid, ~others).T, origin="lower", cmap=ERROR_COLORS, vmin=-1, vmax=1)
    if "ignored" in kinds:
        ignored = np.ma.masked_array(np.ones_like(grid), ~kinds["ignored"])
        ax.imshow(ignored.T, origin="lower", cmap=ListedColormap([COLORS["ignored"]]), vmin=0, vmax=1)
    for kind, mask in kinds.items():
        x, y = np.nonzero(mask)
        size = (0.9 if ERROR_MARKERS[kind] == "s" else 0.7) * cell  # a square round its cell, x and o inside one
        ax.plot(x, y, ERROR_MARKERS[kind], color=COLORS["ink"], markersize=size, **ERROR_INK)


def legend_handles(kinds: list[str]) -> tuple[list[Any], list[str]]:
    """Legend handles and labels for the ``kinds`` drawn: each cell's colour with its mark on it."""
    handles: list[Any] = []
    for kind in kinds:
        mark = Line2D([], [], marker=ERROR_MARKERS[kind], color=COLORS["ink"], linestyle="", markersize=7, **ERROR_INK)
        face = {"missed": COLORS["missed"], "phantom": COLORS["phantom"], "ignored": COLORS["ignored"]}.get(kind)
        handles.append((Patch(facecolor=face), mark) if face else mark)
    return handles, [LABELS[kind] for kind in kinds]


def grid_part(name: str, said: str, grid: np.ndarray, decoded: np.ndarray, flipped: np.ndarray | None = None) -> Part:
    """One workspace's row of :func:`toolkit.plots.cae.reconstructions` read region by region: the blocked share of
    the input and of the decoded grid, and the cells decoded wrong there, counted as the row's title counts them
    (given the ``flipped (nx, ny)`` cells, an ignored flip is neither missed nor invented: :func:`wrong_kinds`)."""
    kinds = wrong_kinds(grid, decoded, flipped)

    def region(cells: tuple[slice, slice]) -> str:
        blocked = f"{np.mean(grid[cells] > 0):.0%} blocked, decoded {np.mean(decoded[cells] > 0):.0%}"
        return f"{blocked}; {wrong_in_words(kinds, cells)}"

    nx, ny = grid.shape
    text = f"{said}. The grid by region, top row first: blocked share of the input and of the decoded grid, wrong cells"
    return map_part(name, text + " as the title counts them", grid.shape, ("x cell", 0, nx), ("y cell", 0, ny), region)
