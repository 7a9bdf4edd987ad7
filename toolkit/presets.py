"""Training presets: ``paper`` (§V-B3, exactly the paper's settings) and ``strong`` (ours, measured).

``paper``: the paper's sizes and data counts, Adagrad with learning rate 0.1
for the MLP, dropout 0.5, lambda = 1e-3, the MLP sees ``[z, q]``. The paper gives
no epoch counts or batch sizes; ours are stated here. One measured deviation: the
CAE trained with Adagrad at learning rate 0.1 diverges (2DS: loss 1e22 after 200
epochs) and at 0.01 collapses to the all-free grid, so the CAE uses AdamW at 1e-3.
Planning with it is the paper's Algorithm 1: predicted samples, exactly checked edges.

``strong``: the same CAE; the MLP sees ``[z, patch, pose]`` (see
:mod:`toolkit.encoding`): the occupancy around the robot's base cell, the base's
position in its cell, sin/cos of its angles, its scaled joints and, from forward
kinematics, where each link box is. Each choice, measured on unseen workspaces
(seed 0, one thread; acc/TPR/TNR in %; README has the full table):

- link features: 3DC-9 83.1 -> 93.5 with the same 128-64 MLP (measured with a
  prototype of them: link frame origins and x axes). The network no longer has to
  learn the kinematics of a 9-DoF chain from sin/cos; it compares link boxes with
  occupied cells.
- MLP 64-32 without dropout: 3DC-9 93.7 (128-32: 93.6, 64-64-32: 93.5, 32-32:
  92.7; the old 256-256-128 without link features: 82.0). Small, because the
  learned checker must be much faster than the exact one: the patch's share of the
  first layer is a per-workspace table (:meth:`~toolkit.models.CollisionPredictor.context`),
  so a prediction costs a row gather, the pose's product and two small layers.
- 20x the paper's labelled samples, 10 epochs, AdamW at 3e-3 with weight decay 1e-4 and a
  cosine schedule, batch 256, inputs standardized (folded into the first layer),
  threshold calibrated on 10 % held-out training workspaces. 20 epochs: 3DC-9 94.0
  instead of 93.7, for twice the MLP's training time.
- planning with it screens edges by prediction too (``screen_edges``, the paper's
  future work; see :mod:`toolkit.prm`): only the candidate path's edges are checked
  exactly.
- CAE capped at 150 steps (the paper preset: 300): the 147M-parameter 3DO CAE takes
  2-5 s a step on 2 cores, and the MLP barely needs ``z`` once it sees the patch
  (3DO 98.2 with a 20-step CAE, 98.4 with 300). CAE accuracy seen/unseen at 150 vs
  300 steps: 3DC 91.1/91.2 both; 2DS 88.6/87.6 vs 89.6/87.5.
"""

from __future__ import annotations

from dataclasses import dataclass, replace


@dataclass(frozen=True)
class Preset:
    """Every setting of one training recipe."""

    name: str
    encoding: str  # MLP input: "raw" = [z, q] (paper), "local" = [z, patch, encoded q]
    optimizer: str  # "adagrad" or "adamw", for the MLP
    lr: float
    cae_optimizer: str
    cae_lr: float
    dropout: float
    cae_lambda: float  # lambda of Eq. (1)
    cae_epochs: int
    cae_batch: int
    cae_max_steps: int  # caps cae_epochs: the 147M-parameter 3DO CAE takes ~2 s a step on 2 cores
    mlp_epochs: int
    mlp_batch: int
    mlp_hidden: tuple[int, ...] | None = None  # None: the paper's widths for the scenario
    samples_factor: int = 1  # labelled samples per workspace = factor x the paper's
    weight_decay: float = 0.0
    cosine_schedule: bool = False  # learning rate decays to 0 along a cosine
    standardize: bool = False  # MLP inputs scaled to zero mean, unit variance on the training data
    holdout: float = 0.0  # share of training workspaces kept from the MLP to calibrate its threshold
    screen_edges: bool = False  # planning with this model: learned edge screening (toolkit.prm), or the paper's exact edges
    quick: bool = False  # shrunk by quick_version()

    def quick_version(self) -> "Preset":
        """The same recipe with few epochs and samples: a whole scenario in seconds (tests, ``--quick``)."""
        if self.quick:
            return self
        return replace(self, quick=True, cae_epochs=max(1, self.cae_epochs // 20), mlp_epochs=max(2, self.mlp_epochs // 10),
                       samples_factor=min(self.samples_factor, 4))


PRESETS: dict[str, Preset] = {
    "paper": Preset("paper", encoding="raw", optimizer="adagrad", lr=0.1,
                    cae_optimizer="adamw", cae_lr=1e-3, dropout=0.5, cae_lambda=1e-3,
                    cae_epochs=200, cae_batch=10, cae_max_steps=300, mlp_epochs=200, mlp_batch=100),
    "strong": Preset("strong", encoding="local", optimizer="adamw", lr=3e-3,
                     cae_optimizer="adamw", cae_lr=1e-3, dropout=0.0, cae_lambda=1e-3,
                     cae_epochs=300, cae_batch=10, cae_max_steps=150, mlp_epochs=10, mlp_batch=256, mlp_hidden=(64, 32),
                     samples_factor=20, weight_decay=1e-4, cosine_schedule=True, standardize=True, holdout=0.1,
                     screen_edges=True),
}

# Quick runs also use fewer workspaces than the paper (seen, seen-test, unseen).
QUICK_WORKSPACES = (8, 4, 4)


def get(name: str) -> Preset:
    """The preset called ``name`` ('paper' or 'strong')."""
    try:
        return PRESETS[name]
    except KeyError:
        raise ValueError(f"unknown preset {name!r}; choose one of {sorted(PRESETS)}") from None
