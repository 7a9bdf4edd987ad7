"""Where prediction pays: an exact check's cost per configuration against the network's (``toolkit bench --crossover``).

:func:`crossover` draws the sweeps of :func:`toolkit.experiments.crossover.crossover` (its
results dict, as ``crossover.json`` holds it): one panel per variable that makes an exact check
dear, microseconds per configuration on log-log axes, the gap between its curve and the compiled one shaded where
the network is the cheaper check by more than the band in which a timing moves (the verdict "network cheaper" of
:func:`toolkit.util.verdicts.cost_verdict`, the words the tables and the conclusion use: a point
they call "can't tell" is not shaded) and a dotted line wherever its curve crosses an exact one (twice, where the
two costs are close: each crossing is marked). On a 3DC scenario's panels a grey strip marks where the paper's own
scenes sit (:data:`PAPER_SCENES`: 110-125 blocks, chains of 2 and 4 links) and, on the call-size panel, the sizes
of our planners' calls (:data:`PLANNER_CALLS`).
Nothing here calls ``show()``.
"""

from __future__ import annotations

from textwrap import fill
from typing import Any

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.colors import to_rgba
from matplotlib.figure import Figure
from matplotlib.ticker import NullFormatter, NullLocator

from toolkit.plots.alt import Part, describe
from toolkit.plots.palette import COLORS, PAGE_WIDTH, halo
from toolkit.plots.tick_rows import name_ticks
from toolkit.util.verdicts import CHEAPER, CLOSE, NEAR, cost_verdict

STYLES = {  # checker -> (marker and line, colour, name)
    "exact": ("o-", COLORS["exact"], "exact, default (compiled)"),
    "fcl": ("s--", COLORS["fcl"], "exact, python-fcl"),
    "learned": ("^-", COLORS["learned"], "learned (the network)"),
}
LEGEND = {  # checker -> its legend's words; reader r24c: which checker the mesh panel times is said
    "exact": "exact, compiled (mesh: our compiled mesh checker)",
    "fcl": "exact, python-fcl (mesh: FCL's mesh tree, numpy inside test)",
    "learned": "the network the title names",  # r25a: not "untrained", which read as a fault; reader r41g,
    # crossover figure: "(its speed does not depend on its weights)" was clutter, the page's text says it; reader
    # r59g: "of the preset's sizes" beside a title naming a paper-size network read as two names for one network
}


