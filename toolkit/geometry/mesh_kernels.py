"""The compiled exact check against a triangle mesh, one configuration at a time (numba).

A link box is in collision with a closed mesh when it touches a triangle or lies wholly inside
the solid. The loop of :func:`mesh_validity` takes each configuration through the box chain's
kinematics (the steps of :mod:`toolkit.geometry.kernels`), then, link by link, stopping at the first
in collision:

- one look-up: the bit of the grid cell that holds the link's centre, for the link's ball (centred there,
  through its corners; :class:`toolkit.geometry.compiled_mesh.CompiledMeshChecker` sets the bits once). A 1
  says the ball lies in the region and misses the bounds of every part of the mesh, and so does the box:
  most links are done;
- else the link's bounds must lie in the region, and its box must touch the bounds of one of the mesh's
  parts (the separating-axis test of boxes; a link that touches none touches no triangle and lies in no
  part); then

0. if one of 27 of its points (centre, faces' and edges' middles, corners) lies in a grid cell that
   no triangle crosses and that lies inside the solid (cells classified once,
   :class:`toolkit.geometry.compiled_mesh.CompiledMeshChecker`), the link meets the solid: in collision;
1. the triangles listed in the grid cells its bounds cover, each tested against the link box
   with the separating-axis theorem (Akenine-Möller, "Fast 3D triangle-box overlap testing",
   2001): in the link's frame, the box's 3 axes, the triangle's normal and the 9 cross products
   of its edges with the box's axes. Touching projections do not separate: closed sets, as in FCL;
2. a link that touches no triangle lies wholly inside or wholly outside, and any of its points says
   which: the state of a cell no triangle crosses that holds one of 27 of its points (step 0), else
   the generalized winding number of its centre (:func:`toolkit.geometry.meshes.winding_numbers`,
   compiled) over the parts whose bounds hold it.

A robot whose base ranges mostly beyond the region (3DO's youBot in a room) leaves it, in most
configurations, with its base link: :func:`base_link_inside` poses and bounds that link alone first, and
the loop checks only the configurations it keeps.

Like :mod:`toolkit.geometry.kernels`, the mesh arrives as arrays and ``cache=True`` keeps the
compiled loop on disk.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from toolkit.geometry.frame_kernels import link_frames, new_frame
from toolkit.geometry.kernels import boxes_touch, far, flat_cell, in_bounds, link_bounds, listed_boxes

OUTSIDE, INSIDE, SURFACE = 0, 1, 2  # a grid cell's state: no triangle crosses it (out, in), or some may


@njit(cache=True, inline="always")
def _separated(p0, p1, p2, radius):
    """Whether the projections ``p0, p1, p2`` of a triangle's corners lie wholly beyond ``[-radius, radius]``."""
    return min(p0, p1, p2) > radius or max(p0, p1, p2) < -radius


@njit(cache=True, inline="always")
def _triangle_touches(triangle, center, R, half, scratch):
    """Whether the ``triangle (3, 3)`` (corners in rows) touches the box ``center (3,)``, ``R (3, 3)`` (columns: its
    axes), ``half (3,)``; ``scratch (6, 3)``: the corners in the box's frame, then the edges."""
    corners, e = scratch[:3], scratch[3:]
    for c in range(3):
        for j in range(3):
            corners[c, j] = 0.0
            for i in range(3):
                corners[c, j] += R[i, j] * (triangle[c, i] - center[i])
    for j in range(3):  # the box's axes
        if _separated(corners[0, j], corners[1, j], corners[2, j], half[j]):
            return False
    for k in range(3):  # the edges
        for j in range(3):
            e[k, j] = corners[(k + 1) % 3, j] - corners[k, j]
    normal = (
        e[0, 1] * e[1, 2] - e[0, 2] * e[1, 1],
        e[0, 2] * e[1, 0] - e[0, 0] * e[1, 2],
        e[0, 0] * e[1, 1] - e[0, 1] * e[1, 0],
    )
    reach = abs(normal[0]) * half[0] + abs(normal[1]) * half[1] + abs(normal[2]) * half[2]
    if abs(normal[0] * corners[0, 0] + normal[1] * corners[0, 1] + normal[2] * corners[0, 2]) > reach:
        return False
    for k in range(3):  # edge k crossed with box axis j: (0, e_v, -e_u) in the (j, u, v) order
        for j in range(3):
            u, v = (j + 1) % 3, (j + 2) % 3
            a_u, a_v = e[k, v], -e[k, u]
            reach = abs(a_u) * half[u] + abs(a_v) * half[v]
            p0 = a_u * corners[0, u] + a_v * corners[0, v]
            p1 = a_u * corners[1, u] + a_v * corners[1, v]
            p2 = a_u * corners[2, u] + a_v * corners[2, v]
            if _separated(p0, p1, p2, reach):
                return False
    return True


