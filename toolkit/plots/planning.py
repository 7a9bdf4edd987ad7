"""Figures of PRM with and without prediction (paper §III-B, Algorithm 1; §V, Table 3): notebook 04.

The 2D figures draw the point robot's configuration space, where a configuration is
the robot's centre (x, y): C-obstacles (the blocks grown by the robot's half-size, as
the exact checker sees them) are shaded, the blocks themselves outlined, and the
bounds of the centre dotted (half a robot inside the region). Samples,
roadmaps and paths are drawn over it. The other figures compare timings and
throughputs. Every function returns a matplotlib ``Figure`` and never calls ``show()``.
"""

from __future__ import annotations

import textwrap
from typing import Any

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.colors import ListedColormap
from matplotlib.figure import Figure
from matplotlib.patches import Rectangle
from matplotlib.ticker import NullFormatter

from toolkit.geometry.collision import CollisionChecker
from toolkit.planning.prm import GOAL, START, PlanStep
from toolkit.planning.sampling import PAPER_SAMPLERS
from toolkit.plots.alt import Part, describe, map_part
from toolkit.plots.cspace import checker_workspace
from toolkit.plots.palette import CATEGORICAL, COLORS, HATCHES, halo
from toolkit.plots.slices import slice_configs

MODES = ("without", "with")
STAGE_KEYS = ("sampling_s", "connection_s", "query_s")  # PRM stats, in the order the planner spends them
STAGE_HATCHES = ("", "//", "..", "xx")  # sampling, connection, query, other: told apart without colour
STAGE_LABELS = {
    "sampling_s": "sampling (S, S')",
    "connection_s": "connection (edges)",
    "query_s": "query (path, verification, repair)",
    "other_s": "other (encoding, set-up)",
}
C_OBSTACLE = ListedColormap([COLORS["free"], COLORS["c_obstacle"]])  # valid, invalid
EDGE_COLOR, NODE_COLOR = COLORS["edge"], COLORS["node"]
PATH_STYLES = {  # by stage: colour, line style (candidate dashed, one a repair rejected dash-dotted, answer solid)
    "candidate": (COLORS["candidate"], "--"),
    "repair": (COLORS["candidate"], "-."),
    "path": (COLORS["path"], "-"),
}
REPAIR_COLOR = COLORS["removed"]  # what the exact checker rejected: removed by a repair (drawn as X)


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
    for lo, hi in ws.boxes:
        ax.add_patch(Rectangle(lo, *(hi - lo), fill=False, edgecolor=COLORS["occupied"], linewidth=0.8))
    ax.add_patch(  # the bounds of the robot's centre
        Rectangle(
            extent[::2],
            extent[1] - extent[0],
            extent[3] - extent[2],
            fill=False,
            edgecolor=COLORS["occupied"],
            linewidth=0.8,
            linestyle=":",
        )
    )
    ax.set_xlim(ws.lower[0], ws.upper[0])
    ax.set_ylim(ws.lower[1], ws.upper[1])
    ax.set_aspect("equal")
    ax.locator_params(nbins=4)
    ax.tick_params(labelsize=8)
    ax.set_xlabel("x")
    ax.set_ylabel("y")


def samplers(exact: CollisionChecker, samples: dict[str, np.ndarray], attempts: int | None = None) -> Figure:
    """One panel per sampler: its samples ``(M, 2)`` over the C-obstacles (§III-B, "Sample Generation")."""
    fig = Figure(figsize=(3.2 * len(samples), 3.6))
    axes = fig.subplots(1, len(samples), squeeze=False)[0]
    for ax, (name, Q) in zip(axes, samples.items()):
        _draw_cspace(ax, exact)
        ax.scatter(Q[:, 0], Q[:, 1], s=6, color=NODE_COLOR)
        count = f"{len(Q)} sample{'' if len(Q) == 1 else 's'}"
        ax.set_title(f"{name}: {count}" + (f" of {attempts} attempts" if attempts else ""), fontsize=9)
    fig.suptitle("Samples over the exact checker (grey: C-obstacles)", fontsize=10)
    fig.tight_layout()
    counts = "; ".join(f"{name}: {len(Q)}" for name, Q in samples.items())
    of = f" of {attempts} attempts each" if attempts else ""
    valid, _ = cspace_validity(exact, pixels=4 * 20)  # (H, W): rows are y; 4 x 4 regions of 20 x 20 pixels
    blocked = 1 - valid.T.reshape(4, 20, 4, 20).mean(axis=(1, 3))  # (4, 4) C-obstacle share per region, [x, y]
    parts = [_samples_part(exact.robot, name, Q, blocked) for name, Q in samples.items()]
    text = f"Samples of {len(samples)} samplers{of} over the point robot's C-obstacles (grey). {counts}."
    return describe(fig, text, parts)


