"""The collision MLP with one workspace folded in, for fast inference (§III-B, Algorithm 1 lines 1 and 3).

Algorithm 1 encodes the workspace once (line 1), then asks the MLP about every
sample of a round (line 3); a planner asks again in every round, and its samplers
ask about a few hundred configurations at a time. :class:`WorkspaceMLP` answers with
the network's own numbers (a test holds it equal to the full forward pass of
:class:`~toolkit.learning.models.CollisionPredictor`) in fewer, cheaper operations:

1. **The workspace folded into the first layer.** The first layer computes
   ``W [z, patch, pose] + b = (W_z z + W_patch patch + b) + W_pose pose``. In one
   workspace ``z`` is fixed and the patch depends only on the base cell, so the
   bracket takes one value per base cell: a table ``(H, n_cells)``, built once
   (:func:`workspace_table`). A prediction gathers its cell's column and multiplies
   only the pose. With the paper's ``[z, q]`` there is no patch and the table has one
   column, added to every prediction without gathering copies of it.
2. **One margin instead of two logits.** Only ``logit(valid) - logit(invalid)``
   decides (P(valid) = sigmoid(margin)), so the last layer's two rows become their
   difference, one vector, and its two biases one number.
3. **Column-major activations** ``(features, N)``: the encoding lays configurations
   out one row per feature already (``InputEncoding.configs``), and the MLP's small
   matrix products run faster with the batch along the contiguous axis.
4. **numpy below a batch size.** A call costs a fixed amount per array operation
   plus an amount per configuration. On the CPU, at the few hundred configurations a
   sampler asks about, the fixed cost dominates, and numpy's is lower than torch's:
   calls of fewer than ``NUMPY_BELOW`` configurations compute in numpy, in chunks of
   ``CHUNK`` whose temporaries stay in the cache. Larger calls go to torch, whose
   fused kernels (``addmm``, in-place ``leaky_relu_``) are faster there. On a GPU
   every call goes to torch.
5. **Read once.** The PReLU slopes become Python floats and the weights contiguous
   copies (numpy views of the same memory); dropout is off, as in ``eval()``.
6. **Replayed on a GPU.** A GPU call of a few hundred configurations costs a kernel
   launch per operation, far more than its arithmetic. :class:`Replay` records the
   operations once for a fixed batch (a CUDA graph) and launches them as one
   (``docs/gpu.md``); elsewhere it calls the same function on the same fixed batch.

``docs/benchmarks.md`` ("The learned checker's fast path") has the measured speed-ups
behind 1, 3 and 4, and the commits they were measured at.

A snapshot: training the predictor further does not change a ``WorkspaceMLP`` made before.
"""

from __future__ import annotations

import copy
from collections.abc import Callable
from dataclasses import dataclass
from typing import Generic, TypeVar

import numpy as np
import torch
from torch import nn

from toolkit.learning.models import VALID, CollisionPredictor

Array = TypeVar("Array", torch.Tensor, np.ndarray)


@dataclass(frozen=True)
class FoldedLayers(Generic[Array]):
    """The MLP's weights after folding, column-major: torch tensors, or numpy arrays (:meth:`numpy`)."""

    table: Array  # (H, n_cells): the workspace's share of the first layer, per base cell
    pose_weight: Array  # (H, pose_size): the first layer's weights on the pose
    hidden: list[tuple[Array, Array]]  # [(weight (H_next, H), bias (H_next, 1)), ...]: between the first and last
    margin_weight: Array  # (H_last,): the last layer's valid row minus its invalid row

    def numpy(self: FoldedLayers[torch.Tensor]) -> FoldedLayers[np.ndarray]:
        """The same numbers as numpy arrays (views of the tensors' memory when they are on the CPU)."""

        def array(t: torch.Tensor) -> np.ndarray:
            return t.cpu().numpy()

        return FoldedLayers(
            array(self.table),
            array(self.pose_weight),
            [(array(w), array(b)) for w, b in self.hidden],
            array(self.margin_weight),
        )

    def to(self: FoldedLayers[torch.Tensor], device: torch.device) -> FoldedLayers[torch.Tensor]:
        """The same numbers on ``device``."""
        return FoldedLayers(
            self.table.to(device),
            self.pose_weight.to(device),
            [(w.to(device), b.to(device)) for w, b in self.hidden],
            self.margin_weight.to(device),
        )


