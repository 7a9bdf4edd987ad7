"""Where the extra time went in the recorded cells where our accurate network cost the most inside Algorithm 1.

Chapter 04's answer table gives, for each scenario and sampler, the median of each query's own ratio (time with
prediction / time without) of our accurate `strong` network inside the paper's Algorithm 1 (``docs/results.md``,
"Preset `strong` with `--planner paper`"). Where that ratio is :data:`DEAR` or more, prediction cost a quarter or
more of the query's time (review r25a: "the recorded costs of 1.5-1.75x are never explained"). The record times two
things a query, sampling and the total, by means: :func:`cost_table` splits each such cell's mean time into the
sampling stage and everything after it (connecting the roadmap's edges, extracting and verifying the path), with
and without prediction. The record keeps no finer split and no counts (rounds, auxiliary samples, roadmap nodes,
edge points) for these runs; chapter 04's section 5 counts them live for one sampler.
"""

from __future__ import annotations

from dataclasses import dataclass

from toolkit.teaching import recorded
from toolkit.teaching.recorded import Tables

DEAR = 1.25  # a median ratio at or above this: prediction cost a quarter or more of the query's time
NAMES = {"2ds": "2DS", "3dc7": "3DC-7", "3dc9": "3DC-9", "3do": "3DO"}


@dataclass(frozen=True)
class Cost:
    """One recorded cell: its median ratio and its mean times in seconds, without and with prediction."""

    scenario: str
    sampler: str
    ratio: float
    sampling: tuple[float, float]  # mean sampling time: without, with
    total: tuple[float, float]  # mean total time: without, with

    @property
    def after(self) -> tuple[float, float]:
        """The mean time after sampling (the total less sampling), without and with."""
        return self.total[0] - self.sampling[0], self.total[1] - self.sampling[1]

    @property
    def after_share(self) -> float:
        """The share of the extra mean time (with less without) that came after sampling."""
        extra = self.total[1] - self.total[0]
        return (self.after[1] - self.after[0]) / extra if extra else 0.0


def dear_cells(tables: Tables | None = None) -> list[Cost]:
    """The cells whose median ratio is :data:`DEAR` or more, with their mean times from "Times behind Table 3"."""
    ratios = recorded.query_ratios(recorded.ALGORITHM_1, tables)
    times = recorded.packaged() if tables is None else tables
    heading = next(name for name in times[recorded.ALGORITHM_1] if "times behind table 3" in name.lower())
    found = times[recorded.ALGORITHM_1][heading]
    rows = {(row[0], row[1]): dict(zip(found["columns"], row)) for row in found["rows"]}
    cells = []
    for scenario, by_sampler in ratios.items():
        for sampler, ratio in by_sampler.items():
            if ratio >= DEAR:
                row = rows[scenario, sampler]
                means = {k: recorded.ours(row[k]) for k in ("sampling without", "sampling with", "total without")}
                cells.append(
                    Cost(
                        NAMES.get(scenario, scenario),
                        sampler,
                        ratio,
                        (means["sampling without"], means["sampling with"]),
                        (means["total without"], recorded.ours(row["total with"])),
                    )
                )
    return cells


def cost_table(tables: Tables | None = None) -> str:
    """The dear cells as a Markdown table (five columns, ms a query by means, without → with), and a line that counts
    in how many the larger part of the extra mean time came after sampling."""
    cells = dear_cells(tables)
    rows = [
        "| cell | median ratio | sampling, ms | after sampling, ms | share of the extra after sampling |",
        "| --- | ---: | ---: | ---: | ---: |",
    ]
    for c in cells:
        rows.append(
            f"| {c.scenario} {c.sampler} | {c.ratio:.2f} | {1000 * c.sampling[0]:.1f} → {1000 * c.sampling[1]:.1f} "
            f"| {1000 * c.after[0]:.1f} → {1000 * c.after[1]:.1f} | {c.after_share:.0%} |"
        )
    mostly = [c for c in cells if c.after_share > 0.5]
    others = ", ".join(f"{c.scenario} {c.sampler}" for c in cells if c not in mostly) or "none"
    return (
        "\n".join(rows) + f"\n\nThe larger part of the extra mean time came after sampling in {len(mostly)} of these "
        f"{len(cells)} cells (the others: {others})."
    )
