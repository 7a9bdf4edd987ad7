"""Marks on a map's cells that one can see however fine the map: notebook 03's mistakes.

A map of a 2-DoF slice (:class:`~toolkit.plots.slices.CSpaceSlice`) marks some of its cells (the classifier's
dangerous mistakes on a P(valid) map, both kinds of mistake on a decision map, :mod:`toolkit.plots.classifier`).
On a coarse map a mark covers most of its cell; on a fine one (chapter 03 at full size: 100 cells over 3 inches,
about 2 points a cell) a mark that size is a speck, and a mark made larger would cover its neighbours' marks.
:func:`draw_cell_marks` puts a mark on each marked cell, over the map and under its outlines (or over them: the
classifier's maps draw their mistakes over the boundary, which would cut a mark beside it in two);
:func:`fit_cell_marks`, once the figure is laid out, sizes each mark to :data:`MARK_SHARE` of its cell, and where
that is under :data:`MIN_MARK` points, puts one mark on each block of ``k x k`` cells holding a marked cell, at their
middle, ``k`` the fewest cells that make it that large.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import PathCollection
from matplotlib.figure import Figure
from scipy import ndimage

from toolkit.plots.slices import CSpaceSlice

MIN_MARK = 5.0  # points: the least side of a mark, however fine the map
MARK_SHARE = 0.7  # of its cell (or block of cells) a mark covers: the map beneath shows between two marks
GID = "cell marks"  # how fit_cell_marks finds the marks draw_cell_marks drew


def draw_cell_marks(ax, grid: CSpaceSlice, mask, **style) -> PathCollection:
    """A mark (``style``: scatter's options) at the centre of each cell of ``grid`` where ``mask (nx, ny)`` holds,
    over the map, under the lines on it (a boundary stays whole) unless ``style`` gives a ``zorder`` above them;
    :func:`fit_cell_marks` sizes them once laid out."""
    i, j = np.nonzero(mask)
    return ax.scatter(grid.axes[0][i], grid.axes[1][j], s=MIN_MARK**2, gid=GID, **style)


def fit_cell_marks(fig: Figure, grid: CSpaceSlice) -> int:
    """Size the marks :func:`draw_cell_marks` drew on ``fig``'s maps of ``grid`` to their cells as laid out,
    merging them into blocks of ``k x k`` cells where a cell is too small; returns the largest ``k`` (1: a mark a
    cell), for the figure's description to say."""
    fig.draw_without_rendering()  # lays the figure out: the axes take their final sizes
    first = np.array([axis[0] for axis in grid.axes])  # (2,) the first cell's centre
    cell = np.array([abs(axis[1] - axis[0]) if len(axis) > 1 else 1.0 for axis in grid.axes])  # (2,) data units
    largest = 1
    for ax in fig.axes:
        marks = [c for c in ax.collections if isinstance(c, PathCollection) and c.get_gid() == GID]
        if not marks:
            continue
        side = cell_points(ax, grid)
        k = max(1, int(np.ceil(MIN_MARK / (MARK_SHARE * side))))  # cells a block, each way
        largest = max(largest, k)
        for mark in marks:
            mark.set_sizes([(MARK_SHARE * k * side) ** 2])
            offsets = np.asarray(mark.get_offsets())  # (n, 2) the marked cells' centres
            if k == 1 or not len(offsets):
                continue  # one mark a cell
            cells = np.rint((offsets - first) / cell).astype(int)  # (n, 2) cell indices
            blocks, block_of = np.unique(cells // k, axis=0, return_inverse=True)  # (m, 2), (n,)
            centres = np.array([cells[block_of.ravel() == b].mean(axis=0) for b in range(len(blocks))])  # (m, 2)
            mark.set_offsets(first + centres * cell)  # each at its marked cells' middle
    return largest


def narrow_cells(mask, width: int) -> np.ndarray:
    """The cells of ``mask (nx, ny)`` in parts of it narrower than ``width`` cells each way (what an opening by a
    ``width x width`` square removes): a strip a hatch's dots, spaced wider than it, may miss (review r16b: a one-cell
    strip of conservative mistakes on chapter 03's strong map showed no dot). Same shape, bool."""
    mask = np.asarray(mask, dtype=bool)
    if width <= 1:
        return np.zeros_like(mask)
    wide = ndimage.binary_opening(mask, structure=np.ones((width, width), dtype=bool), border_value=0)
    return mask & ~wide


def cell_points(ax: Axes, grid: CSpaceSlice) -> float:
    """The smaller side of one cell of ``grid`` on ``ax`` as laid out, in points."""
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    per_unit = np.array([ax.bbox.width / abs(x1 - x0), ax.bbox.height / abs(y1 - y0)]) * 72 / ax.figure.dpi
    cell = np.array([abs(axis[1] - axis[0]) if len(axis) > 1 else 1.0 for axis in grid.axes])  # (2,) data units
    return float(np.min(cell * per_unit))


def draw_narrow_cells(ax, grid: CSpaceSlice, mask, spacing: float, **style) -> int:
    """Mark (:func:`draw_cell_marks`, ``style``) the cells of ``mask (nx, ny)`` on ``ax``, laid out, that lie in strips
    narrower than 1.5 times ``spacing`` points, a hatch's distance between two dots: a square that wide always holds
    one, a narrower strip may hold none. How many cells it marked."""
    narrow = narrow_cells(mask, int(np.ceil(1.5 * spacing / cell_points(ax, grid))))
    if narrow.any():
        draw_cell_marks(ax, grid, narrow, **style)
    return int(narrow.sum())
