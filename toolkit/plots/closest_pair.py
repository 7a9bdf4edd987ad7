"""The closest pair of points between a 3D robot and the blocks, drawn on a path frame's 3D panel (reader r30e).

Section 7 of chapter 05 prints a clearance *bound* for each frame of a path; its picture showed a wide gap between
the chain and the nearest block, and a reader took the small bound for the gap. :func:`mark_closest` draws the gap
itself: a short ink line between the closest points of the robot's link boxes and the blocks, labelled with its
length and the bound, so that a reader sees how loose the bound is.
"""

from __future__ import annotations

import numpy as np
from mpl_toolkits.mplot3d import proj3d

from toolkit.geometry.robots import BoxRobot
from toolkit.plots.palette import COLORS, halo, scene_label

GRID = 9  # points along each edge of a link box's surface grid, an eighth of the edge apart


def surface_points(robot: BoxRobot, q: np.ndarray, grid: int = GRID) -> np.ndarray:
    """``(P, 3)`` points on the surfaces of the robot's oriented link boxes at configuration ``q (dof,)``: a
    ``grid × grid`` lattice on each face."""
    centers, rotations, half = robot.link_boxes(np.asarray(q, dtype=float)[None])  # (1, L, 3), (1, L, 3, 3), (L, 3)
    u = np.linspace(-1.0, 1.0, grid)
    cube = np.stack(np.meshgrid(u, u, u, indexing="ij"), axis=-1).reshape(-1, 3)  # (grid³, 3)
    cube = cube[np.abs(cube).max(axis=1) == 1.0]  # (S, 3) on the cube's surface
    local = cube[None] * half[:, None]  # (L, S, 3) in each link's frame
    points = centers[0][:, None] + np.einsum("lij,lsj->lsi", rotations[0], local)  # (L, S, 3)
    return points.reshape(-1, 3)


def closest_pair(robot: BoxRobot, q: np.ndarray, blocks: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    """The point of the robot at ``q (dof,)`` nearest any of ``blocks (K, 2, 3)`` (min and max corners), the
    block's point nearest it, and their distance (0 where a link touches a block): to the surface grid's
    resolution, an upper bound on the true gap."""
    points = surface_points(robot, q)  # (P, 3)
    nearest = np.clip(points[:, None], blocks[None, :, 0], blocks[None, :, 1])  # (P, K, 3) each block's point
    distances = np.linalg.norm(points[:, None] - nearest, axis=-1)  # (P, K)
    p, k = np.unravel_index(int(np.argmin(distances)), distances.shape)
    return points[p], nearest[p, k], float(distances[p, k])


def mark_closest(scene, robot: BoxRobot, q: np.ndarray, blocks: np.ndarray, bound: float | None) -> float:
    """Draw on the 3D axes ``scene`` a short ink line between the closest points of the robot at ``q`` and
    ``blocks (K, 2, 3)``, labelled with its length and, if given, the clearance ``bound``; return the length."""
    robot_point, block_point, gap = closest_pair(robot, q, blocks)
    ends = np.stack([robot_point, block_point])  # (2, 3)
    scene.plot(*ends.T, color=COLORS["ink"], linewidth=1.5, gid="closest", path_effects=halo(1.5, ("free",)))
    scene.scatter(*ends.T, s=10, color=COLORS["ink"], depthshade=False, gid="closest ends")
    said = f"{gap:.3f} apart" + ("" if bound is None else f"\n(bound {bound:.3f})")  # gap ≥ bound (r36e: not "bound ≥")
    x, y, _ = proj3d.proj_transform(*ends.mean(axis=0), scene.get_proj())  # the line's middle on the picture
    away = _away_from(scene, ends.mean(axis=0), blocks)  # (2,) sideways off the nearest block, a little down
    scene.annotate(  # reader r41e: from a corner its leader crossed the panel; now beside the gap, on a white ground
        said,
        (float(x), float(y)),
        xytext=tuple(LABEL_OFFSET * away),
        textcoords="offset points",
        ha="left" if away[0] > 0 else "right",
        va="top",
        arrowprops=dict(arrowstyle="-", color=COLORS["ink"], linewidth=0.6, shrinkA=1.0, shrinkB=2.0),
        **{**scene_label(), **LABEL_ON_TOP},
    )
    return gap


LABEL_OFFSET = 40.0  # points: the gap's label this far from the gap's middle (reader r41e)
# reader r33e: the base's dashed trace ran through the label ("0.028" read "0:028"). mplot3d gives its lines and
# faces z-orders above the label's by depth, so the label goes above them all, on a white ground.
LABEL_ON_TOP = dict(zorder=1e6, bbox=dict(boxstyle="round,pad=0.2", facecolor=COLORS["free"], edgecolor="none"))


def _away_from(scene, point: np.ndarray, blocks: np.ndarray) -> np.ndarray:
    """A unit direction on the 3D axes' picture, sideways away from the middle of the block nearest ``point (3,)``
    and a little down (reader r31e: a label set below and right of the gap lay over the block's edges)."""
    nearest = blocks[np.argmin(np.linalg.norm(np.clip(point, blocks[:, 0], blocks[:, 1]) - point, axis=1))]
    on_screen = [
        scene.transData.transform(proj3d.proj_transform(*p, scene.get_proj())[:2])
        for p in (nearest.mean(axis=0), point)
    ]
    side = -1.0 if on_screen[1][0] < on_screen[0][0] else 1.0  # left or right of the block, as the gap is
    return np.array([side, -0.45]) / np.hypot(1.0, 0.45)  # and down: the block's name stands above it
