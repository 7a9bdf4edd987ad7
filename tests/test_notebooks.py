"""Every notebook runs top to bottom in quick mode (``TOOLKIT_QUICK=1``); every notebook of the repository
(chapters, tutorials, assignment masters) is committed without outputs.

Executed by :mod:`tools.notebook_runner` in a real kernel, as a student's JupyterLab
would; trained models go to a cache folder of this test session, not the user's.
"""

import json
import re
from pathlib import Path

import pytest

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
    """In quick mode a student learns first what shrank: the first code cell names its sizes and calls ``banner()``."""
    code = next(
        "".join(cell["source"]) for cell in json.loads(path.read_text())["cells"] if cell["cell_type"] == "code"
    )
    assert re.search(r"^banner\(", code, re.MULTILINE), f"{path.name}: its first code cell does not call banner()"
    sizes = re.findall(r"\bsized\((.*)\)", code)
    assert all("what=" in args for args in sizes), f"{path.name}: name every size for the banner (sized(..., what=))"


# Running each one in quick mode (no error, its figures shown) is tests/test_site.py's build: one execution serves both.


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
