"""The course website: the chapters, tutorials, assignments and docs as one static, searchable site.

``make site`` builds it into ``site/`` (``TOOLKIT_QUICK=1 make site``: quick-sized chapters), in two steps:

1. :func:`assemble` gathers a source tree under ``build/site/docs`` that mirrors the repository's paths
   (so a link written in any source still points at its page): the README as the home page, the notebooks
   and tutorials executed by :func:`~tools.notebook_runner.run_notebook` (the one way notebooks run;
   trained models come from the notebooks' cache; a notebook whose inputs have not changed since the last
   build is reused from ``build/site/executed``, :mod:`tools.executed_notebooks`), the assignments' student
   versions (what ``otter assign`` hands out, never the master), every notebook without outputs to download,
   docs/, one API reference page per package, and MathJax;
2. :func:`render` runs mkdocs on it (``mkdocs.yml``: mkdocs-material, mkdocs-jupyter on the executed
   notebooks, mkdocstrings on the docstrings); :mod:`tools.site_hooks` makes links land on pages
   and keeps every page free of files from other hosts, so the site works from an intranet or from disk.

    python -m tools.site --out site             # full size, as `make site` (from the repository's root)
    python -m tools.site --quick --out site     # quick mode
"""

from __future__ import annotations

import argparse
import ast
import contextlib
import functools
import importlib.util
import os
import re
import shutil
import sys
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

import nbformat

from toolkit.teaching import grading
from toolkit.teaching.notebook import QUICK_ENV, is_quick
from tools.executed_notebooks import run_or_reuse
from tools.notebook_runner import NotebookRun, each_in_a_worker, image_widget_output

ROOT = Path(__file__).resolve().parents[1]  # the repository (this file is tools/site.py)
CONFIG = ROOT / "mkdocs.yml"
PAGES = ("README.md", "docs/*.md", "docs/*.png", "tutorials/*.md", "tutorials/assignments/README.md")
CHAPTERS = "notebooks/[0-9][0-9]_*.ipynb"
TUTORIALS = "tutorials/*.ipynb"
INSTRUCTORS_PAGES = "tutorials/instructors_*.md"  # after the instructors' guide in the sidebar
# docs/ pages in the nav, then any others
DOCS_ORDER = (
    "results",
    "fidelity",
    "benchmarks",
    "planner_race",
    "benchmarks_history",
    "checker_engineering",
    "design",
    "viewer",
)
PACKAGES = (
    "util",
    "geometry",
    "scenarios",
    "learning",
    "planning",
    "plots",
    "experiments",
    "viewer",
    "teaching",
    "cli",
)
DOWNLOADS = "downloads"  # the notebooks without outputs, one folder (ignored by mkdocs-jupyter in mkdocs.yml)
MATHJAX = "assets/mathjax"  # MathJax 2.7 from jupyter-server-mathjax, served from the site itself
# its equations out of the tab order: a focusable equation has no accessible name (WCAG 4.1.2); screen readers
# read each one from the MathML MathJax hides beside it, and a wide one still scrolls as a named region
SITE_FILES = {  # the site's own files in docs/site/, and where the site serves them (named in mkdocs.yml)
    "docs/site/iframe-worker-shim.js": "assets/javascripts/iframe-worker-shim.js",  # extra.polyfills
    "docs/site/notebook-pages.css": "assets/stylesheets/notebook-pages.css",  # extra_css
    "docs/site/accessibility.css": "assets/stylesheets/accessibility.css",  # extra_css
    "docs/site/accessibility.js": "assets/javascripts/accessibility.js",  # extra_javascript
}
MATHJAX_CONFIG = """MathJax.Hub.Config({
  "HTML-CSS": {availableFonts: [], preferredFont: null, webFont: "STIX-Web", imageFont: null},
  SVG: {font: "STIX-Web"},
  menuSettings: {inTabOrder: false}
});
MathJax.Ajax.loadComplete("[MathJax]/config/toolkit.js");
"""
ANSI_COLOR = re.compile(r"\x1b\[[0-9;]*m")  # in tracebacks' text
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"
WIDGET_STATE = "application/vnd.jupyter.widget-state+json"
LIVE_ONLY_IN_JUPYTERLAB = (
    '<div class="admonition note live-in-jupyterlab"><p class="admonition-title">Live in JupyterLab</p>'
    "<p>This cell's controls (ipywidgets) work when you run the notebook in JupyterLab (<code>make lab</code>); "
    "this page shows what they display at their starting values.</p></div>"
)


