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

from toolkit.plots.alt import Part, describe
from toolkit.plots.palette import COLORS, PAGE_WIDTH, halo
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
    fig = Figure(figsize=(PAGE_WIDTH, 3.2 * rows + 1.8))  # as wide as the page: its text as large as it is drawn
    axes = fig.subplots(rows, columns, squeeze=False).ravel()
    for ax, sweep in zip(axes, sweeps.values()):
        _panel(ax, sweep)
    for ax in axes[len(sweeps) :]:
        ax.set_visible(False)
    quick = " (quick sizes)" if results.get("quick") else ""
    shaded = any(_cheaper(sweep).any() for sweep in sweeps.values())
    said = (
        f"shaded: the network cheaper by more than {CLOSE:.0%}"
        if shaded
        else f"nowhere cheaper by more than {CLOSE:.0%}"
    )
    fig.suptitle(
        f"Where prediction pays: {results['scenario']}, preset {results['preset']}{quick}\n{said}", fontsize=11
    )
    handles = {label: h for ax in axes for h, label in zip(*ax.get_legend_handles_labels())}  # one legend, below
    fig.legend(handles.values(), handles.keys(), loc="lower center", ncol=1, fontsize=9, frameon=False)
    fig.tight_layout(rect=(0, (0.2 * len(handles) + 0.2) / fig.get_figheight(), 1, 1))  # a line an entry
    text = f"Cost per configuration of the exact and the learned check, {results['scenario']}, preset "
    text += f"{results['preset']}{quick}, microseconds on log axes. "
    parts = [_in_a_table(sweep) for sweep in sweeps.values()]
    return describe(fig, text + " ".join(_in_words(sweep) for sweep in sweeps.values()), parts)


def _in_a_table(sweep: dict) -> Part:
    """One panel's curves as a table: each checker's cost at each value of the variable, and the network's cost
    over the default exact checker's (below 1: the network is cheaper)."""
    columns = (sweep["label"], *(f"{STYLES[name][2]}, µs" for name in STYLES), "learned / exact")
    rows = tuple(
        (f"{v:,.0f}", *(f"{sweep[f'{name}_us'][i]:.3g}" for name in STYLES), f"{learned / exact:.2f}")
        for i, (v, exact, learned) in enumerate(zip(sweep["values"], sweep["exact_us"], sweep["learned_us"]))
    )
    crossings = [f"the {STYLES[n][2]} one at {c['value']:,.3g}" for n, c in sweep["crossing"].items() if c is not None]
    said = _in_words(sweep) + (f" The network's curve crosses {', '.join(crossings)}." if crossings else "")
    return Part(sweep["label"], said, columns, rows)


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
    cheaper = _cheaper(sweep)  # (V,) beyond the band
    for name in ("exact", "fcl", "learned"):
        style, colour, label = STYLES[name]
        outline = halo(1.5) if name == "learned" else []  # orange alone is too light on white
        y = np.asarray(sweep[f"{name}_us"], float)  # (V,)
        ax.plot(x, y, style, color=colour, label=label, path_effects=outline, clip_on=False)  # edge markers whole
    bounds = _halfway(x)  # (V+1,)
    for n, i in enumerate(np.flatnonzero(cheaper)):  # a band round each value the verdict calls "network cheaper"
        legend = f"network cheaper by > {CLOSE:.0%}" if n == 0 else None
        span = bounds[i : i + 2]  # (2,) its band: the panel's whole height (a shaded area, not a mark)
        ax.fill_between(
            span, 0, 1, transform=ax.get_xaxis_transform(), color=COLORS["learned"], alpha=0.2, lw=0, label=legend
        )
    unit = sweep["label"].split()[0]  # what the variable counts: "243 obstacles", not a bare "243"
    for name, found in sweep["crossing"].items():
        if found is not None:
            ax.axvline(found["value"], ls=":", color=STYLES[name][1], label="the curves cross (dotted)")
            right = np.log(found["value"] / x[0]) > np.log(x[-1] / x[0]) / 2  # then its words go to the left
            ax.annotate(
                f"{found['value']:,.3g} {unit}",
                (found["value"], 0.97),
                xycoords=("data", "axes fraction"),
                xytext=(-3 if right else 3, 0),
                ha="right" if right else "left",
                va="top",
                textcoords="offset points",
                fontsize=8,
                path_effects=halo(0.0, ("free",)),  # readable over a curve, which it does not hide
            )
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xticks(x, _tick_labels(x))
    ax.minorticks_off()
    _plain_log_ticks(ax)
    ax.set_xlabel(sweep["label"])
    ax.set_ylabel("µs per configuration")
    ax.tick_params(labelsize=9)


def _plain_log_ticks(ax) -> None:
    """The y axis labelled in plain numbers at 1-2-5 steps (0.2, 0.5, 1, 2, ...) where it spans under three decades,
    at each decade otherwise: the decade where curves cross is never left without a number."""
    lo, hi = ax.get_ylim()
    steps = (1, 2, 5) if hi / lo < 10**2.5 else (1,)
    decades = range(int(np.floor(np.log10(lo))), int(np.ceil(np.log10(hi))) + 1)
    ticks = [m * 10.0**e for e in decades for m in steps if lo <= m * 10.0**e <= hi]
    ax.set_yticks(ticks, [f"{t:g}" for t in ticks])


def _cheaper(sweep: dict) -> np.ndarray:
    """``(V,)`` bool: where the verdict is "network cheaper" (beyond the band, against the default exact check)."""
    ratio = np.asarray(sweep["learned_us"], float) / np.asarray(sweep["exact_us"], float)  # (V,)
    return np.array([cost_verdict(float(r)) == CHEAPER for r in ratio])


def _halfway(x: np.ndarray) -> np.ndarray:
    """``(V+1,)`` the bounds of a band round each of the ``(V,)`` increasing values ``x`` on a log axis: halfway
    (geometrically) between neighbours, as far beyond the first and the last (a factor 1.5 for a lone value)."""
    if len(x) == 1:
        return np.array([x[0] / 1.5, x[0] * 1.5])
    middle = np.sqrt(x[1:] * x[:-1])  # (V-1,)
    return np.concatenate([[x[0] ** 2 / middle[0]], middle, [x[-1] ** 2 / middle[-1]]])


def _tick_labels(x: np.ndarray, panel_px: float = 200.0, char_px: float = 7.0) -> list[str]:
    """The measured values ``x (n,)`` as tick labels on a log axis about ``panel_px`` wide, a label left out where it
    would touch the one before it (9-pt digits about ``char_px`` wide); the last value is always named."""
    labels = [f"{v:,.0f}" for v in x]
    px = np.log10(x / x.min()) * panel_px / max(np.log10(x.max() / x.min()), 1e-9)  # (n,) each tick's place
    room = [char_px * len(label) / 2 + 2 for label in labels]  # (n,) half a label's width, and a gap
    shown = [0]
    for k in range(1, len(x)):
        if px[k] - px[shown[-1]] >= room[k] + room[shown[-1]]:
            shown.append(k)
        elif k == len(x) - 1:  # the last value is named: the one before it gives way
            shown[-1] = k
    return [label if k in shown else "" for k, label in enumerate(labels)]
