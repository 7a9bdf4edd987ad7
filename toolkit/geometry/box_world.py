"""What every exact checker of a box world shares: the region, a grid of cells listing the obstacles, clearance bounds.

A configuration is valid when it lies within the robot's bounds, every link lies
inside the workspace region, and no link box touches an obstacle box (boxes are
closed sets: touching counts as collision, as in FCL).

- :class:`BoxGrid`: per cell of a grid over the region, the obstacles that touch it (the
  broadphase of every box-world checker; the compiled checker's arrays are made from it,
  :mod:`toolkit.geometry.compiled`).
- :class:`BoxWorldChecker`: the base of the exact checkers: a workspace, its grid, and clearance
  bounds for the planner's certificates, in numpy.
- :class:`PrefilteredChecker`: bounds, region and a conservative grid prefilter batched in numpy,
  leaving the exact test of the links the prefilter keeps to a subclass (:mod:`toolkit.geometry.fcl_checker`,
  :class:`SeparatingAxisChecker`).

Two exact checkers here need no library:

- :class:`PointRobotChecker`: the 2D point robot is an axis-aligned square, so an
  interval test against every block is exact; vectorized numpy.
- :class:`SeparatingAxisChecker`: an independent reference for tests, the
  separating-axis theorem for oriented vs axis-aligned boxes, vectorized numpy.
"""

from __future__ import annotations

import numpy as np

from toolkit.geometry.checker import CollisionChecker
from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import MeshWorkspace, Workspace
from toolkit.util.ragged import ragged


