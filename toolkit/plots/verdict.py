"""One check's picture: configurations side by side with a checker's verdict on each (notebook 01's first check and
its youBot nudged into a block), the link boxes and blocks that touch outlined (:mod:`toolkit.plots.contact`), a 2D
link's part inside a block filled; split from :mod:`toolkit.plots.robot_drawing`, whose :func:`draw_robot` draws
each panel.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Patch, Polygon, Rectangle

from toolkit.geometry.box_world import is_point_robot
from toolkit.geometry.checker import CollisionChecker
from toolkit.geometry.collision import exact_checker
from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace
from toolkit.plots.alt import describe
from toolkit.plots.boxes import box_corners, outline
from toolkit.plots.closest_pair import closest_pair
from toolkit.plots.contact import clip_to_box, contacts, name_blocks, nearby_blocks
from toolkit.plots.palette import COLORS, PAGE_WIDTH
from toolkit.plots.robot_drawing import (
    BLOCK_STYLE,
    INVALID_COLOR,
    VALID_COLOR,
    VIEWS,
    configurations_part,
    draw_robot,
    link_colors,
    link_style,
)

INSET = 0.62  # the inset's width, a fraction of its panel's (reader r44a: at 0.38 it was hard to read)
INSET_HIGH = 0.5  # the inset's height, a fraction of its panel's, under the panel (room the figure grows by)
INSET_BACKGROUND = COLORS["free"]  # white, as the room: only blocks are grey (reader r47a: a grey ground read as one)
PARTS = {"youbot": ("platform", "turret", "upper arm", "forearm", "wrist", "gripper"), "point2d": ("square",)}


def verdict_figure(
    checker: CollisionChecker, Q, *, view: str = "xy", margin: float = 1.0, columns: int | None = None
) -> Figure:
    """Configurations ``Q (k, dof)`` side by side, one panel each, drawn in ``view`` with the blocks near them and
    the checker's verdict in each title. Every panel frames the same window (all of ``Q`` within ``margin``,
    review r27a: a move hidden by shifted axes), so a block reaching past it is drawn clipped. In a configuration
    in collision, each link box that touches a block and that block are outlined thick (the block dashed) and named
    in the title, numbered as the arrays are: "platform touches block 11 (desk)" (review r30a), or "square overlaps
    block 0 by 0.2" with a 2D link's part inside the block filled yellow (review r31a); a valid one's title
    gives its clearance where the checker proves one, a lower bound on the gap to the blocks ("valid; at least 0.43
    from every block (a lower bound: the gap can be wider)", reader r42a: read as the gap itself; reader r55a: a
    bound that counted the floor titled a view from above), that gap drawn as a labelled segment where a view from
    above shows it, the gap itself for the point robot.
    ``columns`` panels a row (all of them by default; reader r41a: three panels a row were too small to read the
    first check by), the key in a row's empty place or under the panels."""
    robot, workspace = checker.robot, getattr(checker, "workspace", None)
    if not isinstance(workspace, Workspace):
        raise TypeError(f"this figure draws the checker's workspace, and a {type(checker).__name__} knows none")
    Q = robot.check_configs(Q)  # (k, dof)
    valid = checker.are_valid(Q)  # (k,)
    plane = VIEWS[view] if robot.dim == 3 else (0, 1)
    at = list(plane)
    aabbs = robot.link_aabbs(Q)  # (k, L, 2, D): one window for every panel
    lo = np.maximum(aabbs[:, :, 0].min(axis=(0, 1)) - margin, workspace.lower)
    hi = np.minimum(aabbs[:, :, 1].max(axis=(0, 1)) + margin, workspace.upper)
    columns = columns or len(Q)
    fig, axes, spare = _panels(len(Q), columns, min(float((hi - lo)[at[1]] / (hi - lo)[at[0]]), 1.2))
    said = []
    for ax, q, ok in zip(axes, Q, valid):
        draw_robot(ax, robot, q[None], colors=link_colors(1, ok), view=view, margin=margin)
        for b_lo, b_hi in workspace.boxes[nearby_blocks(workspace, lo, hi)]:
            ax.add_patch(Rectangle(b_lo[at], *(b_hi - b_lo)[at], alpha=0.5, zorder=0.9, **BLOCK_STYLE))
        ax.set(xlim=(lo[at[0]], hi[at[0]]), ylim=(lo[at[1]], hi[at[1]]))
        name_blocks(ax, workspace, nearby_blocks(workspace, lo, hi), at)  # "18 shelf" (r32a)
        found = [] if ok else contacts(robot, workspace, q)  # (link, block, depth) of each pair that touches
        fills = _outline_touching(ax, robot, workspace, q, found, plane)
        _zoom_on_small_fills(ax, fills, robot, q, plane)
        mark_arm(ax, robot, q, view)
        verdict = _valid_panel(ax, checker, q, workspace, view) if ok else _collision_title(robot, workspace, found)
        said.append(verdict.replace("\n", " "))
        ax.set_title(verdict, fontsize=10 if columns < 3 else 9, wrap=True)
        ax.tick_params(labelsize=8)
    filled = any(p.get_gid() == "overlap" for ax in axes for p in ax.patches)
    if any(getattr(ax, "zoomed", False) for ax in axes):  # room under the panels for the inset (reader r50a)
        fig.set_figheight(fig.get_figheight() + 1.7)
    fig.tight_layout(rect=(0, 0 if len(spare) else 0.35 / fig.get_figheight(), 1, 1))
    named = _key(fig, axes, valid, filled, spare[0] if len(spare) else None)
    marked = " Each link that touches a block is outlined thick, and the block it touches dashed." * (not all(valid))
    marked += f" A key {'in the last row' if len(spare) else 'under the panels'} names {', '.join(named)}."
    marked += " The part of the robot inside a block is filled yellow." * filled  # reader r50a: was "light"
    marked += _gap_sentence(axes)
    zoomed = any(getattr(ax, "zoomed", False) for ax in axes)
    marked += " An inset under the panel enlarges a fill too small to see at the panel's scale." * zoomed
    text = f"The {robot.name} robot at {len(Q)} configurations side by side, seen in the {view} plane with the blocks "
    text += "near it, each panel framing the same window, each titled with the exact checker's verdict: " + "; ".join(
        f"configuration {i + 1}, {v}" for i, v in enumerate(said)
    )
    return describe(
        fig, text + "." + marked, [configurations_part(robot, Q, [f"configuration {i + 1}" for i in range(len(Q))])]
    )


