"""Chapter 04's answer beside the paper's Table 3 (reader r47d, items 1 and 3): Table 3's total-time cells quoted
exactly (:func:`papers_line`, :func:`papers_table`), the answer's *Why* with its numbers (:func:`why`), and section
6's fold on savings larger than all of sampling (:func:`beyond_sampling`)."""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping

import numpy as np

from toolkit.experiments.paper_numbers import IMPROVEMENT, TIMES, saved_beyond_sampling
from toolkit.teaching import checker_scope, costs, recorded
from toolkit.teaching.recorded import Tables
from toolkit.util.verdicts import COSTS, SAVES, TIES, time_verdict

RUNS = ((recorded.ALGORITHM_1, "fast checker"), (checker_scope.SLOW, "python-fcl"))  # our two Algorithm 1 runs
SLOW_DOWN = "3DO BT"  # the one cell the paper's text calls "a slow-down for BT (8%)" (§V)


def table3_totals() -> dict[str, list[float]]:
    """Table 3's total-time improvements (the paper's fractions), split: ``saved`` (any saving), ``ten`` (a saving
    of 10 % or more: our tie band's :data:`SAVES`), ``longer`` (the slow-downs, as positive fractions)."""
    totals = [saved for row in IMPROVEMENT.values() for saved in row["total"].values()]
    return {
        "all": totals,
        "saved": [s for s in totals if s > 0],
        "ten": [s for s in totals if time_verdict(1 - s) == SAVES],
        "longer": [-s for s in totals if s < 0],
    }


def papers_line() -> str:
    """The answer's sentence on Table 3, exactly: in how many cells it saves time, and 10 % or more in how many."""
    t = table3_totals()
    return (
        f"The paper's Table 3 takes less time in {len(t['saved'])} of its {len(t['all'])} cells, 10 % or more less in "
        f"{len(t['ten'])}."
    )


def means_sentence(tables: Tables | None = None) -> str:
    """The answer's last sentence (reader r51d, item 1): by means, Table 3's statistic, our fast checker's cells that
    took 10 % or more less time and how many of them lie beyond that statistic's noise band, then Table 3 beside."""
    fast = costs.mean_verdicts(RUNS[0][0], tables)[SAVES]
    beyond = len(costs.clear_mean_savings(RUNS[0][0], tables))
    cells = f"{fast} of {sum(costs.mean_verdicts(RUNS[0][0], tables).values())} cells" if fast else "no cell"
    return (
        f"By means, Table 3's statistic, {cells} took 10 % or more less time with our fast checker, "
        f"{beyond or 'none'} beyond that statistic's noise band; t" + papers_line()[1:]
    )


def mean_ratios(preset: str, tables: Tables | None = None) -> dict[str, float]:
    """``preset``'s ratios of mean times inside Algorithm 1, every scenario and sampler (rounded as printed), by cell:
    ``{"2DS BS": 1.0, ...}``."""
    return {
        f"{checker_scope.NAMES[key]} {s}": round(1 - saved, 2)
        for key in recorded.query_ratios(preset, tables)
        for s, saved in recorded.improvements(preset, key, "total", tables).items()
    }


def _our_means(who: str, ratios: dict[str, float], band: tuple[float, float]) -> str:
    """One row of :func:`papers_table` for our run ``who``: less time, equal, more time (any ratio below, at or above
    1), then faster, tie, slower by our tie band, with those beyond the means' noise ``band`` (reader r49d, items 2-3:
    one column a count, and the equal cells named, so the row adds up to its cells)."""
    said = Counter(time_verdict(r) for r in ratios.values())
    clear = Counter(time_verdict(r) for r in ratios.values() if not costs.inside(r, band))

    def n(verdict: str) -> str:
        beyond = f" ({clear[verdict] or 'none'} beyond the noise band)" * (verdict != TIES and bool(said[verdict]))
        return f"{said[verdict] or 'none'}{beyond}"

    less, more = sum(r < 1 for r in ratios.values()), sum(r > 1 for r in ratios.values())
    equal = [c for c, r in ratios.items() if r == 1]
    same = f", {len(equal)} equal ({', '.join(equal)})" if equal else ""
    return f"| ours, {who} | {less or 'none'} / {more or 'none'}{same} | {n(SAVES)} | {n(TIES)} | {n(COSTS)} |"


