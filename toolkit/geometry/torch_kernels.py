"""The compiled exact check in torch, vectorised over configurations: the same answers on a CPU or a GPU.

:mod:`toolkit.geometry.kernels` takes one configuration at a time through every step in
registers. A GPU wants the opposite: every configuration at once, one step at a time, each
step one array operation. This module is that port, step for step and formula for formula:

1. bounds: ``lower <= q <= upper``;
2. forward kinematics of the box chain, a link's rotation kept as its three columns
   (``frame_kernels.link_frames``: the same turns, the same sums in the same order);
3. per link, its axis-aligned bounds, which must lie inside the region, and the grid cells
   they cover: at most two per axis, since a cell is wider than any link's bounds;
4. the obstacle boxes listed in those cells (a table, one row of box numbers per cell) make
   the candidate (configuration, link, box) triples; the few that exist are gathered into
   one list (``nonzero``) and each tested with the separating-axis theorem (Gottschalk et
   al., OBBTree, 1996) on the world's axes, the link's and, in 3D, their 9 cross products,
   exactly as ``kernels.boxes_touch`` does. Touching projections do not separate: boxes are
   closed, as in FCL.

**Why torch** (not numba.cuda or Triton): torch is already a dependency and runs this very
code on the CPU, so the tests in CI hold the code path a GPU runs to the compiled kernel and
to FCL; numba's CUDA simulator runs a different, interpreted path, and Triton is not
installed where the toolkit is (nor can a GPU session install it).

**Why float64, and why it is exact.** The compiled kernel and FCL compute in float64; so does
this port, with the same formulas, so its answers differ from theirs only where a contact is
decided by the last bits of rounding (a distance within about 1e-15 of zero). A float32
configuration is widened without loss. float32 would move every distance by about 1e-6 at
the scenarios' sizes (coordinates up to 41), enough to turn near-contact answers. A data-centre
GPU (H100, H200) computes float64 at half its float32 rate; this check is bound by memory
traffic and by the gather, not by arithmetic.

The grid here is a hair wider than :class:`~toolkit.geometry.box_world.BoxGrid`'s
(by a factor ``1 + 1e-6``): with exactly the widest link's width, a link's bounds rounded one ulp
wider could cover three cells along an axis. Any grid gives the same answers: a box whose
bounds meet a link's shares a cell with it, whatever the cells' width.
"""

from __future__ import annotations

import itertools
from typing import NamedTuple

import numpy as np
import torch

from toolkit.geometry.box_world import BoxWorldChecker, refuse_mesh
from toolkit.geometry.device import Stager
from toolkit.geometry.robots import AXES, BoxRobot
from toolkit.geometry.workspace import Workspace

WIDER = 1 + 1e-6  # this grid's cells over the widest link bounds (the module's docstring says why)


class Robot(NamedTuple):
    """A :class:`~toolkit.geometry.robots.BoxRobot` as float64 tensors on one device (:func:`robot_tensors`)."""

    lower: torch.Tensor  # (dof,) configuration bounds
    upper: torch.Tensor  # (dof,)
    base: str  # the base's kind, a key of robots.BASES
    base_height: float
    joint_origins: list[tuple[float, float, float]]  # (J, 3) in the parent link's frame
    joint_axes: list[int]  # (J,) 0, 1, 2 for x, y, z
    link_offsets: list[tuple[float, float, float]]  # (L, 3) link box centres in their frames
    half_extents: list[tuple[float, float, float]]  # (L, 3), zero-padded in 2D
    half: torch.Tensor  # (L, D) the half extents as a float64 tensor


class World(NamedTuple):
    """A box workspace as tensors on one device: the region, the boxes, and per grid cell the boxes listed there."""

    lower: torch.Tensor  # (D,) the region
    upper: torch.Tensor  # (D,)
    boxes: torch.Tensor  # (K, 2, D) min / max corners
    cell: float  # width of a grid cell
    shape: torch.Tensor  # (D,) cells per axis, int64
    strides: torch.Tensor  # (D,) a cell's flat index is (cell index * strides).sum()
    table: torch.Tensor  # (C, M) int64: the boxes listed in each flat cell, padded with -1
    picks: torch.Tensor  # (2^D, D) bool: per corner of a link's bounds, which axes take the last cell


