"""The findings of ``docs/results.md`` ("What reproduces and what does not") about time, one bullet each, every
number computed from the tables the page prints: why a fast checker erases the saving (:func:`why_no_saving`: the
sampling stage's share of a query, the network's cost per check, a worked example), where the whole query moved
apart from sampling (:func:`apart`), the answers against the lazy PRM (:func:`lazy_prm`) and against Algorithm 1
(:func:`algorithm_1`). :func:`summary` writes them, with the paper's two networks (:mod:`tools.results_networks`),
between :data:`DETAIL_BEGIN` and :data:`DETAIL_END`."""

from __future__ import annotations

from typing import NamedTuple

from toolkit.experiments.paper_numbers import IMPROVEMENT
from toolkit.teaching import checker_scope, costs, findings, recorded
from toolkit.teaching.recorded import Tables
from toolkit.util import verdicts
from tools.results_networks import cae, mlp, unseen_table
from tools.results_noise import costs_far, medians_floor, noise, own_intervals
from tools.results_words import NAMES, change, counted, grouped, percent, span, told

DETAIL_BEGIN = "<!-- findings: written by `python -m tools.results_summary` from the tables below; edit them there -->"
DETAIL_END = "<!-- end of the findings -->"


VERDICTS = {  # lazy_prm's; reader r53f, item 4: "no typical-query saving", not "saves no time" (2DS OB by means 0.26)
    "no": "makes no typical-query saving",
    "rarely": "rarely saves time",
    "mostly": "mostly saves time",
}


def lazy_prm(tables: Tables) -> str:
    """Against the lazy PRM, one sentence a network (reader r33f, item 5: "Counting ... rarely: 1 of 32" could not be
    read at once): the strong network's cells by the ratio of the two medians, then our `paper`-preset
    network's savings beyond that ratio's noise floor (its planner with prediction is Algorithm 1); one statistic
    (reader r36f, item 8: the strong network's mean saving on 2DS OB is told under "Means and medians")."""
    groups = {
        preset: grouped({s: kinds["total"] for s, kinds in recorded.median_ratios(preset, tables).items()})
        for preset in ("strong", "paper")
    }
    strong = sum(map(len, groups["strong"].values()))
    saved = len(groups["strong"]["less time"])
    answer = "no" if saved == 0 else "rarely" if saved < strong / 2 else "mostly"
    floor = medians_floor(tables)
    beyond = [(name, r) for name, r in groups["paper"]["less time"] if floor is None or not costs.inside(r, floor)]
    known = any("MLP accuracy" in heading for heading in tables.get("paper", {}))
    invalid = {  # reader r38f, contradiction 5: where the paper-recipe MLP answers "invalid" to every sample
        NAMES.get(s, s)
        for s, row in (recorded.table("paper", "MLP accuracy", tables) if known else {}).items()
        if recorded.ours(row["Unseen TPR"]) == 0
    }

    def cell(name: str, r: float) -> str:
        scenario = name.split()[0]
        return f"{name} {r:.2f}" + (
            f", a network that answers “invalid” to every {scenario} sample" if scenario in invalid else ""
        )

    named = f" ({'; '.join(cell(name, r) for name, r in beyond)})" if 0 < len(beyond) <= 3 else ""
    floor_said = (
        f" beyond the noise band of a ratio of medians, {floor[0]:.2f}–{floor[1]:.2f} (twice how far timing alone "
        "moved that ratio on Figure 1's run),"
        if floor
        else ""
    )
    return (  # reader r39f, items 2 and 8; reader r40f, item 5: the means that part from the medians in one parenthesis
        "**Against the lazy PRM, the lazy-PRM network "
        f"{VERDICTS[answer]}.** By the ratio of the two modes' median times (the `strong` section's "
        f"medians table), it took {told(groups['strong'])}{means_beside(tables)}.{costs_far(groups, floor)}"
        f"{means_apart(tables)}"
        "\n\n    The paper-recipe network is no test of the method against the lazy PRM: its planner with prediction "
        "is Algorithm 1, so planner and "
        f"prediction both change. It saved time{floor_said} in {len(beyond) or 'none'} of "
        f"{sum(map(len, groups['paper'].values()))}{named}.\n"
    )


def parted(tables: Tables) -> list[tuple[str, str, str, float, float]]:
    """The lazy-PRM network's cells that save time by means (its Table 3) but not by the ratio of medians:
    ``[("2DS", "2ds", "OB", 0.26, 1.00)]``."""
    medians = recorded.median_ratios("strong", tables)
    return [
        (NAMES.get(s, s), s, sampler, 1 - saved, medians[s]["total"][sampler])
        for s in recorded.table("strong", "time improvement", tables)
        for sampler, saved in recorded.improvements("strong", s, recorded=tables).items()
        if change(1 - saved) == "less time" and change(medians[s]["total"][sampler]) != "less time"
    ]


