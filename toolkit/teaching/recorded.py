"""The results the project records in ``docs/results.md``, read where a notebook quotes them instead of pasted.

``docs/results.md`` holds the tables of the full-size reproductions (``toolkit reproduce
--preset paper|strong``, each copied from its run's ``tables.md``). A notebook that sets
its own small run beside them reads the cells from there, so the figures it quotes are
the ones the docs show, and follow the docs when the reproduction is run again::

    from toolkit.teaching import recorded
    medians = recorded.median_ratios("strong")              # {scenario: {"sampling"|"total": {sampler: ratio}}}
    row = recorded.table("paper", "MLP accuracy")["3dc7"]   # {column: cell} of Table 2's 3DC-7 row
    recorded.ours(row["Seen TPR"])                          # 1.0: our figure of the cell "**100%** / 87%"
    recorded.without("strong", "medians")                   # what "without prediction" was, where the docs say
"""

from __future__ import annotations

import re
from pathlib import Path

RESULTS = Path(__file__).resolve().parents[2] / "docs" / "results.md"
WITHOUT = "*Without prediction*:"  # how tables.md names, under a heading, what "without" was in its table


def table(preset: str, heading: str, path: str | Path = RESULTS) -> dict[str, dict[str, str]]:
    """``{row: {column: cell}}`` of the first table under the ``###`` heading containing ``heading`` (any case)
    in the section ``## Preset `preset` `` of ``path``; rows are named by their first cell (the scenario)."""
    rows = [[cell.strip() for cell in line.strip().strip("|").split("|")] for line in _under(preset, heading, path)[1]]
    if len(rows) < 3:
        raise ValueError(f"{path}, preset {preset!r}: the heading with {heading!r} has no table under it")
    columns = rows[0][1:]
    return {row[0]: dict(zip(columns, row[1:])) for row in rows[2:]}  # rows[1]: the | --- | line


def without(preset: str, heading: str, path: str | Path = RESULTS) -> str | None:
    """What "without prediction" was in that table, as the line under its heading says; None where none does."""
    note = next((line for line in _under(preset, heading, path)[0] if line.startswith(WITHOUT)), None)
    return None if note is None else note.removeprefix(WITHOUT).strip()


def ours(cell: str) -> float:
    """Our figure in a cell (the first number; ``docs/results.md`` writes ours first, in bold, then the paper's):
    a fraction where it is a percentage. ``"**61%** / 92%"`` gives 0.61, ``"0.28"`` 0.28, ``"43,049,544"`` 43049544."""
    found = re.search(r"-?\d[\d,]*(?:\.\d+)?\s*%?", cell)
    if found is None:
        raise ValueError(f"no number in the cell {cell!r}")
    number = found.group().replace(",", "").replace(" ", "")
    return float(number[:-1]) / 100 if number.endswith("%") else float(number)


def median_ratios(preset: str, path: str | Path = RESULTS) -> dict[str, dict[str, dict[str, float]]]:
    """The table "Time with / without prediction, medians over the queries" of ``preset``:
    ``{scenario: {"sampling" | "total": {sampler: median time with / median time without}}}``."""
    ratios: dict[str, dict[str, dict[str, float]]] = {}
    for scenario, cells in table(preset, "medians over the queries", path).items():
        for column, cell in cells.items():
            kind, sampler = column.split()  # e.g. "Sampling BS"
            ratios.setdefault(scenario, {}).setdefault(kind.lower(), {})[sampler] = ours(cell)
    return ratios


def _under(preset: str, heading: str, path: str | Path) -> tuple[list[str], list[str]]:
    """Under that heading: the lines before its table, and the table's ``|`` rows."""
    lines = Path(path).read_text().splitlines()
    title = f"## Preset `{preset}`"
    if title not in lines:
        raise ValueError(f"{path} has no section '{title}'")
    start = lines.index(title) + 1
    section = lines[start : next((i for i in range(start, len(lines)) if lines[i].startswith("## ")), len(lines))]
    found = [i for i, line in enumerate(section) if line.startswith("### ") and heading.lower() in line.lower()]
    if not found:
        raise ValueError(f"{path}, preset {preset!r}: no table under a heading with {heading!r}")
    text = section[found[0] + 1 :]
    begin = next((i for i, line in enumerate(text) if line.startswith(("|", "#"))), len(text))
    end = next((i for i in range(begin, len(text)) if not text[i].startswith("|")), len(text))
    return text[:begin], text[begin:end]
