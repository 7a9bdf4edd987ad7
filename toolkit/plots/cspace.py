"""Figures of notebook 01: workspaces, occupancy grids, robots and configuration-space obstacles (paper §IV-A).

A planner never sees the workspace directly: it asks a collision checker about
configurations ``q``. The set of configurations at which the robot touches a block
is the *configuration-space obstacle*; these figures draw it next to the geometry
that makes it:

- :func:`workspace_figure` draws a workspace's blocks (one patch per block);
- :func:`occupancy_figure` draws its −1/+1 occupancy grid, the CAE's input (a 3D grid as one image per z layer);
- :func:`robot_figure` draws a robot's link boxes at configurations (forward kinematics, ``robot.link_boxes``),
  projected onto coordinate planes or in 3D (:func:`draw_robot` draws them on an axes of your own);
- :func:`cspace_image` draws the point robot's whole 2-DoF C-space, dark where the checker says "in collision";
- :func:`cspace_slice` draws a 2-DoF slice of any robot's C-space (two DoF vary, the others stay fixed) beside
  the robot at the fixed configuration.

Each box (a block or a link) is drawn from its corners (:mod:`toolkit.plots.boxes`). Every function returns a
matplotlib ``Figure``, described in words (:func:`~toolkit.plots.alt.describe`), and never calls ``show()``.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from matplotlib.colors import ListedColormap
from matplotlib.figure import Figure
from matplotlib.patches import Patch, Polygon, Rectangle

from toolkit.geometry.collision import CollisionChecker
from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace
from toolkit.plots.alt import describe
from toolkit.plots.boxes import aabb_corners, add_box_3d, box_corners, outline
from toolkit.plots.palette import CATEGORICAL, COLORS, HATCHES

VALID_COLOR, INVALID_COLOR = COLORS["valid"], COLORS["invalid"]
BLOCK_STYLE: dict[str, Any] = dict(facecolor=COLORS["block"], edgecolor=COLORS["occupied"], gid="block")


def link_style(color: str, hatch: str | None = None) -> dict:
    """A link's face and edge; a link in collision is hatched too (colour is never the only cue), and so is each
    configuration a legend names (``hatch``)."""
    return dict(facecolor=color, edgecolor=COLORS["ink"], hatch="xx" if color == INVALID_COLOR else hatch or None)


COLLISION_CMAP = ListedColormap([COLORS["free"], COLORS["occupied"]])  # 0: valid, 1: in collision (dark)
OCCUPANCY_CMAP = ListedColormap([COLORS["free"], COLORS["occupied"]])  # -1: free, +1: occupied (dark)
VIEWS = {"xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}
POSITION_NAMES = ("x", "y", "z")


def frame_region(ax, workspace: Workspace) -> None:
    """A 3D axes framed on the workspace's region, its axes named x, y, z."""
    lower, upper = workspace.lower, workspace.upper
    ax.set(
        xlim=(lower[0], upper[0]),
        ylim=(lower[1], upper[1]),
        zlim=(lower[2], upper[2]),
        xlabel="x",
        ylabel="y",
        zlabel="z",
    )


def checker_workspace(checker: CollisionChecker) -> Workspace:
    """The workspace ``checker`` decides in (exact and learned checkers know theirs), or a clear error."""
    workspace = getattr(checker, "workspace", None)
    if not isinstance(workspace, Workspace):
        raise TypeError(f"this figure draws the checker's workspace, and a {type(checker).__name__} knows none")
    return workspace


def _dof_label(robot: BoxRobot, index: int) -> str:
    name = robot.dof_names[index]
    return f"{name}" if name in POSITION_NAMES else f"{name} (rad)"


# -- workspaces and their grids --------------------------------------------------


