"""Run a notebook top to bottom in a real kernel, as JupyterLab's "Run All" would, and report what it showed.

The test suite runs every notebook and tutorial this way (in quick mode); the same
command measures the running times the notebooks state in their first cell::

    python -m tools.notebook_runner notebooks/02_cae_reconstruction.ipynb            # full size
    python -m tools.notebook_runner --quick notebooks/*.ipynb tutorials/*.ipynb     # TOOLKIT_QUICK=1
    python -m tools.notebook_runner --quick --jobs 2 notebooks/*.ipynb               # two at a time

It prints the wall-clock time and the kernel's CPU time: on a machine shared with
other work the first grows with the load, the second hardly does. A quick-mode kernel keeps about one core
busy, so ``--jobs`` set to the number of cores runs the set in about that fraction of the time; time a
notebook's full size with one job, on an idle machine, as its first cell quotes.
"""

from __future__ import annotations

import argparse
import base64
import multiprocessing
import os
import resource
import sys
import time
from collections.abc import Callable, Iterator
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from queue import Empty
from typing import TypeVar

import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError

from toolkit.teaching.notebook import QUICK_ENV

T = TypeVar("T")
PNG_IN_HTML = 'src="data:image/png;base64,'  # a picture inside an HTML output
NO_PROGRESS_BARS = "TQDM_DISABLE"  # tqdm's switch, read from the environment: off in a headless run


@dataclass
class NotebookRun:
    """An executed notebook: every output its cells and widgets showed, and what the run cost."""

    notebook: nbformat.NotebookNode  # with its outputs
    outputs: list[dict]  # the code cells' outputs, then what widgets (interact's Output) displayed
    wall_s: float
    kernel_cpu_s: float  # CPU time of the kernel process (user + system)

    @property
    def errors(self) -> list[dict]:
        return [o for o in self.outputs if o.get("output_type") == "error"]

    @property
    def stderr(self) -> str:
        return "".join(
            o.get("text", "") for o in self.outputs if o.get("output_type") == "stream" and o.get("name") == "stderr"
        )

    @property
    def figures(self) -> int:
        """PNG figures shown: outputs, and pictures inside HTML outputs (a still folded under a 3D view)."""
        return sum(
            ("image/png" in o.get("data", {})) + str(o.get("data", {}).get("text/html", "")).count(PNG_IN_HTML)
            for o in self.outputs
        )

    def problem(self) -> str | None:
        """The first error or printed traceback, in one message; None when the notebook ran cleanly."""
        if self.errors:
            return f"{self.errors[0].get('ename')}: {self.errors[0].get('evalue')}"
        if "Traceback" in self.stderr:
            return f"printed a traceback:\n{self.stderr[-2000:]}"
        return None


def run_notebook(path: str | Path, *, timeout: float = 900) -> NotebookRun:
    """Execute ``path`` from its own folder (relative paths work as in JupyterLab); ``timeout`` is per cell."""
    path = Path(path)
    nb = nbformat.read(path, as_version=4)
    client = NotebookClient(
        nb, timeout=timeout, kernel_name="python3", resources={"metadata": {"path": str(path.parent)}}
    )
    client.on_notebook_start = lambda notebook: _poll_shell_in_slices(client.kc)
    began, cpu_before = time.perf_counter(), _children_cpu()
    before = os.environ.get(NO_PROGRESS_BARS)
    os.environ[NO_PROGRESS_BARS] = "1"  # the kernel inherits it: no one watches this run, so no bar (tqdm >= 4.66)
    try:
        client.execute()  # shuts the kernel down and waits for it, so its CPU time is counted below
    finally:
        if before is None:
            os.environ.pop(NO_PROGRESS_BARS, None)
        else:
            os.environ[NO_PROGRESS_BARS] = before
    wall, cpu = time.perf_counter() - began, _children_cpu() - cpu_before
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs] + widget_outputs(nb)
    return NotebookRun(nb, outputs, wall, cpu)


