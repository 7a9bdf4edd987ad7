"""The panels of a 3D scene's still (notebook 05, :func:`toolkit.plots.scenes.scene_still`; paper §IV-A).

A 3D picture on a page cannot be turned, so each panel is drawn to be read from where it stands:

- :func:`overview` draws the whole workspace, its blocks faint (those near the robot darker), one mark per sample (a
  circle valid, a diamond in collision, large enough to tell apart, edged in ink; light; every k-th of them, at most
  :data:`OVERVIEW_SAMPLES`, a star round each one a model gets wrong: stars as common as its mistakes; every
  dangerous one drawn, thinned or not, its star larger, :data:`DANGEROUS_STAR`) and, over
  them, the robot itself at each pose: its links opaque in its colour, edged in ink, ringed in white, labelled;
- :func:`close_up` draws the robot at one pose among the blocks near it: its links opaque, edged thick in ink, each
  joint a white dot ringed in ink, the blocks faded (a robot behind one shows through it), those within
  :data:`NEAR` of a link darker than the rest of its window. The camera looks across the plane the chain spreads
  in (:func:`view_angles`), so a bent chain shows its bends.

mplot3d has no depth buffer: it draws whole collections one after the other. Here the blocks behind the robot come
first, far to near, then the samples, the links far to near, the blocks that stand between a link and the camera
(faded: the robot shows through them) and last the joints.
"""

from __future__ import annotations

import numpy as np
from matplotlib.path import Path
from mpl_toolkits.mplot3d import proj3d

from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace
from toolkit.plots.boxes import aabb_corners, add_box_3d, box_corners, outline
from toolkit.plots.cspace import frame_region
from toolkit.plots.palette import COLORS, halo, scene_label
from toolkit.plots.robot_drawing import BLOCK_STYLE, INVALID_COLOR, VALID_COLOR, draw_robot, few_ticks

SAMPLE_MARKS = {  # kind of sample -> marker, colour, size (points²): the viewer's shapes (drawing.SAMPLE_SHAPES)
    "valid": ("o", VALID_COLOR, 36),  # 6 points across: 8 pixels as the site shows the still (100 dpi)
    "in collision": ("D", INVALID_COLOR, 28),  # as much ink as the circle (a diamond covers s, a circle 0.79 s)
    "model wrong": ((4, 1, 0), COLORS["ink"], 300),  # a four-pointed star: the 3D view's sparkle (one name, r23b)
}
EDGE_LINE, WRONG_LINE = 0.5, 1.2  # points: a sample's ink edge, a star's line
SAMPLE_EDGE = dict(edgecolors=COLORS["ink"], linewidths=EDGE_LINE)  # a thin ink edge: the shape shows on a block too
WRONG_STYLE = dict(facecolors="none", edgecolors=COLORS["ink"], linewidths=WRONG_LINE)  # hollow: the mark shows
TRACE_STYLE = dict(color=COLORS["trace"], linestyle="--")  # dashed: apart from the robot's blue links by more than hue
SAMPLE_WORDS = {
    "valid": "circles",
    "in collision": "diamonds",
    "model wrong": "black sparkles round their marks, larger on a diamond",
}  # SAMPLE_MARKS in words
DANGEROUS_STAR = 1.8  # a dangerous mistake's star this many times a conservative one's area, its line thicker (r27e)
DANGEROUS_LABEL = "sample, model wrong, dangerous"  # a collection of the larger stars, round diamonds
OVERVIEW_SAMPLES = 200  # at most this many samples in a still's overview: more hide the blocks and the robot
DENSE_BLOCKS = 60  # a workspace of more blocks is dense (3DC: 110-125; the office: 25-30)
DENSE_SAMPLES = 100  # at most this many samples in a dense workspace's overview (reader r33e: 3DC-9's was a haze)
OVERVIEW_BLOCKS = {  # {dense: (far blocks' style, near blocks')} in an overview (reader r33e): the office's few blocks
    False: (dict(alpha=0.3, linewidth=0.6), dict(alpha=0.45, linewidth=1.0)),  # darker on its wide floor, the
    True: (dict(alpha=0.1, linewidth=0.2), dict(alpha=0.3, linewidth=0.8)),  # clutter's fainter, the near ones not
}
OVERVIEW_STAR = 100  # points²: an overview's star round a mistake (reader r41e: at 150 the dangerous ones, 1.8
#   times that, overlapped each other and the ringed robot; a close-up's: SAMPLE_MARKS' 300, scaled)
OVERVIEW_ALPHA = 0.45  # an overview's marks, light: the robot drawn over them and the blocks under them show
CLOSE_UP_SCALE = 1.5  # a close-up's marks this many times larger: a small window, seen near
NEAR = 0.3  # workspace units: a block this close to a link's bounding box is drawn darker in a close-up
LINK_EDGE = 1.6  # points: the links' ink edges, thicker than a block's
OVERVIEW_ROBOT = dict(linewidth=3.0, solid_capstyle="round", path_effects=halo(3.0))  # 3-point strokes, ringed
JOINT_MARK = dict(marker="o", s=8, color=COLORS["free"], edgecolors=COLORS["ink"], linewidths=0.8)  # small: a link's
#   0.1 cube shows round it (review r15b: at 22 points² the dots hid 3DC-9's cubes)
ELEVATION = (15.0, 45.0)  # degrees: a close-up's camera stays this far above the horizon, no lower and no higher
USUAL_VIEW = (30.0, -60.0)  # degrees: mplot3d's camera, elevation and azimuth; a close-up's stays on its side
CLOSE_UP_TURNS = (0.0, 180.0, 90.0, -90.0)  # degrees: a close-up's camera turned, the bends' plane still across first
OFF_AXIS = 20.0  # degrees: the least a close-up's azimuth keeps from an axis of the workspace


