"""From the paper's recipe to ours, one change at a time: where the gap to Tables 1 and 2 comes from.

``ablate(config, out)`` trains one model per row of :data:`STEPS`; each row keeps
every change above it and adds its own, starting from the ``paper`` preset (§IV-B3).
Every row is scored on the same test samples: seen workspaces (balanced), unseen
workspaces balanced and validity-blind as the paper (§IV-A, see
:func:`toolkit.learning.data.validity_blind_split`), with the accuracy of answering "valid"
beside them, the CAE's unseen reconstruction, and the seconds training took. Rows
that change nothing in the CAE reuse the CAE of the row above (its seconds are
counted once, in the row that trained it).

Like :func:`toolkit.experiments.reproduce.reproduce`, each row is cached in ``out/cache`` as it
finishes, under its preset's fingerprint, so an interrupted run resumes and a changed
recipe is trained again; ``out/ablation.json`` and
``out/ablation.md`` hold the table. ``docs/fidelity.md`` reads it.
"""

from __future__ import annotations

import hashlib
import time
from dataclasses import asdict, replace
from functools import partial
from pathlib import Path

import torch

from toolkit.experiments import pipeline
from toolkit.experiments.config import QUICK, RunConfig
from toolkit.experiments.stages import Stages
from toolkit.learning import data, presets, training
from toolkit.learning.models import CAE
from toolkit.util import outputs

# (key, what changes, the Preset fields it sets); each row keeps the changes of the rows above it.
STEPS: list[tuple[str, str, dict]] = [
    ("paper", "the paper's recipe (preset `paper`)", {}),
    ("cae_mean", "CAE loss: mean squared error over the cells (§IV-B1) instead of Eq. (1)'s sum", {"cae_loss": "mean"}),
    (
        "cae_many",
        "CAE on 2000 generated grids: AdamW 1e-3, batch 100, 2500 steps, Eq. (1)'s sum",
        {
            "cae_loss": "sum",
            "cae_workspaces": 2000,
            "cae_lr": 1e-3,
            "cae_batch": 100,
            "cae_max_steps": 2500,
            "cae_epochs": 10_000,
        },
    ),
    ("no_dropout", "MLP without dropout (0.5 -> 0)", {"dropout": 0.0}),
    (
        "adamw",
        "MLP: AdamW 3e-3, weight decay 1e-4, cosine schedule, batch 256",
        {"optimizer": "adamw", "lr": 3e-3, "weight_decay": 1e-4, "cosine_schedule": True, "mlp_batch": 256},
    ),
    ("standardize", "MLP inputs standardized", {"standardize": True}),
    (
        "more_workspaces",
        "1000 training workspaces instead of the paper's (100 samples each), 20 epochs",
        {"n_seen": 1000, "mlp_epochs": 20},
    ),
    ("wider", "MLP 64-32 instead of the paper's widths", {"mlp_hidden": (64, 32)}),
    (
        "local",
        "MLP input: occupancy patch and link features beside z and q (toolkit.learning.encoding)",
        {"encoding": "local"},
    ),
    ("no_z", "without z: the MLP sees the patch and pose only", {"latent_input": False}),
]
# The CAE settings a row may change; a row that changes none reuses the CAE above it (the MLP optimizer's weight
# decay and schedule, which train_cae would also read, are the MLP's here: the CAE keeps row 2's training).
CAE_FIELDS = (
    "cae_optimizer",
    "cae_lr",
    "cae_lambda",
    "cae_epochs",
    "cae_batch",
    "cae_max_steps",
    "cae_loss",
    "cae_workspaces",
)


def step_presets(quick: bool = False) -> list[tuple[str, str, presets.Preset]]:
    """Each row's key, description and cumulative preset (quick: shrunk by ``QUICK``, for tests)."""
    rows, preset = [], presets.get("paper")
    for key, what, changes in STEPS:
        preset = replace(preset, name=f"ablation:{key}", **changes)
        rows.append(
            (key, what, replace(QUICK.shrink(preset), n_seen=preset.n_seen and QUICK.study_seen) if quick else preset)
        )
    return rows