def _panels(count: int, columns: int, aspect: float) -> tuple[Figure, list, list]:
    """:func:`verdict_figure`'s figure, its ``count`` panels ``columns`` a row, each row as high as its panels drawn
    to scale (``aspect``: height / width of the window), and the last row's empty places, unframed."""
    rows = -(-count // columns)
    high = PAGE_WIDTH / count + 0.6 if rows == 1 else rows * ((PAGE_WIDTH / columns - 0.8) * aspect + 1.0)
    fig = Figure(figsize=(PAGE_WIDTH, high))
    grid = list(fig.subplots(rows, columns, squeeze=False).ravel())
    for ax in grid[count:]:
        ax.set_axis_off()
    return fig, grid[:count], grid[count:]


def _key(fig: Figure, axes, valid: np.ndarray, filled: bool, place=None) -> list[str]:
    """A key right under :func:`verdict_figure`'s panels (drawn to scale, they need not fill their rows), or in the
    empty ``place`` of their last row, naming what they draw (review r39a: the nudge's panels had none, the first
    check's lived in the paragraph); its names."""
    handles: dict[str, Any] = {"block": Patch(alpha=0.5, **BLOCK_STYLE)}
    handles |= {"valid": Patch(**link_style(VALID_COLOR))} if valid.any() else {}
    if not valid.all():
        handles["in collision"] = Patch(**link_style(INVALID_COLOR))
        handles["block touched"] = Patch(fill=False, edgecolor=COLORS["ink"], linewidth=2, linestyle="--")
    handles |= {"inside the block": Patch(facecolor=COLORS["overlap"], edgecolor=COLORS["ink"])} if filled else {}
    if place is not None:
        place.legend(list(handles.values()), list(handles), loc="center", fontsize=9, frameon=False)
        return list(handles)
    fig.draw_without_rendering()  # the panels' places, drawn to scale
    under = min(ax.get_tightbbox().y0 for ax in axes) / fig.bbox.height
    key: dict[str, Any] = dict(bbox_to_anchor=(0.5, under), ncol=len(handles), fontsize=8, frameon=False)
    fig.legend(list(handles.values()), list(handles), loc="upper center", **key)
    return list(handles)


def _valid_panel(ax, checker: CollisionChecker, q: np.ndarray, ws: Workspace, view: str) -> str:
    """A valid panel's gap drawn (:func:`_mark_gap`) where it can be, and its title (:func:`_valid_title`)."""
    _mark_gap(ax, checker, ws, q, view)
    return _valid_title(checker, q, ws)


def _gap_sentence(axes) -> str:
    """The alt text's sentence on each panel whose gap :func:`_mark_gap` drew, numbered from 1."""
    gaps = [i + 1 for i, ax in enumerate(axes) if any(line.get_gid() == "gap" for line in ax.lines)]
    return "".join(f" In configuration {i}'s panel a labelled segment draws its gap to a block." for i in gaps)


def _valid_title(checker: CollisionChecker, q: np.ndarray, ws: Workspace) -> str:
    """A valid panel's title, with the checker's clearance where it proves one: a hairline gap is invisible at the
    page's width, and a panel titled "valid" that looks touching needs its gap said (review r29a); called a lower bound,
    since the true gap can be wider (reader r42a), except for the point robot, whose square never turns: the distance
    between axis-aligned boxes that bounds it is its gap (reader r43a: the first check's 0.2 is exact). A turning
    robot's title gives the bound to the blocks alone, the gap a view can draw (reader r55a: its 0.15 was the arm's
    height above the floor, the platform 0.02 above it, beside a drawn gap of 0.43 to a shelf)."""
    cap = 1.0
    gap = float(checker.clearances(q[None], cap=cap)[0])
    if gap <= 0:
        return "valid"
    if is_point_robot(checker.robot) and gap < cap:
        return f"valid: {gap:.2g} clear of the nearest\nblock or the region's boundary"
    bound = blocks_bound(checker, q, ws, cap)
    return f"valid; at least {bound:.2g} from every block\n(a lower bound: the gap can be wider)"


def blocks_bound(checker: CollisionChecker, q: np.ndarray, ws: Workspace, cap: float = 1.0) -> float:
    """The exact checker's lower bound on the gap from the robot at ``q (dof,)`` to the blocks alone, up to ``cap``:
    its clearance in the region made ``cap`` wider on every side, so that no wall or floor is nearer than a block."""
    wide = Workspace(ws.lower - cap, ws.upper + cap, ws.boxes)
    return float(exact_checker(wide, checker.robot).clearances(q[None], cap=cap)[0])


def _mark_gap(ax, checker: CollisionChecker, ws: Workspace, q: np.ndarray, view: str) -> bool:
    """In a valid panel from above, a turning 3D robot's gap to the nearest block drawn as a labelled ink segment
    between the closest points found (reader r55a: "the gap drawn beside it" had no mark), if the gap runs mostly
    in the view's plane and is under 1; whether one was drawn."""
    robot = checker.robot
    if robot.dim != 3 or view != "xy" or is_point_robot(robot) or not len(ws.boxes):
        return False
    start, end, length = closest_pair(robot, q, ws.boxes)
    flat = np.linalg.norm((end - start)[:2])
    if not 0 < length < 1.0 or flat < 0.9 * length:
        return False
    ends = np.stack([start[:2], end[:2]])  # (2, 2)
    ax.plot(*ends.T, color=COLORS["ink"], linewidth=1.8, marker="|", markersize=9, zorder=6, gid="gap")
    label = f"gap ≥ {blocks_bound(checker, q, ws):.2g}"
    box = dict(boxstyle="round,pad=0.15", facecolor=COLORS["free"], edgecolor=COLORS["ink"], linewidth=0.6)
    ax.annotate(
        label,
        ends.mean(axis=0),
        xytext=(-8, -12),  # left of the segment and under it, off the robot drawn right of the block here
        textcoords="offset points",
        ha="right",
        fontsize=8,
        bbox=box,
        zorder=7,
        gid="gap label",
    )
    return True


def _outline_touching(
    ax, robot: BoxRobot, workspace: Workspace, q: np.ndarray, found, plane: tuple[int, int]
) -> list[tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]]:
    """Outline thick each link box of ``found`` (link, block, depth) at ``q`` and, dashed, the block it touches; a
    link's part inside the block filled where the flat view shows it exactly (review r31a: "0.2 into the block"
    looked as if it touched): in 2D, and from above for a link that only turns about z (review r40a: the youBot's
    platform "overlaps by 0.078" unseen), whose overlap is its shadow's times a height. Returns each fill with its
    link's outline and its block's corners in the view (fill, link, block lo, block hi)."""
    centers, rotations, half = robot.link_boxes(q[None])
    thick: dict[str, Any] = dict(fill=False, edgecolor=COLORS["ink"], linewidth=2.5)
    at = list(plane)
    fills = []
    for link, block, depth in found:
        b_lo, b_hi = workspace.boxes[block]
        ax.add_patch(Rectangle(b_lo[at], *(b_hi - b_lo)[at], linestyle="--", gid="touched block", zorder=4, **thick))
        corners = outline(box_corners(centers[0, link], rotations[0, link], half[link]), plane)
        ax.add_patch(Polygon(corners, gid="touching link", zorder=5, **thick))
        upright = robot.dim == 3 and plane == (0, 1) and abs(rotations[0, link, 2, 2]) > 1 - 1e-9
        exact = robot.dim == 2 or upright  # elsewhere a shadow's overlap need not be the boxes' own: nothing filled
        inside = clip_to_box(corners, b_lo[at], b_hi[at]) if exact and depth > 0 else np.zeros((0, 2))
        if len(inside) > 2:
            ax.add_patch(Polygon(inside, gid="overlap", zorder=6, **OVERLAP_STYLE))  # over the outlines
            fills.append((inside, corners, b_lo[at], b_hi[at]))
    return fills


