"""The two networks of the paper (§III-A, §IV-B) and the input encoding of the MLP.

- :class:`CAE`: the contractive autoencoder. Linear layers with PReLU, the decoder
  mirrors the encoder; loss = Eq. (1), reconstruction error (summed or averaged over
  the cells: :meth:`CAE.loss` argues both readings) plus ``lambda * sum(W_e ** 2)``
  over the *encoder's* weights, a penalty that really reaches the gradients (it is
  computed from the parameters themselves; MPNet's code takes them from
  ``state_dict()``, detached, so there it changes the loss but not the training).
- :class:`CollisionMLP`: ``[z, q] -> 2`` logits (invalid, valid), hidden blocks of
  Linear -> PReLU -> Dropout(p) (§IV-B2).
- :class:`~toolkit.learning.encoding.InputEncoding` (in :mod:`toolkit.learning.encoding`): what the MLP
  sees, the paper's ``[z, q]`` or ``[z, patch, pose]`` (the ``strong`` preset leaves out ``z``).
- :class:`CollisionPredictor`: the three together, one ``state_dict``.
  :class:`toolkit.learning.inference.WorkspaceMLP` folds one workspace into its MLP:
  the learned checker's fast inference path.
"""

from __future__ import annotations

import torch
from torch import nn

from toolkit.learning.encoding import InputEncoding, reach_cells
from toolkit.scenarios import Scenario

CAE_LOSSES = ("sum", "mean")  # CAE.loss's readings of the reconstruction error: Eq. (1)'s, §IV-B1's
MLP_INITS = ("torch", "he")  # CollisionMLP's initial weights: PyTorch's default, He's

VALID = 1  # class index of "valid" in the MLP's two logits
PRELU_SLOPE = 0.25  # nn.PReLU's initial negative slope


def _stack(widths: list[int], last_activation: bool) -> nn.Sequential:
    """Linear layers ``widths[0] -> widths[1] -> ...``, PReLU after each but (optionally) the last."""
    layers: list[nn.Module] = []
    for i, (a, b) in enumerate(zip(widths[:-1], widths[1:])):
        layers.append(nn.Linear(a, b))
        if last_activation or i < len(widths) - 2:
            layers.append(nn.PReLU())
    return nn.Sequential(*layers)


def he_init(module: nn.Module) -> None:
    """He initialization for PReLU (He et al. 2015) of every linear layer in ``module``; zero biases."""
    for layer in module.modules():
        if isinstance(layer, nn.Linear):
            nn.init.kaiming_normal_(layer.weight, a=PRELU_SLOPE, nonlinearity="leaky_relu")
            nn.init.zeros_(layer.bias)


class CAE(nn.Module):
    """Contractive autoencoder of flattened occupancy grids (§III-A1, §IV-B1).

    ``sizes`` = (input, hidden..., latent), e.g. 2DS (961, 512, 256, 128, 64, 32, 12).

    Weights start with He initialization for PReLU (He et al. 2015; the paper names
    none). PyTorch's default shrinks the signal's variance about threefold per layer,
    so through 7-14 layers the latent hardly depends on the input and the CAE settles
    on the mean grid, all free, even on the grids it trains on (``docs/design.md``,
    "The presets", has the measurement).
    """

    def __init__(self, sizes: tuple[int, ...]):
        super().__init__()
        if len(sizes) < 2:
            raise ValueError(f"a CAE needs an input and a latent size, got {sizes}")
        self.sizes = tuple(int(s) for s in sizes)
        self.encoder = _stack(list(self.sizes), last_activation=False)
        self.decoder = _stack(list(reversed(self.sizes)), last_activation=False)
        he_init(self)

    @property
    def latent_dim(self) -> int:
        return self.sizes[-1]

    def encode(self, grids: torch.Tensor) -> torch.Tensor:
        """Latent codes ``(W, latent)`` of grids ``(W, *grid)``."""
        return self.encoder(grids.reshape(len(grids), -1))

    def forward(self, grids: torch.Tensor) -> torch.Tensor:
        """Reconstructions ``(W, *grid)`` of grids ``(W, *grid)``."""
        return self.decoder(self.encode(grids)).reshape(grids.shape)

    def encoder_weight_penalty(self) -> torch.Tensor:
        """``sum_ij (W^e_ij)^2`` over the encoder's linear weights (biases and PReLU slopes excluded)."""
        penalties = [(layer.weight**2).sum() for layer in self.encoder if isinstance(layer, nn.Linear)]  # per layer
        return sum(penalties[1:], start=penalties[0])

    def loss(self, grids: torch.Tensor, lam: float, reduction: str = "sum") -> torch.Tensor:
        """Eq. (1): the reconstruction error of grids ``(W, *grid)`` plus ``lam * sum (W^e)^2``.

        The paper gives the error two ways. Eq. (1) writes ``1/|D| sum_x ||x - g(f(x))||^2``,
        a squared norm, so a *sum* over the cells averaged over the workspaces
        (``reduction="sum"``); §IV-B1 says "for loss function, we use mean square error
        with weight-decay", the *mean* over cells and workspaces (``"mean"``, PyTorch's
        ``nn.MSELoss()``). The CAEs of MPNet (Qureshi et al.), from which this CAE evidently
        comes (PReLU layers, lambda = 1e-3, a weight penalty called contractive), use the
        latter: ``nn.MSELoss()`` plus ``lam * sum W^2``. The two differ by the number of
        cells (961 in 2DS, 1331 in 3DC): under ``"mean"`` the penalty weighs that much more.
        With a linear encoder the penalty is the contractive term of Rifai et al. (2011),
        ``||df/dx||_F^2 = sum W^2``; with PReLU layers it is weight decay of the encoder
        (the paper: "similar to the loss function of a regularized autoencoder").
        """
        squared = (self(grids) - grids) ** 2
        if reduction == "sum":
            error = squared.reshape(len(grids), -1).sum(dim=1).mean()
        elif reduction == "mean":
            error = squared.mean()
        else:
            raise ValueError(f"unknown CAE loss reduction {reduction!r}; choose one of {CAE_LOSSES}")
        return error + lam * self.encoder_weight_penalty()


