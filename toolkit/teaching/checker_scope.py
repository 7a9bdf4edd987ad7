"""Which exact checker a verdict on the paper's claim holds against, read from the recorded runs.

The paper names no exact checker. ``docs/results.md`` records our accurate `strong` network inside the paper's
Algorithm 1 twice: with our compiled exact checker on both sides (:data:`toolkit.teaching.recorded.ALGORITHM_1`), and
with python-fcl doing every exact check on both sides (:data:`SLOW`), a checker tens of times slower. A slow checker
makes every sample check the network skips worth more, so the chapters name the checker first, then the answer."""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping
from dataclasses import dataclass

from toolkit.experiments.paper_numbers import IMPROVEMENT, MLP
from toolkit.learning import metrics
from toolkit.teaching import costs, findings, recorded
from toolkit.teaching.recorded import Tables
from toolkit.util.verdicts import COSTS, SAVES, TIES, time_verdict

SLOW = "strong --planner paper --baseline paper-fcl-alike"  # the section of docs/results.md: python-fcl on both sides
NAMES = {"2ds": "2DS", "3dc7": "3DC-7", "3dc9": "3DC-9", "3do": "3DO"}


@dataclass(frozen=True)
class SlowChecker:
    """The accurate network inside Algorithm 1 with python-fcl on both sides, as recorded (100 queries a scenario)."""

    scenarios: tuple[str, ...]  # the recorded scenarios, as the page names them ("3DC-7")
    sampling: tuple[float, ...]  # Table 3's sampling improvements, ours: (without - with) / without of mean times
    papers_sampling: tuple[float, ...]  # the paper's Table 3 in the same cells
    totals: tuple[float, ...]  # Table 3's total improvements, ours
    papers_totals: tuple[float, ...]  # ... and the paper's
    own: tuple[float, ...]  # per scenario and sampler: the median of each query's own total-time ratio with / without
    edge: int = 0  # the savings of ``own`` at the noise edge (:func:`toolkit.teaching.costs.at_edge`)

    def sampling_verdicts(self) -> Counter:
        """How many sampling cells saved time, tied or cost (chapter 04's rule on the ratio 1 - improvement)."""
        return Counter(time_verdict(1 - saved) for saved in self.sampling)

    def total_verdicts(self) -> Counter:
        """How many scenario–sampler medians of each query's own total-time ratio saved time, tied or cost."""
        return Counter(time_verdict(ratio) for ratio in self.own)


def slow_checker(tables: Tables | None = None) -> SlowChecker:
    """The section :data:`SLOW` of ``docs/results.md`` (or of ``tables``), whatever scenarios it holds so far."""
    table3 = recorded.table(SLOW, "time improvement", tables)
    own = recorded.query_ratios(SLOW, tables)

    def cells(kind: str, paper: bool) -> tuple[float, ...]:
        return tuple(
            recorded.ours(cell.split("/")[-1] if paper else cell)
            for row in table3.values()
            for column, cell in row.items()
            if column.lower().startswith(kind)
        )

    return SlowChecker(
        scenarios=tuple(NAMES.get(s, s) for s in table3),
        sampling=cells("sampling", False),
        papers_sampling=cells("sampling", True),
        totals=cells("total", False),
        papers_totals=cells("total", True),
        own=tuple(ratio for row in own.values() for ratio in row.values()),
        edge=costs.at_edge(SLOW, tables)[SAVES],
    )


def percents(values: tuple[float, ...]) -> str:
    """``"67–78 %"``; where the signs differ, ``"from −12 to +9 %"`` (a negative improvement is a loss)."""
    low, high = round(100 * min(values)), round(100 * max(values))
    if low == high:
        return f"{low} %"
    if low < 0 <= high:
        return f"from {low:+d} to {high:+d} %".replace("-", "−")
    return f"{low}–{high} %"


