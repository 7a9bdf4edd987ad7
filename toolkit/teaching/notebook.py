"""What the notebooks share: quick mode, read in one place, and trained models cached on disk.

Quick mode (the environment variable ``TOOLKIT_QUICK=1``) shrinks sizes so that a
notebook runs top to bottom in about a minute (the test suite runs every notebook
so); it never changes which code runs. A notebook asks for its sizes with
:func:`sized`::

    from toolkit.teaching.notebook import run_config, sized, trained_models
    n_workspaces = sized(full=200, quick=20)
    models = trained_models("2ds", "strong")   # trains once, then loads in a second
    recipe = run_config("2ds", "strong").preset  # the preset, quick-sized in quick mode

The library's own quick sizes (epochs, workspaces, queries) are in
:data:`toolkit.experiments.config.QUICK`.

Trained models live in ``$TOOLKIT_CACHE`` (default ``~/.cache/sample-collision-toolkit``),
one checkpoint folder per scenario, preset, seed and size, written whole or not at all;
its name ends with a fingerprint of the preset's settings, so a changed preset trains anew
instead of loading a model made by the old one.
"""

from __future__ import annotations

import os
import shutil
import uuid
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


def is_quick() -> bool:
    """True when ``TOOLKIT_QUICK`` is set to ``1`` (or ``true``/``yes``): the notebooks' small sizes."""
    return os.environ.get(QUICK_ENV, "").strip().lower() in ("1", "true", "yes")


def sized(full: T, quick: T) -> T:
    """``quick`` in quick mode, otherwise ``full``: the one place a notebook's sizes change."""
    return quick if is_quick() else full


def cache_dir() -> Path:
    """Where trained models are kept: ``$TOOLKIT_CACHE`` or ``~/.cache/sample-collision-toolkit``."""
    return Path(os.environ.get(CACHE_ENV) or Path.home() / ".cache" / "sample-collision-toolkit")


def run_config(scenario: str, preset: str = "paper", *, seed: int = 0, progress: bool = True) -> RunConfig:
    """The run configuration a notebook works with: quick-sized in quick mode, trained on the CPU."""
    return RunConfig.create(scenario, preset, seed=seed, quick=is_quick(), progress=progress, device="cpu")


def trained_models(scenario: str, preset: str, *, seed: int = 0, progress: bool = True) -> TrainedModels:
    """The CAE and MLP of ``preset`` for ``scenario`` (quick-sized in quick mode), trained once and then loaded.

    The first call trains as ``toolkit train --scenario S --preset P`` does (the same
    :func:`~toolkit.experiments.pipeline.train_and_save`; the notebooks say how long it
    takes) and saves a checkpoint folder in :func:`cache_dir`; later calls, in any
    notebook, load it in about a second.
    """
    config = run_config(scenario, preset, seed=seed, progress=progress)
    recipe = presets.get(preset).fingerprint()  # the full recipe's: a quick model changes with it too
    name = f"{config.scenario.name}-{config.preset.name}-seed{seed}-{recipe}"
    folder = cache_dir() / f"{name}{'-quick' if config.quick else ''}"
    if folder.exists():
        return checkpoints.load_models(folder, config.scenario.name)
    tmp = folder.with_name(f"{folder.name}.{uuid.uuid4().hex}.tmp")  # another notebook may be training the same
    with threads.limited(threads.configured()):  # one thread, as the toolkit command: fast on a shared machine
        models, _, _ = pipeline.train_and_save(config, tmp)
    try:
        tmp.rename(folder)  # the folder appears whole or not at all
    except OSError:  # another process finished first: keep its folder
        shutil.rmtree(tmp, ignore_errors=True)
    return models
