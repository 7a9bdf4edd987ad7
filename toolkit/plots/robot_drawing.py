"""Drawing a robot: its link boxes at configurations, among the blocks near it (paper §IV-A; notebooks 01, 05).

Forward kinematics (``robot.link_boxes``) places each link box; :func:`draw_robot` draws them, and the blocks near
them, on an axes of your own, in 3D or projected onto a plane (the building block of :func:`robot_figure`, one panel
per view with a legend naming the configurations, of :func:`toolkit.plots.cspace.cspace_slice` and
:mod:`toolkit.plots.scenes` and :func:`toolkit.plots.verdict.verdict_figure`, configurations side by side with a
checker's verdict on each).

A configuration is drawn in the valid colour or, hatched, the invalid one (:func:`link_style`: colour is never the
only cue), else in a colour and hatch of its own. Each box is drawn from its corners (:mod:`toolkit.plots.boxes`).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Polygon, Rectangle
from matplotlib.patheffects import Normal, Stroke

from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace
from toolkit.plots.alt import Part, describe
from toolkit.plots.boxes import aabb_corners, add_box_3d, box_corners, outline
from toolkit.plots.contact import nearby_blocks
from toolkit.plots.palette import COLORS, OKABE_ITO, PAGE_WIDTH

VALID_COLOR, INVALID_COLOR = COLORS["valid"], COLORS["invalid"]
BLOCK_STYLE: dict[str, Any] = dict(facecolor=COLORS["block"], edgecolor=COLORS["occupied"], gid="block")


def link_style(color: str, hatch: str | None = None) -> dict:
    """A link's face and edge; a link in collision is hatched too (colour is never the only cue), and so is each
    configuration a legend names (``hatch``)."""
    hatch = "xx" if color == INVALID_COLOR else hatch or None
    return dict(facecolor=color, edgecolor=COLORS["ink"], hatch=hatch, hatchcolor=hatch_ink(color))


def hatch_ink(color: str) -> str:
    """The colour of a hatch on a face of ``color``: white on the black and dark grey of :data:`KEY_COLORS`, where
    a black hatch would not show (reader r47a), else black."""
    return COLORS["free"] if color in (COLORS["ink"], COLORS["rejected"]) else COLORS["ink"]


VIEWS = {"xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}
FLAT_ALPHA = 0.85  # a link's opacity in a flat view, and its legend swatch's: black link 3's hatch shows (r47a)
POSITION_NAMES = ("x", "y", "z")
KEY_HATCHES = ("", "//", "..", "--", "\\\\", "||")
"""Hatches that only tell things apart (links, poses, furniture kinds), in :data:`KEY_COLORS`' order: the
palette's, less the in-collision cross-hatch "xx" and its look-alike "++" (reader r48a: desks, chain9's link 3)."""
KEY_COLORS = (OKABE_ITO["bluish green"], COLORS["ink"], COLORS["rejected"], COLORS["free"])
"""Colours that only tell things apart (links, poses): bluish green, black, a dark grey and white, never the
verdict's blue or orange, so that orange means "in collision" on every figure (reader r50a: chain7's orange link 1
over its blue link 0, where the text says that overlap is no collision); every two stay apart in each colour
vision (``tests/test_plots_cspace.py``)."""

KIND_SHADES = (
    (OKABE_ITO["bluish green"], "--"),  # cabinets
    (COLORS["ink"], ""),  # chairs: black (r40a: orange specks unseen), where no hatch would show
    (COLORS["free"], "||"),  # desks: white
    (OKABE_ITO["reddish purple"], ".."),  # shelves
    (COLORS["block"], "//"),  # tables: a block's grey (reader r51a: yellow meant "inside the block" too)
    (COLORS["rejected"], "\\\\"),  # walls: dark grey
)
"""The office's furniture kinds (sorted), each in a colour and a hatch of its own (its picture in
:func:`toolkit.plots.cspace.workspace_figure`), never the verdict's blue, orange or cross-hatch (reader r50a)."""


def dof_label(name: str) -> str:
    """A DoF's axis label with its unit: a position in the workspace's units as is, an angle with "(rad)"."""
    return name if name in POSITION_NAMES else f"{name} (rad)"