def _samples_part(robot, name: str, Q: np.ndarray, blocked: np.ndarray) -> Part:
    """One sampler's samples ``Q (M, 2)`` counted region by region of the C-space, beside the share of each region
    that is C-obstacle (``blocked (b, b)``, ``[x, y]``): where a sampler that seeks obstacles puts its samples."""
    edges = [np.linspace(lo, hi, len(blocked) + 1) for lo, hi in zip(robot.lower, robot.upper)]
    counts = np.histogram2d(Q[:, 0], Q[:, 1], bins=edges)[0]  # (b, b), [x, y]
    x, y = ("x", robot.lower[0], robot.upper[0]), ("y", robot.lower[1], robot.upper[1])
    cell = lambda r: f"{int(counts[r].sum())} samples; {blocked[r].mean():.0%} C-obstacle"
    text = f"{len(Q)} samples; by region, top row first: how many fell there, and the share of it that is C-obstacle"
    return map_part(name, text, counts.shape, x, y, cell)


def sample_sets(exact: CollisionChecker, S: np.ndarray, accepted: np.ndarray) -> Figure:
    """Algorithm 1, lines 2-3: the attempts ``S (N, 2)``, the ones a checker accepts (``accepted (N,)`` bool: S'),
    and among those the ones the exact checker rejects (the dangerous mistakes: large X in the invalid colour)."""
    truly_valid = exact.are_valid(S)
    fig = Figure(figsize=(4.6, 4.6))
    ax = fig.subplots()
    _draw_cspace(ax, exact)
    groups: list[tuple[np.ndarray, dict[str, Any], str]] = [  # (mask, scatter style, label)
        (~accepted, dict(marker="x", s=10, color=COLORS["rejected"]), "rejected"),
        (accepted & truly_valid, dict(s=10, marker="o", color=COLORS["valid"]), "S' (accepted)"),
        (
            accepted & ~truly_valid,
            dict(s=30, marker="X", color=COLORS["invalid"], path_effects=halo(0.0)),
            "S', truly in collision",
        ),
    ]
    for mask, style, label in groups:
        ax.scatter(S[mask, 0], S[mask, 1], label=f"{label}: {mask.sum()}", **style)
    ax.legend(fontsize=8, loc="upper left", framealpha=0.9)
    ax.set_title(f"S: {len(S)} uniform attempts", fontsize=9)
    fig.tight_layout()
    counts = "; ".join(f"{label}: {mask.sum()} (marker {style['marker']})" for mask, style, label in groups)
    return describe(fig, f"{len(S)} uniform attempts S over the point robot's C-obstacles (grey). {counts}.")


def _draw_roadmap(ax, exact: CollisionChecker, step: PlanStep) -> None:
    """One planner step: edges, nodes (hollow: not yet confirmed exactly), start and goal, the candidate path,
    and what a repair removes (thick, and X at removed nodes); a legend names them."""
    _draw_cspace(ax, exact)
    P = step.nodes  # (V, 2)
    removed_edge = np.zeros(len(step.edges), dtype=bool)
    removed_edge[step.removed_edges] = True
    ax.add_collection(LineCollection(P[step.edges[~removed_edge]], colors=EDGE_COLOR, linewidths=0.5, zorder=2))
    confirmed = step.node_verified
    ax.scatter(*P[confirmed].T, s=7, color=NODE_COLOR, zorder=3, label="node, confirmed")
    ax.scatter(*P[~confirmed].T, s=9, facecolors="none", edgecolors=NODE_COLOR, linewidths=0.7, zorder=3, label="node")
    if len(step.path):
        color, style = PATH_STYLES[step.stage]
        outline = halo(2.2) if color != COLORS["path"] else []  # the candidate's light blue needs an outline
        ax.plot(
            *P[step.path].T,
            color=color,
            linestyle=style,
            linewidth=2.2,
            zorder=4,
            label=f"path ({step.stage})",
            path_effects=outline,
        )
    removed = LineCollection(P[step.edges[removed_edge]], colors=REPAIR_COLOR, linewidths=3, zorder=5)
    removed.set_path_effects(halo(3))
    ax.add_collection(removed)
    ax.scatter(
        *P[step.removed_nodes].T,
        s=70,
        marker="X",
        color=REPAIR_COLOR,
        zorder=5,
        label="removed by a repair",
        path_effects=halo(0.0),
    )
    for node, marker, name in ((START, "s", "start"), (GOAL, "*", "goal")):
        ax.scatter(
            *P[node], s=110, marker=marker, color=COLORS["endpoint"], edgecolors=COLORS["free"], zorder=6, label=name
        )
    ax.set_title(f"round {step.round}, {step.stage}:\n{len(P)} nodes, {len(step.edges)} edges", fontsize=9)


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
    """One step of Algorithm 1 in words (the text alternative of its roadmap picture)."""
    text = f"Round {step.round}, {step.stage}: a roadmap of {len(step.nodes)} nodes "
    text += f"({int(np.sum(step.node_verified))} confirmed exactly) and {len(step.edges)} edges over the C-obstacles"
    if len(step.path):
        line = {"path": "solid", "repair": "dash-dotted"}.get(step.stage, "dashed")
        text += f"; a {line} path through {len(step.path)} nodes"
    return text + f"; a repair removed {len(step.removed_nodes)} nodes and {len(step.removed_edges)} edges."


