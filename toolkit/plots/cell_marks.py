"""Marks on a map's cells that one can see however fine the map: notebook 03's mistakes.

A map of a 2-DoF slice (:class:`~toolkit.plots.slices.CSpaceSlice`) marks some of its cells (the classifier's
mistakes on a P(valid) map and on a decision map, :mod:`toolkit.plots.classifier`). On a coarse map a mark covers
most of its cell; on a fine one (chapter 03 at full size: 100 cells over 4.4 inches, about 3 points a cell) a mark
that size is a speck, and a mark made larger would cover its neighbours' marks.
:func:`draw_cell_marks` puts a mark on each marked cell, over the map and under its outlines (or over them: the
classifier's maps draw their dangerous squares over the boundary, which would cut one beside it in two);
:func:`fit_cell_marks`, once the figure is laid out, puts one mark on each block of ``k x k`` cells holding a marked
cell, on one of those cells (the nearest their mean): ``k`` the fewest cells that make a mark :data:`MIN_MARK` points
wide at :data:`MARK_SHARE` of its block, that keep two marks' centres at least the ``pitch`` the marks were drawn
with apart (review r18b: on chapter 03's `paper` map a pile of squares a block apart merged into one shape that could
not be counted), and that make the ``blocks`` a side they asked for, rounded up to divide the map's side; a mark
drawn with a pitch sits on a cell near its block's middle where it can, so that two in neighbouring blocks keep
:data:`CLEAR` between them, and inside the map's frame (a mark on an edge cell moves in by its rings' width). Marks
drawn with a ``depth`` (:func:`depth_inside`: how far each cell lies inside its side of a line) sit first on their
block's cell deepest inside, up to the depth that holds the whole mark (reader r30c: squares centred on an outline's
corner cell lay half in the free space beside it).
"""

from __future__ import annotations

from weakref import WeakKeyDictionary

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection, PathCollection
from matplotlib.contour import QuadContourSet
from matplotlib.figure import Figure
from scipy.ndimage import distance_transform_edt

from toolkit.plots.slices import CSpaceSlice

MIN_MARK = 5.0  # points: the least side of a mark, however fine the map
MAX_MARK = 7.0  # points: the largest, however coarse: a mark, not a tile hiding its cell's grey
MARK_SHARE = 0.7  # of its cell (or block of cells) a mark covers: the map beneath shows between two marks
CLEAR = 6.0  # points between two marks' sides, at least, where drawn with a pitch: their rings (4.2) and a gap
RING = 2.1  # points: a mark's rings beyond its side, kept inside the map's frame with it (r19b: a top row of marks
# sat on the frame, half outside the map)
GID = "cell marks"  # how fit_cell_marks finds the marks draw_cell_marks drew ("cell marks:PITCH")
_DEPTH: WeakKeyDictionary[PathCollection, np.ndarray] = WeakKeyDictionary()  # marks' cells' depth (n,), where given


def depth_inside(region) -> np.ndarray:
    """Each cell's distance, in cells, from the nearest cell outside ``region (nx, ny)`` (a cell of it beside one: 1;
    outside it: 0): how far inside its side of the region's outline a cell lies."""
    region = np.asarray(region, dtype=bool)
    return np.asarray(distance_transform_edt(region), dtype=float) if (~region).any() else np.full(region.shape, 1e9)


def draw_cell_marks(
    ax, grid: CSpaceSlice, mask, *, pitch: float = 0.0, blocks: int = 0, depth=None, **style
) -> PathCollection:
    """A mark (``style``: scatter's options) at the centre of each cell of ``grid`` where ``mask (nx, ny)`` holds,
    over the map, under the lines on it (a boundary stays whole) unless ``style`` gives a ``zorder`` above them;
    :func:`fit_cell_marks` sizes them once laid out, no two closer than ``pitch`` points (0: a block's width), one per
    block of at least ``n / blocks`` cells a side (0: as small as they fit), so that every map of a figure, and of a
    page that asks the same ``blocks``, marks the same cells alike (reader r29c: 5, 7 and 14 cells on three maps);
    ``depth (nx, ny)`` (:func:`depth_inside`), where given, puts a block's mark on its cell deepest inside."""
    i, j = np.nonzero(mask)
    marks = ax.scatter(grid.axes[0][i], grid.axes[1][j], s=MIN_MARK**2, gid=f"{GID}:{pitch:g}:{blocks}", **style)
    if depth is not None:
        _DEPTH[marks] = np.asarray(depth, dtype=float)[i, j]
    return marks


