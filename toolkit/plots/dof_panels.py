"""A path's degrees of freedom over time, a panel per kind (notebook 05, :func:`toolkit.plots.scenes.path_frame`).

Seven lines in one panel cross and hide each other, so the DoFs are grouped by kind (:func:`dof_groups`: the
base's position, its angles, the joints) and each group drawn in a panel of its own (:func:`draw_dofs`), every
DoF scaled to its bounds and named beside the panel at the height its line ends, the names moved apart just enough to
be read.
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
        ax.plot(x, y, linewidth=1.4, label=robot.dof_names[k], gid="dof", **style)
        lone = _lone_frames(scaled[:, k]) if kind == "angles" else np.zeros(0, dtype=int)  # (l,) one-frame pieces
        if len(lone):  # draw no line: a marker shows each
            ax.plot(along[lone], scaled[lone, k], **(style | dict(linestyle="none", markevery=None)), gid="dof-lone")
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
            fontsize=8,
            va="center",
            color=COLORS["ink"],  # 8-point text in a line's colour is 3.1 to 3.9:1 on white (WCAG 1.4.3 asks 4.5)
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
    """An angle's line ``scaled (T,)`` against ``along (T,)`` broken (a NaN between) where it wraps around: where it
    jumps more than half its range between two frames, it went through -pi = pi, not across the panel."""
    wraps = wrap_frames(scaled) + 1  # (w,) the frames after a wrap
    return np.insert(along, wraps, np.nan), np.insert(scaled, wraps, np.nan)  # (T + w,) each


def _lone_frames(scaled: np.ndarray) -> np.ndarray:
    """The frames ``(l,)`` of an angle ``scaled (T,)`` that wraps both before and after them (or at the path's end):
    drawn broken, each is a piece of one point, which a line cannot show (reader r21c: beta's start at 0.00)."""
    edges = np.concatenate(([0], wrap_frames(scaled) + 1, [len(scaled)]))  # (w + 2,) where each piece starts
    return edges[:-1][np.diff(edges) == 1]


def wrap_frames(scaled: np.ndarray) -> np.ndarray:
    """The frames ``(w,)`` after which an angle ``scaled (T,)`` to its bounds wraps round ±π: where it jumps more
    than half its range between two frames (a path moves in small steps, so it went through -π = π)."""
    return np.flatnonzero(np.abs(np.diff(scaled)) > 0.5)


def wrap_note(robot: BoxRobot, Q: np.ndarray, angles: list[int]) -> str:
    """A legend title's second line where an angle wraps round ±π: its broken line is no missing data (r20c)."""
    scaled = (Q - robot.lower) / (robot.upper - robot.lower)  # (T, dof) in [0, 1]
    names = [robot.dof_names[k] for k in angles if len(wrap_frames(scaled[:, k]))]
    named = ", ".join(names[:-1]) + " and " * (len(names) > 1) + "".join(names[-1:])  # "alpha, beta and gamma"
    return f"\n{named}: a gap where the angle wraps round ±π, no data missing" if names else ""


LEADER_COLOR = COLORS["reference"]  # a name's leader: a grey no DoF's line is drawn in
LABEL_GAP = 14.0  # points between two names at the lines' ends: an 8-point line of text (~9.4 pt tall) and air
# enough that two names never read as one (reader r20c: "y" and "z" 11 points apart nearly touched)


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
