"""A code cell folded in JupyterLab is folded on the course website too.

JupyterLab keeps a code cell whose input a reader collapsed (the bar at the cell's left, or View > Collapse Selected
Code) as nbformat's own cell metadata, ``"jupyter": {"source_hidden": true}``. On the site (:mod:`tools.site_hooks`)
such a cell's input sits in a closed ``<details class="code-folded">`` whose ``<summary>`` says what it holds:
"Code (folded): the imports" when the cell's first line is the comment ``# the imports``, else "Code (folded)"
(:func:`summary`). Its outputs show as always. A native disclosure: the keyboard reaches it, a screen reader names it.

mkdocs-jupyter writes each code cell as a ``<div ... id="cell-id=ID">`` (nbformat 4.5's cell id) whose first child is
its input, ``<div class="jp-Cell-inputWrapper">``; the cell is found by its id, and where its input ends by
:class:`html.parser.HTMLParser`, which reads tags as a browser does (no ``<div>`` counted inside the code's text).
"""

from __future__ import annotations

import html as html_lib
import json
import re
from html.parser import HTMLParser
from pathlib import Path

FOLDED = "Code (folded)"
INPUT = re.compile(r'\s*<div class="jp-Cell-inputWrapper"[^>]*>')  # a code cell's first child, its input


def summary(source: str) -> str:
    """What a folded cell's disclosure says: its first non-blank line's words when that line is a comment
    (``# the imports``: "Code (folded): the imports"), else "Code (folded)"."""
    first = next((line.strip() for line in source.splitlines() if line.strip()), "")
    words = first.lstrip("#").strip() if first.startswith("#") else ""
    return f"{FOLDED}: {words}" if words else FOLDED


def folded_cells(notebook: Path) -> dict[str, str]:
    """The code cells of ``notebook`` whose input is collapsed (``metadata.jupyter.source_hidden``), by cell id, each
    with its :func:`summary`. Raises ``ValueError`` for a folded cell with no id (nbformat before 4.5): the page
    could not find it; JupyterLab 4 saves a notebook with ids."""
    found = {}
    for cell in json.loads(notebook.read_text()).get("cells", []):
        if cell.get("cell_type") != "code" or not cell.get("metadata", {}).get("jupyter", {}).get("source_hidden"):
            continue
        if not cell.get("id"):
            raise ValueError(f"{notebook.name}: a folded code cell has no id (save it with JupyterLab 4)")
        source = cell.get("source", "")
        found[cell["id"]] = summary(source if isinstance(source, str) else "".join(source))
    return found


def fold_code(html: str, notebook: Path) -> str:
    """The page ``html`` of ``notebook`` with the input of each of its folded code cells (:func:`folded_cells`) in a
    closed ``<details>`` named by its summary; the page as it is when ``notebook`` is no file (a page made by hand).
    Raises ``ValueError`` when a folded cell is not on the page as mkdocs-jupyter writes one."""
    if not notebook.is_file():
        return html
    for cell_id, said in folded_cells(notebook).items():
        anchor = f'id="{html_lib.escape(f"cell-id={cell_id}", quote=True)}"'
        at = html.find(anchor)
        tag_end = html.find(">", at) + 1
        wrapper = INPUT.match(html, tag_end) if at >= 0 else None
        if wrapper is None:
            raise ValueError(f"{notebook.name}: folded cell {cell_id} has no input on its page")
        start = wrapper.start() + len(wrapper[0]) - len(wrapper[0].lstrip())
        end = element_end(html, start)
        html = (
            f'{html[:start]}<details class="code-folded"><summary>{html_lib.escape(said)}</summary>\n'
            f"{html[start:end]}</details>{html[end:]}"
        )
    return html


class _DivEnd(HTMLParser):
    """Reads from a ``<div>``'s start tag; ``end`` becomes the (line, column) of the ``</div>`` that closes it."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=False)
        self.depth = 0
        self.end: tuple[int, int] | None = None

    def handle_starttag(self, tag: str, attrs: list) -> None:
        self.depth += tag == "div"

    def handle_endtag(self, tag: str) -> None:
        if tag == "div" and self.end is None:
            self.depth -= 1
            if self.depth == 0:
                self.end = self.getpos()


def element_end(html: str, start: int, chunk: int = 8192) -> int:
    """Where the ``<div>`` that starts at ``start`` of ``html`` ends (just after its closing tag)."""
    parser = _DivEnd()
    for at in range(start, len(html), chunk):
        parser.feed(html[at : at + chunk])
        if parser.end is not None:
            break
    if parser.end is None:
        raise ValueError(f"the <div> at {start} is never closed")
    line, column = parser.end
    closing = start
    for _ in range(line - 1):
        closing = html.index("\n", closing) + 1
    return html.index(">", closing + column) + 1