def few_ticks(ax) -> None:
    """A 3D axes with a few tick labels per axis, at 8 points: they do not run into each other (a flat region, as
    the office's 41 x 41 x 6, gets its z axis labelled at its ends only)."""
    ax.locator_params(nbins=4)
    ax.tick_params(labelsize=8)
    aspect = ax.get_box_aspect()  # (3,) the drawn lengths of x, y, z
    if aspect is not None and aspect[2] < 0.3 * max(aspect[:2]):
        ax.set_zticks(ax.get_zlim())
        ax.zaxis.labelpad = 2


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
    clip: bool = False,
    shades: Sequence[tuple[str, str | None] | None] | None = None,
) -> None:
    """Draw the link boxes of configurations ``Q (k, dof)``, one colour each, and the blocks within ``margin`` of them,
    on one axes (building :func:`robot_figure`, :func:`toolkit.plots.cspace.cspace_slice` and the scene figures).

    ``view``: ``"3d"`` (``ax`` an mplot3d axes) or a plane ``"xy"``, ``"xz"``, ``"yz"`` (the shadow of each box,
    drawn far to near as seen from the page's front: in ``"xy"`` from above, so the highest link lies on top).
    Links have gid ``"link"``, blocks gid ``"block"``; the axes' limits frame them. ``hatches``: one hatch per
    configuration (a second cue where colours tell configurations apart). ``clip``: in 3D, only each block's part
    inside the window (mplot3d draws past its axes, over their tick labels). ``shades``: per link, a face colour and
    hatch that replace the configuration's (a link the same in every configuration, a link of one size)."""
    Q = robot.check_configs(Q)  # (k, dof)
    if view != "3d" and view not in VIEWS:
        raise ValueError(f"unknown view {view!r}; choose '3d' or one of {sorted(VIEWS)}")
    if len(colors) != len(Q):
        raise ValueError(f"{len(colors)} colours for {len(Q)} configurations: give one colour a configuration")
    centers, rotations, half = robot.link_boxes(Q)  # (k, L, D), (k, L, D, D), (L, D)
    lo, hi, blocks = _window(robot.link_aabbs(Q), workspace, margin)  # (D,), (D,), (K, 2, D)
    hatches = hatches if hatches is not None else [None] * len(Q)
    shades = shades if shades is not None else [None] * robot.n_links
    link_boxes = [
        (box_corners(c, r, h), *(shade or (color, hatch)))
        for cs, rs, color, hatch in zip(centers, rotations, colors, hatches)
        for c, r, h, shade in zip(cs, rs, half, shades)
    ]
    if view == "3d":
        for b_lo, b_hi in np.clip(blocks, lo, hi) if clip else blocks:
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
            Polygon(outline(corners, axes), linewidth=0.6, alpha=FLAT_ALPHA, gid="link", **link_style(color, hatch))
        )
    ax.set_xlim(lo[axes[0]], hi[axes[0]])
    ax.set_ylim(lo[axes[1]], hi[axes[1]])
    ax.set_aspect("equal")
    ax.set_xlabel(POSITION_NAMES[axes[0]])
    ax.set_ylabel(POSITION_NAMES[axes[1]])


def _window(aabbs: np.ndarray, workspace: Workspace | None, margin: float):
    """The window round the links' bounds ``aabbs (k, L, 2, D)``, ``margin`` beyond them, inside the workspace, and
    the workspace's blocks in it: ``lo (D,)``, ``hi (D,)``, ``blocks (K, 2, D)``."""
    lo, hi = aabbs[:, :, 0].min(axis=(0, 1)) - margin, aabbs[:, :, 1].max(axis=(0, 1)) + margin  # (D,) window
    if aabbs.shape[-1] == 3:  # every region's floor is z = 0: no window reaches below it unless a link does (r28a)
        lo[2] = max(lo[2], min(0.0, aabbs[:, :, 0, 2].min()))
    if workspace is None:
        return lo, hi, np.zeros((0, 2, aabbs.shape[-1]))
    lo, hi = np.maximum(lo, workspace.lower), np.minimum(hi, workspace.upper)
    return lo, hi, workspace.boxes[nearby_blocks(workspace, lo, hi)]


