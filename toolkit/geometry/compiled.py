"""The compiled exact checker for box worlds: what :func:`toolkit.geometry.collision.exact_checker` returns.

:class:`CompiledChecker` gives the same answers as the python-fcl reference
(:class:`toolkit.geometry.fcl_checker.FCLChecker`; the tests hold it to that and to the
separating-axis reference) for every :class:`~toolkit.geometry.robots.BoxRobot` and every box
workspace, many times faster: the whole check of a configuration runs in one compiled loop
(:mod:`toolkit.geometry.kernels`). This class only turns the robot and the workspace into the
arrays that loop reads.

That speed is the paper's question turned round: prediction pays only where it is cheaper
than an exact check (§V), so a fair comparison needs the fastest exact check there is.

numba compiles the loop on first use (seconds) and keeps it on disk, so later processes load
it; importing this module compiles nothing.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from toolkit.geometry.box_world import BoxWorldChecker, refuse_mesh
from toolkit.geometry.robots import AXES, BoxRobot
from toolkit.geometry.workspace import Workspace

BASE_KINDS = {"point2d": 0, "planar": 1, "free": 2}  # a robot's base kind, as the kernels read it


class Robot(NamedTuple):
    """A :class:`~toolkit.geometry.robots.BoxRobot` as arrays (:func:`robot_arrays`)."""

    lower: np.ndarray  # (dof,) configuration bounds
    upper: np.ndarray  # (dof,)
    base: int  # 0 point2d, 1 planar, 2 free
    base_height: float
    joint_origins: np.ndarray  # (J, 3) in the parent link's frame
    joint_axes: np.ndarray  # (J,) 0, 1, 2 for x, y, z
    link_offsets: np.ndarray  # (L, 3) link box centres in their frames
    half_extents: np.ndarray  # (L, 3), zero-padded in 2D


class World(NamedTuple):
    """A box workspace as arrays, with per grid cell the boxes that touch it (cell ``c``'s boxes are
    ``cell_boxes[cell_first[c]:cell_first[c] + cell_count[c]]``; the cells of ``BoxWorldChecker``)."""

    lower: np.ndarray  # (D,) the region
    upper: np.ndarray  # (D,)
    boxes: np.ndarray  # (K, 2, D) min / max corners
    cell: float  # width of a grid cell
    shape: np.ndarray  # (3,) cells per axis; 1 along a 2D world's third axis
    cell_count: np.ndarray  # (C,)
    cell_first: np.ndarray  # (C,)
    cell_boxes: np.ndarray  # (B,)


class CompiledChecker(BoxWorldChecker):
    """Exact checker compiled with numba: kinematics and separating axes in one loop over configurations.

    Each link is tested against only the obstacle boxes listed in the grid cells that its
    axis-aligned bounds cover, so the cost grows with the links and the obstacles near them,
    not with the workspace.
    """

    def __init__(self, workspace: Workspace, robot: BoxRobot):
        refuse_mesh(workspace)
        super().__init__(workspace, robot)
        self._robot = robot_arrays(robot)
        self._world = world_arrays(self, grow=0.0)
        self._grown: dict[float, World] = {}  # clearances: the world with boxes grown by cap, by cap

    def validity(self, Q: np.ndarray) -> np.ndarray:
        from toolkit.geometry import kernels  # numba loads (or compiles) on first use, not on import

        valid = np.empty(len(Q), dtype=bool)
        kernels.validity(np.ascontiguousarray(Q, dtype=np.float64), self._robot, self._world, valid)
        return valid

    def clearance_bounds(self, Q: np.ndarray, cap: float) -> np.ndarray:
        """The bound of :meth:`BoxWorldChecker.clearance_bounds`, compiled."""
        from toolkit.geometry import kernels

        if cap not in self._grown:
            self._grown[cap] = world_arrays(self, grow=cap)
        clearance = np.empty(len(Q))
        kernels.clearance_bounds(
            np.ascontiguousarray(Q, dtype=np.float64),
            self._robot,
            self._grown[cap],
            int(self.robot.level_links),
            float(cap),
            clearance,
        )
        return clearance


def world_arrays(checker: BoxWorldChecker, grow: float) -> World:
    """A checker's workspace as the kernels read it, its cell lists holding the boxes grown by ``grow``."""
    ws = checker.workspace
    shape = np.ones(3, dtype=np.int64)
    shape[: ws.dim] = checker._shape
    # int32: the grid stays in cache
    lists = checker._box_lists(grow) if grow else checker._lists
    count, first, members = (np.ascontiguousarray(a, dtype=np.int32) for a in lists)
    return World(
        np.array(ws.lower, dtype=np.float64),  # copies: writable arrays, so one compiled version serves all
        np.array(ws.upper, dtype=np.float64),
        np.array(ws.boxes, dtype=np.float64),
        float(checker._cell),
        shape,
        count,
        first,
        members,
    )


def robot_arrays(robot: BoxRobot) -> Robot:
    """A :class:`~toolkit.geometry.robots.BoxRobot` as :func:`toolkit.geometry.kernels.validity` reads it."""
    half = np.zeros((robot.n_links, 3))  # (L, 3): zero-padded in 2D
    half[:, : robot.dim] = robot.half_extents
    return Robot(
        np.array(robot.lower, dtype=np.float64),
        np.array(robot.upper, dtype=np.float64),
        BASE_KINDS[robot.base],
        float(robot.base_height),
        np.array([j.origin for j in robot.joints], dtype=np.float64).reshape(-1, 3),  # (J, 3)
        np.array([AXES[j.axis] for j in robot.joints], dtype=np.int64),  # (J,)
        np.array([link.offset for link in robot.links], dtype=np.float64).reshape(-1, 3),  # (L, 3)
        half,
    )