@torch.no_grad()
def workspace_table(predictor: CollisionPredictor, grid: torch.Tensor) -> torch.Tensor:
    """``(H, n_cells)``: ``W_z z + W_patch patch + b``, all the first layer takes from the workspace ``grid (*grid)``,
    for each base cell (one column when the MLP sees no patch)."""
    encoding, first = predictor.encoding, predictor.mlp.linears[0]
    L, P = encoding.latent_dim, encoding.patch_size
    grids = grid[None]  # (1, *grid)
    share = first.bias.clone()  # (H,)
    if L:
        share += first.weight[:, :L] @ predictor.cae.encode(grids)[0, :L]
    patches = encoding.cell_patches(grids)[0]  # (n_cells, P)
    return first.weight[:, L : L + P] @ patches.T + share[:, None]


class WorkspaceMLP:
    """The collision MLP of a :class:`~toolkit.learning.models.CollisionPredictor` with one workspace folded in.

    ``WorkspaceMLP(predictor, grid)(Q)``: the margins ``logit(valid) - logit(invalid)``,
    ``(N,)`` float32, of configurations ``Q (N, dof)``, equal to the full network's.
    The module's docstring explains how it saves work. ``device``: where torch computes (default: the grid's);
    the workspace is encoded where the predictor is, then the folded weights move there.
    """

    NUMPY_BELOW = 8192  # on the CPU, calls of fewer configurations compute in numpy
    CHUNK = 4096  # configurations a numpy pass computes at once

    @torch.no_grad()
    def __init__(
        self,
        predictor: CollisionPredictor,
        grid: torch.Tensor,
        numpy_below: int | None = None,
        chunk: int | None = None,
        device: torch.device | str | None = None,
    ):
        """``grid (*grid)``: the workspace's occupancy, on the predictor's device. ``numpy_below``: calls of
        fewer configurations compute in numpy (default: ``NUMPY_BELOW`` on the CPU, 0 elsewhere); ``chunk``:
        configurations a numpy pass computes at once (default ``CHUNK``)."""
        encoding = predictor.encoding
        if tuple(grid.shape) != encoding.grid_shape:
            raise ValueError(f"workspace grid {tuple(grid.shape)} does not fit the predictor's {encoding.grid_shape}")
        device = grid.device if device is None else torch.device(device)
        if device != grid.device:  # the encoding's constants travel with it; the predictor's own stay where they are
            encoding = copy.deepcopy(encoding).to(device)
        default_below = self.NUMPY_BELOW if device.type == "cpu" else 0
        self.numpy_below = default_below if numpy_below is None else int(numpy_below)
        self.chunk = self.CHUNK if chunk is None else int(chunk)
        if self.numpy_below < 0 or self.chunk < 1:
            raise ValueError(f"numpy_below must be >= 0 and chunk >= 1, got {self.numpy_below} and {self.chunk}")
        self.encoding, self.device = encoding, device
        linears = predictor.mlp.linears
        first, last = linears[0], linears[-1]
        self.slopes = [float(m.weight) for m in predictor.mlp.net if isinstance(m, nn.PReLU)]  # one per hidden layer
        self.margin_bias = float(last.bias[VALID] - last.bias[1 - VALID])
        table = workspace_table(predictor, grid)  # (H, n_cells)
        self.one_cell = table.shape[1] == 1  # the workspace's share is the same for every configuration
        pose_start = encoding.latent_dim + encoding.patch_size
        self.layers = FoldedLayers(
            _snapshot(table),
            _snapshot(first.weight[:, pose_start:]),
            [(_snapshot(m.weight), _snapshot(m.bias[:, None])) for m in linears[1:-1]],
            _snapshot(last.weight[VALID] - last.weight[1 - VALID]),
        ).to(device)
        # the same numbers, for small calls
        self.numpy_layers: FoldedLayers[np.ndarray] | None = self.layers.numpy() if self.numpy_below else None

    def __call__(self, Q: np.ndarray) -> np.ndarray:
        """Margins ``(N,)`` float32 of configurations ``Q (N, dof)``; P(valid) = sigmoid(margin)."""
        Q = np.asarray(Q)
        if Q.ndim != 2 or Q.shape[1] != self.encoding.dof:
            raise ValueError(f"Q must have shape (N, {self.encoding.dof}), got {Q.shape}")
        if len(Q) >= self.numpy_below:
            return self.margins(torch.as_tensor(Q, dtype=torch.float32, device=self.device)).cpu().numpy()
        if len(Q) <= self.chunk:
            return self._numpy_margins(Q)
        return np.concatenate([self._numpy_margins(Q[i : i + self.chunk]) for i in range(0, len(Q), self.chunk)])

    @torch.inference_mode()
    def margins(self, Q: torch.Tensor) -> torch.Tensor:
        """Margins ``(N,)`` of a float32 tensor ``Q (N, dof)`` on the table's device, with torch's fused operations."""
        layers = self.layers
        cell, pose = self.encoding.configs(Q)  # (N,), (pose_size, N)
        table = layers.table if self.one_cell else layers.table.index_select(1, cell)  # (H, 1 or N)
        h = torch.addmm(table, layers.pose_weight, pose)  # (H, N)
        nn.functional.leaky_relu_(h, self.slopes[0])  # PReLU of one slope: leaky ReLU with that slope
        for (weight, bias), slope in zip(layers.hidden, self.slopes[1:]):
            h = nn.functional.leaky_relu_(torch.addmm(bias, weight, h), slope)  # (H_next, N)
        return torch.mv(h.T, layers.margin_weight) + self.margin_bias  # (N,)

    def _numpy_margins(self, Q: np.ndarray) -> np.ndarray:
        """The same margins as :meth:`margins`, in numpy (float32), of ``Q (N, dof)``."""
        layers = self.numpy_layers
        assert layers is not None, "numpy computes only calls below numpy_below > 0, and then numpy_layers exist"
        cell, pose = self.encoding.configs(Q)  # (N,), (pose_size, N)
        h = layers.pose_weight @ pose  # (H, N)
        h += layers.table if self.one_cell else np.take(layers.table, cell, axis=1)
        prelu_(h, self.slopes[0])
        for (weight, bias), slope in zip(layers.hidden, self.slopes[1:]):
            h = weight @ h  # (H_next, N)
            h += bias
            prelu_(h, slope)
        return layers.margin_weight @ h + self.margin_bias  # (N,)


