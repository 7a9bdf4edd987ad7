"""Batches on a device: a checker answers a torch tensor in kind, and a numpy batch through staged copies.

The checker interface (:mod:`toolkit.geometry.checker`) takes ``Q (N, dof)`` as a numpy
array or as a torch tensor on any device. A tensor is answered by a ``(N,)`` bool tensor on
the same device: a checker that computes on a device (the learned one, the exact one in
torch, :mod:`toolkit.geometry.torch_kernels`) never copies it to the host and never waits
for the device, so batches stay where they are made. Non-finite rows of a tensor are
invalid (they lie outside every bound) rather than an error: saying so would mean waiting
for the device.

A numpy batch given to a checker on a GPU crosses twice, and :class:`Stager` makes the
crossings cheap: the batch goes in chunks through two page-locked ("pinned") host buffers,
so one chunk's copy to the device overlaps the work on the one before, converted to the
device's number type on the way (no float64 copy first), and the answers come back the same way.

torch is imported here only when a batch is a tensor or a checker has a device: the
geometry package imports without it.
"""

from __future__ import annotations

import sys

import numpy as np

from toolkit.geometry.robots import BoxRobot


def is_tensor(Q) -> bool:
    """Whether ``Q`` is a torch tensor (without importing torch: a process that never imported it has none)."""
    torch = sys.modules.get("torch")
    return torch is not None and isinstance(Q, torch.Tensor)


def checked_tensor(robot: BoxRobot, Q, name: str = "Q"):
    """A float tensor ``Q`` as ``(N, dof)`` (a single ``(dof,)`` configuration as one row); a clear error for a
    wrong shape or type. Finiteness is not checked (the module's docstring says why)."""
    if Q.ndim not in (1, 2) or Q.shape[-1] != robot.dof:
        raise ValueError(
            f"{name} must have shape (N, {robot.dof}) or ({robot.dof},) for robot {robot.name!r}, got {tuple(Q.shape)}"
        )
    if not Q.is_floating_point():
        raise ValueError(f"{name} must hold floating-point numbers, got {Q.dtype}")
    return Q[None] if Q.ndim == 1 else Q


def checked_array(robot: BoxRobot, Q, name: str = "Q") -> np.ndarray:
    """``Q`` as an ``(N, dof)`` float32 or float64 array, copied only when it is neither; a clear error for a
    wrong shape. Finiteness is the caller's to check (on the device, where the batch is read anyway)."""
    Q = np.asarray(Q)
    if Q.dtype not in (np.float32, np.float64):
        Q = Q.astype(np.float64)
    if Q.ndim not in (1, 2) or Q.shape[-1] != robot.dof:
        raise ValueError(
            f"{name} must have shape (N, {robot.dof}) or ({robot.dof},) for robot {robot.name!r}, got {Q.shape}"
        )
    return Q[None] if Q.ndim == 1 else Q


class Stager:
    """Answers numpy batches with a function of device tensors, in chunks of ``chunk`` rows.

    ``Stager(device, dof, dtype)(fn, Q)``: ``fn(Q_chunk (n, dof) dtype tensor on device) -> (n,) bool tensor``
    applied to ``Q (N, dof)`` numpy, ``(N,)`` bool numpy. On a CUDA device each chunk is copied into one of two
    pinned buffers (while the device works on the previous chunk), sent without blocking, and its answers
    come back into a pinned buffer; on the CPU, the chunks are torch views of ``Q`` where its type is ``dtype``.
    """

    CHUNK = 1 << 20  # rows per chunk: 28 MiB of float32 at 7 DoF, large enough that a copy runs at full speed

    def __init__(self, device, dof: int, dtype, chunk: int | None = None):
        import torch

        self.device, self.dtype, self.chunk = torch.device(device), dtype, int(chunk or self.CHUNK)
        if self.chunk < 1:
            raise ValueError(f"chunk must be >= 1, got {self.chunk}")
        self.pinned = self.device.type == "cuda"
        if self.pinned:
            self._inputs = [torch.empty((self.chunk, dof), dtype=dtype, pin_memory=True) for _ in range(2)]
            self._sent = [torch.cuda.Event() for _ in range(2)]  # buffer i's last copy to the device is done
            self._answers = torch.empty(0, dtype=torch.bool, pin_memory=True)

    def __call__(self, fn, Q: np.ndarray) -> np.ndarray:
        import torch

        N = len(Q)
        if not self.pinned:
            numpy_type = torch.empty(0, dtype=self.dtype).numpy().dtype
            return np.concatenate(
                [
                    fn(torch.from_numpy(np.ascontiguousarray(Q[i : i + self.chunk], dtype=numpy_type)).to(self.device))
                    .cpu()
                    .numpy()
                    for i in range(0, N, self.chunk)
                ]
                or [np.zeros(0, dtype=bool)]
            )
        if len(self._answers) < N:
            self._answers = torch.empty(N, dtype=torch.bool, pin_memory=True)
        stream = torch.cuda.current_stream(self.device)
        for k, start in enumerate(range(0, N, self.chunk)):
            stop, buffer, sent = min(start + self.chunk, N), self._inputs[k % 2], self._sent[k % 2]
            sent.synchronize()  # the buffer's previous chunk has left it
            np.copyto(buffer[: stop - start].numpy(), Q[start:stop], casting="same_kind")  # float64 -> float32 here
            on_device = buffer[: stop - start].to(self.device, non_blocking=True)
            sent.record(stream)
            self._answers[start:stop].copy_(fn(on_device), non_blocking=True)
        stream.synchronize()
        return self._answers[:N].numpy().copy()
