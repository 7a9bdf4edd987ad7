"""The networks: the paper's sizes, the CAE loss of Eq. (1) and its gradient, the MLP's input encoding."""

import numpy as np
import pytest
import torch
from torch import nn

from toolkit import scenarios
from toolkit.geometry.workspace import Workspace
from toolkit.learning import metrics
from toolkit.learning.encoding import (
    InputEncoding,
    LinkKinematics,
    reach_cells,
)
from toolkit.learning.inference import WorkspaceMLP
from toolkit.learning.models import (
    CAE,
    VALID,
    CollisionMLP,
    build_predictor,
)

PAPER_CAE = {
    "2ds": (961, 512, 256, 128, 64, 32, 12),
    "3do": (10086, 5043, 3125, 1600, 800, 400, 200, 100, 50),
    "3dc7": (1331, 1000, 800, 600, 400, 200, 100, 50),
    "3dc9": (1331, 1000, 800, 600, 400, 200, 100, 50),
}
PAPER_MLP = {
    "2ds": (14, 6, 4, 2),
    "3do": (58, 50, 40, 30, 20, 10, 5, 2),
    "3dc7": (57, 50, 40, 30, 20, 10, 5, 2),
    "3dc9": (59, 50, 40, 30, 20, 10, 5, 2),
}


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


@pytest.mark.parametrize("reduction", ["sum", "mean"])
def test_cae_loss_and_encoder_gradient_match_an_independent_reference(reduction):
    """With a linear encoder the penalty is Rifai's contractive term ||df/dx||_F^2: computed here from the
    encoder's Jacobian (torch.autograd.functional.jacobian, kept in the graph), the reference loss has the
    same value as ``CAE.loss`` and the same gradient on the encoder's weights, a nonzero one."""
    torch.manual_seed(0)
    cae = CAE((6, 3)).double()  # encoder: one Linear 6 -> 3; decoder: Linear 3 -> 6
    x = torch.sign(torch.randn(4, 2, 3, dtype=torch.float64))
    lam, flat = 0.3, x.reshape(4, 6)
    W, b = cae.encoder[0].weight, cae.encoder[0].bias

    def reference(weight):
        encode = lambda v: v @ weight.T + b  # (6,) -> (3,)
        J = torch.autograd.functional.jacobian(encode, flat[0], create_graph=True)  # (3, 6), the same at every x
        squared = (cae.decoder(encode(flat)) - flat) ** 2  # (4, 6)
        error = squared.sum(dim=1).mean() if reduction == "sum" else squared.mean()
        return error + lam * (J**2).sum()

    expected = reference(W)
    (expected_grad,) = torch.autograd.grad(expected, W)
    loss = cae.loss(x, lam, reduction)
    assert torch.allclose(loss, expected)
    (grad,) = torch.autograd.grad(loss, W)
    assert torch.allclose(grad, expected_grad)
    (penalty_grad,) = torch.autograd.grad(cae.loss(x, lam, reduction) - cae.loss(x, 0.0, reduction), W)
    assert torch.allclose(penalty_grad, 2 * lam * W) and penalty_grad.abs().min() > 0
    # the two readings of §IV-B1 / Eq. (1) differ by the number of cells in the error term
    assert torch.allclose(cae.loss(x, 0.0, "sum"), 6 * cae.loss(x, 0.0, "mean"))
    with pytest.raises(ValueError, match="reduction 'median'"):
        cae.loss(x, lam, "median")


def test_penalty_reaches_only_encoder_gradients():
    torch.manual_seed(0)
    cae = CAE((961, 64, 12)).double()  # float64: gradients of ~1e3 leave float32 rounding of ~1e-5
    x = torch.sign(torch.randn(4, 31, 31, dtype=torch.float64))
    grads = {}
    for lam in (0.0, 1e-3):
        cae.zero_grad()
        cae.loss(x, lam).backward()
        grads[lam] = {n: p.grad.clone() for n, p in cae.named_parameters()}
    for name, param in cae.named_parameters():
        difference = grads[1e-3][name] - grads[0.0][name]
        if name.startswith("encoder") and name.endswith("weight") and param.dim() == 2:
            assert torch.allclose(difference, 2e-3 * param, atol=1e-9)  # d/dW of lambda * W^2
            assert difference.abs().max() > 0
        else:
            assert torch.allclose(difference, torch.zeros_like(difference), atol=1e-9), name


