"""Our planners against OMPL's (``toolkit bench --vs-ompl``): each planner's median time a query, per scenario.

:func:`race_medians` draws one row per scenario and one dot per planner on a log axis of milliseconds, OMPL's
planners with their checks batched as a second, hollow marker of the same colour and shape (docs/planner_race.md,
its first table and its ratio tables). :func:`from_tables` reads those figures from the page's Markdown tables, so
the figure is drawn from what the page prints. Nothing here calls ``show()``.
"""

from __future__ import annotations

import re

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.ticker import NullLocator

from toolkit.plots.alt import Part, describe
from toolkit.plots.palette import COLORS, LINE_COLORS, MARKER_NAMES, MARKERS, PAGE_WIDTH

OURS = ("ours: RRT-Connect", "ours: lazy PRM", "ours: the paper's Algorithm 1")
OMPL = ("OMPL RRTConnect", "OMPL PRM")
BATCHED = {  # OMPL's planner -> (the ratio table's batched column, the planner of ours over it)
    "OMPL RRTConnect": ("RRT-Connect / OMPL RRTConnect, checks batched", "ours: RRT-Connect"),
    "OMPL PRM": ("lazy PRM / OMPL PRM, checks batched", "ours: lazy PRM"),
}
POINTS = 9  # the tick labels' and the legend's size


def _marker(k: int, planner: str) -> str:
    """Planner ``k``'s marker: the palette's in turn, a star for Algorithm 1 (reader r35g, race figure b: not a second
    triangle)."""
    return "*" if "Algorithm 1" in planner else MARKERS[k % len(MARKERS)]


def _shape(k: int, planner: str) -> str:
    """:func:`_marker` in words, one of them ("a circle")."""
    names = {**MARKER_NAMES, "*": "stars"}
    word = names[_marker(k, planner)].removesuffix("s")
    return f"an {word}" if word[0] in "aeiou" else f"a {word}"


def from_tables(markdown: str, seed: int) -> tuple[dict[str, dict[str, float]], dict[str, dict[str, float]]]:
    """From the race page's Markdown: ``{scenario: {planner: median ms}}`` of ``seed`` (its table of medians has a row
    a planner and a column a scenario and seed; a table the other way round reads too), and
    ``{scenario: {OMPL planner: ms with its checks batched}}``, our planner's median over its batched ratio (as
    the page computes it)."""
    cells: dict[str, dict[str, str]] = {}
    header: list[str] = []
    for line in markdown.splitlines():
        if not line.startswith("|") or set(line) <= set("|-: "):
            header = [] if not line.startswith("|") else header
            continue
        row = [c.strip() for c in line.strip().strip("|").split("|")]
        if not header:
            header = row
            continue
        name, _, row_seed = row[0].partition(", ")
        if row_seed == str(seed):  # a row a scenario and seed, a column a planner
            cells.setdefault(name, {}).update(zip(header[1:], row[1:]))
        for column, cell in zip(header[1:], row[1:]):  # reader r44g, race: a row a planner, a column a scenario
            scenario, _, column_seed = column.partition(", ")
            if column_seed == str(seed):
                cells.setdefault(scenario, {})[row[0]] = cell
    number = re.compile(r"\d+(?:,\d{3})*(?:\.\d+)?")

    def first(cell: str) -> float:
        return float(number.findall(cell)[0].replace(",", ""))

    medians = {s: {p: first(row[p]) for p in (*OURS, *OMPL)} for s, row in cells.items()}
    batched = {
        s: {p: medians[s][ours] / first(cells[s][column]) for p, (column, ours) in BATCHED.items()} for s in cells
    }
    return medians, batched


