"""Where a drawn robot meets a block: which link boxes touch which blocks, how deep they overlap, and the part of a
flat shape inside a block (the figure of one check, :func:`toolkit.plots.verdict.verdict_figure`).

Separating axes, as ``SeparatingAxisChecker``: two boxes are apart exactly when some axis separates their shadows,
among the world's axes, the link's and, in 3D, their cross products; the least overlap of the shadows along those
axes is how far the link must move to clear the block (closed boxes: touching counts, at depth 0).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.patches import Patch, Rectangle

from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace
from toolkit.plots.boxes import box_corners, outline
from toolkit.plots.palette import COLORS, halo


def nearby_blocks(workspace: Workspace, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """Indices of the blocks that meet the axis-aligned window ``[lo, hi]`` (D,)."""
    return np.flatnonzero(np.all((workspace.boxes[:, 0] <= hi) & (workspace.boxes[:, 1] >= lo), axis=1))


def contacts(robot: BoxRobot, workspace: Workspace, q) -> list[tuple[int, int, float]]:
    """The (link, block, depth) of each link box and block that touch at configuration ``q (dof,)``: ``depth`` is
    how far the link must move to clear the block, 0 where they only touch."""
    Q = robot.check_configs(q)[:1]  # (1, dof)
    centers, rotations, half = robot.link_boxes(Q)  # (1, L, D), (1, L, D, D), (L, D)
    found = []
    for link, (center, rotation, h, (lo, hi)) in enumerate(zip(centers[0], rotations[0], half, robot.link_aabbs(Q)[0])):
        own = rotation.T  # (D, D) rows: the link's axes
        axes = [np.eye(robot.dim), own]
        if robot.dim == 3:
            axes.append(np.cross(np.eye(3)[:, None, :], own[None, :, :]).reshape(9, 3))
        axis = np.concatenate(axes)  # (A, D)
        length = np.linalg.norm(axis, axis=1)  # (A,) a cross product of parallel axes is 0: no axis
        axis = axis[length > 1e-9] / length[length > 1e-9, None]
        for block in nearby_blocks(workspace, lo, hi):
            b_lo, b_hi = workspace.boxes[block]
            gap = np.abs(axis @ (center - (b_lo + b_hi) / 2))  # (A,)
            reach = np.abs(axis @ own.T) @ h + np.abs(axis) @ ((b_hi - b_lo) / 2)  # (A,)
            if not np.any(gap > reach + 1e-12 * (1 + reach)):
                found.append((link, int(block), float(max(0.0, (reach - gap).min()))))
    return found


def touching(robot: BoxRobot, workspace: Workspace, q) -> list[tuple[int, int]]:
    """The (link, block) pairs whose boxes touch at configuration ``q (dof,)``: closed boxes, so touching counts."""
    return [(link, block) for link, block, _ in contacts(robot, workspace, q)]


def passed_over(robot: BoxRobot, workspace: Workspace, q, plane: tuple[int, int]) -> np.ndarray:
    """Which blocks ``(K,) bool`` a flat view onto ``plane`` draws across a link of a 3D robot at ``q (dof,)`` although
    no link touches them: each passes wholly over or under (in front of or behind) every link it is drawn across,
    since a link's part inside the block's prism is one convex piece that misses the block (review r34a: judged by
    the links' bounding boxes, a block above a tilted link was drawn filled across a valid robot)."""
    centers, rotations, half = robot.link_boxes(robot.check_configs(q)[:1])  # (1, L, D), (1, L, D, D), (L, D)
    shadows = [outline(box_corners(c, r, h), plane) for c, r, h in zip(centers[0], rotations[0], half)]
    touched = {block for _, block, _ in contacts(robot, workspace, q)}
    at = list(plane)
    over = np.zeros(len(workspace.boxes), dtype=bool)
    for k, (b_lo, b_hi) in enumerate(workspace.boxes):
        over[k] = k not in touched and any(_area(clip_to_box(s, b_lo[at], b_hi[at])) > 1e-12 for s in shadows)
    return over


TOUCHED: dict[str, Any] = dict(fill=False, edgecolor=COLORS["ink"], linewidth=2.5, linestyle="--")


def key_blocks(ax, robot: BoxRobot, workspace: Workspace, q, plane: tuple[int, int], dotted: bool) -> int:
    """Outline dashed each block a link touches at ``q (dof,)`` in a flat view onto ``plane``, as the figure of one
    check does, and key the panel below it: grey, a block; dotted, one the links pass over or under (in front or
    behind, from the side); dashed, one a link touches; each entry only where such a block is drawn (review r37a:
    grey blocks beside a valid robot read as touched). Grey is a block beside the links, at any height (r48a, r51a).
    Returns how many blocks are dashed."""
    at = list(plane)
    touched = sorted({block for _, block, _ in contacts(robot, workspace, q)})
    for b_lo, b_hi in workspace.boxes[touched]:
        ax.add_patch(Rectangle(b_lo[at], *(b_hi - b_lo)[at], gid="touched block", zorder=4, **TOUCHED))
    depth = "height" if plane == (0, 1) else "depth"  # reader r48a: a block far above the base drawn like one beside it
    key = {
        f"grey: a block beside the links (any {depth})": Patch(
            facecolor=COLORS["block"], edgecolor=COLORS["occupied"], alpha=0.5
        )
    }
    if dotted:
        past = "over or under" if plane == (0, 1) else "in front or behind"
        key[f"dotted: the links pass {past}"] = Patch(fill=False, linestyle=":", edgecolor=COLORS["occupied"])
    if touched:
        key["dashed: a link touches it"] = Patch(**TOUCHED)
    ax.legend(key.values(), key.keys(), fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.16), frameon=False)
    return len(touched)


