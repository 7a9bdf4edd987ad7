"""Tick labels that keep apart: the measured values of a log axis named under their ticks, level in one row where they
fit, in two level rows where one would crowd, slanted where two would, a short unnamed tick for what still crowds
(:func:`name_ticks`; the crossover figure's, :mod:`toolkit.plots.crossover`). Nothing here calls ``show()``.
"""

from __future__ import annotations

import numpy as np
from matplotlib.ticker import NullFormatter


def tick_labels(x: np.ndarray, px: np.ndarray, char_px: float) -> list[str]:
    """The measured values ``x (n,)`` as tick labels at ``px (n,)`` pixels along the axis, a label left out where
    less than one and a half digits' width (``char_px`` each) would part it from the one before it; the last value
    is always named. Where the plain numbers (``1,000``) would leave one out, thousands are written short
    (``1k``, ``10k``: reader r12a found no 1,000 on the batch panel), and only what still crowds is left out."""
    for labels in ([f"{v:,.0f}" for v in x], [_short(v) for v in x]):
        kept = _kept_apart(labels, px, [char_px * (len(label) / 2 + 0.75) for label in labels])
        if all(kept):
            break
    return kept


def _short(value: float) -> str:
    """A tick's value in few characters: ``1k`` for 1,000, ``10k`` for 10,000; below 1,000 (or not whole thousands)
    the plain number."""
    return f"{value / 1000:g}k" if value >= 1000 and value % 1000 == 0 else f"{value:,.0f}"


def _kept_apart(labels: list[str], px: np.ndarray, room: list[float]) -> list[str]:
    """``labels`` with those left out (``""``) that would come closer to the one before than their ``room`` (n,)
    pixels each allows (half a label's width, and half the gap wanted between two)."""
    shown = [0]
    for k in range(1, len(labels)):
        if px[k] - px[shown[-1]] >= room[k] + room[shown[-1]]:
            shown.append(k)
        elif k == len(labels) - 1:  # the last value is named: the one before it gives way
            shown[-1] = k
    return [label if k in shown else "" for k, label in enumerate(labels)]


def _two_rows(labels: list[str], px: np.ndarray, char_px: float) -> list[str] | None:
    """``labels`` level in two rows: each on the first row if it keeps apart from the last label there, else on the
    second (written a line lower, ``"\\n350"``) if it keeps apart from the last label there; None where some label
    would crowd on either row."""
    room = [char_px * (len(label) / 2 + 0.75) for label in labels]  # half a label and half the gap wanted, pixels
    last = [-1, -1]  # the last label on each row; -1: none yet
    placed = []
    for k, label in enumerate(labels):
        free = [r for r in (0, 1) if last[r] < 0 or px[k] - px[last[r]] >= room[k] + room[last[r]]]
        if not free:
            return None
        last[free[0]] = k
        placed.append("\n" * free[0] + label)
    return placed


def name_ticks(ax, measured: np.ndarray, chosen: tuple[float, ...] | None, points: float) -> None:
    """Name the measured values ``measured (n,)`` of a laid-out panel under their ticks, or of them only those in
    ``chosen`` (reader r29f: the obstacles' 350 touched 500; reader r30f: the others get no tick): level where the
    labels keep apart as drawn, in two level rows where one would crowd (reader r36g: slanted, 350 and 500 read as
    one), slanted where two rows would crowd (reader r20d: 1,280 triangles had no number), and only what still
    crowds slanted gets a short, unnamed tick."""
    picked = measured[np.isin(measured, chosen)] if chosen else measured
    x = picked if len(picked) >= 2 else measured  # (m,) the values to name
    px = ax.transData.transform(np.column_stack([x, np.ones_like(x)]))[:, 0]  # (m,) where each tick lies, pixels
    char_px = points * ax.figure.dpi / 72 * 0.64  # a digit's width at the tick labels' size, ``points``
    labels = tick_labels(x, px, char_px)
    if not all(labels):  # reader r36g: slanted, 350 and 500 still read as one; two level rows before a slant
        labels = _two_rows([f"{v:,.0f}" for v in x], px, char_px) or labels
    slanted = not all(labels)
    if slanted:  # steep, neighbours part by a line's height, not a label's width
        labels = _kept_apart([f"{v:,.0f}" for v in x], px, [0.6 * char_px / 0.64] * len(x))
    named = x[[bool(t) for t in labels]]
    ax.set_xticks(named, [t for t in labels if t])  # the values named
    ax.set_xticks(x[~np.isin(x, named)], minor=True)  # crowded out of a name: a short tick; not chosen: none (r30f)
    ax.xaxis.set_minor_formatter(NullFormatter())
    if slanted:
        ax.tick_params(axis="x", labelrotation=SLANT)
        for label in ax.get_xticklabels():
            label.set_horizontalalignment("right")
            label.set_rotation_mode("anchor")  # the label's end at its tick, whatever the angle


SLANT = 75  # degrees: two labels a line's height apart along the axis lie a line's height apart across their slant
# times sin 75° (reader r27f: at 45° the obstacles' 350 and 500 nearly touched; reader r33g: at 60° almost)
