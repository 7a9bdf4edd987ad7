"""The sentences a chapter prints from what it has just computed, so that its prose cannot contradict its figures.

A sentence that states a measured number or a comparison ("saves time", "above 1") is generated here from the
measurements and printed under the figure (``NOTEBOOKS.md``); the chapters' prose then says only what holds at
quick and full size and from run to run. One statistic throughout: medians over the queries, their spread as
quartiles; a single slow query that moves a mean is named.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np

TIE = 0.05  # a ratio of medians within 5 % of 1 is a tie: a shared machine moves timings that much from run to run
OUTLIER = 5.0  # a query at least this many times the other queries' median total is an outlier
MOVED = 1.5  # ... and it moves the mean when the mean is this many times the other queries' median
SCORES = ("acc", "tpr", "tnr")  # a classifier's scores, as toolkit.learning.metrics names them (paper, Table 2)
SCORE_NAMES = {"acc": "accuracy", "tpr": "TPR", "tnr": "TNR"}


def verdict(ratio: float, tie: float = TIE) -> str:
    """``"saves"`` below ``1 - tie`` (a time with / without prediction), ``"costs"`` above ``1 + tie``, else a tie."""
    if not np.isfinite(ratio) or ratio <= 0:
        raise ValueError(f"a time ratio must be a positive number, got {ratio!r}")
    return "saves" if ratio < 1 - tie else "costs" if ratio > 1 + tie else "ties"


def median_ratios(table: Mapping[str, Mapping], kind: str = "total") -> dict[str, float]:
    """Per sampler, ``kind`` time (``"total"`` or ``"sampling"``) with / without prediction, of the medians over
    the queries, from a ``{sampler: {"without": summary, "with": summary}}`` table (``compare_prediction``)."""
    key = f"{kind}_s_median"
    return {s: row["with"][key] / max(row["without"][key], 1e-12) for s, row in table.items()}


def describe_ratios(name: str, ratios: Mapping[str, float], against: str, *, kind: str = "total") -> str:
    """One sentence: for which samplers prediction saves, costs or ties ``kind`` time (ratios with / without)."""
    groups: dict[str, list[str]] = {"saves": [], "costs": [], "ties": []}
    for sampler, ratio in ratios.items():
        groups[verdict(ratio)].append(f"{sampler} ({ratio:.2f})")
    words = {"saves": "saves time with", "costs": "costs time with", "ties": "ties (within 5 %) with"}
    everyone = len(ratios) > 1 and any(len(found) == len(ratios) for found in groups.values())
    parts = [
        f"{words[v]} {'every sampler: ' if everyone else ''}{_joined(found)}" for v, found in groups.items() if found
    ]
    return f"{name}, {kind} time with / without prediction against {against}: prediction {'; '.join(parts)}."


def describe_medians(name: str, table: Mapping[str, Mapping], against: str, *, kind: str = "total") -> str:
    """:func:`describe_ratios` of a ``compare_prediction`` table's medians, with how many queries they are over."""
    n = next(iter(table.values()))["without"]["n_queries"]
    over = f"medians over {n} {'query' if n == 1 else 'queries'}"
    return describe_ratios(f"{name} ({over})", median_ratios(table, kind), against, kind=kind)


def outliers(name: str, table: Mapping[str, Mapping], factor: float = OUTLIER) -> list[str]:
    """A sentence for every sampler and mode whose slowest query took at least ``factor`` times the other queries'
    median total and pulls the mean to ``MOVED`` times that median or more: which query, how long, and where it
    moves the mean (and the median, with two queries)."""
    lines = []
    for sampler, row in table.items():
        for mode in ("without", "with"):
            summary = row[mode]
            totals = np.asarray(summary["total_s_per_query"], dtype=float)  # (queries,)
            if len(totals) < 2:
                continue
            slowest = int(np.argmax(totals))
            rest = float(np.median(np.delete(totals, slowest)))
            if totals[slowest] < factor * max(rest, 1e-12) or summary["total_s"] < MOVED * rest:
                continue  # not an outlier, or one that leaves the mean where the other queries put it
            line = (
                f"{name}, {sampler} {mode} prediction: query {slowest} took {totals[slowest]:.3g} s, "
                f"{totals[slowest] / max(rest, 1e-12):.0f}x the other queries' median ({rest:.3g} s); "
                f"it pulls the mean up to {summary['total_s']:.3g} s"
            )
            if len(totals) == 2:
                line += f", and with only two queries the median too ({summary['total_s_median']:.3g} s)"
            else:
                line += f" (the median: {summary['total_s_median']:.3g} s)"
            lines.append(line + ".")
    return lines