def _area(polygon: np.ndarray) -> float:
    """The area of a polygon ``(n, 2)`` (0 for fewer than three corners: shadows that only touch)."""
    x, y = polygon.T if len(polygon) > 2 else np.zeros((2, 0))
    return 0.5 * abs(float(x @ np.roll(y, -1) - y @ np.roll(x, -1)))


def clip_to_box(polygon: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """The part of a convex ``polygon (n, 2)`` inside the rectangle ``[lo, hi]`` (2,), as a polygon ``(m, 2)``
    (empty where they do not overlap): each side of the rectangle cuts away what lies beyond it."""
    for k in range(2):
        for sign, bound in ((1.0, hi[k]), (-1.0, lo[k])):
            inside = sign * (polygon[:, k] - bound) <= 0  # (n,)
            kept = []
            for i in range(len(polygon)):
                a, b = polygon[i], polygon[(i + 1) % len(polygon)]
                if inside[i]:
                    kept.append(a)
                if inside[i] != inside[(i + 1) % len(polygon)]:  # the side crosses the bound: keep the crossing
                    kept.append(a + (b - a) * (bound - a[k]) / (b[k] - a[k]))
            polygon = np.array(kept).reshape(-1, 2)
            if not len(polygon):
                return polygon
    return polygon


def name_blocks(ax, workspace: Workspace, blocks: np.ndarray, plane: list[int]) -> None:
    """Write each of ``blocks``' number and furniture type ("18 shelf") at the middle of its part inside ``ax``'s
    window, in a flat view onto ``plane``, where the workspace names kinds (review r32a: a clipped shelf drawn grey,
    unnamed, beside a title that named it)."""
    if not workspace.labels:
        return
    window = np.array([ax.get_xlim(), ax.get_ylim()]).T  # (2, 2): low corner, high corner
    box = dict(boxstyle="round,pad=0.1", facecolor=COLORS["free"], edgecolor="none", alpha=0.8)
    for k in blocks:
        lo, hi = (
            np.maximum(workspace.boxes[k, 0, plane], window[0]),
            np.minimum(workspace.boxes[k, 1, plane], window[1]),
        )
        middle = (lo + hi) / 2
        ax.text(*middle, f"{k} {workspace.labels[k]}", fontsize=7, ha="center", va="center", bbox=box, gid="name")


def ring_blocks(ax, workspace: Workspace, kind: str | None, z: float | None = None) -> int:
    """Ring each block of ``kind`` (``workspace.labels``) in a flat view from above, those that reach the height
    ``z`` in 3D (review r39a: the office's chairs, one cell each of a 4-pixel grid, were not to be told from other
    small furniture); returns how many were ringed (none where ``kind`` is None)."""
    if kind is None:
        return 0
    picked = np.array([label == kind for label in workspace.labels or []], dtype=bool)
    boxes = workspace.boxes[picked] if picked.any() else workspace.boxes[:0]  # (M, 2, D)
    if z is not None:
        boxes = boxes[(boxes[:, 0, 2] <= z) & (boxes[:, 1, 2] >= z)]
    middles = boxes[:, :, :2].mean(axis=1)  # (M, 2)
    ring = dict(marker="o", markersize=13, markerfacecolor="none", markeredgewidth=2, linestyle="")
    ring["path_effects"] = halo(2.0, ("free",))  # black, ringed white: seen on a dark cell and a light one alike
    ax.plot(middles[:, 0], middles[:, 1], color=COLORS["ink"], gid="ring", **ring)  # not orange: r50a
    return len(boxes)
