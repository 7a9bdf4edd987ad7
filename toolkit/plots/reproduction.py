"""Figures of the reproduction (paper §V, Figures 5-7): every function returns a matplotlib Figure.

Nothing here calls ``show()``; the figures render headless (Agg) and the caller
saves or displays them.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from toolkit.learning import metrics
from toolkit.learning.metrics import reconstruction_accuracy
from toolkit.plots.alt import Part, describe
from toolkit.plots.cae import grid_part
from toolkit.plots.palette import CATEGORICAL, COLORS, GREYS_CMAP, HATCHES, PAGE_WIDTH, series_style
from toolkit.plots.timings import MS, cut_in_words, ms_text, quartile_whiskers

MODES = ("without", "with")
STATS = ("median", "q1", "q3")  # a time's summary over the queries (queries.summarize)


def _show_grid(ax, grid: np.ndarray, title: str) -> None:
    """A 2D grid as is; a 3D grid as its middle slice along z (the CAE's input is the whole volume)."""
    if grid.ndim == 3:
        z = grid.shape[2] // 2
        grid, title = grid[:, :, z], f"{title} (slice z={z})"
    ax.imshow(grid.T, origin="lower", cmap=GREYS_CMAP, vmin=-1, vmax=1)
    ax.set_title(title, fontsize=9)
    ax.set_xticks([])
    ax.set_yticks([])


def cae_reconstruction(grids: dict[str, np.ndarray], decoded: dict[str, np.ndarray]) -> Figure:
    """Input vs decoded occupancy for named workspaces (e.g. 'seen', 'unseen'); Table 1 in pictures."""
    fig = Figure(figsize=(3.2 * len(grids), 6.4))
    axes = fig.subplots(2, len(grids), squeeze=False)
    for col, name in enumerate(grids):
        _show_grid(axes[0, col], grids[name], f"{name}: input")
        _show_grid(axes[1, col], np.where(decoded[name] >= 0, 1.0, -1.0), f"{name}: decoded (sign)")
    fig.suptitle("CAE reconstruction: black = occupied")
    fig.tight_layout()
    said = "; ".join(
        f"{name}: {float(reconstruction_accuracy(decoded[name][None], grids[name][None])[0]):.1%} of cells right, "
        f"all free {np.mean(grids[name] < 0):.1%}"
        for name in grids
    )
    text = "Occupancy grids (a 3D one as its middle z slice) above their reconstructions, occupied black. "
    parts = [grid_part(name, name, _drawn(grids[name]), _drawn(decoded[name])) for name in grids]
    return describe(fig, text + said + ".", parts)


def _drawn(grid: np.ndarray) -> np.ndarray:
    """The 2D grid :func:`_show_grid` draws: a 3D one's middle z slice."""
    return grid[:, :, grid.shape[2] // 2] if grid.ndim == 3 else grid


TIMES = (("sampling_s", "sampling time"), ("total_s", "total time per query"))  # the rows of planning_times


def planning_times(planning: dict, title: str = "") -> Figure:
    """Sampling and total time per query in ms, without / with prediction (the paper's Figures 5-7): a row per time,
    a small panel per sampler, each on its own scale from zero so that a sampler's two bars compare even where
    another sampler takes fifty times as long; the median over the queries, written under its bar, a whisker from
    the first to the third quartile (the paper draws means and stds; a single slow query moves both, and a std bar
    can reach below zero). A whisker past twice its panel's taller bar is cut at the top, its end written over it
    (``timings.quartile_whiskers``). The bars with prediction are named as the paper names them (BSF: BS with the
    framework)."""
    samplers = list(planning)  # the paper's four, or the ones the run planned
    fig = Figure(figsize=(PAGE_WIDTH, 6.4), layout="constrained")
    grid = fig.add_gridspec(len(TIMES), 1)
    rows = [fig.add_subfigure(grid[k, 0]) for k in range(len(TIMES))]  # a row of panels a time
    said = []
    for row, (key, label) in zip(rows, TIMES):
        panels = row.subplots(1, len(samplers), squeeze=False)[0]
        cuts = [_sampler_panel(ax, planning[s], s, key) for ax, s in zip(panels, samplers)]
        row.suptitle(f"{label} (ms): median under each bar, whiskers from quartile to quartile", fontsize=9)
        bars = ", ".join(
            f"{s} {ms_text(MS * planning[s]['without'][f'{key}_median'])} without, "
            f"{ms_text(MS * planning[s]['with'][f'{key}_median'])} with"
            for s in samplers
        )
        said.append(f"{label}: {bars}" + "".join(f"; {c}" for c in cuts if c))
    shown = {label: h for ax in fig.axes for h, label in zip(*ax.get_legend_handles_labels())}  # each entry once
    order = sorted(shown, key=lambda label: not label.endswith(("prediction", "(F)")))  # the bars first
    fig.legend([shown[label] for label in order], order, loc="outside lower center", ncol=2, fontsize=8, frameon=False)
    fig.suptitle(title or "Time with and without prediction", fontsize=10)
    text = f"{title or 'Time with and without prediction'}: bars of the median over the queries in ms, plain without"
    text += " prediction and hatched with it, whiskers from quartile to quartile, a small panel per sampler, each on"
    text += f" its own scale. {'; '.join(said)}."
    parts = [
        Part(
            label,
            "ms; the median over the queries, first and third quartile",
            ("sampler", *(f"{stat}, {mode}" for mode in MODES for stat in STATS)),
            tuple(
                (s, *(ms_text(MS * planning[s][mode][f"{key}_{stat}"]) for mode in MODES for stat in STATS))
                for s in samplers
            ),
        )
        for key, label in TIMES
    ]
    return describe(fig, text, parts)


def _sampler_panel(ax, times: dict, s: str, key: str) -> str:
    """One sampler's two bars of ``key`` (``times[mode]``: its median and quartiles in s) on ``ax``, in ms, the
    median written under each bar; returns the words for a whisker cut at the top ("" if none)."""
    x = np.array([[0.0, 1.0]])  # (1, modes) bar centres in a panel
    median, q1, q3 = (
        MS * np.array([[times[mode][f"{key}_{stat}"] for mode in MODES]]) for stat in STATS
    )  # (1, modes) each
    for i, mode in enumerate(MODES):
        ax.bar(
            x[:, i],
            median[:, i],
            0.7,
            color=CATEGORICAL[i],
            hatch=HATCHES[i],
            edgecolor=COLORS["ink"],
            linewidth=0.5,
            label=f"{mode} prediction" + (" (F)" if mode == "with" else ""),
        )
    cut = quartile_whiskers(ax, x, median, q1, q3, tallest=median.max(), end_above=True)
    ax.set_xticks(x[0], [f"{name}\n{ms_text(t)}" for name, t in zip((s, s + "F"), median[0])])
    ax.set_xlim(-0.6, 1.6)
    ax.yaxis.set_major_locator(MaxNLocator(4))
    ax.tick_params(labelsize=8)
    ax.set_ylabel("ms", fontsize=8, labelpad=1)
    ax.set_xlabel("median, ms", fontsize=8)
    return cut_in_words(cut, [[s, s + "F"]], q3, ax.get_ylim()[1]).removeprefix("; ")


def threshold_sweep(
    probability: np.ndarray,
    valid: np.ndarray,
    threshold: float | None = None,
    *,
    title: str = "MLP on unseen workspaces",
) -> Figure:
    """Accuracy, TPR and TNR of the MLP as the decision threshold on P(valid) moves over :data:`metrics.SWEEP`
    (:func:`toolkit.learning.metrics.threshold_sweep`); ``(N,)`` arrays. ``title`` names the model and samples (reader
    r37c: a second, zoomed panel over the span of P(valid) showed chapter 03's switch no finer than this one; cut)."""
    p, truth = np.asarray(probability).reshape(-1), np.asarray(valid, dtype=bool).reshape(-1)
    fig = Figure(figsize=(5, 4.2), layout="constrained")
    ax = fig.subplots()
    curves = _draw_sweep(ax, metrics.SWEEP, p, truth, threshold)
    ax.set_title(title, fontsize=10)
    fig.legend(*ax.get_legend_handles_labels(), fontsize=9, loc="outside lower center", ncols=2, frameon=False)
    ts, best = metrics.SWEEP, int(np.argmax(curves["accuracy"]))  # below the axes: the legend hides no curve
    text = "Accuracy, TPR and TNR of the MLP as the threshold on P(valid) moves from 0 to 1: accuracy is highest, "
    text += f"{curves['accuracy'][best]:.2f}, at threshold {ts[best]:.2f}"
    if threshold is not None:
        at = int(np.argmin(np.abs(ts - threshold)))
        text += f"; at the chosen threshold {threshold:.2f}: " + ", ".join(
            f"{name} {curve[at]:.2f}" for name, curve in curves.items()
        )
    return describe(fig, text + ".")


def _draw_sweep(ax, ts: np.ndarray, p: np.ndarray, truth: np.ndarray, threshold: float | None) -> dict:
    """Accuracy, TPR and TNR over thresholds ``ts (T,)``, the chosen ``threshold`` dotted; returns the curves."""
    rates = metrics.threshold_sweep(p, truth, ts)
    curves = {"accuracy": rates["acc"], "TPR (valid kept)": rates["tpr"], "TNR (invalid rejected)": rates["tnr"]}
    every = max(1, len(ts) // 10)
    for k, (name, curve) in zip((0, 3, 2), curves.items()):  # no vermillion square: chapter 03's "invalid kept" (r30c)
        ax.plot(ts, curve, label=name, **series_style(k) | dict(markevery=every, markersize=4))
    if threshold is not None:  # its rates ringed on each curve and named (reader r36c: the line fell on the jump)
        at = metrics.threshold_sweep(p, truth, np.array([threshold]))  # (1,) each: the rates at the threshold itself
        said = ", ".join(f"{name.split()[0]} {at[key][0]:.2f}" for name, key in zip(curves, ("acc", "tpr", "tnr")))
        ax.axvline(threshold, color=COLORS["reference"], linestyle=":", label=f"threshold {threshold:.2f}: {said}")
        for k, key in zip((0, 3, 2), ("acc", "tpr", "tnr")):
            ring = dict(markerfacecolor="none", markeredgewidth=1.8, markersize=11, zorder=5)
            ax.plot([threshold], at[key], "o", color=series_style(k)["color"], **ring)
    ax.set_xlabel("threshold on P(valid)")
    ax.set_ylabel("share")
    ax.set_ylim(0, 1.02)
    return curves
