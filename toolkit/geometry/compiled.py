"""The compiled exact checker for box worlds: what :func:`toolkit.geometry.collision.exact_checker` returns.

:class:`CompiledChecker` gives the same answers as the python-fcl reference
(:class:`toolkit.geometry.fcl_checker.FCLChecker`; the tests hold it to that and to the
separating-axis reference) for every :class:`~toolkit.geometry.robots.BoxRobot` and every box
workspace, many times faster: the whole check of a configuration runs in one compiled loop
(:mod:`toolkit.geometry.block_kernels`). This class only turns the robot and the workspace into the
arrays that loop reads.

That speed is the paper's question turned round: prediction pays only where it is cheaper
than an exact check (§V), so a fair comparison needs the fastest exact check there is.

numba compiles the loop on first use (seconds) and keeps it on disk, so later processes load
it; importing this module compiles nothing.
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np

from toolkit.geometry.box_world import BoxGrid, BoxWorldChecker, refuse_mesh
from toolkit.geometry.robots import AXES, BASE_KINDS, BoxRobot
from toolkit.geometry.workspace import Workspace

FAR_CELL = 1.5  # the far bits' cells: this many times the smallest link ball's radius wide
FAR_CELLS = 128  # or a 128th of the region's longest axis, if wider
NDARRAY = np.ndarray  # what a planner passes (one name to look up, not two, in a call's few tests)
FLOAT64 = np.dtype(np.float64)  # the dtype of configurations the compiled loop takes as they are
BOOL = np.dtype(np.bool_)  # its answers'
EMPTY = np.empty  # one name to look up in a call, not two


ENTRY_POINTS: dict[tuple, Any] = {}  # compiled versions of the kernels, by name and arguments' layout (entry_point)


def layout(value) -> object:
    """What numba's type of an argument depends on: an array's dtype, dimensions, order and writability; a named
    tuple's class and its fields' layouts; else the Python type. Arguments laid out alike share a compiled version."""
    if isinstance(value, np.ndarray):
        flags = value.flags
        return value.dtype.str, value.ndim, flags.c_contiguous, flags.f_contiguous, flags.writeable, flags.aligned
    if isinstance(value, tuple):
        return type(value), *map(layout, value)
    return type(value)


class Robot(NamedTuple):
    """A :class:`~toolkit.geometry.robots.BoxRobot` as arrays (:func:`robot_arrays`)."""

    lower: np.ndarray  # (dof,) configuration bounds
    upper: np.ndarray  # (dof,)
    base: int  # the base's kind: its number in robots.BASE_KINDS (frame_kernels.POINT2D, PLANAR, FREE)
    base_height: float
    joint_origins: np.ndarray  # (J, 3) in the parent link's frame
    joint_axes: np.ndarray  # (J,) 0, 1, 2 for x, y, z
    link_offsets: np.ndarray  # (L, 3) link box centres in their frames
    half_extents: np.ndarray  # (L, 3), zero-padded in 2D


class Far(NamedTuple):
    """Per link ball and cell of a grid over the region, one bit: whether the ball, centred anywhere in the cell,
    lies in the region and misses every obstacle (:func:`far_bits`)."""

    lower: np.ndarray  # (3,) the grid's corner
    cell: float  # width of a cell
    shape: np.ndarray  # (3,) cells per axis
    bits: np.ndarray  # (B, W) uint64 per ball size: bit c % 64 of word c // 64 is cell c's
    link_ball: np.ndarray  # (L,) each link's ball size: its row of bits


class World(NamedTuple):
    """A box workspace as arrays, with per grid cell the boxes that touch it, grown by some distance
    (:func:`world_arrays`; cell ``c``'s boxes are ``cell_boxes[cell_first[c]:cell_first[c] + cell_count[c]]``; the
    cells of a ``BoxGrid``)."""

    lower: np.ndarray  # (D,) the region
    upper: np.ndarray  # (D,)
    boxes: np.ndarray  # (K, 2, D) min / max corners
    cell: float  # width of a grid cell
    shape: np.ndarray  # (3,) cells per axis; 1 along a 2D world's third axis
    cell_count: np.ndarray  # (C,)
    cell_first: np.ndarray  # (C,)
    cell_boxes: np.ndarray  # (B,)
    far: Far | None = None  # the validity loop's first test of a link; a mesh's parts and clearances need none


class CompiledChecker(BoxWorldChecker):
    """Exact checker compiled with numba: kinematics and separating axes in one loop over configurations.

    Each link is tested against only the obstacle boxes listed in the grid cell that holds its
    centre (boxes within the largest link ball's radius of the cell), so the cost grows with the
    links and the obstacles near them, not with the workspace.
    """

    def __init__(self, workspace: Workspace, robot: BoxRobot):
        refuse_mesh(workspace)
        super().__init__(workspace, robot)
        self._robot = robot_arrays(robot)
        # validity lists per cell the boxes within a link ball's radius of it: the only ones a link centred there meets
        reach = float(np.max(np.linalg.norm(robot.half_extents, axis=1))) * (1 + 1e-9)
        self._world = world_arrays(self.grid, grow=reach)._replace(far=far_grid(workspace, robot))
        self._validity: Any = not_compiled  # the compiled kernel for these arrays, once known (entry_point)
        self._clearance: Any = None  # likewise
        self._arrays: Any = None  # the robot's and the world's arrays in one object (block_kernels.Arrays), once made
        self._address, self._kind = 0, None  # where it lies and its numba type, as the kernel takes it (validity_at)
        self._grown: dict[float, World] = {}  # clearances: the world with boxes grown by cap, by cap

    def are_valid(self, Q):
        """:meth:`CollisionChecker.are_valid`; what a planner passes, a float64 array ``(N, dof)`` in C order, goes
        straight to the compiled loop, which also checks its columns, its order and that every number is finite
        (where not, the reference's path gives the same error as ever, or, in another order, a copy the answers):
        a call of 32 configurations then costs little more than checking them. Each test here costs about as much as
        checking a configuration, so there are few; the checker's arrays go as an address (``validity_at``)."""
        if type(Q) is NDARRAY and Q.dtype is FLOAT64 and Q.ndim == 2:  # the loop tests the order
            valid = EMPTY(len(Q), BOOL)
            if self._validity(Q, self._address, valid, self._kind):  # False until compiled: the path below compiles
                self.n_checked += len(valid)
                return valid
        return super().are_valid(Q)

    def validity(self, Q: np.ndarray) -> np.ndarray:
        Q, valid = np.ascontiguousarray(Q, dtype=np.float64), np.empty(len(Q), dtype=bool)
        if self._validity is not not_compiled and Q.flags.writeable:  # the compiled version: no dispatch, no import
            self._validity(Q, self._address, valid, self._kind)
            return valid
        from numba import typeof

        from toolkit.geometry import block_kernels  # numba loads (or compiles) on first use, not on import

        if self._arrays is None:
            self._arrays = block_kernels.arrays(self._robot, self._world)
            self._address, self._kind = block_kernels.address(self._arrays), typeof(self._arrays)
        args = (Q, self._address, valid, self._kind)
        block_kernels.validity_at(*args)
        if Q.flags.writeable:
            self._validity = entry_point(block_kernels.validity_at, args)
        return valid

    def __getstate__(self) -> dict:
        # a compiled function, and where the arrays lie, do not pickle: the copy looks them up again
        return self.__dict__ | dict(_validity=not_compiled, _clearance=None, _arrays=None, _address=0, _kind=None)

    def clearance_bounds(self, Q: np.ndarray, cap: float) -> np.ndarray:
        """The bound of :meth:`BoxWorldChecker.clearance_bounds`, compiled."""
        from toolkit.geometry import kernels

        if cap not in self._grown:
            self._grown[cap] = world_arrays(self.grid, grow=cap)
        Q, clearance = np.ascontiguousarray(Q, dtype=np.float64), np.empty(len(Q))
        args = (Q, self._robot, self._grown[cap], int(self.robot.level_links), float(cap), clearance)
        if self._clearance is not None and Q.flags.writeable:
            self._clearance(*args)
        else:
            kernels.clearance_bounds(*args)
            if Q.flags.writeable:
                self._clearance = entry_point(kernels.clearance_bounds, args)
        return clearance


def not_compiled(Q, address, valid, kind) -> bool:
    """What a checker calls before its kernel is compiled: False, "not checked", so it takes the path that compiles."""
    return False


def entry_point(kernel, args: tuple):
    """The compiled version of ``kernel`` (a numba function, already called with ``args``) for ``args``' types.

    numba's dispatcher picks it by the arguments' types at every call (3 us, as long as 30 configurations take;
    more for named tuples); a checker calls it directly instead. Asking numba's ``typeof`` costs about 100 us, so
    the versions are kept by the arguments' :func:`layout`, which decides their types: one lookup a process."""
    key = (kernel.__name__, layout(args))
    if key not in ENTRY_POINTS:
        from numba import typeof

        ENTRY_POINTS[key] = kernel.overloads[tuple(typeof(a) for a in args)].entry_point
    return ENTRY_POINTS[key]


def world_arrays(grid: BoxGrid, grow: float) -> World:
    """A checker's grid and workspace as the kernels read them, its cell lists holding the boxes grown by ``grow``."""
    ws = grid.workspace
    shape = np.ones(3, dtype=np.int64)
    shape[: ws.dim] = grid.shape
    # int32: the grid stays in cache
    count, first, members = (np.ascontiguousarray(a, dtype=np.int32) for a in grid.box_lists(grow))
    return World(
        np.array(ws.lower, dtype=np.float64),  # copies: writable arrays, so one compiled version serves all
        np.array(ws.upper, dtype=np.float64),
        np.array(ws.boxes, dtype=np.float64),
        float(grid.cell),
        shape,
        count,
        first,
        members,
    )


def far_grid(ws: Workspace, robot: BoxRobot) -> Far:
    """The far bits of a box workspace for ``robot``'s links, on a grid of cells as wide as its smallest link ball's
    radius (at most ``FAR_CELLS`` along an axis)."""
    lower, upper, boxes = (np.zeros(3), np.zeros(3), np.zeros((len(ws.boxes), 2, 3)))  # 2D: a third axis of width 0
    lower[: ws.dim], upper[: ws.dim], boxes[..., : ws.dim] = ws.lower, ws.upper, ws.boxes
    radii, link_ball = np.unique(np.linalg.norm(robot.half_extents, axis=1), return_inverse=True)  # (B,), (L,)
    cell = max(float(radii.min()) * FAR_CELL, float(np.max(upper - lower)) / FAR_CELLS)
    shape = np.ones(3, dtype=np.int64)
    shape[: ws.dim] = np.ceil((upper - lower)[: ws.dim] / cell).astype(np.int64) + 1
    bits = far_bits(boxes, lower, upper, cell, shape, radii, ws.dim)
    return Far(lower, cell, shape, bits, link_ball.astype(np.int64))


def far_bits(
    obstacles: np.ndarray, lower: np.ndarray, upper: np.ndarray, cell: float, shape: np.ndarray, radii, dim: int = 3
) -> np.ndarray:
    """``(B, W)`` per ball radius ``radii (B,)``, the cells of a grid (``lower (3,)``, ``cell``, ``shape (3,)``, over
    the region ``lower`` to ``upper``, its first ``dim`` axes walled) as bits: 1 where the ball round any point of
    the cell lies in the region and farther than its radius from every box of ``obstacles (K, 2, 3)``. Then so does
    a link box that the ball holds, and the box's axis-aligned bounds (no wider than the ball along any axis)."""
    from toolkit.geometry import far_kernels  # numba loads (or compiles) on first use, not on import

    margin = 1e-9 * float(np.max(upper - lower))  # above rounding in the cell a centre falls in
    thresholds = np.asarray(radii, dtype=np.float64) + margin  # (B,)
    limits = np.array([square_limit(t) for t in thresholds])  # (B,)
    boxes = np.ascontiguousarray(obstacles, dtype=np.float64)
    shape = np.ascontiguousarray(shape, dtype=np.int64)
    return far_kernels.far_bits(boxes, lower, upper, float(cell), shape, thresholds, limits, dim)  # (B, W) uint64


def square_limit(threshold: float) -> float:
    """The largest float whose square root is at most ``threshold``: a distance computed as ``sqrt(gap)`` exceeds
    ``threshold`` exactly where ``gap`` exceeds it, so the far bits compare squares and take no roots."""
    limit = threshold * threshold
    while math.sqrt(limit) > threshold:
        limit = math.nextafter(limit, -math.inf)
    while math.sqrt(math.nextafter(limit, math.inf)) <= threshold:
        limit = math.nextafter(limit, math.inf)
    return limit


def robot_arrays(robot: BoxRobot) -> Robot:
    """A :class:`~toolkit.geometry.robots.BoxRobot` as :func:`toolkit.geometry.block_kernels.validity` reads it."""
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
