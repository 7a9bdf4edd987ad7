"""Where prediction pays: an exact check's cost per configuration against the network's (``toolkit bench --crossover``).

:func:`crossover` draws the sweeps of :func:`toolkit.experiments.crossover.crossover` (its
results dict, as ``crossover.json`` holds it): one panel per variable that makes an exact check
dear, microseconds per configuration on log-log axes, shaded where the network is the cheaper
check by more than the band in which a timing moves (the verdict "network cheaper" of
:func:`toolkit.util.verdicts.cost_verdict`, the words the tables and the conclusion use: a point
they call "can't tell" is not shaded) and a dotted line where its curve crosses an exact one.
Nothing here calls ``show()``.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from toolkit.plots.alt import describe
from toolkit.plots.palette import COLORS, halo
from toolkit.util.verdicts import CHEAPER, CLOSE, cost_verdict

STYLES = {  # checker -> (marker and line, colour, legend)
    "exact": ("o-", COLORS["exact"], "exact, default (compiled)"),
    "fcl": ("s--", COLORS["fcl"], "exact, python-fcl (a mesh: + numpy inside test)"),
    "learned": ("^-", COLORS["learned"], "learned (the network)"),
}


def crossover(results: dict) -> Figure:
    """One panel per swept variable: cost per configuration of the default exact checker, of python-fcl and of
    the learned checker against the variable; shaded where the network is cheaper than the default exact check
    by more than :data:`~toolkit.util.verdicts.CLOSE` (the verdict "network cheaper"), a dotted vertical line where
    two curves cross (the crossing's value beside it)."""
    sweeps = results["variables"]
    columns = min(len(sweeps), 2)
    rows = -(-len(sweeps) // columns)
    fig = Figure(figsize=(5.2 * columns, 3.9 * rows))
    axes = fig.subplots(rows, columns, squeeze=False).ravel()
    for ax, sweep in zip(axes, sweeps.values()):
        _panel(ax, sweep)
    for ax in axes[len(sweeps) :]:
        ax.set_visible(False)
    quick = " (quick sizes)" if results.get("quick") else ""
    fig.suptitle(
        f"Where prediction pays: {results['scenario']}, preset {results['preset']}{quick}; "
        f"shaded: the network cheaper by more than {CLOSE:.0%}"
    )
    fig.tight_layout()
    text = f"Cost per configuration of the exact and the learned check, {results['scenario']}, preset "
    text += f"{results['preset']}{quick}, microseconds on log axes. "
    return describe(fig, text + " ".join(_in_words(sweep) for sweep in sweeps.values()))


def _in_words(sweep: dict) -> str:
    """One panel in words: the learned check's cost against the default exact one's, where it is cheaper."""
    x = np.asarray(sweep["values"], dtype=float)
    exact, learned = np.asarray(sweep["exact_us"], float), np.asarray(sweep["learned_us"], float)
    ratio = learned / exact  # (V,) below 1: the network is cheaper
    wins = [f"{v:,.0f}" for v, r in zip(x, ratio) if cost_verdict(float(r)) == CHEAPER]
    low, high = (f"{r:.2f}" if r < 10 else f"{r:,.0f}" for r in (np.nanmin(ratio), np.nanmax(ratio)))
    text = f"{sweep['label']} from {x[0]:,.0f} to {x[-1]:,.0f}: the network costs {low} to {high} times the exact "
    text += "check; "
    by = f"cheaper by more than {CLOSE:.0%}"
    return text + (f"{by} at {', '.join(wins)}." if wins else f"never {by}.")


def _panel(ax, sweep: dict) -> None:
    """One variable: the three curves, the values where the network is cheaper (its verdict) shaded, the crossings."""
    x = np.asarray(sweep["values"], dtype=float)
    exact, learned = np.asarray(sweep["exact_us"], float), np.asarray(sweep["learned_us"], float)
    cheaper = np.array([cost_verdict(float(r)) == CHEAPER for r in learned / exact])  # (V,) beyond the band
    for name in ("exact", "fcl", "learned"):
        style, colour, label = STYLES[name]
        outline = halo(1.5) if name == "learned" else []  # orange alone is too light on white
        ax.plot(x, np.asarray(sweep[f"{name}_us"], float), style, color=colour, label=label, path_effects=outline)
    bounds = _halfway(x)  # (V+1,)
    for n, i in enumerate(np.flatnonzero(cheaper)):  # a band round each value the verdict calls "network cheaper"
        legend = f"network cheaper by > {CLOSE:.0%}" if n == 0 else None
        span = bounds[i : i + 2]  # (2,) its band: the panel's whole height (a shaded area, not a mark)
        ax.fill_between(
            span, 0, 1, transform=ax.get_xaxis_transform(), color=COLORS["learned"], alpha=0.2, lw=0, label=legend
        )
    for name, found in sweep["crossing"].items():
        if found is not None:
            ax.axvline(found["value"], ls=":", color=STYLES[name][1])
            ax.annotate(
                f"{found['value']:,.3g}", (found["value"], 0.02), xycoords=("data", "axes fraction"), fontsize=8
            )
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xticks(x, [f"{v:,.0f}" for v in x])  # the measured values, as numbers
    ax.minorticks_off()
    ax.set_xlabel(sweep["label"])
    ax.set_ylabel("µs per configuration")
    ax.legend(fontsize=8)


def _halfway(x: np.ndarray) -> np.ndarray:
    """``(V+1,)`` the bounds of a band round each of the ``(V,)`` increasing values ``x`` on a log axis: halfway
    (geometrically) between neighbours, as far beyond the first and the last (a factor 1.5 for a lone value)."""
    if len(x) == 1:
        return np.array([x[0] / 1.5, x[0] * 1.5])
    middle = np.sqrt(x[1:] * x[:-1])  # (V-1,)
    return np.concatenate([[x[0] ** 2 / middle[0]], middle, [x[-1] ** 2 / middle[-1]]])
