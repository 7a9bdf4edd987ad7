"""Figures of notebook 01: workspaces, occupancy grids, robots and configuration-space obstacles (paper §IV-A).

A planner never sees the workspace directly: it asks a collision checker about
configurations ``q``. The set of configurations at which the robot touches a block
is the *configuration-space obstacle*; these figures draw it next to the geometry
that makes it:

- :func:`workspace_figure` draws a workspace's blocks (one patch per block);
- :func:`occupancy_figure` draws its −1/+1 occupancy grid, the CAE's input (a 3D grid as one image per z layer);
- :func:`cspace_image` draws the point robot's whole 2-DoF C-space, dark where the checker says "in collision";
- :func:`cspace_slice` draws a 2-DoF slice of any robot's C-space (two DoF vary, the others stay fixed) beside
  the robot at the fixed configuration (:mod:`toolkit.plots.near_blocks` picks one whose slices cross blocks,
  and sweeps slices through it under sliders).

The robot itself is drawn by :mod:`toolkit.plots.robot_drawing` (``robot_figure``, ``draw_robot``), and the grid of
a slice built by :mod:`toolkit.plots.slices`.

Each box (a block or a link) is drawn from its corners (:mod:`toolkit.plots.boxes`). Every function returns a
matplotlib ``Figure``, described in words (:func:`~toolkit.plots.alt.describe`), and never calls ``show()``.
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import partial
from typing import Any

import numpy as np
from matplotlib.colors import ListedColormap
from matplotlib.figure import Figure
from matplotlib.patches import Patch, Rectangle
from matplotlib.patheffects import Normal, Stroke

from toolkit.geometry.collision import CollisionChecker
from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace
from toolkit.plots.alt import Part, describe, map_part
from toolkit.plots.boxes import aabb_corners, add_box_3d
from toolkit.plots.contact import key_blocks, passed_over, ring_blocks
from toolkit.plots.palette import COLORS, PAGE_WIDTH
from toolkit.plots.robot_drawing import (
    BASE_MARK,
    KIND_SHADES,
    POSITION_NAMES,
    VIEWS,
    dof_label,
    draw_robot,
    few_ticks,
    hatch_ink,
    link_colors,
    link_style,
)
from toolkit.plots.slices import joint_bounds, pad_unchecked, slice_configs
from toolkit.plots.verdict import mark_arm

COLLISION_CMAP = ListedColormap([COLORS["free"], COLORS["occupied"]])  # 0: valid, 1: in collision (dark)
OCCUPANCY_CMAP = ListedColormap([COLORS["free"], COLORS["occupied"]])  # -1: free, +1: occupied (dark)


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
    return dof_label(robot.dof_names[index])


# -- workspaces and their grids --------------------------------------------------


def workspace_figure(workspace: Workspace, title: str | None = None) -> Figure:
    """The workspace's blocks: one ``Rectangle`` per block in 2D, one ``Poly3DCollection`` per block in 3D.

    Office blocks are colored and hatched by furniture type (``workspace.labels``); every patch has gid ``"block"``.
    """
    size = " x ".join(f"{s:g}" for s in workspace.upper - workspace.lower)
    title = title or f"{workspace.family or 'workspace'}: {len(workspace.boxes)} blocks in {size}"
    kinds = sorted(set(workspace.labels))
    colors = {kind: KIND_SHADES[i % len(KIND_SHADES)][0] for i, kind in enumerate(kinds)}
    hatches = {kind: KIND_SHADES[i % len(KIND_SHADES)][1] for i, kind in enumerate(kinds)}
    box_colors = [colors[label] for label in workspace.labels] or [COLORS["block"]] * len(workspace.boxes)
    box_hatches = [hatches[label] for label in workspace.labels] or [""] * len(workspace.boxes)
    stretch = 1  # how much taller than its widths a region's height is drawn
    if workspace.dim == 2:
        fig = Figure(figsize=(4.3, 4.3))
        ax = fig.subplots()
        for (lo, hi), color, hatch in zip(workspace.boxes, box_colors, box_hatches):
            ax.add_patch(Rectangle(lo, *(hi - lo), facecolor=color, edgecolor=COLORS["ink"], hatch=hatch, gid="block"))
        ax.set(xlim=(workspace.lower[0], workspace.upper[0]), ylim=(workspace.lower[1], workspace.upper[1]))
        ax.set(aspect="equal", xlabel="x", ylabel="y")
    else:
        extent = workspace.upper - workspace.lower  # (3,)
        stretch = max(1, int(np.ceil(max(extent[:2]) / (3 * extent[2]))))  # r19b: the office's heights unreadable
        # the page's width for a flat region; a cube (the clutter) at about half of it (r36a: a screen of texture)
        fig = Figure(figsize=(PAGE_WIDTH, 5.6) if stretch > 1 else (PAGE_WIDTH * 0.6, PAGE_WIDTH * 0.6))
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
                hatchcolor=hatch_ink(color),  # white on the dark grey walls
                hatch_linewidth=1.3,  # a hatch seen on a small box, at the site's width
            ).set_gid("block")
        frame_region(ax, workspace)
        ax.set_box_aspect(extent * [1, 1, stretch])  # a flat region drawn taller, by a whole factor its z label gives
        few_ticks(ax)
        if stretch > 1:
            ax.set_zlabel(f"z (vertical ×{stretch})")
            ax.view_init(elev=55, azim=-60)  # a flat region seen steeply: low blocks (chairs) less hidden (r26a)
            y_ticks = [t for t in ax.get_yticks() if workspace.lower[1] < t <= workspace.upper[1]]
            ax.set_yticks(y_ticks)  # no y tick at the corner where x's last tick stands (r27a: "40" over "0")
            x_ticks = [t for t in ax.get_xticks() if workspace.lower[0] <= t < workspace.upper[0] - 0.1 * extent[0]]
            ax.set_xticks(x_ticks)  # nor x's last: by the corner, it floated above the legend (r57a: a stray "40")
    if kinds:
        handles = [Patch(label=k, **link_style(colors[k], hatches[k])) for k in kinds]  # as drawn
        fig.legend(handles=handles, fontsize=9, loc="lower center", ncols=min(len(kinds), 3), frameon=False)
        fig.subplots_adjust(bottom=0.16)  # the legend below the view, over no block and clear of its ticks (r29a)
    ax.set_title(title)
    counts = [f"{workspace.labels.count(k)} {k}" for k in kinds] if kinds else []
    text = f"The {workspace.family or 'workspace'} workspace, {size}: {len(workspace.boxes)} blocks"
    text += f" ({', '.join(counts)}, each kind its own colour and hatch)" if counts else ""
    text += f", {_occupied_share(workspace):.0%} of the region occupied"
    text += f"; heights stretched {stretch} times against widths." if stretch > 1 else "."
    return describe(fig, text, [_blocks_part(workspace)])


def _blocks_part(workspace: Workspace) -> Part:
    """The workspace's blocks as a table (a part of a longer description): each one's kind and corners."""
    point = lambda p: "(" + ", ".join(f"{v:.3g}" for v in p) + ")"
    return Part(
        "blocks",
        f"each block's lower and upper corner ({', '.join('xyz'[: workspace.dim])})",
        ("block (its index in boxes)", "kind", "lower corner", "upper corner"),
        tuple(  # numbered from 0, as the arrays and the figure titles number them (review r31a)
            (str(k), workspace.labels[k] if workspace.labels else "block", point(lo), point(hi))
            for k, (lo, hi) in enumerate(workspace.boxes)
        ),
    )


def _occupied_share(workspace: Workspace) -> float:
    """The share of the occupancy grid's cells that are occupied."""
    return float(np.mean(workspace.occupancy() > 0))