def means_beside(tables: Tables) -> str:
    """Reader r54f, item 2: beside the lazy-PRM bullet's medians, the cells whose ratio of means lies beyond its
    noise band on the saving side, each with its saving: ``"; by its ratio of means 2DS OB took 74 % less time,
    from a few long queries"``; empty where there are none."""
    cells = parted(tables)
    if not cells:
        return ""
    band = noise(tables).means
    savings = [
        f"{name} {sampler} took {round((1 - r) * 100)} % less time"
        for name, _, sampler, r, _ in cells
        if r < 1 and not costs.inside(r, band)
    ]
    if not savings:
        return ""
    return f"; by its ratio of means {' and '.join(savings)}, from a few long queries"


def means_apart(tables: Tables) -> str:
    """Reader r40f, item 5; reader r50f, item 3: the lazy-PRM network's cells that save time by means (its Table 3) but
    not by the ratio of medians, each said plainly beside the noise band of a ratio of means, and why the medians are
    the statistic read; empty where there are none."""
    cells = parted(tables)
    if not cells:
        return ""
    band = noise(tables).means
    times = next(t for heading, t in tables["strong"].items() if "Times behind Table 3" in heading)
    column = times["columns"].index("total without")
    spread = {
        (row[0], row[1]): [float(v) for v in row[column].split("/")[0].replace("*", "").split("±")]
        for row in times["rows"]
    }
    said = []
    for name, scenario, sampler, ratio, median in cells:
        clear = "beyond" if not costs.inside(ratio, band) else "inside"
        mean, std = spread[(scenario, sampler)]
        said.append(  # reader r52f, smaller items: the rule first, then the means that read otherwise
            " The medians decide it, by the page's one rule (“Which statistic decides”, under Figure 1): each query's "
            "own ratio, or, where a run kept none, as here, the ratio of medians, because the verdict asks what a "
            f"typical query costs. By medians {name} {sampler} took {change(median)} ({median:.2f}). By means it reads "
            f"otherwise: its ratio of means is {ratio:.2f} (the `strong` section's Table 3), {clear} the noise band of "
            f"a ratio of means, {band[0]:.2f}–{band[1]:.2f}"
            + (
                ", but that saving lies in a few long queries"
                if clear == "beyond"
                else "; its saving lies in a few long queries"
            )
            + f" (without prediction its mean query took {mean:.3g} s, with a standard deviation of {std:.2g} s)."
        )
    return "".join(said)


def algorithm_1(tables: Tables) -> str:
    """The paper-recipe network against the paper's Algorithm 1, Table 3's means counted (the page's section on the
    `paper` preset points here rather than count again)."""
    ours = {
        s: recorded.improvements("paper", s, recorded=tables)
        for s in recorded.table("paper", "time improvement", tables)
    }
    verdicts = [change(1 - saved) for row in ours.values() for saved in row.values()]
    papers = [
        recorded.ours(cell.split("/")[-1])
        for row in recorded.table("paper", "time improvement", tables).values()
        for column, cell in row.items()
        if column.startswith("Total")
    ]
    return (
        "**Against the paper's Algorithm 1, the paper-recipe network "
        f"{'saves time in some cells, but not by the method' if 'less time' in verdicts else 'saves no time'}"
        ".** By means (the paper-recipe run's Table 3), the paper-recipe network saved 10 % or more of a query's "
        f"time in {verdicts.count('less time')} of {len(verdicts)} cells, "
        f"lost 10 % or more in {verdicts.count('more time')} and tied in {verdicts.count('about the same time')} "
        f"(the paper: savings of up to {percent(max(papers))} %){beyond_floor(ours, tables)}. With the MLP above, "
        "those savings are not the "
        "method working (below: “Savings against Algorithm 1 that are not the method”)."
    )


def beyond_floor(ours: dict[str, dict[str, float]], tables: Tables) -> str:
    """Reader r33f, contradiction 3: which of :func:`algorithm_1`'s savings and losses lie beyond the ratio-of-means
    floor, the reach timing alone gave a ratio of means (:func:`tools.results_noise.noise`); empty without the run
    timed twice."""
    if recorded.ALGORITHM_1 not in tables:
        return ""
    low, high = noise(tables).means
    ratios = {f"{NAMES.get(s, s)} {sampler}": 1 - saved for s, row in ours.items() for sampler, saved in row.items()}
    saves = {cell: r for cell, r in ratios.items() if change(r) == "less time"}
    beyond = {cell: r for cell, r in saves.items() if not costs.inside(r, (low, high))}
    lost = {cell: r for cell, r in ratios.items() if change(r) == "more time"}
    far = {cell: r for cell, r in lost.items() if not costs.inside(r, (low, high))}

    def some(found: dict[str, float], of: dict[str, float], what: str) -> str:  # reader r44f, item 1: zero in words
        named = f" ({', '.join(f'{cell} {r:.2f}' for cell, r in found.items())})" if found else ""
        if not found:
            return f"none of the {len(of)} {what}"
        return f"{'all' if len(found) == len(of) else len(found)} of the {len(of)} {what}{named}"

    return (
        f"; beyond the noise band of a ratio of means ({low:.2f}–{high:.2f}), {some(beyond, saves, 'savings')} and "
        f"{some(far, lost, 'losses')}"
    )