def roadmap_steps(exact: CollisionChecker, steps: list[PlanStep], columns: int = 3) -> Figure:
    """Several steps of Algorithm 1 side by side, the roadmap drawn at each (one panel per step)."""
    rows = -(-len(steps) // columns)
    fig = Figure(figsize=(3.8 * columns, 4.2 * rows + 0.8), layout="constrained")
    axes = fig.subplots(rows, columns, squeeze=False).ravel()
    for ax, step in zip(axes, steps):
        _draw_roadmap(ax, exact, step)
    for ax in axes[len(steps) :]:
        ax.set_axis_off()
    fig.suptitle("Algorithm 1 step by step\n(hollow: not yet confirmed exactly; X: removed by a repair)", fontsize=10)
    _roadmap_legend(fig, axes)
    text = f"Algorithm 1 step by step, one panel per step, {len(steps)} steps. First: {step_in_words(steps[0])}"
    text += f" Last: {step_in_words(steps[-1])}" if len(steps) > 1 else ""  # every step: the longer description
    return describe(fig, text, [_step_part(step) for step in steps])


def _step_part(step: PlanStep) -> Part:
    """One step of Algorithm 1 (one panel): in words, and its path's nodes in order with where they lie."""
    rows = tuple(
        (str(k + 1), f"{step.nodes[n][0]:.3g}", f"{step.nodes[n][1]:.3g}", _node_state(step, n))
        for k, n in enumerate(step.path)
    )
    columns = ("path node", "x", "y", "node") if rows else ()
    return Part(f"Round {step.round}, {step.stage}", step_in_words(step), columns, rows)


def _node_state(step: PlanStep, n: int) -> str:
    if n in (START, GOAL):
        return "start" if n == START else "goal"
    if n in step.removed_nodes:
        return "removed by the repair"
    return "confirmed exactly" if step.node_verified[n] else "not yet confirmed"


def _roadmap_legend(fig: Figure, axes) -> None:
    """One legend below the panels naming every kind of mark any of them drew (each name once)."""
    named = {label: handle for ax in axes for handle, label in zip(*ax.get_legend_handles_labels())}
    style: dict[str, Any] = dict(ncol=min(len(named), 4), fontsize=8, frameon=False)
    style["loc"] = "outside lower center" if fig.get_layout_engine() is not None else "lower center"
    fig.legend(list(named.values()), list(named), **style)


def stage_times(panels: dict[str, dict]) -> Figure:
    """Per panel (e.g. a scenario), a ``planning`` table ``{sampler: {"without": summary, "with": summary}}``
    (``queries.summarize``): one bar per sampler and mode, as tall as the median total over the queries, split
    into the planner's stages in the shares of an average query (``_share``; the rest, encoding and set-up, on top
    as "other"); a whisker from the total's first to third quartile; the ratio of the median totals above each
    pair."""
    fig = Figure(figsize=(5.2 * len(panels), 4.8))
    axes = fig.subplots(1, len(panels), squeeze=False)[0]
    said, parts = [], []
    for ax, (title, planning) in zip(axes, panels.items()):
        names = list(planning)  # the samplers planned, in their order
        x = np.arange(len(names))[:, None] + np.array([-0.2, 0.2])  # (samplers, modes) bar centres
        table = {
            key: np.array([[planning[s][m][key] for m in MODES] for s in names])
            for key in [f"total_s_{stat}" for stat in ("median", "q1", "q3")] + [f"{k}_share" for k in STAGE_KEYS]
        }  # key -> (samplers, modes)
        table["total_s"] = table["total_s_median"]
        table.update({key: table["total_s"] * table[f"{key}_share"] for key in STAGE_KEYS})
        table["other_s"] = np.maximum(table["total_s"] - sum(table[k] for k in STAGE_KEYS), 0.0)
        top = _draw_stage_bars(ax, x, table)  # (samplers, modes) the bars' and whiskers' tops
        ratio = table["total_s"][:, 1] / np.maximum(table["total_s"][:, 0], 1e-12)
        for i, r in enumerate(ratio):
            ax.annotate(
                f"{r:.2f}x", (i, top[i].max()), xytext=(0, 3), textcoords="offset points", ha="center", fontsize=8
            )
        ax.set_xticks(x.ravel(), [f"{s}\n{m}" for s in names for m in MODES], fontsize=8)
        ax.set_xlabel("sampler, without / with prediction")
        ax.set_ylabel("seconds per query (median)")
        ax.set_ylim(0, top.max() * 1.15)
        ax.set_title(f"{title}: median total with / without prediction", fontsize=9)
        said.append(
            f"{title}: "
            + ", ".join(
                f"{s} {table['total_s'][i, 0]:.3g} s without, {table['total_s'][i, 1]:.3g} s with ({ratio[i]:.2f}x)"
                for i, s in enumerate(names)
            )
        )
        keys = ("total_s", "total_s_q1", "total_s_q3", *STAGE_KEYS, "other_s")
        rows = tuple(
            (f"{s}, {m}", *(f"{table[key][i, j]:.3g}" for key in keys))
            for i, s in enumerate(names)
            for j, m in enumerate(MODES)
        )
        columns = ("sampler, prediction", "median total", "first quartile", "third quartile", *STAGE_LABELS.values())
        parts.append(Part(title, f"seconds per query; {said[-1]}", columns, rows))
    fig.legend(*axes[0].get_legend_handles_labels(), loc="lower center", ncol=3, fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.12, 1, 1))
    text = "Median planning time per query without and with prediction, per sampler, split into the planner's stages"
    text += f" (hatched), with the ratio with / without above each pair. {'; '.join(said)}."
    return describe(fig, text, parts)


