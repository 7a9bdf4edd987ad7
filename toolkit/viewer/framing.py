"""Where the camera stands: framing a whole workspace, following a robot, and finding the clearest view of it.

A scene is only as good as its camera. :func:`camera_pose` frames the workspace for the live viewer (§IV-A's
scenes); :func:`follow_camera` keeps a moving robot framed through a motion; :func:`robot_camera` frames one
configuration for a snapshot, and given the samples shown, :func:`clear_view` moves it to where the fewest of the
robot's links stand behind blocks and no sample mark hides it; :func:`marks_over_robot` names the marks that would
still sit over the robot on that picture, which a page leaves out.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace
from toolkit.viewer.drawing import (
    FLAT_ROBOT_HEIGHT,
    VIEW_FOV,
    config_points,
    far_scale,
    lift_points,
    obstacle_boxes,
    robot_boxes,
)

# Camera by the robot's base kind: what to look at, and the offset to the camera in workspace extents.
CAMERA = {
    "point2d": ("region", (-0.1, -0.75, 0.8)),  # the whole flat scene
    "planar": ("robot", (-0.05, -0.2, 0.18)),  # near the youBot: it is small in its big office
    "free": ("region", (-0.6, -1.3, 0.9)),  # the whole clutter, from outside
}


def camera_pose(robot: BoxRobot, workspace: Workspace, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(look_at, position)`` of the camera, from the front-left (see :data:`CAMERA`)."""
    target, offset = CAMERA[robot.base]
    if target == "robot":
        look_at = config_points(robot, q[None])[0] * np.array([1.0, 1.0, 0.0])  # its base, on the floor
    else:
        look_at = lift_points((workspace.lower + workspace.upper) / 2, 0.0)
        look_at[0] += 0.1 * float(workspace.upper[0] - workspace.lower[0])  # to the right: the GUI panel covers it
    return look_at, look_at + float(np.max(workspace.upper - workspace.lower)) * np.array(offset)


ROBOT_VIEW = (-0.45, -1.0, 0.7)  # a robot camera's direction: from the front-left and above (length ~1.3: it fits)
ROBOT_SPAN = 2.5  # a moving robot's camera frames this many robot sizes: the robot, large, and the blocks beside it
SNAPSHOT_SPAN = 1.6  # a snapshot's, fewer: at 2.5, 3DC-9's chain was 60 px of 440 among see-through blocks (r15b)


