"""The paper's Tables 1-3 (§V) in markdown, our value beside the published one in every cell.

Each function takes runs as ``results.json`` dicts (one row per run, as the paper
has a row per scenario) and returns markdown lines. A sampler the paper did not
run (one registered from your code) shows ``n/a`` where the paper's figure would be.

Each table says what "without prediction" is in it: Table 3 compares against the run's
baseline (``results["baseline"]``, :data:`toolkit.experiments.config.BASELINES`: by default the
recipe's own planner, so the ``paper`` preset's Table 3 uses Algorithm 1 as the paper does), the
medians table always against the strongest exact planner and checker (``without``).
"""

from __future__ import annotations

import numpy as np

from toolkit import scenarios
from toolkit.experiments import paper_numbers
from toolkit.experiments.config import BASELINES
from toolkit.util import verdicts

MODES = ("without", "with")  # planning without and with prediction
BASELINE = "baseline"  # the planning mode of Table 3's baseline, where it is not "without" (the best exact)


def percent(x: float | None) -> str:
    """``0.873`` as ``87%``; n/a for a missing or non-finite value."""
    return "n/a" if x is None or not np.isfinite(x) else f"{100 * x:.0f}%"


def mean_std(pair: tuple[float, float] | None) -> str:
    return "n/a" if pair is None else f"{pair[0]:.3g} ± {pair[1]:.2g}"


def ours_paper(ours: float | None, paper: float | None) -> str:
    return f"**{percent(ours)}** / {percent(paper)}"


def table(header: list[str], rows: list[list[str]]) -> list[str]:
    """A markdown table."""
    return ["| " + " | ".join(cells) + " |" for cells in [header, ["---"] * len(header), *rows]]


def samplers_of(runs: list[dict]) -> list[str]:
    """The samplers planned in the runs, in the order of the first run."""
    return list(runs[0]["planning"])


def table_3_mode(row: dict) -> str:
    """The mode Table 3 compares "with" against in one sampler's planning ``row``: its baseline's where the run
    planned one, else ``without``."""
    return BASELINE if BASELINE in row else "without"


def baseline_note(runs: list[dict], name: str | None = None) -> str:
    """What "without prediction" is in a table: ``name`` (a key of ``BASELINES``), or each run's baseline."""
    names = {name} if name else {r.get("baseline", "best") for r in runs}
    if len(names) == 1:
        return f"*Without prediction*: {BASELINES[names.pop()]}."
    return (
        "*Without prediction*: "
        + "; ".join(f"{r['scenario']}: {BASELINES[r.get('baseline', 'best')]}" for r in runs)
        + "."
    )


def planners_note(runs: list[dict], modes: tuple[str, ...]) -> str:
    """Which planner ran in each of ``modes``, as the runs' planning summaries record it (``summary["planner"]``;
    a run cached before they did records none)."""
    ran = {
        mode: sorted({p[mode]["planner"] for r in runs for p in r["planning"].values() if "planner" in p.get(mode, {})})
        for mode in modes
    }
    named = [f"{mode}: {', '.join(names)}" for mode, names in ran.items() if names]
    return f"*Planners* (`toolkit.planning.prm`; paper is Algorithm 1): {'; '.join(named)}." if named else ""


def cae_row(run: dict) -> list[str]:
    """Table 1: reconstruction accuracy, seen and unseen, beside the share of free cells ("all free")."""
    cae, paper = run["cae"], paper_numbers.CAE.get(run["scenario"], {})
    if "seen_acc" not in cae:  # a checkpoint whose CAE was left untrained (toolkit train without --cae)
        return [run["scenario"], "not trained", "not trained", "n/a"]
    return (
        [run["scenario"]]
        + [ours_paper(cae[k], paper.get(k)) for k in ("seen_acc", "unseen_acc")]
        + [f"{percent(cae['seen_all_free'])} / {percent(cae['unseen_all_free'])}"]
    )


def mlp_row(run: dict) -> list[str]:
    """Table 2: accuracy / TPR / TNR on seen samples and on the paper's validity-blind unseen ones, then ours on
    balanced unseen samples; "always valid" beside each unseen test."""
    mlp, paper = run["mlp"], paper_numbers.MLP.get(run["scenario"], {})
    trio = ("acc", "tpr", "tnr")
    return (
        [run["scenario"]]
        + [ours_paper(mlp["seen"][m], paper.get("seen", {}).get(m)) for m in trio]
        + [ours_paper(mlp["unseen_uniform"][m], paper.get("unseen", {}).get(m)) for m in trio]
        + [percent(mlp["unseen_uniform"]["always_valid"])]
        + [f"**{percent(mlp['unseen'][m])}**" for m in trio]
        + [percent(mlp["unseen"]["always_valid"])]
    )


def improvement_row(run: dict, samplers: list[str]) -> list[str]:
    """Table 3: the time improvement ratio ``(without - with) / without``, sampling then total, per sampler."""
    paper = paper_numbers.IMPROVEMENT.get(run["scenario"], {})
    return [run["scenario"]] + [
        ours_paper(run["improvement"][k][s], paper.get(k, {}).get(s)) for k in ("sampling", "total") for s in samplers
    ]


