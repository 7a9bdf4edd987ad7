"""The results the project records in ``docs/results.md``, read where a notebook quotes them instead of pasted.

``docs/results.md`` holds the tables of the full-size reproductions (``toolkit reproduce
--preset paper|strong``, each copied from its run's ``tables.md``). A notebook that sets
its own small run beside them reads the cells from here, so the figures it quotes are
the ones the docs show, and follow the docs when the reproduction is run again::

    from toolkit.teaching import recorded
    medians = recorded.median_ratios("strong")              # {scenario: {"sampling"|"total": {sampler: ratio}}}
    row = recorded.table("paper", "MLP accuracy")["3dc7"]   # {column: cell} of Table 2's 3DC-7 row
    recorded.ours(row["Seen TPR"])                          # 1.0: our figure of the cell "**100%** / 87%"
    recorded.without("strong", "medians")                   # what "without prediction" was, where the docs say
    recorded.improvements("paper", "3dc7")                  # Table 3's totals: {"BS": 0.09, "OB": 0.04, ...}
    recorded.query_ratios(recorded.ALGORITHM_1)             # the `strong` network inside Algorithm 1, each
                                                            # query's own ratio: {scenario: {sampler: median}}

A section run with a named planner (``## Preset `strong` with `--planner paper` ``) is read by the preset and the
option, ``"strong --planner paper"`` (:data:`ALGORITHM_1`).

The tables travel with the package, in ``recorded.json`` beside this file (an installed toolkit has no ``docs/``):
``python -m tools.recorded_results`` writes it from ``docs/results.md``, and a test holds the two equal. Every
function also takes ``recorded``, tables of the same form, to read others'.
"""

from __future__ import annotations

import json
import re
from collections.abc import Mapping
from functools import cache
from importlib import resources

Tables = Mapping[str, Mapping[str, dict]]  # {preset: {heading: {"without", "columns", "rows"}}}
ALGORITHM_1 = "strong --planner paper"  # the section of our accurate network inside the paper's Algorithm 1 (a run of
# `toolkit reproduce --preset strong --planner paper --baseline paper`): the paper's claim, tested over 100 queries


@cache
def packaged() -> Tables:
    """The tables of ``docs/results.md`` as the package carries them (``recorded.json``)."""
    return json.loads(resources.files(__package__).joinpath("recorded.json").read_text(encoding="utf-8"))


def table(preset: str, heading: str, recorded: Tables | None = None) -> dict[str, dict[str, str]]:
    """``{row: {column: cell}}`` of the table under the first ``###`` heading containing ``heading`` (any case)
    in the section ``## Preset `preset` `` of ``docs/results.md``; rows are named by their first cell (the
    scenario)."""
    found = _under(preset, heading, recorded)
    columns = found["columns"][1:]
    return {row[0]: dict(zip(columns, row[1:])) for row in found["rows"]}


def without(preset: str, heading: str, recorded: Tables | None = None) -> str | None:
    """What "without prediction" was in that table, as the line under its heading says; None where none does."""
    return _under(preset, heading, recorded)["without"]


def ours(cell: str) -> float:
    """Our figure in a cell (the first number; ``docs/results.md`` writes ours first, in bold, then the paper's):
    a fraction where it is a percentage. ``"**61%** / 92%"`` gives 0.61, ``"0.28"`` 0.28, ``"43,049,544"`` 43049544."""
    found = re.search(r"-?\d[\d,]*(?:\.\d+)?\s*%?", cell)
    if found is None:
        raise ValueError(f"no number in the cell {cell!r}")
    number = found.group().replace(",", "").replace(" ", "")
    return float(number[:-1]) / 100 if number.endswith("%") else float(number)


def median_ratios(preset: str, recorded: Tables | None = None) -> dict[str, dict[str, dict[str, float]]]:
    """The table "Time with / without prediction, medians over the queries" of ``preset``:
    ``{scenario: {"sampling" | "total": {sampler: median time with / median time without}}}``."""
    ratios: dict[str, dict[str, dict[str, float]]] = {}
    for scenario, cells in table(preset, "medians over the queries", recorded).items():
        for column, cell in cells.items():
            kind, sampler = column.split()  # e.g. "Sampling BS"
            ratios.setdefault(scenario, {}).setdefault(kind.lower(), {})[sampler] = ours(cell)
    return ratios


def query_ratios(preset: str, recorded: Tables | None = None) -> dict[str, dict[str, float]]:
    """The table "Time with / without prediction, each query's own ratio" of ``preset`` (a run that kept each query's
    times): ``{scenario: {sampler: the median of each query's total time with / without}}``."""
    return {
        scenario: {column.split()[1]: ours(cell) for column, cell in cells.items()}
        for scenario, cells in table(preset, "each query's own ratio", recorded).items()
    }


def improvements(preset: str, scenario: str, kind: str = "total", recorded: Tables | None = None) -> dict[str, float]:
    """Table 3's row of ``scenario``: ``{sampler: (t_without - t_with) / t_without}`` of mean times, the ``kind``
    ("total" or "sampling") columns; ``1 - improvement`` is the time ratio with / without."""
    cells = table(preset, "time improvement", recorded)[scenario]
    return {column.split()[1]: ours(cell) for column, cell in cells.items() if column.lower().startswith(kind)}


def thresholds(preset: str, recorded: Tables | None = None) -> dict[str, float]:
    """``{scenario: threshold}``: the decision threshold on P(valid) each scenario's MLP of that run used, as the
    line under its Table 2 says (``{"3dc7": 0.63, ...}``); a run's trainings told apart by it (chapter 05)."""
    return dict(_under(preset, "MLP accuracy", recorded).get("thresholds", {}))


def _under(preset: str, heading: str, recorded: Tables | None) -> dict:
    """The table under the first heading of ``preset`` containing ``heading``: ``{"without", "columns", "rows"}``."""
    tables = packaged() if recorded is None else recorded
    if preset not in tables:
        raise ValueError(f"docs/results.md has no section '## Preset `{preset}`'; recorded presets: {sorted(tables)}")
    found = [name for name in tables[preset] if heading.lower() in name.lower()]
    if not found:
        raise ValueError(f"docs/results.md, preset {preset!r}: no table under a heading with {heading!r}")
    return tables[preset][found[0]]