def stage_shares(tables: Tables, preset: str) -> tuple[list[float], list[float]]:
    """A run's times behind Table 3 (means, a row per scenario and sampler): per cell the sampling stage's share of a
    query without prediction, and the sampling time prediction saved as a share of that query's time (negative where
    sampling grew)."""
    times = next(t for heading, t in tables[preset].items() if "Times behind Table 3" in heading)
    columns = times["columns"]

    def mean(row: list[str], column: str) -> float:
        return recorded.ours(row[columns.index(column)].split("/")[0].replace("*", ""))

    shares, saved = [], []
    for row in times["rows"]:
        total = mean(row, "total without")
        shares.append(mean(row, "sampling without") / total)
        saved.append((mean(row, "sampling without") - mean(row, "sampling with")) / total)
    return shares, saved


def network_costs(tables: Tables, preset: str = recorded.ALGORITHM_1) -> dict[str, float]:
    """The network's cost per configuration over the exact check's in the run ``preset`` (by default the `strong`
    network inside Algorithm 1 with our compiled checker; the inverse of its throughput table's "learned / exact"):
    ``{scenario: cost}``."""
    rates = recorded.table(preset, "Checker throughput", tables)
    return {s: 1 / recorded.ours(row["learned / exact"]) for s, row in rates.items()}


def fcl_slower(tables: Tables) -> str:
    """How many times slower python-fcl answered a 3D configuration than the compiled checker, in the throughput table
    of the run inside Algorithm 1 (the python-fcl run's is a copy of it), as a span: "42–79" (reader r34f, c. 4)."""
    rates = recorded.table(recorded.ALGORITHM_1, "Checker throughput", tables)

    def rate(row: dict[str, str], column: str) -> float:
        return float(row[column].replace(",", ""))

    slower = [rate(row, "exact cfg/s") / rate(row, "FCL cfg/s") for s, row in rates.items() if s != "2ds"]
    return span(slower, lambda x: f"{x:.2g}")


class Causes(NamedTuple):
    """The two causes of the verdict, by means (reader r37f, contradiction 1): with our compiled checker the cells
    whose sampling got 10 % or more slower, of how many; with python-fcl the largest share of a query sampling took,
    and the largest share of a query that shortening it saved."""

    slower: int
    cells: int
    share: float
    saved: float
    grew: float  # with our compiled checker, the sampling time prediction saved, least (most grown), as a share


def causes(tables: Tables) -> Causes:
    """:class:`Causes`, read from the two runs inside Algorithm 1."""
    means = counted(
        [
            change(1 - s)
            for scenario in recorded.table(recorded.ALGORITHM_1, "time improvement", tables)
            for s in recorded.improvements(recorded.ALGORITHM_1, scenario, "sampling", recorded=tables).values()
        ]
    )
    shares, saved = stage_shares(tables, checker_scope.SLOW)
    return Causes(means[2], sum(means), max(shares), max(saved), min(stage_shares(tables, recorded.ALGORITHM_1)[1]))


def why_no_saving(tables: Tables) -> str:
    """The arithmetic behind the verdict (review r27f, item 7), as two causes, one per checker (reader r37f, item 2):
    with a fast checker the network costs more than the check it replaces, so sampling gets slower; with a slow one
    the sampling it shortens is a small share of the query. Every number from the two runs inside Algorithm 1."""
    dearer = network_costs(tables)
    cost_3d = [c for s, c in dearer.items() if s != "2ds"]
    cost_2d = f" ({dearer['2ds']:.2g} in {NAMES['2ds']})" if "2ds" in dearer else ""
    why = causes(tables)
    band = costs.floors(tables)["own"]
    cleared = [
        (f"{s} {sampler}", m)
        for s, by in own_intervals(tables, checker_scope.SLOW).items()
        for sampler, (m, _, _) in by.items()
        if change(m) == "less time" and not costs.inside(m, band)
    ]
    return (  # reader r39f, item 9: the finding and its numbers; reader r51f, item 3: a bullet a checker
        "**Why, in the runs of 5 December: with a fast checker the network was the dearer check.** With our compiled "
        f"checker the network cost {span(cost_3d, lambda c: f'{c:.2g}')} times an exact check per configuration in "
        f"3D{cost_2d}, so sampling got 10 % or more slower in {why.slower} of {why.cells} cells."
        f"{cost_exception(tables)}"
        f"{smaller_said(tables)}"
        "\n- **With a slow "
        f"checker, sampling was a small share of a query, which caps the saving that skipping its checks explains"
        f"{exceptions(tables, cleared)}.** python-fcl answered "
        f"{fcl_slower(tables)} times slower than our compiled checker in 3D, yet {worked_example(tables)}"
        f"{cleared_said(tables, cleared)}{share_allows(tables, cleared)}"
    )


