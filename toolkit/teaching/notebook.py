"""What the notebooks share: quick mode, read in one place, and trained models cached on disk.

Quick mode (the environment variable ``TOOLKIT_QUICK=1``) shrinks sizes so that a
notebook runs top to bottom in about a minute (the test suite runs every notebook
so); it never changes which code runs. A notebook asks for its sizes with
:func:`sized`, and its first cell ends with :func:`banner`, which says in quick mode
what shrank::

    from toolkit.teaching.notebook import banner, run_config, sized, trained_models
    n_workspaces = sized(full=200, quick=20, what="workspaces per family")
    banner(models=[("2ds", "strong")])           # quick mode: these sizes, and how the model trains
    models = trained_models("2ds", "strong")     # trains once, then loads in a second
    scores = trained_scores("2ds", "strong")     # its Table 1 and 2 measures, as toolkit train scores them
    recipe = run_config("2ds", "strong").preset  # the preset, quick-sized in quick mode

The library's own quick sizes (epochs, workspaces, queries) are in
:data:`toolkit.experiments.config.QUICK`.

Trained models live in ``$TOOLKIT_CACHE`` (default ``~/.cache/sample-collision-toolkit``),
one checkpoint folder per scenario, preset, seed and size, written whole or not at all;
its name ends with a fingerprint of the preset's settings, so a changed preset trains anew
instead of loading a model made by the old one.
"""

from __future__ import annotations

import dataclasses
import io
import json
import os
import shutil
import time
import uuid
from collections.abc import Iterable
from contextlib import suppress
from pathlib import Path
from typing import TypeVar

from toolkit.experiments import pipeline
from toolkit.experiments.config import RunConfig
from toolkit.learning import checkpoints, presets
from toolkit.learning.training import TrainedModels
from toolkit.util import threads

QUICK_ENV = "TOOLKIT_QUICK"
CACHE_ENV = "TOOLKIT_CACHE"
T = TypeVar("T")
NAMED_SIZES: dict[str, tuple[object, object]] = {}  # what -> (full, quick): the sizes banner() lists


def is_quick() -> bool:
    """True when ``TOOLKIT_QUICK`` is set to ``1`` (or ``true``/``yes``): the notebooks' small sizes."""
    return os.environ.get(QUICK_ENV, "").strip().lower() in ("1", "true", "yes")


def sized(full: T, quick: T, what: str | None = None) -> T:
    """``quick`` in quick mode, otherwise ``full``: the one place a notebook's sizes change.

    ``what`` names the size for :func:`banner` (e.g. ``"training grids"``), which lists every named one."""
    if what is not None:
        NAMED_SIZES[what] = (full, quick)
    return quick if is_quick() else full


def banner(*, models: Iterable[tuple[str, str]] = ()) -> None:
    """Print the size this notebook runs at: at full size one line; in quick mode every size :func:`sized` named
    and how each ``(scenario, preset)`` model of ``models`` trains, quick against full."""
    if not is_quick():
        print(f"Full size: the counts the text describes ({QUICK_ENV}=1 before starting Jupyter runs quick mode).")
        return
    lines = [
        f"QUICK MODE ({QUICK_ENV}=1): smaller sizes, the same code. Scores and figures are rougher than at full"
        " size; the text says where they differ.",
        *(f"  {what}: {_count(quick)} (full size: {_count(full)})" for what, (full, quick) in NAMED_SIZES.items()),
        *(f"  {scenario}/{preset} model: {describe_training(scenario, preset)}" for scenario, preset in models),
    ]
    print("\n".join(lines))


def describe_training(scenario: str, preset: str) -> str:
    """How the ``preset`` model of ``scenario`` trains in this mode, each size beside its full one (:func:`banner`)."""
    sizes, full = (_training_sizes(RunConfig.create(scenario, preset, quick=quick)) for quick in (is_quick(), False))
    text = ", ".join(
        f"{what} {_count(n)}" + (f" (full size {_count(full[what])})" if n != full[what] else "")
        for what, n in sizes.items()
    )
    return text if "CAE epochs" in sizes else text + "; its CAE is not trained (this MLP does not read z)"


def _training_sizes(config: RunConfig) -> dict[str, int]:
    recipe = config.preset
    n_seen = config.workspace_counts().get("n_seen", recipe.n_seen or config.scenario.n_seen)
    sizes = {
        "training workspaces": n_seen,
        "labelled configurations each": config.samples_per_workspace(),
        "MLP epochs": recipe.mlp_epochs,
    }
    if recipe.latent_input:  # the CAE trains only for an MLP that reads its z (training.train_models)
        sizes |= {
            "CAE epochs": recipe.cae_epochs,
            "CAE grids": recipe.cae_workspaces or n_seen,
            "CAE steps at most": recipe.cae_max_steps,
        }
    return sizes


