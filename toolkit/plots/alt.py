"""Text alternatives for figures: what a figure shows, in words, for a reader who cannot see it.

Every figure function of :mod:`toolkit.plots` says what it drew, from its data, with the numbers that carry its
conclusion, in plain words (:func:`describe`; no TeX: a screen reader reads ``$\\|z\\|$`` sign by sign by letter); a
figure made by hand gets one line, ``describe(fig, "...")``. Where nobody did, :func:`alt_text` reads the
figure's own titles and axis labels: a guard, never the description a figure ships with
(``tests/test_plots_accessibility.py`` fails on any figure function whose text starts with :data:`FALLBACK`,
``tests/test_site.py`` on any executed chapter's figure). In a notebook, :func:`register` (run when
:mod:`toolkit.plots` is imported in IPython) attaches the text to every displayed figure as
Jupyter's ``{"image/png": {"alt": ...}}`` output metadata, which nbconvert and the course site
(mkdocs-jupyter, :mod:`tools.site_hooks`) render as the ``<img>``'s ``alt``.

A complex figure (several panels, a map, a 3D view) holds more than a short text can carry; it also gets a
longer description (WCAG technique G74): one :class:`Part` per panel, row or step, in words and with a table of
the numbers it draws (:func:`map_part` for a map, read region by region; :func:`lines_part` for labelled lines).
It travels as the output's ``{"image/png": {"details": [...]}}`` metadata, and the site shows it under the
figure, in a "Figure described" disclosure. A figure of several panels that nobody described this way gets a
guard's part read from its titles (:func:`details`), which the tests refuse as they refuse the short guard.

>>> from matplotlib.figure import Figure
>>> alt_text(describe(Figure(), "two points, both valid"))
'two points, both valid'
"""

from __future__ import annotations

import html
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from matplotlib.figure import Figure

ATTRIBUTE = "toolkit_alt_text"  # where a figure keeps its description
DETAILS = "toolkit_alt_details"  # where a figure keeps its longer description (its parts)
FALLBACK = "Figure with "  # how a text read from titles begins
TEX = ("$", "\\")  # what a plain-words description never holds
DESCRIBED_BELOW = "Described in full below the figure."  # ends the alt of a figure with a longer description
DESCRIBED = "Figure described"  # the summary of the disclosure that holds it
ROWS = 12  # at most this many rows of a line's table (evenly picked, first and last kept)


@dataclass(frozen=True)
class Part:
    """One panel, row or step of a complex figure: its name, what it shows in words, and the numbers it draws as a
    table (``columns``, then ``rows`` of as many cells; the first column names each row)."""

    name: str
    text: str = ""
    columns: tuple[str, ...] = ()
    rows: tuple[tuple[str, ...], ...] = ()

    def __post_init__(self) -> None:
        for cell in (self.name, self.text, *self.columns, *(c for row in self.rows for c in row)):
            _plain(cell)
        if any(len(row) != len(self.columns) for row in self.rows):
            raise ValueError(f"{self.name}: every row of a part's table has one cell per column ({len(self.columns)})")


def _plain(text: str) -> str:
    if any(mark in text for mark in TEX):
        raise ValueError(f"a figure's text alternative is plain words, not TeX: {text[:80]!r}")
    return " ".join(text.split())


def many(n: int, thing: str) -> str:
    """A count in words a text alternative can use: ``"1 edge"``, ``"3 edges"`` (reader r44d: "1 edges")."""
    return f"{n} {thing}{'s' * (n != 1)}"


def describe(fig: Figure, text: str, parts: Sequence[Part] = ()) -> Figure:
    """Attach the text alternative ``text`` to ``fig`` (replacing any), and a longer description when the figure is
    complex (``parts``: one per panel, row or step); returns ``fig``."""
    if not text.strip():
        raise ValueError("a figure's text alternative must say something")
    setattr(fig, ATTRIBUTE, _plain(text))
    setattr(fig, DETAILS, list(parts))
    return fig