def test_cae_learns_more_than_the_mean_grid():
    """A deep CAE must not settle on the mean grid (all free): on a few 3DC grids it memorizes each one."""
    s = scenarios.get("3dc7")
    rng = np.random.default_rng(0)
    grids = torch.as_tensor(np.stack([s.make_workspace(rng).occupancy() for _ in range(4)]))
    torch.manual_seed(0)
    cae = CAE((s.grid_size,) + s.cae_hidden)
    optimizer = torch.optim.AdamW(cae.parameters(), lr=1e-3)
    for _ in range(150):
        optimizer.zero_grad()
        cae.loss(grids, 1e-3).backward()
        optimizer.step()
    with torch.no_grad():
        accuracy = metrics.reconstruction_accuracy(cae(grids).numpy(), grids.numpy())  # (4,)
    all_free = (grids < 0).float().mean(dim=(1, 2, 3)).numpy()  # about 0.91
    assert np.all(accuracy > all_free + 0.05), (accuracy, all_free)


def test_mlp_rejects_bad_settings():
    with pytest.raises(ValueError, match="dropout"):
        CollisionMLP(4, (3,), dropout=1.0)
    with pytest.raises(ValueError, match="hidden layer"):
        CollisionMLP(4, (), dropout=0.0)


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
    x = enc(torch.zeros(1, 1), grid, torch.zeros(2, dtype=torch.long), Q)
    patch = x[:, 1:10].reshape(2, 3, 3)
    expected = -torch.ones(3, 3)
    expected[:2, 2] = 1.0  # base cell (11, 19); the block covers cells x = 10, 11 at y = 20
    assert torch.equal(patch[0], expected)
    assert torch.equal(patch[1][0], torch.ones(3)) and torch.equal(patch[1][:, 2], torch.ones(3))  # outside = occupied
    assert torch.allclose(x[:, 10:12], torch.tensor([[0.2 - 0.5, 0.7 - 0.5], [0.3 - 0.5, 0.6 - 0.5]]), atol=1e-5)


def test_local_encoding_of_angles_joints_and_links():
    s = scenarios.get("3dc7")
    enc = InputEncoding(s.robot, s.grid_shape, latent_dim=2, kind="local", radius=1)
    q = torch.tensor([[5.5, 5.5, 5.25, np.pi / 2, 0.0, 0.0, 2.0]], dtype=torch.float32)
    grid = -torch.ones(1, 11, 11, 11)
    x = enc(torch.zeros(1, 2), grid, torch.zeros(1, dtype=torch.long), q)[0]
    assert x.shape == (enc.out_features,) == (2 + 27 + 3 + 6 + 1 + 2 * 6,)
    pose = x[2 + 27 :]
    assert torch.allclose(pose[:10], torch.tensor([0.0, 0.0, -0.25, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0]), atol=1e-6)
    # yaw pi/2: the small link (0.1 long) points along +y from the base, the big one turns by joint 2 rad about z
    centers, axes = pose[10:16].reshape(2, 3), pose[16:].reshape(2, 3)
    big = torch.tensor([-np.sin(2.0), np.cos(2.0), 0.0], dtype=torch.float32)  # x axis of the big link
    assert torch.allclose(  # relative to the base cell's centre (5.5, 5.5, 5.5)
        centers, torch.stack([torch.tensor([0.0, 0.05, -0.25]), torch.tensor([0.0, 0.1, -0.25]) + 0.2 * big]), atol=1e-6
    )
    assert torch.allclose(axes, torch.stack([torch.tensor([0.0, 1.0, 0.0]), big]), atol=1e-6)


@pytest.mark.parametrize("name", ["3do", "3dc7", "3dc9"])
def test_link_kinematics_match_the_robot(name, rng):
    robot = scenarios.get(name).robot
    Q = robot.sample(rng, 200)
    n_pos = robot.n_positions
    position = np.pad(Q[:, :n_pos], ((0, 0), (0, 3 - n_pos)), constant_values=robot.base_height)  # (N, 3)
    turns = torch.as_tensor(Q[:, n_pos:].T)  # (R, N): base angles, then joints
    centers, axes = LinkKinematics(robot)(torch.as_tensor(position.T), torch.sin(turns), torch.cos(turns))  # (L, 3, N)
    centers, axes = centers.permute(2, 0, 1), axes.permute(2, 0, 1)  # (N, L, 3)
    expected_centers, rotations, half = robot.link_boxes(Q)
    long_axes = np.stack([rotations[:, i, :, np.argmax(h)] for i, h in enumerate(half)], axis=1)  # (N, L, 3)
    assert np.allclose(centers.numpy(), expected_centers, atol=1e-9)
    assert np.allclose(axes.numpy(), long_axes, atol=1e-9)


