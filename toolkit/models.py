"""The two networks of the paper (§III-A, §V-B) and the input encoding of the MLP.

- :class:`CAE`: the contractive autoencoder. Linear layers with PReLU, the decoder
  mirrors the encoder; loss = Eq. (1), reconstruction error plus
  ``lambda * sum(W_e ** 2)`` over the *encoder's* weights, a penalty that really
  reaches the gradients (it is computed from the parameters themselves).
- :class:`CollisionMLP`: ``[z, q] -> 2`` logits (invalid, valid), hidden blocks of
  Linear -> PReLU -> Dropout(p) (§V-B2).
- :class:`~toolkit.encoding.InputEncoding` (in :mod:`toolkit.encoding`): what the MLP
  sees, the paper's ``[z, q]`` or ``[z, patch, pose]`` (the ``strong`` preset leaves out ``z``).
- :class:`CollisionPredictor`: the three together, one ``state_dict``;
  :meth:`~CollisionPredictor.for_workspace` freezes it in one workspace as a
  :class:`WorkspaceMargin`, the fast inference path of the learned checker.
"""

from __future__ import annotations

import numpy as np
import torch
from torch import nn

from .encoding import InputEncoding, reach_cells
from .scenarios import Scenario

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
    """Contractive autoencoder of flattened occupancy grids (§III-A1, §V-B1).

    ``sizes`` = (input, hidden..., latent), e.g. 2DS (961, 512, 256, 128, 64, 32, 12).

    Weights start with He initialization for PReLU (He et al. 2015; the paper names
    none). PyTorch's default shrinks the signal's variance about threefold per layer,
    so through 7-14 layers the latent hardly depends on the input and the CAE settles
    on the mean grid: measured on 3DC, 91.2 % reconstruction accuracy on seen
    workspaces, exactly the all-free share, against 100 % with He initialization.
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
        return sum((layer.weight ** 2).sum() for layer in self.encoder if isinstance(layer, nn.Linear))

    def loss(self, grids: torch.Tensor, lam: float) -> torch.Tensor:
        """Eq. (1): mean over workspaces of ``||x - g(f(x))||^2``, plus ``lam * sum (W^e)^2``."""
        error = ((self(grids) - grids) ** 2).reshape(len(grids), -1).sum(dim=1).mean()
        return error + lam * self.encoder_weight_penalty()


class CollisionMLP(nn.Module):
    """Validity classifier (§III-A2, §V-B2): Linear -> PReLU -> Dropout(p) blocks, then 2 logits (no Dropout when p = 0)."""

    def __init__(self, in_features: int, hidden: tuple[int, ...], dropout: float):
        super().__init__()
        if not 0.0 <= dropout < 1.0:
            raise ValueError(f"dropout must lie in [0, 1), got {dropout}")
        if not hidden:
            raise ValueError("the collision MLP needs at least one hidden layer")
        layers: list[nn.Module] = []
        for a, b in zip((in_features,) + tuple(hidden[:-1]), hidden):
            layers += [nn.Linear(a, b), nn.PReLU()] + ([nn.Dropout(dropout)] if dropout > 0 else [])
        layers.append(nn.Linear(hidden[-1], 2))
        self.net = nn.Sequential(*layers)
        self.in_features, self.hidden, self.dropout = int(in_features), tuple(hidden), float(dropout)

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        """Logits ``(N, 2)`` (invalid, valid) of inputs ``(N, in_features)``."""
        return self.net(x)

    @torch.no_grad()
    def fold_standardization(self, mean: torch.Tensor, std: torch.Tensor) -> None:
        """Make a network trained on ``(x - mean) / std`` take ``x`` itself (rescales the first layer)."""
        first = self.net[0]
        first.weight.div_(std)
        first.bias.sub_(first.weight @ mean)


class CollisionPredictor(nn.Module):
    """CAE + input encoding + MLP, with the decision ``threshold`` on P(valid) kept as a buffer."""

    def __init__(self, cae: CAE, encoding: InputEncoding, mlp: CollisionMLP, threshold: float = 0.5):
        super().__init__()
        self.cae, self.encoding, self.mlp = cae, encoding, mlp
        self.register_buffer("threshold", torch.tensor(float(threshold)))

    def for_workspace(self, grid: torch.Tensor) -> "WorkspaceMargin":
        """This predictor, frozen for fast inference in the workspace ``grid (*grid)``: Algorithm 1, line 1."""
        return WorkspaceMargin(self, grid)


class WorkspaceMargin:
    """``margin(Q) = logit(valid) - logit(invalid)`` of a :class:`CollisionPredictor` in one workspace, for inference.

    Equal to the full network's logit difference (a test holds it to it), computed with
    fewer, cheaper operations:

    - everything the workspace gives the first layer (its bias, ``W z``, ``W patch`` of
      every base cell) is one table ``(n_cells, H)``, built once, so a prediction gathers
      one row and multiplies only the pose;
    - only the difference of the two logits matters, so the last layer is one vector;
    - activations are column-major ``(features, N)``: the small matmuls of these MLPs
      run about 1.5x faster that way on CPU than row-major (measured: the paper's
      3D MLP at 10k configurations, one thread, 1.3 ms against 2.0 ms);
    - on the CPU it computes in numpy: a sampler's call holds a few hundred
      configurations, where the cost per operation dominates, and numpy's is about
      half of torch's (strong 3DC-7 model, 400 configurations right after an exact
      check: 0.4 ms against 0.9 ms a call); at 10k it is about as fast as torch
      was (the paper's 3DC-9 MLP, one thread: 3.6M configurations/s); batches go
      in chunks of ``CHUNK``, whose temporaries stay in cache;
    - the PReLU slopes are read once. Dropout is off, as in ``eval()``.

    A snapshot: training the predictor further does not change it.
    """

    CHUNK = 4096  # configurations per pass

    @torch.no_grad()
    def __init__(self, predictor: CollisionPredictor, grid: torch.Tensor, numpy: bool | None = None):
        """``numpy``: compute in numpy (default: when ``grid`` is on the CPU) or in torch on ``grid``'s device."""
        encoding, net = predictor.encoding, predictor.mlp.net
        grids = grid[None]  # (1, *grid)
        first = net[0]
        L, P = encoding.latent_dim, encoding.patch_size
        share = first.bias.clone()  # (H,)
        if L:
            share += first.weight[:, :L] @ predictor.cae.encode(grids)[0, :L]
        patches = encoding.cell_patches(grids)[0]  # (n_cells, P)
        linears = [m for m in net if isinstance(m, nn.Linear)]
        slopes = [float(m.weight) for m in net if isinstance(m, nn.PReLU)]  # one after each hidden layer
        last = linears[-1]
        self.encoding, self.device, self.slopes = encoding, grid.device, slopes
        self.numpy = self.device.type == "cpu" if numpy is None else bool(numpy)
        arrays = [patches @ first.weight[:, L:L + P].T + share,  # (n_cells, H): rows gather fast
                  first.weight[:, L + P:],  # (H, pose_size)
                  last.weight[VALID] - last.weight[1 - VALID]]  # (H_last,)
        arrays += [a for m in linears[1:-1] for a in (m.weight, m.bias[:, None])]
        arrays = [a.cpu().numpy().copy() if self.numpy else a.clone() for a in arrays]
        self.table, self.pose_weight, self.last_weight = arrays[:3]
        self.hidden = list(zip(arrays[3::2], arrays[4::2]))  # (weight, bias (H_next, 1)) of each hidden layer
        self.last_bias = float(last.bias[VALID] - last.bias[1 - VALID])

    def __call__(self, Q: np.ndarray) -> np.ndarray:
        """Margins ``(N,)`` float32 of configurations ``Q (N, dof)`` (computed on the predictor's device)."""
        margins = []
        for start in range(0, max(len(Q), 1), self.CHUNK):
            q = Q[start:start + self.CHUNK]
            if self.numpy:
                margins.append(self._margins(q))
            else:
                margins.append(self._margins(torch.as_tensor(q, dtype=torch.float32, device=self.device)).cpu().numpy())
        return np.concatenate(margins)

    def _margins(self, Q):
        """One chunk, as arrays or tensors."""
        xp = np if isinstance(Q, np.ndarray) else torch
        with torch.inference_mode():
            cell, pose = self.encoding.configs(Q)  # (N,), (pose_size, N)
            h = self.pose_weight @ pose  # (H, N)
            h += self.table[cell].T
            _prelu_(xp, h, self.slopes[0])
            for (weight, bias), slope in zip(self.hidden, self.slopes[1:]):
                h = weight @ h  # (H_next, N)
                h += bias
                _prelu_(xp, h, slope)
            return self.last_weight @ h + self.last_bias  # (N,)


def _prelu_(xp, h, slope: float) -> None:
    """PReLU in place, for arrays or tensors: the larger of ``h`` and ``slope * h`` (the smaller if slope > 1)."""
    (xp.maximum if slope <= 1 else xp.minimum)(h, slope * h, out=h)


def build_predictor(scenario: Scenario, encoding: str, mlp_hidden: tuple[int, ...] | None = None,
                    dropout: float = 0.5, latent_input: bool = True) -> CollisionPredictor:
    """Untrained networks of the paper's sizes for ``scenario`` (``mlp_hidden`` may override the MLP's;
    ``latent_input=False``: the MLP does not see ``z``)."""
    cae = CAE((scenario.grid_size,) + tuple(scenario.cae_hidden))
    radius = reach_cells(scenario.robot) if encoding == "local" else 0
    enc = InputEncoding(scenario.robot, scenario.grid_shape, cae.latent_dim if latent_input else 0, encoding, radius)
    mlp = CollisionMLP(enc.out_features, tuple(mlp_hidden or scenario.mlp_hidden), dropout)
    return CollisionPredictor(cae, enc, mlp)