def overview(ax, robot: BoxRobot, workspace: Workspace, poses: dict[str, tuple[np.ndarray, str]], samples, trace):
    """A still's first panel: the whole workspace, its samples and path, and the robot at each pose ``{name: (q
    (dof,), colour)}`` drawn over them (:func:`robot_strokes`), its name above it; the blocks near a pose darker."""
    aabbs = [robot.link_aabbs(np.asarray(q, dtype=float)[None])[0] for q, _ in poses.values()]  # (L, 2, 3) each
    near = np.zeros(len(workspace.boxes), dtype=bool)  # (K,) a block near a pose
    for boxes in aabbs:
        near |= near_blocks(workspace.boxes, boxes)
    styles = OVERVIEW_BLOCKS[len(workspace.boxes) > DENSE_BLOCKS]  # (far, near) blocks' styles
    for (lo, hi), dark in zip(workspace.boxes, near):
        add_box_3d(ax, aabb_corners(lo, hi), **styles[bool(dark)], **BLOCK_STYLE)
    step = 1 if samples is None else overview_step(len(samples[0]), len(workspace.boxes))
    extra = 0  # dangerous mistakes drawn beyond the every k-th
    conservative = 0 if samples is None else int((samples[1].get("model wrong", 0) & samples[1]["valid"]).sum())
    if samples is not None:  # every k-th of every kind alike, light: a fair share (reader r19c: every mistake added
        keep = np.arange(len(samples[0])) % step == 0  # (N,) to every k-th right one made stars look 40 % of marks)
        dangerous = dangerous_mask(samples[1])  # (N,) and every dangerous one, the rare kind (reader r27e)
        extra = int((dangerous & ~keep).sum())
        keep |= dangerous
        samples = (samples[0][keep], {kind: mask[keep] for kind, mask in samples[1].items()})
    draw_points(ax, samples, trace, alpha=OVERVIEW_ALPHA)
    for marks in ax.collections:  # every mistake starred, each star smaller than a close-up's: a hundred fit
        if marks.get_label() == "sample, model wrong":
            marks.set(sizes=[OVERVIEW_STAR], linewidth=0.8)
        elif marks.get_label() == DANGEROUS_LABEL:
            marks.set(sizes=[OVERVIEW_STAR * DANGEROUS_STAR], linewidth=1.2)
    ax.computed_zorder = False  # the robot in front of every sample
    _floor_cues(ax, robot, [q for q, _ in poses.values()], trace, workspace.lower[2])
    lift = 0.04 * float(np.max(workspace.upper - workspace.lower))  # a label this far above the robot
    for (name, (q, color)), boxes in zip(poses.items(), aabbs):
        ax.plot(*robot_strokes(robot, q).T, color=color, zorder=6.0, gid="robot", **OVERVIEW_ROBOT)
        x, y = boxes[:, :, :2].mean(axis=(0, 1))
        said = dict(
            fontsize=8, ha="center", va="bottom", zorder=7.0, path_effects=halo(1.0, ("free",)), gid="pose label"
        )
        ax.text(x, y, boxes[:, 1, 2].max() + lift, name, **said)
    frame_region(ax, workspace)
    extent = workspace.upper - workspace.lower  # (3,)
    ax.set_box_aspect(extent, zoom=FLAT_ZOOM if flat(workspace) else 1.0)  # a flat office: wider, less blank above
    few_ticks(ax)
    drawn = f", 1 sample in {step} drawn" if step > 1 else ""
    every = 0 if samples is None else int(dangerous_mask(samples[1]).sum())  # reader r29e: "(11 more)" was cryptic
    shown = 0 if samples is None else int((samples[1].get("model wrong", 0) & samples[1]["valid"]).sum())  # r39e
    drawn += f"\n{every} dangerous mistakes, all drawn; {conservative} conservative, {shown} drawn" if extra else ""
    ax.set_title(f"the whole workspace: {len(workspace.boxes)} blocks{drawn}", fontsize=10)


