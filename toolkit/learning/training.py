"""Training and evaluating the CAE and the collision MLP (paper §III-A, §IV-B3, §V).

The CAE is fitted first on the training workspaces' occupancy grids (Eq. 1), then
frozen; the MLP is fitted on ``[z, q]`` (or the ``strong`` preset's richer input)
with cross-entropy. One call does both, another scores them as Tables 1 and 2 do::

    splits = data.make_splits(scenario, seed)
    models = training.train_models(scenario, presets.get("paper"), splits, seed)
    training.evaluate(models, splits)  # the keys of results.json's "cae" and "mlp"

(:mod:`toolkit.experiments.pipeline` runs these steps from one run configuration.)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import torch
from torch import nn
from tqdm.auto import tqdm

from toolkit.learning import data, metrics
from toolkit.learning.data import CollisionDataset
from toolkit.learning.models import CAE, CollisionPredictor
from toolkit.learning.presets import OPTIMIZERS, Preset
from toolkit.scenarios import Scenario
from toolkit.util import registry

CALIBRATION_THRESHOLDS = np.linspace(0.05, 0.95, 91)


@dataclass
class TrainedModels:
    """A trained predictor with what made it: scenario, preset, seed and the loss per epoch."""

    scenario: Scenario
    preset: Preset
    predictor: CollisionPredictor
    seed: int = 0
    history: dict[str, list[float]] = field(default_factory=dict)

    @property
    def quick(self) -> bool:
        return self.preset.quick

    @property
    def threshold(self) -> float:
        """Decision threshold on P(valid): 0.5, or calibrated on held-out workspaces."""
        return float(self.predictor.threshold)


def default_device() -> torch.device:
    """CUDA when present, else the CPU."""
    return torch.device("cuda" if torch.cuda.is_available() else "cpu")


def train_models(
    scenario: Scenario,
    preset: Preset,
    splits: dict[str, CollisionDataset],
    seed: int = 0,
    *,
    progress: bool = True,
    device: torch.device | str | None = None,
    cae: bool | None = None,
    trained_cae: CAE | None = None,
) -> TrainedModels:
    """Fit the CAE, then the MLP on ``splits["train"]``'s labelled samples; models end on the CPU.

    The CAE trains on the training split's grids, or on ``preset.cae_workspaces`` generated
    ones. ``cae``: train it (True) or leave it untrained (False); by default only when
    the MLP sees its ``z`` (``preset.latent_input``), so that the ``strong`` MLP does not
    wait for a CAE it never asks (``history`` then has no ``"cae"``: Table 1 needs ``cae=True``).
    ``trained_cae``: a CAE already trained with these settings, copied instead of training one
    (``history["cae"]`` is then empty).
    """
    train = splits["train"]
    if train.scenario != scenario.name:
        raise ValueError(f"the training split holds {train.scenario!r} data, not {scenario.name!r}")
    device = torch.device(device) if device is not None else default_device()
    torch.manual_seed(seed)
    predictor = preset.build_predictor(scenario).to(device)
    shuffle = torch.Generator().manual_seed(seed)
    history: dict[str, list[float]] = {}
    if trained_cae is not None:
        predictor.cae.load_state_dict(trained_cae.state_dict())
        history["cae"] = []
    elif cae if cae is not None else preset.latent_input:
        grids = (
            torch.as_tensor(data.occupancy_grids(scenario, "cae_grids", preset.cae_workspaces, seed, progress=progress))
            if preset.cae_workspaces
            else torch.as_tensor(train.occupancy)
        ).to(device)
        history["cae"] = train_cae(
            predictor,
            grids,
            preset,
            shuffle,
            progress=progress,
            max_steps=scenario.cae_max_steps,
            max_batch=scenario.cae_max_batch,
            max_lr=scenario.cae_max_lr,
        )
    n_holdout = int(round(preset.holdout * len(train.workspaces))) if len(train.workspaces) > 1 else 0
    fit, holdout = split_workspaces(train, len(train.workspaces) - n_holdout)
    history["mlp"] = train_mlp(predictor, fit, preset, shuffle, progress=progress)
    if n_holdout:
        predictor.threshold.fill_(calibrate_threshold(predictor, holdout))
    return TrainedModels(scenario, preset, predictor.cpu().eval(), seed, history)


def train_cae(
    predictor: CollisionPredictor,
    grids: torch.Tensor,
    preset: Preset,
    shuffle: torch.Generator,
    *,
    progress: bool = True,
    max_steps: int | None = None,
    max_batch: int | None = None,
    max_lr: float | None = None,
) -> list[float]:
    """Fit the CAE to grids ``(W, *grid)`` with Eq. (1) (``preset.cae_loss``), at most ``max_steps`` steps of at most
    ``max_batch`` grids at a learning rate of at most ``max_lr`` if given; the mean loss of each epoch. Integer grids
    (int8) become float a batch at a time."""
    cae = predictor.cae.train()
    batch = min(preset.cae_batch, max_batch or preset.cae_batch)
    steps_per_epoch = math.ceil(len(grids) / batch)
    max_steps = min(preset.cae_max_steps, max_steps or preset.cae_max_steps)
    epochs = max(1, min(preset.cae_epochs, max_steps // steps_per_epoch))
    batches = _batches(len(grids), batch, epochs, shuffle)
    # no weight decay or schedule of the optimizer here (those settings are the MLP's): Eq. (1)'s penalty is the CAE's
    return fit(
        cae.parameters(),
        batches,
        lambda idx: cae.loss(grids[idx].float(), preset.cae_lambda, preset.cae_loss),
        optimizer_name=preset.cae_optimizer,
        lr=min(preset.cae_lr, max_lr or preset.cae_lr),
        progress=progress,
        desc=f"CAE ({preset.name})",
    )


def train_mlp(
    predictor: CollisionPredictor,
    dataset: CollisionDataset,
    preset: Preset,
    shuffle: torch.Generator,
    *,
    progress: bool = True,
) -> list[float]:
    """Fit the MLP with cross-entropy on a dataset's samples, the CAE frozen; the mean loss of each epoch."""
    device = predictor.threshold.device
    X, y = _inputs(predictor, dataset), torch.as_tensor(dataset.valid.reshape(-1), device=device).long()
    if preset.standardize:
        mean, std = X.mean(dim=0), X.std(dim=0).clamp(min=1e-6)  # (F,) each
    else:
        mean, std = X.new_zeros(()), X.new_ones(())  # leave X as it is
    X = (X - mean) / std
    mlp = predictor.mlp.train()
    batches = _batches(len(X), preset.mlp_batch, preset.mlp_epochs, shuffle)
    losses = fit(
        mlp.parameters(),
        batches,
        lambda idx: nn.functional.cross_entropy(mlp(X[idx]), y[idx]),
        optimizer_name=preset.optimizer,
        lr=preset.lr,
        progress=progress,
        desc=f"MLP ({preset.name})",
        weight_decay=preset.weight_decay,
        cosine_schedule=preset.cosine_schedule,
    )
    mlp.eval()
    if preset.standardize:
        mlp.fold_standardization(mean, std)
    return losses


