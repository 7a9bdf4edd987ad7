"""The compiled exact check, a block of configurations at a time: kinematics, then separating axes (numba).

Numpy checks a batch one step at a time: kinematics for every configuration, then bounds for
every link, then the pairs that may touch. Each step writes arrays the next one reads, so
the cost is memory traffic, and FCL adds a Python call per pair. Here one loop (compiled by
numba to machine code) takes a block of 64 configurations through every step:

1. forward kinematics of the box chain (:meth:`toolkit.geometry.robots.BoxRobot.link_frames`) for the whole
   block, each step a loop over its configurations that the compiler turns into vector instructions (8 numbers
   at once), the sines and cosines included (:func:`sin_cos`: a C library call per angle cost more than the
   rest of the kinematics);
2. then each configuration alone, stopping at its first failure: bounds, ``lower <= q <= upper``;
3. per link, one bit, looked up in the cell of a fine grid that holds the link's centre
   (:class:`toolkit.geometry.compiled.Far`): whether a ball round the link, centred anywhere in that cell, lies in
   the region and misses every obstacle. Most links are done here (the idea of the mesh checker,
   :mod:`toolkit.geometry.mesh_kernels`);
4. else its axis-aligned bounds must lie inside the region, and the obstacle boxes listed in the grid cells
   they cover (:class:`toolkit.geometry.box_world.BoxWorldChecker`'s cell lists) are tested: a ball round the
   link that misses the box, or one inside the link that meets it, settles most pairs; the rest go to the
   separating-axis theorem (Gottschalk et al., OBBTree, 1996): two boxes are disjoint iff
   their projections on some axis are disjoint; it suffices to try the world's axes, the
   link's axes and, in 3D, their 9 cross products. Touching projections do not separate:
   boxes are closed, as in FCL.

The robot and the workspace arrive as arrays (:class:`toolkit.geometry.compiled.CompiledChecker`
builds them), never as constants, so one compiled version serves every robot and
workspace; ``cache=True`` keeps it on disk (in ``NUMBA_CACHE_DIR`` if set, else in ``__pycache__``
beside this file, else, where that is read-only, in the user's cache folder, ``~/.cache/numba``),
so a machine compiles it once. The steps are small functions that numba inlines into the loop
(``inline="always"``): a call that passes arrays costs more than most of the steps themselves.
:func:`link_frames` poses one configuration (the clearance bounds and the mesh checker use it), with the same
sines and cosines.
"""

from __future__ import annotations

import numpy as np
from numba import njit

# Cephes' sin and cos (S. Moshier, sin.c): pi/4 in three parts (subtracting multiples of it exactly up to
# |x| ~ 1e9), then polynomials on [-pi/4, pi/4]; within an ulp or two of the C library's, and, unlike a call to
# it, a loop over many angles of this compiles to vector instructions.
_PI4 = (7.85398125648498535156e-1, 3.77489470793079817668e-8, 2.69515142907905952645e-15)
_SIN = (1.58962301576546568060e-10, -2.50507477628578072866e-8, 2.75573136213857245213e-6,
        -1.98412698295895385996e-4, 8.33333333332211858878e-3, -1.66666666666666307295e-1)  # fmt: skip
_COS = (-1.13585365213876817300e-11, 2.08757008419747316778e-9, -2.75573141792967388112e-7,
        2.48015872888517045348e-5, -1.38888888888730564116e-3, 4.16666666666665929218e-2)  # fmt: skip
SIN_COS_LIMIT = 1e8  # beyond this |angle|, the C library's


@njit(cache=True, inline="always")
def sin_cos(x):
    """``(sin(x), cos(x))`` for ``|x| <= SIN_COS_LIMIT``, without a branch."""
    a = abs(x)
    octant = np.int64(a * (4 / np.pi))
    octant += octant & 1  # even: the nearest multiple of pi/2 below or above
    y = np.float64(octant)
    z = ((a - y * _PI4[0]) - y * _PI4[1]) - y * _PI4[2]  # in [-pi/4, pi/4]
    zz = z * z
    p = _SIN[0]
    for coefficient in _SIN[1:]:
        p = p * zz + coefficient
    q = _COS[0]
    for coefficient in _COS[1:]:
        q = q * zz + coefficient
    sin_z, cos_z = z + z * zz * p, 1.0 - 0.5 * zz + zz * zz * q
    quadrant = (octant >> 1) & 3  # sin a: sin_z, cos_z, -sin_z, -cos_z; cos a: cos_z, -sin_z, -cos_z, sin_z
    sin_a = cos_z if quadrant & 1 else sin_z
    cos_a = sin_z if quadrant & 1 else cos_z
    sin_a = -sin_a if quadrant & 2 else sin_a
    cos_a = -cos_a if (quadrant + 1) & 2 else cos_a
    return (-sin_a if x < 0 else sin_a), cos_a