def _floor_cues(ax, robot: BoxRobot, poses: list[np.ndarray], trace, floor: float) -> None:
    """Depth on a flat picture (reader r20c: the path seemed to dive): the base's ``trace (T, 3)`` cast on the floor
    at height ``floor``, and a line from the base of each pose ``(dof,)`` down to it, unless it stands on it."""
    if trace is not None:
        shadow = np.array(trace, dtype=float)  # (T, 3)
        shadow[:, 2] = floor
        ax.plot(*shadow.T, zorder=2.5, gid="shadow", label="shadow on the floor", **SHADOW_STYLE)
    for k, q in enumerate(poses if not on_floor(robot, poses, floor) else ()):  # r43e: no drop for 3DO's youBot
        base = robot.link_boxes(np.asarray(q, dtype=float)[None])[0][0, 0]  # (3,) the first link's centre
        down = np.array([base, [base[0], base[1], floor]])  # (2, 3)
        ax.plot(*down.T, zorder=2.5, gid="drop", label="" if k else DROP_LABEL, **DROP_STYLE)


def on_floor(robot: BoxRobot, poses: list[np.ndarray], floor: float) -> bool:
    """Whether the base of every pose ``(dof,)`` stands on the ``floor``: its centre no higher than 1.5 times its own
    half height (a mobile base; a drop line from it would be a dot)."""
    centers, rotations, half = robot.link_boxes(np.asarray(poses, dtype=float).reshape(-1, robot.dof))
    reach = np.abs(rotations[:, 0, 2, :]) @ half[0]  # (P,) the base's half height, as turned
    return bool(len(poses)) and bool(np.all(centers[:, 0, 2] - floor <= 1.5 * reach))