@pytest.mark.parametrize("name", ["3do", "3dc7", "3dc9"])
def test_local_pose_is_the_same_in_numpy_and_torch_and_holds_the_link_centres(name, rng):
    s = scenarios.get(name)
    enc = InputEncoding(s.robot, s.grid_shape, latent_dim=0, kind="local", radius=1)
    Q = s.robot.sample(rng, 100)
    cell, pose = enc.configs(Q)  # numpy: the learned checker's path on the CPU
    cell_t, pose_t = enc.configs(torch.as_tensor(Q, dtype=torch.float32))
    np.testing.assert_array_equal(cell, cell_t.numpy())
    np.testing.assert_allclose(pose, pose_t.numpy(), atol=1e-5)
    n_links, n_pos = s.robot.n_links, s.robot.n_positions
    centres = pose[-6 * n_links : -3 * n_links].reshape(n_links, 3, -1).transpose(2, 0, 1)  # (N, L, 3)
    base_cell_centre = np.zeros((len(Q), 1, 3))
    base_cell_centre[:, 0, :n_pos] = np.floor(Q[:, :n_pos]) + 0.5  # the z of a planar base's cell centre: 0
    np.testing.assert_allclose(centres + base_cell_centre, s.robot.link_boxes(Q)[0], atol=1e-4)


def _predictor_and_workspace(kind: str, latent_input: bool, rng):
    """An untrained 3DC-9 predictor in eval mode, each PReLU with its own slope, and one workspace's grid."""
    s = scenarios.get("3dc9")
    torch.manual_seed(0)
    predictor = build_predictor(s, kind, latent_input=latent_input, dropout=0.5, mlp_init="he").eval()
    slopes = [0.25, -0.1, 1.5, 0.0, 0.6, 2.0]  # each read from its own layer; below 0, 0 and above 1 included
    for slope, layer in zip(slopes, (m for m in predictor.mlp.net if isinstance(m, nn.PReLU)), strict=True):
        layer.weight.data.fill_(slope)
    return s, predictor, torch.as_tensor(s.make_workspace(rng).occupancy())


def _full_network_margins(predictor, grid: torch.Tensor, Q: np.ndarray) -> np.ndarray:
    """``(N,)`` logit(valid) - logit(invalid) of the predictor's own forward pass: the reference."""
    with torch.no_grad():
        grids, ws_index = grid[None], torch.zeros(len(Q), dtype=torch.long)
        x = predictor.encoding(predictor.cae.encode(grids), grids, ws_index, torch.as_tensor(Q, dtype=torch.float32))
        logits = predictor.mlp(x)  # (N, 2)
    return (logits[:, VALID] - logits[:, 1 - VALID]).numpy()


@pytest.mark.parametrize("kind, latent_input", [("raw", True), ("local", True), ("local", False)])
def test_workspace_mlp_equals_the_full_network(kind, latent_input, rng):
    s, predictor, grid = _predictor_and_workspace(kind, latent_input, rng)
    assert predictor.encoding.out_features == predictor.mlp.in_features
    assert predictor.encoding.latent_dim == (s.latent_dim if latent_input else 0)
    Q = s.robot.sample(rng, 300)
    Q[:3, :3] = [[0.0, 0.0, 0.0], [11.0, 11.0, 11.0], [10.99, 0.01, 5.0]]  # cells on the grid's faces
    expected = _full_network_margins(predictor, grid, Q)  # (300,)
    assert np.ptp(expected) > 1.0  # the margins vary: a constant would not test much
    default = WorkspaceMLP(predictor, grid)
    assert isinstance(default, WorkspaceMLP) and default.numpy_below == WorkspaceMLP.NUMPY_BELOW  # on the CPU
    assert default.layers.table.shape == (predictor.mlp.hidden[0], 11**3 if kind == "local" else 1)
    variants = {
        "torch": WorkspaceMLP(predictor, grid, numpy_below=0),  # as on a GPU
        "numpy": WorkspaceMLP(predictor, grid, numpy_below=len(Q) + 1),  # one pass
        "numpy, chunks of 16": WorkspaceMLP(predictor, grid, numpy_below=len(Q) + 1, chunk=16),
        "switching at 64, chunks of 16": WorkspaceMLP(predictor, grid, numpy_below=64, chunk=16),
    }
    for name, workspace_mlp in variants.items():
        for n in (0, 1, 15, 16, 17, 63, 64, 65, 300):  # both sides of the chunk size and of the numpy / torch switch
            margins = workspace_mlp(Q[:n])
            assert margins.dtype == np.float32 and margins.shape == (n,), (name, n)
            np.testing.assert_allclose(
                margins, expected[:n], rtol=1e-5, atol=1e-4, err_msg=f"{name}, {n} configurations"
            )


