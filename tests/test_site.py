"""The course website (``make site``, :mod:`tools.site`): built once in quick mode, then read as a
student's browser reads it.

The module's build executes every chapter and tutorial in quick mode with this session's model cache, renders
the assignments' student versions and the API reference, and is checked for what a course needs: every figure
on its page, no file from another host, no solution or hidden test, and (in headless Chromium, served from
127.0.0.1 and opened from disk) loaded images, the embedded viewer, typeset math, search and unbroken links;
and accessible: every figure with alt text, every embedded scene titled and summarized, no serious or critical
axe-core violation on any page (:mod:`tools.accessibility`).
The fast tests hold the pieces (widgets made static, links resolved) against hand-made inputs.
"""

from __future__ import annotations

import html
import itertools
import os
import re
import time
from collections.abc import Iterator
from html.parser import HTMLParser
from pathlib import Path
from urllib.error import HTTPError
from urllib.parse import parse_qs, urldefrag, urljoin, urlsplit
from urllib.request import urlopen

import chapter_claims
import nbformat
import pytest
from mkdocs.structure.files import File, Files

from toolkit.plots import alt
from toolkit.teaching import findings, grading
from toolkit.viewer import browser as viewer_browser
from tools import accessibility, handout, site_fold, site_hooks
from tools.site import LIVE_ONLY_IN_JUPYTERLAB, Site, build_site, modules, page_html, static_widgets

ROOT = Path(__file__).resolve().parents[1]
CHAPTERS = sorted((ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))
TUTORIALS = sorted((ROOT / "tutorials").glob("*.ipynb"))
needs_chromium = pytest.mark.skipif(
    viewer_browser.find_chromium() is None,
    reason="no Chromium installed (run `make browser` or `apt-get install chromium`)",
)


@pytest.fixture(scope="module")
def site(tmp_path_factory, notebook_cache) -> Site:
    """The site in quick mode, built once for this module (its build time is printed: ``pytest -s``)."""
    root = tmp_path_factory.mktemp("site")
    with pytest.MonkeyPatch.context() as env:
        env.setenv("TOOLKIT_CACHE", str(notebook_cache))
        began = time.perf_counter()
        jobs = len(os.sched_getaffinity(0))  # quick kernels keep about one core busy each: one per core at a time
        built = build_site(root / "site", quick=True, work=root / "build", jobs=jobs)
    took = time.perf_counter() - began
    print(f"\nsite built in {took:.0f} s (sources {built.assemble_s:.0f} s, mkdocs {built.render_s:.0f} s)")
    return built


def page_of(site: Site, source: Path) -> Path:
    return site.out / source.relative_to(ROOT).with_suffix(".html")


# ---- the built site, read as files ----


@pytest.mark.slow
def test_every_chapter_and_tutorial_ran_and_shows_every_figure_it_made(site):
    for source in CHAPTERS + TUTORIALS:
        run = site.runs[str(source.relative_to(ROOT))]
        assert run.figures >= (1 if source in CHAPTERS else 2), f"{source.name} showed {run.figures} figures"
        page = page_of(site, source).read_text()
        assert page.count('src="data:image/png;base64,') == run.figures, f"{source.name}: figures lost on the page"
        assert "Traceback" not in html.unescape(re.sub(r"<[^>]+>", "", page)), source.name


@pytest.mark.slow
def test_every_chapter_prints_the_claims_its_prose_relies_on(site):
    """The sentences each chapter generates from its numbers exist and agree with its tables (issue 37)."""
    found = {s.name: chapter_claims.problems(s.name, site.runs[str(s.relative_to(ROOT))].notebook) for s in CHAPTERS}
    assert not any(found.values()), found


@pytest.mark.slow
def test_widgets_are_a_visible_note_and_no_widget_state_is_left(site):
    notes = {s.name: page_of(site, s).read_text().count("live-in-jupyterlab") for s in CHAPTERS}
    assert notes["01_workspaces_and_collision.ipynb"] >= 1, notes  # its interact cells
    for source in CHAPTERS + TUTORIALS:
        page = page_of(site, source).read_text()
        assert "widget-state+json" not in page and "widget-view+json" not in page, source.name


@pytest.mark.slow
def test_the_site_has_every_page_a_student_needs(site):
    expected = ["index.html", "docs/results.html", "docs/fidelity.html", "docs/benchmarks.html", "docs/design.html"]
    expected += ["docs/benchmarks_history.html", "docs/checker_engineering.html", "docs/planner_race.html"]
    expected += ["docs/viewer.html", "tutorials/index.html", "tutorials/instructors.html", "reference/index.html"]
    expected += ["tutorials/instructors_jupyterhub.html"]
    expected += [f"tutorials/assignments/{name}/{name}.html" for name in grading.assignment_names()]
    expected += [f"reference/{p}.html" for p in ("geometry", "learning", "planning", "experiments", "plots")]
    expected += [f"reference/{p}.html" for p in ("viewer", "teaching", "util", "cli", "scenarios")]
    expected += [str(page_of(site, s).relative_to(site.out)) for s in CHAPTERS + TUTORIALS]
    assert [p for p in expected if not (site.out / p).is_file()] == []
    geometry = (site.out / "reference" / "geometry.html").read_text()
    assert 'id="toolkit.geometry.robots.BoxRobot"' in geometry and 'class="autorefs autorefs-internal"' in geometry
    shown = re.findall(r'<h2 id="toolkit\.geometry\.(\w+)"', geometry)  # the modules, in the page's order
    assert shown == modules("geometry") and shown[:2] == ["robots", "workspace"]


@pytest.mark.slow
def test_every_notebook_page_links_its_notebook_without_outputs_and_assignments_their_student_version(site):
    masters = [grading.master(name) for name in grading.assignment_names()]
    for source in CHAPTERS + TUTORIALS + masters:
        page = page_of(site, source)
        link = re.search(r'<p class="notebook-take-away"><a href="([^"]+)" download>', page.read_text())
        assert link, f"{source.name}: no download link"
        download = (page.parent / link[1]).resolve()
        assert download == site.out / "downloads" / source.name
        notebook = nbformat.read(download, as_version=4)
        assert not any(c.get("outputs") or c.get("execution_count") for c in notebook.cells), source.name
        if source in masters:  # the student version: what otter assign hands out
            assert notebook.metadata["otter"]["assignment_name"] == source.stem
        else:
            assert [c.source for c in notebook.cells] == [c.source for c in nbformat.read(source, as_version=4).cells]


@pytest.mark.slow
def test_every_figure_of_every_chapter_and_tutorial_has_a_text_alternative(site):
    lacking = {}
    for name, run in site.runs.items():
        outputs = [o for cell in run.notebook.cells if cell.cell_type == "code" for o in cell.outputs]
        images = [o for o in outputs if "image/png" in o.get("data", {})]
        assert images, name
        alts = [o.get("metadata", {}).get("image/png", {}).get("alt", "").strip() for o in images]
        read_from_titles = [a for a in alts if alt.is_fallback(a)]  # the guard's text: nobody described the data
        if not all(alts) or read_from_titles:
            lacking[name] = (
                f"{alts.count('')} of {len(images)} figures without, {len(read_from_titles)} read from titles"
            )
    assert lacking == {}  # in the notebook (JupyterLab shows it too) ...
    pages = {str(p.relative_to(site.out)): p.read_text() for p in site.out.rglob("*.html")}
    assert [p for p, text in pages.items() if 'alt="No description has been provided' in text] == []  # nbconvert's
    assert {p: n for p, text in pages.items() if (n := len(re.findall(r'<img\b(?![^>]*\balt="[^"]+")', text)))} == {}


SHOWN_UNDER = rf'{re.escape(alt.DESCRIBED_BELOW)}"[^>]*>\s*<details class="figure-described">'  # an img, then it


@pytest.mark.slow
def test_every_figure_of_several_panels_is_described_in_full_under_it(site):
    """A figure of several panels (and a map, a 3D view, Algorithm 1's steps) carries a longer description from its
    data, never the guard's read from titles (:func:`toolkit.plots.alt.details`), and its page shows it under it:
    a figure output's (its metadata's ``details``) and a still picture's (:func:`~toolkit.plots.alt.figure_html`)."""
    guarded, unshown, described = {}, {}, 0
    for name, run in site.runs.items():
        outputs = [o for cell in run.notebook.cells if cell.cell_type == "code" for o in cell.outputs]
        said = [o.get("metadata", {}).get("image/png", {}) for o in outputs if "image/png" in o.get("data", {})]
        details = [s["details"] for s in said if s.get("details")]
        html_outputs = ["".join(o["data"]["text/html"]) for o in outputs if "text/html" in o.get("data", {})]
        in_html = sum(len(re.findall(SHOWN_UNDER, text)) for text in html_outputs)
        described += len(details) + in_html
        read_from_titles = [p["name"] for d in details for p in d if alt.is_fallback(p["name"])]
        read_from_titles += [text[:80] for text in html_outputs if f"<strong>{alt.FALLBACK}" in text]
        if read_from_titles:
            guarded[name] = read_from_titles
        shown = len(re.findall(SHOWN_UNDER, page_of(site, ROOT / name).read_text()))
        if shown != len(details) + in_html:
            unshown[name] = f"{shown} of {len(details) + in_html} described under the figure"
    assert guarded == {}
    assert unshown == {}
    assert described >= 20  # the chapters' maps, grids, steps and crossover curves (a test that can fail)


@pytest.mark.slow
def test_the_embedded_scenes_are_titled_and_told_in_words(site):
    page = page_of(site, ROOT / "notebooks" / "05_3d_scenes.ipynb").read_text()
    frames = re.findall(r"<iframe\b[^>]*>", page)
    assert len(frames) >= 3
    titles = [re.search(r'title="([^"]*)"', f).group(1) for f in frames]
    named = r"3D (scene|animation) of (3DO|3DC-7|3DC-9) \(\d+ blocks\) with the (youBot|box chain) \(\d DoF\)"  # r28e
    assert all(re.match(named, t) for t in titles)
    assert len(set(titles)) == len(titles)  # every view titled apart: the animation from its scene (issue 47)
    summaries = re.findall(r'<p class="scene-summary">([^<]*)</p>', page)
    assert len(summaries) == len(frames) and all("valid" in s for s in summaries)
    assert any(re.search(r"Samples: \d+ valid \(circles\), \d+ in collision \(diamonds\)", s) for s in summaries)
    assert any(re.search(r"Path: \d+ configurations, drawn from start to goal\.", s) for s in summaries)


@pytest.mark.slow
def test_no_solution_or_hidden_test_of_any_assignment_is_in_the_site(site):
    assert all(handout.secret_lines(name) for name in grading.assignment_names())  # there is something to find
    assert handout.find_secrets(site.out) == []


LOADS = [  # what makes a browser fetch a URL: tags' src/href, CSS url() and @import, scripts' imports and workers
    re.compile(
        r"<(?:script|img|iframe|source|audio|video|embed|track|input)\b[^>]*?\bsrc\s*=\s*[\"']?(https?:)?//", re.I
    ),
    re.compile(r"<link\b[^>]*?\bhref\s*=\s*[\"']?(https?:)?//", re.I),
    re.compile(r"\bposter\s*=\s*[\"']?(https?:)?//|\bsrcset\s*=\s*[\"'][^\"']*https?://", re.I),
    re.compile(r"url\(\s*[\"']?(https?:)?//|@import\s+(url\()?[\"']?(https?:)?//", re.I),
    re.compile(r"(?:\bimport\s*\(|\bfrom|importScripts\s*\(|new\s+Worker\s*\(|fetch\s*\()\s*[\"'`](https?:)?//", re.I),
]


def remote_loads(text: str) -> list[str]:
    """Snippets of ``text`` (HTML, CSS or JavaScript) that load something from another host, srcdoc documents too."""
    found = [text[max(0, m.start() - 40) : m.end() + 40] for pattern in LOADS for m in pattern.finditer(text)]
    for document in re.findall(r'srcdoc="([^"]*)"', text):
        found += remote_loads(html.unescape(document))
    return found


def test_the_remote_load_finder_finds_each_kind_of_load():
    for load in (
        '<script src="https://cdn.example/x.js">',
        "<link rel=stylesheet href='//fonts.example/css'>",
        '<img alt="" src="http://example.com/a.png">',
        "body { background: url(https://example.com/a.png) }",
        '@import "https://fonts.example/css";',
        'await import("https://cdn.example/mermaid.mjs")',
        '<iframe srcdoc="&lt;script src=&quot;https://cdn.example/x.js&quot;&gt;"></iframe>',
    ):
        assert remote_loads(load), load
    assert not remote_loads('<a href="https://viser.studio">Viser</a> <svg xmlns="http://www.w3.org/2000/svg">')


@pytest.mark.slow
def test_no_page_loads_a_script_stylesheet_font_or_image_from_another_host(site):
    files = [p for p in site.out.rglob("*") if p.suffix in (".html", ".js", ".css", ".mjs")]
    assert len(files) > 50
    found = {
        str(p.relative_to(site.out)): loads for p in files if (loads := remote_loads(p.read_text(errors="replace")))
    }
    assert found == {}


# ---- the pieces, on hand-made inputs ----


def test_a_reference_page_follows_its_packages_reading_order_and_misses_no_module():
    files = {p.stem for p in (ROOT / "toolkit" / "planning").glob("*.py") if p.stem != "__init__"}
    order = modules("planning")
    assert sorted(order) == sorted(files) and order[:3] == ["sampling", "local_planner", "roadmap"]
    assert order.index("paper_prm") < order.index("lazy_prm")  # Algorithm 1 before the planner that extends it
    assert modules("scenarios") == []  # a module, not a package: its page is the module itself


