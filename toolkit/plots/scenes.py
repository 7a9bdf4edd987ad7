"""Figures of notebook 05: a planned path of a 3D robot, one frame at a time (paper §III-B, Algorithm 1).

A PRM path is a list of configurations joined by straight lines in configuration
space (the straight-line local planner of §III-B). :func:`scene_still` draws a viewer's
scene as a still picture (what a browser without WebGL shows in the 3D view's place): the whole workspace with
its samples and the path, and the robot close up. :func:`path_frame` shows one
configuration along a path in the workspace, among the blocks near the robot, next to
what stays hidden in a 3D picture: every degree of freedom along the path, how much
room the robot has (the exact checker's clearance bound) and what a learned model
thinks of each configuration (P(valid), the MLP of §III-B).

The 3D drawing of the robot and its nearby blocks is :mod:`toolkit.plots.robot_drawing`'s.
Every function returns a matplotlib ``Figure`` and never calls ``show()``.
"""

from __future__ import annotations

from functools import partial

import numpy as np
from matplotlib.figure import Figure
from matplotlib.gridspec import SubplotSpec
from matplotlib.patches import Patch

from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace
from toolkit.plots.alt import ROWS, Part, describe
from toolkit.plots.boxes import aabb_corners, add_box_3d
from toolkit.plots.cspace import frame_region
from toolkit.plots.dof_panels import dof_groups, draw_dofs
from toolkit.plots.palette import COLORS, PAGE_WIDTH, halo
from toolkit.plots.robot_drawing import (
    BLOCK_STYLE,
    INVALID_COLOR,
    VALID_COLOR,
    draw_robot,
    few_ticks,
    link_style,
)

TRACE_COLOR = COLORS["trace"]  # the path of the robot's base, as the viewer's path line
UNCHECKED_COLOR = COLORS["unchecked"]  # the robot when no validity is given
NOW_COLOR = COLORS["occupied"]
SAMPLE_MARKS = {  # kind of sample -> marker, colour, size: the viewer's shapes (toolkit.viewer.drawing.SAMPLE_SHAPES)
    "valid": ("o", VALID_COLOR, 9),
    "in collision": ("D", INVALID_COLOR, 11),
    "model wrong": ("*", COLORS["ink"], 160),
}
WRONG_STYLE = dict(facecolors="none", edgecolors=COLORS["ink"], linewidths=1.0)  # hollow: the mark under it shows
TRACE_STYLE = dict(color=TRACE_COLOR, linestyle="--")  # dashed: apart from the robot's blue links by more than hue
SAMPLE_WORDS = {
    "valid": "circles",
    "in collision": "diamonds",
    "model wrong": "hollow stars round their marks",
}  # SAMPLE_MARKS in words
OVERVIEW_SAMPLES = 500  # at most this many samples in a still's overview: more hide the blocks and the robot
_STATE = {None: "", True: ", valid", False: ", in collision"}  # a pose's verdict, as a title and its text say it
POSE_MARKERS = ("s", "P", "*", "^", "v", "X")  # the poses of a still, marked at their base in its overview


