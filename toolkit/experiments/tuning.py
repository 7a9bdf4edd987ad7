"""Choosing the paper's unstated settings by validation on held-out training workspaces.

§IV-B3 gives the networks' sizes, the MLP's optimizer, learning rate and dropout, and
the CAE's lambda, but not how long either network trains, the MLP's batch, its
initialization, or whether its inputs are scaled. Choosing those by their score on
Table 2's unseen workspaces would fit the test; ``tune(config, out)`` chooses them
as a careful reproduction must, on workspaces the models do not train on but that come
from the training set:

1. the ``paper`` preset's training workspaces are split: the first 80 % fit the
   networks, the last 20 % (``VALIDATION_SHARE``) validate them;
2. the CAE is trained once for each number of epochs in ``CAE_EPOCHS`` on the fitting
   workspaces' grids and scored by its reconstruction of the validation grids; the best
   is kept (ties: fewer epochs);
3. the MLP is trained on the fitting workspaces' samples, with that CAE, once for each
   combination of ``MLP_GRID`` and scored by its accuracy on the validation workspaces'
   samples (balanced, like its training data). With a few hundred validation samples,
   accuracies a standard error apart are noise, so the choice follows the one-standard-
   error rule (Hastie, Tibshirani, Friedman, *Elements of Statistical Learning*, §7.10):
   the first setting in grid order, the cheapest, whose accuracy lies within one
   standard error of the best.

The unseen workspaces are never generated. ``toolkit/learning/presets.py`` states what this chose;
``docs/fidelity.md`` (§5) shows the table. Like :func:`toolkit.experiments.ablation.ablate`, every
trained row is cached in ``out/cache`` under its preset's fingerprint, so an interrupted
run resumes and a changed recipe is trained again.
"""

from __future__ import annotations

import itertools
import time
from dataclasses import dataclass, replace
from functools import partial
from pathlib import Path

import numpy as np
import torch

from toolkit.experiments.config import QUICK, RunConfig
from toolkit.experiments.stages import Stages
from toolkit.learning import data, metrics, presets, training
from toolkit.learning.models import build_predictor
from toolkit.util import outputs

VALIDATION_SHARE = 0.2
CAE_EPOCHS = (100, 500, 1000)
MLP_GRID: dict[str, tuple] = {
    "mlp_epochs": (50, 200, 500),
    "mlp_batch": (32, 100),
    "standardize": (False, True),
    "mlp_init": ("torch", "he"),
}


