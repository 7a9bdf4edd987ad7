"""Marks on the series under a path frame (:func:`toolkit.plots.scenes.path_frame`, notebook 05, section 7).

Reader r39e: markers every few frames on the DoF lines read as roadmap nodes, though the path has only its few
nodes; and the frame's line crossed a dip beside it, so the frame's P(valid) read as the dip's. So the DoF lines
lose their markers (line style, colour and the name at each line's end still tell them apart), the path's nodes get a
tick on each panel's lower edge, and the P(valid) panel a dot at the frame's value and a ring at a dip beside it
(reader r40e: a tick there crossed the threshold).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from toolkit.geometry.robots import BoxRobot
from toolkit.plots.palette import COLORS

NODE_TICK = 0.12  # of a panel's height: a node's tick on its lower edge
DIP = 0.1  # how much lower a neighbouring frame's P(valid) is to get a tick of its own (the title's rule)


def node_fractions(robot: BoxRobot, path) -> np.ndarray:
    """``(P,)`` the fractions of the length of ``path (P, dof)`` (``robot.distance``) at which its nodes lie, as
    :func:`toolkit.planning.local_planner.path_at` spaces the frames."""
    path = robot.check_configs(path, "path")
    ends = np.concatenate([[0.0], np.cumsum(robot.distance(path[:-1], path[1:]))])
    return ends / max(ends[-1], 1e-12)


def dip_beside(p: np.ndarray, index: int) -> int | None:
    """The neighbour of frame ``index`` whose P(valid) ``p (T,)`` is more than :data:`DIP` lower, the lower one; None
    where neither is."""
    j = min((k for k in (index - 1, index + 1) if 0 <= k < len(p)), key=lambda k: p[k], default=index)
    return j if p[j] < p[index] - DIP else None


def mark_series(fig: Figure, index: int, probability, nodes) -> None:
    """On ``fig``'s series panels (each has its frame line, gid ``now``): no markers on the DoF lines (nor in the
    legend), a tick at each of ``nodes (P,)`` (path fractions, or None) on each panel's lower edge, and on the P(valid)
    panel a dot at frame ``index``'s ``probability`` and a ring on a dip beside it, labelled with its frame."""
    panels = [ax for ax in fig.axes if any(line.get_gid() == "now" for line in ax.get_lines())]
    for line in [h for ax in panels for h in ax.get_lines() if h.get_gid() == "dof"]:
        line.set_marker("None")
    for handle in [h for legend in fig.legends for h in legend.legend_handles]:
        if isinstance(handle, Line2D):
            handle.set_marker("None")
    if nodes is not None and panels:
        _tick_nodes(panels, nodes)
    shown = [ax for ax in panels if any(line.get_gid() == "probability" for line in ax.get_lines())]
    if probability is not None and shown:
        _mark_probability(shown[0], np.asarray(probability, dtype=float), index)
        _key_probability(shown[0])


def _key_probability(ax) -> None:
    """The P(valid) panel's own key (reader r41e: its shaded band had no legend entry): the dashed threshold and,
    where there is one, the band of frames the model calls colliding; in the panel's lower right, over the ticks."""
    handles = [h for h in ax.get_lines() if h.get_gid() == "threshold"][:1]
    handles += [h for h in ax.patches if h.get_gid() == "below threshold"][:1]
    words = {"threshold": "threshold (dashed)", "below threshold": "shaded: the model calls it colliding"}
    if handles:
        ax.legend(
            handles,
            [words[h.get_gid()] for h in handles],
            loc="lower right",
            bbox_to_anchor=(1.0, NODE_TICK),
            fontsize=8,
            framealpha=0.9,
            borderaxespad=0.3,
        )


def _tick_nodes(panels: list, nodes: np.ndarray) -> None:
    """A tick at each of ``nodes (P,)`` (path fractions) on each panel's lower edge, named in the last one's label."""
    for ax in panels:
        for x in nodes:
            ax.plot(
                [x, x],
                [0.0, NODE_TICK],
                transform=ax.get_xaxis_transform(),
                color=COLORS["ink"],
                linewidth=1.6,
                solid_capstyle="butt",
                gid="node",
                clip_on=False,
            )
    panels[-1].set_xlabel(f"fraction of the path (ticks inside the lower edges: its {len(nodes)} roadmap nodes)")


def _mark_probability(ax, p: np.ndarray, index: int) -> None:
    """A dot at frame ``index``'s P(valid) ``p (T,)``, and a small ring on a dip beside it, labelled above it with its
    P(valid) against the panel's threshold line and what the model calls it there."""
    along = np.linspace(0.0, 1.0, len(p))
    dot = dict(marker="o", markersize=7, color=COLORS["occupied"], markeredgecolor=COLORS["ink"], linestyle="None")
    ax.plot(along[index], p[index], gid="frame value", zorder=5, **dot)
    j = dip_beside(p, index)
    if j is None:
        return
    # reader r40e, 05 contradiction 2: a tall tick at 0.575 crossed the dashed 0.570 and hid the line's minimum; a
    # small hollow ring sits on the value, its label above it and away from the frame's dot
    ring = dict(marker="o", markersize=5, markerfacecolor=COLORS["free"], markeredgecolor=COLORS["ink"])
    ax.plot(along[j], p[j], gid="dip", zorder=5, linestyle="None", markeredgewidth=1.2, **ring)
    before = j < index
    cut = [h.get_ydata()[0] for h in ax.get_lines() if h.get_gid() == "threshold"]  # reader r42e: the ring sat on the
    said = "" if not cut else f"\n{p[j]:.3f} {'≥' if p[j] >= cut[0] else '<'} {cut[0]:.3f}"  # line; its verdict, said
    called = "" if not cut else f"\ncalled {'valid' if p[j] >= cut[0] else 'colliding'}"
    ax.annotate(
        f"frame {j}{said}{called}",
        (along[j], p[j]),
        xytext=(-10 if before else 10, 8),
        textcoords="offset points",
        ha="right" if before else "left",
        va="bottom",
        fontsize=9,
        color=COLORS["ink"],
    )


def per_frame(values, frames: int, name: str) -> np.ndarray | None:
    """``values`` as a float array ``(T,)``, or None; a clear error for a wrong length."""
    if values is None:
        return None
    values = np.asarray(values, dtype=float).reshape(-1)
    if len(values) != frames:
        raise ValueError(f"{name} must have one value per configuration ({frames}), got {len(values)}")
    return values