def calibrate_threshold(predictor: CollisionPredictor, dataset: CollisionDataset) -> float:
    """The threshold on P(valid) with the best accuracy on a held-out dataset (ties: the one nearest 0.5)."""
    p, valid = probabilities(predictor, dataset).reshape(-1), dataset.valid.reshape(-1)
    acc = np.array([np.mean((p >= t) == valid) for t in CALIBRATION_THRESHOLDS])
    best = np.flatnonzero(acc == acc.max())
    return float(CALIBRATION_THRESHOLDS[best[np.argmin(np.abs(CALIBRATION_THRESHOLDS[best] - 0.5))]])


@torch.no_grad()
def probabilities(predictor: CollisionPredictor, dataset: CollisionDataset) -> np.ndarray:
    """P(valid) of every labelled configuration, ``(W, n)``."""
    predictor.eval()
    logits = predictor.mlp(_inputs(predictor, dataset))
    return torch.softmax(logits, dim=1)[:, 1].cpu().numpy().reshape(dataset.valid.shape)


@torch.no_grad()
def evaluate(models: TrainedModels, splits: dict[str, CollisionDataset]) -> dict:
    """Table 1 and Table 2 measures: ``{"cae": {"seen_acc", "unseen_acc", ...},
    "mlp": {"seen", "unseen", "unseen_uniform"}}``.

    ``cae`` also holds ``seen_all_free`` and ``unseen_all_free``, the share of free cells: the
    reconstruction accuracy of a CAE that ignores its input and answers "all free"; a CAE
    left untrained (``models.history`` without ``"cae"``) gives ``{"trained": False}``.
    ``mlp.seen`` and ``mlp.unseen`` score the balanced test samples; ``mlp.unseen_uniform``
    scores the paper's unseen test, validity-blind samples in the unseen workspaces
    (``splits["unseen_uniform"]``, or :func:`toolkit.learning.data.validity_blind_split` of the
    unseen workspaces). Each holds ``acc``, ``tpr``, ``tnr`` and ``always_valid``, the
    accuracy of answering "valid" on the same samples (their share of valid ones).
    """
    predictor = models.predictor.eval()
    trained_cae = "cae" in models.history
    result: dict = {"cae": {} if trained_cae else {"trained": False}, "mlp": {}}
    for key, split in (("seen", "seen_test"), ("unseen", "unseen_test")):
        dataset = splits[split]
        grids = torch.as_tensor(dataset.occupancy, device=predictor.threshold.device)
        result["mlp"][key] = classification_scores(models, dataset)
        if not trained_cae:  # left untrained (train_models' cae=False): nothing to measure
            continue
        result["cae"][f"{key}_acc"] = float(
            metrics.reconstruction_accuracy(predictor.cae(grids).cpu().numpy(), dataset.occupancy).mean()
        )
        result["cae"][f"{key}_all_free"] = float(np.mean(dataset.occupancy < 0))  # the accuracy of "all free"
    uniform = splits.get("unseen_uniform") or data.validity_blind_split(models.scenario, splits["unseen_test"])
    result["mlp"]["unseen_uniform"] = classification_scores(models, uniform)
    return result