def dear_savings(tables: Tables, preset: str = recorded.ALGORITHM_1) -> dict[str, float]:
    """Reader r56f, item 2: the cells whose sampling took 10 % less time or more although ``preset``'s network was the
    dearer check in their scenario, ``{"2DS BT": 0.81}``, the exceptions to the cost argument."""
    dear = [s for s, c in network_costs(tables, preset).items() if c >= 1 + verdicts.CLOSE]
    return {
        f"{NAMES.get(s, s)} {sampler}": 1 - saved
        for s in dear
        for sampler, saved in recorded.improvements(preset, s, "sampling", recorded=tables).items()
        if change(1 - saved) == "less time"
    }


def cost_exception(tables: Tables) -> str:
    """Reader r56f, item 2: after the cost argument of the runs of 5 December, the cells it does not explain named
    (their sampling took less time with a dearer network), with the paper-recipe network's run where that saved there
    too; empty where there are none."""
    strong, paper = dear_savings(tables), dear_savings(tables, "paper")
    if not strong:
        return ""
    said = " and ".join(
        f"{cell}'s sampling, {round((1 - r) * 100)} % less time"
        + (
            f" (with the paper-recipe network of 2 December, {round((1 - paper[cell]) * 100)} % less)"
            if cell in paper
            else ""
        )
        for cell, r in strong.items()
    )
    many = len(strong) > 1
    return (
        f" {said}, {'are the exceptions' if many else 'is the exception'}: the network was the dearer check there "
        f"too, so the network's cost does not explain {'them' if many else 'it'}."
    )


def exceptions(tables: Tables, cleared: list[tuple[str, float]]) -> str:
    """Reader r54f, item 2: the cells beyond the noise band of their own ratio that saved mostly by something else
    than sampling (:func:`elsewhere`), named in the bold claim (reader r55f, item 5: no parenthesis; what moved them,
    the rest of the query or timing, is the fold's)."""
    other = elsewhere(tables, cleared) if cleared else []
    if not other:
        return ""
    cells, band = sampled(tables), noise(tables).means
    return "".join(  # reader r59f, item 1: the exception read in place, by means against that statistic's band
        f"; {cell}'s whole query saved more, {percent(cells[cell].total)} % by means, "
        f"{'inside' if costs.inside(1 - cells[cell].total, band) else 'beyond'} the noise band of a ratio of means"
        for cell in other
    )


def smaller_said(tables: Tables) -> str:
    """Reader r51f, item 1: a saving turns on the network's cost, which depends on the network: the `paper` preset's
    smaller network's cost per configuration in 3D, in its own run, where it is cheaper than an exact check; empty
    where it is not."""
    cheaper = [c for s, c in network_costs(tables, "paper").items() if s != "2ds"]
    if not cheaper or max(cheaper) >= 1:
        return ""
    return (
        " Whether sampling gets cheaper turns on what the network costs, and that depends on the network: the "
        f"smaller paper-recipe network cost {span(cheaper, lambda c: f'{c:.2g}')} times an exact check in 3D (in its "
        "run of 2 December, against that day's slower compiled checker), but it is not accurate (the MLP's finding, "
        "below)."
    )


def cleared_said(tables: Tables, cleared: list[tuple[str, float]]) -> str:
    """Reader r50f, item 1 (moved from the answer): python-fcl's cells beyond the noise band of their own ratio
    (``cleared``), that band said to be borrowed where the run was not timed twice, those mostly from sampling told so
    (:func:`from_sampling`; :func:`share_allows` tells the others); empty where there are none."""
    if not cleared:
        return ""
    faster = sum(
        change(m) == "less time"
        for _, by in own_intervals(tables, checker_scope.SLOW).items()
        for m, _, _ in by.values()
    )
    borrowed = not any("timed twice" in heading for heading in tables[checker_scope.SLOW])
    mostly = from_sampling(tables, cleared)  # the others, mostly not from sampling, are told next (share_allows)
    ordered = sorted(cleared, key=lambda c: c[0] not in mostly)  # sampling's saving first
    how = dict.fromkeys(mostly, ", mostly from sampling")
    named = ", and ".join(f"{cell} {m:.2f}{how.get(cell, '')}" for cell, m in ordered)
    band = ", a band that run borrows from the compiled one (it was not timed twice)" if borrowed else ""
    return (
        f" Of python-fcl's {faster} cells faster, {len(cleared)} lie beyond the noise band of their own ratio{band}: "
        f"{named}."
    )