@njit(cache=True, inline="always")
def any_sin_cos(x):
    """:func:`sin_cos` of any angle (beyond ``SIN_COS_LIMIT``, the C library's)."""
    return sin_cos(x) if abs(x) <= SIN_COS_LIMIT else (np.sin(x), np.cos(x))


@njit(cache=True, inline="always")
def _turn(rotation, axis, s, c):
    """``rotation (3, 3) @ (rotation about world axis ``axis`` by the angle of sine ``s``, cosine ``c``)``, in place."""
    j, k = (axis + 1) % 3, (axis + 2) % 3  # the plane it turns, in right-handed order
    for row in range(3):
        a, b = rotation[row, j], rotation[row, k]
        rotation[row, j] = a * c + b * s
        rotation[row, k] = b * c - a * s


@njit(cache=True, inline="always")
def first_angle(robot):
    """The column of a configuration's first angle; the rest follow it (the base's, then the joints')."""
    return 3 if robot.base == 2 else 2


@njit(cache=True, inline="always")
def pose_base(q, robot, sines, cosines, position, rotation):
    """Fill the base frame ``position (3,)``, ``rotation (3, 3)`` for configuration ``q``, the sines and cosines of
    its angles given (``sines, cosines``: indexable from :func:`first_angle`'s column on, as ``q``)."""
    rotation[:] = 0.0
    for i in range(3):
        rotation[i, i] = 1.0
    if robot.base == 0:  # point2d
        position[0], position[1], position[2] = q[0], q[1], 0.0
    elif robot.base == 1:  # planar: x, y, yaw on the floor
        position[0], position[1], position[2] = q[0], q[1], robot.base_height
        _turn(rotation, 2, sines[0], cosines[0])
    else:  # free: x, y, z, then Z-Y-X Euler angles
        position[0], position[1], position[2] = q[0], q[1], q[2]
        _turn(rotation, 2, sines[0], cosines[0])
        _turn(rotation, 1, sines[1], cosines[1])
        _turn(rotation, 0, sines[2], cosines[2])


@njit(cache=True, inline="always")
def next_link(robot, link, sines, cosines, position, rotation, center):
    """Move the frame ``position, rotation`` from link ``link - 1``'s to link ``link``'s (none for link 0) and fill
    the link box's ``center (3,)``; ``sines, cosines`` as in :func:`pose_base`."""
    if link > 0:  # joint link - 1 carries this link
        joint = link - 1
        for i in range(3):
            for j in range(3):
                position[i] += rotation[i, j] * robot.joint_origins[joint, j]
        angle = (3 if robot.base == 2 else robot.base) + joint  # after the base's angles: free 3, planar 1
        _turn(rotation, robot.joint_axes[joint], sines[angle], cosines[angle])
    for i in range(3):
        center[i] = position[i]
        for j in range(3):
            center[i] += rotation[i, j] * robot.link_offsets[link, j]


@njit(cache=True, inline="always")
def link_frames(q, robot, frame, centers, rotations, n_links):
    """Fill ``centers (L, 3)`` and ``rotations (L, 3, 3)`` (columns: the link's axes) of the first ``n_links`` links
    for configuration ``q`` (:meth:`toolkit.geometry.robots.BoxRobot.link_boxes`); ``frame (4, 3)``: the frame being
    posed (:func:`new_frame`): position, rotation, then the sines and cosines of ``q``'s angles."""
    position, rotation, sines, cosines = frame[0, :3], frame[1:4, :3], frame[4], frame[5]
    start = first_angle(robot)
    for m in range(len(q) - start):
        sines[m], cosines[m] = any_sin_cos(q[start + m])
    pose_base(q, robot, sines, cosines, position, rotation)
    for link in range(n_links):
        next_link(robot, link, sines, cosines, position, rotation, centers[link])
        rotations[link] = rotation


