"""What a chapter prints from what it has just measured: small Markdown tables, a verdict word in each row.

The chapters' prose states the verdict a student can repeat; the numbers behind it are computed here and shown as
tables (``NOTEBOOKS.md``). A planning verdict is the median's of the per-query ratios, marked :data:`NO_CLEAR` inside
the noise band, :data:`ACROSS` for the other cautions; a checker's cost is read with a band of :data:`CLOSE`
(:mod:`toolkit.util.verdicts`). A slow query that moves a mean is listed."""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping

import numpy as np

from toolkit.experiments.paper_numbers import IMPROVEMENT, table3_against_text
from toolkit.learning import metrics
from toolkit.util.verdicts import (  # noqa: F401 (the words and bands; chapters and tests read them here too)
    CHEAPER,
    CLOSE,
    COSTS,
    DEARER,
    NEAR,
    NEGATIVE,
    POSITIVE,
    SAVES,
    TIE,
    TIES,
    UNSURE,
    cost_verdict,
    judge,
    per_query_ratios,
    time_verdict,
)

OUTLIER = 5.0  # a query at least this many times the other queries' median total is an outlier
MOVED = 1.5  # ... and it moves the mean when the mean is this many times the other queries' median
SCORES = ("acc", "tpr", "tnr")  # a classifier's scores, as toolkit.learning.metrics names them (paper, Table 2)
SCORE_NAMES = {"acc": "accuracy", "tpr": "TPR", "tnr": "TNR"}
CHANCE_BAND = 0.05  # a balanced accuracy this close to 50 % is "about a coin flip" (describe_accuracy)


def noise_band() -> tuple[float, float]:
    """The noise band of the median of each query's own ratio (:func:`toolkit.teaching.costs.floors`)."""
    from toolkit.teaching import costs  # here: costs reads the record, which only a planning verdict needs

    return costs.floors()["own"]


def planning_verdict(
    row: Mapping[str, Mapping], tie: float = TIE, band: tuple[float, float] | None = None
) -> tuple[float, float, float, str]:
    """The per-query ratios' median and quartiles, and the median's verdict: :data:`UNSURE` where that saving or cost
    lies inside the noise band (``band``, else :func:`noise_band`), where the middle half includes a tie band edge
    (a few live queries: a busy machine must not flip a verdict), or with fewer than two queries."""
    ratios = per_query_ratios(row)
    q1, median, q3 = (float(v) for v in np.percentile(ratios, (25, 50, 75)))
    low, high = noise_band() if band is None else band
    said, across = time_verdict(median, tie=tie), len(ratios) < 2 or time_verdict(q1, q3, tie) == UNSURE
    return median, q1, q3, UNSURE if across or (said != TIES and low < median < high) else said


def planning_table(
    tables: Mapping[str, Mapping[str, Mapping]],
    tie: float = TIE,
    planner: str = "",
) -> str:
    """Markdown: per scenario and sampler of ``{scenario: compare_prediction table}``, the verdict (first: reader
    r18a) with the per-query ratios' median and middle half, marked by :func:`_mark`, then the median totals without
    and with prediction; ``planner`` names the planner."""
    rows = [
        f"| scenario{f' ({planner})' if planner else ''} | sampler | with ÷ without: verdict (median; middle half) "
        "| median total, ms: without / with "
        "| queries |",
        "| --- | --- | --- | --- | --- |",
    ]
    for name, table in tables.items():
        for sampler, row in table.items():
            median, q1, q3, said = planning_verdict(row, tie)
            mark = _mark(median, said, tie)
            said = f"{time_verdict(median, tie=tie)}{mark}" if mark else said
            without, with_ = (_ms(row[mode]["total_s_median"]) for mode in ("without", "with"))
            rows.append(
                f"| {name} | {sampler} | {said}<br>(median {median:.2f}; middle half {q1:.2f}–{q3:.2f}) "
                f"| {without} / {with_} | {row['without']['n_queries']} |"
            )
    return "\n".join(rows)