def papers_table(read: tuple[int, int, int], tables: Tables | None = None) -> str:
    """Table 3 by means, folded under the answer's table (reader r49d, item 3): less time, equal, more time, and
    ``read`` (faster, ties, slower) by our 10 % tie band, which is ours, not the paper's, one count a column; beside
    it our two runs by the same statistic (reader r48d, item 3), and one line on the words and why each query's own
    ratio decides."""
    t = table3_totals()
    low, high = (round(100 * f) for f in (min(t["longer"]), max(t["longer"])))
    equal = len(t["all"]) - len(t["saved"]) - len(t["longer"])
    same = f", {equal} equal" if equal else ""
    bands = costs.floors(tables)
    ours = "\n".join(
        _our_means(who + " (noise band borrowed)" * (who != RUNS[0][1]), mean_ratios(preset, tables), bands["means"])
        for preset, who in RUNS
    )

    def n(count: int) -> str:
        return str(count or "none")

    def band(kind: str) -> str:
        return f"{bands[kind][0]:.2f}–{bands[kind][1]:.2f}"

    return (
        f"<details><summary>The same {len(t['all'])} cells by mean times (Table 3's statistic): the paper's Table 3 "
        "beside ours</summary>\n\n"
        f"| {len(t['all'])} cells, by mean times | less / more time | faster | tie | slower |\n"
        "| --- | --- | --- | --- | --- |\n"
        f"| the paper's Table 3 | {len(t['saved'])} / {len(t['longer'])}{same} | {n(read[0])} | {n(read[1])} "
        f"| {n(read[2])} |\n{ours}\n\n"
        "*Less time* and *more time* count any ratio of mean times below or above 1 (*equal*: 1.00 as printed); "
        f"Table 3's {len(t['longer'])} cells with more time are {low}–{high} % more, and of {SLOW_DOWN} the paper "
        'says "a slow-down". '
        "*Faster* counts only 0.90 or less, *slower* only 1.10 or more: our 10 % tie band, not the paper's; we read "
        "the paper's cells and ours with it alike. Why each query's own ratio decides: a ratio of means divides two "
        "sets of 100 queries timed apart, and a few slow queries weigh on a mean, so its noise band is wide "
        f"({band('means')}); each query's own ratio divides one query's two times, taken in turn ({band('own')}). "
        "python-fcl's run was not timed twice: it borrows the fast checker's noise band.\n\n</details>"
    )


def plain(fast: int, slow: int, total: int, tables: Tables | None = None) -> str:
    """The answer's first words, before any statistic (reader r50d, item 2): ``fast`` and ``slow`` cells that took
    10 % or more less time with each checker, of ``total``; sampling's largest share of a query with each checker
    (its range with python-fcl, whose ties it explains), and whether every network call cost more than the check."""
    fast_share, slow_share = (costs.sampling_shares(preset, tables) for preset, _ in RUNS)
    rows = recorded.table(recorded.ALGORITHM_1, "Checker throughput", tables).values()
    dearer = sum(recorded.ours(row["learned / exact"]) < 1 for row in rows)  # a network call costs more
    cheaper = "cheaper than a network call" if dearer == len(rows) else f"the cheaper check in {dearer} of {len(rows)}"
    took = (
        "did not make the paper's planner take 10 % or more less time in any cell"
        if not fast
        else f"made the paper's planner take 10 % or more less time in only {fast} of {total} cells"
    )
    return (
        f"By each query's own ratio, letting our accurate network decide which samples are valid {took} with our fast "
        "exact checker: sampling, "
        f"whose checks the network replaces, is at most {100 * max(fast_share):.0f} % of a query, and in that run "
        f"that checker is {cheaper}. Even against slow python-fcl, where sampling is {100 * min(slow_share):.1f}–"
        f"{100 * max(slow_share):.0f} % of a query, {f'only {slow} of {total} cells' if slow else 'no cell'} took 10 "
        f"% or more less time{sampling_claim(tables)}."
    )