@dataclass
class Site:
    """A built site: where it is, and each executed notebook's run (its outputs, errors and running time)."""

    out: Path
    runs: dict[str, NotebookRun] = field(default_factory=dict)  # by path in the repository
    assemble_s: float = 0.0
    render_s: float = 0.0


def build_site(
    out: str | Path = ROOT / "site",
    *,
    quick: bool = False,
    work: str | Path = ROOT / "build" / "site",
    jobs: int = 1,
) -> Site:
    """Build the static site into ``out`` (replaced), its sources under ``work``; quick-sized when ``quick``;
    ``jobs`` notebooks executed at a time (one for a full-size build, whose chapters time things)."""
    docs = Path(work) / "docs"
    began = time.perf_counter()
    runs = assemble(docs, quick=quick, executed=Path(work) / "executed", jobs=jobs)
    assembled = time.perf_counter()
    render(docs, Path(out))
    return Site(Path(out), runs, assembled - began, time.perf_counter() - assembled)


def assemble(docs: Path, *, quick: bool = False, executed: Path | None = None, jobs: int = 1) -> dict[str, NotebookRun]:
    """Write the site's source tree into ``docs`` (replaced); returns the runs of the notebooks it executed.

    A notebook whose inputs have not changed since it was executed into ``executed`` (default: beside ``docs``)
    is not run again (:mod:`tools.executed_notebooks`); ``jobs`` run at a time, each in a worker process
    (:func:`~tools.notebook_runner.each_in_a_worker`). Each notebook is also offered to download as a student
    runs it, without outputs (:data:`DOWNLOADS`): chapters and tutorials as written, assignments' student versions.
    Raises ``RuntimeError`` naming the notebook when one fails: a chapter with a traceback is no page to publish.
    """
    executed = executed or docs.parent / "executed"
    shutil.rmtree(docs, ignore_errors=True)
    for pattern in PAGES:
        for source in sorted(ROOT.glob(pattern)):
            copy(source, docs / source.relative_to(ROOT))
    for own, served in SITE_FILES.items():
        copy(ROOT / own, docs / served)
    runs = {}
    sources = sorted(ROOT.glob(CHAPTERS)) + sorted(ROOT.glob(TUTORIALS))
    with kernel_environment(quick):
        into_docs = functools.partial(execute_into, docs=docs, quick=quick, executed=executed)
        for source, (run, reused) in each_in_a_worker(into_docs, sources, jobs=jobs):
            name = str(source.relative_to(ROOT))
            runs[name] = run
            took = (
                f"reused, unchanged since it ran ({runs[name].wall_s:.0f} s)"
                if reused
                else f"{runs[name].wall_s:.0f} s"
            )
            print(f"{name}: {took}, {runs[name].figures} figures", flush=True)
            offer_download(source, docs)
    for name in grading.assignment_names():
        student = student_notebook(name)
        copy(student, docs / grading.master(name).relative_to(ROOT))
        offer_download(student, docs)
    shutil.copytree(mathjax_folder(), docs / MATHJAX)
    (docs / MATHJAX / "config" / "toolkit.js").write_text(MATHJAX_CONFIG)
    write_reference(docs / "reference")
    return runs


def copy(source: Path, target: Path) -> None:
    target.parent.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(source, target)