def time_rows(run: dict, samplers: list[str]) -> list[list[str]]:
    """The times behind Table 3 (mean ± std seconds per query, ours / paper), success and path validity."""
    rows, paper = [], paper_numbers.TIMES.get(run["scenario"], {})
    for s in samplers:
        planning = run["planning"][s]
        modes = (table_3_mode(planning), "with")
        cells = [
            f"**{mean_std((planning[m][key], planning[m][key + '_std']))}** / "
            f"{mean_std(paper.get(key, {}).get(s, (None, None))[i])}"
            for key in ("sampling_s", "total_s")
            for i, m in enumerate(modes)
        ]
        rates = [" / ".join(percent(planning[m][rate]) for m in modes) for rate in ("success_rate", "path_valid_rate")]
        rows.append([run["scenario"], s] + cells + rates)
    return rows


EVERY_CELL = (
    "Every cell with two figures: **ours** / the paper's; the success and paths-valid columns hold ours only, "
    "without / with prediction."
)
TABLE_2_NOTE = (
    "*Seen*: balanced samples (half valid) in training workspaces. *Unseen*: validity-blind samples in unseen "
    "workspaces, drawn as we read the paper (§IV-A) to draw its unseen tests, "
    '"regardless of their validity", as many (2DS '
    "200, 3DO 2000, 3DC 400 each); the paper does not give their valid share (its rates imply fewer valid ones than "
    "ours: docs/fidelity.md); *always valid*: the "
    'accuracy of answering "valid" on the same samples. *Balanced unseen*: half-valid samples in the same '
    "workspaces (ours only; the paper reports none)."
)


def paper_tables(runs: list[dict]) -> list[str]:
    """Tables 1-3 of the paper and the times behind Table 3, one row per run, ours / paper in every cell."""
    samplers = samplers_of(runs)
    thresholds = ", ".join(f"{r['scenario']} {r['threshold']:.2f}" for r in runs)
    by_sampler = [f"Sampling {s}" for s in samplers] + [f"Total {s}" for s in samplers]
    return (
        ["## Table 1: CAE reconstruction accuracy", ""]
        + table(["", "Seen", "Unseen", "all free: Seen / Unseen"], [cae_row(r) for r in runs])
        + ["", '*All free*: the accuracy of a CAE that ignores its input and answers "free" everywhere.']
        + ["", "## Table 2: MLP accuracy, TPR, TNR", ""]
        + table(
            [
                "",
                "Seen Acc",
                "Seen TPR",
                "Seen TNR",
                "Unseen Acc",
                "Unseen TPR",
                "Unseen TNR",
                "Unseen always valid",
                "Balanced unseen Acc",
                "TPR",
                "TNR",
                "always valid",
            ],
            [mlp_row(r) for r in runs],
        )
        + [
            "",
            TABLE_2_NOTE,
            "",
            f"Decision threshold on P(valid): {thresholds}.",
            "",
            "## Table 3: time improvement ratio (without − with) / without",
            "",
            baseline_note(runs),
            planners_note(runs, (*MODES, BASELINE)),
            "",
        ]
        + table([""] + by_sampler, [improvement_row(r, samplers) for r in runs])
        + ["", "## Times behind Table 3 (seconds per query, mean ± std; ours / paper)", "", baseline_note(runs), ""]
        + table(
            [
                "",
                "sampler",
                "sampling without",
                "sampling with",
                "total without",
                "total with",
                "success, ours: without / with",
                "paths valid, ours: without / with",
            ],
            [row for r in runs for row in time_rows(r, samplers)],
        )
    )


def median_ratios(runs: list[dict]) -> list[str]:
    """Per sampler, the median time per query with prediction over the median without."""
    samplers = samplers_of(runs)

    def ratio(planning: dict, key: str) -> str:
        return f"{planning['with'][key + '_median'] / planning['without'][key + '_median']:.2f}"

    rows = [
        [r["scenario"]] + [ratio(r["planning"][s], key) for key in ("sampling_s", "total_s") for s in samplers]
        for r in runs
    ]
    named = {r.get("planner") for r in runs}  # --planner paper plans "without" with Algorithm 1 too, not the lazy PRM
    notes = [baseline_note(runs, "paper" if named == {"paper"} else "best"), planners_note(runs, MODES)]
    return ["## Time with / without prediction, medians over the queries", "", *notes, ""] + table(
        [""] + [f"Sampling {s}" for s in samplers] + [f"Total {s}" for s in samplers], rows
    )


def per_query(row: dict, mode: str = "with", against: str = "without") -> str:
    """``"1.03 (0.98–1.10)"``: the median of each query's own total time in ``mode`` over its time in ``against``, and
    the middle half of those ratios (:func:`toolkit.util.verdicts.per_query_ratios`, the ratios the chapters' verdicts
    read); "n/a" for a run that kept no per-query times."""
    if any("total_s_per_query" not in row[m] for m in (mode, against)):
        return "n/a"
    q1, median, q3 = np.percentile(
        verdicts.per_query_ratios({"without": row[against], "with": row[mode]}), (25, 50, 75)
    )
    return f"{median:.2f} ({q1:.2f}–{q3:.2f})"