def link_colors(n: int, valid: np.ndarray | None) -> list[str]:
    """One colour per configuration: valid / invalid by ``valid (n,)``, else :data:`KEY_COLORS` in turn."""
    if valid is None:
        return [KEY_COLORS[k % len(KEY_COLORS)] for k in range(n)]
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
    parts: bool = False,
) -> Figure:
    """The robot's link boxes at configurations ``Q (dof,)`` or ``(k, dof)``, by forward kinematics.

    One panel per view: ``"xy"`` (from above), ``"xz"``, ``"yz"`` (from the side; a box's
    panel shows its shadow, the convex hull of its projected corners) or ``"3d"``.
    Default: ``("xy",)`` for a 2D robot, ``("3d", "xy", "xz")`` for a 3D one. Blocks of
    ``workspace`` within ``margin`` of the robot are drawn too; ``valid (k,)`` colors
    each configuration in the valid colour or, hatched, the invalid one (a legend names them), else each one in a
    colour of its own, named in a legend by ``labels (k,)``, links the same in all of them grey ("the same in each").
    ``parts``: the base marked with a dot, each link in a shade of its own, numbered from the base (r29a, r31a).
    """
    Q = robot.check_configs(Q)  # (k, dof)
    views = views or (("xy",) if robot.dim == 2 else ("3d", "xy", "xz"))
    if labels is not None and len(labels) != len(Q):
        raise ValueError(f"{len(labels)} labels for {len(Q)} configurations: give one label a configuration")
    fig, axes = _panels(views, legend=labels is not None or parts)
    colors = link_colors(len(Q), valid)
    hatches = [KEY_HATCHES[k % len(KEY_HATCHES)] for k in range(len(Q))] if valid is None else [None] * len(Q)
    named = labels is not None and valid is None and len(Q) > 1  # configurations a legend tells apart
    shades, shade_names = _link_shades(robot, Q, named, parts and valid is None)
    ends = robot.link_boxes(Q)[0][:, -1]  # (k, D) the centre of each configuration's last link
    bases = robot.link_frames(Q)[0][:, 0, : robot.dim]  # (k, D) each base's position
    for view in views:
        ax = axes[view]
        draw_robot(
            ax, robot, Q, colors=colors, view=view, workspace=workspace, margin=margin, hatches=hatches, shades=shades
        )
        marks = [(end, _end_mark(k, color)) for k, (end, color) in enumerate(zip(ends, colors))] if named else []
        marks += [(base, BASE_MARK) for base in bases] if parts else []  # thin links hide a hatch: a marker instead
        for where, style in marks:
            ax.plot(*([c] for c in (where if view == "3d" else where[list(VIEWS[view])])), **style)
        if parts and view != "3d":
            _number_links(ax, robot, Q[0], VIEWS[view])
        ax.set_title(f"{robot.name}: {view}", fontsize=10)
        ax.tick_params(labelsize=8)
        if view == "3d":
            few_ticks(ax)
    if labels is None and valid is not None:
        labels = ["valid" if color == VALID_COLOR else "in collision" for color in colors]
    handles = _legend(labels if not parts else None, colors, hatches, named, shade_names, parts)
    lines = _place_key(fig, handles)
    _fit_height(fig, [axes[v] for v in views], lines)
    fig.tight_layout(rect=(0, (0.1 + 0.3 * lines) / fig.get_figheight() if handles else 0, 1, 1))
    text = _robot_figure_text(robot, len(Q), views, workspace is not None, valid, labels, hatches, named)
    text += _shades_text(shade_names, parts)
    return describe(fig, text, [configurations_part(robot, Q, labels)])


def _legend(labels, colors, hatches, named: bool, shade_names: dict, parts: bool) -> dict[str, Any]:
    """:func:`robot_figure`'s legend, name to handle: each labelled configuration (with its end marker where
    ``named``), each shade of :func:`_link_shades`, the base's dot where ``parts``."""
    handles: dict[str, Any] = {}
    for k, (label, c, h) in enumerate(zip(labels or [], colors, hatches)):
        handles[label] = (
            (Patch(**link_style(c, h)), Line2D([], [], **_end_mark(k, c))) if named else Patch(**link_style(c, h))
        )
    handles |= {name: Patch(alpha=FLAT_ALPHA, **link_style(*shade)) for name, shade in shade_names.items()}
    outlines = Line2D([], [], color=HIDDEN_EDGE["edgecolor"], linestyle=HIDDEN_EDGE["linestyle"], linewidth=0.9)
    return handles | ({"base": Line2D([], [], **BASE_MARK), "dashed: link outlines, on top": outlines} if parts else {})


