"""The networks: the paper's sizes, the CAE loss of Eq. (1) and its gradient, the MLP's input encoding."""

import numpy as np
import pytest
import torch
from torch import nn

from toolkit import scenarios
from toolkit.models import CAE, CollisionMLP, InputEncoding, build_predictor, reach_cells
from toolkit.workspace import Workspace

PAPER_CAE = {
    "2ds": (961, 512, 256, 128, 64, 32, 12),
    "3do": (10086, 5043, 3125, 1600, 800, 400, 200, 100, 50),
    "3dc7": (1331, 1000, 800, 600, 400, 200, 100, 50),
    "3dc9": (1331, 1000, 800, 600, 400, 200, 100, 50),
}
PAPER_MLP = {"2ds": (14, 6, 4, 2), "3do": (58, 50, 40, 30, 20, 10, 5, 2),
             "3dc7": (57, 50, 40, 30, 20, 10, 5, 2), "3dc9": (59, 50, 40, 30, 20, 10, 5, 2)}


def _widths(seq: nn.Sequential) -> tuple[int, ...]:
    linears = [m for m in seq if isinstance(m, nn.Linear)]
    return (linears[0].in_features,) + tuple(m.out_features for m in linears)


@pytest.mark.parametrize("name", sorted(PAPER_CAE))
def test_paper_sizes(name):
    with torch.device("meta"):  # the 3DO CAE has 147M parameters: shapes only
        predictor = build_predictor(scenarios.get(name), "raw")
    assert _widths(predictor.cae.encoder) == PAPER_CAE[name]
    assert _widths(predictor.cae.decoder) == PAPER_CAE[name][::-1]
    assert _widths(predictor.mlp.net) == PAPER_MLP[name]
    assert sum(isinstance(m, nn.PReLU) for m in predictor.cae.encoder) == len(PAPER_CAE[name]) - 2
    drops = [m.p for m in predictor.mlp.net if isinstance(m, nn.Dropout)]
    assert drops == [0.5] * (len(PAPER_MLP[name]) - 2)


def test_3do_cae_has_147m_parameters():
    with torch.device("meta"):
        cae = CAE(PAPER_CAE["3do"])
    assert sum(p.numel() for p in cae.parameters()) == 146_688_832


def test_cae_loss_is_eq1():
    torch.manual_seed(0)
    cae = CAE((6, 4, 2))
    x = torch.sign(torch.randn(3, 2, 3))
    rec = cae(x)
    error = ((rec - x) ** 2).sum(dim=(1, 2)).mean()
    penalty = (cae.encoder[0].weight ** 2).sum() + (cae.encoder[2].weight ** 2).sum()
    assert torch.allclose(cae.loss(x, 0.25), error + 0.25 * penalty)


def test_penalty_reaches_only_encoder_gradients():
    torch.manual_seed(0)
    cae = CAE((961, 64, 12))
    x = torch.sign(torch.randn(4, 31, 31))
    grads = {}
    for lam in (0.0, 1e-3):
        cae.zero_grad()
        cae.loss(x, lam).backward()
        grads[lam] = {n: p.grad.clone() for n, p in cae.named_parameters()}
    for name, param in cae.named_parameters():
        difference = grads[1e-3][name] - grads[0.0][name]
        if name.startswith("encoder") and name.endswith("weight") and param.dim() == 2:
            assert torch.allclose(difference, 2e-3 * param, atol=1e-6)  # d/dW of lambda * W^2
            assert difference.abs().max() > 0
        else:
            assert torch.allclose(difference, torch.zeros_like(difference), atol=1e-6), name


def test_mlp_rejects_bad_dropout():
    with pytest.raises(ValueError, match="dropout"):
        CollisionMLP(4, (3,), dropout=1.0)


def test_unknown_encoding():
    s = scenarios.get("2ds")
    with pytest.raises(ValueError, match="input encoding"):
        InputEncoding(s.robot, s.grid_shape, 12, "fancy")