def workspace_figure(workspace: Workspace, title: str | None = None) -> Figure:
    """The workspace's blocks: one ``Rectangle`` per block in 2D, one ``Poly3DCollection`` per block in 3D.

    Office blocks are colored and hatched by furniture type (``workspace.labels``); every patch has gid ``"block"``.
    """
    size = " x ".join(f"{s:g}" for s in workspace.upper - workspace.lower)
    title = title or f"{workspace.family or 'workspace'}: {len(workspace.boxes)} blocks in {size}"
    kinds = sorted(set(workspace.labels))
    colors = {kind: CATEGORICAL[i % len(CATEGORICAL)] for i, kind in enumerate(kinds)}
    hatches = {kind: HATCHES[i % len(HATCHES)] for i, kind in enumerate(kinds)}
    box_colors = [colors[label] for label in workspace.labels] or [COLORS["block"]] * len(workspace.boxes)
    box_hatches = [hatches[label] for label in workspace.labels] or [""] * len(workspace.boxes)
    if workspace.dim == 2:
        fig = Figure(figsize=(5, 5))
        ax = fig.subplots()
        for (lo, hi), color, hatch in zip(workspace.boxes, box_colors, box_hatches):
            ax.add_patch(Rectangle(lo, *(hi - lo), facecolor=color, edgecolor=COLORS["ink"], hatch=hatch, gid="block"))
        ax.set_xlim(workspace.lower[0], workspace.upper[0])
        ax.set_ylim(workspace.lower[1], workspace.upper[1])
        ax.set_aspect("equal")
        ax.set_xlabel("x")
        ax.set_ylabel("y")
    else:
        fig = Figure(figsize=(7, 6))
        ax = fig.add_subplot(projection="3d")
        for (lo, hi), color, hatch in zip(workspace.boxes, box_colors, box_hatches):
            add_box_3d(
                ax,
                aabb_corners(lo, hi),
                facecolor=color,
                edgecolor=COLORS["ink"],
                linewidth=0.3,
                alpha=0.8,
                hatch=hatch,
            ).set_gid("block")
        frame_region(ax, workspace)
        ax.set_box_aspect(workspace.upper - workspace.lower)
        _few_ticks(ax)
    if kinds:
        handles = [Patch(facecolor=colors[k], edgecolor=COLORS["ink"], hatch=hatches[k], label=k) for k in kinds]
        ax.legend(handles=handles, fontsize=8, loc="upper left")
    ax.set_title(title)
    counts = [f"{workspace.labels.count(k)} {k}" for k in kinds] if kinds else []
    text = f"The {workspace.family or 'workspace'} workspace, {size}: {len(workspace.boxes)} blocks"
    text += f" ({', '.join(counts)}, each kind its own colour and hatch)" if counts else ""
    return describe(fig, text + f", {_occupied_share(workspace):.0%} of the region occupied.")


def _occupied_share(workspace: Workspace) -> float:
    """The share of the occupancy grid's cells that are occupied."""
    return float(np.mean(workspace.occupancy() > 0))


def _few_ticks(ax) -> None:
    """A 3D axes with a few tick labels per axis, at 8 points: they do not run into each other (a flat region, as
    the office's 41 x 41 x 6, gets its z axis labelled at its ends only)."""
    ax.locator_params(nbins=4)
    ax.tick_params(labelsize=8)
    aspect = ax.get_box_aspect()  # (3,) the drawn lengths of x, y, z
    if aspect is not None and aspect[2] < 0.3 * max(aspect[:2]):
        ax.set_zticks(ax.get_zlim())
        ax.zaxis.labelpad = 2