def robot_strokes(robot: BoxRobot, q: np.ndarray) -> np.ndarray:
    """``(2 L, 3)``: the robot at ``q (dof,)`` as one line through its links, each from end to end along its longest
    axis (a link as long as it is, drawn thicker: an overview shows a link 0.1 thick as a pixel)."""
    centers, rotations, half = robot.link_boxes(np.asarray(q, dtype=float)[None])  # (1, L, 3), (1, L, 3, 3), (L, 3)
    longest = np.argmax(half, axis=1)  # (L,)
    along = rotations[0, np.arange(len(half)), :, longest] * half[np.arange(len(half)), longest, None]  # (L, 3)
    return np.stack([centers[0] - along, centers[0] + along], axis=1).reshape(-1, 3)


def near_blocks(blocks: np.ndarray, aabbs: np.ndarray) -> np.ndarray:
    """``(K,)`` bool: which ``blocks (K, 2, 3)`` lie within :data:`NEAR` of one of the links' bounding boxes
    ``aabbs (L, 2, 3)``."""
    gaps = np.max(np.maximum(aabbs[None, :, 0] - blocks[:, None, 1], blocks[:, None, 0] - aabbs[None, :, 1]), axis=2)
    return gaps.min(axis=1, initial=np.inf) <= NEAR  # (K,) the gap to the nearest link's box


FLAT_ZOOM = 1.25  # a flat workspace's overview drawn this much larger: mplot3d leaves its box wide margins


def flat(workspace: Workspace) -> bool:
    """Whether ``workspace`` is far lower than it is wide (the office, 41 x 41 x 6): its overview needs less height."""
    extent = workspace.upper - workspace.lower  # (3,)
    return bool(extent[2] < 0.5 * extent[:2].max())


def overview_step(n: int, blocks: int = 0) -> int:
    """k: a still's overview draws every k-th of ``n`` samples, at most :data:`OVERVIEW_SAMPLES`, or
    :data:`DENSE_SAMPLES` among more than :data:`DENSE_BLOCKS` ``blocks``."""
    return -(-n // (DENSE_SAMPLES if blocks > DENSE_BLOCKS else OVERVIEW_SAMPLES))


def close_up(
    ax,
    robot: BoxRobot,
    q: np.ndarray,
    workspace: Workspace,
    *,
    color: str,
    margin: float,
    turns=CLOSE_UP_TURNS,
    view: tuple[float, float] | None = None,
) -> tuple[int, tuple[float, float]]:
    """The robot at ``q (dof,)`` in ``color`` among the blocks within ``margin`` of it (their parts in that window, one
    within :data:`NEAR` up to ``margin`` taller), seen from :func:`view_angles` turned by the first of ``turns``
    (degrees) that puts the fewest blocks on a line of sight through a link (:func:`clear_turn`). Returns how many
    blocks lie within :data:`NEAR` of a link's box, and the camera's (elevation, azimuth); ``view`` sets that camera
    (reader r34e: a still's second close-up seen from its first's, so that the two poses compare)."""
    q = np.asarray(q, dtype=float)
    draw_robot(ax, robot, q[None], colors=[color], view="3d", margin=margin)  # the links; the blocks below
    aabbs = robot.link_aabbs(q[None])[0]  # (L, 2, 3)
    lo = np.maximum(aabbs[:, 0].min(axis=0) - margin, workspace.lower)  # (3,) the window
    hi = np.minimum(aabbs[:, 1].max(axis=0) + margin, workspace.upper)
    z = workspace.boxes[near_blocks(workspace.boxes, aabbs)][:, :, 2]  # (K', 2) reader r30e: a block under the chain
    lo[2] = max(z[:, 0].min(initial=lo[2]), lo[2] - margin, workspace.lower[2])  # cut by the window's floor looked
    hi[2] = min(z[:, 1].max(initial=hi[2]), hi[2] + margin, workspace.upper[2])  # like a thin slab: more of it
    ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), zlim=(lo[2], hi[2]))
    ax.set_box_aspect(hi - lo, zoom=1.15)  # the robot larger in its panel: mplot3d leaves wide margins
    if view is None:
        elevation, azimuth = view_angles(robot, q)  # turned where a block stands on a line of sight through a link
        azimuth += clear_turn(robot, q, workspace, margin, turns, (elevation, azimuth))  # (reader r33e)
    else:
        elevation, azimuth = view
    ax.view_init(elev=elevation, azim=azimuth)
    toward = _toward_camera(elevation, azimuth)  # (3,)
    ax.computed_zorder = False  # drawn in the order set below, not by mplot3d's guess of each collection's depth
    blocks = workspace.boxes[np.all((workspace.boxes[:, 0] <= hi) & (workspace.boxes[:, 1] >= lo), axis=1)]
    near = near_blocks(blocks, aabbs)  # (K,) a block near a link's box
    centers = robot.link_boxes(q[None])[0][0]  # (L, 3)
    before = _in_front(blocks, centers, toward)  # (K,) a block between a link and the camera: drawn over the robot
    for rank, k in enumerate(np.argsort(blocks.mean(axis=1) @ toward)):  # far to near
        style = dict(alpha=0.3, linewidth=0.8) if near[k] else dict(alpha=0.08, linewidth=0.3)
        inside = np.clip(blocks[k], lo, hi)  # (2, 3) the part in the window: mplot3d draws past its axes
        order = (3.5 if before[k] else 1.0) + rank / len(blocks)
        add_box_3d(ax, aabb_corners(*inside), zorder=order, **style, **BLOCK_STYLE)
    links = [c for c in ax.collections if c.get_gid() == "link"]  # one per link, in the robot's order
    for rank, k in enumerate(np.argsort(centers @ toward)):  # far to near
        links[k].set(alpha=1.0, linewidth=LINK_EDGE, zorder=2.5 + rank / len(links))
    joints = robot.link_frames(q[None])[0][0, 1:]  # (L - 1, 3) where each link turns on the one before
    if len(joints):
        ax.scatter(*joints.T, depthshade=False, zorder=5.0, label="joint", **JOINT_MARK)
    few_ticks(ax)
    if hi[2] - lo[2] < 0.5 * np.max(hi - lo):  # a low window, its z axis seen short: ticked at its ends alone
        ax.set_zticks((lo[2], hi[2]))
    return int(near.sum()), (elevation, azimuth)