@njit(cache=True, inline="always")
def new_frame(dof):
    """Scratch for :func:`link_frames` for configurations of ``dof`` numbers."""
    return np.zeros((6, max(3, dof)))


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
def _link_touches(center, R, half, low, high, box, dim, outer, inner):
    """:func:`boxes_touch`, settled first by two balls about the link's centre where they can: none of the
    ``box`` lies within ``outer`` (the squared radius of a ball holding the link box): they do not touch; some lies
    within ``inner`` (of a ball the link box holds): they do. Both are a billionth inside the truth, far above
    rounding; nearer contact goes to the separating axes."""
    for i in range(dim):
        if low[i] > box[1, i] or high[i] < box[0, i]:
            return False
    squared = 0.0  # the squared distance from the centre to the box
    for i in range(dim):
        gap = max(box[0, i] - center[i], center[i] - box[1, i], 0.0)
        squared += gap * gap
    if squared > outer:
        return False
    return squared < inner or boxes_touch(center, R, half, low, high, box, dim)


@njit(cache=True, inline="always")
def _turn_block(rotations, axis, sines, cosines, block):
    """:func:`_turn` for a block of rotations ``(3, 3, B)``, the last axis the configurations (vectorized)."""
    j, k = (axis + 1) % 3, (axis + 2) % 3
    for row in range(3):
        a, b = rotations[row, j], rotations[row, k]
        for n in range(block):
            a_n, b_n = a[n], b[n]
            a[n] = a_n * cosines[n] + b_n * sines[n]
            b[n] = b_n * cosines[n] - a_n * sines[n]


@njit(cache=True, inline="always")
def _block_frames(Q, first, block, robot, angles, sines, cosines, position, rotation, centers, rotations):
    """:func:`link_frames` of the ``block`` configurations ``Q[first:first + block]`` at once, every loop over
    them, so that the compiler turns each into vector instructions: fills ``centers (L, 3, B)`` and
    ``rotations (L, 3, 3, B)``; ``angles, sines, cosines (A, B)``, ``position (3, B)``, ``rotation (3, 3, B)``:
    scratch."""
    start = first_angle(robot)
    for k in range(len(angles)):
        for n in range(block):
            angles[k, n] = Q[first + n, start + k]
    flat_angles, flat_sines, flat_cosines = angles.reshape(-1), sines.reshape(-1), cosines.reshape(-1)
    for t in range(len(flat_angles)):
        flat_sines[t], flat_cosines[t] = sin_cos(flat_angles[t])
    for t in range(len(flat_angles)):
        if abs(flat_angles[t]) > SIN_COS_LIMIT:
            flat_sines[t], flat_cosines[t] = any_sin_cos(flat_angles[t])
    for i in range(3):
        for j in range(3):
            rotation[i, j, :block] = 1.0 if i == j else 0.0
    for n in range(block):
        position[0, n], position[1, n] = Q[first + n, 0], Q[first + n, 1]
    if robot.base == 2:
        for n in range(block):
            position[2, n] = Q[first + n, 2]
    else:
        position[2, :block] = robot.base_height if robot.base == 1 else 0.0
    if robot.base == 1:  # planar: yaw
        _turn_block(rotation, 2, sines[0], cosines[0], block)
    elif robot.base == 2:  # free: Z-Y-X Euler angles
        _turn_block(rotation, 2, sines[0], cosines[0], block)
        _turn_block(rotation, 1, sines[1], cosines[1], block)
        _turn_block(rotation, 0, sines[2], cosines[2], block)
    for link in range(len(centers)):
        if link > 0:  # joint link - 1 carries this link
            joint, origin = link - 1, robot.joint_origins[link - 1]
            for i in range(3):
                p, r0, r1, r2 = position[i], rotation[i, 0], rotation[i, 1], rotation[i, 2]
                for n in range(block):
                    p[n] += r0[n] * origin[0] + r1[n] * origin[1] + r2[n] * origin[2]
            angle = (3 if robot.base == 2 else robot.base) + joint  # after the base's angles: free 3, planar 1
            _turn_block(rotation, robot.joint_axes[joint], sines[angle], cosines[angle], block)
        offset = robot.link_offsets[link]
        for i in range(3):
            p, r0, r1, r2, center = position[i], rotation[i, 0], rotation[i, 1], rotation[i, 2], centers[link, i]
            for n in range(block):
                center[n] = p[n] + r0[n] * offset[0] + r1[n] * offset[1] + r2[n] * offset[2]
        rotations[link, :, :, :block] = rotation[:, :, :block]


BLOCK = 64  # configurations posed together