def describe_lesson(verdicts: Mapping[str, str], crossover_conclusion: Sequence[str]) -> str:
    """Markdown: the chapter's conclusion, ``verdicts`` (a :func:`describe_medians` sentence per scenario) then what
    the crossover study (``toolkit.experiments.crossover.conclusion``) says about where prediction would pay."""
    lines = ["**What was measured.**", ""]
    lines += [f"- {sentence}" for sentence in verdicts.values()]
    lines += ["", "**Where the crossover study says prediction would pay** (`crossover.conclusion`):", ""]
    lines += [f"- {line}" for line in crossover_conclusion]
    return "\n".join(lines)


def _joined(items: Sequence[str]) -> str:
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def describe_throughput(name: str, measured: Mapping[str, float], batch: int) -> str:
    """One sentence from a ``toolkit.experiments.bench.throughput`` result: how many times as many configurations
    a second the learned checker answered as the default exact checker and as python-fcl, and who led."""
    words = {"saves": "it leads", "costs": "it trails", "ties": "a tie, within 5 %"}
    exact, fcl = measured["ratio"], measured["learned_cfg_per_s"] / measured["fcl_cfg_per_s"]  # above 1: it leads
    return (
        f"{name}, calls of {batch:,} configurations on one thread: the learned checker answered {exact:.2f}x as many "
        f"configurations a second as the default exact checker ({words[verdict(1 / exact)]}) and {fcl:.2f}x as "
        f"many as python-fcl ({words[verdict(1 / fcl)]})."
    )


def compare_scores(ours: Mapping[str, float], reference: Mapping[str, float], keys: Sequence[str] = SCORES) -> str:
    """``"accuracy 77% against 71% (higher), TPR ..."``: classifier scores (fractions) next to a reference's, each
    said higher, lower or equal at the printed precision."""
    parts = []
    for key in keys:
        mine, theirs = round(100 * ours[key]), round(100 * reference[key])
        word = "higher" if mine > theirs else "lower" if mine < theirs else "equal"
        parts.append(f"{SCORE_NAMES[key]} {mine}% against {theirs}% ({word})")
    return ", ".join(parts)


def describe_accuracy(label: str, accuracy: float, always_valid: float) -> str:
    """``label``'s accuracy next to answering "valid" to everything on the same samples and next to a coin flip
    (50 %, whatever the share of valid samples): above, below or equal at the printed precision."""

    def side(other: float) -> str:
        mine, theirs = round(100 * accuracy), round(100 * other)
        return "above" if mine > theirs else "below" if mine < theirs else "level with"

    flip = " (worse than chance)" if side(0.5) == "below" else ""
    return (
        f'{label}: accuracy {accuracy:.0%}, {side(always_valid)} "always valid" ({always_valid:.0%}) and '
        f"{side(0.5)} a coin flip (50%){flip}"
    )


def describe_threshold_sweep(probability: np.ndarray, valid: np.ndarray) -> str:
    """What a sweep of the decision threshold over ``probability (N,)`` against the truth ``valid (N,)`` shows: up to
    which threshold the model calls everything valid ("always valid"), the thresholds over which the middle 80 % of
    its P(valid) lie (narrow: an abrupt switch), and its best accuracy over all thresholds."""
    p, truth = np.asarray(probability, dtype=float), np.asarray(valid, dtype=bool)
    if p.shape != truth.shape or p.ndim != 1 or len(p) == 0:
        raise ValueError(f"probability {p.shape} and valid {truth.shape} must be equal, non-empty (N,) arrays")
    cuts = np.unique(np.concatenate([p, [np.inf]]))  # every distinct decision, from "all valid" to "none valid"
    accuracy = np.array([np.mean((p >= t) == truth) for t in cuts])  # (thresholds,)
    best = int(np.argmax(accuracy))
    low, high = np.percentile(p, (10, 90))
    best_at = "above every P(valid): it calls nothing valid" if np.isinf(cuts[best]) else f"at {cuts[best]:.2f}"
    return (
        f'up to a threshold of {p.min():.2f} the model calls every sample valid (TPR 1, TNR 0: "always valid", '
        f"{truth.mean():.0%} accuracy); the middle 80 % of its P(valid) lie between {low:.2f} and {high:.2f}, so "
        f"that is where its answers switch; its best accuracy over all thresholds is {accuracy[best]:.0%}, "
        f"{best_at}"
    )
