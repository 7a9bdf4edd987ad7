"""Figures of the reproduction (paper §V, Figures 5-7): every function returns a matplotlib Figure.

Nothing here calls ``show()``; the figures render headless (Agg) and the caller
saves or displays them.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

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


def planning_times(planning: dict, title: str = "") -> Figure:
    """Sampling and total time per query in ms, without / with prediction (the paper's Figures 5-7), one panel a
    row: the median over the queries, a whisker from the first to the third quartile (the paper draws means and
    stds; a single slow query moves both, and a std bar can reach below zero). Each panel on its own scale, set by
    its bars: a whisker past twice the tallest bar is cut at the top, its end written (``timings.quartile_whiskers``).
    The bars with prediction are named as the paper names them (BSF: BS with the framework)."""
    fig = Figure(figsize=(PAGE_WIDTH, 6.4))
    axes = fig.subplots(2, 1)
    samplers = list(planning)  # the paper's four, or the ones the run planned
    x = np.arange(len(samplers))[:, None] + np.array([-0.2, 0.2])  # (samplers, modes) bar centres
    said = []
    for ax, key, label in (
        (axes[0], "sampling_s", "sampling time (ms), median"),
        (axes[1], "total_s", "total time per query (ms), median"),
    ):
        median, q1, q3 = (
            MS * np.array([[planning[s][mode][f"{key}_{stat}"] for mode in MODES] for s in samplers]) for stat in STATS
        )  # (samplers, modes) each
        for i, mode in enumerate(MODES):
            ax.bar(
                x[:, i],
                median[:, i],
                0.38,
                color=CATEGORICAL[i],
                hatch=HATCHES[i],
                edgecolor=COLORS["ink"],
                linewidth=0.5,
                label=f"{mode} prediction" + (" (F)" if mode == "with" else ""),
            )
        cut = quartile_whiskers(ax, x, median, q1, q3, tallest=median.max())
        ax.set_xticks(x.ravel(), [name for s in samplers for name in (s, s + "F")], fontsize=9)
        ax.set_xlabel("sampler (F: with prediction, the paper's name)")
        ax.set_ylabel(label)
        bars = ", ".join(
            f"{s} {ms_text(median[i, 0])} without, {ms_text(median[i, 1])} with" for i, s in enumerate(samplers)
        )
        said.append(f"{label}: {bars}" + cut_in_words(cut, [[s, s + "F"] for s in samplers], q3, ax.get_ylim()[1]))
    shown = {label: h for ax in axes for h, label in zip(*ax.get_legend_handles_labels())}  # each entry once
    fig.legend(shown.values(), shown.keys(), loc="lower center", ncol=2, fontsize=8, frameon=False)
    fig.suptitle(title or "Time with and without prediction", fontsize=10)
    fig.tight_layout(rect=(0, 0.5 / fig.get_figheight(), 1, 1))  # the legend in the 0.5 in below the panels
    text = f"{title or 'Time with and without prediction'}: bars of the median over the queries in ms, plain without"
    text += f" prediction and hatched with it, whiskers from quartile to quartile. {'; '.join(said)}."
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
        for key, label in (("sampling_s", "sampling time"), ("total_s", "total time per query"))
    ]
    return describe(fig, text, parts)


def threshold_sweep(
    probability: np.ndarray,
    valid: np.ndarray,
    threshold: float | None = None,
    *,
    title: str = "MLP on unseen workspaces",
) -> Figure:
    """Accuracy, TPR and TNR of the MLP as the decision threshold on P(valid) moves over :data:`metrics.SWEEP`
    (:func:`toolkit.learning.metrics.threshold_sweep`); ``(N,)`` arrays. ``title`` names the model and samples."""
    ts = metrics.SWEEP
    rates = metrics.threshold_sweep(np.asarray(probability).reshape(-1), np.asarray(valid, dtype=bool).reshape(-1))
    fig = Figure(figsize=(5, 4.2), layout="constrained")
    ax = fig.subplots()
    curves = {
        "accuracy": rates["acc"],
        "TPR (valid kept)": rates["tpr"],
        "TNR (invalid rejected)": rates["tnr"],
    }  # name -> (T,)
    for k, (name, curve) in enumerate(curves.items()):
        ax.plot(ts, curve, label=name, **series_style(k) | dict(markevery=10, markersize=4))
    if threshold is not None:
        ax.axvline(threshold, color=COLORS["reference"], linestyle=":", label=f"threshold {threshold:.2f}")
    ax.set_xlabel("threshold on P(valid)")
    ax.set_ylabel("share")
    ax.set_ylim(0, 1.02)
    fig.legend(fontsize=9, loc="outside lower center", ncols=2, frameon=False)  # below the axes: it hides no curve
    ax.set_title(title, fontsize=10)
    best = int(np.argmax(curves["accuracy"]))
    text = "Accuracy, TPR and TNR of the MLP as the threshold on P(valid) moves from 0 to 1: accuracy is highest, "
    text += f"{curves['accuracy'][best]:.2f}, at threshold {ts[best]:.2f}"
    if threshold is not None:
        at = int(np.argmin(np.abs(ts - threshold)))
        text += f"; at the chosen threshold {threshold:.2f}: " + ", ".join(
            f"{name} {curve[at]:.2f}" for name, curve in curves.items()
        )
    return describe(fig, text + ".")