def robot_tensors(robot: BoxRobot, device: torch.device | str = "cpu") -> Robot:
    """A robot as :func:`validity` reads it: bounds as float64 tensors on ``device``, the chain's constants as
    Python numbers (each enters one operation on whole batches)."""
    half = np.zeros((robot.n_links, 3))  # (L, 3)
    half[:, : robot.dim] = robot.half_extents

    def rows(array) -> list:
        return [tuple(float(x) for x in row) for row in np.asarray(array, dtype=np.float64).reshape(-1, 3)]

    return Robot(
        torch.tensor(robot.lower, dtype=torch.float64, device=device),
        torch.tensor(robot.upper, dtype=torch.float64, device=device),
        robot.base,
        float(robot.base_height),
        rows([j.origin for j in robot.joints]),
        [AXES[j.axis] for j in robot.joints],
        rows([link.offset for link in robot.links]),
        rows(half),
        torch.tensor(half[:, : robot.dim], dtype=torch.float64, device=device),
    )


def world_tensors(workspace: Workspace, robot: BoxRobot, device: torch.device | str = "cpu") -> World:
    """A box workspace as :func:`validity` reads it: its grid's cells ``WIDER`` than the widest link's bounds,
    each listing the boxes whose bounds' cells cover it (``kernels.cell_lists``)."""
    from toolkit.geometry import kernels  # numba loads (or compiles) on first use, not on import

    dim, boxes = workspace.dim, np.asarray(workspace.boxes, dtype=np.float64)  # (K, 2, D)
    cell = WIDER * 2 * float(np.max(np.linalg.norm(robot.half_extents, axis=1)))
    shape = np.ones(3, dtype=np.int64)  # a 2D grid: one cell along the third axis
    shape[:dim] = np.maximum(np.ceil((workspace.upper - workspace.lower) / cell).astype(np.int64), 1) + 1
    lo, hi = np.zeros((2, len(boxes), 3), dtype=np.int64)  # first and last cell of each box, per axis
    for corners, end in ((lo, 0), (hi, 1)):
        index = np.floor((boxes[:, end] - workspace.lower) / cell).astype(np.int64)
        corners[:, :dim] = np.clip(index, 0, shape[:dim] - 1)
    count, first, members = kernels.cell_lists(lo, hi, shape)
    table = np.full((len(count), max(int(count.max(initial=0)), 1)), -1, dtype=np.int64)  # (C, M)
    for m in range(table.shape[1]):
        has = count > m
        table[has, m] = members[first[has] + m]
    strides = np.array([shape[1] * shape[2], shape[2], 1])[:dim]

    def tensor(array, dtype=torch.float64):
        return torch.as_tensor(np.array(array), dtype=dtype, device=device)  # a writable copy

    return World(
        tensor(workspace.lower),
        tensor(workspace.upper),
        tensor(boxes),
        cell,
        tensor(shape[:dim], torch.int64),
        tensor(strides, torch.int64),
        tensor(table, torch.int64),
        tensor(list(itertools.product((False, True), repeat=dim)), torch.bool),
    )


def _turn(columns: list[torch.Tensor], axis: int, angle: torch.Tensor) -> None:
    """Rotate the frame whose ``columns`` (3 x ``(N, 3)``) are its axes about its own axis ``axis`` by ``angle
    (N,)``, in place (``frame_kernels._turn``)."""
    c, s = torch.cos(angle)[:, None], torch.sin(angle)[:, None]  # (N, 1) each
    j, k = (axis + 1) % 3, (axis + 2) % 3  # the plane it turns, in right-handed order
    a, b = columns[j], columns[k]
    columns[j], columns[k] = a * c + b * s, b * c - a * s


