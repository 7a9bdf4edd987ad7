"""Figures of PRM with and without prediction (paper §III-B, Algorithm 1; §V, Table 3): notebook 04.

The 2D figures draw the point robot's configuration space, where a configuration is the robot's centre (x, y):
C-obstacles (the blocks grown by the robot's half-size, as the exact checker sees them) are shaded, the blocks
themselves outlined, and the bounds of the centre dotted (half a robot inside the region). Samples, roadmaps and paths
are drawn over it (the timings: :mod:`toolkit.plots.timings`). Every function returns a matplotlib ``Figure`` and
never calls ``show()``.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.colors import ListedColormap
from matplotlib.figure import Figure
from matplotlib.patches import Rectangle
from scipy.ndimage import distance_transform_edt

from toolkit.geometry.collision import CollisionChecker
from toolkit.planning.prm import GOAL, START, PlanStep
from toolkit.plots.alt import Part, describe, many, map_part
from toolkit.plots.cspace import checker_workspace
from toolkit.plots.palette import COLORS, PAGE_WIDTH, halo
from toolkit.plots.slices import slice_configs

C_OBSTACLE = ListedColormap([COLORS["free"], COLORS["c_obstacle"]])  # valid, invalid
EDGE_COLOR, NODE_COLOR = COLORS["edge"], COLORS["node"]
PATH_STYLES = {  # by stage: colour, line style (candidate dashed, one a repair rejected dotted, answer solid)
    "candidate": (COLORS["candidate"], "--"),
    "repair": (COLORS["removed"], ":"),  # reader r50d, item 3: the rejected candidate in the repairs' colour too
    "path": (COLORS["path"], "-"),
}
REPAIR_COLOR = COLORS["removed"]  # what the exact checker rejected: removed by a repair (a node drawn as a ring)


def cspace_validity(exact: CollisionChecker, pixels: int = 300) -> tuple[np.ndarray, tuple[float, float, float, float]]:
    """The 2D robot's configuration space as an image: ``(H, W)`` bool validity at pixel centres (row = y), and the
    image's extent ``(x0, x1, y0, y1)``: the robot's bounds."""
    robot = exact.robot
    if robot.dof != 2:
        raise ValueError(f"a 2D configuration-space figure needs a 2-DoF robot, got {robot.name!r} ({robot.dof} DoF)")
    _, _, Q = slice_configs(robot, robot.lower, (0, 1), resolution=pixels)  # (W, H, 2): Q[a, b] = (x_a, y_b)
    valid = exact.are_valid(Q.reshape(-1, 2)).reshape(pixels, pixels).T  # (H, W)
    return valid, (robot.lower[0], robot.upper[0], robot.lower[1], robot.upper[1])


def _draw_cspace(ax, exact: CollisionChecker) -> None:
    """C-obstacles shaded (the exact checker's answer), the blocks themselves outlined."""
    valid, extent = cspace_validity(exact)
    ax.imshow(~valid, origin="lower", extent=extent, cmap=C_OBSTACLE, vmin=0, vmax=1, interpolation="nearest")
    ws = checker_workspace(exact)
    box: dict[str, Any] = dict(fill=False, edgecolor=COLORS["occupied"], linewidth=0.8)
    for lo, hi in ws.boxes:
        ax.add_patch(Rectangle(lo, *(hi - lo), **box))
    ax.add_patch(Rectangle(extent[::2], extent[1] - extent[0], extent[3] - extent[2], linestyle=":", **box))  # bounds
    ax.set_xlim(ws.lower[0], ws.upper[0])
    ax.set_ylim(ws.lower[1], ws.upper[1])
    ax.set_aspect("equal")
    ax.locator_params(nbins=4)
    ax.tick_params(labelsize=8)
    ax.set_xlabel("x")
    ax.set_ylabel("y")


NEAR = 0.05  # "near" in the sampler figure: within this share of the bounds' diagonal (half G's default sigma)


def clearance_map(exact: CollisionChecker, pixels: int = 300) -> tuple[np.ndarray, tuple[float, float, float, float]]:
    """``(H, W)`` each pixel's distance from the nearest C-obstacle pixel of :func:`cspace_validity`'s picture (0 on
    one; ``inf`` in a world without any), between pixel centres, so within a pixel of the exact distance; and the
    picture's extent."""
    valid, extent = cspace_validity(exact, pixels)  # (H, W)
    if valid.all():
        return np.full(valid.shape, np.inf), extent
    size = ((extent[3] - extent[2]) / valid.shape[0], (extent[1] - extent[0]) / valid.shape[1])  # a pixel's y, x
    return distance_transform_edt(valid, sampling=size), extent


def _at_pixels(field: np.ndarray, extent, Q: np.ndarray) -> np.ndarray:
    """``(M,)`` the values of ``field (H, W)`` at the pixels that hold ``Q (M, 2)``."""
    height, width = field.shape
    col = ((Q[:, 0] - extent[0]) / (extent[1] - extent[0]) * width).astype(int).clip(0, width - 1)
    row = ((Q[:, 1] - extent[2]) / (extent[3] - extent[2]) * height).astype(int).clip(0, height - 1)
    return field[row, col]


def _to_walls(robot, Q: np.ndarray) -> np.ndarray:
    """``(M,)`` each configuration's distance from the nearest bound of ``Q (M, 2)``: a wall, to a sampler."""
    return np.minimum(Q - robot.lower, robot.upper - Q).min(axis=1)


def _near_shares(field: np.ndarray, extent, robot, Q: np.ndarray, near: float) -> tuple[float, float]:
    """The shares of ``Q (M, 2)`` within ``near`` of a C-obstacle (read from ``field``, :func:`clearance_map`) and
    within ``near`` of a wall (the bounds)."""
    return float(np.mean(_at_pixels(field, extent, Q) <= near)), float(np.mean(_to_walls(robot, Q) <= near))


def samplers(
    exact: CollisionChecker,
    samples: dict[str, np.ndarray],
    attempts: int | None = None,
    near: float | None = None,
    *,
    nearness: bool = True,
) -> Figure:
    """One panel per sampler: its samples ``(M, 2)`` over the C-obstacles (§III-B, "Sample Generation"), and (unless
    not ``nearness``) how many of them lie near a C-obstacle or a wall, within ``near`` (default :data:`NEAR` of the
    bounds' diagonal; a dashed line at that distance round the C-obstacles), beside the share of the free space that
    does: where a sampler that seeks obstacles puts its samples, said in numbers."""
    robot = exact.robot
    near = NEAR * float(np.linalg.norm(robot.upper - robot.lower)) if near is None else float(near)
    field, extent = clearance_map(exact)  # (H, W)
    x, y = (
        lo + (np.arange(n) + 0.5) * (hi - lo) / n for lo, hi, n in zip(extent[::2], extent[1::2], field.shape[::-1])
    )
    free = np.stack(np.meshgrid(x, y), axis=-1)[field > 0]  # (F, 2) the free pixels' centres
    space = _near_shares(field, extent, robot, free, near)  # what a uniform sampler finds
    shares = {name: _near_shares(field, extent, robot, Q, near) for name, Q in samples.items() if len(Q) and nearness}
    columns = min(len(samples), 2)  # two a row: as wide as the page, its text as large as it is drawn
    rows = -(-len(samples) // columns)
    fig = Figure(figsize=(PAGE_WIDTH, 3.6 * rows + 0.7), layout="constrained")
    axes = fig.subplots(rows, columns, squeeze=False).ravel()
    for ax, (name, Q) in zip(axes, samples.items()):
        _draw_cspace(ax, exact)
        if nearness and np.isfinite(field).all():
            ax.contour(
                x, y, field, levels=[near], colors=COLORS["reference"], linestyles="--", linewidths=1.2, zorder=4
            )
        ax.scatter(Q[:, 0], Q[:, 1], s=8, color=NODE_COLOR, zorder=3)
        count = f"{len(Q)} sample{'' if len(Q) == 1 else 's'}" + (f" of {attempts} attempts" if attempts else "")
        where = f"\nnear: {shares[name][0]:.0%} a C-obstacle, {shares[name][1]:.0%} a wall" if name in shares else ""
        ax.set_title(f"{name}:\n{count}{where}", fontsize=9)  # lines: a long name never runs into its neighbour
    for ax in axes[len(samples) :]:
        ax.set_axis_off()
    title = "Samples over the exact checker (grey: C-obstacles)"
    nearby = f"near: within {near:.2g} of a C-obstacle (dashed line) or of a wall (dotted: how far the centre may go)"
    nearby += f";\nof the free space, {space[0]:.0%} lies near a C-obstacle, {space[1]:.0%} near a wall"
    fig.suptitle(f"{title}.\n{nearby[0].upper()}{nearby[1:]}" if nearness else title, fontsize=9)
    counts = "; ".join(
        f"{name}: {len(Q)}"
        + (f", {shares[name][0]:.0%} near a C-obstacle, {shares[name][1]:.0%} near a wall" if name in shares else "")
        for name, Q in samples.items()
    )
    of = f" of {attempts} attempts each" if attempts else ""
    valid, _ = cspace_validity(exact, pixels=4 * 20)  # (H, W): rows are y; 4 x 4 regions of 20 x 20 pixels
    blocked = 1 - valid.T.reshape(4, 20, 4, 20).mean(axis=(1, 3))  # (4, 4) C-obstacle share per region, [x, y]
    parts = [_samples_part(robot, name, Q, blocked) for name, Q in samples.items()]
    text = f"Samples of {len(samples)} samplers{of} over the point robot's C-obstacles (grey)"
    text += f"; {nearby}" if nearness else ""
    return describe(fig, f"{text}. {counts}.", parts)


def _samples_part(robot, name: str, Q: np.ndarray, blocked: np.ndarray) -> Part:
    """One sampler's samples ``Q (M, 2)`` counted region by region of the C-space, beside the share of each region
    that is C-obstacle (``blocked (b, b)``, ``[x, y]``): where a sampler that seeks obstacles puts its samples."""
    edges = [np.linspace(lo, hi, len(blocked) + 1) for lo, hi in zip(robot.lower, robot.upper)]
    counts = np.histogram2d(Q[:, 0], Q[:, 1], bins=edges)[0]  # (b, b), [x, y]
    x, y = ("x", robot.lower[0], robot.upper[0]), ("y", robot.lower[1], robot.upper[1])
    cell = lambda r: f"{int(counts[r].sum())} samples; {blocked[r].mean():.0%} C-obstacle"
    text = f"{len(Q)} samples; by region, top row first: samples there, and its C-obstacle share (alike in every table)"
    return map_part(name, text, counts.shape, x, y, cell)


OVERLAP = 0.015  # two markers closer than this share of the C-space's diagonal are drawn as one (review r24a)
SIDES = ((1, 1), (-1, 1), (1, -1), (-1, -1))  # where a count "(2)" may sit beside its marker, up and right first


def merged(points: np.ndarray, within: float) -> tuple[np.ndarray, list[int]]:
    """``points (N, 2)``, each group closer than ``within`` to its first point once, at its centre, and how many each
    stands for (r24a: 4 crosses seen beside the legend's "rejected: 5"; r32d: "2×" beside two crosses read as 3)."""
    left, shown, counts = list(range(len(points))), [], []
    while left:
        first = left.pop(0)
        near = [i for i in left if np.linalg.norm(points[i] - points[first]) < within]
        left = [i for i in left if i not in near]
        shown.append(points[[first, *near]].mean(axis=0))
        counts.append(1 + len(near))
    return np.array(shown).reshape(-1, 2), counts


RING = dict(s=70, marker="o", facecolors="none", edgecolors=COLORS["invalid"], linewidths=2.0)  # no checker's mark


def sample_sets(exact: CollisionChecker, S: np.ndarray, accepted: np.ndarray) -> Figure:
    """Algorithm 1, lines 2-3: the attempts ``S (N, 2)``, the ones a checker accepts (``accepted (N,)`` bool: S'),
    and among those the ones the exact checker rejects (the dangerous mistakes: :data:`RING`, as a removed node);
    markers on one another are drawn once (:func:`merged`) with their count, "(2)" (r32d: "2×" read as a cross more)."""
    truly_valid = exact.are_valid(S)
    fig = Figure(figsize=(4.6, 5.4), layout="constrained")
    ax = fig.subplots()
    _draw_cspace(ax, exact)
    groups: list[tuple[np.ndarray, dict[str, Any], str]] = [  # (mask, scatter style, label); reader r45d, item 1:
        # no checker's marker (chapter 04's crosses are our fast checker): dashes rejected, rings the dangerous ones
        (~accepted, dict(marker="_", s=60, linewidths=2.0, color=COLORS["rejected"]), "rejected (dashes)"),
        (accepted & truly_valid, dict(s=16, marker="o", color=COLORS["valid"]), "S' (accepted, dots)"),
        (accepted & ~truly_valid, RING | dict(path_effects=halo(2.0)), "S', truly in collision (rings)"),
    ]
    within = OVERLAP * float(np.linalg.norm(exact.robot.upper - exact.robot.lower))
    for mask, style, label in ((m, st, la) for m, st, la in groups if m.any()):  # reader r33d: no empty legend entry
        shown, many = merged(S[mask], within)  # markers on one another drawn once, with their count
        ax.scatter(shown[:, 0], shown[:, 1], label=f"{label}: {mask.sum()}", clip_on=False, **style)
        for (x, y), n in ((p, n) for p, n in zip(shown, many) if n > 1):
            others = S[np.linalg.norm(S - (x, y), axis=1) > within]  # the markers it must not sit beside
            far = [min(6 * within, *np.linalg.norm(others - (x, y) - 3 * within * np.array(d), axis=1)) for d in SIDES]
            dx, dy = SIDES[int(np.argmax(far))]  # the first side as far as any: up and right where all are free
            ax.annotate(  # beside its marker, on the side farthest from any other (reviews r25a, r28d, r32d)
                f"({n})",
                (x, y),
                xytext=(6 * dx, 6 * dy),
                textcoords="offset points",
                ha=("left" if dx > 0 else "right"),
                va=("bottom" if dy > 0 else "top"),
                fontsize=9,
                path_effects=halo(1.0, ("free",)),
            )
    fig.legend(fontsize=9, loc="outside lower center", ncol=2, frameon=False)  # below: never over a sample
    ax.set_title(f"S: {len(S)} uniform attempts", fontsize=10)
    counts = "; ".join(f"{label}: {mask.sum()}" for mask, _, label in groups)
    return describe(fig, f"{len(S)} uniform attempts S over the point robot's C-obstacles (grey). {counts}.")


EDGE_WORDS = "edge: predicted free, not yet checked"  # reader r31d: the thin edges named in the legend
HOLLOW = dict(marker="D", s=16, facecolors=EDGE_COLOR, edgecolors=COLORS["free"], linewidths=0.5)  # r50d: no ring


def _nodes(ax, P: np.ndarray, confirmed: np.ndarray, labels: tuple, zorder: float = 3, **style) -> None:
    """Nodes ``P``: black dots where ``confirmed`` (checked exactly), grey diamonds where not; ``labels`` name them."""
    ax.scatter(*P[confirmed].T, s=22, color=NODE_COLOR, zorder=zorder, label=labels[0], **style)
    ax.scatter(*P[~confirmed].T, **HOLLOW, zorder=zorder, label=labels[1], **style)


def _draw_roadmap(ax, exact: CollisionChecker, step: PlanStep, number: int = 0) -> None:
    """One planner step: edges, nodes (grey diamonds: not yet confirmed exactly), start and goal, the candidate path,
    and what a repair removes (thick, and a ring at removed nodes); a legend names them."""
    _draw_cspace(ax, exact)
    P = step.nodes  # (V, 2)
    removed_edge = np.zeros(len(step.edges), dtype=bool)
    removed_edge[step.removed_edges] = True
    edges = P[step.edges[~removed_edge]]
    ax.add_collection(LineCollection(edges, colors=EDGE_COLOR, linewidths=0.4, alpha=0.6, zorder=2, label=EDGE_WORDS))
    confirmed = step.node_verified
    _nodes(ax, P, confirmed, ("node, confirmed (black dot)", "node, not yet confirmed (grey diamond)"))
    if len(step.path):
        color, style = PATH_STYLES[step.stage]
        outline = halo(2.2) if color != COLORS["path"] else []  # light blue and vermillion need an outline
        ax.plot(
            *P[step.path].T,
            color=color,
            linestyle=style,
            linewidth=3.2,  # reader r41d: the candidate found at a glance among the edges
            zorder=4,
            label={"candidate": "candidate path (dashed)", "repair": "rejected candidate (dotted)"}.get(
                step.stage, "path, checked exactly (solid)"
            ),
            path_effects=outline,
        )
        on = np.asarray(step.path)  # reader r47d: the path's own nodes over its line, dot or diamond as elsewhere
        filled = on[confirmed[on]]  # reader r49d, item 5: a halo only on black dots; a diamond stays thin, not
        ax.scatter(*P[filled].T, s=22, color=NODE_COLOR, zorder=4.5, path_effects=halo(1.5))  # a ring's look
        ax.scatter(*P[on[~confirmed[on]]].T, **HOLLOW | dict(s=40, edgecolors=NODE_COLOR), zorder=4.5)  # on the line
    _removed_edges(ax, exact, P[step.edges[removed_edge]])
    ax.scatter(  # a ring: what truly collides, as in sample_sets (reader r45d, item 1: a cross is a checker's mark)
        *P[step.removed_nodes].T,
        **RING,
        zorder=5,
        label="node removed by a repair" if len(step.removed_nodes) else None,  # review r29d: none removed, none named
        path_effects=halo(2.0),
    )
    for node, marker, size, name in ((START, "s", 90, "start"), (GOAL, "*", 320, "goal")):  # a star's ink is thin
        ax.scatter(
            *P[node],
            s=size,
            marker=marker,
            color=COLORS["endpoint"],
            edgecolors=COLORS["free"],
            zorder=6,
            label=name,
            clip_on=False,  # whole at the edge of the C-space, where start and goal often lie
        )
    _margin(ax)
    head = f"step {number}: {step.stage}" if number else f"round {step.round}, {step.stage}:"  # r45d: the trace's step
    counts = f"{many(len(P), 'node')}, {many(len(step.edges), 'edge')}" + (f", round {step.round}" if number else "")
    ax.set_title(f"{head}\n{counts}", fontsize=10)


def _removed_edges(ax, exact: CollisionChecker, segments: np.ndarray, points: int = 201) -> None:
    """The edges a repair removes, ``segments (R, 2, 2)``, thick, and where each first enters a C-obstacle, a black
    triangle (review r25a: at the page's size one could not see whether the edge cut the block or grazed it; reader
    r61d, item 6: a ring means only what truly collides); the legend names the triangle (reader r40d)."""
    removed = LineCollection(
        list(segments), colors=REPAIR_COLOR, linewidths=4.5, zorder=5, label="edge removed by a repair"
    )
    removed.set_path_effects(halo(4.5))
    ax.add_collection(removed)
    for a, b in segments:
        Q = a + np.linspace(0.0, 1.0, points)[:, None] * (b - a)
        hit = np.flatnonzero(~exact.are_valid(Q))
        if hit.size:
            x, y = Q[hit[0]]
            entry = dict(s=90, marker="v", color=COLORS["ink"], edgecolors=COLORS["free"], linewidths=0.8, zorder=7)
            ax.scatter([x], [y], **entry, label="where a removed edge enters a C-obstacle")  # review r29d: named


def _margin(ax, share: float = 0.04) -> None:
    """Widen both axes by ``share`` of their span on each side: start and goal often lie at the C-space's edge, and a
    margin keeps their marks whole inside the frame (review r19a: a start square half outside it)."""
    for (low, high), set_limits in ((ax.get_xlim(), ax.set_xlim), (ax.get_ylim(), ax.set_ylim)):
        set_limits(low - share * (high - low), high + share * (high - low))


def roadmap(exact: CollisionChecker, step: PlanStep, title: str = "") -> Figure:
    """The roadmap at one step of Algorithm 1 (a :class:`~toolkit.planning.prm.PlanStep` of ``plan(..., trace=[])``)."""
    fig = Figure(figsize=(5, 5.2))
    ax = fig.subplots()
    _draw_roadmap(ax, exact, step)
    _roadmap_legend(fig, [ax])
    if title:
        fig.suptitle(title, fontsize=10, wrap=True)  # a long stage description wraps at the figure width
    fig.tight_layout(rect=(0, 0.1, 1, 1))
    return describe(fig, f"{title + ': ' if title else ''}{step_in_words(step)}", [_step_part(step)])


def step_in_words(step: PlanStep) -> str:
    """One step of Algorithm 1 in words (its roadmap picture's text alternative), removals only where there are any."""
    text = f"Round {step.round}, {step.stage}: a roadmap of {many(len(step.nodes), 'node')} "
    text += f"({int(np.sum(step.node_verified))} confirmed exactly) and {many(len(step.edges), 'edge')} over the "
    text += "C-obstacles"
    if len(step.path):
        line = {"path": "solid", "repair": "dotted"}.get(step.stage, "dashed")
        text += f"; a {line} path through {many(len(step.path), 'node')}"
    removed = [many(n, w) for n, w in ((len(step.removed_nodes), "node"), (len(step.removed_edges), "edge")) if n]
    return text + (f"; the exact checker rejected {' and '.join(removed)}, removed next" if removed else "") + "."


def roadmap_steps(
    exact: CollisionChecker, steps: list[PlanStep], columns: int = 2, of: int = 0, at: list[int] | None = None
) -> Figure:
    """Several steps of Algorithm 1 side by side, the roadmap drawn at each (one panel per step; ``columns`` a row,
    as wide as the page together); ``of``: the trace's steps in all (reader r37d: the title says "3 of 6 steps");
    ``at``: each step's number in the trace, from 1 (reader r45d: a panel is named by its step; default 1, 2, ...)."""
    at = at or list(range(1, len(steps) + 1))
    rows = -(-len(steps) // columns)
    below = 1.0 if len(steps) == rows * columns else 0.0  # r39d: no empty slot, so the legend's rows go below
    fig = Figure(figsize=(PAGE_WIDTH, PAGE_WIDTH / columns * 1.08 * rows + 0.4 + below), layout="constrained")
    axes = fig.subplots(rows, columns, squeeze=False).ravel()
    for ax, step, k in zip(axes, steps, at):
        _draw_roadmap(ax, exact, step, number=k)
    for ax in axes[len(steps) :]:
        ax.set_axis_off()  # an empty slot: the legend goes there
    title = f"The lazy PRM with edge screening: {len(steps)} of {of or len(steps)} steps"  # its edges predicted
    fig.suptitle(title, fontsize=11)  # reader r31d: one line; the legend names every mark
    _roadmap_legend(fig, axes, axes[len(steps)] if len(steps) < len(axes) else None)
    text = f"{title}, one panel per step, {len(steps)} steps." + "".join(  # review r28d: the repair's panel too
        f" Step {k}: {step_in_words(step)}" for k, step in zip(at, steps)
    )
    return describe(fig, text, [_step_part(step, k) for step, k in zip(steps, at)])


def _step_part(step: PlanStep, number: int = 0) -> Part:
    """One step of Algorithm 1 (one panel): in words, and its path's nodes in order with where they lie; named once
    (reader r45d: the words repeated the name's "Round 1, candidate")."""
    rows = tuple(
        (str(k + 1), f"{step.nodes[n][0]:.3g}", f"{step.nodes[n][1]:.3g}", _node_state(step, n))
        for k, n in enumerate(step.path)
    )
    columns = ("path node", "x", "y", "node") if rows else ()
    name = f"Step {number}, {step.stage}" if number else f"Round {step.round}, {step.stage}"
    return Part(name, step_in_words(step).split(": ", 1)[1], columns, rows)


def _node_state(step: PlanStep, n: int) -> str:
    if n in (START, GOAL):
        return "start" if n == START else "goal"
    if n in step.removed_nodes:
        return "removed by the repair"
    return "confirmed exactly" if step.node_verified[n] else "not yet confirmed"


def _roadmap_legend(fig: Figure, axes, empty=None) -> None:
    """One legend naming every kind of mark any panel drew (each name once): in the ``empty`` slot of the grid where
    there is one, else below the panels."""
    named = {label: handle for ax in axes for handle, label in zip(*ax.get_legend_handles_labels())}
    style: dict[str, Any] = dict(ncol=min(len(named), 2), fontsize=9, frameon=False, handlelength=3.5)
    if empty is not None:
        legend = empty.legend(
            list(named.values()),
            list(named),
            loc="center left",
            bbox_to_anchor=(-0.2, 0.5),
            fontsize=8.5,
            frameon=False,
            handlelength=2.5,
        )
        legend.set_in_layout(False)  # reader r31d: a wide legend shrank every panel; it fits its slot
        return
    style["loc"] = "outside lower center" if fig.get_layout_engine() is not None else "lower center"
    fig.legend(list(named.values()), list(named), **style)
