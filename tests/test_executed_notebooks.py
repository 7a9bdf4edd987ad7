"""tools.executed_notebooks: a site build runs a notebook once, and again only when what it depends on changed."""

import nbformat
import pytest

from tools import executed_notebooks
from tools.notebook_runner import NotebookRun


@pytest.fixture
def counted_runs(monkeypatch, tmp_path):
    """A stand-in for the notebook runner: each run is recorded and prints the run's number."""
    runs = []

    def run_notebook(path, *, timeout):
        runs.append(path)
        nb = nbformat.read(path, as_version=4)
        nb.cells[0].outputs = [nbformat.v4.new_output("stream", name="stdout", text=f"run {len(runs)}\n")]
        return NotebookRun(nb, list(nb.cells[0].outputs), wall_s=12.5, kernel_cpu_s=10.0)

    toolkit = tmp_path / "toolkit"
    toolkit.mkdir()
    (toolkit / "module.py").write_text("X = 1\n")
    monkeypatch.setattr(executed_notebooks, "TOOLKIT", toolkit)
    monkeypatch.setattr(executed_notebooks, "run_notebook", run_notebook)
    return runs


def write_notebook(path, source):
    nbformat.write(nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(source)]), path)


def test_an_unchanged_notebook_is_reused_and_a_change_runs_it_again(counted_runs, tmp_path):
    notebook, kept = tmp_path / "chapter.ipynb", tmp_path / "executed"
    write_notebook(notebook, "print('hello')")
    use = lambda **kw: executed_notebooks.run_or_reuse(notebook, kept, "notebooks/chapter.ipynb", timeout=60, **kw)

    run, reused = use(quick=True)
    assert not reused and run.outputs[0]["text"] == "run 1\n"
    run, reused = use(quick=True)
    assert reused and len(counted_runs) == 1
    assert run.outputs[0]["text"] == "run 1\n" and (run.wall_s, run.kernel_cpu_s) == (12.5, 10.0)
    assert executed_notebooks.KEY not in run.notebook.metadata  # the page does not carry the fingerprint

    assert not use(quick=False)[1]  # full size is another run
    write_notebook(notebook, "print('hello, again')")
    assert not use(quick=True)[1]  # the source changed
    (executed_notebooks.TOOLKIT / "module.py").write_text("X = 2\n")
    assert not use(quick=True)[1]  # the toolkit changed
    (tmp_path / "data").mkdir()
    (tmp_path / "data" / "room.stl").write_text("solid room\n")
    run, reused = use(quick=True)
    assert not reused and run.outputs[0]["text"] == "run 5\n"  # a data file beside it appeared
    assert use(quick=True)[1] and len(counted_runs) == 5


def test_a_run_that_failed_is_not_kept(counted_runs, monkeypatch, tmp_path):
    notebook, kept = tmp_path / "chapter.ipynb", tmp_path / "executed"
    write_notebook(notebook, "1 / 0")
    monkeypatch.setattr(NotebookRun, "problem", lambda self: "ZeroDivisionError: division by zero")
    for _ in range(2):
        assert not executed_notebooks.run_or_reuse(notebook, kept, "chapter.ipynb", quick=True, timeout=60)[1]
    assert len(counted_runs) == 2 and not kept.exists()