def robot_camera(
    robot: BoxRobot,
    q,
    *,
    workspace: Workspace | None = None,
    points: np.ndarray | None = None,
    sizes: npt.ArrayLike = 0.0,
    size: float | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """``(look_at, position)`` of a camera that frames the robot at ``q (dof,)`` (a snapshot's), as
    :func:`follow_camera` does at each configuration of a motion; given the scene's ``workspace`` and sample marks
    (``points (N, 3)`` of ``sizes``, one or ``(N,)``, in workspace units, far ones grown from ``size`` where given),
    the clearest view of it (:func:`clear_view`)."""
    Q = robot.check_configs(q)[:1]  # (1, dof)
    looks, positions = follow_camera(robot, Q, span=SNAPSHOT_SPAN)
    if workspace is None and points is None:
        return looks[0], positions[0]
    lo, hi = _link_bounds(robot, Q)  # (3,) each
    links = robot_boxes(robot, Q).centers  # (L, 3)
    radius = float(np.max(hi - lo)) / 2
    return looks[0], clear_view(looks[0], positions[0], radius, workspace, points, sizes, links=links, size=size)


VIEW_ASPECT = 1.5  # a notebook's view, width / height (the course site's: about 640 x 440 px)
LARGE_MARK = 0.12  # a mark in front of the robot wider than this share of the view's height crowds it
VIEW_ELEVATIONS = np.deg2rad([15.0, 30.0, 45.0, 60.0])  # the directions clear_view tries, above the horizon
VIEW_DISTANCES = (0.7, 0.85, 1.0)  # and its distances, times the default's
HIDDEN_LINK = 100.0  # what a link behind a block costs a camera: more than anything else (a mark in the way: 10)


def clear_view(
    look_at: np.ndarray,
    default: np.ndarray,
    radius: float,
    workspace: Workspace | None,
    points: np.ndarray | None,
    sizes: npt.ArrayLike = 0.0,
    *,
    links: np.ndarray | None = None,
    size: float | None = None,
) -> np.ndarray:
    """The camera position ``(3,)`` looking at ``look_at`` (a subject of ``radius``, the robot, its links centred at
    ``links (L, 3)``) from which the fewest links stand behind blocks and no sample mark hides it, nearest the
    ``default`` position's view.

    viser draws a mark of width ``s`` at depth ``z`` ``s / (z tan(fov / 2))`` view heights wide: a mark a few
    tenths of a unit from the camera covers half the picture. Tried: :data:`VIEW_ELEVATIONS` x 24 headings x
    :data:`VIEW_DISTANCES`, in a fixed order (the first of equal costs wins). Each pays :data:`HIDDEN_LINK` per link
    whose line of sight from the camera to its centre crosses a block (:func:`links_hidden`), for the marks in front
    of the subject (:func:`_marks_in_the_way`; far ones grown from ``size`` as a page grows them), 10 times the
    share of its line of sight to the subject inside blocks, and half its turn from the default (radians) and its
    change of distance (a share); a camera inside a block or below the floor is never taken.
    """
    look_at, default = np.asarray(look_at, dtype=float), np.asarray(default, dtype=float)
    cameras, cost = _candidates(look_at, default)  # (C, 3), (C,)
    d = np.linalg.norm(cameras - look_at, axis=1)  # (C,)
    if points is not None and len(points):
        cost += _marks_in_the_way(cameras, look_at, radius, np.asarray(points, float), sizes, size)
    if workspace is not None:
        blocks = obstacle_boxes(workspace)
        lo, hi = blocks.centers - blocks.sizes / 2, blocks.centers + blocks.sizes / 2  # (K, 3) each
        if links is not None:
            cost += HIDDEN_LINK * links_hidden(cameras, np.asarray(links, dtype=float), lo, hi).sum(axis=1)
        t = np.linspace(0.0, 1.0, 17)[:, None, None] * (1.0 - radius / d)[None, :, None]  # (S, C, 1)
        sight = cameras + t * (look_at - cameras)  # (S, C, 3): camera to the subject's near side
        inside = np.all((sight[..., None, :] > lo) & (sight[..., None, :] < hi), axis=-1).any(axis=-1)  # (S, C)
        cost += 10.0 * inside.mean(axis=0) + np.where(inside[0], np.inf, 0.0)
        cost += np.where(cameras[:, 2] < lift_points(workspace.lower, 0.0)[2], np.inf, 0.0)
    return cameras[np.argmin(cost)]


def _candidates(look_at: np.ndarray, default: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The cameras :func:`clear_view` tries, ``(C, 3)``, and what each costs for leaving the ``default``'s view."""
    d0 = float(np.linalg.norm(default - look_at))
    heading = np.deg2rad(np.arange(0.0, 360.0, 15.0))
    elevation, turn, scale = (a.ravel() for a in np.meshgrid(VIEW_ELEVATIONS, heading, VIEW_DISTANCES))
    away = np.stack([np.cos(elevation) * np.cos(turn), np.cos(elevation) * np.sin(turn), np.sin(elevation)], -1)
    cost = 0.5 * np.arccos(np.clip(away @ (default - look_at) / d0, -1.0, 1.0)) + 0.5 * np.abs(scale - 1.0)
    return look_at + (d0 * scale)[:, None] * away, cost


def links_hidden(cameras: np.ndarray, links: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """``(C, L)`` bool: whether the segment from each camera ``(C, 3)`` to each link centre ``(L, 3)`` crosses one
    of the blocks from ``lo (K, 3)`` to ``hi (K, 3)`` (the slab test, exact): that link stands behind a block."""
    ray = links[None] - cameras[:, None]  # (C, L, 3)
    step = np.where(np.abs(ray) > 1e-12, ray, 1e-12)  # no division by zero
    near = (lo[:, None, None] - cameras[None, :, None]) / step  # (K, C, L, 3): where it crosses each slab
    far = (hi[:, None, None] - cameras[None, :, None]) / step
    enter, leave = np.minimum(near, far).max(axis=-1), np.maximum(near, far).min(axis=-1)  # (K, C, L)
    return np.any((enter < leave) & (leave > 0.0) & (enter < 1.0), axis=0)


def _marks_in_the_way(
    cameras: np.ndarray,
    look_at: np.ndarray,
    radius: float,
    points: np.ndarray,
    sizes: npt.ArrayLike,
    size: float | None = None,
) -> np.ndarray:
    """What the marks ``points (N, 3)`` of ``sizes`` (far ones grown from ``size`` where given: ``far_scale``) cost
    each camera ``(C, 3)`` looking at ``look_at``: 10 per mark in front of the subject overlapping it on the picture,
    plus 3 times each such mark's width beyond :data:`LARGE_MARK` (a share of it)."""
    hides, in_front, width = _on_picture(cameras, look_at, radius, points, sizes, size)  # (C, N) each
    crowds = np.where(in_front, np.maximum(width - LARGE_MARK, 0.0) / LARGE_MARK, 0.0)
    return 10.0 * hides.sum(axis=1) + 3.0 * crowds.sum(axis=1)


def marks_over_robot(
    robot: BoxRobot, q, look_at: np.ndarray, position: np.ndarray, points: np.ndarray, sizes: npt.ArrayLike
) -> np.ndarray:
    """``(N,)`` bool: the marks ``points (N, 3)`` of ``sizes`` (one or ``(N,)``, as drawn) that overlap the robot at
    ``q (dof,)`` (a ball round its middle) on the picture of a camera at ``position`` looking at ``look_at``, before it
    or behind it (a sparkle behind it sticks out round it): a page leaves them out (reader r18c: among 2000 samples,
    marks sat over the 3DC-7 chain from every side)."""
    lo, hi = _link_bounds(robot, robot.check_configs(q)[:1])  # (3,) each
    radius = float(np.max(hi - lo)) / 2
    camera = np.asarray(position, dtype=float)[None]  # (1, 3)
    look_at = np.asarray(look_at, dtype=float)
    return _on_picture(camera, look_at, radius, np.asarray(points, float), sizes, reach=np.inf)[0][0]


def _on_picture(
    cameras: np.ndarray,
    look_at: np.ndarray,
    radius: float,
    points: np.ndarray,
    sizes: npt.ArrayLike,
    size: float | None = None,
    reach: float = 0.0,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Where the marks ``points (N, 3)`` of ``sizes`` (far ones grown from ``size`` where given) land on the picture of
    each camera ``(C, 3)`` looking at ``look_at`` (a subject of ``radius``): ``(C, N)`` whether each overlaps the
    subject from in front of its middle (or from up to ``reach`` behind it), whether it is in view and in front of
    the middle, and its width in view heights."""
    forward = look_at - cameras  # (C, 3)
    distance = np.linalg.norm(forward, axis=1, keepdims=True)
    forward /= distance
    right = np.cross(forward, [0.0, 0.0, 1.0])
    right /= np.linalg.norm(right, axis=1, keepdims=True)
    up = np.cross(right, forward)
    rel = points[None] - cameras[:, None]  # (C, N, 3)
    z, x, y = (np.einsum("cnk,ck->cn", rel, axis) for axis in (forward, right, up))  # (C, N) each
    tan = np.tan(VIEW_FOV / 2)
    depth = np.maximum(z, 1e-6) * tan  # half the view's height at each mark's depth
    width = np.broadcast_to(np.asarray(sizes, dtype=float), points.shape[:1]) / depth  # (C, N) in view heights
    if size is not None:
        width = width * far_scale(z, size)
    # on the picture, in half its height: a mark's centre (x, y) / depth, its radius its width in view heights
    seen = (z > 0) & (np.abs(y) / depth < 1 + width) & (np.abs(x) / depth < VIEW_ASPECT + width)
    hides = seen & (z < distance + reach) & (np.hypot(x, y) / depth < width + radius / (distance * tan))
    return hides, seen & (z < distance), width


def follow_camera(robot: BoxRobot, Q, span: float = ROBOT_SPAN) -> tuple[np.ndarray, np.ndarray]:
    """``(look_at (T, 3), position (T, 3))``: a camera that keeps the robot framed at each configuration of
    ``Q (T, dof)``. It looks at the mean of the link centres (it moves smoothly with the configuration), from
    :data:`ROBOT_VIEW` scaled to ``span`` robot sizes (:data:`ROBOT_SPAN`): a robot small in its workspace fills a good
    part of the picture, with the blocks beside it."""
    centers, _, _ = robot.link_boxes(robot.check_configs(Q))  # (T, L, D)
    look_at = lift_points(centers, FLAT_ROBOT_HEIGHT / 2).mean(axis=1)  # (T, 3)
    return look_at, look_at + span * robot_size(robot) * np.array(ROBOT_VIEW)


def _link_bounds(robot: BoxRobot, Q) -> tuple[np.ndarray, np.ndarray]:
    """The 3D min and max corner ``(3,), (3,)`` of the robot's links at the configurations ``Q (T, dof)``."""
    aabbs = robot.link_aabbs(robot.check_configs(Q))  # (T, L, 2, D)
    lo = lift_points(aabbs[:, :, 0].min(axis=(0, 1)), 0.0)  # (3,)
    hi = lift_points(aabbs[:, :, 1].max(axis=(0, 1)), FLAT_ROBOT_HEIGHT)
    return lo, hi


def robot_size(robot: BoxRobot) -> float:
    """The largest extent of the robot at its zero configuration (its joints straight), in workspace units."""
    lo, hi = _link_bounds(robot, np.clip(np.zeros(robot.dof), robot.lower, robot.upper))
    return float(np.max(hi - lo))
