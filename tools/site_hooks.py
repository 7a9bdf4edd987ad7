"""mkdocs hooks of the course website (``mkdocs.yml``, built by :mod:`tools.site`).

Links: the sources link each other by their paths in the repository (``02_cae_reconstruction.ipynb``,
``../docs/results.md``, ``tutorials/assignments/``), and the site's source tree keeps those paths. mkdocs
turns such links into page URLs in Markdown pages, but not in notebooks (mkdocs-jupyter writes their HTML
as nbconvert made it), and not links to a folder or to a module of ``toolkit/``. These hooks send every
one to its page: a folder to its ``README.md``, a module to its entry in the API reference. In the API
reference, the docstrings' Sphinx roles (``:func:`name```) become links to the object where it is found.

Take-away: each notebook page (chapter, tutorial, assignment) begins with a link to its notebook without outputs
(``downloads/``, written by :mod:`tools.site`) and, when ``mkdocs.yml``'s ``extra.jupyterhub`` names the course's
hub and the repository its students pull, a link that opens it there through nbgitpuller.

Accessible (WCAG 2.2 AA, measured by :mod:`tools.accessibility`): every page has one ``h1`` (a heading that
a notebook's output prints becomes an ``h2``), and every block of code that scrolls sideways can be reached by
keyboard (``tabindex="0"``) and is named for a screen reader (:func:`focusable_code`), while a cell's input and
a cell's output, which nbconvert makes tab stops of no name (every paragraph and figure of a chapter one more
press of Tab), are not (``docs/site/accessibility.js`` makes a region of an output that scrolls); the colours,
underlined links and focus outline are in ``docs/site/accessibility.css``. Every figure of a notebook page takes
the alt text its output carries, and a complex figure (several panels, a map, a 3D view) its longer description
in a "Figure described" disclosure under it (:func:`figure_alts`, from :mod:`toolkit.plots.alt`). A code cell whose
input is collapsed in JupyterLab shows it in a closed "Code (folded)" disclosure (:mod:`tools.site_fold`).

Offline: notebook pages load MathJax from the site's own copy (``assets/mathjax``, at the right depth for
each page), and nbconvert's loader of mermaid diagrams, which imports its script from a CDN, is dropped
(no chapter draws a mermaid diagram).
"""

from __future__ import annotations

import html as html_lib
import json
import posixpath
import re
from collections.abc import Mapping
from pathlib import Path
from typing import TypedDict
from urllib.parse import urlencode, urlsplit

from mkdocs.structure.files import File, Files
from mkdocs.structure.pages import Page
from mkdocs.structure.toc import get_toc

from toolkit.plots import alt as plots_alt
from tools.site_fold import fold_code

MATHJAX_PLACEHOLDER = '"MATHJAX/'  # how mkdocs.yml's custom_mathjax_url starts; the site's copy replaces it
MATHJAX = "assets/mathjax"
DOWNLOADS = "downloads"  # tools.site's folder of notebooks without outputs
MARKDOWN_LINK = re.compile(r"(?P<head>\]\()(?P<url>[^)\s#]+)(?P<fragment>#[^)\s]*)?(?P<tail>\))")
HTML_LINK = re.compile(r'(?P<head>\b(?:href|src)=")(?P<url>[^"#]+)(?P<fragment>#[^"]*)?(?P<tail>")')
HEADING = re.compile(r'<h(?P<level>[1-6]) id="(?P<id>[^"]+)"(?P<attrs>[^>]*)>(?P<body>.*?)</h(?P=level)>', re.DOTALL)
ANCHOR_LINK = re.compile(r'<a class="anchor-link"[^>]*>.*?</a>', re.DOTALL)
MERMAID_LOADER = re.compile(r'<script type="module">(?:(?!</script>).)*?\.jp-Mermaid.*?</script>', re.DOTALL)
IMAGE = re.compile(r'<img\b[^>]*?\bsrc="data:image/png;base64,(?P<data>[^"]+)"[^>]*>')
H1 = re.compile(r"<h1\b(?P<attrs>[^>]*)>(?P<body>.*?)</h1>", re.DOTALL)
CODE_BLOCK = re.compile(
    r'<div class="(?P<cls>[^"]*\bhighlight(?P<cell>-ipynb)?\b[^"]*)">(?P<space>\s*)<pre(?![^>]*tabindex)'
    r"(?P<pre>[^>]*>)(?!(?:<span></span>)?<code)"  # a <pre> around a <code>: BARE_CODE's
)
BARE_CODE = re.compile(r"(?P<pre><pre\b(?![^>]*tabindex)[^>]*>(?:<span></span>)?)<code(?![^>]*tabindex)")  # it scrolls
REGION = 'tabindex="0" role="region" aria-label="code"'
FOLD_OR_HEADING = re.compile(r'<(?P<close>/?)details\b|<h[1-6] id="(?P<id>[^"]+)"')  # a fold's edges and headings
OUTPUT_TAB_STOP = re.compile(r'(<div class="[^"]*\bjp-OutputArea-output\b[^"]*"[^>]*?)\s+tabindex="0"')
CELL_TAB_STOP, CELL = (
    '<div class="jp-Cell-inputWrapper" tabindex="0">',
    '<div class="jp-Cell-inputWrapper">',
)  # see below
ROLE_OR_MODULE = re.compile(
    r'doc-object doc-module">\s*<h\d id="(?P<module>[\w.]+)"'  # where a module's entry begins
    r"|:(?:py:)?(?:mod|func|class|meth|attr|data|exc|obj):<code>(?P<tilde>~)?(?P<name>[\w.]+)</code>"
)