NO_CLEAR = r"\*"  # after a verdict: inside the noise band of its statistic, no clear evidence; that only (r42d)
ACROSS = "†"  # after a live verdict: its middle half includes an edge of the tie band; that only (r61d)
ACROSS_REASON = "its middle half includes an edge of the tie band (0.90 or 1.10)"  # said under a table with a †


def _mark(median: float, said: str, tie: float = TIE) -> str:
    """A live verdict's mark (r42d: \\* means one thing): :data:`NO_CLEAR` inside the noise band, :data:`ACROSS` where
    its middle half (or too few queries) made it :data:`UNSURE`, else none."""
    low, high = noise_band()
    inside = low < median < high and time_verdict(median, tie=tie) != TIES
    return "" if said != UNSURE else NO_CLEAR if inside else ACROSS


HOLDS, IN_PART, DOES_NOT_HOLD = "holds here", "holds here only in part", "does not hold here"  # the paper's claim


def claim_verdict(ratios: Mapping[str, Mapping[str, float]]) -> str:
    """The paper's claim (abstract: "computationally efficient in all investigated problems") read from time ratios
    with / without prediction, ``{scenario: {sampler: ratio}}``: :data:`HOLDS` where every one saves time (a gain of
    10 % or more, :func:`time_verdict`), :data:`IN_PART` where some do, :data:`DOES_NOT_HOLD` where none does."""
    said = [time_verdict(r) for row in ratios.values() for r in row.values()]
    if not said:
        raise ValueError("no time ratios to read the paper's claim from")
    saved = said.count(SAVES)
    return HOLDS if saved == len(said) else IN_PART if saved else DOES_NOT_HOLD


def _saved_in(ratios: Mapping[str, Mapping[str, float]]) -> str:
    """``"none of the 12 scenario–sampler pairs"`` or ``"2 of the 8 scenario–sampler pairs (2DS BS, 3DC-7 OB)"``."""
    pairs = [(f"{name} {sampler}", r) for name, row in ratios.items() for sampler, r in row.items()]
    saved = [pair for pair, r in pairs if time_verdict(r) == SAVES]
    return f"{len(saved) or 'none'} of the {len(pairs)} scenario–sampler pairs" + (
        f" ({', '.join(saved)})" if saved else ""
    )


FAST_CHECKER = "compiled in 3D, numpy interval tests in 2DS"  # what "our fast exact checker" is (review r24a)


def claim_status(eager: Mapping[str, Mapping[str, float]], lazy: Mapping[str, Mapping[str, float]]) -> str:
    """One sentence on the paper's claim with an accurate network, from recorded runs of 100 queries a scenario (each
    query timed without and with prediction in turn), ``{scenario: {sampler: median time with / without}}``:
    ``eager``, our accurate network inside the paper's Algorithm 1 against Algorithm 1 without prediction, which
    decides whether the claim holds (:func:`claim_verdict`); ``lazy``, the same network against the lazy PRM, by the
    ratio of the two median times (which of them lie at the noise edge: :func:`toolkit.teaching.costs.at_edge`)."""
    status = claim_verdict(eager)
    counted = Counter(time_verdict(r) for row in eager.values() for r in row.values())
    rest = f"a tie in {counted[TIES]}, a cost in {counted[COSTS]}"
    return (
        f"Against our fast exact checker ({FAST_CHECKER}), the paper's claim {status} for an accurate network: inside "
        "the "
        "paper's Algorithm 1 the median own ratio of "
        f"our accurate `strong` network saved time in {_saved_in(eager)} ({rest}), and against the lazy PRM (on "
        f"{' and '.join(lazy)}, by the median time with over the median without) in "
        f"{_saved_in(lazy)} (recorded runs, 100 queries a scenario)."
    )