def paper_sampling(tables: Tables) -> str:
    """Reader r40f, contradiction 4: the paper-recipe network's run of 2 December lost sampling time although its
    network was no dearer per check in 3D; one sentence on why (a network that answers "invalid" to every sample of a
    scenario keeps no sample in its round); empty where that network was dearer somewhere in 3D or answers so
    nowhere."""
    named = {NAMES.get(s, s): c for s, c in network_costs(tables, "paper").items() if s != "2ds"}
    costs_ = list(named.values())
    ratios = [
        (NAMES.get(scenario, scenario), sampler, 1 - saved)
        for scenario in recorded.table("paper", "time improvement", tables)
        for sampler, saved in recorded.improvements("paper", scenario, "sampling", recorded=tables).items()
    ]
    slower = counted([change(r) for _, _, r in ratios])
    invalid = [
        NAMES.get(s, s)
        for s, row in recorded.table("paper", "MLP accuracy", tables).items()
        if recorded.ours(row["Unseen TPR"]) == 0
    ]
    if max(costs_) > 1 + findings.TIE or not invalid:
        return ""
    # reader r41f, contradiction 2: the throughput table's 25 % band, so a cost inside it is no "cheaper"
    # reader r44f, item 10: each cost ratio named by its scenario
    close = [f"{s} {c:.2g}" for s, c in named.items() if abs(c - 1) < verdicts.CLOSE]
    cheaper = [f"{s} {c:.2g}" for s, c in named.items() if c <= 1 - verdicts.CLOSE]
    said = [f"{' and '.join(close)} too close to tell"] * bool(close) + [f"{' and '.join(cheaper)} cheaper"] * bool(
        cheaper
    )
    lost = [(name, sampler, r) for name, sampler, r in ratios if change(r) == "more time"]
    # reader r45f, item 3: where the network was the dearer check (2DS), that explains the losses, as for `strong`
    dear = {
        NAMES.get(s, s): c
        for s, c in network_costs(tables, "paper").items()
        if c >= 1 + verdicts.CLOSE and any(name == NAMES.get(s, s) for name, _, _ in lost)
    }
    by_cost = [name for name, _, _ in lost if name in dear]
    by_rounds = [name for name, _, _ in lost if name in invalid]
    others = [f"{name} {sampler} {r:.2f}" for name, sampler, r in lost if name not in invalid and name not in dear]
    dearer = "".join(
        f" In {name} its network was {c:.2g} times as dear as an exact check per configuration: that explains its "
        f"{len(by_cost)} {'loss' if len(by_cost) == 1 else 'losses'} in {name}, as for the strong network"
        + "".join(
            f". {cell}'s sampling, which took {round((1 - r) * 100)} % less time, is the exception with both networks"
            for cell, r in dear_savings(tables, "paper").items()
            if cell.startswith(name + " ") and cell in dear_savings(tables)
        )
        + "."
        for name, c in dear.items()
    )
    read = (  # reader r54f, item 2: in plain view, which of the losses each reading explains, and which none does
        [f"{len(by_cost)} in {' and '.join(dear)} by the network's cost"] * bool(by_cost)
        + [f"{len(by_rounds)} in {' and '.join(invalid)} where it rejects every sample"] * bool(by_rounds)
        + [f"{', '.join(others)} unexplained"] * bool(others)
    )
    left = (
        f" {'The last loss' if len(others) == 1 else f'The last {len(others)} losses'}, {', '.join(others)}, "
        "none of this explains."
        if others
        else ""
    )
    # reader r43f, contradictions 5 and 6: what ends the rounds, and which of the losses that explains
    return (
        f"**Why the paper-recipe network's run of 2 December lost sampling time in {slower[2]} of {sum(slower)} cells: "
        f"{', '.join(read)}.**"
        f"{dearer} In "
        f"3D its network was no dearer than an exact check (cost per configuration: {', '.join(said)}). There it "
        f"answers “invalid” to every {' and '.join(invalid)} sample, so its first round of sampling keeps no sample. "
        "A query whose straight edge from start to goal is blocked then samples again, in rounds that Algorithm 1's "
        f"auxiliary sampler checks exactly, as without prediction. That is our reading of those scenarios' "
        f"{len(by_rounds)} losses.{unexplained(ratios, invalid)}{left}"
    )


def unexplained(ratios: list[tuple[str, str, float]], invalid: list[str]) -> str:
    """Reader r50f, contradiction 4: the cells of the scenarios where the paper-recipe MLP answers "invalid" to every
    sample that did not lose sampling time, which the reading by rounds leaves out (``ratios``: ``(scenario, sampler,
    sampling ratio of means)``); empty where there are none."""
    kept = [(n, sampler, r) for n, sampler, r in ratios if n in invalid and change(r) != "more time"]
    if not kept:
        return ""
    cells = "; ".join(
        f"{n} {sampler} {r:.2f}, {'a saving' if change(r) == 'less time' else 'a tie'}" for n, sampler, r in kept
    )
    return (
        f" It leaves out {'the cell' if len(kept) == 1 else f'the {len(kept)} cells'} of those scenarios that lost no "
        f"sampling time, where the same network answers “invalid” too: {cells}."
    )


def share_table(tables: Tables) -> str:
    """Reader r36f, item 4: the sampling stage's share of a mean query without prediction, and the sampling time
    prediction saved as a share of that query (negative: it grew), a row per checker, the 16 cells' range in each."""
    rows = []
    for name, preset in (
        ("our compiled checker", recorded.ALGORITHM_1),
        ("python-fcl on both sides", checker_scope.SLOW),
    ):
        shares, saved = stage_shares(tables, preset)
        top = max(range(len(shares)), key=shares.__getitem__)
        times = next(t for heading, t in tables[preset].items() if "Times behind Table 3" in heading)
        where = f"{NAMES.get(times['rows'][top][0], times['rows'][top][0])} {times['rows'][top][1]}"
        rows.append(f"    | {name} | {between(shares)} (the most: {where}) | {between(saved)} |")
    return (
        "    | 16 cells, mean times | sampling's share of a query without prediction | sampling time prediction "
        "saved, as a share of that query (below 0: it grew) |\n    | --- | --- | --- |\n" + "\n".join(rows)
    )