def occupancy_figure(workspace: Workspace, layers: Sequence[int] | None = None, columns: int = 4) -> Figure:
    """The occupancy grid (paper §IV-A: +1 occupied, dark; −1 free, white), one image per z layer in 3D.

    Image ``[row, col]`` is cell ``(x=col, y=row)``, so the picture lies as :func:`workspace_figure`'s.
    ``layers``: which z layers of a 3D grid to draw (default: all).
    """
    grid = workspace.occupancy()  # (nx, ny) or (nx, ny, nz)
    extent = (workspace.lower[0], workspace.upper[0], workspace.lower[1], workspace.upper[1])
    if grid.ndim == 2:
        images, titles = [grid], [f"{workspace.family} grid {grid.shape[0]} x {grid.shape[1]}"]
    else:
        drawn = range(grid.shape[2]) if layers is None else layers
        images = [grid[:, :, z] for z in drawn]
        titles = [f"layer z = {workspace.lower[2] + z + 0.5:g}" for z in drawn]
    columns = min(columns, len(images))
    rows = -(-len(images) // columns)
    panel = 4.5 if len(images) == 1 else 2.6  # inches
    fig = Figure(figsize=(panel * columns, panel * rows + 0.4))
    axes = fig.subplots(
        rows, columns, squeeze=False, sharex=True, sharey=True, gridspec_kw={"hspace": 0.35, "wspace": 0.15}
    )
    for ax, image, title in zip(axes.ravel(), images, titles):
        ax.imshow(image.T, origin="lower", extent=extent, cmap=OCCUPANCY_CMAP, vmin=-1, vmax=1, interpolation="nearest")
        ax.set_title(title, fontsize=9)
        ax.locator_params(nbins=3)  # few tick labels: drawing text is most of this figure's cost
        ax.tick_params(labelsize=8)
    for row in axes:
        row[0].set_ylabel("y")
    for column in range(columns):  # the lowest panel of each column names x
        drawn = [r for r in range(rows) if r * columns + column < len(images)]
        axes[drawn[-1], column].set_xlabel("x")
        axes[drawn[-1], column].tick_params(labelbottom=True)
        for r in drawn[:-1]:
            axes[r, column].tick_params(labelbottom=False)
    for c in range(columns):
        for r in range(rows):
            axes[r, c].tick_params(labelleft=c == 0)
    for ax in axes.ravel()[len(images) :]:
        ax.remove()
    fig.suptitle(
        f"Occupancy grid {' x '.join(map(str, grid.shape))}\ndark = +1 (occupied), white = -1 (free)", fontsize=10
    )
    fig.subplots_adjust(top=1 - 0.8 / fig.get_figheight())  # room for the two title lines
    shares = [f"{np.mean(image > 0):.0%}" for image in images]
    text = f"Occupancy grid of the {workspace.family or 'workspace'} workspace, {' x '.join(map(str, grid.shape))} "
    text += f"cells, occupied dark, free white: {np.mean(grid > 0):.0%} of the cells occupied"
    if grid.ndim == 3:
        text += f"; one image per z layer, {len(images)} drawn, occupied per layer from bottom: {', '.join(shares)}"
    return describe(fig, text + ".")


# -- robots ------------------------------------------------------------------------


def _nearby_blocks(workspace: Workspace, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """Indices of the blocks that meet the axis-aligned window ``[lo, hi]`` (D,)."""
    boxes = workspace.boxes
    return np.flatnonzero(np.all((boxes[:, 0] <= hi) & (boxes[:, 1] >= lo), axis=1))


def draw_robot(
    ax,
    robot: BoxRobot,
    Q,
    *,
    colors: list[str],
    view: str = "3d",
    workspace: Workspace | None = None,
    margin=1.0,
    hatches: Sequence[str | None] | None = None,
) -> None:
    """Draw the link boxes of configurations ``Q (k, dof)``, one colour each, and the blocks within ``margin`` of them,
    on one axes (the building block of :func:`robot_figure`, :func:`cspace_slice` and the scene figures).

    ``view``: ``"3d"`` (``ax`` an mplot3d axes) or a plane ``"xy"``, ``"xz"``, ``"yz"`` (the shadow of each box,
    drawn far to near as seen from the page's front: in ``"xy"`` from above, so the highest link lies on top).
    Links have gid ``"link"``, blocks gid ``"block"``; the axes' limits frame them. ``hatches``: one hatch per
    configuration (a second cue where colours tell configurations apart).
    """
    Q = robot.check_configs(Q)  # (k, dof)
    if view != "3d" and view not in VIEWS:
        raise ValueError(f"unknown view {view!r}; choose '3d' or one of {sorted(VIEWS)}")
    if len(colors) != len(Q):
        raise ValueError(f"{len(colors)} colours for {len(Q)} configurations: give one colour a configuration")
    centers, rotations, half = robot.link_boxes(Q)  # (k, L, D), (k, L, D, D), (L, D)
    aabbs = robot.link_aabbs(Q)  # (k, L, 2, D)
    lo, hi = aabbs[:, :, 0].min(axis=(0, 1)) - margin, aabbs[:, :, 1].max(axis=(0, 1)) + margin  # (D,) window
    if workspace is not None:
        lo, hi = np.maximum(lo, workspace.lower), np.minimum(hi, workspace.upper)
        blocks = workspace.boxes[_nearby_blocks(workspace, lo, hi)]
    else:
        blocks = np.zeros((0, 2, robot.dim))
    hatches = hatches if hatches is not None else [None] * len(Q)
    link_boxes = [
        (box_corners(c, r, h), color, hatch)
        for cs, rs, color, hatch in zip(centers, rotations, colors, hatches)
        for c, r, h in zip(cs, rs, half)
    ]
    if view == "3d":
        for b_lo, b_hi in blocks:
            add_box_3d(ax, aabb_corners(b_lo, b_hi), linewidth=0.3, alpha=0.25, **BLOCK_STYLE)
        for corners, color, hatch in link_boxes:
            add_box_3d(ax, corners, linewidth=0.4, alpha=0.9, **link_style(color, hatch)).set_gid("link")
        ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), zlim=(lo[2], hi[2]), xlabel="x", ylabel="y", zlabel="z")
        ax.set_box_aspect(hi - lo)
        return
    axes = VIEWS[view]
    for b_lo, b_hi in blocks:
        ax.add_patch(Rectangle(b_lo[list(axes)], *(b_hi - b_lo)[list(axes)], alpha=0.5, **BLOCK_STYLE))
    toward_viewer = np.cross(*np.eye(3)[list(axes)]) if robot.dim == 3 else np.zeros(2)  # (D,) out of the page
    for corners, color, hatch in sorted(link_boxes, key=lambda box: float((box[0] @ toward_viewer).max())):
        ax.add_patch(  # nearest the viewer last, on top: from above, a higher link hides what lies under it
            Polygon(outline(corners, axes), linewidth=0.6, alpha=0.85, gid="link", **link_style(color, hatch))
        )
    ax.set_xlim(lo[axes[0]], hi[axes[0]])
    ax.set_ylim(lo[axes[1]], hi[axes[1]])
    ax.set_aspect("equal")
    ax.set_xlabel(POSITION_NAMES[axes[0]])
    ax.set_ylabel(POSITION_NAMES[axes[1]])