def _draw_stage_bars(ax, x: np.ndarray, table: dict[str, np.ndarray]) -> np.ndarray:
    """:func:`stage_times`' bars at ``x (samplers, modes)``: the stages of ``table`` (key -> ``(samplers, modes)``)
    stacked, hatched by stage, and a whisker from the total's first to third quartile; returns their tops."""
    bottom = np.zeros_like(table["total_s"])
    for k, key in enumerate(STAGE_KEYS + ("other_s",)):
        ax.bar(
            x.ravel(),
            table[key].ravel(),
            0.38,
            bottom=bottom.ravel(),
            label=STAGE_LABELS[key],
            color=CATEGORICAL[k],
            hatch=STAGE_HATCHES[k],  # a second cue besides the colour
            edgecolor=COLORS["ink"],
            linewidth=0.5,
        )
        bottom = bottom + table[key]
    low, high = table["total_s"] - table["total_s_q1"], table["total_s_q3"] - table["total_s"]
    ax.errorbar(
        x.ravel(),
        table["total_s"].ravel(),
        yerr=[low.ravel(), high.ravel()],
        fmt="none",
        ecolor=COLORS["ink"],
        capsize=3,
        linewidth=1,
        label="total: quartiles",
    )
    return np.maximum(bottom, table["total_s_q3"])