def sampling_claim(tables: Tables | None = None) -> str:
    """The answer's clause on the paper's sampling-time claim against python-fcl (reader r52d, item 3): where every
    cell's sampling took less time by means, the claim holds there, so the answer's "No" is about total time."""
    facts = checker_scope.slow_checker(tables)
    saved, cells = facts.sampling_verdicts()[SAVES], len(facts.sampling)
    if saved < cells:
        return f", and sampling itself took less time in {saved or 'none'} of its {cells} cells by means"
    return (
        f", though sampling itself took {checker_scope.percents(facts.sampling)} less time by means, as the paper's "
        f'Table 3 claims ({checker_scope.percents(facts.papers_sampling)}): the "No" is about total time'
    )


def why(tables: Tables | None = None) -> str:
    """The answer's *Why* (reader r47d, item 3): sampling's share of a query in our fast checker's run, inline, and
    the paper's cells whose total saving exceeds all of their sampling time (:func:`saved_beyond_sampling`)."""
    shares, slow = (costs.sampling_shares(preset, tables) for preset, _ in RUNS)
    ties = costs.median_counts(RUNS[1][0], tables)[TIES][0]
    rows = recorded.table(recorded.ALGORITHM_1, "Checker throughput", tables).values()
    fcl = sum(recorded.ours(r["FCL cfg/s"]) < recorded.ours(r["learned cfg/s"]) for r in rows)  # network cheaper
    over = saved_beyond_sampling()
    top = max(over, key=lambda c: over[c][0])
    cells = sum(len(k["total_s"]) for k in TIMES.values())
    return (
        f"**Why no saving:** the network is accurate ({accuracy(tables)}), but prediction replaces only the "
        "samples' checks, and sampling is "
        f"{100 * min(shares):.1f}–{100 * max(shares):.0f} % of a query (our fast checker's mean times without "
        "prediction, by cell). With our fast checker a network call also costs more than the exact check it replaces "
        "([section 4](#4-is-the-network-a-cheaper-check)), and encoding the workspace comes on top. Against python-fcl "
        + (
            "a network call is the cheaper check"
            if fcl == len(rows)
            else f"a network call is cheaper in {fcl} of {len(rows)} scenarios"
        )
        + f", but sampling is only {100 * min(slow):.1f}–{100 * max(slow):.0f} % of "
        f"a query there, so skipping its checks saves little: {ties} of {len(slow)} cells tie. "
        f"{fcl_savings(tables)}\n\n"
        "**Nor can skipped sample checks explain the paper's savings:** in "
        f"{len(over)} of its {cells} cells the total time saved exceeds the whole sampling time without prediction "
        f"(e.g. {checker_scope.NAMES[top[0]]} {top[1]} saves {over[top][0]:.2f} s; its sampling took "
        f"{over[top][1]:.2f} s)."
    )


def fcl_clear(tables: Tables | None = None) -> list[tuple[str, float, float, bool]]:
    """The python-fcl run's savings beyond the noise band of each query's own ratio: ``[(cell, share of the median
    query saved, sampling's share of a mean query without prediction, whether that share is the run's largest)]``."""
    shares, band = costs.shares_by_cell(RUNS[1][0], tables), costs.floors(tables)["own"]
    return [
        (f"{checker_scope.NAMES[key]} {s}", 1 - median, shares[key, s], shares[key, s] == max(shares.values()))
        for key, row in costs.middle_halves(RUNS[1][0], tables).items()
        for s, (median, _, _) in row.items()
        if time_verdict(median) == SAVES and not costs.inside(median, band)
    ]


def _by_means(cell: str, share: float, tables: Tables | None = None) -> str:
    """Reader r52d, item 4: what skipped checks explain of a python-fcl saving that sampling's share allows, by the
    sampling table's means (sampling's saving times its share of a mean query) beside the total's saving by means."""
    key = next(k for k, name in checker_scope.NAMES.items() if cell.startswith(name + " "))
    sampling, total = (1 - checker_scope.means(RUNS[1][0], key, kind, tables)[cell.split()[-1]] for kind in KINDS)
    return (
        f": by means its sampling took {100 * sampling:.0f} % less time, about {100 * sampling * share:.0f} % of a "
        f"mean query, and its total {100 * total:.0f} % less: skipped checks "
        f"{'can' if sampling * share >= total else 'cannot'} explain that saving by means"
    )