def test_a_widget_becomes_a_note_followed_by_what_its_output_widget_showed():
    figure = nbformat.v4.new_output("display_data", data={"image/png": "iVBORw0KGgo=", "text/plain": "<Figure>"})
    view = {"model_id": "box", "version_major": 2, "version_minor": 0}
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell("interact(f, seed=1)")]
    nb.cells[0].outputs = [
        nbformat.v4.new_output("display_data", data={"application/vnd.jupyter.widget-view+json": view})
    ]
    state = {
        "box": {
            "model_name": "VBoxModel",
            "state": {"children": ["IPY_MODEL_slider", "IPY_MODEL_out", "IPY_MODEL_told", "IPY_MODEL_empty"]},
        },
        "slider": {"model_name": "IntSliderModel", "state": {"value": 1}},
        "out": {"model_name": "OutputModel", "state": {"outputs": [dict(figure)]}},
        "told": {"model_name": "HTMLModel", "state": {"value": "<details>the figure in words</details>"}},
        "empty": {"model_name": "HTMLModel", "state": {"value": ""}},
    }
    nb.metadata["widgets"] = {"application/vnd.jupyter.widget-state+json": {"state": state}}
    outputs = static_widgets(nb).cells[0].outputs
    told = "<details>the figure in words</details>"  # an HTML widget's text: a picture's longer description
    assert [o["data"].get("text/html") for o in outputs] == [LIVE_ONLY_IN_JUPYTERLAB, None, told]
    assert outputs[1]["data"]["image/png"] == "iVBORw0KGgo=" and "widgets" not in nb.metadata


class FakePage:
    def __init__(self, file: File):
        self.file = file


def source_files(tmp_path: Path) -> Files:
    paths = ["README.md", "docs/results.md", "notebooks/chapter.ipynb", "notebooks/02_cae_reconstruction.ipynb"]
    paths += ["tutorials/assignments/README.md", "reference/planning.md", "docs/viewer.png"]
    files = [File(p, str(tmp_path), str(tmp_path / "site"), use_directory_urls=False) for p in paths]
    return Files([as_page(f, str(tmp_path / "site")) if f.src_uri.endswith(".ipynb") else f for f in files])


def as_page(file: File, site_dir: str) -> File:
    """A notebook as mkdocs-jupyter presents it to mkdocs: a page with an ``.html`` URL."""
    from mkdocs_jupyter.plugin import NotebookFile  # type: ignore[import-untyped]

    return NotebookFile(file, use_directory_urls=False, site_dir=site_dir)


CODE_COLUMNS = 78  # what a code block of a prose page shows at 1280 px without scrolling (79 in a screenshot)


@pytest.mark.parametrize("source", ["README.md", "docs/benchmarks.md", "docs/planner_race.md", "docs/results.md"])
def test_the_index_and_the_docs_pages_render_their_lists_as_lists_and_their_code_within_the_column(source):
    """Review r12a: the index's code blocks were cut on the right (lines of up to 122 characters), and results' list
    ran together as one paragraph with literal hyphens."""
    text = (ROOT / source).read_text()
    paragraphs = re.findall(r"<p>(.*?)</p>", page_html(text), re.S)
    assert not [p[:60] for p in paragraphs if re.search(r"(?m)^\s*[-*] ", p)], "a list item rendered as text"
    blocks = re.findall(r"(?ms)^```[a-z]*\n(.*?)^```", text)
    wide = [line for block in blocks for line in block.splitlines() if len(line) > CODE_COLUMNS]
    assert not wide, f"{source}: code lines wider than the page's column: {wide}"


def test_the_index_opens_in_short_sentences():
    """Review r18c graded the home page B: its answer sat under a stack of statistics. It opens in short sentences, the
    answer among them, then one small table of the counts behind it (each checked below)."""
    opening = readme_opening()
    prose = "\n".join(line.removeprefix(">").strip() for line in opening.splitlines() if not line.startswith("|"))
    ends = r"(?:(?<=[.?!])|(?<=[.?!]\*\*))\s+(?=[A-Z*])"  # a sentence ends at its stop, or after a bold one's **
    blocks = re.split(r"\n\s*\n|\n(?=\d\. |- )", prose)  # a paragraph, a list item or a table ends a sentence
    sentences = [s for block in blocks for s in re.split(ends, " ".join(block.split())) if s]
    assert len(sentences) >= 8
    assert max(len(s.split()) for s in sentences) <= 30, max(sentences, key=lambda s: len(s.split()))
    # reader r59e, home lift 2: the bands' table cut from above "Set up"; the answer's table is the opening's one
    assert len(re.findall(r"(?m)^\| --- ", opening)) == 1, "the opening has one table, the answer's"
    assert opening.index("**The answer") < opening.index("\n|")
    first = " ".join(opening.strip().split("\n\n")[0].split())  # review r23b: the repeatable sentence comes first
    from toolkit.teaching import recorded

    chance = [recorded.ours(row["Balanced unseen Acc"]) for row in recorded.table("paper", "MLP accuracy").values()]
    assert max(chance) <= 0.55  # near what one answer to every sample scores on a balanced test (50 %)
    # reader r47e, home: "as a coin would be" drew the wrong picture; in 3D the network gives every sample one answer
    rows = recorded.table("paper", "MLP accuracy")
    assert all(sorted(recorded.ours(rows[s][k]) for k in ("TPR", "TNR")) == [0, 1] for s in ("3dc7", "3dc9", "3do"))
    assert all(recorded.ours(rows[s]["Balanced unseen Acc"]) == 0.5 for s in ("3dc7", "3dc9", "3do"))
    from toolkit.teaching.costs import floors as bands

    own = [
        r
        for key in (recorded.ALGORITHM_1, FCL_ALIKE)
        for row in recorded.query_ratios(key).values()
        for r in row.values()
    ]
    cells = len(own)
    unsaved = cells - sum(r <= bands()["own"][0] for r in own)  # beyond the own ratio's noise band, on the saving side
    costly = sum(r >= bands()["own"][1] for r in own)  # reader r56e, home 3: beyond it on the cost side
    assert (cells, unsaved, costly) == (32, 30, 5)
    # reader r59e, home 1: "share x cut at most 16 %, within timing noise" met python-fcl's two savings beyond noise;
    # the answer says how many of its cells saved beyond noise; reader r60e, home 2: no sampling verdict by direction
    fcl = [r for row in recorded.query_ratios(FCL_ALIKE).values() for r in row.values()]
    fcl_saved = sum(r <= bands()["own"][0] for r in fcl)
    assert (len(fcl), fcl_saved) == (16, cells - unsaved) == (16, 2)
    assert first == (  # review r27e: "only where the exact check is slow" met 2DS BT's 0.81 with the compiled one;
        # reader r49e, home 6: the page's question before its answer; reader r57e, home lift 1: the answer in short
        # sentences a student can repeat, "whole query" in the question, no term before the box that defines it
        "**The question:** does a learned collision check, even an accurate one, save a planner time on a whole "
        "query? **The answer: for a whole query, no. "
        f"In {unsaved} of {cells} cases, compared query by query, our accurate network saved no time beyond timing "
        f"noise, and in {costly} it cost time. With python-fcl, the slow exact check, {fcl_saved} of its {len(fcl)} "
        "cases saved time beyond timing noise.** "
        f"The {cells} cases are 16 pairs of a scenario and a sampler, "
        "each timed with two exact "
        'checkers. The box "How to read the ratios", below, says how each is scored.'
    )  # each clause counted by test_the_index_gives_one_statistic_a_line_behind_its_answer
    box = opening.partition("> **How to read the ratios**\n>\n")[2].partition("\n\n")[0]
    assert box.splitlines() == [  # common57: the visible box of four lines, each band from the record
        "> - A *ratio* is a query's time with the network over its time without; below 1, the network saved time.",
        "> - A *cell* is one scenario with one sampler, 100 queries. Its score: the median of its queries' *own "
        "ratios*.",
        f"> - Above {1 - findings.TIE:.2f} and below {1 + findings.TIE:.2f} is a *tie*: our 10 % band, not the "
        "paper's.",
        "> - Above {:.2f} and below {:.2f} is the *noise band* of that median: a verdict inside it is no clear "
        "evidence.".format(*bands()["own"]),
    ]
    answer_block = opening[: opening.index("> **How to read the ratios**")]
    for term in ("own ratio", "noise band", "borrow", "preset", " cell"):  # reader r57e, home lift 1
        assert term not in answer_block, term
    from toolkit.experiments.paper_numbers import IMPROVEMENT, MLP

    # reader r46e, home lift 1: the paper's claim beside the answer, then the site's finding, in plain words (r45e's
    # "our stand-in, `strong`: ... right on 50-55 %" read as "exactly at")
    accurate = [row["unseen"]["acc"] for row in MLP.values()]
    sampling = [v for row in IMPROVEMENT.values() for v in row["sampling"].values()]
    total = max(v for row in IMPROVEMENT.values() for v in row["total"].values())
    second = " ".join(opening.strip().split("\n\n")[1].split())
    assert second == (
        f"The paper's claim: its network is {percents(accurate)} accurate on unseen workspaces (Table 2). With it, "
        f"sampling took {percents(sampling)} less time and whole queries up to {100 * total:.0f} % less time (Table "
        "3). Our finding: in 3D the rebuilt network gives every sample the same answer, which scores 50 % on a "
        "balanced test. So we "  # reader r55e, home C4: the 50 % is the balanced test's
        "timed an accurate network of our own as well, the `strong` network, and the verdict rests on it "  # r51e
        "([docs/results.md](docs/results.md#what-reproduces-and-what-does-not))."
    )
    assert "right on 50" not in first and "stand-in, `strong`:" not in opening
    assert "sampling stage got cheaper" not in flat_readme()  # reader r60e, home 2: no verdict by direction alone
    assert "faster" not in flat_readme()  # common47 rule 2: a saving is "less time", on the whole page
    assert "coin" not in flat_readme()


FCL_ALIKE = "strong --planner paper --baseline paper-fcl-alike"  # results.md: python-fcl on both sides of Algorithm 1


def test_the_index_table_counts_the_recorded_cells():
    """Each row of the home page's table counted again from docs/results.md's tables, by one statistic (reader r60e,
    home 1): the median of each query's own ratio, read with the box's tie band and noise band (chapter 05's labels:
    saved / tie / within noise / cost). The counts by mean times are the results page's, not the home page's."""
    from toolkit.teaching import recorded
    from tools.recorded_results import RESULTS, parse
    from tools.results_words import change

    tables = parse(RESULTS.read_text())

    from toolkit.teaching.costs import floors, inside

    own_band = floors(tables)["own"]

    def own_ratios(key: str) -> str:
        flat = [r for row in recorded.query_ratios(key, tables).values() for r in row.values()]
        tied = [r for r in flat if change(r) == "about the same time"]
        noisy = [r for r in flat if r not in tied and inside(r, own_band)]
        clear = [change(r) for r in flat if r not in noisy]
        return " / ".join(str(n) for n in (clear.count("less time"), len(tied), len(noisy), clear.count("more time")))

    expected = {
        "the `strong` network in Algorithm 1, compiled checker": ["16", own_ratios(recorded.ALGORITHM_1)],
        "python-fcl on both sides": ["16", own_ratios(FCL_ALIKE)],
    }
    table = readme_opening().partition("\n| a query's total time")  # the answer's table, under the figure
    lines = (table[1] + table[2]).strip().split("\n\n")[0].splitlines()
    rows = [[c.strip() for c in line.strip("|").split("|")] for line in lines if line[:2] == "| "]
    shown = {key: row[1:] for key in expected for row in rows[1:] if key in row[0]}
    assert rows[0][2:] == ["by each query's own ratio: saved / tie / within noise / cost"]
    assert shown == expected
    assert len(rows) == 2 + len(expected)  # the header, the `| --- |` line and a row each
    assert own_ratios(recorded.ALGORITHM_1).startswith("0 / ") and own_ratios(FCL_ALIKE).endswith(" / 0")
    answer = " ".join(readme_opening().split())
    said = (
        "The table counts each cell's median own ratio with the box's two bands. Inside the tie band it is a tie; "
        "beyond it but inside the noise band, within noise: no saving or cost shown. Beyond both, it saved or cost "
        "time."
    )
    assert said in answer
    elsewhere = "The counts by mean times (Table 3's statistic), the paper's recipe reproduced, and our lazy PRM"
    assert elsewhere + " against the network: [docs/results.md](docs/results.md)." in answer
    # reader r60e, home 1: one statistic on the home page; the counts by means, with their wider band, cut
    for gone in ("By means, none", "by mean times (Table 3's statistic, our reading):", "within noise by means"):
        assert gone not in answer, gone
    visible = re.sub(r"(?s)<details.*?</details>", "", flat_readme())
    for band in ("means", "medians"):  # no other statistic's band on the home page
        assert "{:.2f}–{:.2f}".format(*floors(tables)[band]) not in flat_readme(), band
    assert "0.90 or less in" not in visible and "sampling took longer in" not in visible  # r60e, home 2
    # reader r59e, home 2: only the sampling stage's result turns on the checker; r60e, home 2: no sampling verdict
    said = "a whole query saved time beyond timing noise in 2 of the 32 cases, both with python-fcl."  # r63e, home 1
    assert said in answer and "sampling stage's result" not in answer and "no with either" not in answer
    assert "floor" not in answer.split("<details")[0]
    assert "as measured" not in answer and "doubled" not in answer


def test_the_index_names_two_bands_above_its_first_section():
    """Reader r50e, home lift 4 put three bands in a key under Figure 1; reader r59e, home lift 2: four bands before
    "Set up" were too many. The visible text above the first section names the box's two (the tie band, each query's
    own ratio's); reader r60e, home 1: the means' and the medians' are the results page's, not the home page's."""
    from toolkit.teaching.costs import floors
    from tools.recorded_results import RESULTS, parse

    bands = floors(parse(RESULTS.read_text()))
    text = README.read_text()
    top = re.sub(r"(?s)<details.*?</details>", "", text.partition("\n## ")[0])
    assert "{:.2f} and below {:.2f}".format(*bands["own"]) in top  # the box's noise band
    assert f"Above {1 - findings.TIE:.2f} and below {1 + findings.TIE:.2f}" in top  # the box's tie band
    for kind in ("means", "medians"):
        low, high = bands[kind]
        assert f"{low:.2f}–{high:.2f}" not in text, kind
    assert "Figure 1 draws two bands" not in text and "| band | ratios inside it |" not in text
    assert text.index("<summary>How the noise band is derived") < text.index("\n| a query's total time")


