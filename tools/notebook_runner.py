"""Run a notebook top to bottom in a real kernel, as JupyterLab's "Run All" would, and report what it showed.

The test suite runs every notebook and tutorial this way (in quick mode); the same
command measures the running times the notebooks state in their first cell::

    python -m tools.notebook_runner notebooks/02_cae_reconstruction.ipynb            # full size
    python -m tools.notebook_runner --quick notebooks/*.ipynb tutorials/*.ipynb     # TOOLKIT_QUICK=1

It prints the wall-clock time and the kernel's CPU time: on a machine shared with
other work the first grows with the load, the second hardly does.
"""

from __future__ import annotations

import argparse
import base64
import os
import resource
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from queue import Empty

import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError

from toolkit.teaching.notebook import QUICK_ENV

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
    args = parser.parse_args(argv)
    missing = [str(p) for p in args.notebooks if not p.is_file()]
    if missing:
        parser.error(f"no such notebook: {', '.join(missing)}")
    if args.quick:
        os.environ[QUICK_ENV] = "1"
    failed = 0
    for path in args.notebooks:
        try:
            run = run_notebook(path)
        except CellExecutionError as error:  # a cell raised: nbclient stops there
            failed += 1
            print(f"{path}: FAILED: {str(error).strip().splitlines()[-1]}", flush=True)
            continue
        problem = run.problem()
        failed += problem is not None
        print(
            f"{path}: wall {run.wall_s:.0f} s, kernel CPU {run.kernel_cpu_s:.0f} s, {run.figures} figures"
            + (f", FAILED: {problem}" if problem else ""),
            flush=True,
        )
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
