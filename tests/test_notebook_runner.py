"""tools.notebook_runner: a clean notebook runs and its figures are counted; an error inside a widget's
callback, which JupyterLab would show only in the widget, is reported."""

import nbformat
import pytest

from tools import notebook_runner

pytestmark = pytest.mark.slow  # starts kernels


def write(tmp_path, *sources):
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(s) for s in sources])
    path = tmp_path / "try.ipynb"
    nbformat.write(nb, path)
    return path


def test_a_clean_notebook_shows_its_figure_and_costs_kernel_time(tmp_path, monkeypatch):
    monkeypatch.setenv("MPLBACKEND", "module://matplotlib_inline.backend_inline")
    path = write(
        tmp_path,
        "import matplotlib.pyplot as plt\nplt.plot([0, 1])\nplt.show()",
        "sum(i * i for i in range(3_000_000))",
    )
    run = notebook_runner.run_notebook(path, timeout=120)
    assert run.problem() is None and run.figures == 1
    assert run.kernel_cpu_s > 0.1 and run.wall_s >= run.kernel_cpu_s / 4


def test_an_error_inside_interact_is_reported(tmp_path):
    path = write(
        tmp_path,
        "from ipywidgets import interact\n@interact(n=(0, 3))\ndef show(n=1):\n    raise ValueError(f'bad n={n}')",
    )
    run = notebook_runner.run_notebook(path, timeout=120)
    assert run.problem() == "ValueError: bad n=1"


def test_the_command_fails_on_a_raising_cell_and_names_it(tmp_path, capsys):
    path = write(tmp_path, "1 / 0")
    assert notebook_runner.main([str(path)]) == 1
    assert "FAILED" in capsys.readouterr().out


def test_notebooks_run_side_by_side_report_in_order_each_with_its_own_kernels_cpu(tmp_path, capsys):
    busy, idle = tmp_path / "busy", tmp_path / "idle"
    busy.mkdir(), idle.mkdir()
    paths = [write(busy, "sum(i * i for i in range(60_000_000))"), write(idle, "1 + 1")]  # the idle one ends first
    assert notebook_runner.main(["--jobs", "2", *map(str, paths)]) == 0
    lines = [line for line in capsys.readouterr().out.splitlines() if "kernel CPU" in line]
    assert [line.split(": ")[0] for line in lines] == list(map(str, paths))
    cpu = [float(line.split("kernel CPU ")[1].split(" s")[0]) for line in lines]
    assert cpu[0] >= 3 and cpu[1] < cpu[0] / 2, lines  # the busy kernel's CPU is not counted to the idle one


def test_the_command_names_a_bad_number_of_jobs(tmp_path, capsys):
    with pytest.raises(SystemExit):
        notebook_runner.main(["--jobs", "0", str(write(tmp_path, "1"))])
    assert "--jobs must be at least 1, not 0" in capsys.readouterr().err
