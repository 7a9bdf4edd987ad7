"""Training presets: ``paper`` (§IV-B3, exactly the paper's settings) and ``strong`` (ours, measured).

``paper``: the paper's sizes and data counts, Adagrad with learning rate 0.1
for the MLP, dropout 0.5, lambda = 1e-3, the MLP sees ``[z, q]``. The paper gives
no epoch counts or batch sizes; ours are stated here. One measured deviation: the
CAE trained with Adagrad at learning rate 0.1 diverges (2DS: loss 1e22 after 200
epochs) and at 0.01 collapses to the all-free grid, so the CAE uses AdamW at 1e-4
(at 1e-3 the 3DO CAE diverges), for up to 1500 steps of 10 grids: 2DS and 3DC then
reconstruct their training workspaces almost exactly (97 %, 99.7 %). The 3DO CAE stops at 300 steps
(``Scenario.cae_max_steps``: 147M parameters, about 2.3 s a step on 2 cores).
Planning with it is the paper's Algorithm 1: predicted samples, exactly checked edges, rounds of |S|;
and so is planning without it (Table 3's "without" is the paper's baseline,
``toolkit.prm.PAPER_BASELINE``).

Settings the paper leaves unstated, and ours: MLP 200 epochs of batch 100; CAE as
above; He initialization (:class:`~toolkit.models.CAE`); inputs unscaled (``z`` and
``q`` as they come); threshold 0.5. They were set by hand, not yet chosen by
validation on held-out training workspaces (``docs/fidelity.md`` says what that
would take). The CAE loss: Eq. (1)'s squared norm summed over the cells
(``cae_loss="sum"``), not §IV-B1's "mean square error" (``"mean"``,
:meth:`~toolkit.models.CAE.loss` sets out both readings): Eq. (1) is the paper's
one formula, and measured on 2DS (30 grids) the two readings memorize alike (unseen
reconstruction 86.8 % / 88.0 %, all free 87.6 %; ``toolkit ablate``, rows 0 and 1).

``strong``: its CAE trains on 2000 generated grids (``cae_workspaces``; AdamW 1e-3,
batch 100, 2500 steps, Eq. (1)'s sum): it no longer memorizes (2DS unseen
reconstruction 93.3 %, all free 87.6 %; with the mean reading 92.7 %). 3DC and 3DO
cap its learning rate at 1e-4 (``Scenario.cae_max_lr``: the 3DC CAE diverges at 1e-3;
at 1e-4 it matches "all free", 91.2 %). The MLP sees ``[patch, pose]`` (see
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
  first layer is a per-workspace table (:class:`~toolkit.models.WorkspaceMargin`),
  so a prediction costs a gather, the pose's product and two small layers.
- 20x the paper's labelled samples, 10 epochs, AdamW at 3e-3 with weight decay 1e-4 and a
  cosine schedule, batch 256, inputs standardized (folded into the first layer),
  threshold calibrated on 10 % held-out training workspaces. 20 epochs: 3DC-9 94.0
  instead of 93.7, for twice the MLP's training time.
- planning with it screens edges by prediction too (``screen_edges``, the paper's
  future work; see :mod:`toolkit.prm`): only the candidate path's edges are checked
  exactly; and sampling rounds after the first sample with prediction confirmed by
  the exact checker, every fourth of them exactly (``auxiliary="confirmed"``,
  ``exact_every=4``; the paper preset samples every later round exactly: with its
  near-chance networks, confirmed rounds yield few samples). Every fourth rather than
  every second: 100 queries, sampling with / without prediction (means), BT 3DO
  0.31-0.34 -> 0.16-0.17, 3DC-9 0.32 -> 0.26, OB 3DC-9 0.22 -> 0.14, with about as
  many rounds (3DO BT 203 -> 205, 3DC-9 OB 138 -> 136) and every query solved; 3DC-7
  queries rarely need a third round (no change).
- planning without the model is the best exact planner (``toolkit.prm``: lazy edges,
  rounds that double from a small first one), with the same laziness and rounds as
  with it: only the checker differs, so the with / without ratios measure prediction,
  not laziness.
- no ``z``: once the MLP sees the patch, the CAE's latent adds nothing (unseen
  accuracy with / without ``z``: 2DS 99.5 / 99.7, 3DC-7 95.1 / 95.5), and the CAE
  reconstructs unseen workspaces no better than "all free" (3DC: 89.7 vs 91.2), so
  ``z`` of an unseen workspace is noise to the MLP. So ``toolkit train`` leaves its
  CAE untrained unless asked (``--cae``); ``toolkit reproduce`` trains it, for Table 1.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from .prm import PAPER_BASELINE


@dataclass(frozen=True)
class Preset:
    """Every setting of one training recipe."""

    name: str
    encoding: str  # MLP input: "raw" = [z, q] (paper), "local" = [z, patch, pose] (see toolkit.encoding)
    optimizer: str  # "adagrad" or "adamw", for the MLP
    lr: float
    cae_optimizer: str
    cae_lr: float
    dropout: float
    cae_lambda: float  # lambda of Eq. (1)
    cae_epochs: int
    cae_batch: int
    cae_max_steps: int  # caps cae_epochs (a scenario may cap lower: Scenario.cae_max_steps)
    mlp_epochs: int
    mlp_batch: int
    mlp_hidden: tuple[int, ...] | None = None  # None: the paper's widths for the scenario
    cae_loss: str = "sum"  # reconstruction error over the cells: "sum" (Eq. (1)) or "mean" (§IV-B1's MSE); see CAE.loss
    cae_workspaces: int = 0  # the CAE trains on this many generated grids (0: the training split's, the paper)
    n_seen: int | None = None  # training workspaces (None: the paper's, Scenario.n_seen)
    samples_factor: int = 1  # labelled samples per workspace = factor x the paper's
    weight_decay: float = 0.0  # the MLP's optimizer (the CAE's penalty is Eq. (1)'s lambda)
    cosine_schedule: bool = False  # the MLP's learning rate decays to 0 along a cosine
    standardize: bool = False  # MLP inputs scaled to zero mean, unit variance on the training data
    holdout: float = 0.0  # share of training workspaces kept from the MLP to calibrate its threshold
    latent_input: bool = True  # the MLP sees the CAE's z (the paper); False: only the patch and pose
    screen_edges: bool = False  # planning with this model: learned edge screening (toolkit.prm), or the paper's exact edges
    auxiliary: str = "exact"  # planning with this model: how rounds after the first sample (toolkit.prm.AUXILIARY)
    exact_every: int = 4  # planning with this model, auxiliary "confirmed": how often a later round samples exactly
    paper_baseline: bool = False  # planning, with and without this model: the paper's rounds and edges (prm.PAPER_BASELINE)
    quick: bool = False  # shrunk by quick_version()

    def planner_options(self) -> dict:
        """The :class:`~toolkit.prm.PRMOptions` that planning with this model uses."""
        options = {"screen_edges": self.screen_edges, "auxiliary": self.auxiliary, "exact_every": self.exact_every}
        return {**options, **(PAPER_BASELINE if self.paper_baseline else {})}

    def quick_version(self) -> "Preset":
        """The same recipe with few epochs and samples: a whole scenario in seconds (tests, ``--quick``)."""
        if self.quick:
            return self
        return replace(self, quick=True, cae_epochs=max(1, self.cae_epochs // 50), mlp_epochs=max(2, self.mlp_epochs // 10),
                       samples_factor=min(self.samples_factor, 4), cae_workspaces=min(self.cae_workspaces, 40),
                       cae_max_steps=min(self.cae_max_steps, 20))


PRESETS: dict[str, Preset] = {
    "paper": Preset("paper", encoding="raw", optimizer="adagrad", lr=0.1,
                    cae_optimizer="adamw", cae_lr=1e-4, dropout=0.5, cae_lambda=1e-3,
                    cae_epochs=500, cae_batch=10, cae_max_steps=1500, mlp_epochs=200, mlp_batch=100,
                    paper_baseline=True),
    "strong": Preset("strong", encoding="local", optimizer="adamw", lr=3e-3,
                     cae_optimizer="adamw", cae_lr=1e-3, dropout=0.0, cae_lambda=1e-3, cae_workspaces=2000,
                     cae_epochs=10_000, cae_batch=100, cae_max_steps=2500, mlp_epochs=10, mlp_batch=256, mlp_hidden=(64, 32),
                     samples_factor=20, weight_decay=1e-4, cosine_schedule=True, standardize=True, holdout=0.1,
                     latent_input=False, screen_edges=True, auxiliary="confirmed"),
}

# Quick runs also use fewer workspaces than the paper (seen, seen-test, unseen).
QUICK_WORKSPACES = (8, 4, 4)


def get(name: str) -> Preset:
    """The preset called ``name`` ('paper' or 'strong')."""
    try:
        return PRESETS[name]
    except KeyError:
        raise ValueError(f"unknown preset {name!r}; choose one of {sorted(PRESETS)}") from None
