"""Marks on their own mistakes: notebook 03's squares and circles each drawn on a cell it stands for (reader r42c).

:func:`toolkit.plots.cell_marks.fit_cell_marks` sizes the marks on a map and merges them, where the map is fine, into
one per tile of ``k x k`` cells holding any. A mark given its cells (:func:`on_cells`: the map's mistakes of its
kind) is then drawn (:func:`fit_on_cells`, again by :func:`place_on_cells` once its figure is laid out for good) on
one of its tile's mistake cells, the one nearest the tile's mistakes' centroid: a square on a cell kept and in
collision, a circle on a cell rejected and free, so on the side of the threshold's contour the model chose (reader
r42c: moved towards the truth's side of the outline, squares sat on the black the model rejects). Among those cells
it prefers one whose mark, rings included, lies inside the map's frame (r19b) and clear of the marks already placed
(r18b: a pile of squares could not be counted); a tile whose every mistake lies beside a placed mark has none.
"""

from __future__ import annotations

from collections.abc import Mapping
from weakref import WeakKeyDictionary

import numpy as np
from matplotlib.collections import PathCollection
from matplotlib.figure import Figure

from toolkit.plots.cell_marks import CLEAR, RING, cell_marks, cell_points, fit_cell_marks
from toolkit.plots.slices import CSpaceSlice

_CELLS: WeakKeyDictionary[PathCollection, np.ndarray] = WeakKeyDictionary()  # each mark's mistake cells (n, 2)


def on_cells(marks: PathCollection, mask) -> PathCollection:
    """Give ``marks`` (:func:`~toolkit.plots.cell_marks.draw_cell_marks`'s) the cells ``mask (nx, ny)`` they stand
    for (its mistakes of their kind), for :func:`fit_on_cells` to draw each on one of them."""
    _CELLS[marks] = np.argwhere(np.asarray(mask, dtype=bool)).astype(float)
    return marks


def fit_on_cells(fig: Figure, grid: CSpaceSlice) -> dict[str, int]:
    """:func:`~toolkit.plots.cell_marks.fit_cell_marks` (its blocks, per label), then each mark given its cells
    drawn on one of them (:func:`place_on_cells`); a figure that adds a title or legend after this, changing its maps'
    size, calls :func:`place_on_cells` again last with the blocks this returned."""
    blocks = fit_cell_marks(fig, grid)
    place_on_cells(fig, grid, blocks)
    return blocks


