"""Slices of configuration space: two degrees of freedom swept over a grid, the others fixed (paper §IV-A).

A robot of 7 or 9 DoF has a configuration space no figure can show whole; a slice through a configuration ``q``
can: two DoF vary over their bounds, the rest stay at ``q``, and every cell of the grid is a configuration to
check. :func:`slice_configs` builds that grid (notebook 01's C-space slices, :mod:`toolkit.plots.cspace`);
:func:`slice_grid` flattens it into a :class:`CSpaceSlice` that a checker answers in one batch and that turns its
answers back into an image (notebook 03's maps of the MLP, :mod:`toolkit.plots.classifier`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from matplotlib.patches import Patch, Rectangle

from toolkit.geometry.robots import BoxRobot
from toolkit.plots.palette import COLORS
from toolkit.plots.robot_drawing import POSITION_NAMES

UNCHECKED: dict[str, Any] = dict(facecolor=COLORS["shade"], hatch="//", edgecolor=COLORS["reference"], linewidth=0)
"""The pixel's width drawn past a position's bounds: light grey, hatched, never checked (reader r58a: drawn dark,
it read as "in collision")."""


def joint_bounds(robot: BoxRobot, joints: tuple[int, int]) -> tuple:
    """``((lo_i, hi_i), (lo_j, hi_j))``: the bounds of two DoF."""
    return tuple((float(robot.lower[k]), float(robot.upper[k])) for k in joints)


def pad_unchecked(ax, robot: BoxRobot, joints: tuple[int, int], resolution: int) -> bool:
    """Widen each position axis of a slice image on ``ax`` by a pixel's width past the robot's bounds, so that a dark
    bar at a bound stands off the axis's spine (review r26a), drawn :data:`UNCHECKED` and named in a key below the
    axes. Returns whether any axis was widened (an angle's is not: it wraps)."""
    padded = False
    for k, limits, set_limits in ((joints[0], ax.get_xlim(), ax.set_xlim), (joints[1], ax.get_ylim(), ax.set_ylim)):
        if robot.dof_names[k] in POSITION_NAMES:
            pad = (limits[1] - limits[0]) / resolution
            set_limits(limits[0] - pad, limits[1] + pad)
            padded = True
    if padded:
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, zorder=-1, gid="unchecked", **UNCHECKED))
        key = Patch(label="past the bounds: not checked", **UNCHECKED)
        ax.legend(handles=[key], loc="upper center", bbox_to_anchor=(0.5, -0.16), fontsize=8, frameon=False)
    return padded


def slice_configs(
    robot: BoxRobot, q, joints: tuple[int, int], *, resolution: int, window: tuple | None = None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A grid over two DoF with the others fixed at ``q (dof,)``.

    Returns the values of DoF ``i`` ``(n,)``, of DoF ``j`` ``(n,)`` and the configurations
    ``(n, n, dof)`` (``Q[a, b]`` has DoF i at ``values_i[a]``, DoF j at ``values_j[b]``).
    The values are the centres of ``n`` equal cells spanning the robot's bounds, or
    ``window = ((lo_i, hi_i), (lo_j, hi_j))``: one pixel per configuration.
    """
    i, j = joints
    if i == j or not (0 <= i < robot.dof and 0 <= j < robot.dof):
        raise ValueError(
            f"joints must be two different DoF indices of {robot.name!r} (0..{robot.dof - 1}), got {joints}"
        )
    q = robot.check_configs(q)[0]  # (dof,)
    window = window or joint_bounds(robot, joints)
    values_i, values_j = (lo + (np.arange(int(resolution)) + 0.5) * (hi - lo) / int(resolution) for lo, hi in window)
    Q = np.tile(q, (len(values_i), len(values_j), 1))  # (n, n, dof)
    Q[:, :, i], Q[:, :, j] = values_i[:, None], values_j[None, :]
    return values_i, values_j, Q


@dataclass(frozen=True)
class CSpaceSlice:
    """``n x n`` configurations: DoFs ``dofs`` swept over their bounds at cell centres, the others fixed."""

    dofs: tuple[int, int]
    names: tuple[str, str]
    axes: tuple[np.ndarray, np.ndarray]  # (nx,), (ny,) cell centres along each swept DoF
    lower: np.ndarray  # (2,) bounds of the swept DoFs
    upper: np.ndarray  # (2,)
    configs: np.ndarray  # (nx * ny, dof), row i * ny + j holds axes[0][i], axes[1][j]

    @property
    def shape(self) -> tuple[int, int]:
        return len(self.axes[0]), len(self.axes[1])

    @property
    def extent(self) -> tuple[float, float, float, float]:
        """``(left, right, bottom, top)`` for ``imshow``: the swept DoFs' bounds."""
        return float(self.lower[0]), float(self.upper[0]), float(self.lower[1]), float(self.upper[1])

    def image(self, values) -> np.ndarray:
        """Values per configuration ``(nx * ny,)`` as a grid ``(nx, ny)``, ``[i, j]`` at ``axes[0][i], axes[1][j]``."""
        return np.asarray(values).reshape(self.shape)

    def on_grid(self, values, name: str) -> np.ndarray:
        """``values`` already on the grid ``(nx, ny)``, as booleans (as floats for ``name`` "probability"), or a clear
        error naming them."""
        values = np.asarray(values, dtype=bool if name != "probability" else float)
        if values.shape != self.shape:
            raise ValueError(f"{name} has shape {values.shape}, the grid {self.shape}")
        return values


def slice_grid(robot: BoxRobot, dofs: tuple[int, int] = (0, 1), *, fixed=None, n: int = 80) -> CSpaceSlice:
    """The ``n x n`` grid over DoFs ``dofs`` of ``robot``, the others at ``fixed (dof,)`` (default: mid-bounds).

    The configurations of :func:`slice_configs` (notebook 01's slices), flattened.
    """
    fixed = (robot.lower + robot.upper) / 2 if fixed is None else fixed
    values_i, values_j, Q = slice_configs(robot, fixed, dofs, resolution=n)  # (n,), (n,), (n, n, dof); checks the DoFs
    i, j = dofs
    return CSpaceSlice(
        (i, j),
        (robot.dof_names[i], robot.dof_names[j]),
        (values_i, values_j),
        robot.lower[[i, j]],
        robot.upper[[i, j]],
        Q.reshape(-1, robot.dof),
    )