COUNTED = (SAVES, TIES, COSTS)  # the verdicts one recorded ratio can have, in the order a count column gives them
COUNT_COLUMN = "saves / tie / costs"  # short: the table must fit a page's column


def ratio_table(
    series: Mapping[str, Mapping[str, float]], tie: float = TIE, counts: bool = False, narrow: bool = False
) -> str:
    """Markdown: one row per ``{label: {sampler: time with / without}}`` (recorded figures over many queries), each
    ratio with its verdict; with ``counts``, a count of the row's verdicts (:data:`COUNT_COLUMN`), so that a sentence
    need not count them: a last column, or with ``narrow`` a line under the row's label, each ratio on a line below
    its verdict (``<br>``). A page's column holds five columns of a rendered table, not six (each at least 5 rem)."""
    samplers = list(next(iter(series.values())))
    apart = "<br>" if narrow else " "
    extra = [COUNT_COLUMN] if counts and not narrow else []
    rows = [
        "| measured | " + " | ".join([*samplers, *extra]) + " |",
        "| --- |" + " --- |" * (len(samplers) + len(extra)),
    ]
    for label, ratios in series.items():
        said = [time_verdict(ratios[s], tie=tie) for s in samplers]
        cells = [f"{v}{apart}({ratios[s]:.2f})" for v, s in zip(said, samplers)]
        counted = " / ".join(str(said.count(v)) for v in COUNTED)
        if counts and narrow:
            label = f"{label}<br>{COUNT_COLUMN}: {counted}"
        elif counts:
            cells.append(counted)
        rows.append(f"| {label} | " + " | ".join(cells) + " |")
    return "\n".join(rows)


def crossover_table(results: Mapping, tie: float = CLOSE) -> str:
    """Markdown: every point of a ``toolkit.experiments.crossover`` run (variables by their short names), the
    network's cost per configuration against the default exact checker's and python-fcl's with verdicts, then the
    three costs in microseconds."""
    rows = [
        "| what grows | value | network / default exact | network / python-fcl "
        "| µs a configuration: default exact / python-fcl / network |",
        "| --- | --- | --- | --- | --- |",
    ]
    for variable, sweep in results["variables"].items():
        for value, exact, fcl, learned in zip(sweep["values"], sweep["exact_us"], sweep["fcl_us"], sweep["learned_us"]):
            against_fcl = (
                f"{cost_verdict(learned / fcl, tie)} ({learned / fcl:.2f})" if fcl is not None else "not timed"
            )
            rows.append(
                f"| {variable} | {value:,} | {cost_verdict(learned / exact, tie)} ({learned / exact:.2f}) "
                f"| {against_fcl} | {exact:.3g} / {'–' if fcl is None else f'{fcl:.3g}'} / {learned:.3g} |"
            )
    return "\n".join(rows)


def outlier_table(tables: Mapping[str, Mapping[str, Mapping]], factor: float = OUTLIER) -> str:
    """Markdown: every sampler and mode whose slowest query took at least ``factor`` times the other queries'
    median total and pulls the mean to :data:`MOVED` times that median or more; ``""`` when there is none."""
    rows = []
    for name, table in tables.items():
        for sampler, row in table.items():
            for mode in ("without", "with"):
                summary = row[mode]
                totals = np.asarray(summary["total_s_per_query"], dtype=float)  # (queries,)
                if len(totals) < 2:
                    continue
                slowest = int(np.argmax(totals))
                rest = max(float(np.median(np.delete(totals, slowest))), 1e-12)
                if totals[slowest] < factor * rest or summary["total_s"] < MOVED * rest:
                    continue  # not an outlier, or one that leaves the mean where the other queries put it
                rows.append(
                    f"| {name} | {sampler} | {mode} | query {slowest}: {_ms(totals[slowest])} ({_ms(rest)}) "
                    f"| {_ms(summary['total_s'])} / {_ms(summary['total_s_median'])} |"
                )
    if not rows:
        return ""
    head = [
        "| scenario | sampler | prediction | slowest query: ms (the others' median) | mean / median (ms) |",
        "| --- | --- | --- | --- | --- |",
    ]
    return "\n".join(head + rows)


