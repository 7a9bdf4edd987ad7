"""The pieces of the compiled exact checks of box worlds (numba): link bounds, separating axes, grid cells.

:mod:`toolkit.geometry.block_kernels` checks a block of configurations at a time, and
:mod:`toolkit.geometry.mesh_kernels` one configuration at a time against a mesh's parts; both stand on these:

- a link's axis-aligned bounds and the cells of a grid they cover (:func:`one_link_bounds`, :func:`link_bounds`),
  and the obstacle boxes those cells list (:func:`listed_boxes`);
- the separating-axis theorem (Gottschalk et al., OBBTree, 1996), :func:`boxes_touch`: two boxes are disjoint
  iff their projections on some axis are disjoint; it suffices to try the world's axes, the
  link's axes and, in 3D, their 9 cross products. Touching projections do not separate:
  boxes are closed, as in FCL;
- one bit per cell of a fine grid (:func:`far`; :class:`toolkit.geometry.compiled.Far`): whether a ball round a
  link, centred anywhere in the cell, lies in the region and misses every obstacle (the bits are built by
  :mod:`toolkit.geometry.far_kernels`), and the broadphase's cell lists (:func:`cell_lists`);
- clearance bounds, one configuration at a time (:func:`clearance_bounds`, posed by
  :func:`toolkit.geometry.frame_kernels.link_frames` with the same sines and cosines).

The robot and the workspace arrive as arrays (:class:`toolkit.geometry.compiled.CompiledChecker`
builds them), never as constants, so one compiled version serves every robot and
workspace; ``cache=True`` keeps it on disk (in ``NUMBA_CACHE_DIR`` if set, else in ``__pycache__``
beside this file, else, where that is read-only, in the user's cache folder, ``~/.cache/numba``),
so a machine compiles it once. The steps are small functions that numba inlines into the loops
(``inline="always"``): a call that passes arrays costs more than most of the steps themselves.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from toolkit.geometry.frame_kernels import link_frames, new_frame


@njit(cache=True, inline="always")
def one_link_bounds(center, R, half, world, low, high, cells):
    """Fill a link's axis-aligned bounds ``low, high (3,)`` and the cells they cover, ``cells (2, 3)`` (first and
    last per axis, clipped to the grid), for its box ``center (3,)``, ``R (3, 3)``, ``half (3,)``; returns whether
    they lie inside the region."""
    inside = True
    for i in range(len(world.lower)):
        reach = 0.0
        for j in range(len(world.lower)):
            reach += abs(R[i, j]) * half[j]
        low[i], high[i] = center[i] - reach, center[i] + reach
        inside &= world.lower[i] <= low[i] and high[i] <= world.upper[i]
        for end, value in enumerate((low[i], high[i])):
            cell = int(np.floor((value - world.lower[i]) / world.cell))
            cells[end, i] = min(max(cell, 0), world.shape[i] - 1)
    return inside


@njit(cache=True, inline="always")
def link_bounds(half_extents, world, centers, rotations, low, high, cells):
    """:func:`one_link_bounds` of every link: ``low, high (L, 3)``, ``cells (L, 2, 3)``; whether all lie inside."""
    inside = True
    for link in range(len(half_extents)):
        inside &= one_link_bounds(
            centers[link], rotations[link], half_extents[link], world, low[link], high[link], cells[link]
        )
    return inside


@njit(cache=True, inline="always")
def listed_boxes(cells, world, seen, tag, found):
    """Fill ``found`` with the boxes listed in ``cells (2, 3)`` (first and last per axis) that ``seen`` has not
    marked with ``tag`` yet, and mark them; returns their number (a box listed in two cells is tested once)."""
    shape, n_found = world.shape, 0
    for a in range(cells[0, 0], cells[1, 0] + 1):
        for b in range(cells[0, 1], cells[1, 1] + 1):
            for c in range(cells[0, 2], cells[1, 2] + 1):
                flat = (a * shape[1] + b) * shape[2] + c
                for m in range(world.cell_first[flat], world.cell_first[flat] + world.cell_count[flat]):
                    box = world.cell_boxes[m]
                    if seen[box] != tag:
                        seen[box] = tag
                        found[n_found] = box
                        n_found += 1
    return n_found


@njit(cache=True, inline="always")
def boxes_touch(center, R, half, low, high, box, dim):
    """Whether a link box (``center (3,)``, ``R (3, 3)`` whose columns are its axes, ``half (3,)``, bounds
    ``low, high (3,)``) touches the obstacle ``box (2, D)``.

    Separating axes, cheapest first: the world's (do the bounds overlap?), the link's, their cross products.
    """
    for i in range(dim):
        if low[i] > box[1, i] or high[i] < box[0, i]:
            return False
    offset = (  # link centre minus box centre
        center[0] - (box[0, 0] + box[1, 0]) / 2,
        center[1] - (box[0, 1] + box[1, 1]) / 2,
        center[2] - (box[0, 2] + box[1, 2]) / 2 if dim == 3 else 0.0,
    )
    box_half = (
        (box[1, 0] - box[0, 0]) / 2,
        (box[1, 1] - box[0, 1]) / 2,
        (box[1, 2] - box[0, 2]) / 2 if dim == 3 else 0.0,
    )
    for j in range(dim):  # link axis j: the link reaches half[j] along it
        gap, reach = 0.0, half[j]
        for i in range(dim):
            gap += R[i, j] * offset[i]
            reach += abs(R[i, j]) * box_half[i]
        if abs(gap) > reach:
            return False
    if dim == 3:
        for w in range(3):  # world axis w crossed with link axis j: (0, -R[v, j], R[u, j]) in (w, u, v) order
            u, v = (w + 1) % 3, (w + 2) % 3
            for j in range(3):
                a_u, a_v = -R[v, j], R[u, j]
                reach = abs(a_u) * box_half[u] + abs(a_v) * box_half[v]
                for k in range(3):
                    reach += abs(a_u * R[u, k] + a_v * R[v, k]) * half[k]
                if abs(a_u * offset[u] + a_v * offset[v]) > reach:
                    return False
    return True


@njit(cache=True, inline="always")
def in_bounds(q, lower, upper):
    for i in range(len(q)):  # noqa: SIM110 (numba compiles loops, not generators)
        if not lower[i] <= q[i] <= upper[i]:
            return False
    return True


@njit(cache=True, inline="always")
def flat_cell(point, grid):
    """The index of the cell of ``grid`` (``lower (3,)``, ``cell``, ``shape (3,)``) that holds ``point (3,)``,
    clipped to the grid."""
    flat = 0
    for i in range(3):
        flat = flat * grid.shape[i] + _axis_cell(point[i], grid, i)
    return flat


@njit(cache=True, inline="always")
def _axis_cell(x, grid, i):
    """The layer of cells of ``grid`` along axis ``i`` that holds coordinate ``x``, clipped to the grid."""
    return min(max(int(np.floor((x - grid.lower[i]) / grid.cell)), 0), grid.shape[i] - 1)


@njit(cache=True, inline="always")
def far(center, bits, grid):
    """Whether the ball of a link centred at ``center (3,)`` lies in the region and misses every obstacle wherever
    in its cell of ``grid`` the centre lies: ``bits (W,)``, one a cell, that ball's row of
    :class:`toolkit.geometry.compiled.Far`'s ``bits``."""
    return _bit(bits, flat_cell(center, grid))


