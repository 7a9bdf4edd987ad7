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
PRESET = re.compile(r"^## Preset `(\w+)`$")  # a preset's section; "## Preset `paper` before issue 25" is history
WITHOUT = "*Without prediction*:"  # how tables.md names, under a heading, what "without" was in its table


def parse(text: str) -> dict[str, dict[str, dict]]:
    """``{preset: {heading: {"without": str | None, "columns": [...], "rows": [[cell, ...], ...]}}}``: the first table
    under every ``###`` heading of the sections ``## Preset `name` ``, and what its note says "without" was."""
    recorded: dict[str, dict[str, dict]] = {}
    section: dict[str, dict] | None = None
    heading = ""  # the heading whose table is being read; "" once it is read
    notes: list[str] = []  # the lines between that heading and its table
    rows: list[list[str]] = []  # (rows, columns) cells

    def close() -> None:
        if section is not None and heading and len(rows) >= 3:
            section[heading] = {
                "without": next((n.removeprefix(WITHOUT).strip() for n in notes if n.startswith(WITHOUT)), None),
                "columns": rows[0],
                "rows": rows[2:],  # rows[1]: the | --- | line
            }

    for line in text.splitlines():
        if line.startswith(("## ", "### ")):
            close()
            heading, notes, rows = line.removeprefix("### ").strip() if line.startswith("### ") else "", [], []
            if line.startswith("## "):
                found = PRESET.match(line)
                section = recorded.setdefault(found[1], {}) if found else None
        elif heading and line.startswith("|"):
            rows.append([cell.strip() for cell in line.strip().strip("|").split("|")])
        elif heading and rows:  # the first table under a heading is its table
            close()
            heading = ""
        elif heading:
            notes.append(line)
    close()
    return recorded


def packaged_text(results: Path = RESULTS) -> str:
    """What ``recorded.json`` holds for ``results``: its tables, as JSON."""
    return json.dumps(parse(results.read_text()), indent=1, ensure_ascii=False) + "\n"


def main() -> int:
    PACKAGED.write_text(packaged_text())
    print(f"wrote {PACKAGED.relative_to(ROOT)} from {RESULTS.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