def between(shares: list[float]) -> str:
    """``"−18 % to 1.4 %"``: the range of ``shares`` in percent, two figures, a minus sign where one is negative; each
    end its unit, so a share under 1 % does not read as a fraction of a query (reader r42f, contradiction 6)."""
    low, high = (f"{f * 100:.2g}".replace("-", "−") for f in (min(shares), max(shares)))
    return f"{low} % to {high} %"


def worked_example(tables: Tables) -> str:
    """Reader r44f, item 6: the arithmetic once (share × cut), in the cell of the run with python-fcl where sampling
    saved the largest share of a query: its share, the cut in sampling time, their product, and the whole query's
    saving as Table 3 measured it; the largest share named too where it is another cell's. A clause of
    :func:`why_no_saving`."""
    slow, saved = stage_shares(tables, checker_scope.SLOW)
    times = next(t for heading, t in tables[checker_scope.SLOW].items() if "Times behind Table 3" in heading)

    def name(k: int) -> str:
        return f"{NAMES.get(times['rows'][k][0], times['rows'][k][0])} {times['rows'][k][1]}"

    top = max(range(len(saved)), key=saved.__getitem__)
    most = max(range(len(slow)), key=slow.__getitem__)
    total = recorded.improvements(checker_scope.SLOW, times["rows"][top][0], recorded=tables)[times["rows"][top][1]]
    papers = IMPROVEMENT[times["rows"][top][0]]["total"][times["rows"][top][1]]  # reader r49f, item 5: the paper's
    cut = saved[top] / slow[top]  # reader r36f, contradiction 1: unrounded, so the product is the share saved
    share = f"sampling took at most {percent(slow[most])} % of a mean query ({name(most)})"
    there = (
        f"In {name(most)}"
        if top == most
        else f"In {name(top)}, where shortening it saved the most, it took {slow[top]:.1%}"
    )
    return (
        f"{share}. {there} the network cut sampling by {cut * 100:.1f} %, so prediction saved "
        f"{slow[top] * 100:.1f} % × {cut:.3f} ≈ {slow[top] * cut * 100:.0f} % of the query, the most that skipping "
        f"sampling's checks saved in any cell (our python-fcl Table 3 measured {percent(total)} % for the whole "
        f"query; the paper's Table 3, {str(round(papers * 100)).replace('-', '−')} %)."
    )


class Sampled(NamedTuple):
    """A cell's mean times behind Table 3, each as a share of a mean query without prediction."""

    share: float  # the sampling stage's share of that query
    saved: float  # the sampling time prediction saved (negative: it grew)
    total: float  # the whole query's saving, Table 3's (negative: a loss)


def sampled(tables: Tables, preset: str = checker_scope.SLOW) -> dict[str, Sampled]:
    """:class:`Sampled` of every cell of the run ``preset``: ``{"3DC-9 OB": Sampled(0.106, 0.08, 0.34), ...}``."""
    shares, saved = stage_shares(tables, preset)
    times = next(t for heading, t in tables[preset].items() if "Times behind Table 3" in heading)
    found = {}
    for row, share, cut in zip(times["rows"], shares, saved):
        total = recorded.improvements(preset, row[0], recorded=tables)[row[1]]
        found[f"{NAMES.get(row[0], row[0])} {row[1]}"] = Sampled(share, cut, total)
    return found


def elsewhere(tables: Tables, cleared: list[tuple[str, float]]) -> list[str]:
    """Reader r48f, item 1: of the cells with python-fcl that saved beyond the noise band of their own ratio
    (``cleared``: ``[("3DC-9 OB", 0.79), ...]``), those where skipping sampling's checks saved less than half the
    whole query's saving, by each query's own ratio and by means alike (the smaller of the two): mostly not from
    sampling."""
    cells = sampled(tables)
    return [cell for cell, m in cleared if cells[cell].saved < min(1 - m, cells[cell].total) / 2]


def from_sampling(tables: Tables, cleared: list[tuple[str, float]]) -> list[str]:
    """Reader r49f, contradiction 1: of ``cleared`` (as :func:`elsewhere`), the cells where skipping sampling's
    checks saved at least half the whole query's saving, by each query's own ratio and by means alike (the larger of
    the two): mostly from sampling (3DO BT: 16 % of a query, against 28 % and 17 %)."""
    cells = sampled(tables)
    return [cell for cell, m in cleared if cells[cell].saved >= max(1 - m, cells[cell].total) / 2]


