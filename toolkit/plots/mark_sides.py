"""Marks kept wholly on their side of an outline: notebook 03's mistakes (reader r32c).

:func:`toolkit.plots.cell_marks.fit_cell_marks` puts one mark per tile of cells on one of the tile's marked cells, the
deepest inside its side of the outline. A mark is wider than a cell on a fine map (chapter 03 at full size: a square
with its rings about 3.5 cells wide), so that a mark centred on a C-obstacle's corner cell, where all of a `strong`
model's dangerous mistakes lie, covered mostly the free space beside it (reader r32c: "the squares appear to sit in
free space just outside the block they are said to be inside"). A mark given its side (:func:`on_side`) moves, once
fitted (:func:`fit_on_side`) and again once its figure is laid out for good (:func:`keep_on_side`), while its cell
lies within an outline's width of it, to where the least of it, rings included, lies on the other side or beyond the
map's frame: inside the outline and clear of its line (reader r34c: marks on the line read as lying on it) wherever
the region is wide enough to hold it, and never nearer another mark of its kind than the marks' pitch keeps them.
"""

from __future__ import annotations

from collections.abc import Mapping
from weakref import WeakKeyDictionary

import numpy as np
from matplotlib.collections import PathCollection
from matplotlib.figure import Figure

from toolkit.plots.cell_marks import CLEAR, RING, cell_marks, cell_points, fit_cell_marks
from toolkit.plots.slices import CSpaceSlice

STEP = 0.25  # cells: the largest step between two places a mark may move to
_SIDE: WeakKeyDictionary[PathCollection, np.ndarray] = WeakKeyDictionary()  # marks' side of the outline (nx, ny)


def on_side(marks: PathCollection, side) -> PathCollection:
    """Give ``marks`` (:func:`~toolkit.plots.cell_marks.draw_cell_marks`'s) the cells ``side (nx, ny)`` they name
    (dangerous squares: the C-obstacle's), for :func:`fit_on_side` to keep them inside it."""
    _SIDE[marks] = np.asarray(side, dtype=bool)
    return marks


def fit_on_side(fig: Figure, grid: CSpaceSlice) -> dict[str, int]:
    """:func:`~toolkit.plots.cell_marks.fit_cell_marks`, then each mark given a side moved onto it (its blocks); a
    figure that adds a title or legend after this, changing its maps' size, calls :func:`keep_on_side` again last."""
    blocks = fit_cell_marks(fig, grid)
    keep_on_side(fig, grid)
    return blocks


def keep_on_side(fig: Figure, grid: CSpaceSlice) -> None:
    """Each mark given a side (:func:`on_side`) moved, from the cell it was drawn on, to where it lies wholly on that
    side and clear of the outline by :data:`GAP`, that cell within GAP of it, inside the map's frame, as ``fig`` is laid
    out now (reader r34c: a
    legend added after the fit shrank the maps, and marks fitted to the larger cells met their outlines)."""
    fig.draw_without_rendering()  # the layout the figure will be drawn with
    first = np.array([axis[0] for axis in grid.axes])  # (2,) the first cell's centre
    cell = np.array([abs(axis[1] - axis[0]) if len(axis) > 1 else 1.0 for axis in grid.axes])  # (2,) data units
    for ax in fig.axes:
        for mark in cell_marks(ax):
            side = _SIDE.get(mark)
            if side is None or not len(np.asarray(mark.get_offsets())):
                continue
            if mark not in _FROM:
                _FROM[mark] = (np.asarray(mark.get_offsets()) - first) / cell  # (m, 2) the cells drawn on
            points = cell_points(ax, grid)  # one cell, in points
            size = float(np.sqrt(mark.get_sizes()[0]))  # points
            half = (size / 2 + RING) / points  # cells: the mark's half side, rings included
            pitch = float((str(mark.get_gid()).split(":") + ["0"])[1] or 0)
            apart = (size + CLEAR) / points if pitch else 0.0  # cells between two marks' centres, at least
            at = _FROM[mark].copy()
            for n in range(len(at)):
                others = np.delete(at, n, axis=0)
                gap = GAP / points  # cells: the outline's half width
                at[n] = inward(at[n], side, half + gap, half + gap + 0.49, others, apart)  # its cell within the gap
            inset = max(0.0, half - 0.5)  # inside the map's frame, rings and all
            mark.set_offsets(first + np.clip(at, inset, np.array(side.shape) - 1 - inset) * cell)


GAP = 7.0  # points between a mark's rings and its outline's middle: the outline's half width, its rings included (2.2),
# and a gap one sees at the site's width (reader r36c: at 2.5, squares read as lying on the yaw x joint band's outline;
# r39c: at 4, inside "only just", against the band's stepped outline)
_FROM: WeakKeyDictionary[PathCollection, np.ndarray] = WeakKeyDictionary()  # the cells each mark was fitted on


def inward(at: np.ndarray, side: np.ndarray, half: float, reach: float, others: np.ndarray, apart: float):
    """Where a mark of half side ``half`` (cells) centred at ``at (2,)`` (cell indices) moves: of the centres within
    ``reach`` cells of it (:func:`fit_on_side`'s: the mark, rings included, still covers that whole cell) and at least
    ``apart`` from each of ``others (p, 2)``, the one whose square lies least outside ``side (nx, ny)``, then the
    nearest ``at``."""
    steps = np.linspace(-reach, reach, 2 * int(np.ceil(reach / STEP)) + 1)  # (s,) 0 and both ends among them
    moves = np.stack(np.meshgrid(steps, steps, indexing="ij"), axis=-1).reshape(-1, 2)  # (c, 2) the centre (0, 0)
    centres = at + moves
    if len(others):
        clear = np.max(np.abs(centres[:, None] - others[None]), axis=2).min(axis=1)  # (c,) cells to the nearest
        allowed = (clear >= apart - 1e-9) | (np.abs(moves).max(axis=1) == 0)
        centres, moves = centres[allowed], moves[allowed]
    outside = np.round([outside_area(c, side, half) for c in centres], 6)  # (c,) cells' area
    return centres[np.lexsort((np.abs(moves).max(axis=1), outside))[0]]


def outside_area(at: np.ndarray, side: np.ndarray, half: float) -> float:
    """The area, in cells, of the square of half side ``half`` centred at ``at (2,)`` that lies on the map's cells
    outside ``side (nx, ny)`` or beyond the map's frame (reader r34c: a circle pushed beyond it, then pulled back
    inside, sat on the block beside the frame, cut by it)."""
    overlaps = []
    for axis in range(2):
        lo, hi = at[axis] - half, at[axis] + half
        k = np.arange(max(0, int(np.floor(lo + 0.5))), min(side.shape[axis] - 1, int(np.ceil(hi - 0.5))) + 1)
        overlaps.append((k, np.clip(np.minimum(k + 0.5, hi) - np.maximum(k - 0.5, lo), 0.0, None)))
    (i, wi), (j, wj) = overlaps
    beyond = (2 * half) ** 2 - float(np.sum(wi) * np.sum(wj))  # the square's area off the map
    inside = float(np.sum(np.outer(wi, wj) * ~side[np.ix_(i, j)])) if len(i) and len(j) else 0.0
    return max(0.0, round(beyond + inside, 9))  # no -1e-15 for a square wholly on the map


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
OFFSETS = ((30, -30), (-30, -30), (30, 30), (-30, 30), (40, -8), (-40, -8))  # points from the node, tried in order


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