def clear_turn(
    robot: BoxRobot, q: np.ndarray, workspace: Workspace, margin: float, turns, view: tuple[float, float] | None = None
) -> float:
    """The first of ``turns`` (degrees about the vertical, from the camera ``view``, ``(elevation, azimuth)``, by
    default :func:`view_angles`') that puts the fewest of the blocks within ``margin`` of the robot at ``q (dof,)``
    on a line of sight through a link, behind it or before it (review r17c: seen so, a robot beside a block looked
    inside it)."""
    q = np.asarray(q, dtype=float)
    elevation, azimuth = view or view_angles(robot, q)
    aabbs = robot.link_aabbs(q[None])[0]  # (L, 2, 3)
    lo, hi = aabbs[:, 0].min(axis=0) - margin, aabbs[:, 1].max(axis=0) + margin  # (3,) the window
    blocks = workspace.boxes[np.all((workspace.boxes[:, 0] <= hi) & (workspace.boxes[:, 1] >= lo), axis=1)]
    centers = robot.link_boxes(q[None])[0][0]  # (L, 3)
    sights = [_toward_camera(elevation, azimuth + t) for t in turns]  # (3,) each
    crossed = [(_in_front(blocks, centers, v) | _in_front(blocks, centers, -v)).sum() for v in sights]
    return float(turns[int(np.argmin(crossed))])


def model_words(answer: tuple[float, bool] | None, valid: bool | None = None) -> str:
    """A close-up title's second line: what a model answers for the pose, ``(P(valid), predicted valid)``, and where
    the exact checker's ``valid`` differs, which mistake that is (readers r28e, r29e: the robot is itself one)."""
    if answer is None:
        return ""
    wrong = "" if valid is None or answer[1] == valid else f":\na {('dangerous', 'conservative')[valid]} mistake"
    return f"\nthe model: P(valid) {answer[0]:.2f}, {('rejects', 'accepts')[answer[1]]} it{wrong}"