def share_allows(tables: Tables, cleared: list[tuple[str, float]]) -> str:
    """Reader r47f, contradiction 1; reader r48f, items 1 and 5: after the worked example (:func:`worked_example`),
    the cells beyond the noise band of their own ratio (``cleared``) set beside what skipping sampling's checks saved
    there: where the whole query saved about what sampling did, and where it saved mostly by something else (the
    rest of the query, or timing), each number a share of the cell's mean query."""
    if not cleared:
        return ""
    cells = sampled(tables)
    other = elsewhere(tables, cleared)
    top = max(cells, key=lambda cell: cells[cell].saved)  # the worked example's cell, its whole query said there
    alike = [cell for cell, _ in cleared if cell not in other and cell != top]
    said = "".join(
        f" By means, {cell}'s whole query saved {percent(cells[cell].total)} %, what skipping sampling's checks "
        f"saved there ({percent(cells[cell].saved)} %)."
        for cell in alike
        if abs(cells[cell].total - cells[cell].saved) < findings.TIE
    )
    own = dict(cleared)
    said += "".join(
        f" {cell}'s saving with python-fcl is mostly not from sampling: sampling took {percent(cells[cell].share)} % "
        f"of its mean query, and skipping its checks saved {percent(cells[cell].saved)} % of that query, where the "
        f"whole query saved {percent(cells[cell].total)} % by means and {percent(1 - own[cell])} % by each query's own "
        f"ratio ({own[cell]:.2f}). The rest of the query, or timing, moved it (below, in the fold “The findings in "
        "detail”: “Where the whole query moved apart from sampling”)."
        for cell in other
    )
    return said


class Apart(NamedTuple):
    """A cell of the run with python-fcl on both sides whose whole query, by means, moved further than the sampling
    time prediction saved there could move it (review r28f, contradiction 2)."""

    name: str  # "3DC-9 OB"
    total: float  # Table 3's total improvement (negative: a loss)
    sampling: float  # the sampling time saved, as a share of a mean query without prediction


def apart(tables: Tables, preset: str = checker_scope.SLOW) -> list[Apart]:
    """The cells of the run ``preset`` (by default the one with python-fcl on both sides) whose total improvement by
    means lies 10 points or more from the sampling time saved as a share of the query (:func:`stage_shares`): the rest
    of the query, which prediction does not shorten, moved them."""
    _, saved = stage_shares(tables, preset)
    times = next(t for heading, t in tables[preset].items() if "Times behind Table 3" in heading)
    cells = [(row[0], row[1]) for row in times["rows"]]  # scenario, sampler, in the order of ``saved``
    found = []
    for (scenario, sampler), share in zip(cells, saved):
        total = recorded.improvements(preset, scenario, recorded=tables)[sampler]
        if round(abs(total - share) * 100) >= round(findings.TIE * 100):
            found.append(Apart(f"{NAMES.get(scenario, scenario)} {sampler}", total, share))
    return found


APART_BEGIN = "<!-- apart: written by `python -m tools.results_summary` from the tables below; edit it there -->"
APART_END = "<!-- end of apart -->"


def not_from_sampling(tables: Tables) -> str:
    """One sentence on :func:`apart`'s cells, each with its whole query's change beside the sampling time saved
    there, both as shares of a mean query (review r28f, item 4; r31f: which way each moved); empty where there are
    none."""
    cells, fast = apart(tables), apart(tables, recorded.ALGORITHM_1)
    shares = (  # reader r44f, item 6: the arithmetic is one finding's, once; here the 16 cells' ranges
        "- *How little shortening sampling saves*: sampling's share of a mean query, and what prediction saved of "
        f"it, in each checker's 16 cells (the finding “With a slow checker” works the largest saving through).\n\n"
        f"{share_table(tables)}\n\n"
    )
    if not cells and not fast:
        return shares.rstrip()

    def said(cell: Apart) -> str:
        moved = f"{percent(cell.total)} % saved" if cell.total >= 0 else f"{percent(-cell.total)} % longer"
        return f"{cell.name}, {moved} where sampling saved {percent(cell.sampling)} %"

    widest = max(fast, key=lambda cell: abs(cell.total - cell.sampling), default=None)
    compiled = (  # reader r38f, contradiction 1: the compiled run's cost is mostly outside sampling too
        f"{len(fast)} cells of the run with our compiled checker (the widest: {widest.name}, "
        f"{percent(abs(widest.total))} % {'saved' if widest.total >= 0 else 'longer'} where sampling "
        f"{'saved' if widest.sampling >= 0 else 'added'} {percent(abs(widest.sampling))} %) and "
        if widest
        else ""
    )
    return (  # review r30f, contradiction 4; reader r32f, item 4: in the fold, under the worked example's cell
        f"{shares}- *Where the whole query moved apart from sampling*: in {compiled}{len(cells)} cells of the run with "
        "python-fcl the whole query moved 10 points or more away from what sampling saved there "
        f"(as shares of a mean query without prediction: {'; '.join(map(said, cells))}): the rest of the query, "
        "which prediction does not shorten, moved them (with other samples the planner grows another roadmap, with "
        f"other edges to check and other repairs), or timing did.{moved_beyond(tables, fast, cells)}"
    )


