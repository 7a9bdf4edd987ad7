"""The panels beside a path frame (:func:`toolkit.plots.scenes.path_frame`, notebook 05): against the fraction of
the path travelled, every degree of freedom scaled to its bounds, the exact checker's clearance bound and a learned
model's P(valid) with its threshold (the MLP of §III-B), a line at the frame shown; and the same in words and as a
table for the figure's description."""

from __future__ import annotations

from functools import partial

import numpy as np
from matplotlib.figure import Figure
from matplotlib.gridspec import SubplotSpec

from toolkit.geometry.robots import BoxRobot
from toolkit.plots.alt import ROWS, Part
from toolkit.plots.dof_panels import dof_groups, draw_dofs, wrap_frames, wrap_note
from toolkit.plots.palette import COLORS
from toolkit.plots.robot_drawing import INVALID_COLOR

NOW_COLOR = COLORS["occupied"]  # the line at the frame shown


def series_part(robot: BoxRobot, Q: np.ndarray, series: dict) -> Part:
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


def series_in_words(robot: BoxRobot, Q: np.ndarray, series: dict, threshold: float) -> str:
    """The right-hand panels in words: which DoFs move, the clearance and P(valid) along the path."""
    scaled = (Q - robot.lower) / (robot.upper - robot.lower)  # (T, dof) in [0, 1]
    moves = [f"{name} {scaled[0, k]:.2f} to {scaled[-1, k]:.2f}" for k, name in enumerate(robot.dof_names)]
    kinds = "; ".join(
        f"{kind}: {', '.join(robot.dof_names[k] for k in dofs)}" for kind, dofs in dof_groups(robot).items()
    )
    text = f"each DoF scaled to its bounds (0 lower, 1 upper), a panel per kind ({kinds}), from start to end: "
    text += ", ".join(moves)
    for k, name in enumerate(robot.dof_names):  # an angle across ±π: its line jumps from one edge to the other
        wraps = wrap_frames(scaled[:, k])  # (w,) the frames before each wrap, as drawn
        if len(wraps):
            at = ", ".join(  # where, and the two edges: a wrap after the first frame leaves a lone point (r21c)
                f"{(t + 0.5) / (len(Q) - 1):.0%} (from {scaled[t, k]:.2f} to {scaled[t + 1, k]:.2f})" for t in wraps
            )
            text += (
                f"; {name} wraps round (crosses ±π, its line jumping from one edge of its panel to the other) at {at}"
            )
            text += " of the path"
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


def draw_series(
    fig: Figure, spec: SubplotSpec, robot: BoxRobot, Q: np.ndarray, index: int, series: dict, threshold: float
) -> None:
    """The lower part of :func:`~toolkit.plots.scenes.path_frame`: panels one above the other against the fraction
    of the path travelled (the DoFs, then the clearance and P(valid) where given), a line at frame ``index`` in each."""
    along = np.linspace(0.0, 1.0, len(Q))  # (T,)
    groups = dof_groups(robot)
    panels = [partial(draw_dofs, fig, robot, Q, dofs, name) for name, dofs in groups.items()]
    if (clearance := series["clearance"]) is not None:
        panels.append(partial(draw_clearance, clearance))
    if (probability := series["probability"]) is not None:
        panels.append(partial(draw_probability, probability, threshold))
    ratios = [1.0] * len(groups) + [1.6] * (len(panels) - len(groups))  # reader r30e: clearance and P(valid) taller
    grid = spec.subgridspec(len(panels), 1, hspace=0.2, height_ratios=ratios)
    axes = grid.subplots(sharex=True, squeeze=False)[:, 0]
    for ax, draw_panel in zip(axes, panels):
        draw_panel(ax, along)
        ax.axvline(along[index], color=NOW_COLOR, linewidth=1.0, gid="now")
        ax.locator_params(axis="y", nbins=3)
        ax.tick_params(labelsize=10)
        ax.label_outer()
    axes[-1].set_xlabel("fraction of the path")
    handles = [h for ax in axes[: len(groups)] for h in ax.get_lines() if h.get_gid() == "dof"]
    fig.legend(
        handles,
        [h.get_label() for h in handles],
        title="each DoF in its bounds: 0 lower, 1 upper" + wrap_note(robot, Q, groups.get("angles", [])),
        title_fontsize=10,
        fontsize=10,
        ncol=min(robot.dof, 4),
        bbox_to_anchor=(0.5, spec.get_position(fig).y1 + 0.005),  # between the robot's panel and the series
        loc="lower center",
        frameon=False,
        handlelength=3.0,
        columnspacing=0.8,
    ).get_title().set_multialignment("center")


def draw_clearance(clearance: np.ndarray, ax, along: np.ndarray) -> None:
    """The exact checker's lower bound on the distance to the nearest block, ``clearance (T,)``, shaded below."""
    ax.plot(along, clearance, color=COLORS["ink"], linewidth=1.2, gid="clearance")
    ax.fill_between(along, 0.0, clearance, color=COLORS["shade"])
    ax.set_ylim(bottom=0.0)
    ax.set_ylabel("clearance\n(workspace units)")


def draw_probability(p: np.ndarray, threshold: float, ax, along: np.ndarray) -> None:
    """The model's P(valid) ``p (T,)`` with its ``threshold``, shaded where the model calls the path colliding."""
    ax.plot(along, p, color=COLORS["probability"], linewidth=1.2, gid="probability")
    ax.axhline(threshold, color=COLORS["ink"], linestyle="--", linewidth=0.8, gid="threshold")
    for start, stop in below_threshold(p < threshold, along):  # a band per run of frames, one frame's as wide
        ax.axvspan(start, stop, color=INVALID_COLOR, alpha=0.2, linewidth=0, gid="below threshold")
    ax.set_ylim(-0.02, 1.02)
    ax.set_ylabel("P(valid)")


BAND = 0.02  # fraction of the path: the least half-width of a band of frames below the threshold (r24b: at 0.01
#   one frame's band was 4 pixels wide)


def below_threshold(below: np.ndarray, along: np.ndarray) -> list[tuple[float, float]]:
    """The spans ``[(start, stop)]`` of ``along (T,)`` round each run of frames where ``below (T,)``: half a frame's
    step either side, and at least :data:`BAND` either side (reader r23b: a one-frame dip drew no band at all)."""
    half = max((along[-1] - along[0]) / max(len(along) - 1, 1) / 2, BAND) if len(along) else BAND
    spans, run = [], None
    for index, flag in enumerate(below):
        if flag and run is None:
            run = index
        if run is not None and (not flag or index == len(below) - 1):
            last = index if flag else index - 1
            spans.append((float(along[run]) - half, float(along[last]) + half))
            run = None
    return spans