def crossover(results: dict, measured: str | None = None) -> Figure:
    """One panel per swept variable: cost per configuration of the default exact checker, of python-fcl and of
    the learned checker against the variable; shaded where the network is cheaper than the default exact check
    by more than :data:`~toolkit.util.verdicts.CLOSE` (the verdict "network cheaper"), hatched where the two are
    within it ("can't tell"), a dotted vertical line at every value where the network's curve crosses an exact one
    (its value beside it), a grey strip where the paper's scenes sit (3DC only). ``measured`` (else
    ``results["measured"]``, if any), when the sweep was timed, goes in the text alternative; the page's caption says
    it (reader r28f: the date in the title competed with the panels' titles)."""
    sweeps = results["variables"]
    columns = min(len(sweeps), 2)
    rows = -(-len(sweeps) // columns)
    fig = Figure(figsize=(PAGE_WIDTH, 2.9 * rows + 0.7 + LEGEND_INCHES))  # as wide as the page: text as drawn
    axes = fig.subplots(rows, columns, squeeze=False).ravel()
    paper = results["scenario"].lower().startswith("3dc")  # the paper's 3DC scenes: where they sit, marked
    for ax, (key, sweep) in zip(axes, sweeps.items()):
        _panel(ax, sweep)
        ax.set_ylabel("µs per configuration")  # reader r40g: on every panel, the right-hand ones too
        if paper:
            _paper_scenes(ax, key, sweep)
            _planner_calls(ax, key, sweep)
        title = TITLES.get(key, key.capitalize())  # reader r25c: which panel is which, on top
        if paper and key == "triangles":  # reader r32g: the paper's scenes hold no mesh, said where the network wins
            title = f"Mesh{NO_MESH}"  # "Mesh triangles" and this overflow a half-width panel
        ax.set_title(title, fontsize=10)
    for ax in axes[len(sweeps) :]:
        ax.set_visible(False)
    quick = " (quick sizes)" if results.get("quick") else ""
    measured = measured or results.get("measured")
    when = f"Measured {measured}. " if measured else ""
    shaded = any(_cheaper(sweep).any() for sweep in sweeps.values())
    hatched = any(_close(sweep).any() for sweep in sweeps.values())
    said = f"shaded: network cheaper by > {CLOSE:.0%}{' (nowhere here)' if not shaded else ''}"
    said += f"; hatched: within {CLOSE:.0%}, can't tell" if hatched else ""  # reader r27f: no hatching named undrawn
    network = (  # reader r30f: the paper's sizes named in the title, not only in the caption
        "a paper-size network"
        if results["preset"] == "paper"
        else f'the network at the "{results["preset"]}" preset\'s sizes'
    )
    # the network's size said on the figure (reader r27f: "preset paper" alone was easy to miss)
    heading = fig.suptitle(
        f"Cost per check: {scenario_name(results['scenario'])}, {network}{quick}\n{said}", fontsize=11
    )
    room = _legend_above(fig, axes, sweeps, heading)
    fig.tight_layout(rect=room)
    for ax, (key, sweep) in zip(axes, sweeps.items()):
        name_ticks(ax, np.asarray(sweep["values"], dtype=float), TICKS.get(key), TICK_POINTS)
    fig.tight_layout(rect=room)  # again, for the tick labels' height
    text = f"Cost per configuration of the exact and the learned check, {results['scenario']}, preset "
    text += f"{results['preset']}{quick}, microseconds on log axes. {when}"
    text += PAPER_SAID if paper and set(PAPER_SCENES) & set(sweeps) else ""
    text += CALLS_SAID if paper and "batch" in sweeps else ""
    parts = [_in_a_table(sweep) for sweep in sweeps.values()]
    return describe(fig, text + " ".join(_in_words(sweep) for sweep in sweeps.values()), parts)


LEGEND_INCHES = 1.4  # the legend's room over the panels: three rows of two entries, three lines each at most
LEGEND_CHARACTERS = (40, 36, 32, 28)  # a legend entry's line, characters: the longest with two entries side by side
LEGEND_POINTS = 10  # reader r40g: the legend in larger type than the tick labels


def _legend_above(fig: Figure, axes, sweeps: dict, heading) -> tuple[float, float, float, float]:
    """One legend for all panels, above them under the title, in two columns (reader r40g: beside them, six long
    entries in small type squeezed the panels and their labels; reader r42g: below them, a reader of the top panels at
    the site's width saw them a screen before their key), its entries wrapped to the longest of
    :data:`LEGEND_CHARACTERS` that fits; the shading's entry names the panels it is drawn on where that is not all of
    them. Returns the rectangle, in figure fractions, left for the panels."""
    handles = {label: h for ax in axes for h, label in zip(*ax.get_legend_handles_labels())}
    only = [PANEL_NAMES.get(k, k) for k, sweep in sweeps.items() if _cheaper(sweep).any()]
    if SHADED in handles and len(only) < len(sweeps):
        handles[f"{SHADED} ({' and '.join(only)} panel{'s' if len(only) > 1 else ''} only)"] = handles.pop(SHADED)
    renderer = FigureCanvasAgg(fig).get_renderer()
    under = heading.get_window_extent(renderer).y0 / fig.bbox.height - 0.005  # just under the title's bottom edge
    for characters in LEGEND_CHARACTERS:  # the widest lines that keep both columns inside the figure
        legend = fig.legend(
            handles.values(), [fill(label, characters) for label in handles], loc="upper center",
            bbox_to_anchor=(0.5, under), ncol=2, fontsize=LEGEND_POINTS, frameon=False, labelspacing=0.6,
            handlelength=1.6, handletextpad=0.5, columnspacing=1.0, borderaxespad=0.1,
        )  # fmt: skip
        if legend.get_window_extent(renderer).width <= fig.bbox.width or characters == LEGEND_CHARACTERS[-1]:
            break
        legend.remove()
    bottom = legend.get_window_extent(renderer).y0  # the legend's bottom edge, pixels
    heading.set_in_layout(False)  # the rectangle below the legend keeps the panels under the title already
    return (0, 0, 1, bottom / fig.bbox.height)  # the panels below it


PAPER_SCENES = {"obstacles": ((110, 125),), "links": ((2, 2), (4, 4))}  # the paper's 3DC: 110-125 blocks; 2, 4 links
PAPER_LEGEND = "plain grey strip: the paper's 3DC scenes (110–125 blocks; 2 and 4 links)"
PAPER_SAID = (
    "Plain grey strips mark the paper's 3DC scenes: 110 to 125 blocks, chains of 2 and 4 links; they hold no mesh. "
)
NO_MESH = " (paper scenes: no mesh)"
TICKS: dict[str, tuple[float, ...]] = {  # a panel's values to name, if not all (reader r30f: the others get no tick);
    "obstacles": (10, 100, 500),  # reader r39g: one row of labels, where all seven took two rows
    "triangles": (20, 320, 5120),
}
PLANNER_CALLS = (50, 400)  # the calls a network answers on a 3DC scene: a round's samples (the lazy PRM's 50 doubling
# to |S| = plan_samples = 400, Algorithm 1's 400); reader r34g: not RRT-Connect's 8-56, which no network drives
CALLS_NAME = "a round's samples"  # one name on the panel and in the legend (reader r34g, figure c)
CALLS_LEGEND = f"dotted strip: {CALLS_NAME} in 3DC, the calls a network answers (50–400)"
CALLS_SAID = (
    f"On the call-size panel a dotted strip marks {CALLS_NAME} in 3DC, the calls a network answers: 50 to 400 "
    "configurations. "
)


def _paper_scenes(ax, key: str, sweep: dict) -> None:
    """A grey strip over each range of ``key`` where the paper's 3DC scenes sit (:data:`PAPER_SCENES`), a lone value
    widened by 5 % each way on the log axis; none outside the values swept."""
    x = np.asarray(sweep["values"], dtype=float)
    for n, (low, high) in enumerate(r for r in PAPER_SCENES.get(key, ()) if x[0] <= r[0] and r[1] <= x[-1]):
        label = PAPER_LEGEND if n == 0 else None  # a light grey, under the curves
        ax.axvspan(low / 1.05, high * 1.05, color=COLORS["block"], alpha=0.3, zorder=0.5, lw=0, label=label)
        if low <= x[0]:  # reader r41g: a strip at the first value (2 links) was half cut by the axis; room for it
            ax.margins(x=0.1)


CALLS_TOP = 0.86  # the planner calls' strip's top, in the panel's height: its name above it
CALLS_LOOK: dict[str, Any] = dict(facecolor=to_rgba(COLORS["block"], 0.12), edgecolor=COLORS["block"], hatch="..", lw=0,
                                  zorder=0.5)  # fmt: skip


def _planner_calls(ax, key: str, sweep: dict) -> None:
    """On the call-size panel (``batch``), a dotted strip over :data:`PLANNER_CALLS` and its name at the panel's top,
    above the strip (reader r30f: the text said "tens to a few hundred", the figure did not show it; reader r32g: the
    name sat on the dots), which stops at :data:`CALLS_TOP` of the panel's height."""
    x = np.asarray(sweep["values"], dtype=float)
    low, high = PLANNER_CALLS
    if key != "batch" or not (x[0] <= low and high <= x[-1]):
        return
    ax.axvspan(
        low, high, ymax=CALLS_TOP, label=CALLS_LEGEND, **CALLS_LOOK
    )  # dotted: apart from the paper's plain strips (r31f)
    ax.text(
        np.sqrt(low * high),
        0.97,
        CALLS_NAME,
        transform=ax.get_xaxis_transform(),
        ha="center",
        va="top",
        fontsize=TICK_POINTS,
        path_effects=halo(0.0, ("free",)),
    )


PANEL_NAMES = {"obstacles": "obstacles", "triangles": "mesh", "links": "links", "batch": "call-size"}  # in the legend
TITLES = {  # a swept variable's key -> its panel's title (reader r25c: only the x-labels told the panels apart)
    "obstacles": "Obstacles",
    "triangles": "Mesh triangles",
    "links": "Chain links",
    "batch": "Call size",
}
SHADED = f"shaded: network cheaper by > {CLOSE:.0%}"  # the legend's words for a shaded band
HATCHED = f"hatched: within {CLOSE:.0%} of the exact check, can't tell"  # and for a band where the two are too close
HATCH: dict[str, Any] = dict(facecolor="none", edgecolor=COLORS["exact"], hatch="//", alpha=0.35, lw=0)  # its look


def scenario_name(key: str) -> str:
    """The site's name of a scenario from its key: ``3dc7`` -> ``3DC-7``, ``2ds`` -> ``2DS``; any other key as it is
    given, upper case."""
    name = key.upper()
    return f"3DC-{name[3:]}" if name.startswith("3DC") and name[3:].isdigit() else name


def _in_a_table(sweep: dict) -> Part:
    """One panel's curves as a table: each checker's cost at each value of the variable, and the network's cost
    over the default exact checker's (below 1: the network is cheaper)."""
    columns = (sweep["label"], *(f"{STYLES[name][2]}, µs" for name in STYLES), "learned / exact")
    rows = tuple(
        (f"{v:,.0f}", *(f"{sweep[f'{name}_us'][i]:.3g}" for name in STYLES), f"{learned / exact:.2f}")
        for i, (v, exact, learned) in enumerate(zip(sweep["values"], sweep["exact_us"], sweep["learned_us"]))
    )
    crossings = [
        f"the {STYLES[n][2]} one at {' and at '.join(_number(v) for v in found)}"
        for n in ("exact", "fcl")
        if (found := _crossings(sweep, n))
    ]
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
    """One variable: the three curves, the values where the network is cheaper (its verdict) shaded, every crossing
    of the network's curve with an exact one."""
    x = np.asarray(sweep["values"], dtype=float)
    cheaper = _cheaper(sweep)  # (V,) beyond the band
    for name in ("exact", "fcl", "learned"):
        style, colour, _ = STYLES[name]
        y = np.asarray(sweep[f"{name}_us"], float)  # (V,)
        ax.plot(x, y, style, color=colour, label=LEGEND[name], clip_on=False, **MARKS[name])  # edge markers whole
    bounds = _halfway(x)  # (V+1,)
    for n, i in enumerate(np.flatnonzero(cheaper)):  # a band round each value the verdict calls "network cheaper"
        band = _gap(ax, sweep, bounds[i : i + 2], SHADED if n == 0 else None)
        band.set_gid(CHEAPER)
    for n, i in enumerate(np.flatnonzero(_close(sweep))):  # reader r24c: and each value it calls "can't tell"
        band = ax.fill_between(
            bounds[i : i + 2], 0, 1, transform=ax.get_xaxis_transform(), label=HATCHED if n == 0 else None, **HATCH
        )
        band.set_gid(NEAR)
    unit = sweep["label"].split()[0]  # what the variable counts: "243 obstacles", not a bare "243"
    found = sorted((value, name) for name in ("exact", "fcl") for value in _crossings(sweep, name))
    for k, (value, name) in enumerate(found):  # each one's words a line higher than the last's: never on each other
        ax.axvline(value, ls=":", color=STYLES[name][1], label="the curves cross (dotted)")
        right = np.log(value / x[0]) > np.log(x[-1] / x[0]) / 2  # then its words go to the left
        ax.annotate(  # a count in whole units, clear of its dotted line (reader r23a: "62.6 triangles" on the line)
            f"about {value:,.0f} {unit}",
            (value, 0.03 + 0.11 * k),  # at the panel's foot, under the curves (review r25a: on them at the top)
            xycoords=("data", "axes fraction"),
            xytext=(-6 if right else 6, 0),
            ha="right" if right else "left",
            va="bottom",
            textcoords="offset points",
            fontsize=TICK_POINTS + 1,
            path_effects=halo(0.0, ("free",)),  # readable over a curve, which it does not hide
        )
    ax.set_xscale("log")
    ax.set_yscale("log")
    _room_for_marks(ax, sweep)
    ax.set_xticks(x, [f"{v:,.0f}" for v in x])  # named once laid out, where they keep apart (name_ticks)
    ax.yaxis.set_minor_locator(NullLocator())
    _plain_log_ticks(ax)
    ax.set_xlabel(sweep["label"])  # the legend apart: a half-width panel holds its label in one line
    ax.tick_params(labelsize=TICK_POINTS)


def _gap(ax, sweep: dict, span: np.ndarray, label: str | None):
    """The area between the default exact curve and the network's across ``span (2,)``, cut to the values measured
    (reader r36g: a band of the panel's whole height read as the panel's background, not as the network's saving);
    a lone value's band is the panel's height."""
    x = np.asarray(sweep["values"], dtype=float)  # (V,)
    look = dict(color=COLORS["learned"], alpha=0.3, lw=0, label=label, zorder=0.6)
    if len(x) == 1:
        return ax.fill_between(span, 0, 1, transform=ax.get_xaxis_transform(), **look)
    grid = np.geomspace(max(span[0], x[0]), min(span[1], x[-1]), 24)  # (24,) along the log axis

    def curve(name: str) -> np.ndarray:  # (24,) the checker's cost, log-log between its measured values
        return np.exp(np.interp(np.log(grid), np.log(x), np.log(np.asarray(sweep[f"{name}_us"], float))))

    return ax.fill_between(grid, curve("learned"), curve("exact"), **look)


TICK_POINTS = 9
MARKS: dict[str, dict] = {  # where two curves meet, the network's triangle beneath, the exact circle and python-fcl's
    "exact": dict(markersize=6, zorder=3.5),  # square above it, each ringed in white (review r19a: at a batch of one
    "fcl": dict(markersize=7, zorder=3, markeredgecolor=COLORS["free"]),  # the triangle nearly covered the square;
    "learned": dict(markersize=6, zorder=2.5, alpha=0.8, path_effects=halo(1)),  # r23a/c: it hid the exact curve;
    # r33g: at 8 points it hid where the network's own values lie
}


def _room_for_marks(ax, sweep: dict) -> None:
    """The y axis from a tenth of the curves' span in decades, and a tenth of a decade more, below the lowest value
    to as far above the highest: a mark at either end lies whole inside the frame (reader r27f: the 20-triangle
    network point sat half on the lower frame)."""
    y = np.asarray([v for name in STYLES for v in sweep[f"{name}_us"] if v is not None], float)  # every cost, µs
    low, high = np.log10(y.min()), np.log10(y.max())
    pad = 0.1 * (high - low) + 0.1  # decades
    ax.set_ylim(10 ** (low - pad), 10 ** (high + pad))


def _number(value: float) -> str:
    """``value`` to three significant digits in plain numbers: 7.92, 243, 1,550 (never 1.55e+03)."""
    rounded = float(f"{value:.3g}")
    return f"{rounded:,.0f}" if rounded >= 100 else f"{rounded:g}"


def _crossings(sweep: dict, name: str) -> list[float]:
    """Every value where the network's curve crosses checker ``name``'s, interpolated log-log between the measured
    values around each change of sign of ``log(exact / learned)`` (a curve may cross twice); none where ``name``
    was not timed."""
    if any(e is None for e in sweep[f"{name}_us"]):
        return []
    x = np.log(np.asarray(sweep["values"], float))  # (V,)
    gap = np.log(np.asarray(sweep[f"{name}_us"], float) / np.asarray(sweep["learned_us"], float))  # (V,) > 0: cheaper
    i = np.flatnonzero(gap[:-1] * gap[1:] < 0)  # the segments whose ends lie on either side
    t = gap[i] / (gap[i] - gap[i + 1])  # where along each the gap is 0
    met = x[1:-1][gap[1:-1] == 0]  # a measured value inside the sweep where the two costs are equal
    return sorted(float(v) for v in np.exp(np.concatenate([x[i] + t * (x[i + 1] - x[i]), met])))


def _plain_log_ticks(ax) -> None:
    """The y axis labelled in plain numbers at 1-2-5 steps (0.2, 0.5, 1, 2, ...) where it spans under three decades,
    at each decade otherwise, and at 1-2-5 steps below 1 µs where it spans under :data:`WIDE` decades: the decade
    where curves cross is never left without a number, nor the network's and the compiled check's few tenths of a µs
    (reader r24c). On a wider axis (the mesh's and the call size's, four decades or more) the labels below 1 crowd
    (reader r33g: 1 / 0.5 / 0.2 and 0.2 / 0.1 / 0.05): there only decades are named, 2 and 5 short unnamed ticks."""
    lo, hi = ax.get_ylim()
    wide = hi / lo >= 10**WIDE
    steps = (1, 2, 5) if hi / lo < 10**2.5 else (1,)
    below = (1,) if wide else (1, 2, 5)
    decades = range(int(np.floor(np.log10(lo))), int(np.ceil(np.log10(hi))) + 1)
    ticks = [m * 10.0**e for e in decades for m in (steps if e >= 0 else below) if lo <= m * 10.0**e <= hi]
    ax.set_yticks(ticks, [f"{t:g}" for t in ticks])
    if wide:
        minor = [m * 10.0**e for e in decades for m in (2, 5) if lo <= m * 10.0**e <= hi]
        ax.set_yticks(minor, minor=True)
        ax.yaxis.set_minor_formatter(NullFormatter())


WIDE = 3.5  # decades: an axis this wide or wider names only its decades (the obstacles' and links' panels span fewer)


def _cheaper(sweep: dict) -> np.ndarray:
    """``(V,)`` bool: where the verdict is "network cheaper" (beyond the band, against the default exact check)."""
    ratio = np.asarray(sweep["learned_us"], float) / np.asarray(sweep["exact_us"], float)  # (V,)
    return np.array([cost_verdict(float(r)) == CHEAPER for r in ratio])


def _close(sweep: dict) -> np.ndarray:
    """``(V,)`` bool: where the verdict is "can't tell" (within the band of the default exact check's cost)."""
    ratio = np.asarray(sweep["learned_us"], float) / np.asarray(sweep["exact_us"], float)  # (V,)
    return np.array([cost_verdict(float(r)) == NEAR for r in ratio])


def _halfway(x: np.ndarray) -> np.ndarray:
    """``(V+1,)`` the bounds of a band round each of the ``(V,)`` increasing values ``x`` on a log axis: halfway
    (geometrically) between neighbours, as far beyond the first and the last (a factor 1.5 for a lone value)."""
    if len(x) == 1:
        return np.array([x[0] / 1.5, x[0] * 1.5])
    middle = np.sqrt(x[1:] * x[:-1])  # (V-1,)
    return np.concatenate([[x[0] ** 2 / middle[0]], middle, [x[-1] ** 2 / middle[-1]]])
