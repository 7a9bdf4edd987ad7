"""The two networks of the paper (§III-A, §V-B) and the input encoding of the MLP.

- :class:`CAE`: the contractive autoencoder. Linear layers with PReLU, the decoder
  mirrors the encoder; loss = Eq. (1), reconstruction error plus
  ``lambda * sum(W_e ** 2)`` over the *encoder's* weights, a penalty that really
  reaches the gradients (it is computed from the parameters themselves).
- :class:`CollisionMLP`: ``[z, q] -> 2`` logits (invalid, valid), hidden blocks of
  Linear -> PReLU -> Dropout(p) (§V-B2).
- :class:`InputEncoding`: what the MLP sees. ``"raw"`` is the paper's ``[z, q]``;
  ``"local"`` (the ``strong`` preset) is ``[z, local occupancy, encoded q]``: the
  grid cells the robot can reach from its base cell, the base's position inside its
  cell, sin/cos of the angles that wrap and the joints scaled to [-1, 1].
- :class:`CollisionPredictor`: the three together, one ``state_dict``.
"""

from __future__ import annotations

import math

import numpy as np
import torch
from torch import nn

from .robots import BoxRobot
from .scenarios import Scenario

VALID = 1  # class index of "valid" in the MLP's two logits


def _stack(widths: list[int], last_activation: bool) -> nn.Sequential:
    """Linear layers ``widths[0] -> widths[1] -> ...``, PReLU after each but (optionally) the last."""
    layers: list[nn.Module] = []
    for i, (a, b) in enumerate(zip(widths[:-1], widths[1:])):
        layers.append(nn.Linear(a, b))
        if last_activation or i < len(widths) - 2:
            layers.append(nn.PReLU())
    return nn.Sequential(*layers)


class CAE(nn.Module):
    """Contractive autoencoder of flattened occupancy grids (§III-A1, §V-B1).

    ``sizes`` = (input, hidden..., latent), e.g. 2DS (961, 512, 256, 128, 64, 32, 12).
    """

    def __init__(self, sizes: tuple[int, ...]):
        super().__init__()
        if len(sizes) < 2:
            raise ValueError(f"a CAE needs an input and a latent size, got {sizes}")
        self.sizes = tuple(int(s) for s in sizes)
        self.encoder = _stack(list(self.sizes), last_activation=False)
        self.decoder = _stack(list(reversed(self.sizes)), last_activation=False)

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
    """Validity classifier (§III-A2, §V-B2): Linear -> PReLU -> Dropout(p) blocks, then 2 logits."""

    def __init__(self, in_features: int, hidden: tuple[int, ...], dropout: float):
        super().__init__()
        if not 0.0 <= dropout < 1.0:
            raise ValueError(f"dropout must lie in [0, 1), got {dropout}")
        layers: list[nn.Module] = []
        for a, b in zip((in_features,) + tuple(hidden[:-1]), hidden):
            layers += [nn.Linear(a, b), nn.PReLU(), nn.Dropout(dropout)]
        layers.append(nn.Linear(hidden[-1] if hidden else in_features, 2))
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


def reach_cells(robot: BoxRobot, samples: int = 20_000) -> int:
    """How many unit cells from its base cell the robot can reach, along the base's position axes.

    Measured from the links' axis-aligned bounds over a fixed sample of configurations.
    """
    Q = robot.sample(np.random.default_rng(0), samples)
    aabbs = robot.link_aabbs(Q)  # (N, L, 2, D)
    n_pos = position_dofs(robot)
    reach = np.abs(aabbs[..., :n_pos] - Q[:, None, None, :n_pos]).max()
    return int(math.ceil(reach))


def position_dofs(robot: BoxRobot) -> int:
    """How many leading DoFs are base positions: 2 for the point robot and the youBot, 3 for the chains."""
    return int(np.argmax(robot.wraps)) if robot.wraps.any() else robot.dof


