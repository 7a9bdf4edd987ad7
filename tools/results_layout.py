"""How the results page lays out its wide tables (:func:`narrow`): in parts of at most :data:`COLUMNS` columns, each
repeating the columns that name its rows (:data:`KEYS`). Used by :mod:`tools.results_summary`."""

from __future__ import annotations

COLUMNS = 5  # the widest table the page shows: wider ones are cut off, or scroll, at 1280 px (chapter 04's rule)
KEYS = ("", "sampler")  # a table's leading columns that name its rows: every part of a split table repeats them


def narrow(text: str) -> str:
    """``text`` with every table wider than :data:`COLUMNS` shown in parts (:func:`parts`), a blank line between
    them: :func:`tools.recorded_results.parse` reads them as one table again."""
    lines, out, k = text.splitlines(), [], 0
    while k < len(lines):
        end = k
        while end < len(lines) and lines[end].startswith("|"):
            end += 1
        if end == k:
            out.append(lines[k])
            k += 1
            continue
        rows = [[cell.strip() for cell in line.strip().strip("|").split("|")] for line in lines[k:end]]
        shown = ["\n".join("| " + " | ".join(row) + " |" for row in part) for part in parts(rows)]
        out.append("\n\n".join(shown))
        k = end
    return "\n".join(out) + "\n" * text.endswith("\n")


def parts(rows: list[list[str]]) -> list[list[list[str]]]:
    """A table's ``rows`` (its header first) as parts of at most :data:`COLUMNS` columns, each with its leading
    :data:`KEYS` columns: the other columns grouped by their first word (``Sampling BS``, ``Sampling OB`` ...),
    whole groups packed from the right, so a table's last columns, which its prose cites, keep together."""
    keys = next(k for k, name in enumerate([*rows[0], None]) if name not in KEYS)
    if len(rows[0]) <= COLUMNS:
        return [rows]
    groups: list[list[int]] = []  # column indices, grouped by first word
    for c in range(keys, len(rows[0])):
        word = (rows[0][c].split() or [""])[0].strip(",").lower()
        if groups and word == (rows[0][groups[-1][0]].split() or [""])[0].strip(",").lower():
            groups[-1].append(c)
        else:
            groups.append([c])
    packed: list[list[int]] = []
    for group in reversed(groups):
        if packed and len(packed[0]) + len(group) <= COLUMNS - keys:
            packed[0][:0] = group
        else:
            packed.insert(0, list(group))
    return [[row[:keys] + [row[c] for c in columns] for row in rows] for columns in packed]