def alt_text(fig: Figure) -> str:
    """The text alternative of ``fig``: its description, or one read from its titles and axis labels."""
    described = getattr(fig, ATTRIBUTE, None)
    if described:
        return described
    panels = []
    for ax in fig.axes:
        words = [ax.get_title()] + [
            f"{axis}: {label}" for axis, label in (("x", ax.get_xlabel()), ("y", ax.get_ylabel())) if label
        ]
        if any(words):
            panels.append(", ".join(w for w in words if w))
    title = fig.get_suptitle() if hasattr(fig, "get_suptitle") else ""
    text = "; ".join(p for p in [title, *panels] if p)
    return " ".join(f"{FALLBACK}{len(fig.axes)} panel(s): {text or 'no titles'}".split())


def is_fallback(text: str) -> bool:
    """Whether ``text`` is the guard's, read from titles, rather than a description of the data."""
    return text.startswith(FALLBACK)


def parts_of(fig: Figure) -> list[Part]:
    """The parts of ``fig``'s longer description, as :func:`describe` was given them (to describe it again)."""
    return list(getattr(fig, DETAILS, None) or [])


def panels(fig: Figure) -> int:
    """How many panels ``fig`` shows: its visible axes (its subfigures' too), colour bars aside."""
    return sum(1 for ax in fig.axes if ax.get_visible() and (ax.axison or ax.has_data()) and not _is_colorbar(ax))


def _is_colorbar(ax) -> bool:
    return hasattr(ax, "_colorbar")


def details(fig: Figure) -> list[dict]:
    """The longer description of ``fig``, one dict per :class:`Part`; for a figure of several panels that has none,
    a guard's part read from its panels' titles (its name starts with :data:`FALLBACK`); else none."""
    described = getattr(fig, DETAILS, None)
    if described:
        return [_as_dict(p.name, p.text, list(p.columns), [list(row) for row in p.rows]) for p in described]
    if panels(fig) < 2:
        return []
    titles = [ax.get_title() for ax in fig.axes if not _is_colorbar(ax) and ax.get_title()]
    return [_as_dict(f"{FALLBACK}{panels(fig)} panels", "; ".join(titles) or "no titles", [], [])]


def _as_dict(name: str, text: str, columns: list[str], rows: list[list[str]]) -> dict:
    """A part as the notebook's output metadata keeps it (JSON)."""
    return {"name": name, "text": text, "columns": columns, "rows": rows}


def map_part(
    name: str,
    text: str,
    shape: tuple[int, int],
    x: tuple[str, float, float],
    y: tuple[str, float, float],
    cell: Callable[[tuple[slice, slice]], str],
    blocks: int = 4,
) -> Part:
    """A map ``shape = (nx, ny)`` (x across, y up) read region by region: ``blocks`` x ``blocks`` regions, the top
    row first as it is drawn; ``cell(region)`` says one region (``region`` indexes the map's arrays). ``x`` and
    ``y``: each axis's name and range."""
    edges = [np.linspace(0, n, min(blocks, n) + 1).round().astype(int) for n in shape]  # cell edges per axis
    spans = [lo + (hi - lo) * e / n for e, n, (_, lo, hi) in zip(edges, shape, (x, y))]  # the same edges in units
    spans = [np.round(span, 12) + 0.0 for span in spans]  # r28a: -pi + pi/2 * 2 read '-4.44e-16', not 0
    columns = [f"rows: {y[0]}, top first; columns: {x[0]}"]
    columns += [f"{x[0]} {a:.3g} to {b:.3g}" for a, b in zip(spans[0][:-1], spans[0][1:])]
    rows = []
    for j in reversed(range(len(edges[1]) - 1)):
        row = [f"{y[0]} {spans[1][j]:.3g} to {spans[1][j + 1]:.3g}"]
        for i in range(len(edges[0]) - 1):
            row.append(cell((slice(edges[0][i], edges[0][i + 1]), slice(edges[1][j], edges[1][j + 1]))))
        rows.append(tuple(row))
    return Part(name, text, tuple(columns), tuple(rows))


