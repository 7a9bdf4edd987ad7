"""Collision checking: one interface, exact implementations (paper §II-B's "black box").

As in OMPL's ``StateValidityChecker``, everything that needs validity asks a
:class:`CollisionChecker` for whole batches: ``are_valid(Q (N, dof)) -> (N,) bool``.
The exact checkers here and the learned one (:mod:`toolkit.learned`) share it, so
planning with or without prediction differs in one argument.

A configuration is valid when it lies within the robot's bounds, every link lies
inside the workspace region, and no link box touches an obstacle box (boxes are
closed sets: touching counts as collision, as in FCL).

- :class:`ExactChecker`: python-fcl, the ground truth. Kinematics and a
  conservative axis-aligned prefilter run batched in numpy; only links whose
  bounds meet an obstacle's are handed to FCL's ``DynamicAABBTreeCollisionManager``.
- :class:`PointRobotChecker`: the 2D point robot is an axis-aligned square, so an
  interval test against every block is exact; vectorized numpy.
- :class:`SeparatingAxisChecker`: an independent reference for tests, the
  separating-axis theorem for oriented vs axis-aligned boxes, vectorized numpy.
"""

from __future__ import annotations

import fcl
import numpy as np

from .robots import BoxRobot
from .workspace import Workspace


class CollisionChecker:
    """Answers "is this configuration valid?" for batches; counts configurations checked.

    ``few_calls``: a call's fixed cost outweighs its cost per configuration (a neural
    network on CPU): callers then ask about configurations they may not need in one
    call rather than in several dependent ones (same answers, fewer calls).
    """

    few_calls = False

    def __init__(self, robot: BoxRobot):
        self.robot = robot
        self.n_checked = 0  # configurations asked about since construction or reset_count()

    def are_valid(self, Q) -> np.ndarray:
        """``(N,)`` bool: whether each configuration of ``Q (N, dof)`` is valid."""
        Q = self.robot.check_configs(Q)
        self.n_checked += len(Q)
        return self._are_valid(Q)

    def is_valid(self, q) -> bool:
        """Whether the single configuration ``q (dof,)`` is valid."""
        q = np.asarray(q, dtype=float)
        if q.ndim != 1:
            raise ValueError(f"q must have shape ({self.robot.dof},), got {q.shape}")
        return bool(self.are_valid(q[None])[0])

    def reset_count(self) -> None:
        self.n_checked = 0

    def _are_valid(self, Q: np.ndarray) -> np.ndarray:
        raise NotImplementedError


class _BoxWorldChecker(CollisionChecker):
    """Shared exact steps: bounds, region, then a conservative voxel prefilter per link.

    The prefilter marks every cell of a grid that an obstacle touches; cells are at
    least as wide as any link's axis-aligned bounds, so a link's bounds cover at most
    two cells per axis and 2^D look-ups tell whether it may touch an obstacle.
    """

    def __init__(self, workspace: Workspace, robot: BoxRobot):
        if workspace.dim != robot.dim:
            raise ValueError(f"robot {robot.name!r} is {robot.dim}D but the workspace is {workspace.dim}D")
        super().__init__(robot)
        self.workspace = workspace
        self._cell = 2 * float(np.max(np.linalg.norm(robot.half_extents, axis=1)))  # widest link bounds
        shape = np.maximum(np.ceil((workspace.upper - workspace.lower) / self._cell).astype(int), 1) + 1
        self._marked = np.zeros(tuple(shape), dtype=bool)
        lo_cells, hi_cells = self._cells(workspace.boxes[:, 0]), self._cells(workspace.boxes[:, 1])
        for lo, hi in zip(lo_cells, hi_cells):
            self._marked[tuple(slice(a, b + 1) for a, b in zip(lo, hi))] = True

    def _cells(self, points: np.ndarray) -> np.ndarray:
        """Integer cell index of each point ``(..., D)``, clipped to the grid."""
        index = np.floor((points - self.workspace.lower) / self._cell).astype(int)
        return np.clip(index, 0, np.array(self._marked.shape) - 1)

    def _are_valid(self, Q: np.ndarray) -> np.ndarray:
        valid = self.robot.in_bounds(Q)  # (N,)
        idx = np.flatnonzero(valid)
        aabbs = self.robot.link_aabbs(Q[idx])  # (n, L, 2, D)
        inside = np.all((aabbs[:, :, 0] >= self.workspace.lower) & (aabbs[:, :, 1] <= self.workspace.upper), axis=(1, 2))
        valid[idx[~inside]] = False
        idx, aabbs = idx[inside], aabbs[inside]
        lo, hi = self._cells(aabbs[:, :, 0]), self._cells(aabbs[:, :, 1])  # (n, L, D) each
        candidates = np.zeros(lo.shape[:2], dtype=bool)  # (n, L): links that may touch an obstacle
        for corner in np.ndindex(*(2,) * self.robot.dim):
            cell = np.where(np.array(corner, dtype=bool), hi, lo)  # (n, L, D)
            candidates |= self._marked[tuple(np.moveaxis(cell, -1, 0))]
        valid[idx[self._links_collide(Q[idx], aabbs, candidates)]] = False
        return valid

    def _links_collide(self, Q: np.ndarray, aabbs: np.ndarray, candidates: np.ndarray) -> np.ndarray:
        """(n,) whether any link of each configuration meets an obstacle; ``candidates (n, L)`` may."""
        raise NotImplementedError


