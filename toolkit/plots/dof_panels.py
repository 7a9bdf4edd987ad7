"""A path's degrees of freedom over time, a panel per kind (notebook 05, :func:`toolkit.plots.scenes.path_frame`).

Seven lines in one panel cross and hide each other, so the DoFs are grouped by kind (:func:`dof_groups`: the
base's position, its angles, the joints) and each group drawn in a panel of its own (:func:`draw_dofs`), every
DoF scaled to its bounds and named beside the panel at the height its line ends, the names moved apart just enough to
be read. An angle that goes round ±π runs out at one edge of its panel and comes back at the other (:func:`_broken`).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from toolkit.geometry.robots import BASES, BoxRobot
from toolkit.plots.palette import COLORS, series_style


def dof_groups(robot: BoxRobot) -> dict[str, list[int]]:
    """The robot's DoFs by kind, each kind a panel of :func:`toolkit.plots.scenes.path_frame`:
    ``{"position": [0, 1, 2], "angles": [3, 4, 5], "joints": [6]}`` for a free-flying chain."""
    _, angular = BASES[robot.base]  # (base DoFs,) whether each is an angle
    kinds = {
        "position": [k for k, angle in enumerate(angular) if not angle],
        "angles": [k for k, angle in enumerate(angular) if angle],
        "joints": list(range(len(angular), robot.dof)),
    }
    return {kind: dofs for kind, dofs in kinds.items() if dofs}


def draw_dofs(fig: Figure, robot: BoxRobot, Q: np.ndarray, dofs: list[int], kind: str, ax, along: np.ndarray) -> None:
    """The DoFs ``dofs`` of ``Q (T, dof)`` scaled to their bounds (0 = lower, 1 = upper), each in its own colour,
    line style and marker (as the legend above the panels names them), and named in ink beside the panel, at the height
    where its line ends, a thin grey leader from the panel's edge to the name (outside the panel: it is no data)."""
    scaled = (Q - robot.lower) / (robot.upper - robot.lower)  # (T, dof) in [0, 1]
    every = max(1, len(Q) // 6)
    for k in dofs:
        style = series_style(k) | dict(markevery=(k % every, every), markersize=6)
        x, y = _broken(along, scaled[:, k]) if kind == "angles" else (along, scaled[:, k])
        frames = _frame_points(scaled[:, k]) if kind == "angles" else np.arange(len(x))  # (T,) where each frame is
        style["markevery"] = frames[k % every :: every].tolist()  # markers on frames, none where a wrap meets an edge
        ax.plot(x, y, linewidth=1.4, label=robot.dof_names[k], gid="dof", **style)
    ax.set_ylim(-0.05, 1.05)
    box = ax.get_position()  # in figure fractions: the gridspec has placed the panel
    per_unit = box.height * fig.get_figheight() * 72 / 1.1  # points per unit of the y axis (1.1 units tall)
    ends = _spread(scaled[-1, dofs], gap=LABEL_GAP / per_unit)  # (len(dofs),) label heights a line of text apart
    for k, end in zip(dofs, ends):
        ax.annotate(
            robot.dof_names[k],
            (1.0, scaled[-1, k]),  # the axes' right edge, at the height where the line ends
            xycoords=("axes fraction", "data"),
            xytext=(1.02, end),
            textcoords=("axes fraction", "data"),
            fontsize=LABEL_POINTS,  # reader r36e: at 8 points, about 8 px tall on the page
            va="center",
            color=COLORS["ink"],  # text in a line's colour is 3.1 to 3.9:1 on white (WCAG 1.4.3 asks 4.5)
            annotation_clip=False,
            arrowprops=dict(  # a thin grey leader, wholly outside the axes (reader r19c: a solid stroke in the line's
                arrowstyle="-",  # colour past x = 1 read as data, the line still rising after the path's end)
                color=LEADER_COLOR,
                linewidth=0.6,
                shrinkA=0,
                shrinkB=1,
            ),
        )
    ax.set_ylabel(kind, fontsize=9)


def _broken(along: np.ndarray, scaled: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """An angle's line ``scaled (T,)`` against ``along (T,)`` run out at one edge of the panel and on from the other
    where it wraps around (where it jumps more than half its range between two frames it went through -π = π, not
    across the panel): the line goes on to the edge it crosses, where the angle reaches ±π, breaks (a NaN) and comes
    back in at the other edge. Each piece is a line, the one frame before or after a wrap too (reader r23b: a lone
    marker for it read as an outlier)."""
    x: list[np.ndarray] = [along[:1]]
    y: list[np.ndarray] = [scaled[:1]]
    for t in range(len(scaled) - 1):
        a, b = scaled[t], scaled[t + 1]
        if abs(b - a) > 0.5:  # through the top edge (1 = π, on from 0) or the bottom one
            top = b < a
            share = (1.0 - a) / (1.0 - a + b) if top else a / (a + 1.0 - b)  # of the step, to the edge
            at = along[t] + share * (along[t + 1] - along[t])
            x.append(np.array([at, np.nan, at]))
            y.append(np.array([1.0, np.nan, 0.0] if top else [0.0, np.nan, 1.0]))
        x.append(along[t + 1 : t + 2])
        y.append(scaled[t + 1 : t + 2])
    return np.concatenate(x), np.concatenate(y)  # (T + 3 w,) each


def _frame_points(scaled: np.ndarray) -> np.ndarray:
    """Where in the line :func:`_broken` draws of ``scaled (T,)`` each frame lies, ``(T,)``: after each wrap three
    points more (the edge, the break, the other edge)."""
    added = np.zeros(len(scaled), dtype=int)
    added[wrap_frames(scaled) + 1] = 3
    return np.arange(len(scaled)) + np.cumsum(added)


def wrap_frames(scaled: np.ndarray) -> np.ndarray:
    """The frames ``(w,)`` after which an angle ``scaled (T,)`` to its bounds wraps round ±π: where it jumps more
    than half its range between two frames (a path moves in small steps, so it went through -π = π)."""
    return np.flatnonzero(np.abs(np.diff(scaled)) > 0.5)


def wrap_note(robot: BoxRobot, Q: np.ndarray, angles: list[int]) -> str:
    """A legend title's second line where an angle wraps round ±π: its line runs out at one edge and comes back at
    the other (:func:`_broken`), no data missing (reader r20c)."""
    scaled = (Q - robot.lower) / (robot.upper - robot.lower)  # (T, dof) in [0, 1]
    names = [robot.dof_names[k] for k in angles if len(wrap_frames(scaled[:, k]))]
    named = ", ".join(names[:-1]) + " and " * (len(names) > 1) + "".join(names[-1:])  # "alpha, beta and gamma"
    return f"\n{named}: at ±π a line leaves one edge and comes back at the other" if names else ""


LEADER_COLOR = COLORS["reference"]  # a name's leader: a grey no DoF's line is drawn in
LABEL_POINTS = 10.0  # a name at a line's end: 14 px a line at 100 dpi, capitals ~10 px (r36e: 8 points read ~8 px)
LABEL_GAP = 20.0  # points between two names at the lines' ends: a 10-point line of text (~11.7 pt tall) and air
# enough that two names never read as one (reader r20c: "y" and "z" 11 points apart nearly touched; r23b: at 14 they
#   still crowded each other, their leaders meeting)


def _spread(heights: np.ndarray, gap: float) -> np.ndarray:
    """``heights (n,)`` moved apart as little as keeps every two at least ``gap`` apart (labels at a line's end)."""
    order = np.argsort(heights)
    placed = heights[order].astype(float)
    for i in range(1, len(placed)):
        placed[i] = max(placed[i], placed[i - 1] + gap)
    placed -= max(0.0, placed[-1] - 1.05)  # back inside the panel where the top ran over
    for i in range(len(placed) - 2, -1, -1):
        placed[i] = min(placed[i], placed[i + 1] - gap)
    out = np.empty_like(placed)
    out[order] = placed
    return out