def _link_colors(n: int, valid: np.ndarray | None) -> list[str]:
    """One colour per configuration: valid / invalid by ``valid (n,)``, else the categorical colours in turn."""
    if valid is None:
        return [CATEGORICAL[k % len(CATEGORICAL)] for k in range(n)]
    return [VALID_COLOR if v else INVALID_COLOR for v in np.asarray(valid, dtype=bool).reshape(n)]


def robot_figure(
    robot: BoxRobot,
    Q,
    workspace: Workspace | None = None,
    *,
    valid=None,
    views: tuple[str, ...] | None = None,
    margin: float = 1.0,
    labels: Sequence[str] | None = None,
) -> Figure:
    """The robot's link boxes at configurations ``Q (dof,)`` or ``(k, dof)``, by forward kinematics.

    One panel per view: ``"xy"`` (from above), ``"xz"``, ``"yz"`` (from the side; a box's
    panel shows its shadow, the convex hull of its projected corners) or ``"3d"``.
    Default: ``("xy",)`` for a 2D robot, ``("3d", "xy", "xz")`` for a 3D one. Blocks of
    ``workspace`` within ``margin`` of the robot are drawn too; ``valid (k,)`` colors
    each configuration in the valid colour or, hatched, the invalid one (a legend names them), else each one in a
    colour of its own, named in a legend by ``labels (k,)`` (where the boxes coincide, the last one's shows).
    """
    Q = robot.check_configs(Q)  # (k, dof)
    views = views or (("xy",) if robot.dim == 2 else ("3d", "xy", "xz"))
    if labels is not None and len(labels) != len(Q):
        raise ValueError(f"{len(labels)} labels for {len(Q)} configurations: give one label a configuration")
    fig = Figure(figsize=(4.2 * len(views), 4.2 + 0.4 * (labels is not None)))
    colors = _link_colors(len(Q), valid)
    hatches = [HATCHES[k % len(HATCHES)] for k in range(len(Q))] if valid is None else [None] * len(Q)
    for i, view in enumerate(views):
        ax = fig.add_subplot(1, len(views), i + 1, **({"projection": "3d"} if view == "3d" else {}))
        draw_robot(ax, robot, Q, colors=colors, view=view, workspace=workspace, margin=margin, hatches=hatches)
        ax.set_title(f"{robot.name}: {view}", fontsize=10)
        if view == "3d":
            _few_ticks(ax)
    if labels is None and valid is not None:
        labels = ["valid" if color == VALID_COLOR else "in collision" for color in colors]
    if labels is not None:
        styles = {label: link_style(c, h) for label, c, h in zip(labels, colors, hatches)}
        handles = [Patch(label=label, **style) for label, style in styles.items()]
        fig.legend(handles=handles, loc="lower center", ncol=len(handles), fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.08 if labels is not None else 0, 1, 1))
    text = f"The {robot.name} robot's link boxes at {len(Q)} configuration{'s' if len(Q) > 1 else ''}"
    seen = ["in 3D" if v == "3d" else f"in the {v} plane" for v in views]
    text += ", seen " + (", ".join(seen[:-1]) + " and " if len(seen) > 1 else "") + seen[-1]
    text += ", with the blocks near it" if workspace is not None else ""
    if valid is not None:
        n_valid = int(np.sum(np.asarray(valid, dtype=bool)))
        text += f": {n_valid} valid, {len(Q) - n_valid} in collision (hatched)"
    elif labels is not None:
        text += ": " + ", ".join(f"{label} ({_hatch_name(h)})" for label, h in zip(labels, hatches))
    return describe(fig, text + ".")


