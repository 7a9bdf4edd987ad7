"""Every notebook runs top to bottom in quick mode (``TOOLKIT_QUICK=1``); every notebook of the repository
(chapters, tutorials, assignment masters) is committed without outputs.

Executed by :mod:`tools.notebook_runner` in a real kernel, as a student's JupyterLab
would; trained models go to a cache folder of this test session, not the user's.
"""

import base64
import json
import os
import re
from pathlib import Path

import nbformat
import pytest

from tools import notebook_runner
from tools.notebook_runner import NotebookRun, widget_outputs
from tools.site import LIVE_ONLY_IN_JUPYTERLAB, WIDGET_VIEW, static_widgets

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))  # 01_... to 05_...
COMMITTED = (
    NOTEBOOKS  # chapters
    + sorted((ROOT / "tutorials").glob("*.ipynb"))  # tutorials
    + sorted((ROOT / "tutorials" / "assignments").glob("*/*.ipynb"))  # assignment masters
)


def test_the_five_notebooks_exist():
    assert [p.name[:2] for p in NOTEBOOKS] == ["01", "02", "03", "04", "05"]


@pytest.mark.parametrize("path", COMMITTED, ids=lambda p: p.stem)
def test_committed_without_outputs(path):
    nb = json.loads(path.read_text())
    for i, cell in enumerate(nb["cells"]):
        if cell["cell_type"] == "code":
            assert cell.get("outputs") == [], f"{path.name} cell {i} has outputs: clear them before committing"
            assert cell.get("execution_count") is None, f"{path.name} cell {i} has an execution count"
    assert "widgets" not in nb["metadata"], f"{path.name} carries saved widget state"


@pytest.mark.parametrize("path", NOTEBOOKS + sorted((ROOT / "tutorials").glob("*.ipynb")), ids=lambda p: p.stem)
def test_the_first_code_cell_says_the_size_it_runs_at(path):
    """In quick mode a student learns what shrank before anything runs at that size: the first code cell that names a
    size (the first code cell where none does) names them all and calls ``banner()``; a cell before it may only read
    the record (chapter 04 prints its recorded answer first, review r24a), never a size."""
    cells = ["".join(cell["source"]) for cell in json.loads(path.read_text())["cells"] if cell["cell_type"] == "code"]
    first = next((k for k, code in enumerate(cells) if re.search(r"\bsized\(", code)), 0)
    code = cells[first]
    assert all("_quick" not in before and "TOOLKIT_QUICK" not in before for before in cells[:first])
    assert re.search(r"^banner\(", code, re.MULTILINE), f"{path.name}: its first code cell does not call banner()"
    sizes = re.findall(r"\bsized\((.*)\)", code)
    assert all("what=" in args for args in sizes), f"{path.name}: name every size for the banner (sized(..., what=))"


# Running each one in quick mode (no error, its figures shown) is tests/test_site.py's build: one execution serves both.


SIZED = re.compile(r"^([A-Z][A-Z0-9_]*) = sized\(\s*full=([\d_]+), quick=([\d_]+)", re.M)
MENTION = re.compile(r"`([A-Z][A-Z0-9_]*)`([^`]{0,80})")  # a constant named in prose, and what follows it
SAID = {"full": re.compile(r"([\d,]+) at full size"), "quick": re.compile(r"([\d,]+) in quick mode")}


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_a_size_the_prose_gives_by_value_is_the_one_the_code_sets(path):
    """Prose that names a size, e.g. "`N_WORKSPACES` workspaces (200 at full size, 20 in quick mode)", gives the
    values of ``sized(full=..., quick=...)`` in the same notebook: typed numbers go stale when a size changes."""
    nb = nbformat.read(path, as_version=4)
    code = "\n".join(c.source for c in nb.cells if c.cell_type == "code")
    sizes = {name: {"full": int(full), "quick": int(quick)} for name, full, quick in SIZED.findall(code)}
    checked = 0
    for cell in (c for c in nb.cells if c.cell_type == "markdown"):
        for name, after in MENTION.findall(cell.source):
            for mode, pattern in SAID.items():
                said = pattern.search(after.split(".")[0])
                if name in sizes and said:
                    assert int(said.group(1).replace(",", "")) == sizes[name][mode], (name, mode, after)
                    checked += 1
    if path.stem.startswith(("01", "02", "03")):
        assert checked, "no size given by value was found: the pattern no longer matches the prose"