def _counted(verdicts: Counter) -> str:
    """``"each query's total time was a tie for every sampler"`` where every median agrees, else the counts."""
    total = sum(verdicts.values())
    for verdict, words in ((TIES, "a tie"), (SAVES, "shorter"), (COSTS, "longer")):
        if verdicts[verdict] == total:
            return f"each query's total time was {words} for every sampler"
    return (
        f"by the median own ratio, total time was 10 % or more shorter in {verdicts[SAVES] or 'none'} of the {total} "
        f"cells, a tie in {verdicts[TIES]} and 10 % or more longer in {verdicts[COSTS] or 'none'}"
    )


def slow_sentence(facts: SlowChecker, ranges: bool = True) -> str:
    """One sentence, the checker named first: what the accurate network did inside Algorithm 1 with python-fcl on
    both sides, the sampling stage by Table 3's means beside the paper's, the total by each query's own ratio;
    ``ranges``: the ranges of the totals in parentheses (chapter 04's answer leaves them out, review r24a)."""
    where = " and ".join(facts.scenarios) if len(facts.scenarios) < 3 else ", ".join(facts.scenarios)
    sampling = facts.sampling_verdicts()
    if sampling[SAVES] == len(facts.sampling):
        stage = f"saved {percents(facts.sampling)} of the sampling time by Table 3's means"
    else:
        stage = f"saved sampling time (Table 3's means) in {sampling[SAVES]} of {len(facts.sampling)} cells"
    own = facts.own
    total = _counted(facts.total_verdicts())
    if facts.edge:
        total += f" ({facts.edge} of the {facts.total_verdicts()[SAVES]} savings marked {costs.MARK})"
    said = (
        f"With a slow exact checker on both sides (python-fcl, {where}; 100 recorded queries a scenario), our accurate "
        f"network {stage} (the paper's Table 3: {percents(facts.papers_sampling)}), but {total}"
    )
    if not ranges:
        return said + "."
    return (
        f"{said} (the median of each query's own ratio {min(own):.2f}–{max(own):.2f}; Table 3's totals "
        f"{percents(facts.totals)}, the paper's {percents(facts.papers_totals)})."
    )


def like_for_like(facts: SlowChecker) -> str:
    """Table 3's statistic on the run closest to the paper's (python-fcl on both sides): the cells whose total time
    saved 10 % or more by means, ours and the paper's, read by our tie band (the paper has none: reader r47d)."""
    ours = sum(time_verdict(1 - saved) == SAVES for saved in facts.totals)
    papers = sum(time_verdict(1 - saved) == SAVES for saved in facts.papers_totals)
    return (
        "Read by our 10 % tie band, by means (Table 3's statistic), that run saved 10 % or more of the total time in "
        f"{ours or 'none'} of its {len(facts.totals)} cells, the paper's Table 3 in {papers or 'none'} of the same "
        f"{len(facts.papers_totals)}."
    )


def why_sentence(tables: Tables | None = None) -> str:
    """Why the accurate network saved no time inside Algorithm 1 with the compiled checker: what it decides (the
    samples; section 5 of chapter 04 counts the checks), what a call cost in that run, per configuration, over the
    compiled exact check (``docs/results.md``'s throughput table of :data:`toolkit.teaching.recorded.ALGORITHM_1`),
    and how far the slower sampling explains the dearest cells (:func:`toolkit.teaching.costs.split_sentence`)."""
    rates = recorded.table(recorded.ALGORITHM_1, "Checker throughput", tables)
    costly = [1 / recorded.ours(row["learned / exact"]) for row in rates.values()]
    per = ", ".join(
        f"{NAMES.get(key, key)} {1 / recorded.ours(row['learned / exact']):.1f}" for key, row in rates.items()
    )
    return (
        "Why: the network decides only the samples, a small part of Algorithm 1's work (section 5 counts the checks: "
        "nearly all are points along the roadmap's edges, which prediction never checks, though it changes how many "
        f"there are), and in the run with the fast checker a network call cost {min(costly):.1f} to "
        f"{max(costly):.0f} times as much per configuration as the exact check it replaced ({per}). "
        + costs.split_sentence(tables)
    )


