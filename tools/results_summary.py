"""The summary at the top of ``docs/results.md``: its sentences written here, every number in them computed from the
tables the page prints (read as :mod:`tools.recorded_results` reads them)::

    python -m tools.results_summary        # after editing docs/results.md's tables

It rewrites the lines between :data:`BEGIN` and :data:`END` in ``docs/results.md``; ``tests/test_results_page.py``
fails while they differ from what the tables give, so a new run's tables cannot leave an old summary behind.
Time ratios are read with the page's rule (chapter 04's): a change under 10 % is a tie.
"""

from __future__ import annotations

import sys

from toolkit.teaching import recorded
from toolkit.teaching.recorded import Tables
from tools.recorded_results import RESULTS, parse

BEGIN = "<!-- summary: written by `python -m tools.results_summary` from the tables below; edit it there -->"
END = "<!-- end of the summary -->"
TIE = 0.10  # a change of the time under 10 % is a tie
NAMES = {"2ds": "2DS", "3dc7": "3DC-7", "3dc9": "3DC-9", "3do": "3DO"}


def percent(fraction: float) -> str:
    """``0.855`` as ``"86"``: a fraction in whole percent, as the tables write them."""
    return f"{round(fraction * 100)}"


def span(values: list[float], show=percent) -> str:
    """``"86–97"``: the range of ``values`` as ``show`` writes them; one figure where they agree."""
    low, high = show(min(values)), show(max(values))
    return low if low == high else f"{low}–{high}"


def change(ratio: float) -> str:
    """A time ratio with / without read with the tie rule: ``"more time"``, ``"about the same time"`` or
    ``"less time"``."""
    saved = round(1 - ratio, 6)
    return "less time" if saved >= TIE else "more time" if saved <= -TIE else "about the same time"


def grouped(ratios: dict[str, dict[str, float]]) -> dict[str, list[tuple[str, float]]]:
    """The scenario-sampler cells of ``{scenario: {sampler: ratio}}`` by :func:`change`: ``[(name, ratio), ...]``."""
    groups: dict[str, list[tuple[str, float]]] = {"more time": [], "about the same time": [], "less time": []}
    for scenario, row in ratios.items():
        for sampler, ratio in row.items():
            groups[change(ratio)].append((f"{NAMES.get(scenario, scenario)} {sampler}", ratio))
    return groups


def told(groups: dict[str, list[tuple[str, float]]]) -> str:
    """``"more time in 14 of 16 scenario–sampler cells (1.37–2.58 times as much) and about the same time in 2 (2DS BS
    1.07, 2DS OB 1.00)"``: the largest group first; a group of up to three cells named with its ratios, a larger one
    as the range of its ratios."""
    total = sum(map(len, groups.values()))
    parts: list[str] = []
    for word, cells in sorted(groups.items(), key=lambda group: -len(group[1])):  # the largest group first
        if not cells:
            continue
        ratios = [r for _, r in cells]
        count = f"{len(cells)} of {total} scenario–sampler cells" if not parts else f"{len(cells)}"
        if len(cells) <= 3:
            parts.append(f"{word} in {count} ({', '.join(f'{name} {r:.2f}' for name, r in cells)})")
        else:
            parts.append(f"{word} in {count} ({span(ratios, lambda r: f'{r:.2f}')} times as much)")
    return ", ".join(parts[:-1]) + (" and " if len(parts) > 1 else "") + parts[-1]


def cae(tables: Tables) -> str:
    rows = recorded.table("paper", "CAE reconstruction", tables)
    ours = [recorded.ours(row["Unseen"]) for row in rows.values()]
    papers = [recorded.ours(row["Unseen"].split("/")[-1]) for row in rows.values()]
    free = [recorded.ours(row["all free: Seen / Unseen"].split("/")[-1]) for row in rows.values()]
    gain = max(o - f for o, f in zip(ours, free))
    than_free = (
        "no better, scenario by scenario, than a CAE that answers “free” everywhere"
        if round(gain * 100) <= 0
        else f"at most {percent(gain)} points better than a CAE that answers “free” everywhere"
    )
    return (
        f"**The CAE (Table 1).** The `paper` CAE reconstructs unseen workspaces at {span(ours)} % of their cells "
        f"(the paper: {span(papers)} %), {than_free} ({span(free)} %)."
    )


