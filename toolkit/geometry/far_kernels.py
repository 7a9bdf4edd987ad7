"""The far bits, built when a checker is made (numba): per link ball and cell of a fine grid, whether the ball,
centred anywhere in the cell, lies in the region and misses every obstacle (:class:`toolkit.geometry.compiled.Far`,
the first test of a link in :mod:`toolkit.geometry.kernels`).

A cell is far for a ball of radius ``r`` when its distance to every obstacle box and to the region's walls exceeds
``r``. Measuring each cell's distance to its nearest box took milliseconds on 3DC-7's grid of 86³ cells, as long as
a planning query, and a checker is made for every new workspace. Most cells are far, so here the bits start at 1
and only the cells near a wall or a box are cleared:

- the walls across the grid's last axis clear the same cells in every column of cells along that axis: a pattern
  that repeats every column, laid down word by word;
- a wall across another axis clears whole layers of columns;
- a box clears, in each column of cells near it, one run of consecutive cells (the bits of a column are
  consecutive, and along a column a cell's distance to a box only falls, then rises), whose ends are found by
  walking in from the ends of the box's window.

A cell's distance to a box is computed as a cell-by-cell pass would compute it, so the bits are the same
(``tests/test_compiled_checker.py`` holds them to that rule, written in numpy).
"""

from __future__ import annotations

import numpy as np
from numba import njit

ALL = np.uint64(0xFFFFFFFFFFFFFFFF)  # a word of ones


@njit(cache=True)
def far_bits(boxes, lower, upper, cell, shape, thresholds, limits, dim):
    """``(B, W)`` words of bits, per ball: bit ``c`` is 1 where cell ``c`` of the grid (``lower (3,)``, cubes of side
    ``cell``, ``shape (3,)``) lies farther than ``thresholds (B,)`` (the ball's radius and a margin) from the walls of
    the region's first ``dim`` axes (up to ``upper (3,)``) and from every box of ``boxes (K, 2, 3)``: its squared
    distance to each exceeds ``limits (B,)``, the largest square whose root is at most the threshold. Words are
    little-endian: cell ``c`` is bit ``c % 64`` of word ``c // 64``; bits past the last cell are 0."""
    n = shape[0] * shape[1] * shape[2]
    words = np.empty((len(thresholds), (n + 63) // 64), np.uint64)
    squares = np.empty(shape[2])  # one box's gap to each layer of cells along the last axis, squared
    for r in range(len(thresholds)):
        row = words[r]
        _lay_column_pattern(row, lower, upper, cell, shape, thresholds[r], dim)
        _clear_wall_layers(row, lower, upper, cell, shape, thresholds[r], dim)
        for k in range(len(boxes)):
            _clear_near_box(row, boxes[k], lower, cell, shape, thresholds[r], limits[r], squares)
        if n < 64 * len(row):
            _clear(row, n, 64 * len(row) - 1)
    return words


@njit(cache=True, inline="always")
def _clear(row, first, last):
    """Set bits ``first`` to ``last`` (inclusive) of ``row (W,)`` to 0."""
    for w in range(first >> 6, (last >> 6) + 1):
        low, high = max(first - 64 * w, 0), min(last - 64 * w, 63)
        row[w] &= ~((ALL >> np.uint64(63 - high)) & (ALL << np.uint64(low)))


@njit(cache=True, inline="always")
def _near_wall(lower, upper, cell, i, index, threshold):
    """Whether layer ``index`` of cells along axis ``i`` comes within ``threshold`` of the region's walls there."""
    return not min(index * cell, upper[i] - lower[i] - (index + 1) * cell) > threshold


@njit(cache=True, inline="always")
def _gap(box, lower, cell, i, index):
    """The gap along axis ``i`` between layer ``index`` of cells and ``box (2, 3)``: 0 where they overlap."""
    start = lower[i] + index * cell
    return max(box[0, i] - (start + cell), start - box[1, i], 0.0)


@njit(cache=True)
def _lay_column_pattern(row, lower, upper, cell, shape, threshold, dim):
    """Fill ``row (W,)`` with ones but at the cells near a wall across the last axis (all ones if that axis has none).
    Those cells repeat every column of ``shape[2]`` cells, so the words repeat every ``shape[2] / gcd(shape[2], 64)``:
    the first period is laid bit by bit, the rest copied."""
    depth = shape[2]
    far = np.ones(depth, np.bool_)
    for c in range(depth if dim == 3 else 0):
        far[c] = not _near_wall(lower, upper, cell, 2, c, threshold)
    period = depth // np.gcd(depth, 64)
    for w in range(len(row)):
        if w >= period:
            row[w] = row[w - period]
            continue
        word = np.uint64(0)
        for j in range(64):
            if far[(64 * w + j) % depth]:
                word |= np.uint64(1) << np.uint64(j)
        row[w] = word


@njit(cache=True)
def _clear_wall_layers(row, lower, upper, cell, shape, threshold, dim):
    """Clear in ``row (W,)`` the layers of cells near a wall across the first axis (each a run of bits) and the
    second (a run per column layer of the first axis)."""
    layer, depth = shape[1] * shape[2], shape[2]
    for a in range(shape[0]):
        if _near_wall(lower, upper, cell, 0, a, threshold):
            _clear(row, a * layer, (a + 1) * layer - 1)
    for b in range(shape[1] if dim > 1 else 0):
        if _near_wall(lower, upper, cell, 1, b, threshold):
            for a in range(shape[0]):
                _clear(row, a * layer + b * depth, a * layer + (b + 1) * depth - 1)


@njit(cache=True)
def _clear_near_box(row, box, lower, cell, shape, threshold, limit, squares):
    """Clear in ``row (W,)`` the cells within ``threshold`` of ``box (2, 3)``: their squared distance, summed over
    the axes in order as a cell-by-cell pass sums it, is at most ``limit``. The box's window (the cells within
    ``threshold`` and one more cell of it, clipped to the grid) is searched column by column; ``squares
    (shape[2],)`` is scratch."""
    first, last = np.empty(3, np.int64), np.empty(3, np.int64)
    for i in range(3):
        first[i] = min(max(int(np.floor((box[0, i] - threshold - lower[i]) / cell)) - 1, 0), shape[i] - 1)
        last[i] = min(max(int(np.floor((box[1, i] + threshold - lower[i]) / cell)) + 1, 0), shape[i] - 1)
    for c in range(first[2], last[2] + 1):
        squares[c] = _gap(box, lower, cell, 2, c) ** 2
    for a in range(first[0], last[0] + 1):
        across = _gap(box, lower, cell, 0, a) ** 2
        if across > limit:
            continue  # every cell of this layer is farther: the other axes only add
        walked = -1.0  # the last column's squared gap across the last axis, whose run is (low, high)
        for b in range(first[1], last[1] + 1):
            column = across + _gap(box, lower, cell, 1, b) ** 2
            if column > limit:
                continue
            if column != walked:  # else the same sums as the last column's: the same run (most columns near a box)
                walked, low, high = column, first[2], last[2]  # the run's ends: walk in while the cells are farther
                while low <= high and column + squares[low] > limit:
                    low += 1
                while high >= low and column + squares[high] > limit:
                    high -= 1
            if low <= high:
                start = (a * shape[1] + b) * shape[2]
                _clear(row, start + low, start + high)