@contextlib.contextmanager
def kernel_environment(quick: bool) -> Iterator[None]:
    """Kernels started inside see quick mode on or off as asked, and draw figures inline; restored afterwards."""
    before = {key: os.environ.get(key) for key in (QUICK_ENV, "MPLBACKEND")}
    set_environment({QUICK_ENV: "1" if quick else None, "MPLBACKEND": "module://matplotlib_inline.backend_inline"})
    try:
        yield
    finally:
        set_environment(before)


def set_environment(values: dict[str, str | None]) -> None:
    """Set each variable to its value; None removes it."""
    for key, value in values.items():
        if value is None:
            os.environ.pop(key, None)
        else:
            os.environ[key] = value


def offer_download(source: Path, docs: Path) -> None:
    """``source`` without outputs in the site's :data:`DOWNLOADS` folder, where each notebook page links it."""
    target = docs / DOWNLOADS / source.name
    if target.exists():
        raise ValueError(f"two notebooks are named {source.name}: their downloads would be one file")
    notebook = nbformat.read(source, as_version=4)
    for cell in notebook.cells:
        if cell.cell_type == "code":
            cell.outputs, cell.execution_count = [], None
    target.parent.mkdir(parents=True, exist_ok=True)
    nbformat.write(notebook, target)


def execute_into(source: Path, *, docs: Path, quick: bool, executed: Path) -> tuple[NotebookRun, bool]:
    """:func:`execute` of ``source`` to its place in ``docs``."""
    return execute(source, docs / source.relative_to(ROOT), quick=quick, executed=executed)


def execute(source: Path, target: Path, *, quick: bool, executed: Path) -> tuple[NotebookRun, bool]:
    """Run ``source`` from its own folder, or reuse its run kept in ``executed`` (then ``True``), and write it, with
    its outputs and widgets made static, to ``target``."""
    failed = f"{source.relative_to(ROOT)} failed while building the site"
    name = str(source.relative_to(ROOT))
    try:
        run, reused = run_or_reuse(source, executed, name, quick=quick, timeout=600 if quick else 3600)
    except Exception as error:  # nbclient's CellExecutionError (its last line names the error) or a dead kernel
        raise RuntimeError(f"{failed}: {ANSI_COLOR.sub('', str(error)).strip().splitlines()[-1]}") from error
    if run.problem() is not None:
        raise RuntimeError(f"{failed}: {run.problem()}")
    target.parent.mkdir(parents=True, exist_ok=True)
    nbformat.write(static_widgets(run.notebook), target)
    return run, reused


def static_widgets(nb: nbformat.NotebookNode) -> nbformat.NotebookNode:
    """Replace each widget in ``nb`` by what it displayed at its starting values, with a note that it is live only
    in JupyterLab where it has controls; a progress bar (tqdm's) is dropped.

    A page has no kernel to drive a slider, and rendering saved widget state would need the widget
    manager's scripts from a CDN; the figure an ``interact`` showed (in the saved state of its ``Output`` widget)
    and the picture an ``Image`` widget held are kept, so the page still shows every figure.
    """
    state = nb.metadata.pop("widgets", {}).get(WIDGET_STATE, {}).get("state", {})
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        outputs = []
        for output in cell.outputs:
            view = output.get("data", {}).get(WIDGET_VIEW)
            if view is None:
                outputs.append(output)
                continue
            models = {model.get("model_name") for model in tree(view["model_id"], state)}
            if models & PROGRESS:
                continue  # a progress bar: nothing a reader of the page needs
            if any(name not in DISPLAY_ONLY for name in models):
                outputs.append(nbformat.v4.new_output("display_data", data={"text/html": LIVE_ONLY_IN_JUPYTERLAB}))
            outputs.extend(shown_by(view["model_id"], state))
        cell.outputs = outputs
    return nb


PROGRESS = {"FloatProgressModel", "IntProgressModel"}
DISPLAY_ONLY = {  # widgets that show something but take no input: no "Live in JupyterLab" note for these alone
    "OutputModel", "ImageModel", "HTMLModel", "HTMLMathModel", "LabelModel", "BoxModel", "HBoxModel", "VBoxModel",
    "GridBoxModel", *PROGRESS,
}  # fmt: skip