def sampling_words(facts: SlowChecker) -> str:
    """The sampling stage with python-fcl on both sides, by Table 3's means: ``"22–91 % shorter"`` where every cell
    saved time, else ``"shorter in 9 of the 16 cells"``."""
    saved = facts.sampling_verdicts()[SAVES]
    if saved == len(facts.sampling):
        return f"{percents(facts.sampling)} shorter"
    return f"shorter in {saved or 'none'} of the {len(facts.sampling)} cells"


# Chapter 04's section 6's recorded tables, built here so that they follow its prose (review r23a).
SCENARIOS_2 = (("2DS", "2ds"), ("3DC-7", "3dc7"))  # the scenarios the chapter plans itself
SCENARIOS_4 = (*SCENARIOS_2, ("3DC-9", "3dc9"), ("3DO", "3do"))  # ... and those the paper's Table 3 has


def table_3(key: str, kind: str = "total") -> dict[str, float]:
    """The paper's Table 3 row of ``key`` (``"total"`` or ``"sampling"``) as time with / without: {sampler: ratio}."""
    return {s: 1 - saved for s, saved in IMPROVEMENT[key][kind].items()}


def means(preset: str, key: str, kind: str = "total", tables: Tables | None = None) -> dict[str, float]:
    """``docs/results.md``'s Table 3 row of ``preset`` and ``key`` as time with / without: {sampler: ratio}."""
    return {s: 1 - saved for s, saved in recorded.improvements(preset, key, kind, tables).items()}


def against_algorithm_1(tables: Tables | None = None) -> dict[str, dict[str, float]]:
    """Total time with / without prediction against Algorithm 1, 100 queries a scenario, per scenario: the paper's
    Table 3, our `paper` preset by means, our accurate `strong` network by means and by the median of each query's
    own ratio, with the compiled checker and (where recorded) with python-fcl on both sides (:data:`SLOW`)."""
    accurate = recorded.query_ratios(recorded.ALGORITHM_1, tables)
    slow_own = recorded.query_ratios(SLOW, tables)
    rows = {}
    for name, key in SCENARIOS_4:
        rows[f"{name}, the paper's Table 3"] = table_3(key)
        rows[f"{name}, ours (`paper` preset)"] = means("paper", key, tables=tables)
        if key in accurate:  # a scenario the run of the accurate network planned
            rows[f"{name}, ours (`strong` preset), means"] = means(recorded.ALGORITHM_1, key, tables=tables)
            rows[f"{name}, ours (`strong` preset), medians"] = accurate[key]
        if key in slow_own:  # ... and with python-fcl doing every exact check on both sides
            rows[f"{name}, ours (`strong`, python-fcl), means"] = means(SLOW, key, tables=tables)
            rows[f"{name}, ours (`strong`, python-fcl), medians"] = slow_own[key]
    return rows


def compact(tables: Tables | None = None) -> dict[str, dict[str, float]]:
    """Section 6's one visible table (review r24a): per scenario, the paper's Table 3 and our accurate `strong` network
    inside Algorithm 1 by the median of each query's own ratio, with the fast checker and with python-fcl on both
    sides: the rows the chapter's answer reads (:func:`against_algorithm_1` holds them with the rest)."""
    return {
        label: row
        for label, row in against_algorithm_1(tables).items()
        if label.endswith(("the paper's Table 3", "medians"))
    }


def spans(tables: Tables | None = None) -> dict[str, dict[str, tuple[float, float]]]:
    """The middle half of each query's own ratio behind :func:`compact`'s medians: the answer figure's whiskers."""
    out = {}
    for preset, series in (
        (recorded.ALGORITHM_1, "ours (`strong` preset), medians"),
        (SLOW, "ours (`strong`, python-fcl), medians"),
    ):
        for key, cells in costs.middle_halves(preset, tables).items():
            out[f"{NAMES.get(key, key)}, {series}"] = {s: (low, high) for s, (_, low, high) in cells.items()}
    return out


def our_means(tables: Tables | None = None) -> dict[str, dict[str, float]]:
    """Our series' ratios of mean times, by :func:`compact`'s labels of their medians: the answer figure's rings."""
    rows = against_algorithm_1(tables)
    return {label: rows[label.removesuffix("medians") + "means"] for label in compact(tables) if "ours" in label}