def test_the_index_says_what_python_fcl_on_both_sides_saved_and_what_it_did_not():
    """The lead's run with python-fcl doing every exact check of Algorithm 1, with and without the network: the home
    page's answer quotes its sampling savings, its total time's own ratios and sampling's share of a query, read from
    the record, so the page cannot drift from it."""
    from toolkit.experiments.paper_numbers import IMPROVEMENT, TIMES
    from toolkit.teaching import recorded
    from toolkit.teaching.costs import NOISE_EDGE, noise_edge, timing_reach
    from tools.recorded_results import RESULTS, parse
    from tools.results_findings import apart
    from tools.results_noise import at_noise_edge, measured, own_intervals
    from tools.results_words import NAMES, change

    tables = parse(RESULTS.read_text())
    scenarios = list(recorded.table(FCL_ALIKE, "time improvement", tables))
    saved = [v for s in scenarios for v in recorded.improvements(FCL_ALIKE, s, "sampling", tables).values()]
    own = [r for row in recorded.query_ratios(FCL_ALIKE, tables).values() for r in row.values()]

    def shares(key: str) -> list[float]:
        times = next(v for k, v in tables[key].items() if "Times behind Table 3" in k)  # a row per sampler
        column = times["columns"].index
        return [
            recorded.ours(row[column("sampling without")]) / recorded.ours(row[column("total without")])
            for row in times["rows"]
        ]

    answer = " ".join(readme_opening().split())
    names = ", ".join(scenarios_named(scenarios))
    table3 = [v for row in IMPROVEMENT.values() for v in row["sampling"].values()]
    assert names == "2DS, 3DC-7, 3DC-9, 3DO" and min(saved) > 0  # review r25b: one range, not a list of four names
    # reader r60e, home 2: the sampling stage's cut, read by direction with no band, cut from the home page
    assert f"by {percents(saved)} (the paper's Table 3: {percents(table3)})" not in answer
    # reader r30e, item 1: the mechanism under the answer, sampling's share over both Algorithm 1 runs
    both = shares(FCL_ALIKE) + shares(recorded.ALGORITHM_1)
    assert (
        f"In our runs sampling took {percents(both, digits=1)} of a query's time without the network. Algorithm 1's "
        'line 4 says only "a standard PRM approach"; we read it as checking every edge of the roadmap exactly'
        # reader r35e, home 2: the lazy PRM screens edges too; reader r37e, home 2: our reading, not the paper's words
    ) in answer
    assert "spends most of its time" not in answer  # reader r30e, contradiction 3
    # reader r30e, item 2: the own ratio leads, its noise-edge cell named as the results page names it
    fell = [r for r in own if change(r) == "less time"]
    edge = [c for c in at_noise_edge(own_intervals(tables, FCL_ALIKE), tables) if float(c.split()[-1]) < 1]
    assert len(edge) == 1 and len([r for r in own if r <= 0.9]) == len(fell)
    floor, reach = measured(tables).own, timing_reach(tables)  # as timing alone moved it
    # reader r32e, contradictions 1-2: a saving inside the noise edge is not counted as clear; the edge derived
    clear = [
        f"{NAMES[s]} {sampler} {r:.2f}"
        for s, row in recorded.query_ratios(FCL_ALIKE, tables).items()
        for sampler, r in row.items()
        if change(r) == "less time" and abs(r - 1) >= NOISE_EDGE * reach
    ]
    assert len(clear) + len(edge) == len(fell) and len(clear) == 2
    # reader r33e, home contradiction 1: the noise edge is applied to the compiled checker's costs too
    compiled = own_intervals(tables, recorded.ALGORITHM_1)
    costs = [r for row in recorded.query_ratios(recorded.ALGORITHM_1, tables).values() for r in row.values()]
    costs = [r for r in costs if change(r) == "more time"]
    edged = [c for c in at_noise_edge(compiled, tables) if float(c.split()[-1]) > 1]
    assert len(costs) == 9 and len(edged) == 4
    # reader r43e, home Figure 1: the circle drawn on the 1.18 line is inside the noise band, said in the caption
    cells = [
        (s, k, r) for s, row in recorded.query_ratios(recorded.ALGORITHM_1, tables).items() for k, r in row.items()
    ]
    near = max((c for c in cells if c[2] < 1 + noise_edge(tables)), key=lambda c: c[2])
    assert 1 + noise_edge(tables) - near[2] <= 0.015
    # reader r40e, home contradiction 1: the text counts by the figure's rule (every triangle, every circle), those
    # beyond the noise band in brackets; the band's derivation in a fold
    # reader r41e, home 2: the counts said once, in the caption, by the figure's two bands; the clear cells named here
    assert (  # reader r48e, home 3: the caption says what the legend does not (the bands' edges are in the legend)
        f"Triangles mark medians of 0.90 or less: {len(fell)} of 16 hollow points (python-fcl) and 0 filled. Circles "
        f"mark medians of 1.10 or more: {len(costs)} of 16 filled points and 0 hollow. A ring marks a point beyond "
        f"the noise band: {len(clear)} of the triangles and {len(costs) - len(edged)} of the circles; "
        f"{NAMES[near[0]]} {near[1]}'s circle, at {near[2]:.2f}, lies just inside it. The table below counts the "
        "ringed points as saved or cost, the other circles and triangles as within noise. The "
        f"{len(clear)} ringed triangles are python-fcl's; its run was not timed twice, so it "  # r57e, home lift 2
        "borrows this band from the compiled run.*"  # common47 rule 4, r47e: the borrowed band where its count is given
    ) in answer
    alt_said = (  # reader r51e, home figure 1: the alt text says what each shape means, with the caption's counts
        f"Circles mark medians of 1.10 or more: {len(costs)} filled, 0 hollow. Squares mark the tie band. Triangles "
        f"mark medians of 0.90 or less: 0 filled, {len(fell)} hollow. A ring marks each point beyond the noise band: "
        f"{len(costs) - len(edged)} filled circles and {len(clear)} hollow triangles.](docs/results_claim.png)"
    )
    assert alt_said in answer
    legend = f"noise band of this ratio, {1 - NOISE_EDGE * reach:.2f}–{1 + NOISE_EDGE * reach:.2f}"
    assert legend in claim_figure_labels() and f"above {1 - findings.TIE:.2f} and below {1 + findings.TIE:.2f}" in (
        claim_figure_labels()
    )
    assert (
        # reader r43e, home contradiction 1: "clear" in one sense only, beyond the noise band
        f"The two savings beyond the noise band (python-fcl) are {clear[0]} and {clear[1]}, by their own ratios; "
        f"{edge[0]} lies inside the noise band."
    ) in answer
    assert "clear win" not in answer
    assert (  # wave 24: one rule for every band, said once in the fold, each band from the record
        '<details markdown="1"><summary>How the noise band is derived</summary> '
        f"Timing alone moved this median to {floor[0]:.2f}–{floor[1]:.2f}, so the noise band is 1 ± "
        f"twice the larger reach from 1 ({reach:.2f}), {1 - NOISE_EDGE * reach:.2f}–{1 + NOISE_EDGE * reach:.2f}. "
        "Every noise band is built this way, twice timing's reach, because a single repeat understates timing noise. "
        "The python-fcl run was not timed twice: its points borrow this band from the compiled run."
    ) in answer
    assert "doubled" not in answer and "as measured" not in answer  # wave 24: no band built apart from the others
    assert not any("timed twice" in heading for heading in tables[FCL_ALIKE])  # "not timed twice"
    # reader r44e, home 2: one limit, said once near the top: sampling's share of a query times its cut
    times = next(v for k, v in tables[FCL_ALIKE].items() if "Times behind Table 3" in k)

    def limit(scenario: str, sampler: str) -> tuple[float, float]:
        row = next(row for row in times["rows"] if row[:2] == [scenario, sampler])
        sampled = [recorded.ours(row[times["columns"].index(f"sampling {m}")]) for m in ("without", "with")]
        return shares(FCL_ALIKE)[times["rows"].index(row)], 1 - sampled[1] / sampled[0]  # share, and its cut

    bt, cut = limit("3do", "BT")
    limits = {(s, k): limit(s, k) for s, k in (row[:2] for row in times["rows"])}
    under = [c for c, (s, k) in limits.items() if s * k < findings.TIE]
    assert max(limits.values(), key=lambda sk: sk[0] * sk[1]) == (bt, cut)  # 3DO BT's is the largest
    # reader r45e, home 1 and 4: the limit is what skipping the checks can save, a query may save more by another
    # roadmap; "barely moves" gone (16 % is above the tie band's 10 %), the cells under 10 % counted instead
    # reader r46e, home 2: the limit below the figure, in one fold, with the two savings it bounds (said once)
    free = [c for c, (s, k) in limits.items() if s < findings.TIE]  # a free network: at most sampling's whole share
    said = (  # reader r54e, home 2: the limit in sight, not only in the fold; a free network's bound beside ours
        "**A whole query has little to save.** Prediction replaces only the exact checks of sampled configurations. "
        "Even with a free network, skipping those checks can save at most sampling's share of a query: with "
        f"python-fcl, under 10 % in {len(free)} of {len(limits)} cells. With our `strong` network and python-fcl, "
        "it can save at most that share times its cut in sampling: under 10 % "  # r57e, home 3; r59e, home lift 4
        f"in {len(under)} of {len(limits)} cells. "  # reader r59e, home 1: 3DO BT's 16 % in the fold, beside its 0.72
        '<details markdown="1"><summary>Why a whole query rarely saves: the limit</summary> In our runs sampling took '
        f"{percents(both, digits=1)} of a query's time without the network."
    )
    assert (len(free), len(under)) == (10, 14)
    assert said in answer and answer.index(said) > answer.index("](docs/results_claim.png)")
    assert answer.count("at most sampling's share") == 1 and "barely moves" not in answer  # said once
    # both clear own-ratio savings pass that limit: the rest came after sampling
    assert clear[0].startswith("3DC-9 OB") and clear[1].startswith("3DO BT")
    ob = limit("3dc9", "OB")
    assert all(1 - float(c.split()[-1]) > s * k for c, (s, k) in zip(clear, (ob, (bt, cut))))
    saved = [100 * (1 - float(c.split()[-1])) for c in clear]
    # reader r49e, home 4: like with like: the limits (from mean times) against the savings by mean times; 3DO BT's
    # is about its limit, 3DC-9 OB's past it (reader r60e, home 1: the means' band is the results page's)
    by_means = [recorded.improvements(FCL_ALIKE, s)[k] for s, k in (("3dc9", "OB"), ("3do", "BT"))]
    from toolkit.teaching.costs import floors, inside

    means_band = floors()["means"]
    assert round(100 * by_means[1]) == round(100 * bt * cut) and by_means[0] > ob[0] * ob[1]
    assert inside(1 - by_means[0], means_band) and inside(1 - by_means[1], means_band)
    assert (
        f"The two savings beyond the noise band (python-fcl) are {clear[0]} and {clear[1]}, by their own ratios; "
        f"{edge[0]} lies inside the noise band. The limit comes from mean times, so compare like with like. By mean "
        f"times, 3DO BT took {100 * by_means[1]:.0f} % less time, about its limit ({bt:.3f} × {cut:.3f}), and "
        f"3DC-9 OB {100 * by_means[0]:.0f} % less, more than its limit of {100 * ob[0] * ob[1]:.0f} %. The rest "
        "would come after sampling: with other samples the planner grows another roadmap, with other edges to "
        "check. </details>"
    ) in answer
    assert "By their own ratios they saved" not in answer and saved[0] > 100 * by_means[1]  # r49e: no own-ratio saving
    # reader r46e, home 4: "The numbers behind the answer" does not pass through these savings and the limit again
    numbers = README.read_text().partition("\n## The numbers behind the answer\n")[2].partition("\n## ")[0]
    assert "The two savings beyond" not in numbers and f"{100 * bt * cut:.0f} % in 3DO BT" not in numbers
    assert answer.count("The two savings beyond the noise band") == 1
    assert "Both saved more than the limit above" not in answer
    assert reach == max(1 - floor[0], floor[1] - 1) and NOISE_EDGE == 2
    # wave 24: 3DC-9 OB's saving by means (0.66) lies inside the means' noise band, so it is no finding here
    bigger = [c for c in apart(tables) if change(1 - c.total) == "less time" and c.total > c.sampling]
    assert [c.name for c in bigger] == ["3DC-9 OB"] and inside(1 - bigger[0].total, floors(tables)["means"])
    assert "bigger than its sampling stage allows" not in answer and "0.66" not in answer
    # reader r32e, contradiction 4: the paper's own §V times meet the same test (chapter 04's section 6 names them,
    # toolkit.teaching.chapter04_paper.beyond_sampling)
    over = {
        (s, k): (without - with_, TIMES[s]["sampling_s"][k][0][0])
        for s, kinds in TIMES.items()
        for k, ((without, _), (with_, _)) in kinds["total_s"].items()
        if without - with_ > TIMES[s]["sampling_s"][k][0][0]
    }
    most = max(over, key=lambda c: over[c][0])
    table3 = {(s, k) for s, row in IMPROVEMENT.items() for k, v in row["total"].items() if change(1 - v) == "less time"}
    assert len(table3) == len(over) and table3 != set(over)  # reader r37e, home 6: "not the same 10 cells"
    # reader r41e, home lift 5: one visible line, the paragraph in a fold under it; r44e, home 2: the limit not
    # stated again, the paper's cells that break it
    # reader r45e, home 2: the paper's cells read by the same rule as ours, no stricter one
    line = (  # reader r48e, home 1: the limit defined in sight, not only in a fold far above
        "**Many of the paper's savings are bigger than skipping checks allows.** Skipping the samples' exact checks "
        "can save at most the time the whole sampling stage took. A saving beyond that came from elsewhere in the "
        f"query: another roadmap, with other edges to check. In {len(over)} of its 16 cells, the paper's mean times "
        "save more than the whole sampling stage took. In our reading, that stage's time is its §V's \"average time "
        'to validate samples". '  # r52e, home 4; r55e, home C7: our reading, marked
        '<details markdown="1"><summary>Savings bigger than the whole sampling stage, in the paper</summary> '
        "The whole sampling stage is a looser limit than sampling's share times its cut (the fold \"Why a whole "
        "query rarely saves: the limit\"). The paper's largest gap "
        f"beyond it, in its §V mean times: {NAMES[most[0]]} {most[1]}, {over[most][0]:.2f} s saved against "
        f"{over[most][1]:.2f} s of sampling. They are not the same {len(over)} cells as those where Table 3 saves 10 % "
        "or more. </details>"  # common47 rule 1
    )
    assert line in answer and "break the limit" not in answer
    # its throughput against python-fcl and each cell beside Table 3: docs/benchmarks.md (tests/test_benchmarks_page)