class BoxGrid:
    """A grid over a box world's region listing, per cell, the obstacle boxes that touch it: the broadphase.

    Cells are at least as wide as any link's axis-aligned bounds (``cell``: twice the largest link ball's
    radius), so a link's bounds cover at most two cells per axis (:meth:`covered_cells`), and the boxes
    listed there are the only ones it can touch (or, grown by ``grow``, come within ``grow`` of). The
    numpy prefilter (:class:`PrefilteredChecker`), the numpy clearance bounds and the compiled
    checker's arrays (:func:`toolkit.geometry.compiled.world_arrays`) read it.
    """

    def __init__(self, workspace: Workspace, robot: BoxRobot):
        self.workspace, self.dim = workspace, workspace.dim
        self.cell = 2 * float(np.max(np.linalg.norm(robot.half_extents, axis=1)))  # the widest link bounds
        self.shape = tuple(np.maximum(np.ceil((workspace.upper - workspace.lower) / self.cell).astype(int), 1) + 1)
        self._grown: dict[float, tuple] = {}  # box_lists, by grow

    @property
    def lists(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The obstacles of each cell: :meth:`box_lists` of the boxes as they are."""
        return self.box_lists(0.0)

    def box_lists(self, grow: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Per grid cell, the obstacle boxes that touch it once grown by ``grow`` on every side (built once per
        ``grow``).

        ``count (C,)`` and ``first (C,)`` per flattened cell, ``members (B,)``: cell c's boxes
        are ``members[first[c]:first[c] + count[c]]``.
        """
        if grow not in self._grown:
            from toolkit.geometry import kernels  # numba loads (or compiles) on first use, not on import

            boxes, dim = self.workspace.boxes, self.dim  # (K, 2, D)
            lo, hi = np.zeros((2, len(boxes), 3), dtype=np.int64)  # first and last cell per axis, (K, 3) each
            lo[:, :dim], hi[:, :dim] = self.cells(boxes[:, 0] - grow), self.cells(boxes[:, 1] + grow)
            shape = np.ones(3, dtype=np.int64)  # a 2D grid: one cell along the third axis
            shape[:dim] = self.shape
            self._grown[grow] = kernels.cell_lists(lo, hi, shape)
        return self._grown[grow]

    def cells(self, points: np.ndarray) -> np.ndarray:
        """Integer cell index of each point ``(..., D)``, clipped to the grid."""
        index = np.floor((points - self.workspace.lower) / self.cell).astype(int)
        return np.clip(index, 0, np.array(self.shape) - 1)

    def covered_cells(self, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
        """``(2^D, M)`` flat indices of the cells that bounds ``lo, hi (M, D)`` cover (repeats where
        they span one cell).

        Bounds are no wider than a cell, so they cover at most two cells per axis: their 2^D corners' cells.
        """
        lo, hi = self.cells(lo), self.cells(hi)  # (M, D) each
        return np.stack(
            [
                np.ravel_multi_index(tuple(np.where(np.array(corner, dtype=bool), hi, lo).T), self.shape)
                for corner in np.ndindex(*(2,) * self.dim)
            ]
        )


class BoxWorldChecker(CollisionChecker):
    """What every exact checker of a box world (or of a mesh's parts' bounds) has: its ``workspace``, a
    :class:`BoxGrid` over it (``grid``) and clearance bounds from that grid, in numpy. How a configuration is
    decided is a subclass's :meth:`validity`."""

    is_exact = True  # every answer is the geometry's

    def __init__(self, workspace: Workspace, robot: BoxRobot):
        if workspace.dim != robot.dim:
            raise ValueError(f"robot {robot.name!r} is {robot.dim}D but the workspace is {workspace.dim}D")
        super().__init__(robot)
        self.workspace = workspace
        self.grid = BoxGrid(workspace, robot)

    def clearance_bounds(self, Q: np.ndarray, cap: float) -> np.ndarray:
        """0 out of bounds; otherwise the smallest over links of a lower bound on its clearance.

        A link's clearance is bounded by its distance to the region's walls (exact; a
        floor or ceiling that a link never moves towards, ``robot.level_links``, does not
        count) and, for each obstacle box listed in the grid cells its bounds cover (boxes
        grown by ``cap``: farther ones cannot matter), the larger of two lower bounds: the
        distance between the link's axis-aligned bounds and the box, and the gap between
        their projections on any of the link's own axes (a projection on a unit axis
        brings points no closer: the separating-axis theorem's measure).
        """
        clearance = np.zeros(len(Q))
        idx = np.flatnonzero(self.robot.in_bounds(Q))
        centers, rotations, half = self.robot.link_boxes(Q[idx])  # (n, L, D), (n, L, D, D), (L, D)
        n_links, d = half.shape
        centers, rotations = centers.reshape(-1, d), rotations.reshape(-1, d, d)  # (n * L, ...): every link box
        reach = np.einsum("pij,pj->pi", np.abs(rotations), np.tile(half, (len(idx), 1)))  # (n * L, D)
        lo, hi = centers - reach, centers + reach  # the links' bounds
        walls = np.minimum(lo - self.workspace.lower, self.workspace.upper - hi).reshape(len(idx), n_links, d)
        level = walls[:, : self.robot.level_links, -1]  # links that never move vertically: floor and ceiling
        walls[:, : self.robot.level_links, -1] = np.where(level >= 0, np.inf, level)
        link = walls.min(axis=-1).reshape(-1)  # (n * L,)
        count, first, members = self.grid.box_lists(grow=cap)
        cell = self.grid.covered_cells(lo, hi).reshape(-1)  # (2^D * n * L,)
        owner, ordinal = ragged(count[cell])
        # (link, box) pairs from the cells each link's bounds cover; repeats are harmless
        pair_link = owner % len(link)  # (P,)
        pair_box = members[first[cell[owner]] + ordinal]  # (P,)
        boxes = self.workspace.boxes  # (K, 2, D)
        gap = np.maximum(  # (P, D)
            np.maximum(boxes[pair_box, 0] - hi[pair_link], lo[pair_link] - boxes[pair_box, 1]), 0
        )
        bound = np.linalg.norm(gap, axis=-1)  # (P,)
        near = np.flatnonzero(bound < cap)
        j, k = pair_link[near], pair_box[near]
        axes = np.swapaxes(rotations[j], -1, -2)  # (R, D, D): rows are the link's axes
        box_center, box_half = boxes[k].mean(axis=1), (boxes[k, 1] - boxes[k, 0]) / 2  # (R, D)
        along = (  # (R, D): gaps along link axes
            np.abs(np.einsum("rad,rd->ra", axes, centers[j] - box_center))
            - half[j % n_links]
            - np.einsum("rad,rd->ra", np.abs(axes), box_half)
        )
        bound[near] = np.maximum(bound[near], along.max(axis=1))
        np.minimum.at(link, pair_link, bound)
        clearance[idx] = link.reshape(len(idx), n_links).min(axis=1)
        return np.clip(clearance, 0.0, cap)


class PrefilteredChecker(BoxWorldChecker):
    """Bounds, region, then a conservative voxel prefilter per link, batched in numpy; the exact test of the links
    the prefilter keeps is a subclass's :meth:`_links_collide` (python-fcl's, the separating axes').

    The prefilter marks every cell of the grid that an obstacle touches; a link's bounds cover at most
    two cells per axis, so 2^D look-ups tell whether it may touch an obstacle.
    """

    def __init__(self, workspace: Workspace, robot: BoxRobot):
        super().__init__(workspace, robot)
        self._marked = self.grid.lists[0].reshape(self.grid.shape) > 0  # cells an obstacle touches

    def validity(self, Q: np.ndarray) -> np.ndarray:
        valid = self.robot.in_bounds(Q)  # (N,)
        idx = np.flatnonzero(valid)
        aabbs = self.robot.link_aabbs(Q[idx])  # (n, L, 2, D)
        inside = np.all(
            (aabbs[:, :, 0] >= self.workspace.lower) & (aabbs[:, :, 1] <= self.workspace.upper), axis=(1, 2)
        )
        valid[idx[~inside]] = False
        idx, aabbs = idx[inside], aabbs[inside]
        cells = self.grid.covered_cells(
            aabbs[:, :, 0].reshape(-1, self.robot.dim), aabbs[:, :, 1].reshape(-1, self.robot.dim)
        )
        candidates = self._marked.reshape(-1)[cells].any(axis=0).reshape(aabbs.shape[:2])  # (n, L): may touch a block
        valid[idx[self._links_collide(Q[idx], aabbs, candidates)]] = False
        return valid

    def _links_collide(self, Q: np.ndarray, aabbs: np.ndarray, candidates: np.ndarray) -> np.ndarray:
        """(n,) whether any link of each configuration meets an obstacle; ``candidates (n, L)`` may."""
        raise NotImplementedError(f"{type(self).__name__} must override _links_collide")


class PointRobotChecker(BoxWorldChecker):
    """Exact numpy check for the 2D point robot.

    Its square never turns, so its configuration-space obstacles are the blocks grown
    by its half extents (a Minkowski sum of boxes is a box), and the free region is the
    workspace shrunk by the same amount: four comparisons per block on contiguous arrays.
    A check is then cheaper than a clearance bound: certificates do not pay.
    """

    certificates_pay = False

    def __init__(self, workspace: Workspace, robot: BoxRobot):
        if not is_point_robot(robot):
            raise ValueError(f"PointRobotChecker needs the 2D point robot, got {robot.name!r}")
        super().__init__(workspace, robot)
        half = robot.half_extents[0]  # (2,)
        self._free_lo = np.maximum(robot.lower, workspace.lower + half)  # (2,)
        self._free_hi = np.minimum(robot.upper, workspace.upper - half)  # (2,)
        self._c_obstacles = np.stack([workspace.boxes[:, 0] - half, workspace.boxes[:, 1] + half], axis=1)  # (K, 2, 2)

    def validity(self, Q: np.ndarray) -> np.ndarray:
        x, y = np.ascontiguousarray(Q[:, 0]), np.ascontiguousarray(Q[:, 1])  # (N,) each
        (x_lo, y_lo), (x_hi, y_hi) = self._free_lo, self._free_hi
        valid = (x >= x_lo) & (x <= x_hi) & (y >= y_lo) & (y <= y_hi)
        for (bx_lo, by_lo), (bx_hi, by_hi) in self._c_obstacles:  # a handful of blocks: loop over K, never N
            valid &= ~((x >= bx_lo) & (x <= bx_hi) & (y >= by_lo) & (y <= by_hi))
        return valid


def is_point_robot(robot: BoxRobot) -> bool:
    """Whether ``robot`` is a lone square moving in the plane (a 2D base, no joints): :class:`PointRobotChecker`'s."""
    return robot.base == "point2d" and robot.dof == 2


class SeparatingAxisChecker(PrefilteredChecker):
    """Reference: separating-axis test of every candidate (link, obstacle) pair, vectorized.

    Two convex boxes are disjoint iff some axis separates their projections
    (Gottschalk et al., OBBTree, 1996): in 3D the 3 world axes, the link's 3 axes and
    their 9 cross products; in 2D the 2 world axes and the link's 2 axes.
    """

    def _links_collide(self, Q, aabbs, candidates):
        """Ignores the voxel prefilter: every (link, obstacle) pair whose bounds meet is tested."""
        boxes = self.workspace.boxes  # (K, 2, D)
        near = np.all(  # (n, L, K)
            (aabbs[:, :, None, 0] <= boxes[:, 1]) & (aabbs[:, :, None, 1] >= boxes[:, 0]), axis=-1
        )
        centers, rotations, half = self.robot.link_boxes(Q)
        n, l, k = np.nonzero(near)  # candidate pairs
        boxes = self.workspace.boxes[k]  # (P, 2, D)
        box_center, box_half = boxes.mean(axis=1), (boxes[:, 1] - boxes[:, 0]) / 2  # (P, D)
        axes_link = np.swapaxes(rotations[n, l], -1, -2)  # (P, D, D): rows are the link's axes
        d = self.robot.dim
        world = np.broadcast_to(np.eye(d), axes_link.shape)
        axes = [world, axes_link]
        if d == 3:
            axes.append(np.cross(world[:, :, None, :], axes_link[:, None, :, :]).reshape(-1, 9, 3))
        axes = np.concatenate(axes, axis=1)  # (P, A, D)
        gap = np.abs(np.einsum("pad,pd->pa", axes, centers[n, l] - box_center))  # (P, A)
        r_link = np.einsum("pae,pe->pa", np.abs(np.einsum("pad,ped->pae", axes, axes_link)), half[l])  # (P, A)
        r_box = np.einsum("pad,pd->pa", np.abs(axes), box_half)  # (P, A)
        pair_hit = ~np.any(gap > r_link + r_box, axis=1)  # (P,)
        hit = np.zeros(len(Q), dtype=bool)
        np.logical_or.at(hit, n, pair_hit)
        return hit


def refuse_mesh(workspace: Workspace) -> None:
    """A clear error for a checker of boxes handed a mesh workspace, whose obstacles are its triangles."""
    if isinstance(workspace, MeshWorkspace):
        raise ValueError(
            "a mesh workspace's obstacles are its triangles, not its boxes: "
            "use exact_checker(workspace, robot) or MeshChecker"
        )