def _others(tables: Tables | None = None) -> dict[str, dict[str, float]]:
    """:func:`against_algorithm_1` less :func:`compact`'s medians: Table 3 beside the rows read by means."""
    return {label: row for label, row in against_algorithm_1(tables).items() if not label.endswith("medians")}


def against_lazy(tables: Tables | None = None) -> dict[str, dict[str, float]]:
    """Total time with / without prediction against the lazy PRM on 2DS and 3DC-7, 100 queries a scenario: each
    preset's ratio of the two modes' median times, and the `strong` preset's means."""
    rows = {}
    for name, key in SCENARIOS_2:
        rows[f"{name}, `paper` preset, ratio of medians"] = recorded.median_ratios("paper", tables)[key]["total"]
        rows[f"{name}, `strong` preset, means"] = means("strong", key, tables=tables)
        rows[f"{name}, `strong` preset, ratio of medians"] = recorded.median_ratios("strong", tables)[key]["total"]
    return rows


def _lazy_means(tables: Tables | None = None) -> str:
    """Where the `strong` mean saved against the lazy PRM, not its ratio of medians: the spread behind it (r38d)."""
    rows, times = against_lazy(tables), costs.mean_times("strong", tables)
    return "".join(
        f"\n\n{name} {s} saved by means ({r:.2f}), not by the ratio of medians ({mid:.2f}): without prediction its "
        f"query took {1000 * recorded.ours(cell):.0f} ± {1000 * recorded.ours(cell.split('±')[1]):.0f} ms (mean ± "
        "std), a few slow queries."
        for name, key in SCENARIOS_2
        for s, r in rows[f"{name}, `strong` preset, means"].items()
        if time_verdict(r) == SAVES
        and time_verdict(mid := rows[f"{name}, `strong` preset, ratio of medians"][s]) != SAVES
        for cell in [times[key, s]["total without"]]
    )


def sampling_inside(tables: Tables | None = None) -> dict[str, dict[str, float]]:
    """The sampling stage's time with / without prediction inside Algorithm 1: the paper's Table 3, and our accurate
    network by means, by the ratio of the two modes' medians and, with python-fcl on both sides, by means."""
    inside = recorded.median_ratios(recorded.ALGORITHM_1, tables)
    slow_run = recorded.table(SLOW, "time improvement", tables)
    rows = {}
    for name, key in SCENARIOS_4:
        rows[f"{name}, the paper, means"] = table_3(key, "sampling")  # short labels: one line in the page's column
        if key in inside:
            rows[f"{name}, ours, means"] = means(recorded.ALGORITHM_1, key, "sampling", tables)
            rows[f"{name}, ours, ratio of medians"] = inside[key]["sampling"]
        if key in slow_run:
            rows[f"{name}, ours, python-fcl, means"] = means(SLOW, key, "sampling", tables)
    return rows


def _answers(tpr: float, tnr: float) -> str:
    """What a classifier with these rates answers, on two lines (the table fits the page)."""
    return metrics.what_it_answers(tpr, tnr).replace(" to ", " to<br>")