def mark_nearest(scene, links: np.ndarray, blocks: np.ndarray, bounds: tuple | None = None) -> None:
    """Edge in ink, and name, the block nearest the robot's links ``(L, 2, 3)`` among ``blocks (K, 2, 3)`` (box to
    box, min/max corners), its part inside the axes' window: the one a low clearance is about (review r16c: the
    block grazed was not marked). Where a wall of the workspace, ``bounds (lower (3,), upper (3,))``, is nearer the
    links than that block, the name says so (reader r23b: the clearance was the wall's, the block looked far)."""
    gaps = np.maximum(0.0, np.maximum(blocks[:, None, 0] - links[None, :, 1], links[None, :, 0] - blocks[:, None, 1]))
    distances = np.linalg.norm(gaps, axis=-1).min(axis=1)  # (K,) each block's distance to the nearest link
    nearest = int(np.argmin(distances))
    wall = np.inf if bounds is None else min((links[:, 0] - bounds[0]).min(), (bounds[1] - links[:, 1]).min())
    name = "nearest block" if wall >= distances[nearest] else "nearest block\n(a wall of the workspace is nearer)"
    lo, hi = blocks[nearest]
    window = np.array([scene.get_xlim(), scene.get_ylim(), scene.get_zlim()]).T  # (2, 3) the axes' window
    lo, hi = np.clip(lo, *window), np.clip(hi, *window)  # its part inside: mplot3d draws past the axes
    corners = aabb_corners(lo, hi)  # (8, 3)
    add_box_3d(scene, corners, facecolor="none", edgecolor=COLORS["ink"], linewidth=1.6, gid="nearest")
    x, y, _ = proj3d.proj_transform(*corners.T, scene.get_proj())  # (8,) each: the corners on the picture
    top = (float(np.mean(x)), float(np.max(y)))  # above the block's highest corner on the picture (reader r20c)
    scene.annotate(name, top, xytext=(0, 4), textcoords="offset points", ha="center", va="bottom", **scene_label())


def _in_front(blocks: np.ndarray, points: np.ndarray, toward: np.ndarray) -> np.ndarray:
    """``(K,)`` bool: which ``blocks (K, 2, 3)`` a ray from one of ``points (P, 3)`` toward the camera (``toward``,
    a unit vector) passes through: those stand between the robot and the camera (the slab test)."""
    step = np.where(np.abs(toward) > 1e-12, toward, 1e-12)  # (3,) no division by zero
    ends = (blocks[:, None] - points[None, :, None]) / step  # (K, P, 2, 3): where the ray crosses each slab
    enter = np.minimum(ends[:, :, 0], ends[:, :, 1]).max(axis=-1)  # (K, P)
    leave = np.maximum(ends[:, :, 0], ends[:, :, 1]).min(axis=-1)
    return np.any((enter <= leave) & (leave > 0), axis=1)


def _toward_camera(elevation: float, azimuth: float) -> np.ndarray:
    """``(3,)`` the unit direction from the scene to mplot3d's camera at ``elevation``, ``azimuth`` (degrees)."""
    e, a = np.deg2rad([elevation, azimuth])
    return np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])


