"""Executed notebooks kept between builds of the site: a notebook whose inputs have not changed is not run again.

Executing the chapters is most of a site build (minutes each at full size). :func:`run_or_reuse` runs a notebook
with :func:`~tools.notebook_runner.run_notebook` and keeps the executed copy in a folder; the next build reuses
it when its :func:`fingerprint` is the same. The fingerprint covers what a run's outputs depend on: the
notebook's source, the data files beside it (``data/``), the toolkit's sources (``toolkit/``), its version and
the versions of Python and of the libraries that compute or draw, and quick mode. Anything else (an edited
figure style in another package, a new CPU) is not seen: delete the folder (``rm -r build/site/executed``) to
run everything again.
"""

from __future__ import annotations

import hashlib
import importlib.metadata
import json
import platform
from pathlib import Path

import nbformat

from tools.notebook_runner import NotebookRun, run_notebook, widget_outputs

ROOT = Path(__file__).resolve().parents[1]  # the repository (this file is tools/executed_notebooks.py)
TOOLKIT = ROOT / "toolkit"
LIBRARIES = ("sample-collision-toolkit", "torch", "numpy", "scipy", "matplotlib", "viser", "trimesh", "python-fcl")
KEY = "toolkit_site"  # the executed copy's metadata entry: its fingerprint and the run's times


def fingerprint(notebook: Path, *, quick: bool) -> str:
    """A hash of everything a run of ``notebook`` depends on that this module knows of (the module's docstring)."""
    digest = hashlib.sha256()
    data = sorted(p for p in (notebook.parent / "data").rglob("*") if p.is_file())
    for path in [notebook, *data, *sorted(TOOLKIT.rglob("*.py"))]:
        digest.update(f"{path.name}\0{path.stat().st_size}\0".encode())
        digest.update(path.read_bytes())
    versions = {name: _version(name) for name in LIBRARIES}
    digest.update(json.dumps({"quick": quick, "python": platform.python_version(), **versions}).encode())
    return digest.hexdigest()


def _version(distribution: str) -> str:
    try:
        return importlib.metadata.version(distribution)
    except importlib.metadata.PackageNotFoundError:
        return "absent"


def run_or_reuse(notebook: Path, folder: Path, name: str, *, quick: bool, timeout: float) -> tuple[NotebookRun, bool]:
    """The run of ``notebook``: the copy kept as ``folder/name`` when its fingerprint matches (and ``True``),
    else a new run (``timeout`` per cell), kept there when it ran cleanly (and ``False``)."""
    kept, key = folder / name, fingerprint(notebook, quick=quick)
    if kept.is_file():
        nb = nbformat.read(kept, as_version=4)
        saved = nb.metadata.pop(KEY, {})
        if saved.get("fingerprint") == key:
            outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs] + widget_outputs(nb)
            return NotebookRun(nb, outputs, saved["wall_s"], saved["kernel_cpu_s"]), True
    run = run_notebook(notebook, timeout=timeout)
    if run.problem() is None:
        kept.parent.mkdir(parents=True, exist_ok=True)
        copy = nbformat.from_dict(run.notebook)  # the published page does not carry the fingerprint
        copy.metadata[KEY] = {"fingerprint": key, "wall_s": run.wall_s, "kernel_cpu_s": run.kernel_cpu_s}
        nbformat.write(copy, kept)
    return run, False