class InputEncoding(nn.Module):
    """Turns workspace context and configurations into MLP inputs.

    ``kind="raw"``: ``[z, q]`` (the paper). ``kind="local"``: ``[z, patch, position in
    cell, sin/cos(angles), scaled joints]``; the patch is the occupancy of the
    ``(2r+1)`` cells around the base cell along each position axis (the whole extent
    of the other grid axes, e.g. the office's height), grids padded with "occupied"
    so leaving the workspace reads as an obstacle.
    """

    def __init__(self, robot: BoxRobot, grid_shape: tuple[int, ...], latent_dim: int, kind: str, radius: int = 0):
        super().__init__()
        if kind not in ("raw", "local"):
            raise ValueError(f"unknown input encoding {kind!r}; choose 'raw' or 'local'")
        self.kind, self.radius, self.grid_shape = kind, int(radius), tuple(grid_shape)
        self.n_pos = position_dofs(robot)
        self.register_buffer("lower", torch.tensor(np.array(robot.lower), dtype=torch.float32))
        self.register_buffer("upper", torch.tensor(np.array(robot.upper), dtype=torch.float32))
        self.register_buffer("wraps", torch.tensor(np.array(robot.wraps)))
        window = [torch.arange(-self.radius, self.radius + 1)] * self.n_pos
        window += [torch.arange(n) for n in self.grid_shape[self.n_pos:]]
        offsets = torch.stack(torch.meshgrid(*window, indexing="ij"), dim=-1).reshape(-1, len(self.grid_shape))
        self.register_buffer("offsets", offsets)  # (P, G): cell offsets of the patch
        self.register_buffer("last_cell", torch.tensor(self.grid_shape[: self.n_pos]) - 1)  # (n_pos,)
        n_angles = int(robot.wraps.sum())
        if kind == "raw":
            self.out_features = latent_dim + robot.dof
        else:
            self.out_features = latent_dim + len(offsets) + self.n_pos + 2 * n_angles + (robot.dof - self.n_pos - n_angles)

    def pad(self, grids: torch.Tensor) -> torch.Tensor:
        """Grids ``(W, *grid)`` padded by ``radius`` cells of +1 along the position axes."""
        if self.kind == "raw":
            return grids
        pad: list[int] = []
        for axis in reversed(range(len(self.grid_shape))):  # F.pad lists the last axis first
            pad += [self.radius, self.radius] if axis < self.n_pos else [0, 0]
        return nn.functional.pad(grids, pad, value=1.0)

    def forward(self, z: torch.Tensor, padded: torch.Tensor, ws_index: torch.Tensor, Q: torch.Tensor) -> torch.Tensor:
        """MLP inputs ``(N, out_features)``: latents ``z (W, L)``, padded grids ``(W, *)``, ``ws_index (N,)``, ``Q (N, dof)``."""
        return torch.cat([z[ws_index], self.config_features(padded, ws_index, Q)], dim=1)

    def config_features(self, padded: torch.Tensor, ws_index: torch.Tensor, Q: torch.Tensor) -> torch.Tensor:
        """The inputs after ``z``: ``q`` itself, or ``[patch, position in cell, sin/cos(angles), scaled joints]``."""
        if self.kind == "raw":
            return Q
        position = Q[:, : self.n_pos]  # (N, n_pos); grid cells are unit cubes from the origin
        cell = torch.minimum(torch.floor(position).long().clamp(min=0), self.last_cell)  # (N, n_pos)
        base = torch.zeros(len(Q), len(self.grid_shape), dtype=torch.long, device=Q.device)
        base[:, : self.n_pos] = cell + self.radius  # (N, G) in padded coordinates
        cells = base[:, None, :] + self.offsets  # (N, P, G)
        patch = padded[(ws_index[:, None],) + tuple(cells.unbind(-1))]  # (N, P)
        angles = Q[:, self.wraps]
        joints = Q[:, ~self.wraps][:, self.n_pos:]
        lo, hi = self.lower[~self.wraps][self.n_pos:], self.upper[~self.wraps][self.n_pos:]
        return torch.cat([patch, position - cell - 0.5, torch.sin(angles), torch.cos(angles),
                          2 * (joints - lo) / (hi - lo) - 1], dim=1)


class CollisionPredictor(nn.Module):
    """CAE + input encoding + MLP, with the decision ``threshold`` on P(valid) kept as a buffer."""

    def __init__(self, cae: CAE, encoding: InputEncoding, mlp: CollisionMLP, threshold: float = 0.5):
        super().__init__()
        self.cae, self.encoding, self.mlp = cae, encoding, mlp
        self.register_buffer("threshold", torch.tensor(float(threshold)))

    def context(self, grids: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor, torch.Tensor]:
        """What a workspace contributes, computed once: latents ``z (W, L)``, padded grids, and the
        first MLP layer's share of ``z`` plus its bias, ``(W, H)``."""
        z = self.cae.encode(grids)
        first = self.mlp.net[0]
        return z, self.encoding.pad(grids), z @ first.weight[:, : z.shape[1]].T + first.bias

    def logits(self, context: tuple[torch.Tensor, torch.Tensor, torch.Tensor], ws_index: torch.Tensor,
               Q: torch.Tensor) -> torch.Tensor:
        """Logits ``(N, 2)`` for configurations ``Q (N, dof)`` in workspaces ``ws_index (N,)``.

        Equal to ``mlp(encoding(...))``, but the first layer's share of ``z`` comes from the
        context (once per workspace, not once per configuration).
        """
        z, padded, share = context
        first = self.mlp.net[0]
        h = self.encoding.config_features(padded, ws_index, Q) @ first.weight[:, z.shape[1]:].T  # (N, H)
        h = h + (share if len(share) == 1 else share[ws_index])  # one workspace: broadcast, no gather
        return self.mlp.net[1:](h)


def build_predictor(scenario: Scenario, encoding: str, mlp_hidden: tuple[int, ...] | None = None,
                    dropout: float = 0.5) -> CollisionPredictor:
    """Untrained networks of the paper's sizes for ``scenario`` (``mlp_hidden`` may override the MLP's)."""
    cae = CAE((scenario.grid_size,) + tuple(scenario.cae_hidden))
    radius = reach_cells(scenario.robot) if encoding == "local" else 0
    enc = InputEncoding(scenario.robot, scenario.grid_shape, cae.latent_dim, encoding, radius)
    mlp = CollisionMLP(enc.out_features, tuple(mlp_hidden or scenario.mlp_hidden), dropout)
    return CollisionPredictor(cae, enc, mlp)
