"""Verdicts read from ratios against a tie band: "saves", "costs", "a tie" or "can't tell" for planning time, "network
cheaper", "network dearer" or "close: can't tell" for a check's cost per configuration.

A verdict is read from an *interval* of ratios (with / without, or network / exact), not from one number, so that a
busy machine cannot turn "saves" into "costs": where the interval crosses the tie band the verdict is "can't tell".
The chapters' tables (:mod:`toolkit.teaching.findings`) and the crossover's conclusion
(:mod:`toolkit.experiments.crossover`) say them in the same words.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

TIE = 0.10  # planning: a time change of 10 % or more counts; a ratio less than 10 % from 1 is a tie (queries timed
# in turns moved that much run to run)
CLOSE = 0.25  # a checker's cost per configuration, timed in a few rounds: within 25 % of the other's, too close to call
DIGITS = 2  # tables print a ratio to two decimals; a verdict reads it as printed: 0.904 is 0.90, a saving of 10 %

SAVES, COSTS, TIES, UNSURE = "saves time", "costs time", "a tie", "can't tell"  # planning time, with / without
CHEAPER, DEARER, NEAR = "network cheaper", "network dearer", "close: can't tell"  # a check's cost, network / exact
POSITIVE, NEGATIVE = (SAVES, CHEAPER), (COSTS, DEARER)  # a verdict never flips between these two from run to run


def judge(low: float, high: float, tie: float = TIE, edge_counts: bool = False) -> str:
    """``"below"`` when the interval ``[low, high]`` of ratios (with / without, or network / exact) lies below
    ``1 - tie``, ``"above"`` when it lies above ``1 + tie``, ``"inside"`` when inside the band, else ``"across"``.
    The ends are read as the tables print them (:data:`DIGITS` decimals). A ratio on the band's edge belongs to the
    band, unless ``edge_counts``: then a change of ``tie`` or more counts, and only one strictly inside is in it."""
    if not all(np.isfinite(v) and v > 0 for v in (low, high)) or low > high:
        raise ValueError(f"an interval of ratios must be positive numbers, low <= high, got {low!r}, {high!r}")
    low, high = round(low, DIGITS), round(high, DIGITS)
    lower, upper = round(1 - tie, DIGITS), round(1 + tie, DIGITS)  # the band's edges as printed (1 + 0.1 is 1.1000...1)
    if high < lower or (edge_counts and high == lower):
        return "below"
    if low > upper or (edge_counts and low == upper):
        return "above"
    inner = lower < low and high < upper if edge_counts else lower <= low and high <= upper
    return "inside" if inner else "across"


def time_verdict(low: float, high: float | None = None, tie: float = TIE) -> str:
    """:data:`SAVES`, :data:`COSTS`, :data:`TIES` or :data:`UNSURE` for time ratios with / without prediction (one
    ratio, or an interval). The one rule for a time saved, tied or lost, wherever a page counts them: read as printed,
    a change of 10 % or more counts, so 0.90 or below saves time, 1.10 or above costs time, and a ratio strictly
    between is a tie (the paper's 3DO Gaussian sampler, 0.90: a saving of 10 %, no tie)."""
    return {"below": SAVES, "above": COSTS, "inside": TIES, "across": UNSURE}[
        judge(low, low if high is None else high, tie, edge_counts=True)
    ]


def cost_verdict(ratio: float, tie: float = CLOSE) -> str:
    """:data:`CHEAPER`, :data:`DEARER` or :data:`NEAR` for a cost per configuration, network / exact."""
    return {"below": CHEAPER, "above": DEARER}.get(judge(ratio, ratio, tie), NEAR)


def per_query_ratios(row: Mapping[str, Mapping]) -> np.ndarray:
    """``(queries,)`` total time with / without prediction of each query, from a ``compare_prediction`` row
    ``{"without": summary, "with": summary}`` (the two modes solved each query in turn): the ratios a planning
    verdict is read from, and the chapters' figures print their median."""
    without = np.asarray(row["without"]["total_s_per_query"], dtype=float)  # (queries,)
    with_ = np.asarray(row["with"]["total_s_per_query"], dtype=float)  # (queries,)
    return with_ / np.maximum(without, 1e-12)