def view_angles(robot: BoxRobot, q: np.ndarray) -> tuple[float, float]:
    """``(elevation, azimuth)`` in degrees of a camera looking across the plane the robot at ``q (dof,)`` spreads in
    (the least spread of its link boxes' corners, a principal axis), on the side of mplot3d's usual camera
    (:data:`USUAL_VIEW`), within :data:`ELEVATION`; a robot that spreads along a line (a straight chain) is seen
    square to it, from 30 degrees up. It never looks within :data:`OFF_AXIS` of an axis of the workspace: seen
    along one, that axis' tick labels pile onto the others'."""
    centers, rotations, half = robot.link_boxes(np.asarray(q, dtype=float)[None])  # (1, L, 3), (1, L, 3, 3), (L, 3)
    corners = np.concatenate([box_corners(c, r, h) for c, r, h in zip(centers[0], rotations[0], half)])  # (8 L, 3)
    spread, axes = np.linalg.eigh(np.cov(corners.T))  # ascending spread; axes[:, k] its direction
    usual = _toward_camera(*USUAL_VIEW)  # (3,)
    if spread[1] < 0.1 * spread[2]:  # a line: seen square to it, horizontally, then lifted
        flat = np.array([-axes[1, 2], axes[0, 2], 0.0])  # (3,) square to the line, horizontal
        flat = flat / np.linalg.norm(flat) if np.linalg.norm(flat) > 1e-6 else usual * [1.0, 1.0, 0.0]
        normal = np.cos(np.pi / 6) * flat * np.sign(flat @ usual or 1.0) + np.array([0.0, 0.0, np.sin(np.pi / 6)])
    else:
        normal = axes[:, 0] * np.sign(axes[:, 0] @ usual or 1.0)  # the least spread, on the usual side
    elevation = float(np.clip(np.rad2deg(np.arcsin(np.clip(normal[2], -1.0, 1.0))), *ELEVATION))
    azimuth = float(np.rad2deg(np.arctan2(normal[1], normal[0])))
    within = azimuth % 90.0  # degrees past the last axis
    return elevation, azimuth + max(OFF_AXIS - within, 0.0) - max(within - (90.0 - OFF_AXIS), 0.0)


def dangerous_mask(kinds: dict) -> np.ndarray:
    """``(N,)`` bool: the samples of ``kinds {kind: (N,) mask}`` that a model calls valid although they collide."""
    wrong = kinds.get("model wrong")
    return np.zeros_like(kinds["valid"]) if wrong is None else wrong & kinds["in collision"]


def draw_points(
    ax, samples, trace, clip: bool = False, alpha: float = 1.0, scale: float = 1.0, hide: np.ndarray | None = None
) -> int:
    """The samples ``(points (N, 3), {kind: mask})`` by kind and the base's ``trace (T, 3)`` on a 3D axes; with
    ``clip``, only what lies inside the axes' window (mplot3d does not clip); marks ``scale`` times their size, with
    ``alpha``; none where ``hide (N,)`` is true. Returns how many samples it drew."""
    drawn = np.zeros(0 if samples is None else len(samples[0]), dtype=bool)  # (N,)
    for kind, mask in ({} if samples is None else samples[1]).items():
        mask = mask & inside_mask(ax, samples[0]) if clip else mask
        mask = mask & ~hide if hide is not None else mask
        drawn |= mask
        marker, color, size = SAMPLE_MARKS[kind]
        style = dict(color=color, **SAMPLE_EDGE) if kind != "model wrong" else WRONG_STYLE  # round the mark
        large = mask & samples[1]["in collision"] if kind == "model wrong" else np.zeros_like(mask)  # dangerous ones
        for part, label, grow in ((mask & ~large, f"sample, {kind}", 1.0), (large, DANGEROUS_LABEL, DANGEROUS_STAR)):
            if part.any():  # a dangerous mistake's star larger, its line thicker: told apart (reader r27e)
                ax.scatter(
                    *samples[0][part].T,
                    marker=marker,
                    s=size * scale * grow,
                    depthshade=False,
                    alpha=alpha if kind != "model wrong" else 1.0,  # a star in ink, never faded: it flags a mistake
                    zorder=2.0,
                    label=label,
                    **(style | {"linewidths": (WRONG_LINE if kind == "model wrong" else EDGE_LINE) * grow}),
                )
    if trace is not None:
        points = trace.copy()
        if clip:
            points[~inside_mask(ax, points)] = np.nan
        ax.plot(*points.T, linewidth=2.0, path_effects=halo(2.0), label="path of the base (dashed)", **TRACE_STYLE)
    return int(drawn.sum())