def moved_beyond(tables: Tables, fast: list[Apart], slow: list[Apart]) -> str:
    """Reader r44f, item 1: of :func:`apart`'s cells (``fast``: our compiled checker's; ``slow``: python-fcl's), those
    whose ratio of means lies beyond the noise band of a ratio of means (read strictly), each named with its run, the
    rest inside it, where timing alone could have moved them that far."""
    band = noise(tables).means
    runs = (("our compiled checker", fast), ("python-fcl", slow))
    far = [(run, cell) for run, cells in runs for cell in cells if not costs.inside(1 - cell.total, band)]
    every = len(fast) + len(slow)
    named = "; ".join(
        f"{run}: {', '.join(f'{cell.name} {1 - cell.total:.2f}' for r, cell in far if r == run)}"
        for run, _ in runs
        if any(r == run for r, _ in far)
    )
    if not far:
        return f" By the noise band of a ratio of means, {band[0]:.2f}–{band[1]:.2f}, all {every} lie inside it."
    return (
        f" By the noise band of a ratio of means, {band[0]:.2f}–{band[1]:.2f}, {len(far)} of these {every} ratios lie "
        f"beyond it ({named})" + (", the rest inside it." if len(far) < every else ".")
    )


def summary(tables: Tables, table_3: str = "") -> str:
    """The findings ("What reproduces and what does not"), without their markers: why the summary's verdict comes out
    as it does (:func:`why_no_saving`), the paper's networks (Tables 1 and 2, with :func:`unseen_table`), and the
    answers against the lazy PRM and against Algorithm 1 with the paper-recipe network; no count the summary gives
    is said again (review r27f, item 2)."""
    items = [  # reader r54f, item 3: what reproduces first, then why
        *(table_3.split("\n- ") if table_3 else []),  # reader r47f, item 1: the counts by means, moved from the answer
        cae(tables),
        mlp(tables),
        algorithm_1(tables),  # reader r54f, item 3: the lazy PRM's finding under its own heading (:func:`lazy_said`)
        *why_no_saving(tables).split("\n- "),
        *([paper_why] if (paper_why := paper_sampling(tables)) else []),  # reader r48f, item 4: its own bullet
    ]
    cut = [brief(item) for item in items]  # reader r53f, item 4: a bold claim and one sentence; the rest folded
    table = "\n".join(f"    {line}" if line else "" for line in unseen_table(tables).splitlines())
    shown = [f"- {said}" + (f"\n\n{table}\n" if said.startswith("**The MLP") else "") for said, _, _ in cut]
    folded = "\n".join(  # an item of two paragraphs ends with a blank line, so the next is an item too
        f"- *{named(claim)}*: {rest}" + ("\n" if "\n\n" in rest else "") for _, claim, rest in cut if rest
    )
    return "\n".join(shown) + f"\n\n{HOW_READ}\n\n{folded}\n\n</details>"


HOW_READ = '<details markdown="1"><summary>How each finding was read: the arithmetic and the mechanisms</summary>'
LAZY_BEGIN = "<!-- the lazy PRM: written by `python -m tools.results_summary` from the tables below; edit it there -->"
LAZY_END = "<!-- end of the lazy PRM -->"
LAZY_HEADING = "### Against the lazy PRM, a second baseline"


def lazy_said(tables: Tables) -> str:
    """Reader r54f, item 3: the lazy-PRM finding under its own small heading, apart from the findings against the
    paper's Algorithm 1 (another baseline, another network, another run): its bold claim and first sentence, the
    rest folded under it."""
    shown, _, rest = brief(lazy_prm(tables).rstrip("\n"))
    folded = rest.replace("\n\n    ", "\n\n")  # no longer inside a list item
    return (
        f"\n{LAZY_HEADING}\n\n- {shown}\n\n"
        '<details markdown="1"><summary>How this finding was read</summary>\n\n'
        f"{folded}\n\n</details>"
    )


def named(claim: str) -> str:
    """A finding's name in the fold under the findings: its bold claim up to a colon, or, if longer than 60
    characters, up to its first comma: ``"Against the lazy PRM"``."""
    name = claim.partition(":")[0]
    for start, other in FOLD_NAMES.items():  # reader r57f, item 3: no fold paragraph repeats a bold heading
        if name.startswith(start):
            return other
    return name.partition(",")[0] if len(name) > 60 else name


FOLD_NAMES = {  # a finding whose fold opens on another claim than its bold heading's, named for what the fold says
    "Why the paper-recipe network's run of 2 December": (
        "The run of 2 December, cell by cell: 2DS BT, then the 3D losses"
    ),
}


def brief(item: str) -> tuple[str, str, str]:
    """Reader r53f, item 4: a finding cut after its bold claim and the first sentence that follows it: ``(shown, claim,
    rest)``, ``claim`` the bold words without their full stop, ``rest`` what the fold under the findings says."""
    head, _, body = item.partition(".** ")
    first, stop, rest = body.partition(". ")
    if not stop:
        return item, head.removeprefix("**"), ""
    return f"{head}.** {first}.", head.removeprefix("**"), rest.strip()