def mlp(tables: Tables) -> str:
    def balanced(preset: str) -> list[float]:
        return [
            recorded.ours(row["Balanced unseen Acc"]) for row in recorded.table(preset, "MLP accuracy", tables).values()
        ]

    rows = recorded.table("paper", "MLP accuracy", tables)
    one_answer = [
        NAMES.get(name, name)
        for name, row in rows.items()
        if min(recorded.ours(row["Unseen TPR"]), recorded.ours(row["Unseen TNR"])) == 0
    ]
    listed = ", ".join(one_answer[:-1]) + " and " * (len(one_answer) > 1) + "".join(one_answer[-1:])
    trivial = (
        f" In {listed} the `paper` MLP gives one answer to every sample (a TPR or TNR of 0 %)." if one_answer else ""
    )
    return (
        f"**The MLP (Table 2).** On unseen workspaces, half their samples valid, the `paper` MLP is right "
        f"{span(balanced('paper'))} % of the time, where a coin flip is right 50 %; the `strong` MLP "
        f"{span(balanced('strong'))} %.{trivial}"
    )


def lazy_prm(tables: Tables) -> str:
    groups = {
        preset: grouped({s: kinds["total"] for s, kinds in recorded.median_ratios(preset, tables).items()})
        for preset in ("strong", "paper")
    }
    saved = sum(len(g["less time"]) for g in groups.values())
    cells = sum(len(cells) for g in groups.values() for cells in g.values())
    answer = "No" if saved == 0 else "Rarely" if saved < cells / 2 else "Mostly"
    return (
        f"**Does prediction save planning time against the lazy PRM, the fastest exact planner a network can "
        f"drive?** {answer}. In the medians tables (a query's time with prediction over its time without), the "
        f"`strong` network's median query took {told(groups['strong'])}; the `paper` network's, "
        f"{told(groups['paper'])}."
    )


def algorithm_1(tables: Tables) -> str:
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
        "**Against the paper's Algorithm 1** (the `paper` section's Table 3, of means) the `paper` network "
        f"saved 10 % or more of a query's time in {verdicts.count('less time')} of {len(verdicts)} cells, "
        f"lost 10 % or more in {verdicts.count('more time')} and tied in {verdicts.count('about the same time')} "
        f"(the paper: savings of up to {percent(max(papers))} %). With the MLP above, those savings are not the "
        "method working: the first part of this page says why."
    )


def summary(tables: Tables) -> str:
    """The summary's Markdown, without its markers."""
    items = [
        "**What was measured**: full-size runs of `toolkit reproduce` that set our figures beside the paper's "
        "Tables 1–3, for two recipes: `paper` (the paper's settings) and `strong` (ours).",
        cae(tables),
        mlp(tables),
        lazy_prm(tables),
        algorithm_1(tables),
        "**Where the details are**: the first table below says when each run was measured (today's exact "
        "checker is faster, which can only weaken prediction's case); “What reproduces and what does not” "
        "explains each finding; each preset's section holds its tables.",
    ]
    return "**In short** (every number in this list is computed from this page's tables):\n\n" + "\n".join(
        f"- {item}" for item in items
    )


def with_summary(text: str) -> str:
    """``text`` (docs/results.md) with the lines between its markers replaced by :func:`summary` of its tables."""
    head, found, rest = text.partition(BEGIN)
    _, end, tail = rest.partition(END)
    if not found or not end:
        raise ValueError(f"docs/results.md has no summary markers: a line {BEGIN!r} and, after it, {END!r}")
    return f"{head}{BEGIN}\n{summary(parse(text))}\n{END}{tail}"


def main() -> int:
    RESULTS.write_text(with_summary(RESULTS.read_text()))
    print(f"wrote the summary of {RESULTS.name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