def tune(config: RunConfig, out: str | Path) -> dict:
    """Validate the ``paper`` preset's unstated settings for the configuration's scenario and seed (each candidate is
    a variant of the paper preset, whatever ``config.preset``); writes ``tuning.json`` and ``tuning.md``."""
    out = Path(out)
    stages = Stages(out, {"tuning": config.scenario.name, "quick": config.quick, "seed": config.seed}, config.progress)
    held = held_out(config)
    scale = QUICK.study_epochs_divisor if config.quick else 1  # quick: a fraction of the epochs, for tests
    # every tuned setting is set in each row, so a row's fingerprint does not change when presets.py adopts the
    # choice; the CAE's steps are not capped, its epochs decide
    base = replace(presets.get("paper"), cae_max_steps=10**9, **{k: v[0] for k, v in MLP_GRID.items()})
    cae_rows, cae_files = tune_cae(held, stages, base, scale)
    best_cae = max(cae_rows, key=lambda r: r["validation_acc"])  # max keeps the first of equals: fewer epochs
    with_cae = replace(base, cae_epochs=best_cae["cae_epochs"] // scale)
    mlp_rows = tune_mlp(held, stages, base=with_cae, scale=scale, cae_file=cae_files[best_cae["cae_epochs"]])
    n_validation = int(held.validation.valid.size)
    best_mlp = one_standard_error_choice(mlp_rows, n_validation)
    result = {
        "scenario": config.scenario.name,
        "seed": config.seed,
        "quick": config.quick,
        "fit_workspaces": len(held.fit.workspaces),
        "validation_workspaces": len(held.validation.workspaces),
        "validation_samples": n_validation,
        "cae": cae_rows,
        "mlp": mlp_rows,
        "chosen": {"cae_epochs": best_cae["cae_epochs"], **{k: best_mlp[k] for k in MLP_GRID}},
    }
    outputs.write_json(out / "tuning.json", result)
    (out / "tuning.md").write_text(markdown(result))
    return result


@dataclass(frozen=True)
class HeldOut:
    """What every candidate trains and is scored on: the run's settings and its training workspaces split in two."""

    config: RunConfig
    fit: data.CollisionDataset  # the first workspaces: the networks train on them
    validation: data.CollisionDataset  # the last VALIDATION_SHARE of them: the candidates are scored on them


def held_out(config: RunConfig) -> HeldOut:
    """The ``paper`` preset's training samples (the train split of ``data.make_splits``), split into the fitting and
    the validation workspaces (step 1); the unseen workspaces are not generated."""
    scenario, seed = config.scenario, config.seed
    n_seen = QUICK.workspaces[0] if config.quick else scenario.n_seen
    seen = scenario.workspaces("seen", n_seen, seed)
    train = data.label_workspaces(
        scenario,
        seen,
        samples_per_workspace=scenario.samples_per_workspace,
        seed=seed,
        stream="train_samples",
        progress=config.progress,
        desc="train samples",
    )
    n_fit = n_seen - max(1, int(round(VALIDATION_SHARE * n_seen)))
    fit, validation = training.split_workspaces(train, n_fit)
    return HeldOut(config, fit, validation)


def tune_cae(held: HeldOut, stages: Stages, base: presets.Preset, scale: int) -> tuple[list[dict], dict[int, Path]]:
    """Step 2: one CAE for each of ``CAE_EPOCHS`` (divided by ``scale``), each row cached; the rows and, by epochs,
    the files holding the trained CAEs."""
    rows, files = [], {}
    for epochs in CAE_EPOCHS:
        preset = replace(base, name=f"tuning:cae{epochs}", cae_epochs=epochs // scale)
        name = f"cae_{epochs}_{preset.fingerprint()}"
        files[epochs] = stages.cache / f"{name}.pt"
        rows.append(dict(stages.json(name, partial(_cae_row, held, preset, files[epochs])), cae_epochs=epochs))
    return rows, files


def tune_mlp(held: HeldOut, stages: Stages, *, base: presets.Preset, scale: int, cae_file: Path) -> list[dict]:
    """Step 3: one MLP for each combination of ``MLP_GRID`` (epochs divided by ``scale``), with the CAE in
    ``cae_file``, each row cached; the rows in grid order."""
    rows = []
    for values in itertools.product(*MLP_GRID.values()):
        settings = dict(zip(MLP_GRID, values))
        key = "mlp_" + "_".join(str(v) for v in values)
        preset = replace(
            base, name=f"tuning:{key}", **dict(settings, mlp_epochs=max(2, settings["mlp_epochs"] // scale))
        )
        name = f"{key}_{preset.fingerprint()}_{cae_file.stem}"
        rows.append(dict(stages.json(name, partial(_mlp_row, held, preset, cae_file)), **settings))
    return rows


def standard_error(acc: float, n: int) -> float:
    """The standard error of an accuracy ``acc`` measured on ``n`` samples, sqrt(acc (1 - acc) / n)."""
    return float(np.sqrt(acc * (1 - acc) / n))


def one_standard_error_choice(rows: list[dict], n: int) -> dict:
    """The first row whose ``validation_acc`` lies within one standard error (on ``n`` samples) of the best."""
    best = max(r["validation_acc"] for r in rows)
    return next(r for r in rows if r["validation_acc"] >= best - standard_error(best, n))


def _cae_row(held: HeldOut, preset: presets.Preset, cae_file: Path) -> dict:
    """Train the paper's CAE on the fitting grids, kept in ``cae_file``; its reconstruction accuracy on them and on
    the validation grids."""
    scenario, seed, fit, validation = held.config.scenario, held.config.seed, held.fit, held.validation
    torch.manual_seed(seed)
    predictor = build_predictor(scenario, "raw")
    began = time.perf_counter()
    training.train_cae(  # capped as training.train_models caps it
        predictor,
        torch.as_tensor(fit.occupancy),
        preset,
        torch.Generator().manual_seed(seed),
        progress=held.config.progress,
        max_steps=scenario.cae_max_steps,
        max_batch=scenario.cae_max_batch,
        max_lr=scenario.cae_max_lr,
    )
    seconds = time.perf_counter() - began
    state = predictor.cae.state_dict()
    outputs.write_atomically(cae_file, lambda tmp: torch.save(state, tmp))  # a rerun trusts it: whole or none
    with torch.no_grad():
        acc = {
            name: float(
                metrics.reconstruction_accuracy(predictor.cae(torch.as_tensor(d.occupancy)).numpy(), d.occupancy).mean()
            )
            for name, d in (("fit", fit), ("validation", validation))
        }
    return {
        "fit_acc": acc["fit"],
        "validation_acc": acc["validation"],
        "validation_all_free": float(np.mean(validation.occupancy < 0)),
        "train_seconds": seconds,
    }


def _mlp_row(held: HeldOut, preset: presets.Preset, cae_file: Path) -> dict:
    """Train the paper's MLP on the fitting samples with the chosen CAE; its accuracy on the validation samples."""
    scenario, fit, validation = held.config.scenario, held.fit, held.validation
    cae = build_predictor(scenario, "raw").cae
    cae.load_state_dict(torch.load(cae_file, weights_only=True))
    began = time.perf_counter()
    models = training.train_models(
        scenario, preset, {"train": fit}, held.config.seed, progress=held.config.progress, device="cpu", trained_cae=cae
    )
    seconds = time.perf_counter() - began
    scores = {name: training.classification_scores(models, d) for name, d in (("fit", fit), ("validation", validation))}
    return {
        "fit_acc": scores["fit"]["acc"],
        "validation_acc": scores["validation"]["acc"],
        "validation_tpr": scores["validation"]["tpr"],
        "validation_tnr": scores["validation"]["tnr"],
        "train_seconds": seconds,
    }


def markdown(result: dict) -> str:
    """The two validation tables, the chosen rows marked, and the paper preset's current values beside them."""
    pct = lambda x: f"{100 * x:.1f}"
    chosen, paper = result["chosen"], presets.get("paper")
    n = result["validation_samples"]
    lines = [
        f"## Tuning the paper preset's unstated settings, {result['scenario']}",
        "",
        f"Fitted on {result['fit_workspaces']} training workspaces, validated on the other "
        f"{result['validation_workspaces']} ({n} balanced samples); the unseen workspaces are never used.",
        "",
        "| CAE epochs | fit rec. | validation rec. (all free) | train s |",
        "| --- | --- | --- | --- |",
    ]
    for r in result["cae"]:
        mark = " **chosen**" if r["cae_epochs"] == chosen["cae_epochs"] else ""
        lines.append(
            f"| {r['cae_epochs']}{mark} | {pct(r['fit_acc'])} | {pct(r['validation_acc'])} "
            f"({pct(r['validation_all_free'])}) | {r['train_seconds']:.0f} |"
        )
    best = max(r["validation_acc"] for r in result["mlp"])
    lines += [
        "",
        f"MLP with the chosen CAE. The best validation accuracy has a standard error of "
        f"{100 * standard_error(best, n):.1f} points; the chosen row is the first within one standard error "
        "of the best.",
        "",
        "| epochs | batch | standardized | init | fit acc | validation acc / TPR / TNR | train s |",
        "| --- | --- | --- | --- | --- | --- | --- |",
    ]
    for r in result["mlp"]:
        mark = " **chosen**" if all(r[k] == chosen[k] for k in MLP_GRID) else ""
        lines.append(
            f"| {r['mlp_epochs']}{mark} | {r['mlp_batch']} | {'yes' if r['standardize'] else 'no'} "
            f"| {r['mlp_init']} | {pct(r['fit_acc'])} | {pct(r['validation_acc'])} / "
            f"{pct(r['validation_tpr'])} / {pct(r['validation_tnr'])} | {r['train_seconds']:.0f} |"
        )
    current = {"cae_epochs": paper.cae_epochs, **{k: getattr(paper, k) for k in MLP_GRID}}
    lines += ["", f"Chosen: {chosen}.", f"The `paper` preset has: {current}."]
    return "\n".join(lines) + "\n"