class ExactChecker(_BoxWorldChecker):
    """Ground truth with python-fcl: obstacles in a ``DynamicAABBTreeCollisionManager``."""

    def __init__(self, workspace: Workspace, robot: BoxRobot):
        super().__init__(workspace, robot)
        self._world = fcl.DynamicAABBTreeCollisionManager()
        self._world.registerObjects([_fcl_box(lo, hi) for lo, hi in workspace.boxes])
        self._world.setup()
        half3 = np.array([link.half_extents for link in robot.links], dtype=float)  # (L, 3)
        if robot.dim == 2:  # FCL is 3D: the square becomes a unit-thick slab inside the plane's slab
            half3[:, 2] = 0.5
        self._links = [fcl.CollisionObject(fcl.Box(*(2 * h))) for h in half3]

    def _links_collide(self, Q, aabbs, candidates):
        if not candidates.any():
            return np.zeros(len(Q), dtype=bool)
        some = np.flatnonzero(candidates.any(axis=1))  # kinematics only where FCL will be asked
        hit = np.zeros(len(Q), dtype=bool)
        centers, rotations, _ = self.robot.link_boxes(Q[some])
        if self.robot.dim == 2:  # lift to 3D: obstacles become slabs z in [-1, 1]
            centers = np.concatenate([centers, np.zeros(centers.shape[:2] + (1,))], axis=-1)
            eye = np.broadcast_to(np.eye(3), rotations.shape[:2] + (3, 3)).copy()
            eye[..., :2, :2] = rotations
            rotations = eye
        request = fcl.CollisionRequest()
        for i, l in zip(*np.nonzero(candidates[some])):
            if hit[some[i]]:
                continue
            link = self._links[l]
            link.setTransform(fcl.Transform(rotations[i, l], centers[i, l]))
            data = fcl.CollisionData(request=request)
            self._world.collide(link, data, _first_contact)
            hit[some[i]] = data.result.is_collision
        return hit


def _first_contact(o1, o2, data) -> bool:
    """Broadphase callback: test one candidate pair, and stop the search at the first contact.

    (FCL's default callback never sets ``done`` for a default request, so it would test
    every overlapping pair after a hit.)
    """
    if not data.done:
        data.done = fcl.collide(o1, o2, data.request, data.result) > 0
    return data.done


def _fcl_box(lo: np.ndarray, hi: np.ndarray) -> fcl.CollisionObject:
    lo3, hi3 = np.zeros(3) - 1.0, np.zeros(3) + 1.0  # 2D boxes: slabs z in [-1, 1]
    lo3[: len(lo)], hi3[: len(hi)] = lo, hi
    return fcl.CollisionObject(fcl.Box(*(hi3 - lo3)), fcl.Transform((lo3 + hi3) / 2))


class PointRobotChecker(_BoxWorldChecker):
    """Exact numpy check for the 2D point robot.

    Its square never turns, so its configuration-space obstacles are the blocks grown
    by its half extents (a Minkowski sum of boxes is a box), and the free region is the
    workspace shrunk by the same amount: four comparisons per block on contiguous arrays.
    """

    def __init__(self, workspace: Workspace, robot: BoxRobot):
        if robot.base != "point2d" or robot.dof != 2:
            raise ValueError(f"PointRobotChecker needs the 2D point robot, got {robot.name!r}")
        super().__init__(workspace, robot)
        half = robot.half_extents[0]  # (2,)
        self._free_lo = np.maximum(robot.lower, workspace.lower + half)  # (2,)
        self._free_hi = np.minimum(robot.upper, workspace.upper - half)  # (2,)
        self._c_obstacles = np.stack([workspace.boxes[:, 0] - half, workspace.boxes[:, 1] + half], axis=1)  # (K, 2, 2)

    def _are_valid(self, Q: np.ndarray) -> np.ndarray:
        x, y = np.ascontiguousarray(Q[:, 0]), np.ascontiguousarray(Q[:, 1])  # (N,) each
        (x_lo, y_lo), (x_hi, y_hi) = self._free_lo, self._free_hi
        valid = (x >= x_lo) & (x <= x_hi) & (y >= y_lo) & (y <= y_hi)
        for (bx_lo, by_lo), (bx_hi, by_hi) in self._c_obstacles:  # a handful of blocks: loop over K, never N
            valid &= ~((x >= bx_lo) & (x <= bx_hi) & (y >= by_lo) & (y <= by_hi))
        return valid


class SeparatingAxisChecker(_BoxWorldChecker):
    """Reference: separating-axis test of every candidate (link, obstacle) pair, vectorized.

    Two convex boxes are disjoint iff some axis separates their projections
    (Gottschalk et al., OBBTree, 1996): in 3D the 3 world axes, the link's 3 axes and
    their 9 cross products; in 2D the 2 world axes and the link's 2 axes.
    """

    def _links_collide(self, Q, aabbs, candidates):
        """Ignores the voxel prefilter: every (link, obstacle) pair whose bounds meet is tested."""
        boxes = self.workspace.boxes  # (K, 2, D)
        near = np.all((aabbs[:, :, None, 0] <= boxes[:, 1]) & (aabbs[:, :, None, 1] >= boxes[:, 0]), axis=-1)  # (n, L, K)
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


def exact_checker(workspace: Workspace, robot: BoxRobot) -> CollisionChecker:
    """The fastest exact checker for this robot: numpy for the 2D point robot, FCL otherwise."""
    if robot.base == "point2d":
        return PointRobotChecker(workspace, robot)
    return ExactChecker(workspace, robot)