def test_every_mention_of_a_notebook_names_one_that_exists():
    documents = [ROOT / "README.md"] + [
        p
        for folder in ("docs", "notebooks", "tutorials", "toolkit", "tests")
        for p in (ROOT / folder).rglob("*")
        if p.suffix in (".md", ".ipynb", ".py") and "dist" not in p.relative_to(ROOT).parts
    ]
    names = {p.name for p in NOTEBOOKS}
    wrong = {
        (str(doc.relative_to(ROOT)), name)
        for doc in documents
        for name in re.findall(r"\b\d\d_[a-z0-9_]+\.ipynb", doc.read_text(errors="ignore"))
        if name not in names
    }
    assert not wrong, f"mentions of notebooks that do not exist: {sorted(wrong)}"


# ---- what a static page shows of an executed notebook's widgets (tools/site.py, tools/notebook_runner.py) ----


def executed_with_widget(state: dict, top: str) -> nbformat.NotebookNode:
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell("widget")]
    view = {"model_id": top, "version_major": 2, "version_minor": 0}
    nb.cells[0].outputs = [nbformat.v4.new_output("display_data", data={WIDGET_VIEW: view, "text/plain": "w"})]
    nb.metadata["widgets"] = {"application/vnd.jupyter.widget-state+json": {"state": state}}
    return nb


def test_a_progress_bar_leaves_nothing_on_the_page():
    state = {  # what tqdm.auto shows in a kernel: an HBox of a label, a FloatProgress and a label
        "bar": {"model_name": "HBoxModel", "state": {"children": ["IPY_MODEL_a", "IPY_MODEL_p", "IPY_MODEL_b"]}},
        "a": {"model_name": "HTMLModel", "state": {"value": "train samples"}},
        "p": {"model_name": "FloatProgressModel", "state": {"value": 3}},
        "b": {"model_name": "HTMLModel", "state": {"value": "3/8"}},
    }
    assert static_widgets(executed_with_widget(state, "bar")).cells[0].outputs == []


def test_an_image_widget_shows_its_picture_with_its_tooltip_as_alt_and_a_note_only_beside_a_control():
    png = base64.b64encode(b"\x89PNG picture").decode()
    picture = {
        "model_name": "ImageModel",
        "state": {"format": "png", "tooltip": "threshold 0.50: 3 mistakes"},
        "buffers": [{"path": ["value"], "data": png, "encoding": "base64"}],
    }
    alone = static_widgets(executed_with_widget({"img": picture}, "img")).cells[0].outputs
    assert [o["data"]["image/png"] for o in alone] == [png]  # no "Live in JupyterLab" note: nothing to drive
    assert alone[0]["metadata"]["image/png"]["alt"] == "threshold 0.50: 3 mistakes"
    state = {
        "box": {"model_name": "VBoxModel", "state": {"children": ["IPY_MODEL_slider", "IPY_MODEL_img"]}},
        "slider": {"model_name": "FloatSliderModel", "state": {"value": 0.5}},
        "img": picture,
    }
    nb = executed_with_widget(state, "box")
    assert NotebookRun(nb, widget_outputs(nb), 0.0, 0.0).figures == 1  # the runner counts the picture too
    outputs = static_widgets(nb).cells[0].outputs
    assert outputs[0]["data"]["text/html"] == LIVE_ONLY_IN_JUPYTERLAB and outputs[1]["data"]["image/png"] == png


def test_a_headless_run_switches_progress_bars_off_and_restores_the_variable(monkeypatch, tmp_path):
    seen = []
    monkeypatch.setattr(
        notebook_runner.NotebookClient, "execute", lambda self: seen.append(os.environ.get("TQDM_DISABLE"))
    )
    monkeypatch.delenv("TQDM_DISABLE", raising=False)
    nbformat.write(nbformat.v4.new_notebook(), tmp_path / "empty.ipynb")
    notebook_runner.run_notebook(tmp_path / "empty.ipynb")
    assert seen == ["1"] and "TQDM_DISABLE" not in os.environ