def ratio_comparison(baselines: dict[str, dict[str, dict[str, float]]]) -> Figure:
    """Time with / without prediction per sampler (below 1: prediction saves time), one panel per baseline.

    ``{baseline: {series: {sampler: ratio}}}``: a baseline is what "without" was (the paper's own planner and
    means, our eager or lazy exact planner and medians), a series what was timed (e.g. "2DS, sampling"). Ratios
    against different baselines never share a bar group; the panels share one log axis, so heights compare.
    """
    fig = Figure(figsize=(3.8 * len(baselines), 4.2))
    axes = fig.subplots(1, len(baselines), squeeze=False, sharey=True)[0]
    said = []
    for ax, (title, series) in zip(axes, baselines.items()):
        width = 0.8 / len(series)
        for i, (name, ratios) in enumerate(series.items()):
            ax.bar(
                np.arange(len(PAPER_SAMPLERS)) + (i - (len(series) - 1) / 2) * width,
                [ratios[s] for s in PAPER_SAMPLERS],
                width,
                label=name,
                color=CATEGORICAL[i % len(CATEGORICAL)],
                hatch=HATCHES[i % len(HATCHES)],
                edgecolor=COLORS["ink"],
                linewidth=0.5,
            )
        every = np.array([[ratios[s] for s in PAPER_SAMPLERS] for ratios in series.values()])  # (series, samplers)
        said.append(
            f"{title}: {len(series)} series, ratios from {every.min():.2f} to {every.max():.2f}, below 1 for "
            f"{int(np.sum(every < 1))} of {every.size}"
        )  # each ratio: the longer description
        ax.axhline(1.0, color=COLORS["ink"], linewidth=0.8)
        ax.set_xticks(np.arange(len(PAPER_SAMPLERS)), PAPER_SAMPLERS)
        ax.set_xlabel("sampler")
        ax.set_title(textwrap.fill(title, 40), fontsize=9)
    _log_ticks(axes[0])  # shared by every panel
    axes[0].set_ylabel("time with / without")
    handles, names = axes[0].get_legend_handles_labels()
    fig.legend(handles, names, loc="lower center", ncol=min(len(names), 3), fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.1, 1, 1))
    text = "Planning time with prediction divided by the time without, per sampler, log scale; below 1 prediction saves"
    parts = [
        Part(
            title,
            "time with prediction / time without; below 1, prediction saves time",
            ("series", *PAPER_SAMPLERS),
            tuple((name, *(f"{ratios[s]:.2f}" for s in PAPER_SAMPLERS)) for name, ratios in series.items()),
        )
        for title, series in baselines.items()
    ]
    return describe(fig, f"{text} time. {'; '.join(said)}.", parts)


def _log_ticks(ax) -> None:
    """A log y axis labelled in plain numbers at 1-2-5 steps (0.2, 0.5, 1, 2), finer over less than a decade."""
    ax.set_yscale("log")
    lo, hi = ax.get_ylim()
    steps = (1, 2, 5) if hi / lo >= 10 else (1, 1.5, 2, 3, 5, 7)
    ticks = [m * 10.0**e for e in range(int(np.floor(np.log10(lo))), int(np.ceil(np.log10(hi))) + 1) for m in steps]
    ticks = [t for t in ticks if lo <= t <= hi]
    ax.set_yticks(ticks, [f"{t:g}" for t in ticks])
    ax.yaxis.set_minor_formatter(NullFormatter())


def throughputs(rates: dict[str, dict[str, float]]) -> Figure:
    """Configurations checked per second, ``{scenario: {checker: rate}}`` (e.g. exact, learned), log scale,
    each bar labelled with its rate."""
    fig = Figure(figsize=(5, 3.6))
    ax = fig.subplots()
    checkers = list(next(iter(rates.values())))
    width = 0.8 / len(checkers)
    for i, checker in enumerate(checkers):
        bars = ax.bar(
            np.arange(len(rates)) + (i - (len(checkers) - 1) / 2) * width,
            [rates[s][checker] for s in rates],
            width,
            label=checker,
            color=CATEGORICAL[i % len(CATEGORICAL)],
            hatch=HATCHES[i % len(HATCHES)],
            edgecolor=COLORS["ink"],
            linewidth=0.5,
        )
        ax.bar_label(bars, labels=[_per_second(rates[s][checker]) for s in rates], fontsize=8)
    ax.set_yscale("log")
    ax.set_xticks(np.arange(len(rates)), list(rates))
    ax.set_xlabel("scenario")
    ax.set_ylabel("configurations checked per second")
    ax.set_title("Collision checking in batches: exact vs learned", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    said = "; ".join(f"{s}: " + ", ".join(f"{c} {_per_second(r[c])}" for c in checkers) for s, r in rates.items())
    return describe(fig, f"Configurations checked per second in batches, log scale, per scenario and checker. {said}.")


def _per_second(rate: float) -> str:
    """A rate in thousands or millions: ``'210k/s'``, ``'3.4M/s'``."""
    return f"{rate / 1e6:.2g}M/s" if rate >= 1e6 else f"{rate / 1e3:.3g}k/s"