OVERLAP_STYLE: dict[str, Any] = dict(facecolor=COLORS["overlap"], edgecolor=COLORS["ink"], linewidth=1)


def _zoom_on_small_fills(ax, fills, robot: BoxRobot, q: np.ndarray, plane: tuple[int, int]) -> None:
    """An inset enlarging a fill under a twentieth of the panel's width (review r40a: 0.078 of overlap was a few
    pixels at a corner), under the panel, out of its data area (reader r50a: inside the room it read at first as a
    second block and robot), its window marked in the panel; framed heavy (reader r42a)."""
    if not fills:
        return
    points = np.concatenate([f[0] for f in fills])  # (m, 2)
    f_lo, f_hi = points.min(axis=0), points.max(axis=0)
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    if (f_hi - f_lo).max() >= (x1 - x0) / 20:
        return
    half = max((f_hi - f_lo).max() * 1.5, (x1 - x0) / 40)
    mid = (f_lo + f_hi) / 2
    w, h, at = INSET, INSET_HIGH, ((1 - INSET) / 2, -INSET_HIGH - 0.2)  # under the x axis's ticks and label
    wide = w * (x1 - x0) / (h * (y1 - y0))  # the inset's width / height, in data units as on the page
    half_x, half_y = half * max(1.0, wide), half * max(1.0, wide) / wide
    inset = ax.inset_axes([*at, w, h])
    for fill, link, b_lo, b_hi in fills:
        inset.add_patch(Rectangle(b_lo, *(b_hi - b_lo), alpha=0.5, zorder=0.9, **BLOCK_STYLE))
        inset.add_patch(Rectangle(b_lo, *(b_hi - b_lo), fill=False, edgecolor=COLORS["ink"], linewidth=2, ls="--"))
        inset.add_patch(Polygon(link, linewidth=2, **link_style(INVALID_COLOR)))
        inset.add_patch(Polygon(fill, gid="overlap", zorder=6, **OVERLAP_STYLE))
    inset.set(xlim=(mid[0] - half_x, mid[0] + half_x), ylim=(mid[1] - half_y, mid[1] + half_y), xticks=[], yticks=[])
    inset.set_aspect("equal")
    inset.set_facecolor(INSET_BACKGROUND)  # reader r42a: unframed, the inset read as a block and a robot in the room
    for spine in inset.spines.values():
        spine.set(linewidth=2.5, edgecolor=COLORS["ink"])
    inset.set_xlabel(f"zoom x{w * (x1 - x0) / (2 * half_x):.0f}", fontsize=9, labelpad=3)  # under it: the axis above
    marker = ax.indicate_inset_zoom(inset, edgecolor=COLORS["ink"], linewidth=1.2, alpha=1)
    marker.set_zorder(7)  # reader r45a: its connectors ran under the robot, unseen; now over it, under the inset
    inset.set_zorder(8)
    ax.zoomed = True