def lines_part(ax, name: str = "", text: str = "", digits: int = 3) -> Part:
    """The labelled lines of ``ax`` as a table: its x values down the first column (at most :data:`ROWS`, evenly
    picked), one column per line (lines on other x values get their own column, read at the nearest x)."""
    lines = [line for line in ax.get_lines() if not line.get_label().startswith("_")]
    if not lines:
        raise ValueError(f"{name or ax.get_title()}: no labelled line to put in a table")
    x = np.asarray(lines[0].get_xdata(), dtype=float)  # (T,)
    keep = np.unique(np.linspace(0, len(x) - 1, min(ROWS, len(x))).round().astype(int))
    columns = (ax.get_xlabel() or "x", *(line.get_label() for line in lines))
    rows = []
    for i in keep:
        row = [f"{x[i]:.{digits}g}"]
        for line in lines:
            lx, ly = (np.asarray(v, dtype=float) for v in line.get_data())
            row.append(f"{ly[np.argmin(np.abs(lx - x[i]))]:.{digits}g}")
        rows.append(tuple(row))
    said = f"{ax.get_ylabel()} against {ax.get_xlabel()}" + (f", {text}" if text else "")
    return Part(name or ax.get_title() or ax.get_ylabel(), said, columns, tuple(rows))


def details_html(parts: list[dict]) -> str:
    """A longer description (:func:`details`) as HTML: a closed disclosure, :data:`DESCRIBED`, holding each part's
    name and words, then its numbers as a table with row and column headers, in a named region that scrolls
    sideways where the page is narrow and the keyboard reaches; "" for none. The course site puts it under the
    figure (``tools/site_hooks.py``), as :func:`figure_html` does."""
    if not parts:
        return ""
    esc = html.escape
    blocks = []
    for part in parts:
        words = f": {esc(part['text'])}" if part.get("text") else ""
        blocks.append(f"<p><strong>{esc(part['name'])}</strong>{words}</p>")
        if part.get("columns"):
            head = "".join(f'<th scope="col">{esc(c)}</th>' for c in part["columns"])
            body = "".join(
                f'<tr><th scope="row">{esc(row[0])}</th>' + "".join(f"<td>{esc(c)}</td>" for c in row[1:]) + "</tr>"
                for row in part["rows"]
            )
            table = f"<table><caption>{esc(part['name'])}</caption><thead><tr>{head}</tr></thead>"
            table += f"<tbody>{body}</tbody></table>"
            region = f'role="region" tabindex="0" aria-label="table: {esc(part["name"], quote=True)}"'
            blocks.append(f'<div class="figure-described-table" {region}>{table}</div>')
    return f'\n<details class="figure-described"><summary>{DESCRIBED}</summary>\n{"".join(blocks)}\n</details>'


def figure_html(fig: Figure, png: str, style: str = "") -> str:
    """``fig`` drawn as ``png`` (base64) in an ``<img>`` with its alt text, its longer description under it."""
    found = details(fig)
    alt = alt_text(fig) + (f" {DESCRIBED_BELOW}" if found else "")
    shown = f'<img src="data:image/png;base64,{png}" alt="{html.escape(alt, quote=True)}"'
    return shown + (f' style="{style}"' if style else "") + ">" + details_html(found)


def metadata(fig: Figure) -> tuple[dict, dict]:
    """IPython's mime-bundle formatter for a figure: no data of its own (the PNG comes from matplotlib's
    formatter), the alt text and any longer description as the PNG's metadata."""
    found = details(fig)
    return {}, {"image/png": {"alt": alt_text(fig)} | ({"details": found} if found else {})}


def register() -> bool:
    """In an IPython kernel, give every displayed matplotlib figure its alt text; False outside IPython."""
    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None else None
    if shell is None:
        return False
    shell.display_formatter.mimebundle_formatter.for_type(Figure, metadata)
    return True
