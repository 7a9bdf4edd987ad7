"""The offline phase (§III-A, §IV) from one run configuration: data, training, scores, a checkpoint folder.

1. :func:`make_splits` — labelled configurations in the training, seen-test and unseen workspaces (§IV-A);
2. :func:`train` — the CAE on the occupancy grids (Eq. 1), then the MLP on ``[z, q]`` (§III-A);
3. ``training.evaluate`` — Tables 1 and 2's measures on the test splits (§V);
4. ``checkpoints.save_checkpoint`` — the models and their scores, written whole or not at all.

:func:`train_and_save` runs the four in order. ``toolkit train`` and the notebooks'
model cache (:func:`toolkit.teaching.notebook.trained_models`) call it;
``toolkit reproduce`` calls the same steps one at a time, caching each
(:mod:`toolkit.experiments.reproduce`).

>>> config = RunConfig.create("2ds", "strong", quick=True)  # doctest: +SKIP
>>> models, scores, folder = train_and_save(config, "runs/2ds-try")  # doctest: +SKIP
"""

from __future__ import annotations

from pathlib import Path

from toolkit.experiments.config import RunConfig
from toolkit.learning import checkpoints, data, training
from toolkit.learning.data import CollisionDataset
from toolkit.learning.training import TrainedModels


def make_splits(config: RunConfig) -> dict[str, CollisionDataset]:
    """The ``train``, ``seen_test`` and ``unseen_test`` splits of the run (its counts and samples per workspace)."""
    return data.make_splits(
        config.scenario,
        config.seed,
        samples_per_workspace=config.samples_per_workspace(),
        progress=config.progress,
        **config.workspace_counts(),
    )


def train(config: RunConfig, splits: dict[str, CollisionDataset], *, cae: bool | None = None) -> TrainedModels:
    """The run's preset trained on ``splits["train"]``; ``cae``: as :func:`toolkit.learning.training.train_models`."""
    return training.train_models(
        config.scenario, config.preset, splits, config.seed, progress=config.progress, device=config.device, cae=cae
    )


def train_and_save(
    config: RunConfig, folder: str | Path, *, cae: bool | None = None, overwrite: bool = False
) -> tuple[TrainedModels, dict, Path]:
    """Make the data, train, evaluate and write a checkpoint folder: the models, their scores and the folder."""
    splits = make_splits(config)
    models = train(config, splits, cae=cae)
    scores = training.evaluate(models, splits)
    return models, scores, checkpoints.save_checkpoint(models, folder, evaluation=scores, overwrite=overwrite)