def _hatch_name(hatch: str | None) -> str:
    return {"": "plain", "//": "hatched with slashes", "..": "dotted", "xx": "cross-hatched"}.get(
        hatch or "", "hatched"
    )


# -- configuration space --------------------------------------------------------------


def _joint_bounds(robot: BoxRobot, joints: tuple[int, int]) -> tuple:
    """``((lo_i, hi_i), (lo_j, hi_j))``: the bounds of two DoF."""
    return tuple((float(robot.lower[k]), float(robot.upper[k])) for k in joints)


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
    window = window or _joint_bounds(robot, joints)
    values_i, values_j = (lo + (np.arange(int(resolution)) + 0.5) * (hi - lo) / int(resolution) for lo, hi in window)
    Q = np.tile(q, (len(values_i), len(values_j), 1))  # (n, n, dof)
    Q[:, :, i], Q[:, :, j] = values_i[:, None], values_j[None, :]
    return values_i, values_j, Q


def _draw_cspace(
    ax, checker: CollisionChecker, q, joints: tuple[int, int], resolution: int, window: tuple | None
) -> np.ndarray:
    """Image of the slice, dark where the checker says "in collision"; returns validity ``(n, n)``."""
    robot = checker.robot
    _, _, Q = slice_configs(robot, q, joints, resolution=resolution, window=window)  # (n, n, dof); checks the joints
    window = window or _joint_bounds(robot, joints)
    valid = checker.are_valid(Q.reshape(-1, robot.dof)).reshape(Q.shape[:2])  # (n, n)
    ax.imshow(
        (~valid).T.astype(float),
        origin="lower",
        extent=np.ravel(window),
        cmap=COLLISION_CMAP,
        vmin=0,
        vmax=1,
        interpolation="nearest",
        aspect="auto",
    )
    ax.set_xlabel(_dof_label(robot, joints[0]))
    ax.set_ylabel(_dof_label(robot, joints[1]))
    return valid


def cspace_image(checker: CollisionChecker, resolution: int = 600, window: tuple | None = None) -> Figure:
    """The point robot's whole C-space (x, y), dark where ``checker`` reports a collision.

    The workspace's blocks are outlined (``COLORS["block_outline"]``, gid ``"block"``): each dark C-obstacle is
    its block grown by the robot's half width, since the square's centre is the configuration.
    ``window = ((x_lo, x_hi), (y_lo, y_hi))`` zooms in; ``resolution``: pixels (configurations) per axis.
    """
    robot = checker.robot
    if robot.dof != 2:
        raise ValueError(f"cspace_image draws a 2-DoF C-space; {robot.name!r} has {robot.dof} DoF: use cspace_slice")
    fig = Figure(figsize=(5.5, 5.2))
    ax = fig.subplots()
    valid = _draw_cspace(ax, checker, robot.lower, (0, 1), resolution, window)
    for lo, hi in checker_workspace(checker).boxes:
        ax.add_patch(
            Rectangle(lo, *(hi - lo), fill=False, edgecolor=COLORS["block_outline"], linewidth=1.2, gid="block")
        )
    left, right, bottom, top = ax.images[0].get_extent()
    ax.set(xlim=(left, right), ylim=(bottom, top), aspect="equal")  # the window, whatever blocks lie beyond it
    ax.set_title(
        f"C-space of the point robot: {1 - valid.mean():.0%} {'of this window ' if window else ''}in collision (dark)\n"
        "outlined: the workspace's blocks",
        fontsize=10,
    )
    where = f"{checker_workspace(checker).family} workspace" + (" (a window of it)" if window else "")
    text = f"Configuration space of the 2D point robot in the {where}: {1 - valid.mean():.0%} of configurations"
    return describe(fig, text + " in collision, drawn dark; the workspace's blocks outlined inside them.")