def test_the_index_gives_one_statistic_a_line_behind_its_answer():
    """Review r27e: "the three numbers" set two own-ratio counts beside the paper's count of means. Reader r60e, home
    1-2: one statistic on the home page, each query's own ratio; Table 3's means, and the sampling stage's counts read
    by direction with no band, are the results page's. Each count is counted again here from docs/results.md."""
    from toolkit.experiments.paper_numbers import IMPROVEMENT
    from toolkit.teaching import recorded
    from toolkit.teaching.findings import SAVES, time_verdict
    from tools.recorded_results import RESULTS, parse

    tables = parse(RESULTS.read_text())

    def own(key: str) -> int:
        ratios = [r for row in recorded.query_ratios(key, tables).values() for r in row.values()]
        return [time_verdict(r) for r in ratios].count(SAVES)

    fcl, compiled = FCL_ALIKE, recorded.ALGORITHM_1
    opening = readme_opening()
    assert "Table 3's statistic (our reading), for comparison" not in opening  # reader r60e, home 1
    # reader r29e: "own ratio" defined where it is first used, before its count
    answer = " ".join(opening.split())
    # reader r41e, home lift 3: the own ratio as a student would say it
    assert (  # reader r57e, home lift 1: in the box "How to read the ratios", its own ratio glossed under it
        "A *cell* is one scenario with one sampler, 100 queries. Its score: the median of its queries' *own ratios*."
    ) in answer and "Each query is timed with and without the network in turn, so its own ratio divides" in answer
    assert answer.index("*own ratios*.") < answer.index("0.90 or less: 3 of 16 hollow points")
    assert f"0.90 or less: 3 of 16 hollow points (python-fcl) and {own(compiled)} filled" in answer
    # reader r31e: the finding's figure under the answer, its caption counting the same cells
    assert README.read_text().index("](docs/results_claim.png)") < README.read_text().index("\n## ")
    assert own(fcl) == 3  # reader r32e, contradiction 1: the caption tells the noise edge's saving apart
    assert (  # reader r40e, home contradiction 1: the caption counts every triangle and circle the figure draws
        f"Triangles mark medians of 0.90 or less: 3 of 16 hollow points (python-fcl) and {own(compiled)} filled. "
        "Circles mark medians of 1.10 or more: 9 of 16 filled points and 0 hollow."  # r51e, home 4: as the legend
    ) in answer
    from toolkit.teaching.costs import noise_edge
    from tools.results_noise import measured

    edge = (1 - noise_edge(tables), 1 + noise_edge(tables))
    clear = [r for row in recorded.query_ratios(fcl, tables).values() for r in row.values() if r < edge[0]]
    evidence = f"A ring marks a point beyond the noise band: {len(clear)} of the triangles"
    floor = measured(tables).own  # reader r42e, home 1: twice timing's reach, not "as far as timing alone could put"
    defined = (  # wave 24: one rule for every noise band, said once, then this median's band
        # reader r56e, home 2: the rule holds with the borrowed band, said in the rule
        "Every noise band on this site is built from a run timed twice: twice how far timing alone moved its statistic "
        "from 1. A run not timed twice borrows the band of one that was: python-fcl's borrows the compiled run's. "
        f"For this median timing alone reached {floor[0]:.2f}–{floor[1]:.2f}."
    )  # reader r46e, home 2: "borrow" said once, in the caption, where the hollow points are read
    # reader r39e, home lift 1: "Terms" in two sentences; "own ratio" and "noise edge" under the figure, which the
    # caption reads, and said once (the paragraph that repeated the caption's count cut)
    terms = re.search(r"Terms\. (.*?)\n\n", README.read_text(), re.S).group(1)
    assert len(re.findall(r"\.(?:\s|$)", terms)) == 1 and "own ratio" not in terms and "noise band" not in terms
    assert "*cell*" not in terms  # reader r57e, home lift 1: defined once, in the box "How to read the ratios"
    # reader r40e, home lift 2: "own ratio" and "noise band" defined before the figure whose title uses them
    assert answer.index(defined) < answer.index("](docs/results_claim.png)") < answer.index(evidence)
    assert answer.index(evidence) < answer.index("The two savings beyond the noise band (python-fcl) are")
    assert "noise edge" not in answer  # reader r40e: one name, "noise band", on every page
    assert answer.index("*python-fcl* calls") < answer.index("*compiled checker*") < answer.index(evidence)
    assert "By mean times, sampling got" not in answer
    # reader r34e, home figure 1: the caption says what a whisker is
    assert "a whisker spans the middle half of the cell's 100 queries" in answer
    assert "hollow: python-fcl on both sides" in claim_figure_labels()  # reader r38e; r48e: said by the legend
    # reader r45e, home 6, and r47e (common47 rule 4): the borrowed band said where python-fcl's count is given
    assert answer.count("borrows this band from the compiled run.") == 1 and "which borrows" not in answer
    assert answer.index("borrows this band") < answer.index("The two savings beyond the noise band (python-fcl)")
    assert not any("timed twice" in heading for heading in tables[fcl])  # it borrows: its run was timed once
    # reader r60e, home 2: the sampling stage's verdicts by direction alone, with no band, cut from the home page
    assert "The sampling stage alone" not in answer and "We still read python-fcl's cut" not in answer
    # reader r41e, home lift 3: the answer, then what the paper does, then the terms, then the figure
    assert (
        answer.index("**The answer")
        < answer.index("The paper's claim: its network")  # reader r46e, home lift 1
        < answer.index("The paper is *Predicting Sample Collision")  # reader r52e, home 5: a plain opening
        < answer.index("Terms. ")
    )
    # reader r46e, home 3: Table 3 as a ratio of means is our reading, the agreeing entries counted from the paper
    from toolkit.experiments.paper_numbers import table3_against_text

    entries = sum(len(row) for kinds in IMPROVEMENT.values() for row in kinds.values())
    agree = entries - len(table3_against_text())
    assert (
        f"In our reading it divides mean times ({agree} of its {entries} entries agree with the mean times of its "
        "text)."
    ) in answer and (agree, entries) == (25, 32)
    assert max(own(fcl), own(compiled)) <= 3


SCENARIOS = ("2ds", "3dc7", "3dc9", "3do")


def test_the_index_tells_our_networks_cost_from_the_papers():
    """Reader r32e, contradiction 5: the home page gave the paper's network's cost (2.6-5.5 compiled checks, the idle
    benchmark) and chapter 05 our `strong` network's (6.9 on 3DC-7); the home page now gives both, each named, ours
    from the timed run's throughput table."""
    from toolkit.teaching import recorded

    rates = recorded.table(recorded.ALGORITHM_1, "Checker throughput")
    cost = {
        s: recorded.ours(r["exact cfg/s"]) / recorded.ours(r["learned cfg/s"]) for s, r in rates.items() if s != "2ds"
    }
    fcl = {s: recorded.ours(r["learned cfg/s"]) / recorded.ours(r["FCL cfg/s"]) for s, r in rates.items() if s != "2ds"}
    said = (  # reader r36e, home 3 and lift 3: two ratios, no more; the idle ones and the paper's on benchmarks.md
        f"In the loaded planning run one answer of our `strong` network cost as much as "
        f"{min(cost.values()):.1f}–{max(cost.values()):.1f} compiled checks, and one python-fcl check as much as "
        f"{min(fcl.values()):.1f}–{max(fcl.values()):.1f} answers ([docs/results.md](docs/results.md); idle "
        "benchmarks and the paper's network: [docs/benchmarks.md](docs/benchmarks.md))."
    )
    assert said in flat_readme()
    assert "a little more" not in flat_readme()  # reader r35e, home 3: 6.9 against 2.6-5.5 is not "a little"
    assert "times cheaper than that network" not in flat_readme() and "× python-fcl" not in flat_readme()


def test_the_index_leaves_the_lazy_prm_to_the_results_page():
    """Reader r42e, home lift 6 asked for the lazy PRM's ratio of median times on the home page; reader r60e, home 1:
    one statistic there, each query's own ratio, which the lazy PRM's run did not keep, so its count (by the ratio of
    medians and that ratio's band) is the results page's, linked from the table's footnote."""
    assert "**Our lazy PRM**" not in flat_readme() and "noise band of a ratio of medians" not in flat_readme()
    assert "our lazy PRM against the network: [docs/results.md](docs/results.md)." in flat_readme()


def test_the_index_says_the_paper_network_gives_one_answer_to_every_3d_sample():
    """Review r19c: the index said "nearly every sample" where Table 2 (TPR 100 %, TNR 0 %) says every."""
    from toolkit.teaching import recorded

    rows = recorded.table("paper", "MLP accuracy")
    for scenario in ("3dc7", "3dc9", "3do"):
        for tpr, tnr in (("Seen TPR", "Seen TNR"), ("Unseen TPR", "Unseen TNR"), ("TPR", "TNR")):
            assert sorted((recorded.ours(rows[scenario][tpr]), recorded.ours(rows[scenario][tnr]))) == [0, 1]
    assert 'one answer, "valid" or "invalid", to every sample' in flat_readme() and "nearly every" not in flat_readme()
    accuracy = [recorded.ours(row["Balanced unseen Acc"]) for row in rows.values()]
    strong = [recorded.ours(row["Balanced unseen Acc"]) for row in recorded.table("strong", "MLP accuracy").values()]
    three_d = percents([recorded.ours(rows[s]["Balanced unseen Acc"]) for s in ("3dc7", "3dc9", "3do")])
    assert three_d == "50–50 %"  # reader r59e, home 3: the intro's "50 %" and this line's, each scenario named
    two_d = recorded.ours(rows["2ds"]["Balanced unseen Acc"])
    said = f"in a balanced test of unseen samples its MLP is right on 50 % in 3D, {100 * two_d:.0f} % in 2DS"
    assert said in flat_readme() and "50–55 %" not in flat_readme()  # not 05's uniform samples
    assert max(accuracy) == two_d
    # reader r29e: the runs trained the network more than once (the lazy PRM's, Algorithm 1's); the range holds for each
    trainings = [recorded.table(key, "MLP accuracy").values() for key in ("strong", recorded.ALGORITHM_1)]
    each = [[recorded.ours(row["Balanced unseen Acc"]) for row in rows] for rows in trainings]
    assert all(min(strong) <= a <= max(strong) for scores in each for a in scores)
    assert f"Every recorded training of it was {percents(strong)} accurate on unseen workspaces" in flat_readme()
    uniform = rows["3dc7"]  # chapter 05's test: uniform samples, where one answer scores what "always valid" does
    assert recorded.ours(uniform["Unseen Acc"]) == recorded.ours(uniform["Unseen always valid"]) > 0.5


def scenarios_named(keys: list[str]) -> list[str]:
    """The pages' names of scenarios ("2DS", "3DC-7") from the record's keys ("2ds", "3dc7")."""
    from toolkit.teaching.checker_scope import NAMES

    return [NAMES[k] for k in keys]


def percents(fractions: list[float], digits: int = 0) -> str:
    """ "67–78 %" as the pages write a range of fractions (the low end to ``digits`` decimals)."""
    return f"{100 * min(fractions):.{digits}f}–{100 * max(fractions):.0f} %"


def claim_figure_labels() -> str:
    """The words of Figure 1's legend, as tools.results_figures draws it from docs/results.md (the caption under it on
    the home page says only what these do not)."""
    from tools.results_figures import RESULTS, claim_figure

    fig = claim_figure(RESULTS.read_text())
    words = [
        t.get_text() for legend in fig.legends + [ax.get_legend() for ax in fig.axes] if legend for t in legend.texts
    ]
    return " | ".join(words)


def flat_readme() -> str:
    return " ".join(README.read_text().split())


def test_the_index_gives_each_scenarios_training_grids():
    """Review r18c: the index said the paper's CAE learns nothing from "30 training grids", true of 2DS alone."""
    from toolkit import scenarios

    said = re.search(r"on (\d+) grids in 2DS, (\d+) in 3DO and (\d+) in 3DC", " ".join(README.read_text().split()))
    assert said, "the index no longer gives the CAE's training grids per scenario"
    assert said.groups() == tuple(str(scenarios.get(s).n_seen) for s in ("2ds", "3do", "3dc7"))
    assert scenarios.get("3dc9").n_seen == scenarios.get("3dc7").n_seen


def test_the_index_says_the_python_fcl_count_once_above_its_brief():
    """Reader r43e, home lift 5: "What we found, in brief" repeated the count of python-fcl's savings given twice
    above; its bullet is the bold line and a link to the numbers."""
    brief = README.read_text().partition("\n## What we found, in brief\n")[2].partition("\n## ")[0]
    bullet = next(b for b in brief.split("\n- ") if "is needed for skipping checks to pay" in b)
    assert " ".join(bullet.split()) == (
        "**A network answer cheaper than an exact check is needed for skipping checks to pay, and is not enough** "
        "([the numbers behind the answer](#the-numbers-behind-the-answer))."
    )
    assert "of 16" not in brief and "clear win" not in README.read_text()


README = ROOT / "README.md"


def readme_opening() -> str:
    """The index page's answer and the numbers behind it: its text before the first section, then its section "The
    numbers behind the answer" (reader r29e: set-up and the notebooks now come between them)."""
    text = (ROOT / "README.md").read_text()
    numbers = text.partition("\n## The numbers behind the answer\n")[2].partition("\n## ")[0]
    assert numbers, "the home page has no section 'The numbers behind the answer'"
    return text.partition("\n## ")[0].partition("\n")[2] + "\n" + numbers