class Heading(TypedDict):
    """A table of contents entry, as mkdocs reads them (its ``get_toc``)."""

    level: int
    id: str
    name: str  # as HTML
    children: list[Heading]


def target(url: str, page: Page, files: Files) -> tuple[File, str] | None:
    """The file a relative link ``url`` in ``page`` means and a fragment for it (``""``: keep the link's own);
    None for another site's address, an absolute path, or a path that names nothing of the site."""
    if not url or urlsplit(url).scheme or url.startswith(("/", "#")):
        return None
    path = source_path(url, page)
    for candidate in (path, f"{path}/README.md", f"{path}/index.md"):
        found = files.get_file_from_path(candidate)
        if found is not None:
            return found, ""
    parts = path.removesuffix(".py").split("/")
    if parts[0] == "toolkit" and len(parts) > 1 and path.endswith(".py"):
        reference = files.get_file_from_path(f"reference/{parts[1]}.md")
        module = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        return (reference, f"#{module}") if reference is not None else None
    return None


def source_path(url: str, page: Page) -> str:
    """The path in the source tree that the relative link ``url`` of ``page`` names."""
    return posixpath.normpath(posixpath.join(posixpath.dirname(page.file.src_uri), url))


def on_page_markdown(markdown: str, page: Page, config, files: Files) -> str:
    """A link to a folder or to a module becomes a link to its page's source, which mkdocs then resolves."""

    def resolve(match: re.Match) -> str:
        found = target(match["url"], page, files)
        if found is None or found[0].src_uri == source_path(match["url"], page):  # mkdocs resolves it
            return match[0]
        link = posixpath.relpath(found[0].src_uri, posixpath.dirname(page.file.src_uri) or ".")
        return f"{match['head']}{link}{found[1] or match['fragment'] or ''}{match['tail']}"

    return MARKDOWN_LINK.sub(resolve, markdown)


def on_page_content(html: str, page: Page, config, files: Files) -> str:
    """Notebook pages: links go to pages, MathJax comes from the site, no mermaid loader, folded cells stay folded.
    API reference: Sphinx roles become cross-references. Every page: its code blocks can be reached by keyboard."""
    html = focusable_code(html)
    toc = getattr(page, "toc", None)  # a Markdown page's, made by mkdocs before this hook
    if toc is not None:
        toc.items = unfolded(list(toc), folded(html))
    if page.file.src_uri.startswith("reference/"):
        return cross_references(html)
    if not page.file.src_uri.endswith(".ipynb"):
        return html
    mathjax = posixpath.relpath(MATHJAX, posixpath.dirname(page.file.dest_uri) or ".")
    html = headings_and_contents(MERMAID_LOADER.sub("", html.replace(MATHJAX_PLACEHOLDER, f'"{mathjax}/')), page)
    notebook = Path(page.file.abs_src_path or "")
    html = fold_code(figure_alts(one_h1(html), notebook).replace(CELL_TAB_STOP, CELL), notebook)
    html = take_away(page, config["extra"].get("jupyterhub") if config else None, files) + html

    def resolve(match: re.Match) -> str:
        found = target(match["url"], page, files)
        if found is None:
            return match[0]
        return (
            f"{match['head']}{found[0].url_relative_to(page.file)}{found[1] or match['fragment'] or ''}{match['tail']}"
        )

    return HTML_LINK.sub(resolve, html)