def star_on_mark(handles: dict) -> dict:
    """A still's legend ``handles {label: artist}`` with the mistakes' sparkle drawn round a sample's mark, as the
    panels draw it (reader r21c: a hollow star alone in the legend): one entry per kind of mistake drawn, the larger
    sparkle round a diamond (dangerous) and the sparkle round a circle (conservative) (reader r24b, r27e)."""
    star, large = handles.get("sample, model wrong"), handles.get(DANGEROUS_LABEL)
    circle, diamond = handles.get("sample, valid"), handles.get("sample, in collision")
    if (star is None and large is None) or (circle is None and diamond is None):
        return handles
    kinds = {key: value for key, value in handles.items() if key not in ("sample, model wrong", DANGEROUS_LABEL)}
    if diamond is not None and large is not None:
        kinds[DANGEROUS_ENTRY] = (diamond, large)  # a tuple: both drawn, overlaid
    if circle is not None and star is not None:
        kinds[CONSERVATIVE_ENTRY] = (circle, star)
    return kinds


DANGEROUS_ENTRY = "diamond in a large sparkle: model wrong, dangerous"  # in collision, predicted valid
CONSERVATIVE_ENTRY = "circle in a sparkle: model wrong, conservative"  # valid, predicted in collision


SHADOW_STYLE = dict(color=COLORS["ink"], alpha=0.6, linewidth=1.2, linestyle=":")  # the path's shadow on the floor
DROP_LABEL = "the robot's base, straight down to the floor"  # reader r29e: no sample has one
DROP_STYLE = dict(color=COLORS["ink"], alpha=0.6, linewidth=0.9, linestyle="-.")  # a base, straight down: r31e
OVER = 10.0  # pixels: a close-up's mark this near a link's picture is left out (r42e: a diamond reaches 7, an edge 1)


def over_robot(ax, robot: BoxRobot, q: np.ndarray, points: np.ndarray) -> np.ndarray:
    """``(N,)`` bool: which ``points (N, 3)`` the 3D axes, its view and window set, pictures within :data:`OVER`
    pixels of a link of the robot at ``q (dof,)``, in front of it or behind (reader r20c: a diamond half behind a
    bar read as part of the robot); a close-up leaves them out, as the 3D views do."""
    panel = ax.get_position(original=True)  # reader r42e: measured in the box as drawn, square, then the panel back
    ax.apply_aspect()  # (the panel's own shape stretched the pixels: a diamond on a link was not found)
    proj = ax.get_proj()

    def on_screen(p: np.ndarray) -> np.ndarray:  # (n, 3) -> (n, 2) display pixels
        x, y, _ = proj3d.proj_transform(*p.T, proj)
        return ax.transData.transform(np.column_stack([x, y]))

    marks = on_screen(points)  # (N, 2)
    centers, rotations, half = robot.link_boxes(np.asarray(q, dtype=float)[None])  # (1, L, 3), (1, L, 3, 3), (L, 3)
    over = np.zeros(len(points), dtype=bool)
    for c, r, h in zip(centers[0], rotations[0], half):
        link = Path(outline(on_screen(box_corners(c, r, h)), (0, 1)))  # the link's picture, a convex polygon
        over |= link.contains_points(marks, radius=OVER) | link.contains_points(marks, radius=-OVER)  # grown: the sign
    ax.set_position(panel, which="active")  # of the radius that grows a polygon depends on its orientation, so both
    return over


def inside_mask(ax, points: np.ndarray) -> np.ndarray:
    """``(N,)`` bool: which ``points (N, 3)`` lie inside the 3D axes' window."""
    lo, hi = np.array([ax.get_xlim(), ax.get_ylim(), ax.get_zlim()]).T  # (3,) each
    return np.all((points >= lo) & (points <= hi), axis=1)