def test_links_between_sources_land_on_pages(tmp_path):
    files = source_files(tmp_path)
    chapter = FakePage(files.get_file_from_path("notebooks/chapter.ipynb"))
    page = site_hooks.on_page_content(
        '<a href="02_cae_reconstruction.ipynb#eq-1">next</a> <a href="../docs/results.md">results</a> '
        '<img src="../docs/viewer.png"> <a href="../toolkit/planning/paper_prm.py">Algorithm 1</a> '
        '<a href="https://viser.studio">Viser</a> <img src="data:image/png;base64,AAAA">',
        chapter,
        None,
        files,
    )
    assert re.findall(r'(?:href|src)="([^"]*)"', page) == [
        "02_cae_reconstruction.html#eq-1",
        "../docs/results.html",
        "../docs/viewer.png",
        "../reference/planning.html#toolkit.planning.paper_prm",
        "https://viser.studio",
        "data:image/png;base64,AAAA",
    ]
    home = FakePage(files.get_file_from_path("README.md"))
    markdown = "[a](tutorials/assignments/) [b](docs/results.md#x) [c](toolkit/planning/__init__.py) [d](nowhere.md)"
    assert site_hooks.on_page_markdown(markdown, home, None, files) == (
        "[a](tutorials/assignments/README.md) [b](docs/results.md#x) [c](reference/planning.md#toolkit.planning) "
        "[d](nowhere.md)"
    )


HUB = {"url": "https://hub.example.edu/", "repository": "https://github.com/course/handout.git", "branch": "spring"}


def test_a_notebook_page_links_its_download_and_with_a_hub_its_nbgitpuller_link(tmp_path):
    files = source_files(tmp_path)
    files.append(File("downloads/chapter.ipynb", str(tmp_path), str(tmp_path / "site"), use_directory_urls=False))
    chapter = FakePage(files.get_file_from_path("notebooks/chapter.ipynb"))
    page = site_hooks.on_page_content("<h1 id='c'>Chapter</h1>", chapter, {"extra": {"jupyterhub": HUB}}, files)
    links = re.findall(r'<a href="([^"]*)"', page.split("<h1")[0])
    assert links == [
        "../downloads/chapter.ipynb",
        "https://hub.example.edu/hub/user-redirect/git-pull?repo=https%3A%2F%2Fgithub.com%2Fcourse%2Fhandout.git"
        "&amp;branch=spring&amp;targetpath=handout&amp;urlpath=lab%2Ftree%2Fhandout%2Fnotebooks%2Fchapter.ipynb",
    ]
    assert site_hooks.nbgitpuller_link({**HUB, "branch": ""}, "a b.ipynb").endswith(
        "branch=main&targetpath=handout&urlpath=lab%2Ftree%2Fhandout%2Fa+b.ipynb"
    )
    unset = {"extra": {"jupyterhub": {"url": "", "repository": ""}}}  # as mkdocs.yml ships
    assert re.findall(r'<a href="([^"]*)"', site_hooks.on_page_content("", chapter, unset, files)) == [
        "../downloads/chapter.ipynb"
    ]
    other = FakePage(files.get_file_from_path("notebooks/02_cae_reconstruction.ipynb"))  # no download: no links
    assert site_hooks.on_page_content("<p>x</p>", other, unset, files) == "<p>x</p>"


@pytest.mark.parametrize(
    "repository",
    [
        "https://github.com/course/handout",
        "https://github.com/course/handout.git",
        "https://github.com/course/handout.git/",
    ],
)
def test_an_nbgitpuller_link_opens_the_folder_it_clones_into_with_or_without_dot_git(repository):
    """nbgitpuller clones into ``targetpath``, by default the URL's last part as it is (``handout.git``, or empty
    after a ``/``: jupyterhub/nbgitpuller, handlers.py); the link names the folder, and opens the notebook in it."""
    query = parse_qs(urlsplit(site_hooks.nbgitpuller_link({**HUB, "repository": repository}, "n/c.ipynb")).query)
    assert query["repo"] == [repository]
    assert query["targetpath"] == ["handout"] and query["urlpath"] == ["lab/tree/handout/n/c.ipynb"]


def test_a_page_keeps_one_h1_and_its_scrolling_code_can_be_reached_by_keyboard():
    assert site_hooks.one_h1('<h1 id="a">A</h1> <h1 id="b">B <em>b</em></h1>') == (
        '<h1 id="a">A</h1> <h2 id="b">B <em>b</em></h2>'
    )
    code = '<div class="highlight-ipynb hl-python"><pre>x</pre></div><div class="language-sh highlight"><pre><code>'
    code += '<pre id="fence"><span></span><code>y</code></pre><p><code>inline</code></p>'  # a Markdown cell's fence
    code += '<div class="highlight"><pre><span></span>z</pre></div>'  # a Markdown cell's fence with a language
    code += '<div class="jp-RenderedText jp-OutputArea-output" data-mime-type="text/plain" tabindex="0"><pre>'
    region = 'tabindex="0" role="region" aria-label="code"'
    made = site_hooks.focusable_code(code)
    assert re.findall(r"<(?:div|pre|code)\b[^>]*>", made) == [
        f'<div class="highlight-ipynb hl-python" {region}>',  # a code cell: its <div> scrolls
        "<pre>",
        '<div class="language-sh highlight">',
        "<pre>",
        f"<code {region}>",  # material scrolls the <code> in a <pre>
        '<pre id="fence">',
        f"<code {region}>",
        "<code>",  # inline code is no region
        '<div class="highlight">',
        f"<pre {region}>",
        '<div class="jp-RenderedText jp-OutputArea-output" data-mime-type="text/plain">',  # an output: no tab stop
        "<pre>",
    ]
    assert site_hooks.focusable_code(made) == made


def test_a_figure_on_a_page_gets_the_alt_text_of_its_output(tmp_path):
    figure = nbformat.v4.new_output(
        "display_data", data={"image/png": "iVBORw0K\nGgo="}, metadata={"image/png": {"alt": 'a "dark" square'}}
    )
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell("fig")]
    nb.cells[0].outputs = [figure]
    nbformat.write(nb, tmp_path / "chapter.ipynb")
    page = (
        '<img alt="No description has been provided for this image" class="" src="data:image/png;base64,iVBORw0KGgo=">'
    )
    assert site_hooks.figure_alts(page, tmp_path / "chapter.ipynb") == (
        '<img alt="a &quot;dark&quot; square" class="" src="data:image/png;base64,iVBORw0KGgo=">'
    )


def test_a_complex_figure_is_described_in_full_under_it_and_its_alt_says_so(tmp_path):
    parts = [
        {"name": "left <panel>", "text": "3 blocks", "columns": ["block", "x"], "rows": [["1", "2.5"], ["2", "4"]]},
        {"name": "right", "text": "", "columns": [], "rows": []},
    ]
    figure = nbformat.v4.new_output(
        "display_data",
        data={"image/png": "iVBORw0KGgo="},
        metadata={"image/png": {"alt": "two panels", "details": parts}},
    )
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell("fig")]
    nb.cells[0].outputs = [figure]
    nbformat.write(nb, tmp_path / "chapter.ipynb")
    page = '<div class="jp-RenderedImage"><img alt="No description" src="data:image/png;base64,iVBORw0KGgo="></div>'
    assert site_hooks.figure_alts(page, tmp_path / "chapter.ipynb") == (
        '<div class="jp-RenderedImage">'
        f'<img alt="two panels {alt.DESCRIBED_BELOW}" src="data:image/png;base64,iVBORw0KGgo=">\n'
        '<details class="figure-described"><summary>Figure described</summary>\n'
        "<p><strong>left &lt;panel&gt;</strong>: 3 blocks</p>"
        '<div class="figure-described-table" role="region" tabindex="0" aria-label="table: left &lt;panel&gt;">'
        "<table><caption>left &lt;panel&gt;</caption>"
        '<thead><tr><th scope="col">block</th><th scope="col">x</th></tr></thead>'
        '<tbody><tr><th scope="row">1</th><td>2.5</td></tr><tr><th scope="row">2</th><td>4</td></tr></tbody>'
        "</table></div>"
        "<p><strong>right</strong></p>\n</details></div>"
    )


def test_a_code_cell_folded_in_jupyterlab_is_folded_on_its_page_and_its_outputs_are_not(tmp_path):
    hidden = {"jupyter": {"source_hidden": True}}  # what JupyterLab writes when its input is collapsed
    nb = nbformat.v4.new_notebook()
    nb.cells = [
        nbformat.v4.new_code_cell("# the imports\nimport numpy", id="aa1", metadata=hidden),
        nbformat.v4.new_code_cell("x = 1", id="bb2"),
        nbformat.v4.new_code_cell("\nprint(1)", id="cc3", metadata=hidden),
    ]
    nbformat.write(nb, tmp_path / "chapter.ipynb")
    code = (  # a code cell's input as mkdocs-jupyter writes it; a "</div>" in its code is text
        '<div class="jp-Cell-inputWrapper">\n<div class="jp-InputArea jp-Cell-inputArea">'
        '<div class="highlight-ipynb"><pre>s = "&lt;/div&gt;"</pre></div>\n</div>\n</div>'
    )
    output = '\n<div class="jp-Cell-outputWrapper"><div class="jp-OutputArea-output"><pre>1</pre></div></div>\n</div>'
    page = "".join(f'<div class="jp-Cell jp-CodeCell" id="cell-id={i}">\n{code}{output}' for i in ("aa1", "bb2", "cc3"))
    assert site_fold.fold_code(page, tmp_path / "chapter.ipynb") == (
        '<div class="jp-Cell jp-CodeCell" id="cell-id=aa1">\n'
        f'<details class="code-folded"><summary>Code (folded): the imports</summary>\n{code}</details>{output}'
        f'<div class="jp-Cell jp-CodeCell" id="cell-id=bb2">\n{code}{output}'
        '<div class="jp-Cell jp-CodeCell" id="cell-id=cc3">\n'
        f'<details class="code-folded"><summary>Code (folded)</summary>\n{code}</details>{output}'
    )
    assert site_fold.fold_code(page, tmp_path / "a_page_made_by_hand.ipynb") == page
    assert site_fold.summary("\n  # a helper: draw  \nx") == "Code (folded): a helper: draw"


def test_the_audit_counts_nodes_per_rule_and_lists_only_serious_and_critical_ones():
    found = {
        "a.html": [{"id": "color-contrast", "impact": "serious", "nodes": [{}, {}]}],
        "b.html": [
            {"id": "color-contrast", "impact": "serious", "nodes": [{}]},
            {"id": "region", "impact": "moderate", "nodes": [{}]},
        ],
    }
    assert accessibility.tally(found) == {
        "color-contrast": {"impact": "serious", "nodes": 3, "pages": 2},
        "region": {"impact": "moderate", "nodes": 1, "pages": 1},
    }
    assert accessibility.blocking(found) == {
        "a.html": ["color-contrast (serious): 2 nodes"],
        "b.html": ["color-contrast (serious): 1 nodes"],
    }


def test_sphinx_roles_in_the_api_reference_become_cross_references():
    rendered = (
        '<div class="doc doc-object doc-module">\n<h2 id="toolkit.teaching.grading" class="doc doc-heading">'
        "<p>:func:<code>build</code> then :mod:<code>~toolkit.teaching.notebook</code></p>"
    )
    assert site_hooks.cross_references(rendered).endswith(
        '<p><autoref identifier="toolkit.teaching.grading.build" slug="build" optional><code>build</code></autoref>'
        ' then <autoref identifier="toolkit.teaching.notebook" slug="toolkit.teaching.notebook" optional>'
        "<code>notebook</code></autoref></p>"
    )


# ---- in Chromium ----


@pytest.fixture(scope="module")
def served(site) -> Iterator[str]:
    """The site on a free port of 127.0.0.1, for this module; the port is free again afterwards."""
    with accessibility.served(site.out) as url:
        yield url


def open_page(chromium, url: str, remote: list[str]):
    """A new page at ``url``, loaded; every request it makes to a host other than 127.0.0.1 is aborted and listed."""
    page = chromium.new_page(viewport={"width": 1280, "height": 900})
    page.set_default_timeout(120_000)

    def route(request_route):
        host = urlsplit(request_route.request.url).hostname
        if request_route.request.url.startswith(("http:", "https:", "ws:", "wss:")) and host != "127.0.0.1":
            remote.append(request_route.request.url)
            return request_route.abort()
        return request_route.continue_()

    page.route("**/*", route)
    page.goto(url, wait_until="load")
    return page


def broken_images(page) -> list[str]:
    """The images of ``page`` that did not load (``naturalWidth`` 0), once every image has settled."""
    page.wait_for_function("[...document.images].every(i => i.complete)")
    return page.evaluate("[...document.images].filter(i => i.naturalWidth === 0).map(i => i.src.slice(0, 80))")


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_home_chapters_tutorials_assignments_and_api_reference_show_every_image_in_chromium(site, served, chromium):
    remote: list[str] = []
    executed = ["index.html"] + [str(page_of(site, s).relative_to(site.out)) for s in CHAPTERS + TUTORIALS]
    assignments = [f"tutorials/assignments/{name}/{name}.html" for name in grading.assignment_names()]  # not run
    for path in executed + assignments + ["reference/index.html", "reference/geometry.html"]:
        page = open_page(chromium, served + path, remote)
        try:
            count = page.evaluate("document.images.length")
            assert broken_images(page) == [], path
            assert count >= (1 if path in executed else 0), path
        finally:
            page.close()
    assert remote == []


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_the_chapter_shows_the_embedded_viewer_and_typeset_math(served, chromium):
    remote: list[str] = []
    page = open_page(chromium, served + "notebooks/05_3d_scenes.html", remote)
    try:
        frame = page.locator(".jp-OutputArea-output iframe").first
        frame.scroll_into_view_if_needed()  # under its still, a view is one line tall until it draws (reader r25b)
        page.wait_for_function("f => f.getBoundingClientRect().height > 100", arg=frame.element_handle())
        frame.content_frame.locator("canvas").first.wait_for(state="attached")  # the viewer's WebGL scene
    finally:
        page.close()
    page = open_page(chromium, served + "notebooks/02_cae_reconstruction.html", remote)
    try:
        page.wait_for_function("document.querySelectorAll('.MathJax, .MathJax_Display').length > 10")
        assert page.get_by_text("Math Processing Error").count() == 0
    finally:
        page.close()
    assert remote == []


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_no_page_has_a_serious_or_critical_accessibility_violation(site, served, chromium):
    """axe-core's WCAG 2.0/2.1 A and AA rules on every page, the embedded viewers' frames included
    (``python -m tools.accessibility SITE`` prints the same audit; docs/accessibility.md records it)."""
    found = accessibility.audit_site(chromium, served, accessibility.pages(site.out))
    assert len(found) >= 30
    assert accessibility.blocking(found) == {}