def test_workspace_mlp_switches_to_torch_at_its_default_batch_size(rng):
    s, predictor, grid = _predictor_and_workspace("local", False, rng)
    n = WorkspaceMLP.NUMPY_BELOW
    Q = s.robot.sample(rng, n)
    expected = _full_network_margins(predictor, grid, Q)
    workspace_mlp = WorkspaceMLP(predictor, grid)
    np.testing.assert_allclose(workspace_mlp(Q[: n - 1]), expected[: n - 1], atol=1e-4)  # numpy, in chunks
    np.testing.assert_allclose(workspace_mlp(Q), expected, atol=1e-4)  # torch


def test_workspace_mlp_is_a_snapshot(rng):
    s, predictor, grid = _predictor_and_workspace("local", True, rng)
    Q = s.robot.sample(rng, 40)
    workspace_mlps = [WorkspaceMLP(predictor, grid, numpy_below=below) for below in (0, 100)]  # torch, numpy
    before = _full_network_margins(predictor, grid, Q)
    with torch.no_grad():
        for parameter in predictor.parameters():
            parameter.add_(0.5)  # training further
    assert not np.allclose(_full_network_margins(predictor, grid, Q), before, atol=1e-2)
    for workspace_mlp in workspace_mlps:
        np.testing.assert_allclose(workspace_mlp(Q), before, atol=1e-4)


def test_workspace_mlp_rejects_bad_input(rng):
    _, predictor, grid = _predictor_and_workspace("local", False, rng)
    with pytest.raises(ValueError, match=r"workspace grid \(11, 11\) does not fit the predictor's \(11, 11, 11\)"):
        WorkspaceMLP(predictor, grid[0])
    with pytest.raises(ValueError, match="chunk >= 1"):
        WorkspaceMLP(predictor, grid, chunk=0)
    workspace_mlp = WorkspaceMLP(predictor, grid)
    with pytest.raises(ValueError, match=r"Q must have shape \(N, 9\), got \(4, 7\)"):
        workspace_mlp(np.zeros((4, 7)))
    with pytest.raises(ValueError, match=r"got \(9,\)"):
        workspace_mlp(np.zeros(9))


def test_cell_patches_match_the_patch_of_each_configuration(rng):
    s = scenarios.get("3do")
    enc = InputEncoding(s.robot, s.grid_shape, latent_dim=1, kind="local", radius=2)
    grids = torch.as_tensor(np.stack([s.make_workspace(rng).occupancy() for _ in range(2)]))
    patches = enc.cell_patches(grids)
    assert patches.shape == (2, 41 * 41, 5 * 5 * 6)
    padded = np.pad(grids.numpy(), ((0, 0), (2, 2), (2, 2), (0, 0)), constant_values=1.0)
    for w, (i, j) in [(0, (0, 0)), (1, (40, 17)), (1, (13, 40))]:
        expected = padded[w, i : i + 5, j : j + 5, :].reshape(-1)  # cells (i-2..i+2, j-2..j+2), all heights
        assert torch.equal(patches[w, i * 41 + j], torch.as_tensor(expected))


def test_fold_standardization():
    torch.manual_seed(0)
    mlp = CollisionMLP(5, (8, 4), dropout=0.0).eval()
    x, mean, std = torch.randn(20, 5) * 3 + 1, torch.randn(5), torch.rand(5) + 0.5
    expected = mlp((x - mean) / std)
    mlp.fold_standardization(mean, std)
    assert torch.allclose(mlp(x), expected, atol=1e-5)