def tree(model_id: str, state: dict) -> list[dict]:
    """The widget ``model_id`` and every widget inside it (its ``children``), as saved in ``state``."""
    model = state.get(model_id)
    if model is None:
        return []
    children = model.get("state", {}).get("children", [])
    return [model] + [m for child in children for m in tree(str(child).removeprefix("IPY_MODEL_"), state)]


def shown_by(model_id: str, state: dict) -> list[nbformat.NotebookNode]:
    """The outputs the widget ``model_id`` and the widgets inside it displayed: its ``Output`` widgets' outputs, its
    ``Image`` widgets' pictures (their ``tooltip`` as the picture's alt text) and its ``HTML`` widgets' text (a
    picture's longer description, :func:`toolkit.plots.alt.details_html`)."""
    model = state.get(model_id)
    if model is None:
        return []
    if model.get("model_name") == "OutputModel":
        return [nbformat.from_dict(o) for o in model.get("state", {}).get("outputs", [])]
    if model.get("model_name") == "ImageModel":
        return image_widget_output(model)
    if model.get("model_name") == "HTMLModel" and model.get("state", {}).get("value"):
        return [nbformat.v4.new_output("display_data", data={"text/html": model["state"]["value"]})]
    children = model.get("state", {}).get("children", [])
    return [o for child in children for o in shown_by(str(child).removeprefix("IPY_MODEL_"), state)]


def student_notebook(name: str) -> Path:
    """The student version of assignment ``name`` that ``otter assign`` wrote; built first when missing or older
    than its master (:func:`toolkit.teaching.grading.build`, as ``make assignments``)."""
    master = grading.master(name)
    student = master.parent / "dist" / "student" / master.name
    if not student.is_file() or student.stat().st_mtime < master.stat().st_mtime:
        grading.build(name)
    return student


def mathjax_folder() -> Path:
    """MathJax 2.7's files, as the PyPI package ``jupyter-server-mathjax`` ships them."""
    spec = importlib.util.find_spec("jupyter_server_mathjax")
    if spec is None or spec.origin is None:
        raise FileNotFoundError("the site serves MathJax itself: pip install jupyter-server-mathjax")
    return Path(spec.origin).parent / "static"


def packages() -> list[str]:
    """The packages of ``toolkit/`` in the layers' order (any new one last), each to get a reference page."""
    found = {p.parent.name for p in (ROOT / "toolkit").glob("*/__init__.py")} | {"scenarios"}
    return [name for name in PACKAGES if name in found] + sorted(found - set(PACKAGES))


def docstring(package: str) -> str:
    """A package's docstring (read without importing it)."""
    folder = ROOT / "toolkit" / package
    source = folder / "__init__.py" if folder.is_dir() else folder.with_suffix(".py")
    return (ast.get_docstring(ast.parse(source.read_text())) or "").strip()


def summary(package: str) -> str:
    """The first line of a package's docstring."""
    text = docstring(package)
    return text.splitlines()[0] if text else ""


def modules(package: str) -> list[str]:
    """The modules of a package in the reading order its docstring gives (``toolkit.geometry.robots``, ...),
    any it does not name last, by name; none for a single-module package (``toolkit.scenarios``)."""
    folder = ROOT / "toolkit" / package
    found = sorted(p.stem for p in folder.glob("*.py") if not p.stem.startswith("_")) if folder.is_dir() else []
    named = list(dict.fromkeys(re.findall(rf"toolkit\.{package}\.(\w+)", docstring(package))))
    return [m for m in named if m in found] + [m for m in found if m not in named]


def reference_page(package: str) -> str:
    """The mkdocstrings page of one package: its docstring, then each module in reading order."""
    blocks = [f"::: toolkit.{package}\n    options:\n      show_submodules: false\n"]
    for module in modules(package):
        blocks.append(
            f"::: toolkit.{package}.{module}\n    options:\n      heading_level: 2\n      show_root_full_path: false\n"
        )
    return "\n".join(blocks)


