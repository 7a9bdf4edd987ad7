"""Training presets: ``paper`` (§IV-B3: every setting the paper states but one, the CAE's optimizer) and ``strong``
(ours).

``paper``: the paper's sizes and data counts; the MLP sees ``[z, q]`` and trains with
Adagrad at learning rate 0.1 and dropout 0.5; the CAE has lambda = 1e-3 and Eq. (1)'s
loss summed over the cells (``cae_loss="sum"``; :meth:`~toolkit.learning.models.CAE.loss` sets
out the other reading, §IV-B1's "mean square error"). Where the paper is silent, the
CAE's epochs and the MLP's epochs, batch, initialization and input scaling were chosen
by validation on held-out training workspaces, never the unseen test (``toolkit tune``,
:mod:`toolkit.experiments.tuning`; its table is in ``docs/fidelity.md`` §5); the CAE's batch (10)
and the decision threshold (0.5) are ours. One deviation: the CAE trains with AdamW at
1e-4, because with Adagrad at the paper's rate it diverges or collapses to the all-free
grid.

``strong``: what it takes to make the idea work. Its CAE trains on thousands of
generated grids (``cae_workspaces``) so it stops memorizing; its MLP sees
``[patch, pose]`` (:mod:`toolkit.learning.encoding`): the occupancy around the robot and where
each link box is, by forward kinematics, instead of only ``z``, which once the MLP sees
the patch adds nothing, so ``toolkit train`` leaves its CAE untrained unless asked
(``--cae``). A small MLP (the learned checker must stay much faster than the exact
one), 20x the labelled samples, AdamW with a cosine schedule, standardized inputs and
a threshold calibrated on held-out training workspaces.

A preset says how to train a model, not how to plan with it: which planner each recipe plans
with is the experiments' choice (:mod:`toolkit.experiments.planners`). Why each choice,
measured one change at a time: ``docs/design.md`` ("The presets") and ``docs/fidelity.md``
(``toolkit ablate``).
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable
from dataclasses import dataclass

import torch

from toolkit.learning.encoding import ENCODINGS
from toolkit.learning.models import CAE_LOSSES, MLP_INITS, CollisionPredictor, build_predictor
from toolkit.scenarios import Scenario
from toolkit.util import registry

OPTIMIZERS: dict[str, Callable[..., torch.optim.Optimizer]] = {  # the optimizers a preset may name
    "adagrad": torch.optim.Adagrad,
    "adamw": torch.optim.AdamW,
}
CHOICES = {  # a preset's settings that name something, and the names each may take (checked as a preset is made)
    "encoding": ENCODINGS,
    "optimizer": tuple(OPTIMIZERS),
    "cae_optimizer": tuple(OPTIMIZERS),
    "mlp_init": MLP_INITS,
    "cae_loss": CAE_LOSSES,
}


@dataclass(frozen=True)
class Preset:
    """Every setting of one training recipe."""

    name: str
    encoding: str  # MLP input: "raw" = [z, q] (paper), "local" = [z, patch, pose] (see toolkit.learning.encoding)
    optimizer: str  # the MLP's: a name of OPTIMIZERS, "adagrad" or "adamw"
    lr: float
    cae_optimizer: str  # the CAE's, likewise
    cae_lr: float
    dropout: float
    cae_lambda: float  # lambda of Eq. (1)
    cae_epochs: int
    cae_batch: int
    cae_max_steps: int  # caps cae_epochs (a scenario may cap lower: Scenario.cae_max_steps)
    mlp_epochs: int
    mlp_batch: int
    mlp_hidden: tuple[int, ...] | None = None  # None: the paper's widths for the scenario
    mlp_init: str = "torch"  # the MLP's initial weights: PyTorch's default or "he" (see models.CollisionMLP)
    cae_loss: str = "sum"  # reconstruction error over the cells: "sum" (Eq. (1)) or "mean" (§IV-B1's MSE); see CAE.loss
    cae_workspaces: int = 0  # the CAE trains on this many generated grids (0: the training split's, the paper)
    n_seen: int | None = None  # training workspaces (None: the paper's, Scenario.n_seen)
    samples_factor: int = 1  # labelled samples per workspace = factor x the paper's
    weight_decay: float = 0.0  # the MLP's optimizer (the CAE's penalty is Eq. (1)'s lambda)
    cosine_schedule: bool = False  # the MLP's learning rate decays to 0 along a cosine
    standardize: bool = False  # MLP inputs scaled to zero mean, unit variance on the training data
    holdout: float = 0.0  # share of training workspaces kept from the MLP to calibrate its threshold
    latent_input: bool = True  # the MLP sees the CAE's z (the paper); False: only the patch and pose
    quick: bool = False  # shrunk for a quick run (toolkit.experiments.config.QUICK)
    origin: str = ""  # the recipe this one was made from (dataclasses.replace keeps it); "": its own name

    def __post_init__(self):
        """Refuses a setting outside its :data:`CHOICES` at once, in one line, rather than minutes into training."""
        for setting, allowed in CHOICES.items():
            if (value := getattr(self, setting)) not in allowed:
                raise ValueError(f"preset {self.name!r}: {setting} must be one of {', '.join(allowed)}; got {value!r}")
        if not self.origin:
            object.__setattr__(self, "origin", self.name)  # frozen: set once, as it is made

    def build_predictor(self, scenario: Scenario) -> CollisionPredictor:
        """Untrained networks of this recipe for ``scenario``: the CAE, the MLP's input encoding and the MLP, with the
        recipe's sizes, dropout and initialization (what training starts from and a checkpoint's weights fill)."""
        return build_predictor(
            scenario,
            self.encoding,
            mlp_hidden=self.mlp_hidden,
            dropout=self.dropout,
            latent_input=self.latent_input,
            mlp_init=self.mlp_init,
        )

    def fingerprint(self) -> str:
        """8 hex digits that change with any setting: a cache keyed by it never serves a changed recipe."""
        return hashlib.sha256(repr(self).encode()).hexdigest()[:8]


PRESETS: dict[str, Preset] = {
    "paper": Preset(
        "paper",
        encoding="raw",
        optimizer="adagrad",
        lr=0.1,
        cae_optimizer="adamw",  # the one deviation: the paper's Adagrad at 0.1 diverges here (chapter 02 says why)
        cae_lr=1e-4,
        dropout=0.5,
        cae_lambda=1e-3,
        # unstated in the paper, chosen by `toolkit tune --scenario 2ds` on held-out training workspaces:
        cae_epochs=100,
        mlp_epochs=50,
        mlp_batch=32,
        mlp_init="he",
        standardize=False,
        cae_batch=10,
        cae_max_steps=1500,
    ),
    "strong": Preset(
        "strong",
        encoding="local",
        optimizer="adamw",
        lr=3e-3,
        cae_optimizer="adamw",
        cae_lr=1e-3,
        dropout=0.0,
        cae_lambda=1e-3,
        cae_workspaces=2000,
        cae_epochs=10_000,
        cae_batch=100,
        cae_max_steps=2500,
        mlp_epochs=10,
        mlp_batch=256,
        mlp_hidden=(64, 32),
        samples_factor=20,
        weight_decay=1e-4,
        cosine_schedule=True,
        standardize=True,
        holdout=0.1,
        latent_input=False,
    ),
}


def register(preset: Preset, *, replace: bool = False) -> Preset:
    """Make ``get(preset.name)`` return ``preset`` (a recipe of your own), so that everything that takes a preset's
    name accepts it: ``toolkit train --preset``, ``toolkit reproduce --preset`` (with ``--import MODULE``), the
    notebooks' ``trained_models``. A name already taken (``paper``, ``strong``) is refused unless ``replace``.
    Registration lasts for the Python process: register again before loading a checkpoint trained with it.
    """
    if not isinstance(preset, Preset):
        raise TypeError(f"expected a Preset, got {type(preset).__name__}")
    return registry.bind(PRESETS, preset.name, preset, kind="preset", replace=replace)


def get(name: str) -> Preset:
    """The preset called ``name`` ('paper', 'strong' or a registered one)."""
    return registry.lookup(PRESETS, name, kind="preset")