@njit(cache=True, inline="always")
def _bit(bits, flat):
    return (bits[flat >> 6] >> (flat & 63)) & 1


@njit(cache=True, inline="always")
def _box_clearance(center, R, half, low, high, box, dim, cap):
    """A lower bound on the distance between a link box and an obstacle ``box (2, D)`` (arguments as in
    :func:`boxes_touch`): the larger of the gap between the link's bounds and the box and the gap between their
    projections on each of the link's axes; the first alone when it reaches ``cap`` (the caller's limit)."""
    gap = 0.0
    for i in range(dim):
        gap += max(box[0, i] - high[i], low[i] - box[1, i], 0.0) ** 2
    gap = np.sqrt(gap)
    if gap < cap:
        for j in range(dim):
            along, reach = 0.0, half[j]
            for i in range(dim):
                along += R[i, j] * (center[i] - (box[0, i] + box[1, i]) / 2)
                reach += abs(R[i, j]) * (box[1, i] - box[0, i]) / 2
            gap = max(gap, abs(along) - reach)
    return gap


@njit(cache=True)
def clearance_bounds(Q, robot, world, level_links, cap, clearance):
    """Fill ``clearance (N,)`` with lower bounds in ``[0, cap]``: 0 out of bounds, else the least over links of
    the distance to the walls (a floor or ceiling that a level link never moves towards does not count) and to
    each box listed near it: :meth:`toolkit.geometry.box_world.BoxWorldChecker.clearance_bounds`, compiled.

    ``world`` as in :func:`toolkit.geometry.block_kernels.validity`, its cell lists holding the boxes grown by ``cap``.
    """
    half, boxes, region_lo, region_hi = robot.half_extents, world.boxes, world.lower, world.upper
    n_links, dim = len(half), len(region_lo)
    frame, centers, rotations = new_frame(Q.shape[1]), np.zeros((n_links, 3)), np.zeros((n_links, 3, 3))
    low, high, cells = np.zeros((n_links, 3)), np.zeros((n_links, 3)), np.zeros((n_links, 2, 3), np.int64)
    seen, found = np.full(len(boxes), -1), np.zeros(len(boxes), np.int64)
    for n in range(len(Q)):
        clearance[n] = 0.0
        if not in_bounds(Q[n], robot.lower, robot.upper):
            continue
        link_frames(Q[n], robot, frame, centers, rotations, n_links)
        link_bounds(half, world, centers, rotations, low, high, cells)
        bound = cap
        for link in range(n_links):
            for i in range(dim):
                wall = min(low[link, i] - region_lo[i], region_hi[i] - high[link, i])
                if not (link < level_links and i == dim - 1 and wall >= 0):
                    bound = min(bound, wall)
            for m in range(listed_boxes(cells[link], world, seen, n * n_links + link, found)):
                box = boxes[found[m]]
                gap = _box_clearance(centers[link], rotations[link], half[link], low[link], high[link], box, dim, cap)
                bound = min(bound, gap)
        clearance[n] = max(bound, 0.0)