FOCUS = (0x1F, 0x5F, 0x99)  # docs/site/accessibility.css's focus outline
FOCUSABLE = {  # a kind of focusable element: a page that has one, and how to find it
    "scrolling code cell": (
        "notebooks/01_workspaces_and_collision.html",
        ".jupyter-wrapper [role=region][tabindex='0']:visible",  # not one inside a closed fold (an answer's code)
    ),
    "scrolling table": ("docs/accessibility.html", ".md-typeset__scrollwrap[tabindex='0']"),
    "answer disclosure": ("notebooks/01_workspaces_and_collision.html", "details > summary"),
    "figure described": ("notebooks/02_cae_reconstruction.html", "details.figure-described > summary"),
    "link in text": ("index.html", "article p a[href]"),
    "navigation link": ("index.html", ".md-sidebar--primary .md-nav__link[href]"),
}


def focus_ring(page, element) -> int:
    """How many pixels around and on ``element`` turn the focus outline's colour when it takes the focus from the
    keyboard (a screenshot of its box, 8 px wider each side, before and after)."""
    import io

    import numpy as np
    from PIL import Image

    element.scroll_into_view_if_needed()
    page.evaluate("document.activeElement && document.activeElement.blur()")
    page.mouse.move(0, 0)
    box = element.bounding_box()
    width, height = page.viewport_size["width"], page.viewport_size["height"]
    x0, y0 = max(box["x"] - 8, 0), max(box["y"] - 8, 0)
    clip = {
        "x": x0,
        "y": y0,
        "width": min(box["width"] + 16, width - x0),
        "height": min(box["height"] + 16, height - y0),
    }
    shots = []
    for focused in (False, True):
        if focused:
            page.keyboard.press("Shift")  # the keyboard is in use: :focus-visible applies
            element.focus()
        shots.append(np.asarray(Image.open(io.BytesIO(page.screenshot(clip=clip))).convert("RGB"), dtype=int))
    before, after = shots
    near_focus = np.abs(after - np.array(FOCUS)).sum(axis=-1) < 60  # (H, W)
    return int(np.sum(near_focus & (np.abs(after - before).sum(axis=-1) > 30)))


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_every_kind_of_focusable_element_shows_its_focus(site, served, chromium):
    """WCAG 2.4.7: focusing each kind of element from the keyboard draws the outline around it, where a reader
    sees it: not clipped by a scrolling ancestor, not removed by a stylesheet."""
    remote: list[str] = []
    ring = {}
    for kind, (path, selector) in FOCUSABLE.items():
        page = open_page(chromium, served + path, remote)
        try:
            ring[kind] = focus_ring(page, page.locator(selector).first)
        finally:
            page.close()
    assert remote == []
    assert {kind: pixels for kind, pixels in ring.items() if pixels < 40} == {}, ring


FOCUSED_SEEN = """() => {  // the focused element: its name, and whether a reader sees it (some width, not faded out)
    const e = document.activeElement, box = e.getBoundingClientRect();
    let opacity = 1;
    for (let n = e; n; n = n.parentElement) opacity *= parseFloat(getComputedStyle(n).opacity);
    return [e.className.toString(), box.width > 0 && box.height > 0 && opacity > 0.5];
}"""


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_tab_from_the_search_box_never_focuses_something_unseen(site, served, chromium):
    """WCAG 2.4.7/2.4.3: Tab from the search box closes material's search overlay; the focus then goes on to a tab
    stop a reader sees, never to the results box faded out with the overlay (its results are reached by the arrow
    keys), before a query or after one."""
    remote: list[str] = []
    page = open_page(chromium, served + "index.html", remote)
    try:
        focused = []
        for query in ("", "bridge"):
            page.locator("input.md-search__input").click()
            page.keyboard.type(query)
            if query:
                page.locator(".md-search-result__item").first.wait_for()
            for _ in range(2):
                page.keyboard.press("Tab")
                focused.append(page.evaluate(FOCUSED_SEEN))
            page.reload()
    finally:
        page.close()
    assert remote == []
    assert [name for name, seen in focused if not seen or "md-search" in name] == [], focused


FOCUSED_ON_SCREEN = """() => {  // the focused element's name, and whether any of it lies across the viewport's width
    const e = document.activeElement, box = e.getBoundingClientRect();
    return [e.tagName + " " + (e.textContent || "").trim().slice(0, 40), box.right > 0 && box.left < innerWidth];
}"""


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_at_320_px_tab_never_goes_into_the_closed_navigation_drawer(site, served, chromium):
    """WCAG 2.4.7 at 320 CSS px: below material's breakpoint the navigation is a drawer off the screen's left edge;
    closed, its links once took 38 of the home page's first 40 tab stops where no one could see them. Now inert while
    closed: every stop of the first 40 lies on the screen, and opening the drawer makes its links reachable again."""
    remote: list[str] = []
    for path in ("index.html", "notebooks/04_prm_with_and_without_prediction.html"):
        page = open_page(chromium, served + path, remote)
        try:
            page.set_viewport_size({"width": 320, "height": 640})
            page.wait_for_timeout(300)
            off = []
            for _ in range(40):
                page.keyboard.press("Tab")
                name, on_screen = page.evaluate(FOCUSED_ON_SCREEN)
                if not on_screen:
                    off.append(name)
            page.evaluate("document.getElementById('__drawer').click()")
            opened = page.evaluate("!document.querySelector('.md-sidebar--primary').inert")
        finally:
            page.close()
        assert off == [] and opened, (path, off, opened)
    assert remote == []


IN_VIEW = """() => {  // the focused element: its name, and whether all of it is in the window
    const e = document.activeElement, box = e.getBoundingClientRect();
    const name = e.getAttribute("aria-label") || (e.textContent || "").trim().slice(0, 40);
    const inside = box.top >= 0 && box.bottom <= innerHeight && box.left >= 0 && box.right <= innerWidth;
    return [e.tagName + " " + name, inside];
}"""


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_at_320_px_the_keyboard_opens_the_navigation_drawer_and_reaches_its_links(site, served, chromium):
    """WCAG 2.1.1 at 320 CSS px: material opens the navigation drawer by a click on its menu icon only, a label that
    takes no focus, and the closed drawer is inert, so a keyboard user had no way to the site's navigation. The icon is
    now a button the Tab key reaches, saying whether the drawer is open; Enter opens the drawer with the focus on a
    link in it, in view, and Escape closes it and gives the focus back to the button."""
    remote: list[str] = []
    page = open_page(chromium, served + "notebooks/04_prm_with_and_without_prediction.html", remote)
    try:
        page.set_viewport_size({"width": 320, "height": 640})
        page.wait_for_timeout(300)
        menu = page.get_by_role("button", name="The site's navigation")
        assert menu.count() == 1
        for _ in range(10):
            page.keyboard.press("Tab")
            if menu.evaluate("button => button === document.activeElement"):
                break
        assert menu.evaluate("button => button === document.activeElement"), page.evaluate(FOCUSED_ON_SCREEN)
        assert menu.get_attribute("aria-expanded") == "false"
        page.keyboard.press("Enter")
        page.wait_for_timeout(500)  # the drawer slides in (0.25 s)
        assert menu.get_attribute("aria-expanded") == "true"
        in_drawer = "() => !!document.activeElement.closest('.md-sidebar--primary')"
        reached = []
        for _ in range(3):
            name, in_view = page.evaluate(IN_VIEW)
            assert page.evaluate(in_drawer) and name.startswith(("A ", "LABEL ")) and in_view, (name, in_view)
            reached.append(name)
            page.keyboard.press("Tab")
        assert len(set(reached)) == 3, reached
        page.keyboard.press("Escape")
        assert menu.get_attribute("aria-expanded") == "false"
        assert menu.evaluate("button => button === document.activeElement")
        assert page.evaluate("document.querySelector('.md-sidebar--primary').inert")
    finally:
        page.close()
    assert remote == []


OUTLINE_AND_BACKGROUND = """() => {  // the focused element's outline colour, and the colour of what lies behind it
    const e = document.activeElement, style = getComputedStyle(e);
    let behind = e, colour = "rgba(0, 0, 0, 0)";
    while (behind && colour.startsWith("rgba(0, 0, 0, 0)")) {
        colour = getComputedStyle(behind).backgroundColor;
        behind = behind.parentElement;
    }
    return [e.getAttribute("aria-label") || e.textContent.trim().slice(0, 40), style.outlineStyle, style.outlineColor,
            colour];
}"""


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_at_320_px_the_drawers_first_stop_on_the_home_page_shows_its_focus(site, served, chromium):
    """Audit a11y11 (WCAG 2.4.7, 1.4.11): opening the drawer on the home page puts the focus on the site's name, a
    link on the header's blue, and its outline (#1f5f99) stood at 1.03:1 against that blue; now 3:1 or more."""
    from toolkit.plots.palette import contrast

    as_hex = lambda rgb: "#" + "".join(f"{int(v):02x}" for v in re.findall(r"[\d.]+", rgb)[:3])
    remote: list[str] = []
    page = open_page(chromium, served + "index.html", remote)
    try:
        open_drawer(page)
        name, style, outline, behind = page.evaluate(OUTLINE_AND_BACKGROUND)
    finally:
        page.close()
    assert style != "none" and contrast(as_hex(outline), as_hex(behind)) >= 3, (name, outline, behind)
    assert remote == []


def open_drawer(page):
    """At 320 CSS px, the navigation drawer opened from the keyboard (Enter on the menu button); the button."""
    page.set_viewport_size({"width": 320, "height": 640})
    page.wait_for_timeout(300)
    menu = page.get_by_role("button", name="The site's navigation")
    menu.focus()
    page.keyboard.press("Enter")
    page.wait_for_timeout(500)  # the drawer slides in (0.25 s)
    return menu


IN_DRAWER = """() => {  // whether the focus is in the navigation drawer, on the screen; the focused element
    const e = document.activeElement, box = e.getBoundingClientRect();
    const inside = !!e.closest(".md-sidebar--primary") && box.width > 0 && box.left >= 0 && box.right <= innerWidth;
    return [inside, e.tagName + " " + (e.getAttribute("aria-label") || e.textContent || "").trim().slice(0, 40)];
}"""


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_at_320_px_the_open_navigation_drawer_keeps_the_focus_until_escape(site, served, chromium):
    """WCAG 2.4.3 at 320 CSS px: the open navigation drawer covers the page, yet Tab went on from its last link into
    the page behind it (the second outside pass). Tab and Shift+Tab now cycle inside the drawer, every stop on the
    screen, and Escape closes it and gives the focus back to the menu button."""
    remote: list[str] = []
    page = open_page(chromium, served + "notebooks/04_prm_with_and_without_prediction.html", remote)
    try:
        menu = open_drawer(page)
        forward = []
        for _ in range(100):
            forward.append(page.evaluate(IN_DRAWER))
            page.keyboard.press("Tab")
        assert forward[0] in forward[1:], [name for inside, name in forward if not inside]  # Tab went round the drawer
        again = forward.index(forward[0], 1)
        for _ in range(100 % again):  # back to the first stop with Shift+Tab, then on backwards round the drawer
            page.keyboard.press("Shift+Tab")
        assert page.evaluate(IN_DRAWER) == forward[0]
        page.keyboard.press("Shift+Tab")
        assert page.evaluate(IN_DRAWER) == forward[again - 1]
        page.keyboard.press("Escape")
        closed = menu.get_attribute("aria-expanded"), menu.evaluate("button => button === document.activeElement")
    finally:
        page.close()
    assert all(inside for inside, _ in forward), [name for inside, name in forward if not inside]
    assert again >= 6, forward[:3]  # the chapters' panel: its back button and five chapters
    assert closed == ("false", True)
    assert remote == []


SEEN = """() => {  // the focused element's name, whether it is expanded, and whether it shows: on top, in the window
    const e = document.activeElement, box = e.getBoundingClientRect();
    const x = box.left + box.width / 2, y = box.top + Math.min(box.height / 2, 10);
    const top = document.elementFromPoint(x, y), outline = getComputedStyle(e).outlineStyle;
    const seen = box.width > 0 && y >= 0 && y < innerHeight && !!top && e.contains(top) && outline !== "none";
    return [(e.getAttribute("aria-label") || e.textContent).trim().replace(/\\s+/g, " ").slice(0, 30),
        e.getAttribute("aria-expanded"), seen];
}"""


def drawer_stops(page, presses: int) -> list[list]:
    """What :data:`SEEN` says of the focus now and after each of ``presses`` Tab presses."""
    seen = [page.evaluate(SEEN)]
    for _ in range(presses):
        page.keyboard.press("Tab")
        seen.append(page.evaluate(SEEN))
    return seen


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_at_320_px_tab_reaches_only_the_drawers_panel_on_screen_and_its_panel_buttons(site, served, chromium):
    """WCAG 2.4.7, 2.4.3 and 2.1.1 at 320 CSS px (a11y10): material's drawer shows one panel at a time, each nested
    section sliding over its parent, yet Tab went through the links of the panels under it and beside it (41 of 59
    stops unseen on chapter 04), and the labels that open a panel ("Chapters >") or go back took no focus. Tab now
    stops only on what the panel shown holds, each stop on top and outlined; a panel's buttons say whether it is
    open, and Enter and Space open and close it, the focus going on to the panel then shown."""
    remote: list[str] = []
    page = open_page(chromium, served + "notebooks/04_prm_with_and_without_prediction.html", remote)
    try:
        open_drawer(page)
        chapters = drawer_stops(page, 7)  # the chapters' panel, material's panel for the page's own section
        for _ in range(3):  # back to chapter 04's button, which opens its contents
            page.keyboard.press("Shift+Tab")
        opener = page.evaluate(SEEN)
        page.keyboard.press("Enter")
        page.wait_for_timeout(500)
        contents = drawer_stops(page, 25)
        for _ in range(len(contents)):
            if page.evaluate(SEEN)[0] == "Back from Table of contents":
                break
            page.keyboard.press("Shift+Tab")
        page.keyboard.press(" ")  # back to the chapters' panel
        page.wait_for_timeout(500)
        back = page.evaluate(SEEN)
        for _ in range(4):  # on "Back from Chapters"
            page.keyboard.press("Shift+Tab")
        page.keyboard.press("Enter")
        page.wait_for_timeout(500)
        root = drawer_stops(page, 8)
    finally:
        page.close()
    names = [name for name, _, _ in chapters]
    assert names[0] == "Back from Chapters" and [n[:2] for n in names[1:6]] == ["01", "02", "03", "04", "05"], names
    assert names[6] == names[0], names  # and round again
    assert opener[:2] == [names[4], "false"], opener
    assert contents[0][0] == "Back from Table of contents" and len(contents) - len(set(map(tuple, contents))) > 0
    assert back == [names[4], "false", True], back
    assert {name for name, _, _ in root} >= {"Home", "Chapters", "Tutorials", "Docs"}, root
    assert next(stop for stop in root if stop[0] == "Docs")[1] == "false"
    assert [stop for stop in chapters + contents + root if not stop[2]] == []
    assert remote == []