def block_side(needed: int, blocks: int, shape: tuple[int, ...]) -> int:
    """The cells a side of one mark's block: at least ``needed`` and ``n / blocks`` (``blocks`` 0: none asked), and
    a divisor of each side of a map of ``shape`` where one is that large, so that no sliver of a block at the map's
    edge doubles a row of marks (reader r29c: blocks of 14 of 100 cells left 2 at the top and right)."""
    k = max(1, needed, -(-min(shape) // blocks) if blocks else 1)
    return next((d for d in range(k, min(shape) + 1) if all(n % d == 0 for n in shape)), k)


def cell_marks(ax: Axes) -> list[PathCollection]:
    """The marks :func:`draw_cell_marks` drew on ``ax``."""
    return [c for c in ax.collections if isinstance(c, PathCollection) and str(c.get_gid()).startswith(GID)]


def fit_cell_marks(fig: Figure, grid: CSpaceSlice) -> dict[str, int]:
    """Size the marks :func:`draw_cell_marks` drew on ``fig``'s maps of ``grid`` to their cells as laid out,
    merging them into blocks of ``k x k`` cells where a cell is too small or the marks' pitch too wide; returns, per
    label of marks, the largest ``k`` (1: a mark a cell), for the figure's description and legend to say."""
    fig.draw_without_rendering()  # lays the figure out: the axes take their final sizes
    first = np.array([axis[0] for axis in grid.axes])  # (2,) the first cell's centre
    cell = np.array([abs(axis[1] - axis[0]) if len(axis) > 1 else 1.0 for axis in grid.axes])  # (2,) data units
    blocks: dict[str, int] = {}
    for ax in fig.axes:
        side = cell_points(ax, grid) if cell_marks(ax) else 0.0
        for mark in cell_marks(ax):
            _, pitch_said, blocks_said = (str(mark.get_gid()).split(":") + ["", ""])[:3]
            pitch = float(pitch_said or 0)
            needed = max(int(np.ceil(MIN_MARK / (MARK_SHARE * side))), int(np.ceil(pitch / side - 1e-9)))
            k = block_side(needed, int(blocks_said or 0), grid.shape)
            label = str(mark.get_label())
            blocks[label] = max(blocks.get(label, 1), k)
            size = min(MARK_SHARE * k * side, MAX_MARK)
            mark.set_sizes([size**2])
            offsets = np.asarray(mark.get_offsets())  # (n, 2) the marked cells' centres
            if k == 1 or not len(offsets):
                continue  # one mark a cell
            cells = np.rint((offsets - first) / cell).astype(int)  # (n, 2) cell indices
            block, block_of = np.unique(cells // k, axis=0, return_inverse=True)  # (m, 2), (n,) the block of each
            block_of = block_of.ravel()
            middle = block * k + (k - 1) / 2  # (m, 2) each block's middle cell
            spread = max(0.0, (k * side - size - CLEAR) / (2 * side)) if pitch else k  # cells off the middle, at most
            apart = (size + CLEAR) / side if pitch else 0.0  # cells between two marks' centres, at least
            centres = np.empty((len(block), 2))  # (m, 2) each on one of its block's marked cells
            depth = _DEPTH.get(mark, np.zeros(len(cells)))  # (n,) each cell's depth inside its side
            depth = np.minimum(depth, np.ceil((size / 2 + RING) / side) + 1)  # deeper holds the mark no better
            for b in range(len(block)):
                centres[b] = _on_a_cell(
                    cells[block_of == b],
                    middle[b],
                    spread,
                    centres[:b][~np.isnan(centres[:b, 0])],
                    apart,
                    depth[block_of == b],
                )
            centres = centres[~np.isnan(centres[:, 0])]
            inset = max(0.0, (size / 2 + RING) / side - 0.5)  # cells: from the edge cells' centres to a whole mark
            centres = np.clip(centres, inset, np.array(grid.shape) - 1 - inset)  # inside the map, rings and all
            mark.set_offsets(first + centres * cell)
    return blocks


def _on_a_cell(
    cells: np.ndarray, middle: np.ndarray, spread: float, placed: np.ndarray, apart: float, depth: np.ndarray
) -> np.ndarray:
    """The one of a block's marked ``cells (n, 2)`` its mark sits on: of those at least ``apart`` cells from every
    mark ``placed (p, 2)``, the deepest inside its side (``depth (n,)``, r30c), then the nearest their mean (clipped to
    ``spread`` cells of the block's ``middle``), the window's first; where none is that far, none (NaN: they lie beside
    that mark, less than a block from it). Never the mean itself (review r26c: a block's mistakes on two of an
    obstacle's edges averaged into its inside, where a circle then claimed a free cell rejected)."""
    mean = np.clip(cells.mean(axis=0), middle - spread, middle + spread)  # (2,) where the mark would best sit
    near = np.max(np.abs(cells - mean), axis=1) + 1e6 * (np.max(np.abs(cells - middle), axis=1) > spread + 1e-9)
    clear = (
        np.max(np.abs(cells[:, None] - placed[None]), axis=2).min(axis=1)
        if len(placed)
        else np.full(len(cells), np.inf)
    )
    if (clear >= apart - 1e-9).any():
        shallow = np.max(depth) - depth  # (n,) 0 for the deepest
        return cells[np.argmin(np.where(clear >= apart - 1e-9, near + 1e9 * shallow, np.inf))].astype(float)
    return np.full(2, np.nan)  # every one of them beside a mark already: that mark stands for them too


def cell_points(ax: Axes, grid: CSpaceSlice) -> float:
    """The smaller side of one cell of ``grid`` on ``ax`` as laid out, in points."""
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    per_unit = np.array([ax.bbox.width / abs(x1 - x0), ax.bbox.height / abs(y1 - y0)]) * 72 / ax.figure.dpi
    cell = np.array([abs(axis[1] - axis[0]) if len(axis) > 1 else 1.0 for axis in grid.axes])  # (2,) data units
    return float(np.min(cell * per_unit))


EDGE = 4  # sub-cells a side: an outline's contour runs between their centres, on the cells' edges, its corners cut by
# an eighth of a cell (reader r27c: drawn through the cells' centres it rounded off the corner cells, and a dangerous
# square on one seemed to lie in free space)


def draw_cell_outline(ax: Axes, grid: CSpaceSlice, mask, **style) -> QuadContourSet:
    """The outline of the cells of ``grid`` where ``mask (nx, ny)`` holds, drawn along the cells' edges (``style``:
    contour's options): a mark on a cell of either side lies on its side of the line."""
    return ax.contour(*_sub_cells(grid, mask), levels=[0.5], **style)


def draw_cell_hatch(ax: Axes, grid: CSpaceSlice, mask, *, color: str, hatch: str = "//") -> QuadContourSet:
    """A hatch in ``color`` over the cells of ``grid`` where ``mask (nx, ny)`` holds, inside :func:`draw_cell_outline`'s
    line, nothing filled (reader r29c: on a dark map a free region the model calls colliding looked like the
    C-obstacle beside it; the hatch says which is which without the grey)."""
    hatched = ax.contourf(*_sub_cells(grid, mask), levels=[0.5, 1.5], colors="none", hatches=[hatch], zorder=1.2)
    hatched.set_edgecolor(color)
    hatched.set_linewidth(0)
    return hatched


def _sub_cells(grid: CSpaceSlice, mask) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The centres of EDGE x EDGE sub-cells of each cell, per axis ``(n * EDGE,)``, and ``mask`` on them, transposed
    for contour: ``(ny * EDGE, nx * EDGE)``."""
    subs = []
    for axis in grid.axes:
        width = abs(axis[1] - axis[0]) if len(axis) > 1 else 1.0
        subs.append((axis[:, None] + width * ((np.arange(EDGE) + 0.5) / EDGE - 0.5)[None]).ravel())
    fine = np.repeat(np.repeat(np.asarray(mask, dtype=float), EDGE, axis=0), EDGE, axis=1)  # each cell EDGE x EDGE
    return subs[0], subs[1], fine.T


FRAME = "outline on the frame"  # the gid of the boundary's runs along a map's frame


def frame_runs(valid, grid: CSpaceSlice, walls: list[bool]) -> list[np.ndarray]:
    """The map's frame where C-obstacle cells of ``valid (nx, ny)`` touch it, one segment ``(2, 2)`` per run of them
    along each side: the outline closed there, so that a block on the map's edge reads as whole, not cut off. Only
    where ``walls`` (one per axis) says the map ends at a wall: an angle's ends are none (α wraps round; a joint's
    limits). Chapter 03's maps (:mod:`toolkit.plots.classifier`)."""
    (x0, x1, y0, y1), runs = grid.extent, []
    for along, cells, at, lo, hi, horizontal in (
        (valid[:, 0], grid.shape[0], y0, x0, x1, True),
        (valid[:, -1], grid.shape[0], y1, x0, x1, True),
        (valid[0, :], grid.shape[1], x0, y0, y1, False),
        (valid[-1, :], grid.shape[1], x1, y0, y1, False),
    ):
        if not walls[1 if horizontal else 0]:
            continue
        edges = lo + (hi - lo) * np.arange(cells + 1) / cells  # (cells + 1,) the cells' edges along this side
        blocked = np.concatenate([[0], (~along).astype(int), [0]])
        starts, ends = np.flatnonzero(np.diff(blocked) == 1), np.flatnonzero(np.diff(blocked) == -1)
        for a, b in zip(edges[starts], edges[ends]):
            runs.append(np.array([[a, at], [b, at]] if horizontal else [[at, a], [at, b]]))
    return runs


def draw_frame_runs(ax: Axes, grid: CSpaceSlice, valid, walls: list[bool], **style) -> LineCollection:
    """:func:`frame_runs` drawn on ``ax`` as one collection (gid :data:`FRAME`), whole on the frame, not clipped to
    half of it; ``style``: the outline's colours and line widths."""
    frame = LineCollection(frame_runs(valid, grid, walls), zorder=2, gid=FRAME, **style)
    frame.set_clip_on(False)
    ax.add_collection(frame, autolim=False)
    return frame