def race_medians(
    medians: dict[str, dict[str, float]], batched: dict[str, dict[str, float]] | None = None, seed: int | None = None
) -> Figure:
    """One row per scenario of ``medians`` (``{scenario: {planner: median ms}}``), one filled dot per planner on a
    log axis; ``batched`` (``{scenario: {OMPL planner: ms}}``) as a hollow marker of the planner's colour and shape.
    Ours sit a little below each scenario's name, OMPL's a little above, so that near values do not cover each other."""
    scenarios = list(medians)
    planners = list(next(iter(medians.values())))
    # reader r41g, race figure: shorter rows, so that the scale and the dots share a screen at 1280 x 800
    fig = Figure(figsize=(PAGE_WIDTH, 0.97 + 0.55 * len(scenarios) + 0.25 * (len(planners) + 2)))
    ax = fig.subplots()
    for k, planner in enumerate(planners):
        colour, marker = LINE_COLORS[k % len(LINE_COLORS)], _marker(k, planner)
        y = np.arange(len(scenarios)) + (0.15 if planner.startswith("ours") else -0.15)  # (S,)
        x = [medians[s][planner] for s in scenarios]  # (S,) ms
        ax.plot(x, y, marker, color=colour, markersize=8, ls="none", label=planner, clip_on=False)
        if batched and all(planner in batched[s] for s in scenarios):
            x = [batched[s][planner] for s in scenarios]
            # reader r34g, race figure b: an estimate drawn apart from a timing (hollow), and named so; r36g: and
            # marked so; r37g: at full colour and the "est." in ink, since the pale pink was hard to see on white
            ax.plot(x, y, marker, color=colour, markersize=9, ls="none", mfc=COLORS["free"], mew=2.0,
                    label=f"{planner}, checks batched (estimated)", clip_on=False)  # fmt: skip
            for at, row in zip(x, y, strict=True):
                ax.annotate("est.", (at, row), xytext=(0, 6), textcoords="offset points", ha="center", va="bottom",
                            fontsize=POINTS - 1, color=COLORS["ink"])  # fmt: skip
    ax.set_xscale("log")
    low, high = ax.set_xlim(ax.get_xlim()[0], 1.5 * ax.get_xlim()[1])  # reader r35g, race figure c: room past 197 ms
    ticks = [m * 10.0**e for e in range(-1, 5) for m in (1, 2, 5) if low <= m * 10.0**e <= high]
    ax.set_xticks(ticks, [f"{v:g}" for v in ticks])  # plain numbers, not 10^2
    ax.xaxis.set_minor_locator(NullLocator())
    ax.tick_params(axis="x", top=True, labeltop=True)  # reader r41g: the scale on top too, seen with the first dots
    ax.set_yticks(range(len(scenarios)), scenarios)
    tagged = [y + d for y in range(len(scenarios)) for d in (-0.15, 0.15)]  # reader r33g: each row says whose it is
    ax.set_yticks(tagged, ["OMPL", "ours"] * len(scenarios), minor=True)
    ax.tick_params(axis="y", which="minor", labelsize=POINTS, labelcolor=COLORS["rejected"], length=2)  # r34g: legible
    ax.tick_params(axis="y", which="major", length=0, pad=POINTS * 4.4)  # scenario left of its rows' tags; r47g: room

    ax.set_ylim(len(scenarios) - 0.5, -0.5)  # the first scenario on top
    ax.grid(axis="x", color=COLORS["block"], lw=0.6, zorder=0)
    for between in np.arange(len(scenarios) - 1) + 0.5:  # reader r31f: a line between scenarios, the dots in rows
        ax.axhline(between, color=COLORS["block"], lw=0.6, ls=":", zorder=0)
    ax.set_xlabel("median time a query, ms (log axis)")
    ax.set_ylabel("scenario")  # reader r34g, race figure c: each row's "OMPL" / "ours" tag says whose it is
    ax.tick_params(labelsize=POINTS)
    # reader r36g, race figure a: the scenario a heading, not a third row's tag; r37g: larger, not bold, since the
    # bold face drew in serif beside the sans ticks
    ax.tick_params(axis="y", which="major", labelsize=POINTS + 2, labelcolor=COLORS["ink"])
    held = f", seed {seed}" if seed is not None else ""
    ax.set_title(f"Median time a query by planner{held}: further left is faster", fontsize=10)
    handles, labels = _columns(*ax.get_legend_handles_labels())
    rows = len(labels) // 2
    room = (0, (0.18 * rows + 0.16) / fig.get_figheight(), 1, 1)  # reader r50g: no white band under the legend
    fig.legend(handles, labels, loc="upper center", bbox_to_anchor=(0.5, room[1]), ncol=2, fontsize=POINTS - 1,
               frameon=False)  # fmt: skip
    fig.tight_layout(rect=room)
    return describe(fig, _in_words(medians, batched, held), [_in_a_table(medians, batched)])


def _columns(handles: list, labels: list[str]) -> tuple[list, list[str]]:
    """The legend's entries as two columns, ours on the left and OMPL's on the right (reader r31f: "ours" and "OMPL"
    were mixed in the left one), the shorter padded with blank entries; a legend of ``ncol=2`` fills by columns."""
    ours = [(h, label) for h, label in zip(handles, labels, strict=True) if label.startswith("ours")]
    theirs = [(h, label) for h, label in zip(handles, labels, strict=True) if not label.startswith("ours")]
    rows = max(len(ours), len(theirs))
    blank = (Line2D([], [], ls="none"), "")
    entries = ours + [blank] * (rows - len(ours)) + theirs + [blank] * (rows - len(theirs))
    return [h for h, _ in entries], [label for _, label in entries]


def _ms(value: float) -> str:
    """A median as the page's tables print it (reader r44g, race: the text alternative's values are the figure's)."""
    return f"{value:.1f}"


def _in_words(medians: dict[str, dict[str, float]], batched: dict[str, dict[str, float]] | None, held: str) -> str:
    """The figure in words: what each marker is, then per scenario every marker's time, fastest first (reader r44g,
    race: the values the figure draws, estimates named as such)."""
    planners = list(next(iter(medians.values())))
    text = f"Dot chart of each planner's median time a query in milliseconds on a log axis{held}, a row a scenario"
    text += ", OMPL's planners a little above the scenario's name and ours a little below. Filled markers, timings: "
    text += "; ".join(f"{_shape(k, p)}, {p}" for k, p in enumerate(planners)) + ". "
    extra = list(next(iter(batched.values()))) if batched else []
    if extra:
        shapes = " and ".join(f"{_shape(planners.index(p), p).partition(' ')[2]}" for p in extra)
        text += f"Open {shapes}, marked est.: {' and '.join(extra)} with their checks batched, estimated, not timed. "
    for s, row in medians.items():
        dots = {p: row[p] for p in planners}
        dots.update({f"{p}, checks batched (est.)": batched[s][p] for p in extra if batched})
        order = sorted(dots, key=dots.__getitem__)
        text += f"{s}, fastest first: " + "; ".join(f"{p} {_ms(dots[p])} ms" for p in order) + ". "
    return text


def _in_a_table(medians: dict[str, dict[str, float]], batched: dict[str, dict[str, float]] | None) -> Part:
    planners = list(next(iter(medians.values())))
    extra = list(next(iter(batched.values()))) if batched else []
    columns = ("scenario", *(f"{p}, ms" for p in planners), *(f"{p}, checks batched, ms" for p in extra))
    rows = tuple(
        (s, *(_ms(medians[s][p]) for p in planners), *(_ms(batched[s][p]) for p in extra if batched)) for s in medians
    )
    return Part("median time a query", "Each planner's median time a query, ms, per scenario.", columns, rows)
