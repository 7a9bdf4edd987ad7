"""How the results page says its numbers: a time ratio read with chapter 04's rule (:data:`RULE`,
:func:`change`), a range of values (:func:`span`) and a count of cells by what they read as (:func:`told`).
Shared by :mod:`tools.results_summary` and the modules it draws on."""

from __future__ import annotations

from toolkit.teaching import findings

RULE = (  # chapter 04's rule for a time ratio with / without, in the page's words
    "a gain of 10 % or more, on the ratio as shown to two decimals (0.90 or less), is a saving, a loss of 10 % or "
    "more (1.10 or more) a loss, anything between a tie"
)
NAMES = {"2ds": "2DS", "3dc7": "3DC-7", "3dc9": "3DC-9", "3do": "3DO"}


def percent(fraction: float) -> str:
    """``0.855`` as ``"86"``: a fraction in whole percent, as the tables write them."""
    return f"{round(fraction * 100)}"


def span(values: list[float], show=percent) -> str:
    """``"86–97"``: the range of ``values`` as ``show`` writes them; one figure where they agree."""
    low, high = show(min(values)), show(max(values))
    return low if low == high else f"{low}–{high}"


WORDS = {findings.SAVES: "less time", findings.TIES: "about the same time", findings.COSTS: "more time"}


def change(ratio: float) -> str:
    """A time ratio with / without read with chapter 04's rule (:func:`toolkit.teaching.findings.time_verdict`):
    ``"more time"``, ``"about the same time"`` or ``"less time"``."""
    return WORDS[findings.time_verdict(ratio)]


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


def counted(verdicts: list[str]) -> tuple[int, int, int]:
    """How many of ``verdicts`` (:func:`change`'s words) save time, tie and cost time."""
    return verdicts.count("less time"), verdicts.count("about the same time"), verdicts.count("more time")