def _count(size: object) -> str:
    """A size as the banner prints it: whole numbers with thousands separators, ranges by their length."""
    if isinstance(size, range):
        return f"{len(size)} ({size.start}..{size.stop - 1})"
    if dataclasses.is_dataclass(size) and not isinstance(size, type):  # e.g. a crossover's sizes: its fields, briefly
        return "; ".join(f"{field.name} {_count(getattr(size, field.name))}" for field in dataclasses.fields(size))
    if isinstance(size, tuple):
        return "/".join(_count(v) for v in size)
    return f"{size:,}" if isinstance(size, int) else str(size)


def cache_dir() -> Path:
    """Where trained models are kept: ``$TOOLKIT_CACHE`` or ``~/.cache/sample-collision-toolkit``."""
    return Path(os.environ.get(CACHE_ENV) or Path.home() / ".cache" / "sample-collision-toolkit")


def run_config(scenario: str, preset: str = "paper", *, seed: int = 0, progress: bool = True) -> RunConfig:
    """The run configuration a notebook works with: quick-sized in quick mode, trained on the CPU."""
    return RunConfig.create(scenario, preset, seed=seed, quick=is_quick(), progress=progress, device="cpu")


def trained_models(scenario: str, preset: str, *, seed: int = 0, progress: bool = True) -> TrainedModels:
    """The CAE and MLP of ``preset`` for ``scenario`` (quick-sized in quick mode), trained once and then loaded.

    The first call trains as ``toolkit train --scenario S --preset P`` does (the same
    :func:`~toolkit.experiments.pipeline.train_and_save`, and prints how long it took) and
    saves a checkpoint folder in :func:`cache_dir`; later calls, in any notebook, load it
    in about a second.
    """
    config = run_config(scenario, preset, seed=seed, progress=progress)
    folder = _cached_folder(config)
    if folder.exists():
        return checkpoints.load_models(folder, config.scenario)
    tmp = folder.with_name(f"{folder.name}.{uuid.uuid4().hex}.tmp")  # another notebook may be training the same
    began = time.perf_counter()
    try:
        with threads.limited(threads.configured()):  # one thread, as the toolkit command: fast on a shared machine
            models, _, _ = pipeline.train_and_save(config, tmp)
        with suppress(OSError):  # another process finished first: keep its folder
            tmp.rename(folder)  # the folder appears whole or not at all
    finally:
        shutil.rmtree(tmp, ignore_errors=True)  # gone once renamed; also after an error or Ctrl-C
    if progress:
        print(f"trained the {scenario}/{preset} model in {time.perf_counter() - began:.0f} s; later runs load it")
    return models


def trained_scores(scenario: str, preset: str, *, seed: int = 0, progress: bool = True) -> dict:
    """The scores of :func:`trained_models`' model, as ``toolkit train`` evaluates it (training it if need be).

    ``{"cae": {"seen_acc", "unseen_acc", "seen_all_free", "unseen_all_free"}, "mlp": {"seen", "unseen",
    "unseen_uniform"}}`` (:func:`toolkit.learning.training.evaluate`): Table 1 and 2's measures on this size's
    test workspaces, the numbers ``toolkit reproduce`` puts in its tables for the same preset, seed and size.
    """
    trained_models(scenario, preset, seed=seed, progress=progress)
    folder = _cached_folder(run_config(scenario, preset, seed=seed, progress=progress))
    return json.loads((folder / "meta.json").read_text())["evaluation"]


def _cached_folder(config: RunConfig) -> Path:
    recipe = presets.get(config.preset.name).fingerprint()  # the full recipe's: a quick model changes with it too
    name = f"{config.scenario.name}-{config.preset.name}-seed{config.seed}-{recipe}"
    return cache_dir() / f"{name}{'-quick' if config.quick else ''}"


def still(fig, summary: str):
    """``fig`` as a still picture under ``summary`` (HTML ``<details>``, open), its alt text and any longer description
    from the figure (:func:`toolkit.plots.alt.figure_html`): what a browser without WebGL shows in place of a 3D view
    beside it (the view stays blank there, the still does not)."""
    import base64
    import html

    from IPython.display import HTML

    from toolkit.plots.alt import figure_html

    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=80, bbox_inches="tight")
    png = base64.b64encode(buffer.getvalue()).decode()
    shown = figure_html(fig, png, style="max-width:100%")
    return HTML(f"<details open><summary>{html.escape(summary)}</summary>{shown}</details>")