def each_in_a_worker(call: Callable[[Path], T], paths: list[Path], *, jobs: int) -> Iterator[tuple[Path, T]]:
    """``call(path)`` for every path, ``jobs`` at a time, each in a worker process: yields ``(path, result)`` in
    the order of ``paths`` (an exception of ``call`` is raised there, and what has not started is dropped).

    A worker of its own counts each kernel's CPU time apart (:func:`run_notebook` reads the CPU time of the
    process's finished children); ``call`` must be picklable, a module's function or a ``functools.partial``
    of one. Workers are spawned, so they see the environment as it is when this is called."""
    pool = ProcessPoolExecutor(jobs, mp_context=multiprocessing.get_context("spawn"))
    try:
        futures = [pool.submit(call, path) for path in paths]
        for path, future in zip(paths, futures, strict=True):
            yield path, future.result()
    finally:
        pool.shutdown(wait=True, cancel_futures=True)


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def widget_outputs(nb) -> list[dict]:
    """What the widgets' default values displayed (an ``interact`` shows its output, and a failing callback's
    traceback, in an Output widget, not in the cell's outputs; an ``Image`` widget holds its picture)."""
    state = nb.metadata.get("widgets", {}).get("application/vnd.jupyter.widget-state+json", {}).get("state", {})
    shown = []
    for model in state.values():
        if model.get("model_name") == "OutputModel":
            shown += model.get("state", {}).get("outputs", [])
        elif model.get("model_name") == "ImageModel":
            shown += image_widget_output(model)
    return shown


def image_widget_output(model: dict) -> list[nbformat.NotebookNode]:
    """A saved ``Image`` widget's PNG as a ``display_data`` output (its value is saved as a base64 buffer), its
    ``tooltip`` as the picture's alt text; nothing for an empty or non-PNG one."""
    widget = model.get("state", {})
    value = next((b["data"] for b in model.get("buffers", []) if b.get("path") == ["value"]), widget.get("value"))
    if not value or widget.get("format", "png") != "png":
        return []
    data = value if isinstance(value, str) else base64.b64encode(bytes(value)).decode()
    alt = widget.get("tooltip") or "the picture this control shows at its starting value"
    return [nbformat.v4.new_output("display_data", data={"image/png": data}, metadata={"image/png": {"alt": alt}})]


def _poll_shell_in_slices(kc, every: float = 1.0) -> None:
    """Make the kernel client wait for shell replies in one-second polls instead of one long one.

    After a cell that displays widgets, one long poll of the shell channel sometimes misses
    the reply that has arrived, and nbclient waits out the whole cell timeout although the
    kernel is idle (jupyter/nbclient#312; about one run in two of an ``interact`` cell on a
    loaded machine). The next short poll finds the reply.
    """
    wait = kc.shell_channel.get_msg

    async def get_msg(timeout=None):
        deadline = None if timeout is None else time.monotonic() + timeout
        while True:
            step = every if deadline is None else min(every, max(0.0, deadline - time.monotonic()))
            try:
                return await wait(timeout=step)
            except Empty:
                if deadline is not None and time.monotonic() >= deadline:
                    raise

    kc.shell_channel.get_msg = get_msg


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m tools.notebook_runner",
        description="Run notebooks top to bottom and print each one's running time.",
    )
    parser.add_argument("notebooks", nargs="+", type=Path, help="notebook files (.ipynb)")
    parser.add_argument("--quick", action="store_true", help=f"set {QUICK_ENV}=1: the notebooks' small sizes")
    parser.add_argument("--jobs", type=int, default=1, help="notebooks run at a time (default 1)")
    args = parser.parse_args(argv)
    missing = [str(p) for p in args.notebooks if not p.is_file()]
    if missing:
        parser.error(f"no such notebook: {', '.join(missing)}")
    if args.jobs < 1:
        parser.error(f"--jobs must be at least 1, not {args.jobs}")
    if args.quick:
        os.environ[QUICK_ENV] = "1"
    lines = each_in_a_worker(_report, args.notebooks, jobs=args.jobs)
    failed = 0
    for _, line in lines:
        failed += "FAILED" in line
        print(line, flush=True)
    return 1 if failed else 0


def _report(path: Path) -> str:
    """The runner's line for one notebook: its times and figures, or FAILED and why."""
    try:
        run = run_notebook(path)
    except CellExecutionError as error:  # a cell raised: nbclient stops there
        return f"{path}: FAILED: {str(error).strip().splitlines()[-1]}"
    problem = run.problem()
    return f"{path}: wall {run.wall_s:.0f} s, kernel CPU {run.kernel_cpu_s:.0f} s, {run.figures} figures" + (
        f", FAILED: {problem}" if problem else ""
    )


if __name__ == "__main__":
    sys.exit(main())