def place_on_cells(fig: Figure, grid: CSpaceSlice, blocks: Mapping[str, int]) -> None:
    """Each mark given its cells (:func:`on_cells`) drawn, one per tile of ``blocks[label]`` cells a side holding
    any, on the tile's cell nearest its mistakes' centroid (:func:`nearest_mistake`), as ``fig`` is laid out now."""
    fig.draw_without_rendering()  # the layout the figure will be drawn with
    first = np.array([axis[0] for axis in grid.axes])  # (2,) the first cell's centre
    cell = np.array([abs(axis[1] - axis[0]) if len(axis) > 1 else 1.0 for axis in grid.axes])  # (2,) data units
    for ax in fig.axes:
        for mark in cell_marks(ax):
            cells = _CELLS.get(mark)
            if cells is None or not len(cells):
                continue
            points = cell_points(ax, grid)  # one cell, in points
            size = float(np.sqrt(mark.get_sizes()[0]))  # points
            pitch = float((str(mark.get_gid()).split(":") + ["0"])[1] or 0)
            apart = (size + CLEAR) / points if pitch else 0.0  # cells between two marks' centres, at least
            inset = max(0.0, (size / 2 + RING) / points - 0.5)  # cells: an edge cell's centre to a whole mark
            k = int(blocks.get(str(mark.get_label()), 1))
            tiles, tile_of = np.unique((cells // k).astype(int), axis=0, return_inverse=True)
            placed = np.zeros((0, 2))
            for t in range(len(tiles)):
                at = nearest_mistake(cells[tile_of.ravel() == t], placed, apart, inset, grid.shape)
                if at is not None:
                    placed = np.vstack([placed, at])
            mark.set_offsets(first + placed * cell)


def nearest_mistake(cells: np.ndarray, placed: np.ndarray, apart: float, inset: float, shape) -> np.ndarray | None:
    """Of one tile's mistake ``cells (n, 2)``, the one a mark is drawn on: nearest their centroid among those at least
    ``apart`` cells (the larger axis) from every mark ``placed (p, 2)``, those whose mark lies ``inset`` cells inside
    the map of ``shape`` first; None where every one lies beside a placed mark (that mark stands for them too)."""
    if len(placed):
        cells = cells[np.max(np.abs(cells[:, None] - placed[None]), axis=2).min(axis=1) >= apart - 1e-9]
    if not len(cells):
        return None
    framed = np.all((cells >= inset - 1e-9) & (cells <= np.array(shape) - 1 - inset + 1e-9), axis=1)  # (n,)
    distance = np.linalg.norm(cells - cells.mean(axis=0), axis=1) + 1e6 * ~framed
    return cells[np.argmin(distance)]


def marks_counted(counts: Mapping[str, int], ax, blocks: Mapping[int, int]) -> str:
    """A P(valid) map's title lines: the share of its cells wrong (reader r36c), then its dangerous and conservative
    cells (``counts``, by answer: ``confusion_counts``) and, where a mark stands for a tile of ``blocks[code]`` cells
    a side (3: squares, 1: circles), the marks on ``ax`` beside them (reader r34c: "6,343 conservative (circles)" over
    27 circles, the rule only in the legend)."""
    dangerous, conservative = counts["invalid kept (dangerous)"], counts["valid rejected"]
    share = (dangerous + conservative) / max(1, sum(counts.values()))  # r36c: 22 circles stood for 64 % of the map
    wrong = f"{share:.0%} of the map wrong" if share >= 0.01 or not share else f"{share:.1%} of the map wrong"
    if max(blocks.values()) == 1:
        return f"{wrong}\n{dangerous:,} dangerous cells (squares), {conservative:,} conservative (circles)"
    marks = {str(m.get_label()): len(np.asarray(m.get_offsets())) for m in cell_marks(ax)}
    return f"{wrong}\n" + "\n".join(
        f"{cells:,} {word} cells: {marks.get(label, 0)} {shape}, 1 per {k} x {k}-cell tile"
        if cells
        else f"0 {word} cells"
        for cells, word, label, shape, k in (
            (dangerous, "dangerous", "invalid kept (dangerous)", "squares", blocks[3]),
            (conservative, "conservative", "valid rejected", "circles", blocks[1]),
        )
    )


LABEL = (66.0, 28.0)  # points: a node's "in collision" label and its coordinates, two lines, box included (9-point)
OFFSETS = ((30, -30), (-30, -30), (30, 30), (-30, 30), (40, -8), (-40, -8), (60, 40))  # points from the node, in order


def labels_clear_of(ax, grid: CSpaceSlice, side, text: str) -> None:
    """Each annotation starting with ``text`` on ``ax`` moved to the first of :data:`OFFSETS` (points from the point
    it names, the middle of its nearer side there) where its :data:`LABEL`-sized box lies wholly on the cells of
    ``side (nx, ny)`` inside the map, as ``ax`` is laid out now (reader r39c: "in collision" sat inside the hatched
    block and hid it)."""
    first = np.array([axis[0] for axis in grid.axes])  # (2,) the first cell's centre
    cell = np.array([abs(axis[1] - axis[0]) if len(axis) > 1 else 1.0 for axis in grid.axes])  # (2,) data units
    points, side = cell_points(ax, grid), np.asarray(side, dtype=bool)  # one cell, in points; (nx, ny)
    for label in (t for t in ax.texts if t.get_text().startswith(text)):
        for dx, dy in OFFSETS:
            lo = np.array([dx if dx > 0 else dx - LABEL[0], dy - LABEL[1] / 2])  # points: the box's lower left corner
            xs, ys = (np.linspace(lo[k], lo[k] + LABEL[k], 7) / points for k in range(2))  # cells, across the box
            across = np.stack(np.meshgrid(xs, ys), axis=-1).reshape(-1, 2)  # (49, 2)
            cells = np.round((np.asarray(label.xy) - first) / cell + across).astype(int)  # (49, 2)
            if np.all((cells >= 0) & (cells < side.shape)) and side[cells[:, 0], cells[:, 1]].all():
                label.xyann = (dx, dy)
                label.set_horizontalalignment("left" if dx > 0 else "right")
                break