def scene_still(
    robot: BoxRobot,
    workspace: Workspace,
    poses: dict[str, np.ndarray],
    *,
    valid: dict[str, bool] | None = None,
    samples: tuple[np.ndarray, dict[str, np.ndarray]] | None = None,
    trace: np.ndarray | None = None,
    margin: float = 1.0,
) -> Figure:
    """A viewer's 3D scene as a still picture: first the whole workspace, its blocks, the ``samples`` at their
    base (``(points (N, 3), {kind: mask (N,)})``, kinds as :func:`toolkit.viewer.drawing.sample_kinds` names them:
    circles valid, diamonds in collision, hollow stars round them where a model is wrong), the ``trace (T, 3)`` of
    the robot's base along a path (dashed) and each pose marked at its base; then one close-up per pose
    ``{label: q (dof,)}``, the robot's link boxes among the blocks within ``margin`` (the valid colour, or the invalid
    one hatched, by ``valid``; every other link lighter), the samples inside its window and the trace. Of more than
    :data:`OVERVIEW_SAMPLES` samples the overview draws every k-th, lighter, so the blocks and the robot show."""
    if robot.dim != 3:
        raise ValueError(f"a scene's still is drawn in 3D; the {robot.name} robot moves in {robot.dim}D")
    valid = valid or {}
    rows = -(-(1 + len(poses)) // 2)
    fig = Figure(figsize=(PAGE_WIDTH, 3.7 * rows + 0.9))  # as wide as the page: its text as large as it is drawn
    _overview(fig.add_subplot(rows, 2, 1, projection="3d"), robot, workspace, poses, samples, trace)
    near = {}  # pose -> samples drawn in its close-up
    for k, (label, q) in enumerate(poses.items()):
        ax = fig.add_subplot(rows, 2, k + 2, projection="3d")
        ok = valid.get(label)
        color = UNCHECKED_COLOR if ok is None else VALID_COLOR if ok else INVALID_COLOR
        draw_robot(ax, robot, np.asarray(q)[None], colors=[color], view="3d", workspace=workspace, margin=margin)
        _tell_links_apart(ax)
        near[label] = _draw_points(ax, samples, trace, clip=True, scale=2.0)  # a small window: larger marks
        few_ticks(ax)
        ax.set_title(f"{label}, close up{_STATE[ok]}", fontsize=10)
    handles = {name: h for ax in fig.axes for h, name in zip(*ax.get_legend_handles_labels())}
    shown = {ok for ok in valid.values() if ok is not None}  # the robot's states drawn: name those alone
    handles |= {
        text: Patch(label=text, **link_style(c))
        for ok, text, c in ((True, "robot, valid", VALID_COLOR), (False, "robot, in collision", INVALID_COLOR))
        if ok in shown
    }
    fig.tight_layout(rect=(0, 0.8 / fig.get_figheight(), 1, 1))
    low = min((ax.get_tightbbox() or ax.bbox).y0 for ax in fig.axes) / fig.bbox.height  # the lowest label
    fig.legend(handles.values(), handles.keys(), loc="upper center", bbox_to_anchor=(0.5, low), ncol=3, frameon=False)
    return describe(fig, *_still_described(robot, workspace, poses, valid, samples, trace, near))


def _still_described(robot: BoxRobot, workspace: Workspace, poses, valid, samples, trace, near) -> tuple[str, list]:
    """A still's text alternative and its longer description (what each panel draws, each pose's values and the
    samples ``near`` it, ``{label: count}``)."""
    text = f"The {robot.name} robot in workspace {workspace.family} ({len(workspace.boxes)} blocks) as a still: "
    text += "the whole workspace"
    if samples is not None:
        text += ", " + ", ".join(
            f"{int(m.sum())} samples {kind} ({SAMPLE_WORDS[kind]})" for kind, m in samples[1].items() if m.any()
        )
        step = _overview_step(len(samples[0]))
        text += f", 1 sample in {step} drawn, lighter" if step > 1 else ""
    text += ", the path of the robot's base" if trace is not None else ""
    counted = [("blocks", str(len(workspace.boxes)))]
    counted += [(f"samples {kind}", str(int(m.sum()))) for kind, m in (samples[1].items() if samples else ())]
    counted += [("points of the base's path", str(len(trace)))] if trace is not None else []
    parts = [
        Part("the whole workspace", "what the first panel draws", ("drawn", "count"), tuple(counted)),
        Part(
            "the robot close up",
            "each pose's joint values, in the robot's order, and what the exact checker says of it",
            ("pose", "exact checker", "samples drawn near it", "configuration"),
            tuple(
                (
                    label,
                    {None: "not checked", True: "valid", False: "in collision"}[valid.get(label)],
                    str(near[label]),
                    ", ".join(f"{v:.2f}" for v in np.asarray(q)),
                )
                for label, q in poses.items()
            ),
        ),
    ]
    said = [
        f"{label}{_STATE[valid.get(label)]}"
        + (f", {near[label]} sample{'s' * (near[label] != 1)} near it" if samples else "")
        for label in poses
    ]
    return text + "; then the robot close up among the blocks near it: " + "; ".join(said) + ".", parts


def _overview(ax, robot: BoxRobot, workspace: Workspace, poses: dict[str, np.ndarray], samples, trace) -> None:
    """A still's first panel: the whole workspace, its samples and path, each pose marked at the robot's base."""
    for lo, hi in workspace.boxes:
        add_box_3d(ax, aabb_corners(lo, hi), linewidth=0.2, alpha=0.2, **BLOCK_STYLE)
    if samples is not None:  # every k-th, lighter, under the poses' marks
        keep = np.arange(len(samples[0])) % _overview_step(len(samples[0])) == 0  # (N,)
        samples = (samples[0][keep], {kind: mask[keep] for kind, mask in samples[1].items()})
    _draw_points(ax, samples, trace, alpha=0.45)
    ax.computed_zorder = False  # the poses' marks in front of every sample
    for k, (label, q) in enumerate(poses.items()):
        base = robot.link_boxes(np.asarray(q)[None])[0][0, 0]  # (3,) the first link's centre
        ax.scatter(
            *base,
            marker=POSE_MARKERS[k % len(POSE_MARKERS)],
            s=90,
            color=COLORS["free"],
            edgecolors=COLORS["ink"],
            linewidths=1.2,
            depthshade=False,
            zorder=5,
            label=f"robot: {label}",
        )
    frame_region(ax, workspace)
    ax.set_box_aspect(workspace.upper - workspace.lower)
    few_ticks(ax)
    ax.set_title(f"the whole workspace: {len(workspace.boxes)} blocks", fontsize=10)


def _tell_links_apart(ax) -> None:
    """A chain's links, one colour, told apart: each edged in thick ink, every other one lighter."""
    for k, link in enumerate(c for c in ax.collections if c.get_gid() == "link"):
        link.set_linewidth(1.0)
        link.set_alpha(0.9 if k % 2 == 0 else 0.55)


def _overview_step(n: int) -> int:
    """k: a still's overview draws every k-th of ``n`` samples, at most :data:`OVERVIEW_SAMPLES`."""
    return -(-n // OVERVIEW_SAMPLES)


def _draw_points(ax, samples, trace, clip: bool = False, alpha: float = 1.0, scale: float = 1.0) -> int:
    """The samples ``(points (N, 3), {kind: mask})`` by kind and the base's ``trace (T, 3)`` on a 3D axes; with
    ``clip``, only what lies inside the axes' window (mplot3d does not clip); marks ``scale`` times their size, with
    ``alpha``. Returns how many samples it drew."""
    drawn = np.zeros(0 if samples is None else len(samples[0]), dtype=bool)  # (N,)
    for kind, mask in ({} if samples is None else samples[1]).items():
        mask = mask & _inside_mask(ax, samples[0]) if clip else mask
        drawn |= mask
        if mask.any():
            marker, color, size = SAMPLE_MARKS[kind]
            style = dict(color=color) if kind != "model wrong" else WRONG_STYLE  # a star round the mark, not over it
            ax.scatter(
                *samples[0][mask].T,
                marker=marker,
                s=size * scale,
                depthshade=False,
                alpha=alpha,
                label=f"sample, {kind}",
                **style,
            )
    if trace is not None:
        points = trace.copy()
        if clip:
            points[~_inside_mask(ax, points)] = np.nan
        ax.plot(*points.T, linewidth=2.0, path_effects=halo(2.0), label="path of the base (dashed)", **TRACE_STYLE)
    return int(drawn.sum())


def _inside_mask(ax, points: np.ndarray) -> np.ndarray:
    """``(N,)`` bool: which ``points (N, 3)`` lie inside the 3D axes' window."""
    lo, hi = np.array([ax.get_xlim(), ax.get_ylim(), ax.get_zlim()]).T  # (3,) each
    return np.all((points >= lo) & (points <= hi), axis=1)


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
) -> Figure:
    """Frame ``index`` of a path ``configurations (T, dof)`` evenly spaced along it.

    Left (3D): the robot's link boxes at that frame among the blocks of ``workspace``
    within ``margin`` of it (in the valid colour if ``valid[index]``, the invalid
    colour if not, the title saying which; ``COLORS["unchecked"]`` if ``valid`` is None) and the trace of its base
    along the whole path (``COLORS["trace"]``, inside the window).
    Right, against the fraction of the path travelled, a line at this frame in each:
    every DoF scaled to its bounds (0 = lower, 1 = upper; straight segments between
    roadmap nodes show as straight lines), a panel per kind (:func:`toolkit.plots.dof_panels.dof_groups`);
    ``clearance (T,)``, a lower bound on the distance to the nearest block (``checker.clearances``), if given;
    the model's ``probability (T,)`` of validity with its ``threshold``, if given.
    """
    Q = robot.check_configs(configurations, "configurations")  # (T, dof)
    frames = len(Q)
    if not 0 <= index < frames:
        raise ValueError(f"index must be in [0, {frames}), got {index}")
    series = {
        name: _per_frame(values, frames, name)
        for name, values in (("valid", valid), ("clearance", clearance), ("probability", probability))
    }
    fig = Figure(figsize=(PAGE_WIDTH, 6.6))  # as wide as the page: its text as large as it is drawn
    grid = fig.add_gridspec(1, 2, width_ratios=(1.0, 1.2), wspace=0.7, top=0.8, bottom=0.08, left=0.05, right=0.88)
    valid_now = None if series["valid"] is None else bool(series["valid"][index])
    _draw_scene(fig.add_subplot(grid[0], projection="3d"), robot, Q, index, valid_now, workspace, margin)
    _draw_series(fig, grid[1], robot, Q, index, series, threshold)
    fig.suptitle(_frame_title(index, frames, series, threshold), fontsize=10, wrap=True)
    text = f"A path of the {robot.name} robot, {_frame_title(index, frames, series, threshold)}. Left, the robot"
    text += " in 3D among the blocks near it and its base's trace; right, against the fraction of the path travelled, "
    return describe(fig, text + _series_in_words(robot, Q, series, threshold) + ".", [_series_part(robot, Q, series)])


def _series_part(robot: BoxRobot, Q: np.ndarray, series: dict) -> Part:
    """The right-hand panels as a table: at evenly picked frames (at most :data:`~toolkit.plots.alt.ROWS`), each
    DoF scaled to its bounds, and the validity, clearance and P(valid) where given."""
    scaled = (Q - robot.lower) / (robot.upper - robot.lower)  # (T, dof) in [0, 1]
    given = {name: values for name, values in series.items() if values is not None}
    columns = ("frame", "fraction of the path", *robot.dof_names, *given)
    rows = tuple(
        (
            str(t),
            f"{t / max(len(Q) - 1, 1):.0%}",
            *(f"{v:.2f}" for v in scaled[t]),
            *(
                ("valid" if values[t] else "in collision") if name == "valid" else f"{values[t]:.3g}"
                for name, values in given.items()
            ),
        )
        for t in np.unique(np.linspace(0, len(Q) - 1, min(ROWS, len(Q))).round().astype(int))
    )
    return Part("along the path", "each DoF scaled to its bounds (0 lower, 1 upper)", columns, rows)


def _series_in_words(robot: BoxRobot, Q: np.ndarray, series: dict, threshold: float) -> str:
    """The right-hand panels in words: which DoFs move, the clearance and P(valid) along the path."""
    scaled = (Q - robot.lower) / (robot.upper - robot.lower)  # (T, dof) in [0, 1]
    moves = [f"{name} {scaled[0, k]:.2f} to {scaled[-1, k]:.2f}" for k, name in enumerate(robot.dof_names)]
    kinds = "; ".join(
        f"{kind}: {', '.join(robot.dof_names[k] for k in dofs)}" for kind, dofs in dof_groups(robot).items()
    )
    text = f"each DoF scaled to its bounds (0 lower, 1 upper), a panel per kind ({kinds}), from start to end: "
    text += ", ".join(moves)
    if (valid := series["valid"]) is not None:
        text += f"; {int(np.sum(valid == 0))} of {len(valid)} frames in collision"
    if (clearance := series["clearance"]) is not None:
        text += f"; the clearance is smallest, {np.min(clearance):.3f}, at {np.argmin(clearance) / (len(Q) - 1):.0%}"
        text += " of the path"
    if (p := series["probability"]) is not None:
        below = int(np.sum(p < threshold))
        text += f"; P(valid) from {np.min(p):.2f} to {np.max(p):.2f}, below the threshold {threshold:.2f} at {below}"
        text += f" of {len(p)} frames"
    return text


def _draw_series(
    fig: Figure, spec: SubplotSpec, robot: BoxRobot, Q: np.ndarray, index: int, series: dict, threshold: float
) -> None:
    """The right of :func:`path_frame`: panels one above the other against the fraction of the path travelled (the
    DoFs, then the clearance and P(valid) where given), a line at frame ``index`` in each."""
    along = np.linspace(0.0, 1.0, len(Q))  # (T,)
    groups = dof_groups(robot)
    panels = [partial(draw_dofs, fig, robot, Q, dofs, name) for name, dofs in groups.items()]
    if (clearance := series["clearance"]) is not None:
        panels.append(partial(_draw_clearance, clearance))
    if (probability := series["probability"]) is not None:
        panels.append(partial(_draw_probability, probability, threshold))
    axes = spec.subgridspec(len(panels), 1, hspace=0.2).subplots(sharex=True, squeeze=False)[:, 0]
    for ax, draw_panel in zip(axes, panels):
        draw_panel(ax, along)
        ax.axvline(along[index], color=NOW_COLOR, linewidth=1.0, gid="now")
        ax.locator_params(axis="y", nbins=3)
        ax.tick_params(labelsize=9)
        ax.label_outer()
    axes[-1].set_xlabel("fraction of the path")
    handles = [h for ax in axes[: len(groups)] for h in ax.get_lines() if h.get_gid() == "dof"]
    fig.legend(
        handles,
        [h.get_label() for h in handles],
        title="each DoF in its bounds: 0 lower, 1 upper",
        title_fontsize=9,
        fontsize=9,
        ncol=min(robot.dof, 4),
        loc="upper center",
        bbox_to_anchor=(0.68, 0.93),  # between the title and the panels
        frameon=False,
        handlelength=3.0,
        columnspacing=0.8,
    )


def _draw_clearance(clearance: np.ndarray, ax, along: np.ndarray) -> None:
    """The exact checker's lower bound on the distance to the nearest block, ``clearance (T,)``, shaded below."""
    ax.plot(along, clearance, color=COLORS["ink"], linewidth=1.2, gid="clearance")
    ax.fill_between(along, 0.0, clearance, color=COLORS["shade"])
    ax.set_ylim(bottom=0.0)
    ax.set_ylabel("clearance")


def _draw_probability(p: np.ndarray, threshold: float, ax, along: np.ndarray) -> None:
    """The model's P(valid) ``p (T,)`` with its ``threshold``, shaded where the model calls the path colliding."""
    ax.plot(along, p, color=COLORS["probability"], linewidth=1.2, gid="probability")
    ax.axhline(threshold, color=COLORS["ink"], linestyle="--", linewidth=0.8, gid="threshold")
    ax.fill_between(along, 0.0, 1.0, where=p < threshold, color=INVALID_COLOR, alpha=0.15, linewidth=0)
    ax.set_ylim(-0.02, 1.02)
    ax.set_ylabel("P(valid)")


def _draw_trace(ax, robot: BoxRobot, Q: np.ndarray) -> None:
    """The base's path (first link's centre, ``(T, 3)``), left out where it leaves the 3D axes' window."""
    trace = robot.link_boxes(Q)[0][:, 0].copy()  # (T, 3)
    trace[~_inside_mask(ax, trace)] = np.nan  # mplot3d does not clip lines to the axes
    ax.plot(*trace.T, linewidth=2.0, gid="trace", path_effects=halo(2.0), **TRACE_STYLE)


def _draw_scene(
    scene, robot: BoxRobot, Q: np.ndarray, index: int, valid: bool | None, workspace, margin: float
) -> None:
    """The 3D panel of :func:`path_frame`: the robot at frame ``index`` among the blocks near it, its base's trace."""
    color = UNCHECKED_COLOR if valid is None else VALID_COLOR if valid else INVALID_COLOR
    draw_robot(scene, robot, Q[index : index + 1], colors=[color], view="3d", workspace=workspace, margin=margin)
    _draw_trace(scene, robot, Q)
    verdict = "" if valid is None else ": valid" if valid else ": in collision"
    scene.set_title(f"the robot, blocks near it{verdict}", fontsize=9)
    scene.set_box_aspect(None, zoom=1.15)  # the robot larger in its panel: mplot3d leaves wide margins
    scene.locator_params(nbins=4)  # few tick labels: drawing text is most of a frame's cost
    scene.tick_params(labelsize=8)


def _per_frame(values, frames: int, name: str) -> np.ndarray | None:
    """``values`` as a float array ``(T,)``, or None; a clear error for a wrong length."""
    if values is None:
        return None
    values = np.asarray(values, dtype=float).reshape(-1)
    if len(values) != frames:
        raise ValueError(f"{name} must have one value per configuration ({frames}), got {len(values)}")
    return values


def _frame_title(index: int, frames: int, series: dict, threshold: float) -> str:
    parts = [f"frame {index} of 0-{frames - 1}"]
    if series["valid"] is not None:
        parts.append("valid (exact checker)" if series["valid"][index] else "IN COLLISION (exact checker)")
    if series["clearance"] is not None:
        parts.append(f"clearance ≥ {series['clearance'][index]:.3f}")
    if series["probability"] is not None:
        p = series["probability"][index]
        parts.append(f"P(valid) = {p:.2f} (threshold {threshold:.2f}: {'valid' if p >= threshold else 'colliding'})")
    return ", ".join(parts)