KINDS = ("sampling", "total")


def fcl_savings(tables: Tables | None = None) -> str:
    """The python-fcl run's savings beyond the noise band (:func:`fcl_clear`) put to the test the paper's cells fail
    (reader r51d, item 2): the share of the median query saved against sampling's share of a mean query; the cell
    whose share is the top of the answer's range is named so."""
    said = [
        f"{cell} saved {100 * saved:.0f} % where sampling is {100 * share:.0f} %"
        + " (the top of that range)" * top
        + (": skipped checks cannot explain it" if saved > share else _by_means(cell, share, tables))
        for cell, saved, share, top in fcl_clear(tables)
    ]
    if not said:
        return ""
    return (
        "A saving larger than all of sampling cannot come from skipping sample checks. Of python-fcl's "
        f"{len(said)} saving{'s' * (len(said) > 1)} beyond the noise band (by each query's own ratio; sampling as a "
        f"share of a mean query): {'; '.join(said)}."
    )


def accuracy(tables: Tables | None = None) -> str:
    """The accurate network's accuracy in the Algorithm 1 run, one range (reader r48d: the page gave no number): its
    balanced unseen accuracy by scenario, as ``docs/results.md``'s accuracy table records it for that run."""
    scores = [
        int(row["Balanced unseen Acc"].strip("*%"))
        for row in recorded.table(RUNS[0][0], "MLP accuracy", tables).values()
    ]
    return (
        f"it is right {min(scores)}–{max(scores)} % of the time on half-valid samples in unseen workspaces, by "
        "scenario: the results page's accuracy table for that run, `docs/results.md`"
    )


def beyond_sampling(tables: Tables | None = None) -> str:
    """Section 6 (review r31d): where a recorded saving is larger than the whole sampling stage, all that skipping
    the samples' checks can save: the paper's own mean times (§V), the largest two, how many its spread exceeds;
    ours (:func:`_ours_beyond`)."""
    over = saved_beyond_sampling()  # the paper's cells: (seconds saved, seconds of sampling without, its spread)
    best = {key: max((c for c in over if c[0] == key), key=lambda c: over[c][0]) for key, _ in over}
    first, second = sorted(best.values(), key=lambda c: -over[c][0])[:2]
    spread = sum(over[c][2] > over[c][0] for c in over)

    def cell(c: tuple[str, str]) -> str:
        return f"{checker_scope.NAMES[c[0]]} {c[1]}"

    return (
        "**Savings larger than all of sampling.** Skipping the samples' checks can save at most the whole sampling "
        "stage. Yet in the paper's own mean times (§V, the times behind Table 3) the total time saved exceeds all the "
        f"sampling time without prediction in {len(over)} of its {sum(len(k['total_s']) for k in TIMES.values())} "
        f"cells: {cell(first)} saves {over[first][0]:.2f} s while its sampling took {over[first][1]:.2f} s, "
        f"{cell(second)} {over[second][0]:.2f} s against {over[second][1]:.2f} s. Prediction of samples alone cannot "
        "explain these. Another roadmap can, and so can the spread of the times: in "
        f"{spread} of those {len(over)} cells the paper's standard deviation of a query's time exceeds the saving."
        + _ours_beyond(tables)
    )