def section_6(this_run: dict[str, float], tables: Tables | None = None, first: str = "") -> list[str]:
    """Chapter 04's section 6 as two Markdown blocks: the answer's table (:func:`compact`), then, folded in a
    ``<details>`` box (review r24a), ``first`` (the answer's counts in full sentences) and the other tables from
    the recorded runs: against Algorithm 1 by means, against the lazy PRM, the sampling stage inside Algorithm 1,
    the `paper` MLP's answers, a network call's cost over the exact check's (``this_run``: section 4's)."""

    def table(rows: dict[str, dict[str, float]], **how: bool) -> str:  # our verdicts inside timing's reach marked
        return costs.marked(findings.ratio_table(rows, **how), tables)

    inside = recorded.median_ratios(recorded.ALGORITHM_1, tables)
    ours_sampling = [r for key in inside for r in inside[key]["sampling"].values()]
    papers_saved = [IMPROVEMENT[key]["sampling"][s] for _, key in SCENARIOS_4 for s in IMPROVEMENT[key]["sampling"]]
    more = [
        "**Against Algorithm 1, by means.** Total time with / without prediction, 100 queries a scenario, by means "
        "(Table 3's statistic as we read it): the paper's Table 3, the reproduction's `paper` preset and our accurate "
        "`strong` network, with the fast checker and with python-fcl on both sides:\n\n"
        + table(_others(tables), counts=True, narrow=True)
        + f"\n\n{papers_longer_sentence()} {findings.table3_sentence()}",
        "**Against the lazy PRM.** Total time with / without prediction, 100 queries a scenario, our runs as "
        "`docs/results.md` records them (our fast exact checker as it was that day), by means and by the median "
        'time with prediction over the median without ("ratio of medians", noise band '
        f"{'{:.2f}–{:.2f}'.format(*costs.floors(tables)['medians'])}, by the rule under the answer figure):\n\n"
        + table(against_lazy(tables), counts=True, narrow=True)
        + _lazy_means(tables),
        "**Sampling inside Algorithm 1.** The sampling stage's time with / without prediction, 100 queries a scenario: "
        'the paper\'s Table 3 ("the paper"), and our accurate `strong` network inside Algorithm 1 ("ours") as '
        '`docs/results.md` records it ("Preset `strong` with `--planner paper`"), by means and by the median sampling '
        "time with prediction over the median without, and by means with python-fcl doing every exact check on both "
        'sides ("python-fcl", the section after it):\n\n'
        + table(sampling_inside(tables), counts=True, narrow=True)
        + f"\n\nThe paper's Table 3 has sampling {min(papers_saved):.0%} to {max(papers_saved):.0%} shorter with "
        "prediction; in our run with the fast checker the median sampling time with the accurate network was "
        f"{min(ours_sampling):.2f} to {max(ours_sampling):.2f} times the median without.",
        _paper_mlp(tables),
        _call_costs(this_run, tables),
    ]
    return [
        "**The answer's table.** Total time with / without prediction inside the paper's Algorithm 1, 100 queries a "
        'scenario: the paper\'s Table 3 (its "Average time improvement ratio", read as means; the paper names no '
        "exact checker), and our accurate `strong` network by the median of each query's own ratio, with our fast "
        "exact checker (compiled in 3D, numpy interval tests in 2DS) and with python-fcl on both sides "
        "(`docs/results.md`):\n\n" + table(compact(tables), counts=True, narrow=True),
        "<details><summary>The counts in full sentences and by means, and more tables: the same runs by means, the "
        "<code>paper</code> preset, the lazy PRM, the sampling stage, the <code>paper</code> MLP's accuracy (not "
        "the answer's network), and what a network call "
        "cost</summary>\n\n" + "\n\n".join([first, *more] if first else more) + "\n\n</details>",
    ]


def _paper_mlp(tables: Tables | None = None) -> str:
    """The `paper` preset's MLP on unseen workspaces (docs/results.md's accuracy table) beside the paper's, Markdown."""
    mlp = recorded.table("paper", "MLP accuracy", tables)
    cols = ("Unseen TPR", "Unseen TNR", "Unseen Acc", "Unseen always valid")
    rates = {name: {c: recorded.ours(mlp[key][c]) for c in cols} for name, key in SCENARIOS_4}
    papers = {name: {r: f" ({MLP[key]['unseen'][r]:.0%})" for r in ("tpr", "tnr", "acc")} for name, key in SCENARIOS_4}
    balanced = [recorded.ours(mlp[key]["Balanced unseen Acc"]) for _, key in SCENARIOS_4]  # half the samples valid
    fair = [(MLP[k]["unseen"]["tpr"] + MLP[k]["unseen"]["tnr"]) / 2 for _, k in SCENARIOS_4]  # the paper's, so
    return (
        "**The `paper` preset's MLP (not the network the answer uses)** on unseen workspaces, on samples drawn "
        '"regardless of their validity" as the paper\'s (§IV-A); in parentheses, its rates (Table 2). From the results '
        "page's accuracy table (`docs/results.md`; on balanced samples, half of them valid, the same MLP is right "
        f"{min(balanced):.0%} to {max(balanced):.0%} of the time, its *Balanced unseen* column, where the paper's "
        f"rates would be right {min(fair):.0%} to {max(fair):.0%}):\n\n"
        '| scenario | keeps valid<br>(TPR) | rejects colliding<br>(TNR) | accuracy / "valid" to all '
        "| what it<br>answers |\n| --- | ---: | ---: | ---: | --- |\n"
        + "\n".join(
            f"| {name} | {r['Unseen TPR']:.0%}{papers[name]['tpr']} | {r['Unseen TNR']:.0%}{papers[name]['tnr']} | "
            f"{r['Unseen Acc']:.0%}{papers[name]['acc']} / {r['Unseen always valid']:.0%} | "
            f"{_answers(r['Unseen TPR'], r['Unseen TNR'])} |"
            for name, r in rates.items()
        )
    )