def _moved(position: torch.Tensor, columns: list[torch.Tensor], offset: tuple[float, float, float]) -> torch.Tensor:
    """``position + rotation @ offset`` ``(N, 3)``, summed in ``frame_kernels.link_frames``' order."""
    for j in range(3):
        if offset[j] != 0.0:  # adding 0 * x is adding 0: the same number
            position = position + columns[j] * offset[j]
    return position


def link_frames(Q: torch.Tensor, robot: Robot) -> tuple[torch.Tensor, torch.Tensor]:
    """Centres ``(N, L, 3)`` and rotations ``(N, L, 3, 3)`` (columns: the link's axes) of every link for
    configurations ``Q (N, dof)`` float64 (:meth:`toolkit.geometry.robots.BoxRobot.link_boxes`)."""
    n = len(Q)
    position = torch.zeros((n, 3), dtype=Q.dtype, device=Q.device)
    columns = [torch.zeros_like(position) for _ in range(3)]
    for i in range(3):
        columns[i][:, i] = 1.0
    if robot.base == "point2d":
        position[:, :2], first_joint = Q[:, :2], 2
    elif robot.base == "planar":  # x, y, yaw on the floor
        position[:, :2], position[:, 2], first_joint = Q[:, :2], robot.base_height, 3
        _turn(columns, 2, Q[:, 2])
    else:  # free: x, y, z, then Z-Y-X Euler angles
        position[:], first_joint = Q[:, :3], 6
        _turn(columns, 2, Q[:, 3])
        _turn(columns, 1, Q[:, 4])
        _turn(columns, 0, Q[:, 5])
    centers, rotations = [], []
    for link, offset in enumerate(robot.link_offsets):
        if link > 0:  # joint link - 1 carries this link
            position = _moved(position, columns, robot.joint_origins[link - 1])
            _turn(columns, robot.joint_axes[link - 1], Q[:, first_joint + link - 1])
        centers.append(_moved(position, columns, offset))
        rotations.append(torch.stack(columns, dim=-1))  # (N, 3, 3)
    return torch.stack(centers, dim=1), torch.stack(rotations, dim=1)


def validity(Q: torch.Tensor, robot: Robot, world: World) -> torch.Tensor:
    """``(N,)`` bool: whether each configuration of ``Q (N, dof)`` (float64, on the tensors' device) is valid,
    by the steps of the module's docstring."""
    dim = len(world.lower)
    valid = ((Q >= robot.lower) & (Q <= robot.upper)).all(dim=1)  # (N,)
    centers, rotations = link_frames(Q, robot)  # (N, L, 3), (N, L, 3, 3)
    centers, rotations = centers[..., :dim], rotations[..., :dim, :dim]
    half, picks = robot.half, world.picks  # (L, D), (2^D, D)
    reach = torch.zeros_like(centers)  # (N, L, D): sum_j |R_ij| half_j, in kernels.link_bounds' order
    for j in range(dim):
        reach = reach + rotations[..., j].abs() * half[:, j, None]
    low, high = centers - reach, centers + reach  # (N, L, D) each
    valid &= ((low >= world.lower) & (high <= world.upper)).all(dim=2).all(dim=1)
    first, last = (torch.floor((x - world.lower) / world.cell).long().clamp(min=0) for x in (low, high))
    first, last = torch.minimum(first, world.shape - 1), torch.minimum(last, world.shape - 1)  # (N, L, D)
    corner = torch.where(picks, last[:, :, None], first[:, :, None])  # (N, L, 2^D, D): the cells of the corners
    wanted = ((last > first)[:, :, None] | ~picks).all(-1) & valid[:, None, None]  # (N, L, 2^D): each cell once
    listed = world.table[(corner * world.strides).sum(-1)]  # (N, L, 2^D, M): the boxes listed there, -1 for none
    n, link, slot = torch.nonzero(((listed >= 0) & wanted[..., None]).flatten(2), as_tuple=True)  # candidates
    listed = listed.flatten(2)  # (N, L, 2^D * M)
    box = world.boxes[listed[n, link, slot]]  # (P, 2, D)
    touch = boxes_touch(centers[n, link], rotations[n, link], half[link], low[n, link], high[n, link], box)  # (P,)
    hits = torch.zeros(len(Q), dtype=torch.int32, device=Q.device).index_add_(0, n, touch.int())  # (N,)
    return valid & (hits == 0)