@njit(cache=True)
def triangle_cell_lists(triangles, lo, hi, lower, cell, shape):
    """Per cell of a grid (``lower (3,)``, cubes of side ``cell``, ``shape (3,)``), the triangles ``(T, 3, 3)`` that
    touch it, in triangle order, as :func:`toolkit.geometry.kernels.cell_lists` returns them: each triangle tested
    (separating axes) against each cell of its bounds' block ``lo, hi (T, 3)``, the cell a hair larger (a cell no
    triangle touches then surely lies off the surface)."""
    count = np.zeros(shape[0] * shape[1] * shape[2], np.int64)
    identity, half = np.eye(3), np.full(3, cell / 2 * (1 + 1e-9) + 1e-12)
    center, scratch = np.zeros(3), np.zeros((6, 3))
    members = np.zeros(0, np.int64)
    for fill in range(2):  # 0: count each cell's triangles; 1: list them
        if fill:
            first = np.cumsum(count) - count
            members, at = np.empty(count.sum(), np.int64), first.copy()
        for t in range(len(triangles)):
            for a in range(lo[t, 0], hi[t, 0] + 1):
                for b in range(lo[t, 1], hi[t, 1] + 1):
                    for c in range(lo[t, 2], hi[t, 2] + 1):
                        for i, index in enumerate((a, b, c)):
                            center[i] = lower[i] + (index + 0.5) * cell
                        if _triangle_touches(triangles[t], center, identity, half, scratch):
                            flat = (a * shape[1] + b) * shape[2] + c
                            if fill:
                                members[at[flat]] = t
                                at[flat] += 1
                            else:
                                count[flat] += 1
    return count, np.cumsum(count) - count, members


@njit(cache=True)
def winding_number(point, triangles, faces):
    """The generalized winding number of ``point (3,)`` over ``triangles[faces]`` (``triangles (T, 3, 3)``): the
    solid angles they subtend there (Van Oosterom and Strackee 1983), summed, over 4 pi."""
    total = 0.0
    for f in faces:
        a, b, c = triangles[f, 0] - point, triangles[f, 1] - point, triangles[f, 2] - point
        la, lb, lc = np.sqrt(a @ a), np.sqrt(b @ b), np.sqrt(c @ c)
        det = (
            a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])
        )
        total += 2 * np.arctan2(det, la * lb * lc + (a @ b) * lc + (b @ c) * la + (c @ a) * lb)
    return total / (4 * np.pi)


@njit(cache=True, inline="always")
def _cell_state(point, mesh, world):
    """The state of the grid cell holding ``point (3,)`` (clipped to the grid)."""
    return mesh.cell_state[flat_cell(point, world)]