class CollisionMLP(nn.Module):
    """Validity classifier (§III-A2, §IV-B2): Linear -> PReLU -> Dropout(p) blocks, then 2 logits
    (no Dropout when p = 0).

    ``init``: the paper names no initialization; "torch" keeps PyTorch's default for ``nn.Linear``, "he" uses
    He initialization for PReLU like the CAE (:func:`he_init`). ``toolkit tune`` chooses between them.
    """

    def __init__(self, in_features: int, hidden: tuple[int, ...], dropout: float, init: str = "torch"):
        super().__init__()
        if init not in MLP_INITS:
            raise ValueError(f"unknown MLP initialization {init!r}; choose one of {MLP_INITS}")
        if not 0.0 <= dropout < 1.0:
            raise ValueError(f"dropout must lie in [0, 1), got {dropout}")
        if not hidden:
            raise ValueError("the collision MLP needs at least one hidden layer")
        layers: list[nn.Module] = []
        for a, b in zip((in_features,) + tuple(hidden[:-1]), hidden):
            layers += [nn.Linear(a, b), nn.PReLU()] + ([nn.Dropout(dropout)] if dropout > 0 else [])
        layers.append(nn.Linear(hidden[-1], 2))
        self.net = nn.Sequential(*layers)
        if init == "he":
            he_init(self)
        self.in_features, self.hidden, self.dropout = int(in_features), tuple(hidden), float(dropout)

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        """Logits ``(N, 2)`` (invalid, valid) of inputs ``(N, in_features)``."""
        return self.net(x)

    @property
    def linears(self) -> list[nn.Linear]:
        """The linear layers, first to last: the first takes the inputs, the last gives the logits."""
        return [layer for layer in self.net if isinstance(layer, nn.Linear)]

    @torch.no_grad()
    def fold_standardization(self, mean: torch.Tensor, std: torch.Tensor) -> None:
        """Make a network trained on ``(x - mean) / std`` take ``x`` itself (rescales the first layer)."""
        first = self.linears[0]
        first.weight.div_(std)
        first.bias.sub_(first.weight @ mean)


class CollisionPredictor(nn.Module):
    """CAE + input encoding + MLP, with the decision ``threshold`` on P(valid) kept as a buffer."""

    threshold: torch.Tensor  # () buffer, saved with the weights

    def __init__(self, cae: CAE, encoding: InputEncoding, mlp: CollisionMLP, threshold: float = 0.5):
        super().__init__()
        self.cae, self.encoding, self.mlp = cae, encoding, mlp
        self.register_buffer("threshold", torch.tensor(float(threshold)))


def build_predictor(
    scenario: Scenario,
    encoding: str,
    *,
    mlp_hidden: tuple[int, ...] | None = None,
    dropout: float = 0.5,
    latent_input: bool = True,
    mlp_init: str = "torch",
) -> CollisionPredictor:
    """Untrained networks of the paper's sizes for ``scenario`` (``mlp_hidden`` may override the MLP's;
    ``latent_input=False``: the MLP does not see ``z``; ``mlp_init``: see :class:`CollisionMLP`)."""
    cae = CAE((scenario.grid_size,) + tuple(scenario.cae_hidden))
    radius = reach_cells(scenario.robot) if encoding == "local" else 0
    enc = InputEncoding(scenario.robot, scenario.grid_shape, cae.latent_dim if latent_input else 0, encoding, radius)
    mlp = CollisionMLP(enc.out_features, tuple(mlp_hidden or scenario.mlp_hidden), dropout, mlp_init)
    return CollisionPredictor(cae, enc, mlp)