def cspace_slice(
    checker: CollisionChecker,
    q,
    joints: tuple[int, int] = (0, 1),
    *,
    resolution: int = 60,
    view: str | None = "xy",
    margin: float = 1.0,
) -> Figure:
    """A 2-DoF slice of the C-space through ``q (dof,)``: DoF ``joints`` vary over their bounds, the rest stay at ``q``.

    Left: dark where ``checker`` reports a collision, with a star at ``q`` itself. Right
    (unless ``view`` is None): the robot at ``q`` among the nearby blocks, in the valid colour if ``q``
    is valid, in the invalid colour and hatched if not, the title saying which (see :func:`robot_figure`).
    """
    robot = checker.robot
    q = robot.check_configs(q)[0]  # (dof,)
    q_valid = checker.are_valid(q[None])
    fig = Figure(figsize=(9.5 if view else 5, 4.4))
    ax = fig.add_subplot(1, 2 if view else 1, 1)
    valid = _draw_cspace(ax, checker, q, joints, resolution, None)
    star: dict[str, Any] = dict(
        marker="*", markersize=14, markeredgecolor=COLORS["free"], color=_link_colors(1, q_valid)[0]
    )
    ax.plot(q[joints[0]], q[joints[1]], linestyle="none", gid="q", **star)
    fixed = [f"{robot.dof_names[k]}={q[k]:.2f}" for k in range(robot.dof) if k not in joints]
    ax.set_title(
        f"{robot.name}: {1 - valid.mean():.0%} of this slice in collision (dark)\nfixed: " + ", ".join(fixed),
        fontsize=8,
    )
    if view:
        robot_ax = fig.add_subplot(1, 2, 2, **({"projection": "3d"} if view == "3d" else {}))
        colors, workspace = _link_colors(1, q_valid), checker_workspace(checker)
        draw_robot(robot_ax, robot, q[None], colors=colors, view=view, workspace=workspace, margin=margin)
        verdict = "valid" if q_valid[0] else "in collision"
        robot_ax.set_title(f"the robot at the star ({view}): {verdict}", fontsize=9)
        if view == "3d":
            _few_ticks(robot_ax)
    fig.tight_layout()
    swept = " and ".join(robot.dof_names[k] for k in joints)
    text = f"Slice of the {robot.name} robot's configuration space over {swept}, the other DoF fixed: "
    text += f"{1 - valid.mean():.0%} in collision (dark). A star marks the fixed configuration, which is "
    text += ("valid." if q_valid[0] else "in collision.") + (" Beside it, the robot there." if view else "")
    return describe(fig, text)


def configuration_near_blocks(checker: CollisionChecker, rng: np.random.Generator, n: int = 2000) -> np.ndarray:
    """A valid configuration ``(dof,)`` close to a block: a slice through it is likely to cross C-obstacles.

    Of ``n`` uniform samples, the valid one whose link boxes' axis-aligned bounds come
    nearest a block (a random valid configuration is usually far from every block, and
    its slices through arm joints are all free).
    """
    robot, boxes = checker.robot, checker_workspace(checker).boxes  # boxes (K, 2, D)
    Q = robot.sample(rng, n)
    Q = Q[checker.are_valid(Q)]  # (M, dof)
    if len(Q) == 0:
        raise ValueError(f"none of {n} samples is valid: draw more")
    if len(boxes) == 0:
        return Q[0]
    aabbs = robot.link_aabbs(Q)[:, :, None]  # (M, L, 1, 2, D)
    gap = np.maximum(np.maximum(boxes[:, 0] - aabbs[..., 1, :], aabbs[..., 0, :] - boxes[:, 1]), 0)  # (M, L, K, D)
    return Q[np.argmin(np.linalg.norm(gap, axis=-1).min(axis=(1, 2)))]
