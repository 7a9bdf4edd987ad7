"""The tables of ``docs/results.md`` as data the installed toolkit carries: ``toolkit/teaching/recorded.json``.

``docs/results.md`` is where the project records its full-size reproductions (each table copied from a run's
``tables.md``); the notebooks quote some of its cells (:mod:`toolkit.teaching.recorded`). An installed toolkit has no
``docs/``, so the tables travel inside the package as JSON, written from the markdown here::

    python -m tools.recorded_results        # after editing docs/results.md
    python -m tools.results_summary         # and the summary at its top, computed from its tables

``tests/test_teaching_recorded.py`` fails while the packaged copy differs from what ``docs/results.md`` says.
"""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "docs" / "results.md"
PACKAGED = ROOT / "toolkit" / "teaching" / "recorded.json"
# a preset's section, or one planned with a named planner (and baseline)
PRESET = re.compile(r"^## Preset `(\w+)`(?: with `--planner (\w+)(?: --baseline ([\w-]+))?`(?:: .*)?)?$")
WITHOUT = "*Without prediction*:"  # how tables.md names, under a heading, what "without" was in its table
THRESHOLDS = "Decision threshold on P(valid):"  # the line under a run's Table 2: "2ds 0.41, 3dc7 0.63, ..."


def parse(text: str) -> dict[str, dict[str, dict]]:
    """``{preset: {heading: {"without": str | None, "columns": [...], "rows": [[cell, ...], ...]}}}``: the first table
    under every ``###`` heading of the sections ``## Preset `name` ``, and what its note says "without" was. A table
    the page shows in parts (tables separated by blank lines only, each repeating the first's leading key columns:
    the scenario, the sampler) is read as one (:func:`joined`). The line of decision thresholds under a table is kept
    with it, as ``"thresholds": {scenario: threshold}`` (chapter 05 names each training by its threshold)."""
    recorded: dict[str, dict[str, dict]] = {}
    section: dict[str, dict] | None = None
    heading = ""  # the heading whose table is being read; "" once it is read
    notes: list[str] = []  # the lines between that heading and its table
    parts: list[list[list[str]]] = []  # each part's (rows, columns) cells
    ended = False  # a blank line ended the last part: another may follow
    last: dict = {}  # the table read last in this section

    def close() -> None:
        nonlocal last
        rows = joined(parts)
        if section is not None and heading and len(rows) >= 3:
            last = section[heading] = {
                "without": next((n.removeprefix(WITHOUT).strip() for n in notes if n.startswith(WITHOUT)), None),
                "columns": rows[0],
                "rows": rows[2:],  # rows[1]: the | --- | line
            }

    for line in text.splitlines():
        if line.startswith(THRESHOLDS) and section is not None:
            if heading and parts:  # the line ends the table it follows
                close()
                heading = ""
            said = re.findall(r"(\w+) (\d\.\d+)", line.removeprefix(THRESHOLDS))
            last["thresholds"] = {scenario: float(value) for scenario, value in said}
        elif line.startswith(("## ", "### ")):
            close()
            heading, notes, parts = line.removeprefix("### ").strip() if line.startswith("### ") else "", [], []
            if line.startswith("## "):
                last = {}
                found = PRESET.match(line)
                section = recorded.setdefault(section_key(found), {}) if found else None
        elif heading and line.startswith("|"):
            if not parts or ended:
                parts.append([])
            parts[-1].append([cell.strip() for cell in line.strip().strip("|").split("|")])
            ended = False
        elif heading and parts and not line.strip():
            ended = True
        elif heading and parts:  # the first table under a heading, in its parts, is its table
            close()
            heading = ""
        elif heading:
            notes.append(line)
    close()
    return recorded


def section_key(found: re.Match) -> str:
    """The name a section's tables are read by (:mod:`toolkit.teaching.recorded`): its preset, ``"strong"``, or for a
    run that named its planner (and baseline) the preset and the options, ``"strong --planner paper"``."""
    options = zip(("planner", "baseline"), found.groups()[1:])
    named = "".join(f" --{option} {value}" for option, value in options if value)
    return found[1] + named


def joined(parts: list[list[list[str]]]) -> list[list[str]]:
    """The parts of one table as one: each part after the first repeats the first's leading key columns (its header
    begins as the first's does, its rows name the same rows in the same order) and adds its own columns."""
    if not parts:
        return []
    rows = [list(row) for row in parts[0]]
    for part in parts[1:]:
        keys = next(k for k in range(len(part[0]) + 1) if k == len(part[0]) or part[0][k] != rows[0][k])
        if keys == 0 or len(part) != len(rows) or any(a[:keys] != b[:keys] for a, b in zip(rows[2:], part[2:])):
            raise ValueError(f"a table's part {part[0]} does not repeat the rows of its first part {rows[0]}")
        for row, more in zip(rows, part):
            row += more[keys:]
    return rows


def packaged_text(results: Path = RESULTS) -> str:
    """What ``recorded.json`` holds for ``results``: its tables, as JSON."""
    return json.dumps(parse(results.read_text()), indent=1, ensure_ascii=False) + "\n"


def main() -> int:
    PACKAGED.write_text(packaged_text())
    print(f"wrote {PACKAGED.relative_to(ROOT)} from {RESULTS.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