COPY_BUTTONS = """() => {
  document.querySelectorAll("details.code-folded").forEach(d => { d.open = true; });  // a folded cell's code, opened
  return [...document.querySelectorAll(".jupyter-wrapper .zeroclipboard-container")].map(box => {
    box.scrollIntoView({block: "center"});  // each copy button: how far its code runs under it, whether it shows
    const button = box.querySelector("[role=button]").getBoundingClientRect();
    const code = box.parentElement.querySelector(".highlight-ipynb").getBoundingClientRect();
    const top = document.elementFromPoint(button.left + button.width / 2, button.top + button.height / 2);
    return [Math.round(code.right - button.left), button.width > 0 && button.right <= innerWidth && box.contains(top)];
  });
}"""


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_at_320_px_no_copy_button_covers_the_end_of_a_code_line(site, served, chromium):
    """WCAG 1.4.10 at 320 CSS px: a code cell's "Copy to Clipboard" button sat over the cell's top right corner and
    hid the end of the line shown there (the second outside pass, chapter 02). Every cell's code now stops short of
    its button, which still shows, on top, within the window."""
    remote: list[str] = []
    for path in ("notebooks/02_cae_reconstruction.html", "notebooks/04_prm_with_and_without_prediction.html"):
        page = open_page(chromium, served + path, remote)
        try:
            page.set_viewport_size({"width": 320, "height": 640})
            page.wait_for_timeout(300)
            buttons = page.evaluate(COPY_BUTTONS)
        finally:
            page.close()
        assert buttons and all(under <= 0 and shown for under, shown in buttons), (path, buttons)
    assert remote == []


FRAME_FOCUS_IN_VIEW = """(frame) => {  // the control focused in ``frame``: its name, whether all of it is in the window
    const e = frame.contentDocument.activeElement, box = e.getBoundingClientRect(), at = frame.getBoundingClientRect();
    const top = at.top + box.top, bottom = at.top + box.bottom;
    const header = document.querySelector(".md-header").getBoundingClientRect().bottom;
    return [e.tagName + " " + (e.getAttribute("aria-label") || e.textContent.trim().slice(0, 40)),
            top >= header && bottom <= innerHeight, [Math.round(top), Math.round(bottom), scrollY]];
}"""


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_a_control_of_an_embedded_scene_that_takes_the_focus_is_scrolled_into_view(site, served, chromium):
    """WCAG 2.4.7 and 2.4.3 on chapter 05 at 1280 x 900: Tab reached a scene's "Show scene tree" button while only
    the frame's top edge showed at the window's bottom; the browser scrolled the frame's own page, not the chapter,
    so the focus was out of sight. Now every control focused in a frame, by Tab or Shift+Tab, lies in the window
    below the header."""
    remote: list[str] = []
    page = open_page(chromium, served + "notebooks/05_3d_scenes.html", remote)
    try:
        frames = page.locator("iframe")
        for i in range(frames.count()):  # each scene's page built (its controls exist) before the keyboard comes
            frames.nth(i).content_frame.locator("button").first.wait_for(state="attached")
        unseen, seen = [], 0
        for key in ("Tab", "Shift+Tab"):
            page.evaluate("window.scrollTo(0, 0); document.activeElement.blur()")
            for _ in range(400):
                page.keyboard.press(key)
                inside = page.evaluate("[...document.querySelectorAll('iframe')].indexOf(document.activeElement)")
                if inside < 0:
                    continue
                page.wait_for_timeout(100)  # a smooth scroll, were there one, is over
                name, in_view, where = frames.nth(inside).evaluate(FRAME_FOCUS_IN_VIEW)
                seen += 1
                if not in_view:
                    unseen.append((key, inside, name, where))
    finally:
        page.close()
    assert seen >= 20 and unseen == [], (seen, unseen)
    assert remote == []


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_play_in_3d_puts_the_focus_on_the_players_play_pause_button(site, served, chromium):
    """WCAG 2.4.3 on chapter 05: the animation shows a still with a "play in 3D" button first; pressed, it took the
    still away and the focus with it (to the frame's body), so a keyboard user started again from the frame's top.
    Now the focus goes on to the player's play / pause button."""
    from toolkit.viewer import labels

    remote: list[str] = []
    page = open_page(chromium, served + "notebooks/05_3d_scenes.html", remote)
    try:
        page.locator("iframe").last.content_frame.locator("button").first.wait_for(state="attached")
        stills = [f for f in page.frames if f.get_by_role("button", name="play in 3D").count()]
        assert len(stills) == 1
        stills[0].get_by_role("button", name="play in 3D").focus()
        page.keyboard.press("Enter")
        page.wait_for_timeout(300)
        named = stills[0].evaluate("document.activeElement.getAttribute('aria-label')")
    finally:
        page.close()
    assert named == labels.PLAY_PAUSE, named
    assert remote == []


TABLES_CUT = r"""() => {
    // Each table of the page, read as a student at 1280 px sees it: it fits its column, or the region that scrolls it
    // sideways fits the column, says that it scrolls, and is reachable by keyboard; no ancestor cuts it off.
    const scrolls = (e) => ["auto", "scroll"].includes(getComputedStyle(e).overflowX);
    const clips = (e) => ["hidden", "clip"].includes(getComputedStyle(e).overflowX);
    const cut = [];
    for (const table of document.querySelectorAll(".md-content table")) {
        const column = table.closest(".md-content").getBoundingClientRect();
        let box = table.getBoundingClientRect(), why = "";
        for (let e = table.parentElement; e && !e.classList.contains("md-content"); e = e.parentElement) {
            const r = e.getBoundingClientRect();
            if (scrolls(e) && e.scrollWidth > e.clientWidth + 1) {  // a region that scrolls the table sideways
                if (e.getAttribute("tabindex") !== "0") why ||= "scrolls, but the keyboard cannot reach it";
                const note = getComputedStyle(e, "::before").content;  // what tells a reader it scrolls
                if (!note.toLowerCase().includes("scroll sideways")) why ||= "scrolls, but nothing says so";
                box = r;
            } else if (clips(e) && r.right < box.right - 1) why ||= `cut by ${e.className || e.tagName}`;
        }
        if (box.right > column.right + 1 || box.left < column.left - 1) why ||= "wider than its column";
        if (why) cut.push(`${table.rows[0]?.textContent.trim().replace(/\s+/g, " ").slice(0, 50)}: ${why}`);
    }
    return cut;
}"""


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_every_table_fits_its_column_or_scrolls_in_a_region_the_keyboard_reaches(site, served, chromium):
    """At 1280 px, a wide table on a chapter or on the benchmarks page is never cut off at the column's edge: it fits,
    or it scrolls sideways in a region that says so in words (a headless or overlay scroll bar shows nothing) and that
    the keyboard reaches (WCAG 1.4.10, 2.1.1)."""
    remote: list[str] = []
    cut = {}
    for path in [str(page_of(site, s).relative_to(site.out)) for s in CHAPTERS] + ["docs/benchmarks.html"]:
        page = open_page(chromium, served + path, remote)
        try:
            page.wait_for_timeout(300)  # material wraps the tables when the page is ready
            cut[path] = page.evaluate(TABLES_CUT)
            if path == "docs/benchmarks.html":  # the check finds a wide table no stylesheet made scroll
                wide = (  # material lets a bare table scroll itself: this one cannot, and its box cuts it off
                    '<div style="overflow: hidden"><table style="display: table; overflow: visible">'
                    '<tr><td style="min-width: 3000px">wide</td></tr></table>'
                )
                page.evaluate("html => document.querySelector('article').insertAdjacentHTML('beforeend', html)", wide)
                assert page.evaluate(TABLES_CUT) == cut[path] + ["wide: cut by DIV"]
        finally:
            page.close()
    assert {path: tables for path, tables in cut.items() if tables} == {}
    assert remote == []


MATHJAX_IDLE = (  # MathJax 2 has typeset everything it was given
    "MathJax.Hub.queue.pending === 0 && MathJax.Hub.queue.running === 0"
    " && document.querySelectorAll('.MathJax_Preview:not(:empty)').length === 0"
)
TEXT_SPACING = "* { line-height: 1.5 !important; letter-spacing: 0.12em !important; word-spacing: 0.16em !important; }"


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
@pytest.mark.parametrize("spacing", [False, True], ids=["as styled", "WCAG text spacing"])
def test_display_math_scrolls_at_320_px_instead_of_being_cut(served, chromium, spacing):
    """WCAG 1.4.10 and 1.4.12: at 320 CSS px, with and without the text spacing of 1.4.12, every display equation
    fits or scrolls sideways, and one that scrolls is a region the keyboard reaches."""
    remote: list[str] = []
    cut = {}
    for path in ("notebooks/01_workspaces_and_collision.html", "notebooks/02_cae_reconstruction.html"):
        page = chromium.new_page(viewport={"width": 320, "height": 640})
        try:
            page.goto(served + path, wait_until="load")
            page.wait_for_function("document.querySelectorAll('.MathJax').length > 10", timeout=120_000)
            page.wait_for_function(MATHJAX_IDLE, timeout=120_000)
            if spacing:
                page.add_style_tag(content=TEXT_SPACING)
            page.wait_for_timeout(500)
            found = page.evaluate(
                """() => [...document.querySelectorAll('.MathJax_Display')].map(m => {
                    const style = getComputedStyle(m), over = m.scrollWidth - m.clientWidth;
                    const scrolls = over > 1 && ['auto', 'scroll'].includes(style.overflowX);
                    const reachable = m.getAttribute('tabindex') === '0' && m.getAttribute('role') === 'region';
                    const tall = m.scrollHeight - m.clientHeight > 1 && !['auto', 'scroll'].includes(style.overflowY);
                    return {over, ok: (over <= 1 || (scrolls && reachable)) && !tall, text: m.textContent.slice(0, 30)};
                })"""
            )
            assert any(f["over"] > 1 for f in found), path  # at 320 px an equation of each page is too wide
            cut[path] = [f"{f['text']!r} {f['over']} px" for f in found if not f["ok"]]
        finally:
            page.close()
    assert {path: eqs for path, eqs in cut.items() if eqs} == {}
    assert remote == []


GLYPHS = """() => {  // per equation: how far its glyphs run past its box (px), and how many pairs of them overlap
    const found = [];
    for (const math of document.querySelectorAll('.MathJax')) {
        const box = math.getBoundingClientRect();
        const glyphs = [...math.querySelectorAll('span.mi, span.mo, span.mn, span.mtext')]
            .map(g => g.getBoundingClientRect()).filter(r => r.width > 0);
        let overlaps = 0;
        for (let i = 0; i < glyphs.length; i++) for (let j = i + 1; j < glyphs.length; j++) {
            const a = glyphs[i], b = glyphs[j];
            const wide = Math.min(a.right, b.right) - Math.max(a.left, b.left);
            const high = Math.min(a.bottom, b.bottom) - Math.max(a.top, b.top);
            if (wide > 2 && high > 2) overlaps++;
        }
        const past = Math.max(0, ...glyphs.map(r => r.right - box.right));
        found.push({tex: math.nextElementSibling?.textContent.slice(0, 40), past: Math.round(past), overlaps});
    }
    return found;
}"""


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_equations_keep_their_glyphs_apart_under_text_spacing(served, chromium):
    """WCAG 1.4.12: MathJax places each glyph where its font's metrics put it; with the text spacing of 1.4.12 no
    glyph runs past its equation's box (02's Eq. (1), 04's inline "t_with / t_without = 1 - improvement", cut by
    its cell at 320 px) and no two glyphs overlap that did not as styled (02's superscript 2 ran into the "+")."""
    remote: list[str] = []
    changed = {}
    for path in ("notebooks/02_cae_reconstruction.html", "notebooks/04_prm_with_and_without_prediction.html"):
        page = open_page(chromium, served + path, remote)
        try:
            page.set_viewport_size({"width": 320, "height": 640})
            page.wait_for_function("document.querySelectorAll('.MathJax').length > 3", timeout=120_000)
            page.wait_for_function(MATHJAX_IDLE, timeout=120_000)
            styled = page.evaluate(GLYPHS)
            page.add_style_tag(content=TEXT_SPACING)
            page.wait_for_timeout(500)
            spaced = page.evaluate(GLYPHS)
            assert len(spaced) == len(styled) > 3
            changed[path] = [
                f"{after['tex']!r}: {after['past']} px out, overlaps {before['overlaps']} -> {after['overlaps']}"
                for before, after in zip(styled, spaced)
                if after["past"] > 1 or after["overlaps"] > before["overlaps"]
            ]
        finally:
            page.close()
    assert remote == []
    assert {path: found for path, found in changed.items() if found} == {}


