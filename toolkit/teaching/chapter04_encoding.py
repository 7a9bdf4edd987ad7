"""Chapter 04, section 6: the encoding measured in section 5's live queries beside the growth after sampling of the
recorded cells that cost the most (reader r52d, item 2; moved out of :mod:`chapter04_paper` to keep it short), and
the cell where the two statistics lie furthest apart (reader r57d, item 6)."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from toolkit.teaching import checker_scope, costs, recorded
from toolkit.teaching.recorded import Tables
from toolkit.util.verdicts import COSTS, SAVES, TIES, time_verdict


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
    short = [n for n, g in here.items() if ms < g]  # reader r53d, item 5: named, not "2 of the 2"
    rest = (
        f"In {' and '.join(short)} the encoding is smaller than that growth, so something else after sampling grew "
        "too; these runs do not say what. "
        if short
        else ""
    )
    return (
        "**The encoding beside that growth.** The time after sampling includes encoding the workspace for the network. "
        f"Section 5's live 3DC-7 queries spent {ms:.1f} ms a query on it (median, this machine; the recorded runs do "
        f"not time the encoding). {'; '.join(said) or 'No 3DC-7 cell costs that much'}. "
        + rest
        + (
            f"The other scenarios' encoding is not measured here ({', '.join(elsewhere)} after sampling), so these "
            "runs cannot tell what grew there."
            if elsewhere
            else ""
        )
    ).strip()


def disagreement(tables: Tables | None = None) -> str:
    """Reader r57d, item 6: the cell where the median own ratio and the ratio of means lie furthest apart (log)."""
    own = recorded.query_ratios(recorded.ALGORITHM_1, tables)
    cells = [
        (o, 1 - recorded.improvements(recorded.ALGORITHM_1, k, "total", tables)[s], k, s)
        for k in own
        for s, o in own[k].items()
    ]
    o, m, k, s = max(cells, key=lambda c: abs(np.log(c[0] / c[1])))
    said = {SAVES: "saves time", TIES: "ties", COSTS: "costs time"}
    return (
        f"The two statistics lie furthest apart in {checker_scope.NAMES[k]} {s}: by its median own ratio it "
        f"{said[time_verdict(o)]} ({o:.2f}), by means it {said[time_verdict(m)]} ({m:.2f}); a mean follows a few slow "
        "queries."
    )


def live_cell(tables: Tables | None = None) -> str:
    """Reader r58d, item 1: section 5's live cell (3DC-7, BS) as the record's median own ratio reads it."""
    ratio = recorded.query_ratios(recorded.ALGORITHM_1, tables).get("3dc7", {}).get("BS")
    said = {SAVES: "a cell that saves time", TIES: "a tie cell", COSTS: "a costly cell"}
    return said[time_verdict(ratio)] if ratio is not None else "one cell"