def occupancy_figure(
    workspace: Workspace, layers: Sequence[int] | None = None, columns: int = 4, *, ring: str | None = None
) -> Figure:
    """The occupancy grid (paper §IV-A: +1 occupied, dark; −1 free, white), one image per z layer in 3D.

    Image ``[row, col]`` is cell ``(x=col, y=row)``, so the picture lies as :func:`workspace_figure`'s.
    ``layers``: which z layers of a 3D grid to draw (default: all); ``ring``: a kind of block ringed where it is.
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
    wide = len(images) > 1  # layers fill the page's width, little room between them (r39a: 4 px a cell were too few)
    # reader r44a: one image at 4.2 inches was too small to read at 1280 px; now most of the page's width
    fig = Figure(figsize=(PAGE_WIDTH, rows * PAGE_WIDTH / columns * 1.05 + 0.9) if wide else (5.4, 5.8))
    axes = fig.subplots(
        rows, columns, squeeze=False, sharex=True, sharey=True, gridspec_kw={"hspace": 0.25, "wspace": 0.08}
    )
    ringed = []
    for ax, image, title in zip(axes.ravel(), images, titles):
        ax.imshow(image.T, origin="lower", extent=extent, cmap=OCCUPANCY_CMAP, vmin=-1, vmax=1, interpolation="nearest")
        ringed.append(ring_blocks(ax, workspace, ring, float(title.split()[-1]) if grid.ndim == 3 else None))
        ax.set_title(title if len(images) > 1 else "", fontsize=9)  # one image: the figure's title names it (r29a)
        ax.locator_params(nbins=6 if len(images) == 1 else 4)  # a tick every few cells (0..31: every 5), no more:
        # drawing text is most of a many-layered figure's cost
        ax.tick_params(labelsize=8)
    for row in axes:
        row[0].set_ylabel("y")
    for column in range(columns):  # the lowest panel of each column names x
        drawn = [r for r in range(rows) if r * columns + column < len(images)]
        axes[drawn[-1], column].set_xlabel("x")
        axes[drawn[-1], column].tick_params(labelbottom=True)
        for r in drawn[:-1]:
            axes[r, column].tick_params(labelbottom=False)
    for (_, c), ax in np.ndenumerate(axes):
        ax.tick_params(labelleft=c == 0)
    for ax in axes.ravel()[len(images) :]:
        ax.remove()
    said = f"Occupancy grid {' x '.join(map(str, grid.shape))}\ndark = +1 (occupied), white = -1 (free)"
    fig.suptitle(said + f"; each {ring} ringed" * bool(ring), fontsize=10)
    fig.subplots_adjust(top=1 - 0.8 / fig.get_figheight())  # room for the two title lines; in the layers, the width
    fig.subplots_adjust(**(dict(left=0.08, right=0.98, bottom=0.5 / fig.get_figheight()) if wide else {}))
    shares = [f"{np.mean(image > 0):.0%}" for image in images]
    text = f"Occupancy grid of the {workspace.family or 'workspace'} workspace, {' x '.join(map(str, grid.shape))} "
    text += f"cells, occupied dark, free white: {np.mean(grid > 0):.0%} of the cells occupied"
    if grid.ndim == 3:
        text += f"; one image per z layer, {len(images)} drawn, occupied per layer from bottom: {', '.join(shares)}"
    text += f"; each {ring} ringed, per image: {', '.join(map(str, ringed))}" if ring else ""
    x, y = ("x", extent[0], extent[1]), ("y", extent[2], extent[3])
    parts = [  # each image by region: what share of its cells is occupied
        map_part(title, f"{share} occupied; by region, top row first", image.shape, x, y, partial(_occupied, image))
        for title, share, image in zip(titles, shares, images)
    ]
    return describe(fig, text + ".", parts)


def _occupied(image: np.ndarray, cells: tuple[slice, slice]) -> str:
    return f"{np.mean(image[cells] > 0):.0%} occupied"


# -- configuration space --------------------------------------------------------------


def _draw_cspace(
    ax, checker: CollisionChecker, q, joints: tuple[int, int], resolution: int, window: tuple | None
) -> np.ndarray:
    """Image of the slice, dark where the checker says "in collision"; returns validity ``(n, n)``."""
    robot = checker.robot
    _, _, Q = slice_configs(robot, q, joints, resolution=resolution, window=window)  # (n, n, dof); checks the joints
    window = window or joint_bounds(robot, joints)
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


BLOCK_OUTLINE = COLORS["block_outline"]  # 3.7:1 on the dark C-obstacle; not orange, "in collision" (reader r50a)
PAST_BOUNDS = "A pixel's width past the bounds, hatched light grey, is never checked and not in the share in collision."


def cspace_image(checker: CollisionChecker, resolution: int = 600, window: tuple | None = None) -> Figure:
    """The point robot's whole C-space (x, y), dark where ``checker`` reports a collision.

    The workspace's blocks are outlined (:data:`BLOCK_OUTLINE`, gid ``"block"``): each dark C-obstacle is
    its block grown by the robot's half width, since the square's centre is the configuration.
    ``window = ((x_lo, x_hi), (y_lo, y_hi))`` zooms in; ``resolution``: pixels (configurations) per axis.
    """
    robot = checker.robot
    if robot.dof != 2:
        raise ValueError(f"cspace_image draws a 2-DoF C-space; {robot.name!r} has {robot.dof} DoF: use cspace_slice")
    fig = Figure(figsize=(4.7, 4.4))
    ax = fig.subplots()
    valid = _draw_cspace(ax, checker, robot.lower, (0, 1), resolution, window)
    for lo, hi in checker_workspace(checker).boxes:
        ax.add_patch(Rectangle(lo, *(hi - lo), fill=False, edgecolor=BLOCK_OUTLINE, linewidth=1.2, gid="block"))
    left, right, bottom, top = ax.images[0].get_extent()
    ax.set(xlim=(left, right), ylim=(bottom, top), aspect="equal")  # the window, whatever blocks lie beyond it
    ax.set_title(
        f"C-space of the point robot: {1 - valid.mean():.0%} {'of this window ' if window else ''}in collision (dark)\n"
        "outlined: the workspace's blocks",
        fontsize=10,
    )
    where = f"{checker_workspace(checker).family} workspace" + (" (a window of it)" if window else "")
    text = f"Configuration space of the 2D point robot in the {where}: {1 - valid.mean():.0%} of configurations"
    parts = [_collision_part("C-space", ax, valid), _blocks_part(checker_workspace(checker))]
    return describe(fig, text + " in collision, drawn dark; the workspace's blocks outlined inside them.", parts)


def _collision_part(name: str, ax, valid: np.ndarray) -> Part:
    """A C-space image (``valid (n, n)``, drawn on ``ax``) read region by region: the share in collision."""
    left, right, bottom, top = ax.images[0].get_extent()
    x, y = (ax.get_xlabel(), left, right), (ax.get_ylabel(), bottom, top)
    text = f"{1 - valid.mean():.0%} in collision; by region, top row first, the share in collision"
    return map_part(name, text, valid.shape, x, y, lambda cells: f"{1 - valid[cells].mean():.0%} in collision")


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
    is valid, in the invalid colour and hatched if not, its base a black dot, the title saying which
    (see :func:`toolkit.plots.robot_drawing.robot_figure`).
    """
    robot = checker.robot
    q = robot.check_configs(q)[0]  # (dof,)
    q_valid = checker.are_valid(q[None])
    fig = Figure(figsize=(PAGE_WIDTH if view else 4.5, 4.2))
    side = view in ("xz", "yz")  # a side view of a flat robot: its panel wider (r26a), not so wide as to squeeze the
    # slice beside it into a strip (r27a)
    grid = fig.add_gridspec(1, 2 if view else 1, width_ratios=(1, 1.1) if side else None)
    ax = fig.add_subplot(grid[0, 0])
    valid = _draw_cspace(ax, checker, q, joints, resolution, None)
    padded = pad_unchecked(ax, robot, joints, resolution)  # a pixel past the bounds: grey, hatched, keyed
    lengths = all(robot.dof_names[k] in POSITION_NAMES for k in joints)  # reader r48a: the 41 x 41 slice drawn tall
    ax.set_aspect("equal", adjustable="box") if lengths else ax.set_box_aspect(1)  # to scale; angles square
    star: dict[str, Any] = dict(  # an ink edge in a white halo: seen on the free white and the dark alike (r39a)
        marker="*", markersize=11, markeredgecolor=COLORS["ink"], color=link_colors(1, q_valid)[0], markeredgewidth=1
    )  # reader r50a: at 15 points the youBot's star, 2 units across, touched a grown shelf 0.4 away
    star["path_effects"] = [Stroke(linewidth=3, foreground=COLORS["free"]), Normal()]
    ax.plot(q[joints[0]], q[joints[1]], linestyle="none", gid="q", **star)
    ax.set_title(  # the fixed values are the description's table: four-line titles were the page's hardest (r31a)
        f"{robot.name}: {1 - valid.mean():.0%} in collision (dark)\nthe other DoF at the star's values", fontsize=9
    )
    outlined, dashed = _robot_panel(fig, grid[0, 1], checker, q, q_valid, view, margin) if view else (0, 0)
    fig.tight_layout()
    swept = " and ".join(robot.dof_names[k] for k in joints)
    text = f"Slice of the {robot.name} robot's configuration space over {swept}, the other DoF fixed: "
    text += f"{1 - valid.mean():.0%} in collision (dark). A star marks the fixed configuration, which is "
    text += ("valid." if q_valid[0] else "in collision.") + " Beside it, the robot there, its base a dot." * bool(view)
    rim = not np.concatenate([valid[0], valid[-1], valid[:, 0], valid[:, -1]]).any()  # every edge pixel dark (r55a)
    text += " A dark frame runs round the slice: the robot must stay inside the region's boundary." * (rim and lengths)
    text += f" {PAST_BOUNDS}" * padded  # reader r58a: grey and hatched, not dark
    dotted = " A block drawn across the links that no link touches (above or below them) is a dotted outline"
    text += (dotted + ", drawn a little inside its edges.") * bool(outlined)
    text += " A block a link touches is outlined dashed." * bool(dashed)
    star_at = Part(
        "the star's configuration",
        "valid" if q_valid[0] else "in collision",
        ("DoF", "value", "swept here"),
        tuple((name, f"{q[k]:.3g}", "yes" if k in joints else "no") for k, name in enumerate(robot.dof_names)),
    )
    return describe(fig, text, [_collision_part("slice", ax, valid), star_at])