@njit(cache=True)
def validity(Q, robot, world, valid):
    """Fill ``valid (N,)`` for configurations ``Q (N, dof)``: the steps in the module's docstring, each
    configuration stopping at its first failure. ``robot``, ``world``: arrays
    (:class:`toolkit.geometry.compiled.Robot`, :class:`~toolkit.geometry.compiled.World`, with its far bits)."""
    half, n_links, grid = robot.half_extents, len(robot.half_extents), world.far
    outer = np.sum(half**2, axis=1) * (1 + 1e-9)  # (L,) the squared radii of the balls of _link_touches
    inner = np.empty(n_links)
    for link in range(n_links):
        inner[link] = np.min(half[link, : len(world.lower)]) ** 2 * (1 - 1e-9)
    angles = np.zeros((Q.shape[1] - first_angle(robot), BLOCK))  # (A, B); past a short last block: stale, unread
    sines, cosines = np.empty_like(angles), np.empty_like(angles)
    position, rotation = np.zeros((3, BLOCK)), np.zeros((3, 3, BLOCK))
    centers, rotations = np.zeros((n_links, 3, BLOCK)), np.zeros((n_links, 3, 3, BLOCK))
    cell = np.zeros((n_links, BLOCK), np.int64)  # the far grid's cell of each link's centre
    low, high, cells = np.zeros(3), np.zeros(3), np.zeros((2, 3), np.int64)
    seen, found = np.full(len(world.boxes), -1), np.zeros(len(world.boxes), np.int64)  # per box: the last link
    for first in range(0, len(Q), BLOCK):
        block = min(BLOCK, len(Q) - first)
        _block_frames(Q, first, block, robot, angles, sines, cosines, position, rotation, centers, rotations)
        for link in range(n_links):
            flat, x, y, z = cell[link], centers[link, 0], centers[link, 1], centers[link, 2]
            for n in range(block):
                row = _axis_cell(x[n], grid, 0) * grid.shape[1] + _axis_cell(y[n], grid, 1)
                flat[n] = row * grid.shape[2] + _axis_cell(z[n], grid, 2)
        for b in range(block):
            n = first + b
            valid[n] = False
            if not in_bounds(Q[n], robot.lower, robot.upper):
                continue
            valid[n] = True
            for link in range(n_links):
                if _bit(grid.bits[grid.link_ball[link]], cell[link, b]):
                    continue  # its ball, wherever in its cell, lies in the region and touches no obstacle
                # else its bounds must lie in the region, and its box touch none of the obstacles listed in the
                # cells they cover (written out here: as a function of its own, numba compiles it slower)
                center, R = centers[link, :, b], rotations[link, :, :, b]
                touches = not one_link_bounds(center, R, half[link], world, low, high, cells)
                for m in range(0 if touches else listed_boxes(cells, world, seen, n * n_links + link, found)):
                    box = world.boxes[found[m]]
                    if _link_touches(center, R, half[link], low, high, box, len(world.lower), outer[link], inner[link]):
                        touches = True
                        break
                if touches:
                    valid[n] = False
                    break


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

    ``world`` as in :func:`validity`, its cell lists holding the boxes grown by ``cap``.
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


@njit(cache=True)
def cell_distances(bounds, lower, cell, shape, cap):
    """``(C,)`` per cell of a grid (``lower (3,)``, cubes of side ``cell``, ``shape (3,)``), the distance from the cell
    to the nearest of the boxes ``bounds (K, 2, 3)`` (min / max corners), or ``cap`` where none lies nearer."""
    clearance = np.full(shape[0] * shape[1] * shape[2], cap)
    block = np.zeros((2, 3), np.int64)
    for k in range(len(bounds)):
        for i in range(3):  # the cells within cap of box k
            for end, value in enumerate((bounds[k, 0, i] - cap, bounds[k, 1, i] + cap)):
                block[end, i] = min(max(int(np.floor((value - lower[i]) / cell)), 0), shape[i] - 1)
        for a in range(block[0, 0], block[1, 0] + 1):
            for b in range(block[0, 1], block[1, 1] + 1):
                for c in range(block[0, 2], block[1, 2] + 1):
                    gap = 0.0
                    for i, index in enumerate((a, b, c)):
                        start = lower[i] + index * cell
                        gap += max(bounds[k, 0, i] - (start + cell), start - bounds[k, 1, i], 0.0) ** 2
                    flat = (a * shape[1] + b) * shape[2] + c
                    clearance[flat] = min(clearance[flat], np.sqrt(gap))
    return clearance


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