def boxes_touch(
    center: torch.Tensor, R: torch.Tensor, half: torch.Tensor, low: torch.Tensor, high: torch.Tensor, box: torch.Tensor
) -> torch.Tensor:
    """``(P,)`` whether each link box (``center (P, D)``, ``R (P, D, D)`` whose columns are its axes, ``half (P,
    D)``, bounds ``low, high (P, D)``) touches its obstacle ``box (P, 2, D)``: ``kernels.boxes_touch`` on P pairs,
    an axis separating where the projections' gap exceeds their reach."""
    dim = center.shape[1]
    apart = ((low > box[:, 1]) | (high < box[:, 0])).any(dim=1)  # the world's axes: do the bounds overlap?
    offset = center - (box[:, 0] + box[:, 1]) / 2  # (P, D): link centre minus box centre
    box_half = (box[:, 1] - box[:, 0]) / 2  # (P, D)
    for j in range(dim):  # link axis j: the link reaches half[j] along it
        gap, reach = torch.zeros_like(offset[:, 0]), half[:, j]
        for i in range(dim):
            gap = gap + R[:, i, j] * offset[:, i]
            reach = reach + R[:, i, j].abs() * box_half[:, i]
        apart |= gap.abs() > reach
    if dim == 3:
        for w in range(3):  # world axis w crossed with link axis j: (0, -R[v, j], R[u, j]) in (w, u, v) order
            u, v = (w + 1) % 3, (w + 2) % 3
            for j in range(3):
                a_u, a_v = -R[:, v, j], R[:, u, j]
                reach = a_u.abs() * box_half[:, u] + a_v.abs() * box_half[:, v]
                for k in range(3):
                    reach = reach + (a_u * R[:, u, k] + a_v * R[:, v, k]).abs() * half[:, k]
                apart |= (a_u * offset[:, u] + a_v * offset[:, v]).abs() > reach
    return ~apart


class TorchChecker(BoxWorldChecker):
    """The exact box-world checker in torch on ``device`` (default the CPU): :func:`validity` on whole batches.

    A tensor is answered on its own device without a round trip (moved to the checker's, if elsewhere);
    a numpy batch goes through :class:`~toolkit.geometry.device.Stager` (pinned, chunked copies on a GPU).
    Clearance bounds stay those of :class:`~toolkit.geometry.box_world.BoxWorldChecker`, in numpy.
    """

    CHUNK = 1 << 18  # configurations computed at once: bounds the candidate triples' memory

    def __init__(self, workspace: Workspace, robot: BoxRobot, device: torch.device | str = "cpu"):
        refuse_mesh(workspace)
        super().__init__(workspace, robot)
        self.device = torch.device(device)
        self._robot = robot_tensors(robot, self.device)
        self._world = world_tensors(workspace, robot, self.device)
        self._stager = Stager(self.device, robot.dof, torch.float64, self.CHUNK)

    def _decide(self, Q: torch.Tensor) -> torch.Tensor:
        """``(N,)`` bool on the checker's device, in chunks of ``CHUNK``."""
        Q = Q.to(self.device, torch.float64)
        if len(Q) <= self.CHUNK:
            return validity(Q, self._robot, self._world)
        return torch.cat([validity(part, self._robot, self._world) for part in Q.split(self.CHUNK)])

    def validity(self, Q: np.ndarray) -> np.ndarray:
        return self._stager(self._decide, Q)

    def validity_tensor(self, Q: torch.Tensor) -> torch.Tensor:
        return self._decide(Q).to(Q.device)