@njit(cache=True, inline="always")
def _block_cells(lo, hi, shape, cells):
    """Fill ``cells`` with the flat indices of the block of cells from ``lo`` to ``hi (3,)``; returns their number."""
    n = 0
    for a in range(lo[0], hi[0] + 1):
        for b in range(lo[1], hi[1] + 1):
            for c in range(lo[2], hi[2] + 1):
                cells[n] = (a * shape[1] + b) * shape[2] + c
                n += 1
    return n


@njit(cache=True)
def cell_lists(lo, hi, shape):
    """Per cell of a grid of ``shape (3,)`` cells, the boxes whose blocks of cells ``lo, hi (K, 3)`` (first and last
    cell per axis) cover it, in box order: ``count (C,)``, ``first (C,)``, ``members (B,)``, cell ``c``'s boxes being
    ``members[first[c]:first[c] + count[c]]``. A counting sort: one pass counts each cell's boxes, one lists them."""
    count = np.zeros(shape[0] * shape[1] * shape[2], np.int64)
    cells = np.empty(shape[0] * shape[1] * shape[2], np.int64)  # one box's block
    for k in range(len(lo)):
        for m in range(_block_cells(lo[k], hi[k], shape, cells)):
            count[cells[m]] += 1
    first = np.cumsum(count) - count
    members, at = np.empty(count.sum(), np.int64), first.copy()
    for k in range(len(lo)):
        for m in range(_block_cells(lo[k], hi[k], shape, cells)):
            members[at[cells[m]]] = k
            at[cells[m]] += 1
    return count, first, members