def _call_costs(this_run: dict[str, float], tables: Tables | None = None) -> str:
    """A network call's cost over the exact check's, per recorded run and ``this_run``, a Markdown block."""
    throughput = {p: recorded.table(p, "Checker throughput", tables) for p in ("paper", "strong", recorded.ALGORITHM_1)}
    dearer = {
        **{
            f"`{preset}` run": {name: 1 / recorded.ours(rows[key]["learned / exact"]) for name, key in SCENARIOS_4}
            for preset, rows in throughput.items()
        },
        "this run (section 4)": this_run,
    }
    return (
        "A network call's cost per configuration over the fast exact check's (below 1 the network is the cheaper "
        "check; from 0.75 to 1.25, too close to tell). The answer's run is `strong --planner paper`; the other "
        "recorded runs show how this ratio moves from run to run and machine to machine (`docs/results.md`'s "
        "throughput tables), beside this run's section 4:\n\n" + costs.call_cost_table(dearer)
    )


def papers_longer_sentence() -> str:
    """The cells of the paper's Table 3 whose total time is longer with prediction, read by the one rule every page
    counts with (:func:`time_verdict`), and what the paper's own text calls its 3DO bridge test (review r23a)."""
    longer = {
        f"{NAMES[key]} {sampler}": 1 - saved
        for key, row in IMPROVEMENT.items()
        for sampler, saved in row["total"].items()
        if saved < 0
    }
    band = {time_verdict(ratio) for ratio in longer.values()}
    cells = sum(len(row["total"]) for row in IMPROVEMENT.values())
    listed = ", ".join(f"{cell} {ratio:.2f}×" for cell, ratio in longer.items())
    said = f"The paper's own Table 3 has total time longer with prediction in {len(longer)} of {cells} cells ({listed})"
    if band == {TIES}:
        return (
            f"{said}: each within 10 %, a tie by our tie band (the paper has none), though the paper's text says of "
            '3DO "a slow-down for BT (8%)": the band reads the paper\'s cells and ours alike.'
        )
    return f"{said}: by our 10 % tie band, {', '.join(sorted(band))}."


def sampling_line(name: str, planning: Mapping[str, Mapping[str, Mapping]]) -> str:
    """One line under a run's sampling bars (review r23a: "one sampler may come out a little faster" hedged where
    every sampler was slower): each sampler's median sampling time with prediction over its median without, and the
    samplers whose sampling was shorter, a tie or longer by :func:`time_verdict`."""
    ratios = {s: row["with"]["sampling_s_median"] / row["without"]["sampling_s_median"] for s, row in planning.items()}
    said = Counter(time_verdict(r) for r in ratios.values())
    listed = ", ".join(f"{s} {r:.2f}" for s, r in ratios.items())
    counted = "; ".join(
        f"{words} for all {len(ratios)} samplers"
        if said[verdict] == len(ratios)
        else f"{words} for {said[verdict]} of the {len(ratios)} samplers"
        for verdict, words in ((COSTS, "longer with prediction"), (TIES, "a tie"), (SAVES, "shorter"))
        if said[verdict]
    )
    return f"This run's sampling stage on {name}, median time with prediction / median without: {listed}: {counted}."