class Replay:
    """``fn`` on a fixed batch of ``capacity`` rows, the rows of a call copied into it: on a CUDA device its
    operations recorded once as a CUDA graph and replayed, elsewhere ``fn`` called on the fixed batch.

    ``Replay(fn, fill)(Q (n, ...))`` equals ``fn(Q)`` for ``n <= capacity``, when row ``i`` of ``fn``'s answer
    depends on row ``i`` of its batch only (true of the margins and of a checker's decisions); ``fill
    (capacity, ...)``: the fixed batch's first contents (the rows past ``n`` in a call), on the device.
    """

    WARM_UP = 3  # calls on a side stream before recording, as torch's documentation asks

    def __init__(self, fn: Callable[[torch.Tensor], torch.Tensor], fill: torch.Tensor):
        self.fn, self.batch, self.capacity = fn, fill.clone(), len(fill)
        self.graph: torch.cuda.CUDAGraph | None = None
        if self.batch.device.type == "cuda":
            side = torch.cuda.Stream(self.batch.device)
            side.wait_stream(torch.cuda.current_stream(self.batch.device))
            with torch.cuda.stream(side):
                for _ in range(self.WARM_UP):
                    fn(self.batch)
            torch.cuda.current_stream(self.batch.device).wait_stream(side)
            self.graph = torch.cuda.CUDAGraph()
            with torch.cuda.graph(self.graph):
                self.answer = fn(self.batch)

    def __call__(self, Q: torch.Tensor) -> torch.Tensor:
        n = len(Q)
        if n > self.capacity:
            raise ValueError(f"a replay of {self.capacity} rows was asked about {n}")
        self.batch[:n].copy_(Q)
        if self.graph is None:
            return self.fn(self.batch)[:n]
        self.graph.replay()
        return self.answer[:n].clone()  # the next replay overwrites its answer


def _snapshot(t: torch.Tensor) -> torch.Tensor:
    """A contiguous copy: later training does not reach it, and products read it in order."""
    return t.detach().clone().contiguous()


def prelu_(h: np.ndarray, slope: float) -> None:
    """PReLU in place: ``h`` where positive, ``slope * h`` elsewhere (the larger of the two, the
    smaller if slope > 1)."""
    (np.maximum if slope <= 1 else np.minimum)(h, slope * h, out=h)