def classification_scores(models: TrainedModels, dataset: CollisionDataset) -> dict[str, float]:
    """``{"acc", "tpr", "tnr", "always_valid"}`` of the models' predictions on a dataset's samples."""
    predicted = probabilities(models.predictor, dataset) >= models.threshold
    return dict(
        metrics.classification(predicted.reshape(-1), dataset.valid.reshape(-1)),
        always_valid=float(np.mean(dataset.valid)),
    )


# -- helpers ---------------------------------------------------------------------


def _inputs(predictor: CollisionPredictor, dataset: CollisionDataset) -> torch.Tensor:
    """MLP inputs ``(W * n, F)`` of a dataset's samples, the workspaces encoded once (no gradient)."""
    device = predictor.threshold.device
    ws_index, Q, _ = dataset.flat()
    with torch.no_grad():
        grids = torch.as_tensor(dataset.occupancy, device=device)
        return predictor.encoding(
            predictor.cae.encode(grids),
            grids,
            torch.as_tensor(ws_index, device=device),
            torch.as_tensor(Q, dtype=torch.float32, device=device),
        )


def split_workspaces(dataset: CollisionDataset, n_first: int) -> tuple[CollisionDataset, CollisionDataset]:
    """The first ``n_first`` workspaces and the rest, as two datasets."""
    parts = []
    for part in (slice(0, n_first), slice(n_first, None)):
        parts.append(
            CollisionDataset(
                dataset.scenario,
                dataset.workspaces[part],
                dataset.occupancy[part],
                dataset.configs[part],
                dataset.valid[part],
                dict(dataset.meta),
            )
        )
    return parts[0], parts[1]


def _batches(n: int, batch: int, epochs: int, shuffle: torch.Generator) -> list[list[torch.Tensor]]:
    """Index batches of each epoch, every epoch a fresh permutation drawn from ``shuffle``."""
    return [list(torch.randperm(n, generator=shuffle).split(batch)) for _ in range(epochs)]


def fit(
    params,
    epochs: list[list[torch.Tensor]],
    loss_of,
    *,
    optimizer_name: str,
    lr: float,
    progress: bool,
    desc: str,
    weight_decay: float = 0.0,
    cosine_schedule: bool = False,
) -> list[float]:
    """Minimize ``loss_of(batch indices)`` over the epochs with the named optimizer; mean loss per epoch."""
    params = list(params)
    optimizer = registry.lookup(OPTIMIZERS, optimizer_name, kind="optimizer")(params, lr=lr, weight_decay=weight_decay)
    total = sum(map(len, epochs))
    schedule = (lambda step: 0.5 * (1 + math.cos(math.pi * step / total))) if cosine_schedule else (lambda step: 1.0)
    scheduler = torch.optim.lr_scheduler.LambdaLR(optimizer, schedule)
    history = []
    bar = tqdm(epochs, desc=desc, disable=not progress, leave=False)
    for batches in bar:
        losses = []
        for idx in batches:
            optimizer.zero_grad(set_to_none=True)
            loss = loss_of(idx.to(params[0].device))
            loss.backward()
            optimizer.step()
            scheduler.step()
            losses.append(loss.item())
        history.append(float(np.mean(losses)))
        bar.set_postfix(loss=f"{history[-1]:.4g}")
    return history
