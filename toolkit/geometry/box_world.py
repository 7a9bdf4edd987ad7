"""What every exact checker of a box world shares: bounds, region, a voxel prefilter, clearance bounds.

A configuration is valid when it lies within the robot's bounds, every link lies
inside the workspace region, and no link box touches an obstacle box (boxes are
closed sets: touching counts as collision, as in FCL). :class:`BoxWorldChecker` runs the
first two tests and a conservative grid prefilter batched in numpy and leaves the last
one, for the links the prefilter keeps, to a subclass (:mod:`toolkit.geometry.fcl_checker`);
it also lists, per grid cell, the obstacles near it (the compiled checker's broadphase,
:mod:`toolkit.geometry.compiled`) and bounds clearances for the planner's certificates.

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


class BoxWorldChecker(CollisionChecker):
    """Shared exact steps: bounds, region, then a conservative voxel prefilter per link.

    The prefilter marks every cell of a grid that an obstacle touches; cells are at
    least as wide as any link's axis-aligned bounds, so a link's bounds cover at most
    two cells per axis and 2^D look-ups tell whether it may touch an obstacle. The same
    grid lists, per cell, the obstacles that touch it (:meth:`_box_lists`): the only ones a
    link there can touch (the compiled checker's broadphase) or, grown, come near.
    """

    is_exact = True  # every answer is the geometry's

    def __init__(self, workspace: Workspace, robot: BoxRobot):
        if workspace.dim != robot.dim:
            raise ValueError(f"robot {robot.name!r} is {robot.dim}D but the workspace is {workspace.dim}D")
        super().__init__(robot)
        self.workspace = workspace
        self._cell = 2 * float(np.max(np.linalg.norm(robot.half_extents, axis=1)))  # widest link bounds
        self._shape = tuple(np.maximum(np.ceil((workspace.upper - workspace.lower) / self._cell).astype(int), 1) + 1)
        self._lists = self._box_lists(grow=0.0)  # the obstacles of each cell
        self._marked = self._lists[0].reshape(self._shape) > 0  # cells an obstacle touches
        self._near: dict[float, tuple] = {}  # clearances: _box_lists(cap), by cap

    def _box_lists(self, grow: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Per grid cell, the obstacle boxes that touch it once grown by ``grow`` on every side.

        ``count (C,)`` and ``first (C,)`` per flattened cell, ``members (B,)``: cell c's boxes
        are ``members[first[c]:first[c] + count[c]]``.
        """
        from toolkit.geometry import kernels  # numba loads (or compiles) on first use, not on import

        boxes, dim = self.workspace.boxes, self.workspace.dim  # (K, 2, D)
        lo, hi = np.zeros((2, len(boxes), 3), dtype=np.int64)  # first and last cell per axis, (K, 3) each
        lo[:, :dim], hi[:, :dim] = self._cells(boxes[:, 0] - grow), self._cells(boxes[:, 1] + grow)
        shape = np.ones(3, dtype=np.int64)  # a 2D grid: one cell along the third axis
        shape[:dim] = self._shape
        return kernels.cell_lists(lo, hi, shape)

    def _cells(self, points: np.ndarray) -> np.ndarray:
        """Integer cell index of each point ``(..., D)``, clipped to the grid."""
        index = np.floor((points - self.workspace.lower) / self._cell).astype(int)
        return np.clip(index, 0, np.array(self._shape) - 1)

    def _covered_cells(self, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
        """``(2^D, M)`` flat indices of the cells that bounds ``lo, hi (M, D)`` cover (repeats where
        they span one cell).

        Bounds are no wider than a cell, so they cover at most two cells per axis: their 2^D corners' cells.
        """
        lo, hi = self._cells(lo), self._cells(hi)  # (M, D) each
        return np.stack(
            [
                np.ravel_multi_index(tuple(np.where(np.array(corner, dtype=bool), hi, lo).T), self._shape)
                for corner in np.ndindex(*(2,) * self.robot.dim)
            ]
        )

    def validity(self, Q: np.ndarray) -> np.ndarray:
        valid = self.robot.in_bounds(Q)  # (N,)
        idx = np.flatnonzero(valid)
        aabbs = self.robot.link_aabbs(Q[idx])  # (n, L, 2, D)
        inside = np.all(
            (aabbs[:, :, 0] >= self.workspace.lower) & (aabbs[:, :, 1] <= self.workspace.upper), axis=(1, 2)
        )
        valid[idx[~inside]] = False
        idx, aabbs = idx[inside], aabbs[inside]
        cells = self._covered_cells(
            aabbs[:, :, 0].reshape(-1, self.robot.dim), aabbs[:, :, 1].reshape(-1, self.robot.dim)
        )
        candidates = self._marked.reshape(-1)[cells].any(axis=0).reshape(aabbs.shape[:2])  # (n, L): may touch a block
        valid[idx[self._links_collide(Q[idx], aabbs, candidates)]] = False
        return valid

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
        if cap not in self._near:
            self._near[cap] = self._box_lists(grow=cap)
        count, first, members = self._near[cap]
        cell = self._covered_cells(lo, hi).reshape(-1)  # (2^D * n * L,)
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

    def _links_collide(self, Q: np.ndarray, aabbs: np.ndarray, candidates: np.ndarray) -> np.ndarray:
        """(n,) whether any link of each configuration meets an obstacle; ``candidates (n, L)`` may."""
        raise NotImplementedError


class PointRobotChecker(BoxWorldChecker):
    """Exact numpy check for the 2D point robot.

    Its square never turns, so its configuration-space obstacles are the blocks grown
    by its half extents (a Minkowski sum of boxes is a box), and the free region is the
    workspace shrunk by the same amount: four comparisons per block on contiguous arrays.
    A check is then cheaper than a clearance bound: certificates do not pay.
    """

    certificates_pay = False

    def __init__(self, workspace: Workspace, robot: BoxRobot):
        if robot.base != "point2d" or robot.dof != 2:
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


class SeparatingAxisChecker(BoxWorldChecker):
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