def _ms(seconds: float) -> str:
    """Milliseconds, 3 significant figures with their zeros, no exponent: "0.0812", "7.00" (not "7"), "2,100"."""
    ms = 1e3 * seconds
    return f"{ms:,.0f}" if ms >= 100 else f"{ms:#.3g}".rstrip(".")


def accuracy_against(
    balanced: Mapping[str, float], paper: Mapping[str, float], uniform: Mapping[str, float], always_valid: float
) -> str:
    """Two comparisons in one sentence, each read at the printed precision (whole percent): a model's accuracy on
    its ``balanced`` unseen test against the ``paper``'s (Table 2), and its accuracy on ``uniform`` samples against
    answering "valid" to all of them (``always_valid``, the valid share)."""
    return (
        f"On its balanced unseen test the model is {_as_accurate(balanced['acc'], paper['acc'])} the paper's MLP "
        f"(Table 2); on these uniform samples it is {_as_accurate(uniform['acc'], always_valid)} answering "
        '"valid" to all of them.'
    )


def _as_accurate(mine: float, theirs: float) -> str:
    a, b = round(100 * mine), round(100 * theirs)
    return "more accurate than" if a > b else "less accurate than" if a < b else "as accurate as"


def crossover_counts(results: Mapping, tie: float = CLOSE) -> str:
    """One sentence: at how many of a ``toolkit.experiments.crossover`` run's points the network is the cheaper
    check, the dearer one, or too close to tell, against the default exact checker and against python-fcl (the
    verdicts of :func:`crossover_table`)."""
    said: list[str] = []
    for key, name in (("exact_us", "the default exact checker"), ("fcl_us", "python-fcl")):
        verdicts = [
            cost_verdict(learned / exact, tie)
            for sweep in results["variables"].values()
            for exact, learned in zip(sweep[key], sweep["learned_us"])
            if exact is not None
        ]
        if verdicts:
            close = verdicts.count(NEAR)
            lead = f"Against {name} the network was the cheaper check" if not said else f"against {name}, the cheaper"
            said.append(
                f"{lead} at {verdicts.count(CHEAPER)} of {len(verdicts)} points and the dearer at "
                f"{verdicts.count(DEARER)}" + (f" ({close} too close to tell)" if close else "")
            )
    return "; ".join(said) + "."


def describe_accuracy(label: str, scores: Mapping[str, float], always_valid: float) -> str:
    """``label``'s accuracy (``scores``: :func:`toolkit.learning.metrics.classification`'s) next to answering "valid"
    to everything on the same samples, then its balanced accuracy, (TPR + TNR) / 2, next to a coin flip: 50 % whatever
    the share of valid samples. Both comparisons say "about" within :data:`CHANCE_BAND` (on balanced samples "always
    valid" scores 50 % too, and one model cannot be above the one and about the other); worse than chance only below
    that band. Plain accuracy below "always valid" is not below chance (review r16b: 38 % on samples 86 % valid,
    balanced accuracy 54 %)."""
    balanced = (scores["tpr"] + scores["tnr"]) / 2
    mine, theirs, even = round(100 * scores["acc"]), round(100 * always_valid), round(100 * balanced)
    side, chance = (_beside(difference) for difference in (mine - theirs, even - 50))
    worse = " (worse than chance)" if chance == "below" else ""
    accuracy = f'{label}: accuracy {scores["acc"]:.0%}, {side} "always valid" ({always_valid:.0%})'
    return f"{accuracy}; balanced accuracy {even}%, {chance} a coin flip (50%){worse}"


