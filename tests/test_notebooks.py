"""Every notebook runs top to bottom in quick mode (``TOOLKIT_QUICK=1``), and is committed without outputs.

Executed with nbclient in a real kernel, as a student's JupyterLab would; trained
models go to a cache folder of this test session, not the user's.
"""

import json
from pathlib import Path

import nbformat
import pytest
from nbclient import NotebookClient

NOTEBOOKS = sorted((Path(__file__).resolve().parents[1] / "notebooks").glob("[0-9][0-9]_*.ipynb"))  # 01_... to 05_...


def test_the_five_notebooks_exist():
    assert [p.name[:2] for p in NOTEBOOKS] == ["01", "02", "03", "04", "05"]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_committed_without_outputs(path):
    nb = json.loads(path.read_text())
    for i, cell in enumerate(nb["cells"]):
        if cell["cell_type"] == "code":
            assert cell.get("outputs") == [], f"{path.name} cell {i} has outputs: clear them before committing"
            assert cell.get("execution_count") is None, f"{path.name} cell {i} has an execution count"
    assert "widgets" not in nb["metadata"], f"{path.name} carries saved widget state"


@pytest.mark.slow
@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_runs_in_quick_mode(path, monkeypatch, notebook_cache):
    monkeypatch.setenv("TOOLKIT_QUICK", "1")
    monkeypatch.setenv("TOOLKIT_CACHE", str(notebook_cache))
    monkeypatch.setenv("MPLBACKEND", "module://matplotlib_inline.backend_inline")
    nb = nbformat.read(path, as_version=4)
    NotebookClient(nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(path.parent)}}).execute()
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "error"]
    errors += [o for o in _widget_outputs(nb) if o.get("output_type") == "error"]  # raised inside interact()
    assert not errors, f"{path.name}: {errors[0]['ename']}: {errors[0]['evalue']}" if errors else ""
    streams = "".join(o.get("text", "") for c in nb.cells if c.cell_type == "code" for o in c.outputs
                      if o.output_type == "stream" and o.name == "stderr")
    assert "Traceback" not in streams, f"{path.name} printed a traceback:\n{streams[-2000:]}"


def _widget_outputs(nb) -> list[dict]:
    """The outputs that widgets (``interact``'s Output widgets) captured, from the executed notebook's widget state."""
    state = nb.metadata.get("widgets", {}).get("application/vnd.jupyter.widget-state+json", {}).get("state", {})
    return [o for model in state.values() for o in model.get("state", {}).get("outputs", [])]