def take_away(page: Page, hub: Mapping | None, files: Files) -> str:
    """The links a notebook page begins with: its notebook without outputs to download, and (when ``hub`` names
    the course's ``url`` and ``repository``) a link that opens it on that JupyterHub; "" when there is no download."""
    download = files.get_file_from_path(f"{DOWNLOADS}/{posixpath.basename(page.file.src_uri)}")
    if download is None:
        return ""
    links = [
        f'<a href="{download.url_relative_to(page.file)}" download>Download this notebook</a> '
        "(without outputs: run it in JupyterLab)"
    ]
    if hub and hub.get("url") and hub.get("repository"):
        url = html_lib.escape(nbgitpuller_link(hub, page.file.src_uri), quote=True)
        links.append(f'<a href="{url}">Open it on the course\'s JupyterHub</a>')
    return f'<p class="notebook-take-away">{" · ".join(links)}</p>\n'


def nbgitpuller_link(hub: Mapping, path: str) -> str:
    """A link that clones (or updates) the course's ``repository`` into the student's home on the JupyterHub at
    ``url`` and opens ``path`` (the notebook's path in that repository) in JupyterLab: nbgitpuller's ``git-pull``
    (installed in the hub's image). ``branch`` defaults to ``main``. The folder it clones into is the repository's
    name without ``.git``, named in the link (``targetpath``): nbgitpuller's own default is the URL's last part as it
    is, ``.git`` kept (or empty after a ``/``), which the notebook's path would then miss."""
    repository = str(hub["repository"])
    folder = repository.rstrip("/").removesuffix(".git").rsplit("/", 1)[-1]
    query = urlencode(
        {
            "repo": repository,
            "branch": hub.get("branch") or "main",
            "targetpath": folder,
            "urlpath": f"lab/tree/{folder}/{path}",
        }
    )
    return f"{str(hub['url']).rstrip('/')}/hub/user-redirect/git-pull?{query}"


def figure_alts(html: str, notebook: Path) -> str:
    """Each figure's ``<img>`` gets the alt text its output carries in ``notebook`` (``metadata["image/png"]["alt"]``,
    :mod:`toolkit.plots.alt`): nbconvert's lab template leaves that metadata out and writes a placeholder. A complex
    figure's longer description (``metadata["image/png"]["details"]``) follows it, and its alt says so (WCAG
    technique G74)."""
    if not notebook.is_file():  # a page made by hand (the tests')
        return html
    outputs = [o for c in json.loads(notebook.read_text()).get("cells", []) for o in c.get("outputs", [])]
    said = {
        "".join(o["data"]["image/png"].split()): o.get("metadata", {}).get("image/png", {})
        for o in outputs
        if "image/png" in o.get("data", {})
    }

    def put(match: re.Match) -> str:
        found = said.get("".join(match["data"].split()), {})
        alt, parts = found.get("alt"), found.get("details") or []
        if not alt:
            return match[0]
        alt += f" {plots_alt.DESCRIBED_BELOW}" if parts else ""
        tag = re.sub(r'\s\balt="[^"]*"', "", match[0])
        return tag.replace("<img", f'<img alt="{html_lib.escape(alt, quote=True)}"', 1) + plots_alt.details_html(parts)

    return IMAGE.sub(put, html)


def one_h1(html: str) -> str:
    """The page's first ``h1`` stays; any later one (a notebook output's title) becomes an ``h2``."""
    count = 0

    def demote(match: re.Match) -> str:
        nonlocal count
        count += 1
        return match[0] if count == 1 else f"<h2{match['attrs']}>{match['body']}</h2>"

    return H1.sub(demote, html)