def ablate(config: RunConfig, out: str | Path) -> list[dict]:
    """Every row of :data:`STEPS` for the configuration's scenario and seed (its preset is each row's), cached in
    ``out``; writes ``ablation.json`` and ``ablation.md``."""
    scenario, seed, quick = config.scenario, config.seed, config.quick
    out = Path(out)
    stages = Stages(out, {"ablation": scenario.name, "quick": quick, "seed": seed}, config.progress)
    tests = pipeline.make_splits(replace(config, preset=presets.get("paper")))  # the paper's counts: every row's test
    tests["unseen_uniform"] = data.validity_blind_split(scenario, tests["unseen_test"])
    caes: dict[tuple, CAE] = {}
    rows = []
    for key, what, preset in step_presets(quick):
        row_config = replace(config, preset=preset, device="cpu")
        rows.append(
            dict(
                stages.json(f"{key}_{preset.fingerprint()}", partial(_row, stages, row_config, tests, caes)),
                key=key,
                change=what,
            )
        )
    outputs.write_json(out / "ablation.json", {"scenario": scenario.name, "seed": seed, "quick": quick, "rows": rows})
    (out / "ablation.md").write_text(markdown(scenario.name, rows))
    return rows


def _row(stages: Stages, config: RunConfig, tests: dict, caes: dict) -> dict:
    """Train one row's models (the CAE reused when an earlier row trained the same), score them on ``tests``."""
    scenario, preset = config.scenario, config.preset
    cae_key = tuple((f, getattr(preset, f)) for f in CAE_FIELDS)
    cae_file = stages.cache / f"cae_{hashlib.sha1(repr(cae_key).encode()).hexdigest()[:12]}.pt"
    trained = caes.get(cae_key)
    if trained is None and cae_file.exists():
        trained = CAE((scenario.grid_size,) + tuple(scenario.cae_hidden))
        trained.load_state_dict(torch.load(cae_file, weights_only=True))
    splits = dict(tests, train=pipeline.make_splits(config)["train"])
    began = time.perf_counter()
    models = training.train_models(
        scenario,
        preset,
        splits,
        config.seed,
        progress=config.progress,
        device=config.device,
        cae=True,
        trained_cae=trained,
    )
    seconds = time.perf_counter() - began
    if trained is None:
        state = models.predictor.cae.state_dict()
        outputs.write_atomically(cae_file, lambda tmp: torch.save(state, tmp))  # a rerun trusts it: whole or none
    caes[cae_key] = models.predictor.cae
    scores = training.evaluate(models, splits)
    return {
        "cae": scores["cae"],
        "mlp": scores["mlp"],
        "train_seconds": seconds,
        "cae_trained": trained is None,
        "preset": {k: v for k, v in asdict(preset).items() if k != "name"},
    }


def _pct(x: float) -> str:
    return f"{100 * x:.1f}"


def markdown(scenario_name: str, rows: list[dict]) -> str:
    """The ablation as a markdown table: accuracy / TPR / TNR in %, "always valid" beside the unseen tests."""
    head = (
        "| # | change (cumulative) | CAE unseen rec. (all free) | seen acc / TPR / TNR "
        "| unseen balanced acc / TPR / TNR | unseen validity-blind acc / TPR / TNR (always valid) | train s |"
    )
    lines = [
        f"## Ablation, {scenario_name}: the paper's recipe to ours, one change at a time",
        "",
        head,
        "|" + " --- |" * 7,
    ]
    for i, r in enumerate(rows):
        mlp, cae = r["mlp"], r["cae"]
        trio = lambda m: " / ".join(_pct(m[k]) for k in ("acc", "tpr", "tnr"))
        lines.append(
            f"| {i} | {r['change']} | {_pct(cae['unseen_acc'])} ({_pct(cae['unseen_all_free'])}) "
            f"| {trio(mlp['seen'])} | {trio(mlp['unseen'])} "
            f"| {trio(mlp['unseen_uniform'])} ({_pct(mlp['unseen_uniform']['always_valid'])}) "
            f"| {r['train_seconds']:.0f}{'' if r['cae_trained'] else ' (CAE reused)'} |"
        )
    return "\n".join(lines) + "\n"