def _ours_beyond(tables: Tables | None = None) -> str:
    """:func:`beyond_sampling`'s sentences on our two runs (:data:`RUNS`), :func:`costs.over_sampling`'s cells."""
    runs = {who: costs.over_sampling(preset, tables) for preset, who in RUNS}
    count = sum(len(cells) for cells in runs.values())
    if not count:
        return " Ours have no such saving, by means or by the median own ratio."
    named = "; ".join(
        f"{who}: " + ", ".join(f"{c} {100 * a:.0f} % against {100 * b:.0f} %" for c, a, b in cells)
        for who, cells in runs.items()
        if cells
    )
    said = (
        f" Ours have {count} such saving{'s' * (count > 1)} by means (the share of the mean query saved against "
        f"sampling's share without prediction; {named})."
    )
    band = costs.floors(tables)["means"]
    noisy = [f"{who} {c}" for who, cells in runs.items() for c, a, _ in cells if costs.inside(round(1 - a, 2), band)]
    if len(noisy) == count:  # common46: by means ours lie within timing noise, so no story is told of them
        return said + (
            f" Each lies inside the noise band of a ratio of means ({band[0]:.2f}–{band[1]:.2f}): within timing "
            "noise, so no evidence of a saving larger than sampling." + _by_own(tables)
        )
    medians = {who: costs.middle_halves(preset, tables) for preset, who in RUNS}
    split: dict[bool, list[str]] = {False: [], True: []}
    for who, cells in runs.items():
        for c, _, _ in cells:
            key = next(k for k, n in checker_scope.NAMES.items() if c.startswith(n + " "))
            split[time_verdict(medians[who][key][c.split()[1]][0]) == SAVES].append(f"{who} {c}")
    if noisy:
        said += f" Inside the noise band of a ratio of means, so no evidence: {', '.join(noisy)}."
    if split[False]:
        said += (
            f" In {len(split[False])} of them ({', '.join(split[False])}) the median own ratio did not save: a few "
            "slow queries moved the mean, not prediction."
        )
    if split[True]:
        said += (
            f" Where the median own ratio saved too ({', '.join(split[True])}), another roadmap can explain it; that "
            "run was not timed twice (`docs/results.md`)."
        )
    return said


def _by_own(tables: Tables | None = None) -> str:
    """The fold's last sentence (reader r51d, item 2): python-fcl's savings larger than all of sampling by each
    query's own ratio, beyond that statistic's noise band, where the answer's *Why* names them."""
    over = [
        f"{cell} ({100 * saved:.0f} % against {100 * share:.0f} %)"
        for cell, saved, share, _ in fcl_clear(tables)
        if saved > share
    ]
    return (
        f" By each query's own ratio, python-fcl's {', '.join(over)} did save more than all of sampling, beyond that "
        "statistic's noise band (the answer's *Why*)."
    ) * bool(over)


def encoding_line(records: Mapping[str, list[dict]], tables: Tables | None = None) -> str:
    """Under section 6's cost table (reader r52d, item 2): the encoding, measured in section 5's live 3DC-7 queries,
    beside each costly cell's growth after sampling (which includes it), and what it leaves unexplained."""
    encoded = [r.get("encode_s", 0.0) for r in records.get("with", [])]
    if not encoded or max(encoded) <= 0:
        return ""
    ms = 1000 * float(np.median(encoded))
    grew = {f"{c.scenario} {c.sampler}": 1000 * (c.after[1] - c.after[0]) for c in costs.dear_cells(tables)}
    here = {n: g for n, g in grew.items() if n.startswith("3DC-7")}
    said = [
        f"{n}'s time after sampling grew {g:.1f} ms, "
        + (
            "which the encoding alone could cover"
            if ms >= g
            else f"of which the encoding is about {100 * ms / g:.0f} %"
        )
        for n, g in here.items()
    ]
    elsewhere = [f"{n} +{g:.1f} ms" for n, g in grew.items() if n not in here]
    short = sum(ms < g for g in here.values())
    return (
        "**The encoding beside that growth.** The time after sampling includes encoding the workspace for the network. "
        f"Section 5's live 3DC-7 queries spent {ms:.1f} ms a query on it (median; on this machine, not in the recorded "
        f"run, so a rough size). {'; '.join(said) or 'No 3DC-7 cell costs that much'}. "
        + (
            f"The other scenarios' encoding is not measured here ({', '.join(elsewhere)} after sampling). "
            if elsewhere
            else ""
        )
        + f"Where the encoding falls short (in {short} of the {len(here)} 3DC-7 cells), something else after sampling "
        "grew too, and these runs do not say what; elsewhere they cannot tell."
    )