def test_reach_cells_of_the_robots():
    assert [reach_cells(scenarios.get(n).robot) for n in ("2ds", "3do", "3dc7", "3dc9")] == [1, 2, 1, 2]


def test_local_encoding_reads_the_grid_around_the_base():
    s = scenarios.get("2ds")
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10.0, 20.0], [12.0, 21.0]]]))
    enc = InputEncoding(s.robot, s.grid_shape, latent_dim=1, kind="local", radius=1)
    grid = torch.as_tensor(ws.occupancy())[None]
    Q = torch.tensor([[11.2, 19.7], [0.3, 30.6]])  # next to the block; in the corner
    x = enc(torch.zeros(1, 1), enc.pad(grid), torch.zeros(2, dtype=torch.long), Q)
    patch = x[:, 1:10].reshape(2, 3, 3)
    expected = -torch.ones(3, 3)
    expected[:2, 2] = 1.0  # base cell (11, 19); the block covers cells x = 10, 11 at y = 20
    assert torch.equal(patch[0], expected)
    assert torch.equal(patch[1][0], torch.ones(3)) and torch.equal(patch[1][:, 2], torch.ones(3))  # outside = occupied
    assert torch.allclose(x[:, 10:12], torch.tensor([[0.2 - 0.5, 0.7 - 0.5], [0.3 - 0.5, 0.6 - 0.5]]), atol=1e-5)


def test_local_encoding_of_angles_and_joints():
    s = scenarios.get("3dc7")
    enc = InputEncoding(s.robot, s.grid_shape, latent_dim=2, kind="local", radius=1)
    q = torch.tensor([[5.5, 5.5, 5.5, np.pi / 2, 0.0, -np.pi / 2, 2.0]], dtype=torch.float32)
    grid = -torch.ones(1, 11, 11, 11)
    x = enc(torch.zeros(1, 2), enc.pad(grid), torch.zeros(1, dtype=torch.long), q)[0]
    assert x.shape == (enc.out_features,) == (2 + 27 + 3 + 6 + 1,)
    assert torch.allclose(x[-7:], torch.tensor([1.0, 0.0, -1.0, 0.0, 1.0, 0.0, 1.0]), atol=1e-6)  # sin, cos, joint


@pytest.mark.parametrize("kind", ["raw", "local"])
def test_logits_shortcut_equals_the_full_network(kind, rng):
    s = scenarios.get("3dc9")
    torch.manual_seed(0)
    predictor = build_predictor(s, kind).eval()
    grids = torch.as_tensor(np.stack([s.make_workspace(rng).occupancy() for _ in range(2)]))
    Q = torch.as_tensor(s.robot.sample(rng, 50), dtype=torch.float32)
    ws_index = torch.as_tensor(rng.integers(0, 2, 50))
    with torch.no_grad():
        context = predictor.context(grids)
        z, padded, _ = context
        full = predictor.mlp(predictor.encoding(z, padded, ws_index, Q))
        assert torch.allclose(predictor.logits(context, ws_index, Q), full, atol=1e-5)
        one = predictor.context(grids[:1])  # a single workspace broadcasts its share instead of gathering it
        assert torch.allclose(predictor.logits(one, torch.zeros(50, dtype=torch.long), Q),
                              predictor.mlp(predictor.encoding(z[:1], padded[:1], torch.zeros(50, dtype=torch.long), Q)), atol=1e-5)


def test_fold_standardization():
    torch.manual_seed(0)
    mlp = CollisionMLP(5, (8, 4), dropout=0.0).eval()
    x, mean, std = torch.randn(20, 5) * 3 + 1, torch.randn(5), torch.rand(5) + 0.5
    expected = mlp((x - mean) / std)
    mlp.fold_standardization(mean, std)
    assert torch.allclose(mlp(x), expected, atol=1e-5)
