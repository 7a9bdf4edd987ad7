"""The compiled exact checker for triangle meshes: what :func:`toolkit.geometry.collision.exact_checker` returns for a
:class:`~toolkit.geometry.workspace.MeshWorkspace`.

:class:`CompiledMeshChecker` gives the answers of the reference :class:`~toolkit.geometry.collision.MeshChecker`
(python-fcl's BVH for "does a link touch a triangle?", numpy winding numbers for "does it lie inside?"; the tests
hold the two equal near contact) in one compiled loop (:mod:`toolkit.geometry.mesh_kernels`). This class turns the
mesh into the arrays that loop reads:

- a grid over the region whose cells list the triangles that touch them (the broadphase: a link tests
  only the triangles listed where its box lies);
- per cell and link, one bit: whether the link's ball (centred at the link's centre, through its corners) lies
  in the region and misses the bounds of every part of the mesh wherever in the cell its centre lies. Most links
  in most configurations are done with that one look-up; one bit a cell keeps the grid in the processor's cache
  (a link's 1.5 million cells in 185 kB, on the tutorials' room subdivided three times), where a distance a cell
  would not;
- each cell's state: a cell no triangle touches lies wholly inside or wholly outside a closed mesh, and so
  does every cell joined to it through such cells, so one winding number per connected region of them classifies
  them all, once; a link with a point in such a cell needs no winding number. An open (or inconsistently
  oriented) mesh has no inside to share: every cell then asks the winding number.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from scipy import ndimage

from toolkit.geometry.box_world import BoxWorldChecker
from toolkit.geometry.compiled import World, far_bits, robot_arrays, world_arrays
from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import MeshWorkspace

MAX_CELLS = 128  # cells an axis, at most
TRIANGLES_PER_CELL = 0.5  # the grid's cells are sized to hold about this many triangles each, near the surface


class Mesh(NamedTuple):
    """A mesh as :func:`toolkit.geometry.mesh_kernels.mesh_validity` reads it."""

    triangles: np.ndarray  # (T, 3, 3) corners in rows
    cell_state: np.ndarray  # (C,) int8: OUTSIDE, INSIDE or SURFACE (mesh_kernels)
    # (B, W) uint64, per ball size: bit c % 64 of word c // 64 says a ball centred in cell c lies in the region and
    # meets no part's bounds
    far: np.ndarray
    link_ball: np.ndarray  # (L,) each link's ball size: its row of far
    part_bounds: np.ndarray  # (K, 2, 3) min / max corners of each connected part
    part_first: np.ndarray  # (K,) part k's faces are part_faces[part_first[k]:part_first[k] + part_count[k]]
    part_count: np.ndarray  # (K,)
    part_faces: np.ndarray  # (F,)


class CompiledMeshChecker(BoxWorldChecker):
    """Exact checker against a mesh, compiled with numba: kinematics, triangle-box separating axes and inside tests
    in one loop over configurations. Clearance bounds: the numpy ones of :class:`BoxWorldChecker`, on the parts'
    bounds (conservative, as the reference's)."""

    def __init__(self, workspace: MeshWorkspace, robot: BoxRobot):
        if not isinstance(workspace, MeshWorkspace):
            raise ValueError(f"CompiledMeshChecker needs a MeshWorkspace, got {type(workspace).__name__}")
        super().__init__(workspace, robot)
        solid = workspace.solid
        self._robot = robot_arrays(robot)
        self._base_first = self._base_mostly_outside()
        self._parts = world_arrays(self.grid, grow=0.0)  # the parts' bounds on the prefilter's grid
        bounds = np.stack([solid.triangles.min(axis=1), solid.triangles.max(axis=1)], axis=1)  # (T, 2, 3)
        self._grid = self._triangle_grid(solid.triangles, bounds)
        mesh = workspace.mesh
        state = self._cell_states(solid, closed=bool(mesh.is_watertight and mesh.is_winding_consistent))
        parts = solid.parts or [np.zeros(0, dtype=np.int64)]
        count = np.array([len(p) for p in parts], dtype=np.int64)
        part_bounds = np.ascontiguousarray(solid.bounds.reshape(-1, 2, 3), dtype=np.float64)  # (K, 2, 3)
        radii, link_ball = np.unique(np.linalg.norm(robot.half_extents, axis=1), return_inverse=True)  # (B,), (L,)
        self._mesh = Mesh(
            np.ascontiguousarray(solid.triangles, dtype=np.float64),
            state,
            self._far_bits(part_bounds, radii),
            link_ball.astype(np.int64),
            part_bounds,
            np.cumsum(count) - count,
            count,
            np.concatenate(parts).astype(np.int64),
        )

    def _base_mostly_outside(self) -> bool:
        """Whether less than half of the box the base's position ranges over lies in the region (a robot bounded for
        a larger workspace, as 3DO's youBot in a room): then most configurations leave the region with the base link,
        which the loop poses and bounds alone first."""
        ws, robot = self.workspace, self.robot
        n = robot.n_positions  # the base's position coordinates, first in a configuration
        lo, hi = robot.lower[:n], robot.upper[:n]
        overlap = np.clip(np.minimum(hi, ws.upper[:n]) - np.maximum(lo, ws.lower[:n]), 0.0, None)
        return bool(np.prod(overlap / np.maximum(hi - lo, 1e-12)) < 0.5)

    def _triangle_grid(self, tri: np.ndarray, bounds: np.ndarray) -> World:
        """The region's grid, cells listing the triangles ``tri (T, 3, 3)`` (their ``bounds (T, 2, 3)``) that touch
        them; its cells hold about ``TRIANGLES_PER_CELL`` triangles of mean area where the surface crosses them, and
        are no wider than the robot's thinnest link, so that a link near the surface mostly has points in cells the
        surface does not cross (no winding number to compute)."""
        from toolkit.geometry import mesh_kernels

        ws = self.workspace
        extent = ws.upper - ws.lower  # (3,)
        area = (
            0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=-1).mean()
            if len(tri)
            else 1.0
        )
        thinnest = 2 * float(np.min(self.robot.half_extents))  # the thinnest link's thickness
        size = min(np.sqrt(area * TRIANGLES_PER_CELL), thinnest)
        cell = float(np.clip(size, extent.max() / MAX_CELLS, extent.max()))
        shape = (np.ceil(extent / cell).astype(np.int64) + 1).astype(np.int64)  # (3,)
        lo = np.clip(np.floor((bounds[:, 0] - ws.lower) / cell).astype(np.int64), 0, shape - 1)  # (T, 3)
        hi = np.clip(np.floor((bounds[:, 1] - ws.lower) / cell).astype(np.int64), 0, shape - 1)
        count, first, members = mesh_kernels.triangle_cell_lists(tri, lo, hi, np.asarray(ws.lower, float), cell, shape)
        return World(
            np.array(ws.lower, dtype=np.float64),
            np.array(ws.upper, dtype=np.float64),
            np.ascontiguousarray(bounds, dtype=np.float64),
            cell,
            shape,
            count.astype(np.int32),
            first.astype(np.int32),
            members.astype(np.int32),
        )

    def _far_bits(self, part_bounds: np.ndarray, radii: np.ndarray) -> np.ndarray:
        """``(B, W)`` per ball radius ``radii (B,)``, the grid's cells as bits: 1 where the ball round any point of the
        cell lies in the region and farther than its radius from every part's bounds ``part_bounds (K, 2, 3)``. Then
        so does the link's box and its axis-aligned bounds (no wider than the ball), the box touches no triangle,
        and its centre lies in no part (where the reference's winding number is 0)."""
        grid = self._grid
        return far_bits(part_bounds, grid.lower, grid.upper, grid.cell, grid.shape, radii)

    def _cell_states(self, solid, *, closed: bool) -> np.ndarray:
        """``(C,)`` each cell's state; cells no triangle touches, by connected region, from one winding number each;
        none unless the mesh is ``closed`` (every edge joins two faces, consistently oriented), where the winding
        number can change only across the surface."""
        from toolkit.geometry.mesh_kernels import INSIDE, OUTSIDE, SURFACE

        grid = self._grid
        state = np.full(len(grid.cell_count), SURFACE, dtype=np.int8)  # int8: the grid stays in cache
        if not closed:
            return state
        regions, n_regions = ndimage.label((grid.cell_count == 0).reshape(tuple(grid.shape)))
        regions = regions.reshape(-1)
        cells = np.flatnonzero(regions)
        first = cells[np.unique(regions[cells], return_index=True)[1]]  # one cell per region, in region order
        centres = grid.lower + grid.cell * (np.stack(np.unravel_index(first, tuple(grid.shape)), axis=-1) + 0.5)
        inside = solid.inside(centres) if n_regions else np.zeros(0, dtype=bool)  # (regions,)
        state[cells] = np.where(inside[regions[cells] - 1], INSIDE, OUTSIDE)
        return state

    def validity(self, Q: np.ndarray) -> np.ndarray:
        from toolkit.geometry import mesh_kernels  # numba loads (or compiles) on first use, not on import

        Q = np.ascontiguousarray(Q, dtype=np.float64)
        valid = np.zeros(len(Q), dtype=bool)
        if self._base_first:  # the configurations whose base link leaves the region are invalid: the loop skips them
            inside = np.empty(len(Q), dtype=bool)
            mesh_kernels.base_link_inside(Q, self._robot, self._parts, inside)
            kept, valid_kept = np.flatnonzero(inside), np.empty(int(inside.sum()), dtype=bool)
            mesh_kernels.mesh_validity(Q[kept], self._robot, self._parts, self._grid, self._mesh, valid_kept)
            valid[kept] = valid_kept
        else:
            mesh_kernels.mesh_validity(Q, self._robot, self._parts, self._grid, self._mesh, valid)
        return valid