def _beside(points: int) -> str:
    """A score ``points`` percentage points from its baseline: "about" within :data:`CHANCE_BAND`, else the side."""
    return "about" if abs(points) <= 100 * CHANCE_BAND else "above" if points > 0 else "below"


def describe_threshold_sweep(probability: np.ndarray, valid: np.ndarray) -> str:
    """What a sweep of the decision threshold over ``probability (N,)`` against the truth ``valid (N,)`` shows, in three
    short sentences, each read off the thresholds that :func:`toolkit.plots.reproduction.threshold_sweep` draws
    (:data:`toolkit.learning.metrics.SWEEP`, the same numbers, so that the sentence names points of the figure): up to
    which threshold the model calls everything valid ("always valid"), the last threshold at which it still calls 90 %
    or more of the samples valid and the first at which it calls 10 % or fewer (80 % or more of its P(valid) lie
    between them: narrow, an abrupt switch), and its best accuracy next to "always valid"."""
    p, truth = np.asarray(probability, dtype=float), np.asarray(valid, dtype=bool)
    accuracy = metrics.threshold_sweep(p, truth)["acc"]  # (T,) over metrics.SWEEP; checks the shapes
    called = (p[None, :] >= metrics.SWEEP[:, None]).mean(axis=1)  # (T,) the share it calls valid, falling
    best = int(np.argmax(accuracy))  # the lowest threshold of the best accuracy
    always, top = round(100 * truth.mean()), round(100 * accuracy[best])
    every, most = (metrics.SWEEP[called >= share].max() for share in (1.0, 0.9))  # at 0 it calls every sample valid
    few = metrics.SWEEP[called <= 0.1]  # (F,) where it calls 10 % or fewer valid: none if a tenth reach P(valid) 1
    switch = (
        f"at {few.min():.2f} only 10 % or fewer: between the two, where 80 % or more of its P(valid) lie"
        if len(few)
        else f"and even at 1 more than 10 %: above {most:.2f}"
    )
    beats = "no threshold beats" if top <= always else f"{top - always} points above"
    return (
        f"Up to a threshold of {every:.2f}, at or just under its lowest P(valid) on these samples, the model calls "
        f'every sample valid: TPR 1, TNR 0, "always valid", {always}% accuracy. '
        f"At {most:.2f} it still calls 90 % or more of the samples valid, {switch}, its answers "
        f"switch. Its best accuracy over the thresholds 0, 0.01, ..., 1 is {top}%, at {metrics.SWEEP[best]:.2f}: "
        f'{beats} "always valid".'
    )


def table3_sentence() -> str:
    """In how many of Table 3's 32 entries the text's mean times give its percentage, and what they give in the others
    (:func:`~toolkit.experiments.paper_numbers.table3_against_text`)."""
    differ, cells = table3_against_text(), sum(len(row) for kinds in IMPROVEMENT.values() for row in kinds.values())
    listed = "; ".join(f"{cell}: {given:.0%}, Table 3 {printed:.0%}" for cell, (given, printed) in differ.items())
    return (
        f"The improvement of the mean times in the paper's text gives Table 3's percentage, within the rounding "
        f"of both, in {cells - len(differ)} of its {cells} entries, and not in {len(differ)} ({listed})."
    )


def slow_fold(tables: Mapping[str, Mapping[str, Mapping]], segments: str) -> str:
    """Chapter 04's fold under section 3's table: :func:`outlier_table` and ``segments``, the stage bars' segments."""
    slow = outlier_table(tables)
    return (
        "<details><summary>Queries so slow that they move a mean; the bars' segments in ms</summary>\n\n"
        + ("Queries so slow that they move a mean:\n\n" + slow if slow else "No query moved a mean.")
        + "\n\nThe figure's bars, segment by segment, in ms a query, without / with prediction: each stage's share of "
        "the average query times the median total, so a segment is not that stage's own median; *query* is the path, "
        f"its verification and repairs, *other* the encoding and set-up:\n\n{segments}\n\n</details>"
    )
