"""Figures of notebook 05: a planned path of a 3D robot, one frame at a time (paper §III-B, Algorithm 1).

A PRM path is a list of configurations joined by straight lines in configuration space (the straight-line local planner
of §III-B). :func:`scene_still` draws a viewer's scene as a still picture (what a browser without WebGL shows in the 3D
view's place): the whole workspace with its samples and the path, and the robot close up, its panels drawn by
:mod:`toolkit.plots.still_panels`. :func:`path_frame` shows one configuration along a path in the workspace, among the
blocks near the robot (the closest pair marked by :mod:`toolkit.plots.closest_pair`), next to what stays hidden in a 3D
picture, drawn by :mod:`toolkit.plots.path_series`: every degree of freedom along the path, how much room the robot has
(the exact checker's clearance bound) and what a learned model thinks of each configuration (P(valid)). The 3D drawing
of the robot and its nearby blocks is :mod:`toolkit.plots.robot_drawing`'s. Every function returns a matplotlib
``Figure`` and never calls ``show()``.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Patch
from mpl_toolkits.mplot3d import proj3d

from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace
from toolkit.plots.alt import Part, describe
from toolkit.plots.closest_pair import mark_closest
from toolkit.plots.palette import COLORS, PAGE_WIDTH, halo
from toolkit.plots.path_marks import dip_beside, mark_series, node_fractions, per_frame
from toolkit.plots.path_series import draw_series, series_in_words, series_part
from toolkit.plots.robot_drawing import INVALID_COLOR, VALID_COLOR, draw_robot, link_style
from toolkit.plots.still_panels import (
    CLOSE_UP_SCALE,
    NEAR,
    SAMPLE_WORDS,
    TRACE_STYLE,
    clear_turn,
    close_up,
    dangerous_mask,
    draw_points,
    flat,
    inside_mask,
    mark_nearest,
    model_words,
    on_floor,
    over_robot,
    overview,
    overview_step,
    star_on_mark,
)

UNCHECKED_COLOR = COLORS["unchecked"]  # the robot when no validity is given
_STATE = {None: "", True: ", valid", False: ", in collision"}  # a pose's verdict, as a title and its text say it
_POSE_COLOR = {None: UNCHECKED_COLOR, True: VALID_COLOR, False: INVALID_COLOR}  # a pose's links, by its verdict
FRAME_TURNS = (0.0, 30.0, -60.0, 90.0, -90.0, 180.0)  # degrees: a path frame's camera, turned the least it can from
#   mplot3d's azimuth of -60, never to within 20 degrees of an axis (reader r19c: seen along x, its ticks crowded "5 x")
CLOSE_UP_HEIGHT = 3.2  # inches: a row of two close-ups
SINGLE_CLOSE_UP_HEIGHT = 3.6  # inches: a single pose's close-up, a row of its own (reader r31e)
FLAT_OVERVIEW_HEIGHT = 4.0  # inches: the overview of a flat workspace (still_panels.flat), drawn larger
OVERVIEW_HEIGHT = 5.0  # inches: the overview, a row of its own (review r16c: in half a row, 230 px, stars were lost)
OVERVIEW_COLUMNS = ("what", "in the workspace or sample set", "drawn in the overview")  # r51e: not "what is drawn"


def scene_still(
    robot: BoxRobot,
    workspace: Workspace,
    poses: dict[str, np.ndarray],
    *,
    valid: dict[str, bool] | None = None,
    samples: tuple[np.ndarray, dict[str, np.ndarray]] | None = None,
    trace: np.ndarray | None = None,
    margin: float = 0.6,
    model: dict[str, tuple[float, bool]] | None = None,
    close: tuple[str, ...] | None = None,
) -> Figure:
    """A viewer's 3D scene as a still picture: the whole workspace, its blocks, the ``samples`` at their base
    (``(points (N, 3), {kind: mask (N,)})``, kinds as :func:`toolkit.viewer.drawing.sample_kinds` names them: circles
    valid, diamonds in collision, sparkles round them where a model is wrong), the ``trace (T, 3)`` of the robot's
    base along a path (dashed) and the robot drawn over them at each pose, labelled (a single pose ringed, its name
    beside the region: :func:`_ring_the_robot`); and the robot close up at each pose
    ``{label: q (dof,)}`` (:func:`toolkit.plots.still_panels.close_up`: opaque links in the valid colour, or the
    invalid one hatched, by ``valid``; its joints dotted; the blocks within ``margin``, those near a link darker), with
    the samples inside its window and the trace; where a ``model`` gives a pose's ``(P(valid), predicted valid)``,
    its close-up's title says what the model answers (review r17c: nothing marked that it rejects a valid pose).
    ``close`` names the poses seen close up (default: every one; a path's start and goal, reader r25b: its "goal"
    close-up sat alone in a third row).
    A single pose is seen once, a whole row wide, above the overview (reader r31e: two views side by side were about
    200 px each, the robot a few pixels tall); several follow it, two a row. Of more than
    :data:`~toolkit.plots.still_panels.OVERVIEW_SAMPLES` samples the overview draws every k-th (its title says which
    k), of every kind alike."""
    if robot.dim != 3:
        raise ValueError(f"a scene's still is drawn in 3D; the {robot.name} robot moves in {robot.dim}D")
    valid = valid or {}
    colors = {label: _POSE_COLOR[valid.get(label)] for label in poses}
    views = [(label, np.asarray(q, dtype=float)) for label, q in poses.items() if close is None or label in close]
    first = -(-len(views) // 2) if len(poses) == 1 else 0  # the overview's row: after a single pose's view
    fig, panels = _still_panels(len(views), first, flat(workspace))
    at = min(2 * first, len(views))  # the overview's panel: after the close-ups of the rows before it
    named = {_overview_name(label, len(poses), valid.get(label)): (q, colors[label]) for label, q in poses.items()}
    overview(panels.pop(at), robot, workspace, named, samples, trace)
    if len(poses) == 1:
        _ring_the_robot(fig.axes[at], robot, workspace, views[0][1])
    # pose -> (samples drawn in its close-up, blocks near it, the camera's elevation and azimuth)
    seen: dict[str, tuple[int, int, tuple[float, float]]] = {}
    moved = False  # a z axis moved, maybe beside the other view's: the panels further apart
    for ax, (label, q) in zip(panels, views):
        ok = valid.get(label)
        camera = next(iter(seen.values()))[2] if seen else None  # reader r34e: each close-up seen from the first's
        near, angles = close_up(ax, robot, q, workspace, color=colors[label], margin=margin, view=camera)
        hide = None if samples is None else over_robot(ax, robot, q, samples[0])  # (N,) marks over the robot
        drawn = draw_points(ax, samples, trace, clip=True, scale=CLOSE_UP_SCALE, hide=hide)
        seen.setdefault(label, (drawn, near, angles))
        if len(views) > 1:  # reader r39e: half a row wide, its ticks crowded; r41e: but with none, no scale
            ax.locator_params(nbins=2)
            ax.tick_params(labelsize=8, pad=0)
        else:
            moved |= _z_apart(ax)  # reader r29e: a close-up's z ticks stood over its y ticks
        verdict = model_words((model or {}).get(label), ok)
        ax.set_title(f"{label}, close up{_STATE[ok]}{verdict}", fontsize=10)
    _still_legend(fig, valid, h_pad=4.0 if first else 1.5, w_pad=8.0 if moved else 5.0, close_ups=panels)  # r25b
    described = _still_described(robot, workspace, poses, valid, samples, trace, seen, model or {})
    return describe(fig, *described)


def _z_apart(ax) -> bool:
    """A close-up's z axis moved to the panel's other side where its ticks stand over the y axis' on one edge
    (readers r28e, r29e: stacked there, the z and y ticks read as one axis); whether it moved."""

    def stacked() -> bool:
        z, y = ax.zaxis.get_tightbbox(), ax.yaxis.get_tightbbox()
        return z is not None and y is not None and z.x0 < y.x1 and y.x0 < z.x1  # sharing a strip of the panel

    for position in ("lower", "upper", "default"):  # the default last: where neither other side helps
        if not stacked():
            return position != "lower"
        ax.zaxis.set_ticks_position(position)
        ax.zaxis.set_label_position(position)
    return False


def _still_panels(views: int, first: int, is_flat: bool) -> tuple[Figure, list]:
    """A still's figure and its 3D panels in reading order: the close-ups of ``views`` poses two a row, and the
    overview a whole row of its own (its stars show) at row ``first``, shorter for a flat workspace (r25b: the
    office's flat box left half its panel blank); a single close-up a whole row too (reader r31e)."""
    heights = [SINGLE_CLOSE_UP_HEIGHT if views == 1 else CLOSE_UP_HEIGHT] * -(-views // 2)  # inches: two a row
    heights.insert(first, FLAT_OVERVIEW_HEIGHT if is_flat else OVERVIEW_HEIGHT)
    fig = Figure(figsize=(PAGE_WIDTH, sum(heights) + 0.9))  # as wide as the page: text as drawn
    grid = fig.add_gridspec(len(heights), 2, height_ratios=heights)
    whole = {first} | (set(range(len(heights))) if views == 1 else set())  # the rows of a single panel
    cells = [grid[row, :] if row in whole else grid[row, column] for row in range(len(heights)) for column in (0, 1)]
    cells = [cell for k, cell in enumerate(cells) if k % 2 == 0 or k // 2 not in whole][: 1 + views]  # reading order
    return fig, [fig.add_subplot(cell, projection="3d") for cell in cells]


def _ring_the_robot(ax, robot: BoxRobot, workspace: Workspace, q: np.ndarray) -> None:
    """A single pose's overview: a ring round the robot at ``q (dof,)`` and its name moved out of the region, left
    of it at the robot's height (the right holds the y and z axes' ticks), a leader from the name to the ring (reader
    r23b: in a cube of 123 blocks the robot, about 10 px tall, was hard to find, and its name over it sat on marks)."""
    (label,) = [text for text in ax.texts if text.get_gid() == "pose label"]
    centre = robot.link_aabbs(np.asarray(q, dtype=float)[None])[0].mean(axis=(0, 1))  # (3,) the links' boxes' middle
    ring = dict(s=(2 * RING_PT) ** 2, depthshade=False, zorder=9.0, gid="robot ring")  # r41e: over the sparkles
    ax.scatter(*centre[:, None], **ring, **RING_STYLE).set_path_effects(halo(1.6, ("free",)))  # ringed in white
    x, y, _ = proj3d.proj_transform(*centre, ax.get_proj())  # where the robot is drawn, in the panel's 2D data
    corners = np.array(np.meshgrid(*np.stack([workspace.lower, workspace.upper], axis=1))).reshape(3, -1)  # (3, 8)
    sides, _, _ = proj3d.proj_transform(*corners, ax.get_proj())  # (8,) the region's corners, across the panel
    ax.annotate(
        label.get_text().replace(", ", ",\n"),  # "the robot,\nin collision": narrow, in the margin
        (x, y),
        xytext=(sides.min() - RING_PAD * np.ptp(sides), y),
        ha="right",
        va="center",
        fontsize=9,
        zorder=8.0,
        path_effects=halo(1.0, ("free",)),
        arrowprops=LEADER,
        gid="pose label",
    ).set_in_layout(False)  # beside the region, maybe past the panel's side: the layout leaves the panels be
    label.remove()


RING_PT = 14.0  # points: the radius of the ring round a single robot in its still's overview
RING_STYLE = dict(marker="o", facecolors="none", edgecolors=COLORS["ink"], linewidths=1.6)
LEADER = dict(arrowstyle="-", color=COLORS["ink"], linewidth=0.8, shrinkA=2.0, shrinkB=RING_PT)  # name to ring,
LEADER |= dict(path_effects=halo(0.8, ("free",)))  # ringed in white over the sparkles (reader r41e)
RING_PAD = 0.02  # of the region's width as drawn: the robot's name this far out from its side


def _overview_name(label: str, poses: int, valid: bool | None) -> str:
    """A pose's name in a still's overview: its label ("the robot" where it is the only one), and where it collides,
    in words too (a colour is never the only cue)."""
    return ("the robot" if poses == 1 else label) + (", in collision" if valid is False else "")


def _still_legend(
    fig: Figure, valid: dict[str, bool], h_pad: float = 4.0, w_pad: float = 5.0, close_ups: list | tuple = ()
) -> None:
    """The still's legend, under its panels: every mark they name and the robot's states drawn; ``h_pad`` between
    rows of panels (a close-up's "x" over the overview's title needs 4), ``w_pad`` between ``close_ups``."""
    handles = star_on_mark({name: h for ax in fig.axes for h, name in zip(*ax.get_legend_handles_labels())})
    shown = {ok for ok in valid.values() if ok is not None}  # the robot's states drawn: name those alone
    handles |= {
        text: Patch(label=text, **link_style(c))
        for ok, text, c in ((True, "robot, valid", VALID_COLOR), (False, "robot, in collision", INVALID_COLOR))
        if ok in shown
    }
    fig.tight_layout(rect=(0, 0.8 / fig.get_figheight(), 1, 1), w_pad=w_pad, h_pad=h_pad)  # r17c: "y" met a title;
    #   r23b: a close-up's "x" touched the overview's title at h_pad 2.5
    for name in (t for ax in fig.axes for t in ax.texts if t.get_gid() == "pose label"):  # r48e, 05 item 6: laid out,
        name.set_in_layout(True)  # now counted in a tight crop (it clipped "the robot" to "robot" at the page's edge)
    for ax in close_ups:  # the layout reshapes each panel, and mplot3d may then draw its z axis on the other side
        _z_apart(ax)
    low = min((ax.get_tightbbox() or ax.bbox).y0 for ax in fig.axes) / fig.bbox.height  # the lowest label
    for ncol in (3, 2, 1):  # reader r25b: a three-column legend wider than the panels widened the PNG to 1008 px
        legend = fig.legend(
            handles.values(), handles.keys(), loc="upper center", bbox_to_anchor=(0.5, low), ncol=ncol, frameon=False
        )
        if legend.get_window_extent().width <= fig.bbox.width or ncol == 1:
            break
        legend.remove()


def _still_described(robot, workspace, poses, valid, samples, trace, seen, model) -> tuple[str, list]:
    """A still's text alternative and its longer description (what each panel draws, each pose's values, the
    samples and blocks near it and where the camera stands, ``seen``: ``{label: (samples, blocks, (elev, azim))}``,
    and what the ``model`` answers for it)."""
    text = _overview_words(robot, workspace, poses, samples, trace)
    n = len(samples[0]) if samples else 0  # reader r51e, 05 item 1: the sample set's counts beside what is drawn
    keep = np.arange(n) % max(1, overview_step(n, len(workspace.boxes))) == 0  # (N,) as still_panels.overview draws
    keep = keep | dangerous_mask(samples[1]) if samples else keep  # every k-th, and every dangerous mistake
    counted = [("blocks", *[str(len(workspace.boxes))] * 2)]
    kinds = {k: m for k, m in (samples[1] if samples else {}).items() if model or k != "model wrong"}  # r48e, 05 5
    counted += [(f"samples {kind}", str(int(m.sum())), str(int((m & keep).sum()))) for kind, m in kinds.items()]
    counted += [("points of the base's path", *[str(len(trace))] * 2)] if trace is not None else []
    within = f"blocks within {NEAR} of a link"
    columns = ("pose", "exact checker", "samples drawn near it (none over it)", within, "seen from")
    parts = [
        Part("the whole workspace", "its sample set, and what is drawn", OVERVIEW_COLUMNS, tuple(counted)),
        Part(
            "the robot close up",
            "each pose's joint values, in the robot's order, what the exact checker says of it, and the camera's "
            "elevation and azimuth (degrees)",
            (*columns, "configuration"),
            tuple(
                (
                    label,
                    {None: "not checked", True: "valid", False: "in collision"}[valid.get(label)],
                    str(seen[label][0]),
                    str(seen[label][1]),
                    "{:.0f}, {:.0f}".format(*seen[label][2]),
                    ", ".join(f"{v:.2f}" for v in np.asarray(q)),
                )
                for label, q in poses.items()
                if label in seen
            ),
        ),
    ]
    said = [
        f"{label}{_STATE[valid.get(label)]}"
        + model_words(model.get(label), valid.get(label)).replace(":\n", ": ").replace("\n", ", ")
        + (f", {seen[label][0]} sample{'s' * (seen[label][0] != 1)} near it" if samples else "")
        for label in seen
    ]
    named = {label: label if label.startswith("the ") else f"the {label}" for label in seen}  # "the start"
    darker = ", ".join(  # reader r25b: "(the robot: 0)" was unreadable; "(0 blocks near the robot)"
        f"{seen[label][1]} block{'s' * (seen[label][1] != 1)} near {named[label]}" for label in seen
    )
    seen_as = "the robot seen across the plane it spreads in, its links opaque, its joints white dots, "
    seen_as += f"the blocks within {NEAR} of a link darker ({darker})"
    close = "the robot close up among the blocks near it: " + "; ".join(said)
    if len(poses) == 1:  # reader r32e: a single pose's close-up stands above the overview, and is told first
        head, _, whole = text.partition(" as a still: ")
        return f"{head} as a still: first {close}, {seen_as}; then {whole}.", parts
    return f"{text}; {seen_as}; then {close}.", parts


SCENE_NAMES = {  # robot -> the scenario and the robot as the pages name them (reader r28e: not "3do", "youbot")
    "youbot": ("3DO", "youBot"),
    "chain7": ("3DC-7", "box chain"),
    "chain9": ("3DC-9", "box chain"),
    "point2d": ("2DS", "point robot"),
}


def scene_words(workspace: Workspace, robot: BoxRobot) -> str:
    """A scene's workspace and robot by the pages' names, for the captions of its 3D views and stills: "3DO (28
    blocks) with the youBot (8 DoF)"."""
    scenario, name = SCENE_NAMES.get(robot.name, (f"workspace {workspace.family}", f"{robot.name} robot"))
    return f"{scenario} ({len(workspace.boxes)} blocks) with the {name} ({robot.dof} DoF)"


def _overview_words(robot, workspace, poses, samples, trace) -> str:
    """What a still's overview draws, in words: the workspace, its samples by kind, the path, the robot at each
    pose."""
    text = f"{scene_words(workspace, robot)} as a still: "
    text += "the whole workspace"
    if samples is not None:  # reader r51e, 05 item 1: these counts are the sample set's, the overview draws fewer
        text += "; in its sample set, " + ", ".join(
            f"{int(m.sum())} samples {kind} ({SAMPLE_WORDS[kind]})" for kind, m in samples[1].items() if m.any()
        )
        step = overview_step(len(samples[0]), len(workspace.boxes))
        text += f", 1 sample in every {step} drawn (in the order sampled, whatever its kind)" if step > 1 else ""
        text += ", and all the dangerous mistakes" if step > 1 and dangerous_mask(samples[1]).any() else ""
    text += ", the path of the robot's base and its shadow on the floor, dotted" if trace is not None else ""
    text += (
        f", a thin dash-dot line from the robot's base straight down to the floor{' at each pose' * (len(poses) > 1)}"
        if poses and not on_floor(robot, list(poses.values()), workspace.lower[2])
        else ""
    )
    if poses:
        text += ", the robot drawn " + ("over them" if samples is not None else "in it")
        text += " at each pose, labelled" if len(poses) > 1 else ", ringed, its name beside the workspace"
    return text


def path_frame(
    robot: BoxRobot,
    configurations,
    index: int,
    *,
    workspace: Workspace | None = None,
    valid=None,
    clearance=None,
    probability=None,
    threshold: float = 0.5,
    margin: float = 1.0,
    nodes=None,
) -> Figure:
    """Frame ``index`` of a path ``configurations (T, dof)`` evenly spaced along it (through ``nodes (P, dof)``).

    Top (3D): the robot's link boxes at that frame among the blocks of ``workspace`` within ``margin`` of it (in the
    valid colour if ``valid[index]``, the invalid colour if not, the title saying which; ``COLORS["unchecked"]`` if
    ``valid`` is None) and the trace of its base along the whole path (``COLORS["trace"]``, inside the window).
    Below, against the fraction of the path travelled, a line at this frame in each: every DoF scaled to its bounds
    (0 = lower, 1 = upper; straight segments between roadmap nodes show as straight lines), a panel per kind
    (:func:`toolkit.plots.dof_panels.dof_groups`);
    ``clearance (T,)``, a lower bound on the distance to the nearest block (``checker.clearances``), if given;
    the model's ``probability (T,)`` of validity with its ``threshold``, if given.
    """
    Q = robot.check_configs(configurations, "configurations")  # (T, dof)
    frames = len(Q)
    if not 0 <= index < frames:
        raise ValueError(f"index must be in [0, {frames}), got {index}")
    series = {
        name: per_frame(values, frames, name)
        for name, values in (("valid", valid), ("clearance", clearance), ("probability", probability))
    }
    fig = Figure(figsize=(PAGE_WIDTH, 16.4))  # as wide as the page: its text as large as it is drawn
    # the robot a whole row above the series (review r16c: beside them its panel was 200 px wide); the series the
    # larger share (readers r18c, r31e, r37e: five panels of 70, 90, then 80 px were too small at the site's width)
    grid = fig.add_gridspec(2, 1, height_ratios=(3.5, 8.6), hspace=0.3, top=0.93, bottom=0.05, left=0.12, right=0.86)
    valid_now = None if series["valid"] is None else bool(series["valid"][index])
    bound = None if series["clearance"] is None else float(series["clearance"][index])
    _draw_scene(fig.add_subplot(grid[0], projection="3d"), robot, Q, index, (valid_now, bound), workspace, margin)
    draw_series(fig, grid[1], robot, Q, index, series, threshold)
    mark_series(fig, index, series["probability"], None if nodes is None else node_fractions(robot, nodes))
    fig.suptitle(_frame_title(index, frames, series, threshold), fontsize=10, wrap=True)
    named = " ".join(SCENE_NAMES.get(robot.name, (robot.name, "robot")))  # "3DC-7 box chain" (reader r30e)
    text = f"A path of the {named}, {_frame_title(index, frames, series, threshold)}. At the top, the robot in 3D among"
    text += " the blocks near it (the nearest edged in ink and named, an ink line between the closest points labelled"
    text += " with the gap and the bound) and its base's trace; below, against the path's fraction travelled, "
    return describe(fig, text + series_in_words(robot, Q, series, threshold) + ".", [series_part(robot, Q, series)])


def _draw_trace(ax, robot: BoxRobot, Q: np.ndarray) -> None:
    """The base's path (first link's centre, ``(T, 3)``), left out where it leaves the 3D axes' window."""
    trace = robot.link_boxes(Q)[0][:, 0].copy()  # (T, 3)
    trace[~inside_mask(ax, trace)] = np.nan  # mplot3d does not clip lines to the axes
    ax.plot(*trace.T, linewidth=2.0, gid="trace", path_effects=halo(2.0), **TRACE_STYLE)


def _draw_scene(scene, robot: BoxRobot, Q: np.ndarray, index: int, checked: tuple, workspace, margin: float) -> None:
    """The 3D panel of :func:`path_frame` at frame ``index``; ``checked``: its ``(valid, clearance bound)`` or Nones."""
    valid, bound = checked
    color = UNCHECKED_COLOR if valid is None else VALID_COLOR if valid else INVALID_COLOR
    draw_robot(
        scene, robot, Q[index : index + 1], colors=[color], view="3d", workspace=workspace, margin=margin, clip=True
    )  # the blocks clipped to the window (reader r19c: a block past it hid the tick labels and the y axis' name)
    if workspace is not None:  # mplot3d's usual camera, turned where a block stands on a line of sight through it
        scene.view_init(30.0, -60.0 + clear_turn(robot, Q[index], workspace, margin, FRAME_TURNS, (30.0, -60.0)))
    _draw_trace(scene, robot, Q)
    verdict = "" if valid is None else ": valid" if valid else ": in collision"
    scene.set_title(f"the robot, blocks near it{verdict}", fontsize=9)
    scene.set_box_aspect(None, zoom=1.15)  # the robot larger in its panel: mplot3d leaves wide margins
    if workspace is not None and len(workspace.boxes):  # after the view and the zoom: it places its name on them
        links, bounds = robot.link_aabbs(Q[index : index + 1])[0], (workspace.lower, workspace.upper)
        mark_nearest(scene, links, workspace.boxes, bounds)
        mark_closest(scene, robot, Q[index], workspace.boxes, bound)  # reader r30e: the gap the bound is about
    scene.locator_params(nbins=4)  # few tick labels: drawing text is most of a frame's cost
    scene.tick_params(labelsize=9)


def _frame_title(index: int, frames: int, series: dict, threshold: float) -> str:
    """The title: "frame 48 (frames 0–89): valid (exact checker), clearance ≥ 0.028, P(valid) 0.92 ≥ threshold 0.57"."""
    parts = []
    if series["valid"] is not None:
        parts.append("valid (exact checker)" if series["valid"][index] else "IN COLLISION (exact checker)")
    if series["clearance"] is not None:
        parts.append(f"clearance ≥ {series['clearance'][index]:.3f}")
    if series["probability"] is not None:
        q, j = series["probability"], dip_beside(series["probability"], index)  # r35e: a dip beside it, named
        dip = "" if j is None else f" (frame {j}: {q[j]:.2f})"
        parts.append(f"P(valid) {q[index]:.2f} {'≥' if q[index] >= threshold else '<'} threshold {threshold:.2f}{dip}")
    return f"frame {index} (frames 0–{frames - 1})" + (": " + ", ".join(parts) if parts else "")