def mark_arm(ax, robot: BoxRobot, q: np.ndarray, view: str) -> None:
    """Label the youBot's arm in a flat view: a few pixels on its platform, it went unseen (review r31a)."""
    if robot.name != "youbot" or view not in VIEWS:
        return
    at = robot.link_boxes(q[None])[0][0, 1:][:, list(VIEWS[view])].mean(axis=0)  # (2,) the arm links' mean centre
    box = dict(boxstyle="round,pad=0.15", facecolor=COLORS["free"], edgecolor=COLORS["ink"], linewidth=0.6)
    arrow = dict(arrowstyle="-", color=COLORS["ink"], linewidth=0.8)
    ax.annotate("arm", at, xytext=(14, 14), textcoords="offset points", fontsize=8, bbox=box, arrowprops=arrow)


def _collision_title(robot: BoxRobot, workspace: Workspace, found) -> str:
    """An in-collision panel's title: each (link, block, depth) of ``found`` named, or the region left."""
    named = [f"{_part(robot, link)} {_met(workspace, block, depth)}" for link, block, depth in found]
    return "in collision:\n" + ("; ".join(named) or "leaves the region")


def _met(workspace: Workspace, block: int, depth: float) -> str:
    """How a link meets a block in a title: "touches block 0" at depth 0, else "overlaps block 0 by 0.2"."""
    return f"{'overlaps' if depth > 1e-9 else 'touches'} block {block}{_kind(workspace, block)}" + (
        f" by {depth:.2g}" if depth > 1e-9 else ""
    )


def _kind(workspace: Workspace, block: int) -> str:
    """A block's kind in brackets where the workspace names kinds (the office's furniture), else nothing."""
    return f" ({workspace.labels[block]})" if workspace.labels else ""


def _part(robot: BoxRobot, link: int) -> str:
    """A link in a title: the youBot's and the point robot's by name, a chain's numbered from 0 as ``link_boxes``."""
    return PARTS[robot.name][link] if robot.name in PARTS else f"link {link}"