def _place_key(fig: Figure, handles: dict[str, Any]) -> int:
    """The legend under the panels, in one row or, of five names or more, two (the 9-DoF chain's five overran the
    page); its number of rows."""
    lines = 0 if not handles else 1 if len(handles) <= 4 else 2
    if handles:
        key: dict[str, Any] = dict(loc="lower center", ncol=-(-len(handles) // lines), fontsize=9, frameon=False)
        fig.legend(list(handles.values()), list(handles), **key)
    return lines


def _panels(views: tuple[str, ...], legend: bool) -> tuple[Figure, dict]:
    """:func:`robot_figure`'s figure and axes by view: two panels a row; of three, the first tall on the left."""
    columns, rows = min(2, len(views)), -(-len(views) // 2)
    mosaic: list[list[Any]] = [list(views[2 * r : 2 * r + 2]) for r in range(rows)]  # each view once: a panel's name
    if len(views) == 3:
        mosaic = [[views[0], views[1]], [views[0], views[2]]]
    width = min(PAGE_WIDTH, 3.6 * columns)
    fig = Figure(figsize=(width, width / columns * (1.6 if len(views) == 3 else rows) + 0.4 * legend))
    in_3d: dict[str | tuple[str, ...], dict[str, Any]] = {"3d": {"projection": "3d"}} if "3d" in views else {}
    return fig, fig.subplot_mosaic(mosaic, per_subplot_kw=in_3d)


def _fit_height(fig: Figure, axes: list, legend: int) -> None:
    """Flat views only: the figure's height set so that each row's panels, drawn to scale, fill their width (review
    r39a: chain9's two views 140 px wide under a wide legend; the youBot's side view above an empty band). One panel
    alone is never taller than it is wide, and one much wider than tall is drawn wider."""
    if any(ax.name == "3d" for ax in axes):
        return
    columns, rows = min(2, len(axes)), -(-len(axes) // 2)
    ratio = max(np.ptp(ax.get_ylim()) / np.ptp(ax.get_xlim()) for ax in axes)  # the tallest window, height / width
    if columns == 1 and ratio < 0.75:  # one wide panel drawn wider (reader r40a: the youBot's arm in hairlines)
        fig.set_figwidth(PAGE_WIDTH * 0.85)
    drawn = fig.get_figwidth() / columns - 0.7  # inches: a panel's axes, less its y label and ticks
    ratio = min(max(ratio, 0.3), 1.6 if columns > 1 else 1.0)
    fig.set_size_inches(fig.get_figwidth(), rows * (drawn * ratio + 0.8) + (0.1 + 0.3 * legend) * bool(legend))


SHARED_SHADE = (COLORS["shade"], KEY_HATCHES[-1])  # links the same in every configuration (the youBot's platform,
# turret), hatched: beside a plain pose none but that pose is plain (reader r51a)
BASE_MARK: dict[str, Any] = dict(marker="o", ms=7, color=COLORS["ink"], mec=COLORS["free"], ls="", zorder=99)


def _link_shades(robot: BoxRobot, Q: np.ndarray, named: bool, parts: bool):
    """Per link, the colour and hatch replacing its configuration's (or None), and the legend's name of each: links
    the same in every named configuration grey ("the same in each"), or with ``parts`` one shade per link."""
    if parts:  # a shade per link, numbered as link_boxes: two of one size told apart (r31a); link 2 filled (r41a)
        shades = [(KEY_COLORS[i % len(KEY_COLORS)], KEY_HATCHES[i % len(KEY_HATCHES)]) for i in range(robot.n_links)]
        names = {
            f"link {i}: {2 * h.max():g} long": shade for i, (h, shade) in enumerate(zip(robot.half_extents, shades))
        }
        return shades, names
    if not named:
        return None, {}
    centers, rotations, _ = robot.link_boxes(Q)  # (k, L, D), (k, L, D, D)
    same = np.all(np.isclose(centers, centers[:1]), axis=(0, 2)) & np.all(
        np.isclose(rotations, rotations[:1]), axis=(0, 2, 3)
    )  # (L,)
    if not same.any():
        return None, {}
    return [SHARED_SHADE if s else None for s in same], {"the same in each": SHARED_SHADE}


HIDDEN_EDGE: dict[str, Any] = dict(fill=False, edgecolor=COLORS["ink"], linestyle=(0, (3, 2)), linewidth=0.9)
"""A link's outline drawn again on top of every link, dashed in a white halo: a link under another (chain9's link 2
under link 3, from above) still shows its whole shape (reader r53a)."""


def _number_links(ax, robot: BoxRobot, q: np.ndarray, axes: tuple[int, int]) -> None:
    """Each link's number on the flat view, at the centre of its shadow, on top of every link (reader r41a: chain9's
    small link 2, under its neighbours' ends, could not be found from the legend alone), and its outline dashed on
    top (:data:`HIDDEN_EDGE`)."""
    centers, rotations, half = robot.link_boxes(q[None])
    halo = [Stroke(linewidth=2.4, foreground=COLORS["free"]), Normal()]
    for link in range(robot.n_links):
        shadow = outline(box_corners(centers[0, link], rotations[0, link], half[link]), axes)  # (corners, 2)
        ax.add_patch(Polygon(shadow, zorder=97, gid="link outline", path_effects=halo, **HIDDEN_EDGE))
        middle = shadow.mean(axis=0)
        ax.text(
            *middle,
            str(link),
            ha="center",
            va="center",
            fontsize=8,
            fontweight="bold",
            gid="link number",
            zorder=98,
            bbox=dict(boxstyle="circle,pad=0.15", facecolor=COLORS["free"], edgecolor=COLORS["ink"], linewidth=0.6),
        )


def _shades_text(shade_names: dict, parts: bool) -> str:
    """What :func:`_link_shades` changed, for the figure's description."""
    if parts:
        return (
            f" Its base is marked with a black dot; its links from the base ({', '.join(shade_names)}), each shaded"
            " and, in a flat view, numbered on the drawing and outlined dashed on top of every link."
        )
    same = f" Links the same in every configuration are drawn in light grey, {_hatch_name(SHARED_SHADE[1])}"
    return (same + " ('the same in each').") * bool(shade_names)


def _robot_figure_text(robot, count, views, near, valid, labels, hatches, named) -> str:
    """:func:`robot_figure`'s description: what it shows, seen from where, and each configuration's cue (its
    hatch and, when ``named``, the marker on its last link)."""
    text = f"The {robot.name} robot's link boxes at {count} configuration{'s' if count > 1 else ''}"
    seen = ["in 3D" if v == "3d" else f"in the {v} plane" for v in views]
    text += ", seen " + (", ".join(seen[:-1]) + " and " if len(seen) > 1 else "") + seen[-1]
    text += ", with the blocks near it" if near else ""
    if valid is not None:
        n_valid = int(np.sum(np.asarray(valid, dtype=bool)))
        text += f": {n_valid} valid, {count - n_valid} in collision (hatched)"
    elif labels is not None:
        ends_said = [f", its last link marked {END_MARKERS[k % len(END_MARKERS)][1]}" for k in range(count)]
        marked = ends_said if named else [""] * count
        text += ": " + ", ".join(f"{label} ({_hatch_name(h)}{m})" for label, h, m in zip(labels, hatches, marked))
        text += ". A thin link has no room to show a hatch: its marker tells the configurations apart" if named else ""
    return text + "."


END_MARKERS = (("o", "with a circle"), ("s", "with a square"), ("^", "with a triangle"), ("D", "with a diamond"))
"""The marker on each named configuration's last link, in turn, and its name in the figure's description."""


def _end_mark(k: int, color: str) -> dict:
    """The marker of the ``k``-th named configuration, in its colour with a black edge, white on a dark one (seen
    on a black link), ``plot``'s options."""
    edge = dict(markeredgecolor=hatch_ink(color), markeredgewidth=1.2, linestyle="", zorder=5, clip_on=False)
    return dict(marker=END_MARKERS[k % len(END_MARKERS)][0], markersize=8, color=color, **edge)


def configurations_part(robot: BoxRobot, Q: np.ndarray, labels: Sequence[str] | None) -> Part:
    """The drawn configurations ``Q (k, dof)`` as a table: each one's DoF values and where its last link lies."""
    centers = robot.link_boxes(Q)[0][:, -1]  # (k, D) the last link's centre
    names = labels or [f"configuration {i + 1}" for i in range(len(Q))]
    return Part(
        "configurations",
        "each configuration's degrees of freedom, and the centre of its last link in the workspace",
        ("configuration", *robot.dof_names, "last link's centre"),
        tuple(
            (name, *(f"{v:.3g}" for v in q), "(" + ", ".join(f"{c:.3g}" for c in centre) + ")")
            for name, q, centre in zip(names, Q, centers)
        ),
    )


def _hatch_name(hatch: str | None) -> str:
    names = {"": "plain", "//": "hatched with slashes", "..": "dotted", "xx": "cross-hatched", "||": "hatched upright"}
    names |= {"--": "hatched with level lines", "\\\\": "hatched with back-slashes"}
    return names.get(hatch or "", "hatched")