def focusable_code(html: str) -> str:
    """Each block of code that scrolls sideways becomes a named region the keyboard can reach (:data:`REGION`) on the
    element that scrolls: a code cell's ``<div class="highlight-ipynb">``, the ``<code>`` in a Markdown page's
    ``<pre>`` (material's stylesheet scrolls it, and its script makes it a tab stop, with no name, when it is too wide;
    a notebook's Markdown writes a fence without a language so, with no ``<div>``), else the ``<pre>`` in
    ``<div class="highlight">`` (a notebook's Markdown). A notebook output is no tab stop (nbconvert's ``tabindex``
    dropped): it does not scroll, and ``accessibility.js`` names one that does."""

    def region(m: re.Match) -> str:
        if m["cell"]:
            return f'<div class="{m["cls"]}" {REGION}>{m["space"]}<pre{m["pre"]}'
        return f'<div class="{m["cls"]}">{m["space"]}<pre {REGION}{m["pre"]}'

    html = BARE_CODE.sub(rf"\g<pre><code {REGION}", CODE_BLOCK.sub(region, html))
    return OUTPUT_TAB_STOP.sub(r"\1", html)


def headings_and_contents(html: str, page: Page) -> str:
    """Give a notebook page's headings unique ids (a second "Try this" becomes ``try-this_1``) and make its table
    of contents from them: mkdocs-jupyter's own is made from the Markdown with code removed, so an entry for a
    heading with code in it, or for a repeated one, pointed at no heading."""
    seen: dict[str, int] = {}
    tokens: list[Heading] = []

    def unique(match: re.Match) -> str:
        given = match["id"]
        seen[given] = seen.get(given, -1) + 1
        new = given if seen[given] == 0 else f"{given}_{seen[given]}"
        name = ANCHOR_LINK.sub("", match["body"]).strip()
        tokens.append({"level": int(match["level"]), "id": new, "name": name, "children": []})
        return match[0].replace(f'"{given}"', f'"{new}"').replace(f'"#{given}"', f'"#{new}"')

    html = HEADING.sub(unique, html)
    page.toc = get_toc(nested(tokens))
    return html


def folded(html: str) -> set[str]:
    """The ids of the headings inside a ``<details>`` fold of ``html``, at any depth of folds."""
    depth, ids = 0, set()
    for match in FOLD_OR_HEADING.finditer(html):
        if match["id"] is None:
            depth += -1 if match["close"] else 1
        elif depth > 0:
            ids.add(match["id"])
    return ids


def unfolded(entries: list, hidden: set[str]) -> list:
    """A table of contents' ``entries`` without those whose heading is folded away (review r28f, item 7: the results
    page's contents listed each of its twenty folded tables); their anchors still work."""
    kept = [entry for entry in entries if entry.id not in hidden]
    for entry in kept:
        entry.children = unfolded(list(entry.children), hidden)
    return kept


def nested(tokens: list[Heading]) -> list[Heading]:
    """Flat heading tokens in page order, each put among the children of the last one above its level."""
    roots: list[Heading] = []
    open_: list[Heading] = []  # the current chain of headings, outermost first
    for token in tokens:
        while open_ and open_[-1]["level"] >= token["level"]:
            open_.pop()
        (open_[-1]["children"] if open_ else roots).append(token)
        open_.append(token)
    return roots


def cross_references(html: str) -> str:
    """``:func:`name``` (as mkdocstrings renders it) becomes a cross-reference that mkdocs-autorefs links to the
    object, tried as a name in the module whose entry it sits in, then as written; plain code when not found."""
    module = ""

    def link(match: re.Match) -> str:
        nonlocal module
        if match["module"]:
            module = match["module"]
            return match[0]
        name = match["name"]
        shown = name.rsplit(".", 1)[-1] if match["tilde"] else name
        scoped = f"{module}.{name}" if module and not name.startswith("toolkit.") else name
        return f'<autoref identifier="{scoped}" slug="{name}" optional><code>{shown}</code></autoref>'

    return ROLE_OR_MODULE.sub(link, html)