def per_query_ratios(runs: list[dict]) -> list[str]:
    """Per sampler, the median of each query's own total time with / without prediction, with the middle half: a
    query's two times are taken in turn, under the same load, so their ratio moves less than a ratio of medians,
    which jumps where the queries' times gather in two groups."""
    samplers = samplers_of(runs)
    rows = [[r["scenario"]] + [per_query(r["planning"][s]) for s in samplers] for r in runs]
    note = "*Each query's own ratio*: total time with / without prediction, its median over the queries (middle half)."
    lines = ["## Time with / without prediction, each query's own ratio", "", note, ""] + table(
        ["", *(f"Total {s}" for s in samplers)], rows
    )
    against = [r for r in runs if all(BASELINE in r["planning"][s] for s in samplers)]
    if not against:
        return lines
    rows = [[r["scenario"]] + [per_query(r["planning"][s], against=BASELINE) for s in samplers] for r in against]
    note = "*Against Table 3's baseline*: total time with prediction / Table 3's without, each query's own ratio."
    return (
        lines
        + ["", "## Time with prediction / Table 3's baseline, each query's own ratio", "", note, ""]
        + table(["", *(f"Total {s}" for s in samplers)], rows)
    )


def timed_twice(runs: list[dict]) -> list[str]:
    """Where a run planned without prediction twice (``--planner paper --baseline paper``: "without" and Table 3's
    baseline are then one computation, Algorithm 1 with the same checker and seeds), their ratio per sampler: how far
    timing alone moves a ratio of means, of medians, and each query's own ratio."""
    rows = [
        [r["scenario"], s]
        + [f"{p[BASELINE][key] / p['without'][key]:.2f}" for key in ("total_s", "total_s_median")]
        + [per_query(p, BASELINE)]
        for r in runs
        if r.get("baseline") == "paper" and r.get("planner") == "paper"
        for s, p in r["planning"].items()
    ]
    if not rows:
        return []
    note = (
        "*Timed twice*: without prediction and Table 3's baseline are the same computation (Algorithm 1, the same "
        "exact checker, the same seeds), each query timed in turn with the other modes; total time, baseline / "
        "without."
    )
    return ["## Without prediction, timed twice", "", note, ""] + table(
        ["", "sampler", "ratio of the means", "ratio of the medians", "each query's own ratio: median (middle half)"],
        rows,
    )


def run_costs(runs: list[dict]) -> list[str]:
    """Checker throughput and the seconds each stage took, one row per run."""
    rows = []
    for r in runs:
        t, seconds = r["throughput"], r["stage_seconds"]
        planning = sum(seconds.get(f"planning_{s}", 0.0) for s in r["planning"])
        fcl = f"{t['fcl_cfg_per_s']:,.0f}" if "fcl_cfg_per_s" in t else "n/a"  # a run from before issue 25
        rows.append(
            [r["scenario"], f"{t['exact_cfg_per_s']:,.0f}", fcl, f"{t['learned_cfg_per_s']:,.0f}", f"{t['ratio']:.3g}"]
            + [f"{seconds[k]:.0f}" if k in seconds else "n/a" for k in ("data", "models")]
            + [f"{planning:.0f}"]
        )
    return [
        "## Checker throughput (configurations per second, median) and stage times (seconds)",
        "",
        "*Exact*: the fastest exact checker (`exact_checker`: compiled; numpy interval tests for the 2D point "
        "robot); *FCL*: the python-fcl reference; *learned*: the networks of the preset's sizes; the three timed in "
        "turns. Each stage's time when it was computed (a "
        "resumed run keeps them). *planning*: the samplers' runs (each query in every mode in turn) added up (by "
        "default in parallel, one process per core; `--workers`).",
        "",
    ] + table(
        ["", "exact cfg/s", "FCL cfg/s", "learned cfg/s", "learned / exact", "data s", "models s", "planning s"], rows
    )


def tables_markdown(results: dict) -> str:
    """One run's tables: the paper's Tables 1-3 with the published numbers beside ours, and its costs."""
    title = (
        f"# {scenarios.get(results['scenario']).title} — preset `{results['preset']}`"
        f"{' (quick)' if results['quick'] else ''}, seed {results['seed']}"
    )
    return _document(title, [results])


def summary_markdown(runs: list[dict]) -> str:
    """Several scenarios' tables in one: a row per scenario, as in the paper."""
    first = runs[0]
    return _document(f"# Preset `{first['preset']}`{' (quick)' if first['quick'] else ''}, seed {first['seed']}", runs)


def _document(title: str, runs: list[dict]) -> str:
    return "\n".join(
        [title, "", EVERY_CELL, ""]
        + paper_tables(runs)
        + [""]
        + median_ratios(runs)
        + [""]
        + per_query_ratios(runs)
        + [""]
        + [*timed_twice(runs), ""] * bool(timed_twice(runs))
        + run_costs(runs)
        + [""]
    )