OUT_OF_REACH: dict[str, Any] = dict(edgecolor=COLORS["occupied"], linewidth=1.0, zorder=0.5)


def _robot_panel(
    fig: Figure, cell, checker: CollisionChecker, q: np.ndarray, q_valid: np.ndarray, view: str, margin
) -> tuple[int, int]:
    """The robot at ``q (dof,)`` among the nearby blocks in ``fig``'s grid ``cell``, its base a black dot, its
    verdict titled; a block drawn across the links that no link touches (wholly above or below them, in front or
    behind from the side: :func:`toolkit.plots.contact.passed_over`) outlined dotted, never filled, a little inside
    its edges so that neighbours' outlines do not join into lines across the panel (review r34a); a block a link
    touches dashed, and a key below (:func:`toolkit.plots.contact.key_blocks`). Returns how many blocks were
    outlined dotted and dashed."""
    robot_ax = fig.add_subplot(cell, **({"projection": "3d"} if view == "3d" else {}))
    robot = checker.robot
    colors, workspace = link_colors(1, q_valid), checker_workspace(checker)
    flat_3d = robot.dim == 3 and view in VIEWS
    beyond = passed_over(robot, workspace, q, VIEWS[view]) if flat_3d else np.zeros(len(workspace.boxes), dtype=bool)
    near = Workspace(workspace.lower, workspace.upper, workspace.boxes[~beyond])
    draw_robot(robot_ax, robot, q[None], colors=colors, view=view, workspace=near, margin=margin)
    flat = workspace.boxes[beyond][:, :, list(VIEWS.get(view, (0, 1)))]  # (B, 2, 2) in the view's plane
    window = np.array([robot_ax.get_xlim(), robot_ax.get_ylim()])  # (2, 2): each axis's low, high
    flat = np.unique(flat[np.all((flat[:, 0] <= window[:, 1]) & (flat[:, 1] >= window[:, 0]), axis=1)], axis=0)
    for b_lo, b_hi in flat:  # outlined only, inset: no link touches them
        inset = np.minimum(0.03 * np.ptp(window, axis=1).min(), (b_hi - b_lo) / 4)  # (2,)
        robot_ax.add_patch(
            Rectangle(b_lo + inset, *(b_hi - b_lo - 2 * inset), fill=False, linestyle=":", gid="beyond", **OUT_OF_REACH)
        )
    base = robot.link_frames(q[None])[0][0, 0, : robot.dim]  # (D,) the base's position: a black dot (r30a)
    robot_ax.plot(*([c] for c in (base if view == "3d" else base[list(VIEWS[view])])), gid="base", **BASE_MARK)
    mark_arm(robot_ax, robot, q, view)
    verdict = "valid" if q_valid[0] else "in collision"
    height = f" at z = {base[2]:.2f}" if robot.dim == 3 and view == "xy" else ""  # reader r41a: from above, unseen
    robot_ax.set_title(f"the robot at the star ({view}):\n{verdict} — base (black dot){height}", fontsize=9)  # r53a
    if view == "3d":
        few_ticks(robot_ax)
        return len(flat), 0
    return len(flat), key_blocks(robot_ax, robot, workspace, q, VIEWS[view], dotted=bool(len(flat)))
