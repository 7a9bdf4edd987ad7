"""What the collision MLP sees: the paper's ``[z, q]``, or ``[z, patch, pose]`` (the ``strong`` preset: ``z`` left out).

- :class:`InputEncoding` ``"raw"``: ``[z, q]`` (§III-A2). ``"local"``: ``z``, the
  occupancy patch around the robot's base cell, and the *pose*: the base's position
  inside its cell, sin/cos of the angles that wrap, the joints scaled to [-1, 1] and,
  for robots of several links, where each link box is (its centre relative to the
  base cell's centre, its long axis), from forward kinematics.
- :class:`LinkKinematics`: that forward kinematics, batched, float32: the same frames
  as :meth:`toolkit.geometry.robots.BoxRobot.link_frames` (a test holds it to it).

Both take torch tensors (training, GPU) or numpy arrays (the learned checker on CPU:
a few hundred configurations per call, where numpy's fixed cost per operation is
lower than torch's; ``docs/benchmarks.md``, "The learned checker's fast path") and are
written once for both: the functions they call have the same name and meaning in
numpy (>= 2.0) and torch.

The patch depends only on the workspace and the base cell, so :meth:`InputEncoding.cell_patches`
lists it for every cell at once; inference folds it into a per-workspace table
(:func:`toolkit.learning.inference.workspace_table`).
"""

from __future__ import annotations

import math

import numpy as np
import torch
from torch import nn

from toolkit.geometry.robots import AXES, BoxRobot

ENCODINGS = ("raw", "local")  # an InputEncoding's kinds: the paper's [z, q], ours with the patch and the pose


def reach_cells(robot: BoxRobot, samples: int = 20_000) -> int:
    """How many unit cells from its base cell the robot can reach, along the base's position axes.

    Measured from the links' axis-aligned bounds over a fixed sample of configurations.
    """
    Q = robot.sample(np.random.default_rng(0), samples)
    aabbs = robot.link_aabbs(Q)  # (N, L, 2, D)
    n_pos = robot.n_positions  # the base's position DoFs come first
    reach = np.abs(aabbs[..., :n_pos] - Q[:, None, None, :n_pos]).max()
    return int(math.ceil(reach))


def _namespace(x):
    """The array library of ``x``: ``numpy`` for arrays, ``torch`` for tensors."""
    return np if isinstance(x, np.ndarray) else torch


def _turn(columns: list, axis: int, sin, cos) -> list:
    """The columns of ``R @ rotation(axis, angle)``, given the columns ``3 x (3, N)`` of ``R`` and ``sin, cos (1, N)``
    (tensors or arrays: only ``*``, ``+`` and ``-``)."""
    j, k = (axis + 1) % 3, (axis + 2) % 3
    turned = list(columns)
    turned[j], turned[k] = cos * columns[j] + sin * columns[k], cos * columns[k] - sin * columns[j]
    return turned


def _rotate(columns: list, vector: tuple[float, float, float]):
    """``R @ vector`` ``(3, N)`` from the columns of ``R``, skipping the vector's zero entries."""
    return sum(v * column for v, column in zip(vector, columns) if v)


class LinkKinematics(nn.Module):
    """Link box centres and long axes of a :class:`BoxRobot`, ``(L, 3, N)`` each.

    Takes the base position ``(3, N)`` and sin/cos ``(R, N)`` of the robot's ``R``
    rotational DoFs (base angles, then joints), which the encoding computes anyway;
    batches lie along the last axis, where elementwise ops are fastest.
    """

    def __init__(self, robot: BoxRobot):
        super().__init__()
        base_turns = {"point2d": [], "planar": [AXES["z"]], "free": [AXES["z"], AXES["y"], AXES["x"]]}[robot.base]
        self.n_base_turns = len(base_turns)  # Z-Y-X Euler angles for the free base, yaw for the planar one
        self.turn_axes = base_turns + [AXES[j.axis] for j in robot.joints]  # (R,): axis of each rotational DoF
        self.long_axes = [int(np.argmax(link.half_extents)) for link in robot.links]
        self.origins = [tuple(map(float, j.origin)) for j in robot.joints]  # (J, 3): joint in its parent's frame
        self.offsets = [tuple(map(float, l.offset)) for l in robot.links]  # (L, 3): box centre in its link's frame

    def forward(self, position, sin, cos):
        """Centres and long axes of the link boxes, ``(L, 3, N)`` each (tensors or arrays, as the inputs)."""
        xp = _namespace(position)
        eye = xp.eye(3, dtype=position.dtype, device=position.device)
        columns = [xp.broadcast_to(eye[:, i : i + 1], (3, position.shape[1])) for i in range(3)]
        for r in range(self.n_base_turns):
            columns = _turn(columns, self.turn_axes[r], sin[r : r + 1], cos[r : r + 1])
        centers, long_axes = [], []
        for link, offset in enumerate(self.offsets):
            if link:
                position = position + _rotate(columns, self.origins[link - 1])  # (3, N)
                r = self.n_base_turns + link - 1
                columns = _turn(columns, self.turn_axes[r], sin[r : r + 1], cos[r : r + 1])
            centers.append(position + _rotate(columns, offset))
            long_axes.append(columns[self.long_axes[link]])
        return xp.stack(centers), xp.stack(long_axes)