def write_reference(folder: Path) -> None:
    """One mkdocstrings page per package (its modules below it, in reading order) and an index listing them."""
    folder.mkdir(parents=True, exist_ok=True)
    lines = ["# API reference", "", "Generated from the docstrings; one page per package of `toolkit/`, in the"]
    lines += ["order of its layers (a package imports only from those above it); on each page its modules follow"]
    lines += ["the reading order of the package's docstring.", ""]
    for package in packages():
        (folder / f"{package}.md").write_text(reference_page(package))
        lines.append(f"- [`toolkit.{package}`]({package}.md): {summary(package)}")
    (folder / "index.md").write_text("\n".join(lines) + "\n")


def in_order(paths: list[str], text: str) -> list[str]:
    """``paths`` in the order ``text`` first mentions their file names (unmentioned ones last, by name)."""
    position = {p: text.find(Path(p).name) for p in paths}
    return sorted(paths, key=lambda p: (position[p] < 0, position[p], p))


def navigation(docs: Path) -> list:
    """The sidebar: home, chapters, tutorials, assignments, docs, API reference."""
    found = lambda pattern: sorted(str(p.relative_to(docs)) for p in docs.glob(pattern))
    tutorials = in_order(found(TUTORIALS), (docs / "tutorials" / "README.md").read_text())
    named = [f"docs/{stem}.md" for stem in DOCS_ORDER if (docs / "docs" / f"{stem}.md").is_file()]
    return [
        {"Home": "README.md"},
        {"Chapters": found(CHAPTERS)},
        {"Tutorials": ["tutorials/README.md", *tutorials, "tutorials/instructors.md", *found(INSTRUCTORS_PAGES)]},
        {"Assignments": ["tutorials/assignments/README.md", *found("tutorials/assignments/*/*.ipynb")]},
        {"Docs": named + [p for p in found("docs/*.md") if p not in named]},
        {"API reference": ["reference/index.md", *({f"toolkit.{p}": f"reference/{p}.md"} for p in packages())]},
    ]


def page_html(markdown_text: str) -> str:
    """The HTML that mkdocs makes of one Markdown page's body (``mkdocs.yml``'s Markdown extensions, no theme):
    what a test reads to see a list render as a list without building the site."""
    import markdown  # type: ignore[import-untyped]  # no stubs installed; mkdocs renders with it
    import yaml

    config = yaml.safe_load(CONFIG.read_text())
    names = [e if isinstance(e, str) else next(iter(e)) for e in config["markdown_extensions"]]
    options = {next(iter(e)): next(iter(e.values())) for e in config["markdown_extensions"] if isinstance(e, dict)}
    return markdown.markdown(markdown_text, extensions=names, extension_configs=options)


def render(docs: Path, out: Path) -> None:
    """Run mkdocs (``mkdocs.yml``) on the source tree ``docs``, writing the site into ``out`` (replaced)."""
    from mkdocs.commands import build
    from mkdocs.config import load_config

    config = load_config(str(CONFIG), docs_dir=str(docs), site_dir=str(out.resolve()), nav=navigation(docs))
    build.build(config)
    (out / ".nojekyll").touch()  # GitHub Pages serves files named _* (assets/_mkdocstrings.css) only so


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m tools.site", description="Build the course website.")
    parser.add_argument("--out", type=Path, default=ROOT / "site", help="where the site goes (default: site/)")
    parser.add_argument("--quick", action="store_true", help=f"quick-sized chapters (also when {QUICK_ENV}=1)")
    parser.add_argument(
        "--jobs",
        type=int,
        default=1,
        help="notebooks executed at a time (default 1: a full-size chapter times things, so give it the machine)",
    )
    args = parser.parse_args(argv)
    if args.jobs < 1:
        parser.error(f"--jobs must be at least 1, not {args.jobs}")
    site = build_site(args.out, quick=args.quick or is_quick(), jobs=args.jobs)
    print(f"site: {site.out}/index.html (sources {site.assemble_s:.0f} s, mkdocs {site.render_s:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
