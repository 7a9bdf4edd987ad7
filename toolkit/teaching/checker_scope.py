"""Which exact checker a verdict on the paper's claim holds against, read from the recorded runs.

The paper names no exact checker. ``docs/results.md`` records our accurate `strong` network inside the paper's
Algorithm 1 twice: with our compiled exact checker on both sides (:data:`toolkit.teaching.recorded.ALGORITHM_1`), and
with python-fcl doing every exact check on both sides (:data:`SLOW`), a checker tens of times slower. A slow checker
makes every sample check the network skips worth more, so the claim's answer depends on it: the chapters name the
checker first, then the answer. Table 3's statistic (means) gives the sampling stage; each query's own ratio (time
with prediction over its own time without) gives the total, as the verdict on the compiled checker reads it.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

from toolkit.teaching import recorded
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
    )


def _percents(values: tuple[float, ...]) -> str:
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
        f"the median query's total time was shorter in {verdicts[SAVES] or 'none'} of the {total} scenario–sampler "
        f"pairs, a tie in {verdicts[TIES]} and longer in {verdicts[COSTS]}"
    )


def slow_sentence(facts: SlowChecker) -> str:
    """One sentence, the checker named first: what the accurate network did inside Algorithm 1 with python-fcl on
    both sides, the sampling stage by Table 3's means beside the paper's, the total by each query's own ratio."""
    where = " and ".join(facts.scenarios) if len(facts.scenarios) < 3 else ", ".join(facts.scenarios)
    sampling = facts.sampling_verdicts()
    if sampling[SAVES] == len(facts.sampling):
        stage = f"saved {_percents(facts.sampling)} of the sampling time by Table 3's means"
    else:
        stage = f"saved sampling time (Table 3's means) in {sampling[SAVES]} of {len(facts.sampling)} cells"
    own = facts.own
    total = _counted(facts.total_verdicts())
    return (
        f"With a slow exact checker on both sides (python-fcl, {where}; 100 recorded queries a scenario), our accurate "
        f"network {stage} (the paper's Table 3: {_percents(facts.papers_sampling)}), but {total} (the median of each "
        f"query's own ratio {min(own):.2f}–{max(own):.2f}; Table 3's totals {_percents(facts.totals)}, the paper's "
        f"{_percents(facts.papers_totals)})."
    )