class InputEncoding(nn.Module):
    """Turns workspace context and configurations into MLP inputs ``[z, patch, pose]``.

    ``kind="raw"``: ``[z, q]`` (the paper; no patch). ``kind="local"``: the patch is
    the occupancy of the ``(2r+1)`` cells around the base cell along each position
    axis (the whole extent of the other grid axes, e.g. the office's height), grids
    padded with "occupied" so leaving the workspace reads as an obstacle; the pose is
    ``[position in cell, sin/cos(angles), scaled joints, link centres, link long axes]``
    (link features only for robots of several links; centres relative to the base
    cell's centre along the position axes).
    """

    # buffers, registered in __init__: they follow the module's device and are not saved in checkpoints
    joint_scale: torch.Tensor  # (n_joints, 1)
    joint_shift: torch.Tensor  # (n_joints, 1)
    last_cell: torch.Tensor  # (n_pos, 1), 0 rows for "raw"
    cell_strides: torch.Tensor  # (n_pos, 1)
    offsets: torch.Tensor  # (P, G)

    def __init__(self, robot: BoxRobot, grid_shape: tuple[int, ...], latent_dim: int, kind: str, radius: int = 0):
        super().__init__()
        if kind not in ENCODINGS:
            raise ValueError(f"unknown input encoding {kind!r}; choose one of {ENCODINGS}")
        self.kind, self.radius, self.grid_shape = kind, int(radius), tuple(grid_shape)
        self.dof = robot.dof  # configurations are (N, dof)
        self.n_pos = robot.n_positions  # buffers below derive from the robot and grid: not saved in checkpoints
        self.n_angles = int(robot.wraps.sum())  # configurations are [positions, angles, joints]
        self.base_height = robot.base_height  # the planar base's z
        lower, upper = (np.array(bound[self.n_pos + self.n_angles :])[:, None] for bound in (robot.lower, robot.upper))
        scale = 2 / (upper - lower)  # joints to [-1, 1]: q * scale + shift
        cell_axes = self.grid_shape[: self.n_pos] if kind == "local" else ()
        strides = [math.prod(cell_axes[i + 1 :]) for i in range(len(cell_axes))]  # exact in float32 below 2**24 cells
        for name, value in [
            ("joint_scale", scale),
            ("joint_shift", -1 - lower * scale),  # (n_joints, 1)
            ("last_cell", np.array(cell_axes)[:, None] - 1),
            ("cell_strides", np.array(strides)[:, None]),
        ]:
            self.register_buffer(name, torch.tensor(value, dtype=torch.float32).reshape(-1, 1), persistent=False)
        self._numpy_constants: tuple[np.ndarray, ...] | None = None  # the buffers in numpy, made on first use
        self.n_cells = math.prod(cell_axes)  # 1 for "raw"
        window = [torch.arange(-self.radius, self.radius + 1)] * self.n_pos
        window += [torch.arange(n) for n in self.grid_shape[self.n_pos :]]
        offsets = torch.stack(torch.meshgrid(*window, indexing="ij"), dim=-1).reshape(-1, len(self.grid_shape))
        self.register_buffer("offsets", offsets, persistent=False)  # (P, G): cell offsets of the patch
        self.kinematics = LinkKinematics(robot) if kind == "local" and robot.n_links > 1 else None
        self.latent_dim = int(latent_dim)
        self.patch_size = len(offsets) if kind == "local" else 0
        n_joints = robot.dof - self.n_pos - self.n_angles
        self.pose_size = (
            robot.dof
            if kind == "raw"
            else (self.n_pos + 2 * self.n_angles + n_joints + (6 * robot.n_links if self.kinematics else 0))
        )
        self.out_features = self.latent_dim + self.patch_size + self.pose_size

    def forward(self, z: torch.Tensor, grids: torch.Tensor, ws_index: torch.Tensor, Q: torch.Tensor) -> torch.Tensor:
        """MLP inputs ``(N, out_features)``: latents ``z (W, L)``, grids ``(W, *grid)``,
        ``ws_index (N,)``, ``Q (N, dof)``."""
        cell, pose = self.configs(Q)
        return torch.cat([z[ws_index, : self.latent_dim], self.cell_patches(grids)[ws_index, cell], pose.T], dim=1)

    def cell_patches(self, grids: torch.Tensor) -> torch.Tensor:
        """``(W, n_cells, P)``: the patch around every base cell of every grid ``(W, *grid)``."""
        if self.kind == "raw":
            return grids.new_zeros(len(grids), 1, 0)
        pad: list[int] = []
        for axis in reversed(range(len(self.grid_shape))):  # F.pad lists the last axis first
            pad += [self.radius, self.radius] if axis < self.n_pos else [0, 0]
        padded = nn.functional.pad(grids, pad, value=1.0)  # (W, *grid padded along the position axes)
        cells = torch.meshgrid(
            *[torch.arange(n, device=grids.device) for n in self.grid_shape[: self.n_pos]], indexing="ij"
        )
        base = torch.zeros(self.n_cells, len(self.grid_shape), dtype=torch.long, device=grids.device)
        base[:, : self.n_pos] = torch.stack(cells, dim=-1).reshape(-1, self.n_pos) + self.radius  # (n_cells, G), padded
        index = (base[:, None, :] + self.offsets).unbind(-1)  # G x (n_cells, P)
        return padded[(slice(None),) + index]  # (W, n_cells, P)

    def configs(self, Q):
        """Configurations ``Q (N, dof)`` as ``(cell, pose)``: each one's base cell, ``(N,)`` indices into the rows of
        :meth:`cell_patches` (0 for "raw"), and its pose, one row per feature ``(pose_size, N)`` (``q.T`` for "raw").

        ``Q`` is a float32 tensor, or a numpy array (computed in float32, answered in numpy).
        """
        xp = _namespace(Q)
        # one row per feature: elementwise ops on contiguous (k, N) rows are several times faster than on (N, k) columns
        rows = Q.T.contiguous() if xp is torch else np.ascontiguousarray(Q.T, dtype=np.float32)  # (dof, N)
        n = rows.shape[1]
        if self.kind == "raw":
            return xp.zeros(n, dtype=xp.int64, device=rows.device), rows
        last_cell, strides, scale, shift = self._constants(xp)
        first_joint = self.n_pos + self.n_angles
        position = rows[: self.n_pos]  # (n_pos, N); grid cells are unit cubes from the origin
        cell = xp.minimum(xp.clip(xp.floor(position), 0, None), last_cell)  # (n_pos, N), clamped into the grid
        centre = cell + 0.5
        turns = rows[self.n_pos :] if self.kinematics is not None else rows[self.n_pos : first_joint]  # (R, N)
        sin, cos = xp.sin(turns), xp.cos(turns)
        parts = [position - centre, sin[: self.n_angles], cos[: self.n_angles], rows[first_joint:] * scale + shift]
        if self.kinematics is not None:
            position_3d, centre_3d = position, centre  # (3, N) each
            if self.n_pos < 3:  # the planar base's z, not a DoF
                up = 3 - self.n_pos
                position_3d = xp.concat(
                    [position, xp.full((up, n), self.base_height, dtype=rows.dtype, device=rows.device)]
                )
                centre_3d = xp.concat([centre, xp.zeros((up, n), dtype=rows.dtype, device=rows.device)])
            centers, long_axes = self.kinematics.forward(position_3d, sin, cos)  # (L, 3, N) each; forward: no hooks
            parts += [(centers - centre_3d).reshape(3 * len(centers), n), long_axes.reshape(3 * len(centers), n)]
        index = (cell * strides).sum(0)  # (N,)
        return (index.long() if xp is torch else index.astype(np.int64)), xp.concat(parts)  # (N,), (pose_size, N)

    def _constants(self, xp) -> tuple:
        """``(last_cell, cell_strides, joint_scale, joint_shift)``, ``(k, 1)`` each, as tensors or numpy arrays."""
        buffers = (self.last_cell, self.cell_strides, self.joint_scale, self.joint_shift)
        if xp is torch:
            return buffers
        if self._numpy_constants is None:
            self._numpy_constants = tuple(b.cpu().numpy() for b in buffers)
        return self._numpy_constants