AUDITED = ["index.html", *(f"notebooks/{c.stem}.html" for c in CHAPTERS)]  # what the manual pass went through
TAB_STOP = """() => {  // the focused element: its accessible name as ARIA computes it, its box, its outline
    const e = document.activeElement;
    if (!e || e === document.body) return null;
    const box = e.getBoundingClientRect(), style = getComputedStyle(e);
    const labelled = (e.getAttribute('aria-labelledby') || '').split(/\\s+/).filter(Boolean)
        .map(id => document.getElementById(id)?.textContent || '').join(' ');
    // a link, a button or a disclosure is named by its content; a <div>, <pre> or <code> that takes the focus
    // (to scroll) never is (ARIA: its role prohibits it), though Chromium's tree reads its text as a name
    const fromContent = ['A', 'BUTTON', 'SUMMARY'].includes(e.tagName)
        || ['button', 'link', 'tab', 'menuitem', 'option', 'checkbox', 'switch'].includes(e.getAttribute('role'));
    const content = fromContent ? e.textContent.trim() || [...e.querySelectorAll('img')].map(i => i.alt).join(' ') : '';
    const labels = e.labels ? [...e.labels].map(l => l.textContent).join(' ') : '';
    const name = (e.getAttribute('aria-label') || labelled || content || labels || e.getAttribute('title')
        || (e.tagName === 'IMG' ? e.alt : '') || e.getAttribute('placeholder') || '').trim();
    return {tag: e.tagName, cls: String(e.className).slice(0, 40), name: name.slice(0, 60),
            area: box.width * box.height,
            outline: style.outlineStyle !== 'none' && parseFloat(style.outlineWidth) >= 2,
            where: Math.round(box.x) + ',' + Math.round(box.y + scrollY)};
}"""


def tab_stops(page, limit: int = 1000) -> list[dict]:
    """Every element the Tab key reaches on ``page``, in order, once round (:data:`TAB_STOP` of each)."""
    stops: list[dict] = []
    for _ in range(limit):
        page.keyboard.press("Tab")
        stop = page.evaluate(TAB_STOP)
        if stop is None or (stops and stop == stops[0]):
            break
        stops.append(stop)
    return stops


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_every_tab_stop_of_the_home_page_and_the_chapters_is_named_and_outlined(site, served, chromium):
    """WCAG 2.4.7 and 4.1.2, as the manual pass checked them: Tab through the home page and every chapter; each
    element that takes the focus has a name and a box, and an outline of 2 px or more (the search box, whose
    focus material shows by turning it white, and the viewer's frames, where the focus moves inside, aside).
    A region that takes the focus to scroll is named by its label, never by its text (:data:`TAB_STOP`): read so,
    the site before issue 47's last round had 6 blocks of code (material's ``<pre><code>``), the search results
    and every notebook output as tab stops of no name."""
    remote: list[str] = []
    unnamed, unseen, counted = {}, {}, {}
    for path in AUDITED:
        page = open_page(chromium, served + path, remote)
        try:
            page.wait_for_timeout(1000)  # MathJax and material's scripts have made their elements focusable
            stops = tab_stops(page)
        finally:
            page.close()
        counted[path] = len(stops)
        unnamed[path] = [s for s in stops if not s["name"] and s["tag"] != "IFRAME"]
        framed = ("IFRAME", "INPUT")
        unseen[path] = [s for s in stops if s["tag"] not in framed and (not s["outline"] or s["area"] < 4)]
    assert all(n >= 20 for n in counted.values()), counted
    assert {p: s for p, s in unnamed.items() if s} == {}
    assert {p: s for p, s in unseen.items() if s} == {}
    assert remote == []


FRAME_STOP = """() => {  // inside an embedded scene: the focused control, its name and whether it is outlined
    const e = document.activeElement;
    if (!e || e === document.body) return null;
    const style = getComputedStyle(e), labelled = e.getAttribute('aria-labelledby');
    const name = e.getAttribute('aria-label') || (labelled && document.getElementById(labelled)?.textContent)
        || (e.tagName === 'BUTTON' ? e.textContent.trim() : '') || e.getAttribute('title') || '';
    return {tag: e.tagName, name: name.trim().slice(0, 40),
            outline: style.outlineStyle !== 'none' && parseFloat(style.outlineWidth) >= 2};
}"""


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
@pytest.mark.parametrize("key", ["Tab", "Shift+Tab"])
def test_the_keyboard_enters_and_leaves_every_embedded_scene_and_sees_where_it_is(site, served, chromium, key):
    """WCAG 2.1.2, 2.4.3 and 2.4.7 on chapter 05: pressing Tab (or Shift+Tab) round the page enters each scene's frame
    (each titled apart), meets only named controls there, each outlined when it has the focus, and leaves the frame
    to the page again after a few presses: no keyboard trap."""
    remote: list[str] = []
    page = open_page(chromium, served + "notebooks/05_3d_scenes.html", remote)
    try:
        frames = page.locator("iframe")
        titles = frames.evaluate_all("all => all.map(f => f.title)")
        assert len(titles) >= 3 and len(set(titles)) == len(titles)
        for i in range(len(titles)):  # each scene's page built (its controls exist) before the keyboard comes
            frames.nth(i).content_frame.locator("button").first.wait_for(state="attached")
        visits: list[int] = []  # per press: the frame that holds the focus (its index), -1 for the page itself
        stops: dict[int, list[dict]] = {i: [] for i in range(len(titles))}
        for _ in range(600):
            page.keyboard.press(key)
            inside = page.evaluate("[...document.querySelectorAll('iframe')].indexOf(document.activeElement)")
            visits.append(inside)
            if inside >= 0:
                stops[inside].append(frames.nth(inside).element_handle().content_frame().evaluate(FRAME_STOP))
            if all(stops.values()) and visits[-1] == -1 and visits.count(-1) > 150:
                break
    finally:
        page.close()
    runs = [(f, len(list(group))) for f, group in itertools.groupby(visits) if f >= 0]  # each stay in a frame
    assert {f for f, _ in runs} == set(range(len(titles))), visits  # every frame entered ...
    assert visits[-1] == -1 and max(n for _, n in runs) <= 10, runs  # ... and left after a few presses
    lacking = [
        (titles[f][:40], s) for f, found in stops.items() for s in found if not (s and s["name"] and s["outline"])
    ]
    assert lacking == []
    assert remote == []


def accessibility_tree(page) -> list[dict]:
    """Chromium's accessibility tree of ``page`` (CDP's ``Accessibility.getFullAXTree``): what a screen reader reads,
    names in full (Playwright's ``aria_snapshot`` leaves out names of about 1000 characters and more), in reading
    order: depth first from the root through each node's children (CDP's flat list need not be in that order; it
    once put chapter 03's title after its first sections)."""
    session = page.context.new_cdp_session(page)
    try:
        nodes = session.send("Accessibility.getFullAXTree")["nodes"]
    finally:
        session.detach()
    by_id = {n["nodeId"]: n for n in nodes}
    ordered, stack = [], [nodes[0]["nodeId"]] if nodes else []
    while stack:
        node = by_id.get(stack.pop())
        if node is None:
            continue
        if not node.get("ignored"):
            ordered.append(node)
        stack.extend(reversed(node.get("childIds", [])))
    return ordered


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_a_screen_reader_hears_every_image_link_and_button_named_and_the_headings_in_order(site, served, chromium):
    """WCAG 1.1.1, 1.3.1, 2.4.6 and 4.1.2 in Chromium's accessibility tree of the home page and every chapter:
    every image (material's icons hidden), link and button has a name, no figure says nbconvert's placeholder,
    one heading of level 1 opens the page and no heading skips a level below the one before it."""
    remote: list[str] = []
    found = {}
    for path in AUDITED:
        page = open_page(chromium, served + path, remote)
        try:
            page.wait_for_timeout(1000)
            nodes = accessibility_tree(page)
        finally:
            page.close()
        name = lambda n: str(n.get("name", {}).get("value", "")).strip()
        role = lambda n: n.get("role", {}).get("value")
        levels = [
            int(p["value"]["value"])
            for n in nodes
            if role(n) == "heading"
            for p in n.get("properties", [])
            if p["name"] == "level"
        ]
        found[path] = {
            "unnamed": [role(n) for n in nodes if role(n) in ("image", "img", "link", "button") and not name(n)],
            "placeholder": [name(n)[:60] for n in nodes if "No description has been provided" in name(n)],
            "first heading": levels[:1],
            "skips": [(a, b) for a, b in zip(levels, levels[1:]) if b > a + 1],
            "level 1": levels.count(1),
        }
    expected = {"unnamed": [], "placeholder": [], "first heading": [1], "skips": [], "level 1": 1}
    assert {p: f for p, f in found.items() if f != expected} == {}
    assert remote == []


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
@pytest.mark.parametrize("spacing", [False, True], ids=["as styled", "WCAG text spacing"])
def test_no_page_of_the_manual_pass_scrolls_sideways_at_320_px(served, chromium, spacing):
    """WCAG 1.4.10 and 1.4.12: at 320 CSS px, with and without text spacing, the home page and every chapter reflow:
    the page itself never scrolls sideways (wide code, tables, equations and figures scroll or shrink in their
    own boxes)."""
    wide = {}
    for path in AUDITED:
        page = chromium.new_page(viewport={"width": 320, "height": 640})
        try:
            page.goto(served + path, wait_until="load")
            if spacing:
                page.add_style_tag(content=TEXT_SPACING + " p { margin-bottom: 2em !important; }")
            page.wait_for_timeout(1500)
            wide[path] = page.evaluate("document.documentElement.scrollWidth - document.documentElement.clientWidth")
        finally:
            page.close()
    assert {p: px for p, px in wide.items() if px > 0} == {}


def search(page, words: str) -> list[str]:
    """Type ``words`` into the site's search box (key by key, as a reader does); the titles of the results."""
    page.locator("input.md-search__input").click()
    page.keyboard.type(words)
    page.locator(".md-search-result__item").first.wait_for()
    return page.locator(".md-search-result__item h1, .md-search-result__item h2").all_inner_texts()


@pytest.mark.slow
@pytest.mark.browser
@needs_chromium
def test_search_finds_the_bridge_test_served_and_opened_from_disk(site, served, chromium):
    remote: list[str] = []
    for url in (served + "index.html", (site.out / "index.html").as_uri()):
        page = open_page(chromium, url, remote)
        try:
            results = search(page, "bridge test")
            assert any("bridge" in r.lower() for r in results), (url, results)
        finally:
            page.close()
    assert remote == []


class Links(HTMLParser):
    """The ``href``/``src`` of a page's tags and the ids it defines."""

    def __init__(self):
        super().__init__()
        self.links: list[str] = []
        self.ids: set[str] = set()

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if name in ("href", "src") and value and tag != "iframe":
                self.links.append(value)
            elif name in ("id", "name") and value:
                self.ids.add(value)


def crawl(base: str) -> tuple[int, list[str]]:
    """Follow every internal link from ``base + "index.html"``; the number of files read and the links that are
    broken (no such file, or no such anchor on its page)."""
    pages: dict[str, Links | None] = {}
    queue, broken = [base + "index.html"], set()
    while queue:
        url, fragment = urldefrag(queue.pop())
        if url not in pages:
            pages[url] = found = read(url)
            links = [urljoin(url, link) for link in (found.links if found else []) if not link.startswith("data:")]
            queue += [link for link in links if link.startswith(base)]
        page = pages[url]
        if page is None or (fragment and fragment not in page.ids):
            broken.add(f"{url}#{fragment}" if fragment else url)
    return len(pages), sorted(broken)


def read(url: str) -> Links | None:
    try:
        with urlopen(url) as response:
            body = response.read()
    except HTTPError:
        return None
    links = Links()
    if url.endswith(".html"):
        links.feed(body.decode("utf-8", "replace"))
    return links


@pytest.mark.slow
@pytest.mark.browser
def test_no_internal_link_is_broken(site, served):
    pages, broken = crawl(served)
    assert pages >= 30 and broken == []


def test_folded_headings_stay_out_of_the_table_of_contents():
    """Review r28f, item 7: the results page's table of contents listed every table folded inside a ``<details>``.
    Headings in a fold, at any depth of folds, leave the contents; the ones outside stay, with their children."""
    from mkdocs.structure.toc import get_toc

    page = (
        '<h2 id="run">Run</h2><details><summary>tables</summary><h3 id="t1">T1</h3>'
        '<details><summary>more</summary><h3 id="t2">T2</h3></details><h3 id="t3">T3</h3></details>'
        '<h3 id="shown">Shown</h3><h2 id="next">Next</h2>'
    )
    assert site_hooks.folded(page) == {"t1", "t2", "t3"}
    tokens = [
        {"level": 2, "id": "run", "name": "Run", "children": []},
        {"level": 3, "id": "t1", "name": "T1", "children": []},
        {"level": 3, "id": "shown", "name": "Shown", "children": []},
        {"level": 2, "id": "next", "name": "Next", "children": []},
    ]
    toc = site_hooks.unfolded(list(get_toc(site_hooks.nested(tokens))), site_hooks.folded(page))
    assert [(e.id, [c.id for c in e.children]) for e in toc] == [("run", ["shown"]), ("next", [])]


def test_the_index_links_out_for_the_valid_share_argument():
    """Reader r49e, home contradiction 3: 50-55 % on a balanced test beside the paper's 71-88 % could look chosen;
    on uniform 3DC-7 samples the rebuilt network's one answer scores the valid share, above the paper's 71 %.
    Reader r57e, home lift 4: "What we found, in brief" gives one line per finding and links to chapter 05, whose fold
    'Which "unseen" test did the paper score?' makes that argument from the record."""
    from toolkit.experiments.paper_numbers import MLP
    from toolkit.teaching import chapter05_runs, recorded

    row = recorded.table("paper", "MLP accuracy")["3dc7"]
    assert row["Unseen TPR"].startswith("**100%**") and row["Unseen TNR"].startswith("**0%**")  # "valid" to all
    share = recorded.ours(row["Unseen always valid"])
    assert recorded.ours(row["Unseen Acc"]) == share > MLP["3dc7"]["unseen"]["acc"]
    paper = MLP["3dc7"]["unseen"]
    valid = (paper["acc"] - paper["tnr"]) / (paper["tpr"] - paper["tnr"])  # acc = p TPR + (1 - p) TNR
    fold = chapter05_runs.paper_share()
    assert f"valid share of about {valid:.0%}" in fold and f"the share is about {1 - valid:.0%}" in fold
    brief = README.read_text().partition("\n## What we found, in brief\n")[2].partition("\n## ")[0]
    accuracy = " ".join(next(b for b in brief.split("\n- ") if "**Accuracy.**" in b).split())
    assert accuracy.endswith(
        "why the paper's 71 % on 3DC-7 is not a no-skill score: [notebook 05](notebooks/05_3d_scenes.ipynb))."
    )
    assert "hint at a test" not in flat_readme() and len(accuracy.split()) <= 70