@njit(cache=True, inline="always")
def _known_state(center, R, half, mesh, world, point):
    """The state of the first cell no triangle crosses that holds one of 27 points of a box (``center (3,)``,
    ``R (3, 3)``, ``half (3,)``): its centre first, then its faces' and edges' middles and corners; SURFACE if none
    does; ``point (3,)``: scratch. INSIDE: the box meets the solid."""
    for k in range(27):
        for i in range(3):
            point[i] = center[i]
        for j in range(3):  # k's digit j in base 3, taken 0, 1, 2 -> 0, +1, -1 times half[j] along axis j
            step = (k // 3**j) % 3
            if step:
                for i in range(3):
                    point[i] += R[i, j] * half[j] * (1.0 if step == 1 else -1.0)
        state = _cell_state(point, mesh, world)
        if state != SURFACE:
            return state
    return SURFACE


@njit(cache=True, inline="always")
def _winding_inside(point, mesh):
    """Whether ``point (3,)`` lies inside the solid: its winding number over the parts whose bounds hold it > 1/2."""
    winding = 0.0
    for part in range(len(mesh.part_bounds)):
        lo, hi = mesh.part_bounds[part, 0], mesh.part_bounds[part, 1]
        if lo[0] <= point[0] <= hi[0] and lo[1] <= point[1] <= hi[1] and lo[2] <= point[2] <= hi[2]:
            start = mesh.part_first[part]
            winding += winding_number(point, mesh.triangles, mesh.part_faces[start : start + mesh.part_count[part]])
    return winding > 0.5


@njit(cache=True, inline="always")
def _covered_cells(low, high, world, cells):
    """Fill ``cells (2, 3)`` with the first and last cell per axis of ``world``'s grid that bounds ``low, high (3,)``
    cover, clipped to the grid."""
    for i in range(3):
        for end, value in enumerate((low[i], high[i])):
            cell = int(np.floor((value - world.lower[i]) / world.cell))
            cells[end, i] = min(max(cell, 0), world.shape[i] - 1)


@njit(cache=True, inline="always")
def _overlaps(low, high, box):
    """Whether the bounds ``low, high (3,)`` meet the ``box (2, 3)`` (min / max corners)."""
    return (
        low[0] <= box[1, 0] and box[0, 0] <= high[0]
        and low[1] <= box[1, 1] and box[0, 1] <= high[1]
        and low[2] <= box[1, 2] and box[0, 2] <= high[2]
    )  # fmt: skip


@njit(cache=True, inline="always")
def _near_a_part(center, R, half, low, high, cells, parts, seen, tag, found):
    """Whether a link box (as in :func:`toolkit.geometry.kernels.boxes_touch`) touches the bounds of a part of the mesh
    listed in ``cells (2, 3)``: else it touches no triangle and lies in no part."""
    for m in range(listed_boxes(cells, parts, seen, tag, found)):
        if boxes_touch(center, R, half, low, high, parts.boxes[found[m]], 3):
            return True
    return False


@njit(cache=True, inline="always")
def _touches_a_triangle(center, R, half, low, high, cells, world, mesh, seen, tag, scratch):
    """Whether a link box touches a triangle listed in the cells ``cells (2, 3)`` of ``world``, its triangles' grid,
    that the box itself touches (not only its bounds); ``seen``: a triangle listed in two cells is tested once."""
    shape, cell_box = world.shape, scratch[7:9]
    for a in range(cells[0, 0], cells[1, 0] + 1):
        for b in range(cells[0, 1], cells[1, 1] + 1):
            for c in range(cells[0, 2], cells[1, 2] + 1):
                flat = (a * shape[1] + b) * shape[2] + c
                if world.cell_count[flat] == 0:
                    continue
                for i, index in enumerate((a, b, c)):
                    cell_box[0, i] = world.lower[i] + index * world.cell
                    cell_box[1, i] = cell_box[0, i] + world.cell
                if not boxes_touch(center, R, half, low, high, cell_box, 3):
                    continue
                for m in range(world.cell_first[flat], world.cell_first[flat] + world.cell_count[flat]):
                    t = world.cell_boxes[m]
                    if seen[t] == tag:
                        continue
                    seen[t] = tag
                    if _overlaps(low, high, world.boxes[t]) and _triangle_touches(
                        mesh.triangles[t], center, R, half, scratch
                    ):
                        return True
    return False


@njit(cache=True)
def base_link_inside(Q, robot, world, inside):
    """Fill ``inside (N,)``: whether the base link of each configuration of ``Q (N, dof)`` lies inside ``world``'s
    region (:func:`toolkit.geometry.kernels.link_bounds` of that link alone); false, the configuration is invalid."""
    frame, centers, rotations = new_frame(Q.shape[1]), np.zeros((1, 3)), np.zeros((1, 3, 3))
    low, high, cells = np.zeros((1, 3)), np.zeros((1, 3)), np.zeros((1, 2, 3), np.int64)
    for n in range(len(Q)):
        link_frames(Q[n], robot, frame, centers, rotations, 1)
        inside[n] = link_bounds(robot.half_extents[:1], world, centers, rotations, low, high, cells)


@njit(cache=True)
def mesh_validity(Q, robot, parts, world, mesh, valid):
    """Fill ``valid (N,)`` for configurations ``Q (N, dof)``: the steps in the module's docstring, a link tested only
    where its cell's far bit is 0 and its box meets a part's bounds. ``robot``:
    :class:`toolkit.geometry.compiled.Robot`; ``parts``: a :class:`~toolkit.geometry.compiled.World` of the parts'
    bounds (a box world's coarse grid), ``world`` one of the triangles' bounds (a finer grid, whose cells the far
    bits follow); ``mesh``: :class:`toolkit.geometry.compiled_mesh.Mesh`."""
    half, n_links = robot.half_extents, len(robot.half_extents)
    frame, centers, rotations = new_frame(Q.shape[1]), np.zeros((n_links, 3)), np.zeros((n_links, 3, 3))
    low, high, scratch = np.zeros((1, 3)), np.zeros((1, 3)), np.zeros((9, 3))  # low, high: one link's bounds
    part_cells, cells = np.zeros((1, 2, 3), np.int64), np.zeros((2, 3), np.int64)
    seen = np.full(len(world.boxes), -1)  # per triangle: the last link that tested it
    seen_part, found_part = np.full(len(parts.boxes), -1), np.zeros(len(parts.boxes), np.int64)
    for n in range(len(Q)):
        valid[n] = False
        if not in_bounds(Q[n], robot.lower, robot.upper):
            continue
        link_frames(Q[n], robot, frame, centers, rotations, n_links)
        valid[n] = True
        for link in range(n_links):
            tag = n * n_links + link
            c, R, h = centers[link], rotations[link], half[link]
            if far(c, mesh.far[mesh.link_ball[link]], world):
                continue  # its ball, wherever in its cell, lies in the region and meets no part's bounds
            one = slice(link, link + 1)
            if not link_bounds(half[one], parts, centers[one], rotations[one], low, high, part_cells):
                valid[n] = False  # out of the region
                break
            lo, hi = low[0], high[0]
            if not _near_a_part(c, R, h, lo, hi, part_cells[0], parts, seen_part, tag, found_part):
                continue  # no triangle lies there, nor any inside
            _covered_cells(lo, hi, world, cells)
            state = _known_state(c, R, h, mesh, world, scratch[6])  # INSIDE: some point of the link is
            if (
                state == INSIDE
                or _touches_a_triangle(c, R, h, lo, hi, cells, world, mesh, seen, tag, scratch)
                or (state == SURFACE and _winding_inside(c, mesh))  # it touches none: wholly inside or outside
            ):
                valid[n] = False
                break
